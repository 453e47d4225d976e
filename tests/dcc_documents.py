"""Digital calibration certificates built by hand from PTB's DCC 3.3.0 / D-SI 2.2.1 schemas
(../shared/dcc), as another laboratory's software would write them: lxml element by element,
importing nothing from models.dcc. Used to test DCC in; each document validates against the
schema folder (:func:`schema`).

A polygon's face deviations are simulated from its geometry: N faces whose normals stand at
k·360°/N plus a small manufacturing error per face; the deviation a calibration reports is
that error, in the unit asked for (D-SI unit strings)."""

from __future__ import annotations

import base64
import functools
import math
from pathlib import Path

from lxml import etree

DCC = "https://ptb.de/dcc"
SI = "https://ptb.de/si"
SHARED_DCC = Path(__file__).resolve().parents[1].parent / "shared" / "dcc"
if not SHARED_DCC.is_dir():  # a worktree beside /work/shared
    SHARED_DCC = Path("/work/shared/dcc")
QUDT = "https://www.ptb.de/si/v2.2.1/qudt/quantitykind.xsd"
#: the angle per D-SI unit, in arcseconds (written out here, not taken from the reader)
PER_UNIT = {r"\arcsecond": 1.0, r"\arcminute": 60.0, r"\degree": 3600.0,
            r"\radian": 180.0 * 3600.0 / math.pi, r"\micro\radian": 0.18 * 3.6 / math.pi}


def d(tag: str) -> str:
    return f"{{{DCC}}}{tag}"


def s(tag: str) -> str:
    return f"{{{SI}}}{tag}"


def sub(parent, tag: str, text: str | None = None, **attrs):
    element = etree.SubElement(parent, tag, {k.replace("_", ""): v for k, v in attrs.items()})
    if text is not None:
        element.text = text
    return element


def text(parent, tag: str, content: str, lang: str = "en"):
    element = sub(parent, tag)
    sub(element, d("content"), content, lang=lang)
    return element


@functools.lru_cache(maxsize=1)
def schema():
    local = SHARED_DCC / "si" / "qudt" / "quantitykind.xsd"

    class Local(etree.Resolver):
        def resolve(self, url, pubid, context):
            return self.resolve_filename(str(local), context) if url == QUDT else None

    parser = etree.XMLParser(no_network=True)
    parser.resolvers.add(Local())
    return etree.XMLSchema(etree.parse(str(SHARED_DCC / "dcc.xsd"), parser))


def assert_valid(data: bytes) -> None:
    doc = etree.fromstring(data)
    if not schema().validate(doc):
        raise AssertionError("\n".join(f"{e.path}: {e.message}" for e in schema().error_log))


def polygon_errors(faces: int, seed: int = 1, spread_arcsec: float = 0.4) -> list[float]:
    """Each face normal's angle minus its nominal k·360/N, in arcseconds: a made polygon's
    errors (deterministic), with the sum of errors zero (the faces close the circle)."""
    normals = [k * 360.0 / faces * 3600.0 + spread_arcsec * math.sin(1.7 * k * seed + 0.3)
               for k in range(faces)]
    errors = [n - k * 360.0 / faces * 3600.0 for k, n in enumerate(normals)]
    mean = sum(errors) / faces
    return [e - mean for e in errors]


def _fmt(values) -> str:
    return " ".join(repr(float(v)) for v in values)


def document(number: str = "PTB-2026-0042", *, end_date: str = "2026-03-10",
             results=None, statements=None, pdf: bytes | None = None, root_extra=None,
             item: str = "Optical polygon, 12 faces", serial: str = "PG-12-007") -> bytes:
    """A complete DCC 3.3.0 with ``results`` (a function filling dcc:results) and
    ``statements`` (a function filling dcc:statements, or None for none), of the ``item``
    with its ``serial`` ("": no identification)."""
    root = etree.Element(d("digitalCalibrationCertificate"), nsmap={"dcc": DCC, "si": SI},
                         schemaVersion="3.3.0")
    admin = sub(root, d("administrativeData"))
    software = sub(sub(admin, d("dccSoftware")), d("software"))
    text(software, d("name"), "Other lab's DCC writer")
    sub(software, d("release"), "7.1")
    core = sub(admin, d("coreData"))
    sub(core, d("countryCodeISO3166_1"), "DE")
    sub(core, d("usedLangCodeISO639_1"), "en")
    sub(core, d("mandatoryLangCodeISO639_1"), "en")
    sub(core, d("uniqueIdentifier"), number)
    sub(core, d("beginPerformanceDate"), "2026-03-09")
    sub(core, d("endPerformanceDate"), end_date)
    sub(core, d("performanceLocation"), "laboratory")
    items = sub(admin, d("items"))
    item_element = sub(items, d("item"))
    text(item_element, d("name"), item)
    if serial:
        ident = sub(sub(item_element, d("identifications")), d("identification"))
        sub(ident, d("issuer"), "manufacturer")
        sub(ident, d("value"), serial)
    lab = sub(sub(admin, d("calibrationLaboratory")), d("contact"))
    text(lab, d("name"), "Angle laboratory")
    sub(sub(lab, d("location")), d("city"), "Braunschweig")
    person = sub(sub(admin, d("respPersons")), d("respPerson"))
    text(sub(person, d("person")), d("name"), "A. Person")
    customer = sub(admin, d("customer"))
    text(customer, d("name"), "Customer lab")
    sub(sub(customer, d("location")), d("city"), "Beijing")
    if statements is not None:
        statements(sub(admin, d("statements")))
    measurement = sub(sub(root, d("measurementResults")), d("measurementResult"))
    text(measurement, d("name"), "Calibration of the polygon")
    (results or polygon_results())(sub(measurement, d("results")))
    if pdf is not None:
        doc = sub(root, d("document"))
        sub(doc, d("fileName"), f"{number}.pdf")
        sub(doc, d("mimeType"), "application/pdf")
        sub(doc, d("dataBase64"), base64.b64encode(pdf).decode())
    if root_extra is not None:
        root_extra(root)
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8")


def validity(date: str = "", period: str = "", reftype: str = "anglebench_validity"):
    def fill(statements):
        statement = sub(statements, d("statement"), refType=reftype)
        text(statement, d("declaration"), "Recalibration is due as stated.")
        if date:
            sub(statement, d("date"), date)
        if period:
            sub(statement, d("period"), period)
    return fill


def real_list(parent, values, unit, u=None, k=2.0, p=0.95, reftype="", name=""):
    quantity = sub(parent, d("quantity"), **({"refType": reftype} if reftype else {}))
    if name:
        text(quantity, d("name"), name)
    rl = sub(quantity, s("realListXMLList"))
    sub(rl, s("valueXMLList"), _fmt(values))
    sub(rl, s("unitXMLList"), unit)
    if u is not None:
        mu = sub(sub(rl, s("measurementUncertaintyUnivariateXMLList")), s("expandedMUXMLList"))
        sub(mu, s("valueExpandedMUXMLList"), _fmt(u))
        sub(mu, s("coverageFactorXMLList"), _fmt([k]))
        sub(mu, s("coverageProbabilityXMLList"), _fmt([p]))
    return quantity


def polygon_results(errors_arcsec=None, unit=r"\arcsecond", u_arcsec=0.15, k=2.0, p=0.95,
                    indices=None, with_u=True, index_reftype="anglebench_faceIndex",
                    result_reftype="anglebench_polygonFaceDeviations"):
    """Fill dcc:results with the polygon's face deviations (converted to ``unit``)."""
    errors = polygon_errors(12) if errors_arcsec is None else list(errors_arcsec)
    factor = PER_UNIT.get(unit, 1.0)

    def fill(results):
        result = sub(results, d("result"), refType=result_reftype)
        text(result, d("name"), "Face deviations")
        data = sub(result, d("data"))
        listing = sub(data, d("list"))
        real_list(listing, indices or range(1, len(errors) + 1), r"\one", reftype=index_reftype)
        real_list(listing, [e / factor for e in errors], unit,
                  u=[u_arcsec / factor] * len(errors) if with_u else None, k=k, p=p,
                  reftype="anglebench_faceDeviation")
    return fill


def standard_results(values, unit, u, k=2.0, p=0.95):
    """Fill dcc:results with a plain calibration (no polygon): a single list of errors."""
    def fill(results):
        result = sub(results, d("result"))
        text(result, d("name"), "Errors")
        real_list(sub(result, d("data")), values, unit, u=u, k=k, p=p, name="error")
    return fill


def self_signed(tmp_path: Path, name: str = "Test lab DCC signing") -> tuple[bytes, bytes]:
    """A test key and self-signed certificate (PEM), as the README's openssl commands make
    them (here with cryptography, no openssl binary needed)."""
    import datetime as dt

    from cryptography import x509
    from cryptography.hazmat.primitives import hashes, serialization
    from cryptography.hazmat.primitives.asymmetric import rsa
    from cryptography.x509.oid import NameOID

    key = rsa.generate_private_key(public_exponent=65537, key_size=2048)
    subject = x509.Name([x509.NameAttribute(NameOID.COMMON_NAME, name)])
    now = dt.datetime.now(dt.timezone.utc)
    cert = (x509.CertificateBuilder().subject_name(subject).issuer_name(subject)
            .public_key(key.public_key()).serial_number(x509.random_serial_number())
            .not_valid_before(now - dt.timedelta(days=1))
            .not_valid_after(now + dt.timedelta(days=365))
            .sign(key, hashes.SHA256()))
    key_pem = key.private_bytes(serialization.Encoding.PEM, serialization.PrivateFormat.PKCS8,
                                serialization.NoEncryption())
    return key_pem, cert.public_bytes(serialization.Encoding.PEM)
