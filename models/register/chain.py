"""The register's hash chain (ISO/IEC 17025 7.11.3: changes to records are detectable).

Each record's ``chain_sha256`` is the SHA-256 of the previous record's (in the order of
issue) and of the record's own fields as issued — the PDF's SHA-256 among them. A record,
or a PDF and its hash, changed in the database afterwards no longer gives the stored
chain; neither does a record deleted or inserted before the last. What changes lawfully
after issue — the status and ``superseded_by`` when an amendment or replacement is issued —
is outside the chain and checked against the record that supersedes it, which is in it;
so is a withdrawal's status and ``withdrawn_reason``, a copy of the reason its chained
withdrawal entry holds (compared with it: rev64 F9).

Since schema version 4 the chain also runs through the register's other records (the
``entries`` table: calibration intervals, numbering continued, withdrawals), in one order
(``seq``), and a record's chain covers who issued it (the operating-system user), who
approved it, its place and the counter value its number came from (``chain_format`` 2).
Since schema version 5 a certificate issued with a digital calibration certificate (DCC XML)
has chain format 3: its chain also covers the DCC's SHA-256, so the DCC, its hash, or both
set to nothing are found as the PDF's are; records issued without one keep format 2.
Since schema version 6 every record issued has chain format 4: its chain also covers what
the document is (``document_kind``: a calibration certificate or a test report) and its
DCC's SHA-256 or that it has none; records issued before keep their format and their chain
values, and their kind is not recorded.
The ``register_state`` row holds the number of records and the head, so a deleted tail is
found; the counters are cross-checked against the records allocated from them.

Since AngleBench 0.8.21 every certificate issued has chain format 5 (the fields of format
4): its PDF carries the digest of its record's content (:func:`content_digest`: the readings,
results and details as recorded, not the files' hashes, which are made after it), so a
record rewritten after its PDF was issued is found from the customer's copy, key or no key;
and with the lab's key the state (record count, head and number counters) is signed with
every record, so a deleted tail with the state set back is found
(models/register/signing.state_text).

Since AngleBench 0.8.22 every certificate issued has chain format 6 (the fields of format
4): the digest its PDF carries is of content form 2 (:func:`content_form`), which also covers
every field that identifies a file issued with it or what it is: the document kind and the
DCC (its SHA-256 is made after the PDF it embeds, so the digest covers the DCC as issued with
the embedded PDF and any XML signature left out, :func:`dcc_body_digest`) — so the newest
record's DCC or kind rewritten with its chain recomputed is found from the customer's PDF,
key or no key (reg73 #1). A record of chain format 5 carries content form 1 and is checked
against it. The results file is made after the PDF and names its SHA-256: no digest the PDF
carries can cover it; its chained entry is found rewritten by the customer's results file
(which names its certificate's PDF) and, with the key, by its signature.

Since schema version 8 every certificate issued has chain format 7 (the fields of format 4,
content form 2): its chain also covers the identity of its readings (``readings_key``), by
which the register looks up a certificate's readings issued again; set otherwise in the
database after issue, the register's opening finds it and issues nothing (hostile79 #2: it
laundered a copy of the readings as another item's certificate unseen until ``register
verify``). Records issued before keep their format; their identity, filled in by migration 8,
is made again from their readings by ``register verify``.

Since schema version 9 every certificate issued has chain format 8 (the fields of format 7):
its chain also covers the identity of its readings by their physical values
(``readings_layout``, ``readings_anchor``, ``readings_reach``: readings_identity.
readings_identity), by which the register finds the same readings issued again re-typed in
decimal degrees or in another unit (ident80); set otherwise in the database, the opening
finds it. Records issued before keep their format; their identity, filled in by migration
9, is made again from their readings by ``register verify``.

Anyone with write access can recompute the whole chain: the chain's head (``anglebench
register head``), noted outside the database, and the head printed on every certificate
(the head *before* it) anchor it (``anglebench register verify --head``).
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Mapping
from typing import Any

__all__ = ["CHAINED", "CHAINED_V2", "CHAINED_V3", "CHAINED_V4", "CHAINED_V5", "CHAINED_V6", "CONTENT",
           "CONTENT_MARK",
           "CONTENT_V2", "ENTRY_CHAINED", "GENESIS", "HEAD_MARK", "PROOF_MARK", "content_digest",
           "content_digest_v2", "content_form", "content_in_pdf", "dcc_body_digest", "head_in_pdf", "link",
           "link_entry", "number_in_pdf", "proof_in_pdf"]

#: a record's fields as issued, in the chain (status and superseded_by change later)
CHAINED = ("number", "issued_at", "issue_date", "calibration_date", "workbench",
           "item_description", "item_manufacturer", "item_serial", "customer", "operator",
           "workstation", "supersedes", "revision", "change_note", "project_json",
           "software_json", "headline_json", "pdf_sha256")
#: what a record of chain format 2 (schema version 4) adds to its chain
CHAINED_V2 = ("seq", "counter", "counter_value", "os_user", "approver")
#: what a record of chain format 3 (schema version 5: issued with a digital calibration
#: certificate) adds to chain format 2's: the DCC's SHA-256
CHAINED_V3 = ("dcc_sha256",)
#: what a record of chain format 4 (schema version 6: every record issued since) adds to
#: chain format 3's: what the document is, "calibration" or "test" (chain format 4 covers
#: the DCC's SHA-256 also when it is None: a record issued without a DCC)
CHAINED_V4 = ("document_kind",)
#: what a record of chain format 7 (schema version 8: every record issued since) adds to
#: chain format 4's: the identity of its readings (readings_identity.readings_key), which
#: the register looks them up by: set otherwise in the database it hid a record's readings
#: from the check of one item's readings issued as another's until 'register verify' made
#: every identity again (hostile79 #2); chained, the opening's check finds it and nothing
#: is issued into the register. Records of earlier formats (their identity filled in by
#: migration 8) are still compared with their readings by 'register verify'
CHAINED_V5 = ("readings_key",)
#: what a record of chain format 8 (schema version 9: every record issued since) adds to
#: chain format 7's: the identity of its readings by their physical values
#: (readings_identity.readings_identity: the layout, the anchor and its reach), by which the
#: register finds them issued again, re-typed too (ident80); set otherwise in the database,
#: the opening's check of the chain finds it, as format 7's readings_key
CHAINED_V6 = ("readings_layout", "readings_anchor", "readings_reach")
#: an entry's fields, all in the chain
ENTRY_CHAINED = ("seq", "kind", "subject", "body_json", "recorded_at", "os_user", "workstation")
GENESIS = "0" * 64


def _digest(previous: str, fields: Mapping[str, Any]) -> str:
    body = json.dumps(dict(fields), sort_keys=True, ensure_ascii=False, separators=(",", ":"))
    return hashlib.sha256(f"{previous}\n{body}".encode()).hexdigest()


def link(previous: str, record: Mapping[str, Any]) -> str:
    """The chain after the certificate ``record``, given the chain before it."""
    chain_format = record.get("chain_format") or 1
    keys = (CHAINED + (CHAINED_V2 if chain_format >= 2 else ())
            + (CHAINED_V3 if chain_format >= 3 else ())
            + (CHAINED_V4 if chain_format >= 4 else ())
            + (CHAINED_V5 if chain_format >= 7 else ())
            + (CHAINED_V6 if chain_format >= 8 else ()))
    # .get: a record set to format 7 (8) in a register read as it is at version 7 (8), which
    # has no column readings_key (readings_layout …), breaks its chain instead of the check
    fields = {k: record.get(k) if k in CHAINED_V5 or k in CHAINED_V6 else record[k]
              for k in keys}
    if chain_format >= 2:
        fields["chain_format"] = record["chain_format"]
    return _digest(previous, fields)


def link_entry(previous: str, entry: Mapping[str, Any]) -> str:
    """The chain after the entry ``entry`` (an interval, a withdrawal …)."""
    return _digest(previous, {"entry": {k: entry[k] for k in ENTRY_CHAINED}})


#: how a certificate's PDF carries the head before it, in its document information
#: (keywords), besides printing it
HEAD_MARK = "anglebench-register-head-before:"


#: a record's content as recorded, known before its PDF is rendered: what the digest its PDF
#: carries covers in content form 1 (chain format 5; form 2 adds :data:`CONTENT_V2`)
CONTENT = ("number", "issued_at", "issue_date", "calibration_date", "workbench",
           "item_description", "item_manufacturer", "item_serial", "customer", "operator",
           "workstation", "supersedes", "revision", "change_note", "project_json",
           "software_json", "headline_json", "seq", "counter", "counter_value", "os_user",
           "approver")
#: how a certificate's PDF (so the DCC, which embeds it) carries its record's content digest
CONTENT_MARK = "anglebench-record-content:"
#: how a certificate's PDF carries the proof that the register issued it, made with the
#: lab's key (models/register/signing.proof; AngleBench 0.8.22 on, keyed registers)
PROOF_MARK = "anglebench-register-proof:"


#: what content form 2 (chain format 6, AngleBench 0.8.22 on) adds to form 1: what the
#: document is and the DCC issued with it (its :func:`dcc_body_digest`, None for none)
CONTENT_V2 = ("document_kind", "dcc_body")


def content_form(record: Mapping[str, Any]) -> int:
    """Which form of content digest a record's PDF carries: 2 for chain format 6 on (AngleBench
    0.8.22 on: the document kind and the DCC covered), 1 for chain format 5 (0.8.21: the
    readings, results and details only), 0 for older records (their PDFs carry none)."""
    chain_format = record.get("chain_format") or 1
    return 2 if chain_format >= 6 else 1 if chain_format == 5 else 0


def content_digest(record: Mapping[str, Any], dcc: bytes | None = None,
                   form: int | None = None) -> str:
    """The SHA-256 of a record's content as recorded, in the record's form
    (:func:`content_form`; ``form`` to choose): form 1 of :data:`CONTENT`, form 2 also of
    :data:`CONTENT_V2`, with ``dcc`` the record's stored DCC (None: issued without one)."""
    form = form if form is not None else max(content_form(record), 1)
    if form < 2:
        return _digest("content", {k: record.get(k) for k in CONTENT})
    return content_digest_v2(record, None if dcc is None else dcc_body_digest(dcc))


def content_digest_v2(record: Mapping[str, Any], dcc_body: str | None) -> str:
    """The content digest in form 2 of ``record`` (its document kind among its fields) and
    its DCC's :func:`dcc_body_digest` (None: no DCC)."""
    fields = {k: record.get(k) for k in CONTENT}
    fields.update(document_kind=record.get("document_kind"), dcc_body=dcc_body)
    return _digest("content-2", fields)


def dcc_body_digest(dcc: bytes) -> str:
    """The SHA-256 of a DCC as issued, but for the PDF it embeds (its ``dataBase64`` texts
    emptied) and any XML signature (``ds:Signature`` left out; it covers the PDF): what is
    known of the DCC before its PDF is rendered, in canonical XML (C14N), so that its
    measurement results, names and numbers are covered. A DCC that cannot be read as XML is
    covered byte for byte."""
    from lxml import etree

    try:
        root = etree.fromstring(bytes(dcc), etree.XMLParser(
            resolve_entities=False, no_network=True, load_dtd=False, huge_tree=False))
    except (etree.XMLSyntaxError, ValueError):
        return hashlib.sha256(b"unreadable\n" + bytes(dcc)).hexdigest()
    for signature in root.findall("{http://www.w3.org/2000/09/xmldsig#}Signature"):
        root.remove(signature)
    for element in root.iter():
        if isinstance(element.tag, str) and etree.QName(element).localname == "dataBase64":
            element.text = ""
    return hashlib.sha256(etree.tostring(root, method="c14n")).hexdigest()


def content_in_pdf(data: bytes) -> str:
    """The record content digest a certificate's PDF carries (its keywords), or "" (issued
    before AngleBench 0.8.21, a draft, a specimen)."""
    import re

    found = re.search(CONTENT_MARK.encode() + rb"([0-9a-f]{64})", data)
    return found.group(1).decode() if found else ""


def proof_in_pdf(data: bytes) -> str:
    """The register's proof a certificate's PDF carries (its keywords), or "" (issued
    without the lab's key, or before AngleBench 0.8.22)."""
    import re

    found = re.search(PROOF_MARK.encode() + rb"([0-9a-f]{64})", data)
    return found.group(1).decode() if found else ""


def head_in_pdf(data: bytes) -> str:
    """The chain head a certificate's PDF carries (its keywords), or ""."""
    import re

    found = re.search(HEAD_MARK.encode() + rb"([0-9a-f]{64})", data)
    return found.group(1).decode() if found else ""


def number_in_pdf(data: bytes) -> str:
    """The certificate number a certificate's PDF names in its document information (its
    title, "Calibration certificate AB-2026-0001" in any language: the last word), or ""
    when it has no title that can be read (a number is never guessed further)."""
    import re

    found = re.search(rb"/Title\s*(?:<([0-9A-Fa-f\s]*)>|\(((?:\\.|[^\\)])*)\))", data,
                      re.DOTALL)
    if not found:
        return ""
    if found.group(1) is not None:
        try:
            raw = bytes.fromhex(found.group(1).decode("ascii"))
        except ValueError:
            return ""
    else:
        escapes = {b"n": b"\n", b"r": b"\r", b"t": b"\t", b"b": b"\b", b"f": b"\f"}
        raw = re.sub(rb"\\(.)", lambda m: escapes.get(m.group(1), m.group(1)),
                     found.group(2), flags=re.DOTALL)
    text = (raw[2:].decode("utf-16-be", "replace") if raw.startswith(b"\xfe\xff")
            else raw.decode("latin-1"))
    words = text.split()
    return words[-1] if len(words) > 1 else ""
