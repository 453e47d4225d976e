"""A DCC read in as a reference standard's certificate that this register issued: read only
as issued, and only while its certificate is current.

A polygon cross-calibrated here and its DCC read back as the reference of the next test
(``analyze polygon … --reference-dcc``, *Load polygon certificate…*, *Read from DCC…*):
the reader checks a supplier's DCC as far as its signature goes, but the register holds
this lab's own DCCs byte for byte. A copy with a face deviation edited (0.23″ → 3.23″, its U
made smaller) was read and a certificate issued citing the lab's certificate for figures it
never stated; a withdrawn certificate's DCC was read the same (hostile78 F4). A DCC is this
register's when its SHA-256 is an issued DCC's, when a PDF it embeds is an issued PDF, or
when it names a certificate number of this register with that certificate's laboratory.
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

from models.messages import QT_TR_NOOP, Message, message

__all__ = ["own_dcc_refusal", "own_dcc_refusal_at"]


def _named(data: bytes) -> tuple[str, str, list[bytes], list[str]]:
    """The DCC's certificate number, its laboratory's name, the PDFs it embeds and its
    item's identifications ("", "", [], [] for a document that cannot be read: the reader
    says why)."""
    from models.dcc.reader import DccError, embedded_pdfs, parse_dcc
    from models.dcc.vocabulary import DCC_NAMESPACE

    d = f"{{{DCC_NAMESPACE}}}"
    try:
        root = parse_dcc(data, "DCC")
        pdfs = embedded_pdfs(data)
    except DccError:
        return "", "", [], []
    number = (root.findtext(f".//{d}coreData/{d}uniqueIdentifier") or "").strip()
    lab = root.find(f".//{d}calibrationLaboratory/{d}contact")
    names = [] if lab is None else [
        (c.text or "").strip() for c in lab.iterfind(f"{d}name/{d}content")]
    serials = [(v.text or "").strip() for v in root.iterfind(
        f".//{d}items/{d}item/{d}identifications/{d}identification/{d}value")]
    return number, next((n for n in names if n), ""), pdfs, [s for s in serials if s]


def _same_lab(a: str, b: str) -> bool:
    """Two laboratory names that print alike, case and spaces aside."""
    from models.register.identifiers import same_identifier

    a, b = " ".join(a.split()), " ".join(b.split())
    return bool(a and b) and (a.casefold() == b.casefold() or same_identifier(a, b))


def _same_item(serials: list[str], record) -> bool:
    from models.register.identifiers import same_serial

    return bool(record.item_serial) and any(same_serial(s, record.item_serial)
                                            for s in serials)


def _lab_of(record) -> str:
    try:
        details = json.loads(record.project_json)["metadata"]["certificates"][record.workbench]
    except (TypeError, ValueError, KeyError):
        return ""
    return str(details.get("lab_name", "")) if isinstance(details, dict) else ""


def _record(register, number: str):
    from models.register.register_error import RegisterError

    try:
        return register.get(number)
    except (RegisterError, KeyError, LookupError):
        return None


def own_dcc_refusal(register: Any, data: bytes, source: str) -> Message | None:
    """Why the DCC ``data`` (read from ``source``) may not be read in as a standard's
    certificate: it is this register's (above) but not byte for byte the DCC it issued, or
    its certificate was withdrawn or superseded; None when it may (another laboratory's, or
    this register's as issued and current)."""
    digest = hashlib.sha256(data).hexdigest()
    issued = [n for n, what in register.issued_file(digest) if what == "dcc"]
    name = Path(source).name or source
    if issued:
        record = _record(register, issued[0])
    else:
        number, lab, pdfs, serials = _named(data)
        by_pdf = [n for pdf in pdfs for n, what in
                  register.issued_file(hashlib.sha256(pdf).hexdigest()) if what == "pdf"]
        record = _record(register, by_pdf[0]) if by_pdf else None
        named = _record(register, number) if number and record is None else None
        # this register's number under its laboratory's name, or for its item: another
        # laboratory numbering alike calibrates another item under another name
        if named is not None and (_same_lab(lab, _lab_of(named)) or _same_item(serials, named)):
            record = named
        if record is None:
            return None
        return message(QT_TR_NOOP(
            "{source} is a DCC of certificate {number}, which this register issued, but it is "
            "not the DCC it issued (its SHA-256 is no issued DCC's: altered since, or another "
            "certificate's PDF put inside): its figures are not the ones certified, so it is "
            "not read. Read the DCC as issued: anglebench register show {number} --dcc "
            "OUT.xml"), source=name, number=record.number)
    if record is None:
        return None
    if record.status == "withdrawn":
        return message(QT_TR_NOOP(
            "{source} is the DCC of certificate {number}, which was withdrawn ({reason}): a "
            "withdrawn certificate calibrates nothing, so it is not read as a standard's "
            "certificate"), source=name, number=record.number,
            reason=record.withdrawn_reason or "—")
    if record.status == "superseded":
        return message(QT_TR_NOOP(
            "{source} is the DCC of certificate {number}, which was superseded by {by}: read "
            "the DCC of {by} (anglebench register show {by} --dcc OUT.xml)"),
            source=name, number=record.number, by=record.superseded_by or "—")
    return None


def own_dcc_refusal_at(url: str, path: str) -> Message | None:
    """:func:`own_dcc_refusal` of the DCC file ``path`` against the register at ``url``; None
    where there is no register there yet (a SQLite file not made: nothing issued, and none
    is made by reading a DCC), or the file cannot be read (the reader says why)."""
    from models.register.store import Register

    if url.startswith("sqlite:///") and not Path(url.removeprefix("sqlite:///")).exists():
        return None
    try:
        data = Path(path).read_bytes()
    except OSError:
        return None
    with Register(url) as register:
        return own_dcc_refusal(register, data, path)
