"""The laboratory's XML signature on a digital calibration certificate (XML-DSig, enveloped,
RSA or EC with SHA-256, made with signxml).

The ``ds:Signature`` is appended as the root's last child: DCC 3.3.0 allows it there, after
``dcc:document`` (``digitalCalibrationCertificateType``), so a signed document still validates
against the DCC schema. The signed reference is the whole document (``URI=""``), so any change
to any element after signing makes the signature fail.

The lab configures a private key and its X.509 certificate (PEM files) with the settings
``dcc_signing_key`` / ``dcc_signing_certificate`` or the environment variables
:data:`KEY_ENV_VAR` / :data:`CERT_ENV_VAR`; a reader checks a signature against a trusted
certificate (:data:`TRUSTED_ENV_VAR`, the lab's own or its CA's), or else against the
certificate the document carries and says that its signer was not checked.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, cast

from models.dcc.vocabulary import DS_NAMESPACE
from models.messages import QT_TR_NOOP, message

if TYPE_CHECKING:
    from signxml import VerifyResult

__all__ = ["CERT_ENV_VAR", "KEY_ENV_VAR", "TRUSTED_ENV_VAR", "SignatureCheck", "SigningError",
           "has_signature", "load_signing", "sign", "sign_if_configured", "signature_demanded",
           "trusted_certificate",
           "verify"]

KEY_ENV_VAR = "ANGLEBENCH_DCC_SIGNING_KEY"
CERT_ENV_VAR = "ANGLEBENCH_DCC_SIGNING_CERTIFICATE"
TRUSTED_ENV_VAR = "ANGLEBENCH_DCC_TRUSTED_CERTIFICATE"


class SigningError(ValueError):
    """The key or certificate cannot be used, or the document cannot be signed."""


@dataclass(frozen=True)
class SignatureCheck:
    """What checking a document's signature found: ``problems`` (empty: it verifies),
    the signer's subject, whether it was checked against a trusted certificate, and the
    signed document (the bytes a reader must read: what the signature covers)."""

    problems: tuple
    signer: str = ""
    trusted: bool = False
    signed_xml: bytes = b""


def _read(path: str, what: str) -> bytes:
    try:
        return Path(path).expanduser().read_bytes()
    except OSError as exc:
        raise SigningError(message(QT_TR_NOOP("the DCC signing {what} {path} cannot be read "
                                              "({reason})"), what=what, path=path,
                                   reason=exc.strerror or str(exc))) from None


def load_signing(key_file: str = "", cert_file: str = "") -> tuple[bytes, bytes] | None:
    """The lab's private key and certificate (PEM bytes) from the files given, else from the
    files the environment names; None when neither is set. SigningError (naming the file)
    when only one is set or one cannot be read."""
    key_file = key_file.strip() or os.environ.get(KEY_ENV_VAR, "").strip()
    cert_file = cert_file.strip() or os.environ.get(CERT_ENV_VAR, "").strip()
    if not key_file and not cert_file:
        return None
    if not key_file or not cert_file:
        raise SigningError(message(QT_TR_NOOP(
            "a DCC is signed with a private key and its X.509 certificate: both are needed "
            "(dcc_signing_key and dcc_signing_certificate, or {key_var} and {cert_var})"),
            key_var=KEY_ENV_VAR, cert_var=CERT_ENV_VAR))
    key = _read(key_file, message(QT_TR_NOOP("key")))
    cert = _read(cert_file, message(QT_TR_NOOP("certificate")))
    if b"PRIVATE KEY" not in key:
        raise SigningError(message(QT_TR_NOOP("{path}: not a PEM private key"), path=key_file))
    if b"BEGIN CERTIFICATE" not in cert:
        raise SigningError(message(QT_TR_NOOP("{path}: not a PEM X.509 certificate"),
                                   path=cert_file))
    return key, cert


def sign_if_configured(xml_bytes: bytes, key_file: str = "", cert_file: str = "") -> bytes:
    """``xml_bytes`` signed with the lab's key and certificate when they are configured (the
    settings ``dcc_signing_key`` / ``dcc_signing_certificate`` passed here, else the
    environment), unchanged when neither is; SigningError when they cannot be used (a DCC is
    then not issued rather than issued unsigned against the lab's configuration)."""
    signing = load_signing(key_file, cert_file)
    return xml_bytes if signing is None else sign(xml_bytes, *signing)


def trusted_certificate(path: str = "") -> bytes | None:
    """The certificate a reader checks signatures against: ``path``, else the file
    :data:`TRUSTED_ENV_VAR` names, else the lab's own signing certificate
    (:data:`CERT_ENV_VAR`); None when none is set. SigningError when it cannot be read."""
    path = (path.strip() or os.environ.get(TRUSTED_ENV_VAR, "").strip()
            or os.environ.get(CERT_ENV_VAR, "").strip())
    return _read(path, message(QT_TR_NOOP("certificate"))) if path else None


def signature_demanded(path: str = "") -> bool:
    """Whether a DCC read must be signed: a trusted certificate named for the DCCs read
    (``path``, the window's setting, or :data:`TRUSTED_ENV_VAR`). The laboratory's own
    signing certificate (:data:`CERT_ENV_VAR`), which :func:`trusted_certificate` falls back
    to for checking a signature that is there, demands none: it is set to sign what the lab
    issues, and a supplier's unsigned DCC (a signature is optional in DCC 3.3.0) would
    otherwise be refused with no way to read it."""
    return bool(path.strip() or os.environ.get(TRUSTED_ENV_VAR, "").strip())


def _parser():
    from lxml import etree

    return etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False,
                           load_dtd=False, remove_blank_text=False)


def has_signature(xml_bytes: bytes) -> bool:
    from lxml import etree

    root = etree.fromstring(xml_bytes, _parser())
    return root.find(f"{{{DS_NAMESPACE}}}Signature") is not None


def sign(xml_bytes: bytes, key: bytes, cert: bytes) -> bytes:
    """``xml_bytes`` signed enveloped with ``key`` and ``cert`` (PEM): the ds:Signature as
    the root's last child, carrying the certificate. SigningError when it cannot be."""
    from lxml import etree
    from signxml import XMLSigner

    try:
        root = etree.fromstring(xml_bytes, _parser())
    except etree.XMLSyntaxError as exc:
        raise SigningError(message(QT_TR_NOOP("the DCC to sign is not XML: {reason}"),
                                   reason=str(exc))) from None
    if root.find(f"{{{DS_NAMESPACE}}}Signature") is not None:
        raise SigningError(message(QT_TR_NOOP("the DCC is signed already")))
    try:
        signed = XMLSigner().sign(root, key=key, cert=cert.decode("ascii"))
    except Exception as exc:  # noqa: BLE001 — signxml/cryptography raise many kinds
        raise SigningError(message(QT_TR_NOOP("the DCC cannot be signed with this key and "
                                              "certificate: {reason}"), reason=str(exc))) from None
    return etree.tostring(signed, xml_declaration=True, encoding="UTF-8")


def verify(xml_bytes: bytes, trusted_cert: bytes | None = None) -> SignatureCheck:
    """Check the document's ds:Signature: against ``trusted_cert`` (PEM: the signer's own
    certificate, or the CA that issued it) when given, else against the certificate the
    document carries (then only that the document is unchanged since it was signed with
    that certificate's key; ``trusted`` False). ``problems`` empty when it verifies; a
    document without a signature has the problem that it is not signed."""
    from lxml import etree
    from signxml import XMLVerifier

    try:
        root = etree.fromstring(xml_bytes, _parser())
    except etree.XMLSyntaxError as exc:
        return SignatureCheck((message(QT_TR_NOOP("not XML: {reason}"), reason=str(exc)),))
    signatures = root.findall(f".//{{{DS_NAMESPACE}}}Signature")
    if not signatures:
        return SignatureCheck((message(QT_TR_NOOP("the document is not signed")),))
    if len(signatures) > 1:
        return SignatureCheck((message(QT_TR_NOOP(
            "the document carries {n} signatures; AngleBench checks one enveloped signature"),
            n=len(signatures)),))
    embedded = root.findtext(f".//{{{DS_NAMESPACE}}}X509Certificate") or ""
    carried = ("-----BEGIN CERTIFICATE-----\n" + "".join(embedded.split())
               + "\n-----END CERTIFICATE-----\n") if embedded.strip() else ""
    signer = _subject(carried)
    try:
        if trusted_cert is not None:
            is_ca = _is_ca(trusted_cert)
            if is_ca:
                result = XMLVerifier().verify(xml_bytes, ca_pem_file=trusted_cert,
                                              parser=_parser())
            else:
                result = XMLVerifier().verify(xml_bytes, x509_cert=trusted_cert.decode("ascii"),
                                              parser=_parser())
        elif carried:
            result = XMLVerifier().verify(xml_bytes, x509_cert=carried, parser=_parser())
        else:
            return SignatureCheck((message(QT_TR_NOOP(
                "the signature carries no X.509 certificate and no trusted certificate is "
                "configured ({var})"), var=TRUSTED_ENV_VAR),))
    except Exception as exc:  # noqa: BLE001 — signxml raises InvalidSignature, InvalidCertificate …
        if trusted_cert is not None and carried and _verifies(xml_bytes, carried):
            # intact and signed, by a signer the trusted certificate does not vouch for: said
            # so, not "Signature verification failed" (which reads as a document changed)
            return SignatureCheck((message(QT_TR_NOOP(
                "signed by {signer}, which the trusted certificate ({trusted}) does not "
                "vouch for: the document is unchanged since it was signed, but not by the "
                "signer trusted"), signer=signer or "?",
                trusted=_subject(trusted_cert.decode("ascii", "replace")) or "?"),), signer)
        return SignatureCheck((message(QT_TR_NOOP("the signature does not verify: {reason}"),
                                       reason=str(exc) or type(exc).__name__),), signer)
    # one reference is expected (the verifier's default expect_references=1, checked by it),
    # so verify() gave one VerifyResult, not a list
    verified = cast("VerifyResult", result)
    signed = etree.tostring(verified.signed_xml) if verified.signed_xml is not None else b""
    return SignatureCheck((), signer, trusted_cert is not None, signed)


def _verifies(xml_bytes: bytes, certificate_pem: str) -> bool:
    """Whether the document's signature verifies against ``certificate_pem`` (the one it
    carries): unchanged since it was signed with that certificate's key."""
    from signxml import XMLVerifier

    try:
        XMLVerifier().verify(xml_bytes, x509_cert=certificate_pem, parser=_parser())
    except Exception:  # noqa: BLE001 — as verify()
        return False
    return True


def _certificate(pem: bytes | str):
    from cryptography import x509

    data = pem.encode("ascii") if isinstance(pem, str) else pem
    return x509.load_pem_x509_certificate(data)


def _subject(pem: str) -> str:
    if not pem:
        return ""
    try:
        return _certificate(pem).subject.rfc4514_string()
    except ValueError:
        return ""


def _is_ca(pem: bytes) -> bool:
    """Whether ``pem`` is a CA's certificate (basic constraints CA true) that is not self-
    signed for one signer only: a lab's self-signed signing certificate is used as is."""
    from cryptography import x509

    try:
        cert = _certificate(pem)
    except ValueError:
        return False
    try:
        ca = cert.extensions.get_extension_for_class(x509.BasicConstraints).value.ca
    except x509.ExtensionNotFound:
        return False
    return bool(ca) and cert.issuer != cert.subject
