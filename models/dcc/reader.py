"""DCC in: a reference standard's digital calibration certificate (PTB DCC 3.3.0, D-SI)
read as its certificate. Pure: lxml only, no Qt.

- :func:`read_polygon_dcc`: a polygon's calibration (the ``anglebench_polygonFaceDeviations``
  result: face indices 1…N and each face's deviation with its expanded uncertainty), as the
  polygon workbench takes it in place of the readings' deviation column. Never a reference
  polygon's deviations that an encoder's DCC restates
  (``anglebench_referencePolygonFaceDeviations``, or in a document of 0.8.11 and before the
  old refType under that result's name): such a DCC is refused, naming the polygon's own
  certificate as it lists it.
- :func:`read_standard_dcc`: any standard's certificate (any maker's): its id
  (``coreData/uniqueIdentifier``), calibration date (``endPerformanceDate``), the largest
  expanded uncertainty of the results that are the standard's errors (or deviations, or
  measured values) — not of a fitted set-up parameter — and its due date when a validity
  statement gives one.

Every refusal is a :class:`DccError` naming the file and why: the schema (when a folder is
given), a unit that is not an angle (\\arcsecond, \\arcminute, \\degree, \\radian with
\\milli, \\micro or \\nano are converted exactly to arcseconds), a face count that does not
fit, a signature that does not verify, no signature where a trusted certificate is set, a
calibration that expired before the measurement or is dated after it, a validity period past
the year 9999, a coverage factor below 1 or against its probability, a face's deviation or U
no polygon has, no polygon result, an encoder's DCC whose only polygon is its reference. The
DCC's item (name, serials) is read: :func:`item_notes` refuses a DCC of another item than
the standard it is read for. The XML is parsed
with no network, no entity resolution, no DTD and no huge-tree mode, and a document that
declares a DTD at all is refused: a hostile file can neither read local files nor expand
entities.
"""

from __future__ import annotations

import base64
import binascii
import datetime as dt
import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

from models.dcc.vocabulary import (
    DCC_NAMESPACE,
    DS_NAMESPACE,
    POLYGON_ENCODER_TEST_NAMES,
    PTB_MEASURED_VALUE,
    PTB_MEASUREMENT_ERROR,
    PTB_NOMINAL_VALUE,
    PTB_REFERENCE_VALUE,
    REFERENCE_POLYGON_RESULT_NAMES,
    REFTYPE_BUDGET,
    REFTYPE_FACE_DEVIATION,
    REFTYPE_FACE_INDEX,
    REFTYPE_POLYGON_FACE_DEVIATIONS,
    REFTYPE_REFERENCE_POLYGON_FACE_DEVIATIONS,
    REFTYPE_SETUP_PARAMETERS,
    REFTYPE_STANDARD_DUE,
    REFTYPE_SUMMARY,
    REFTYPE_VALIDITY,
    SI_NAMESPACE,
)
from models.messages import QT_TR_NOOP, listed, message, reason_of

if TYPE_CHECKING:
    from lxml.etree import _Element  # (lxml ships no types: pyproject.toml [tool.mypy])

__all__ = ["ARCSEC_PER_UNIT", "PLAUSIBLE_ARCSEC", "DccError", "is_u95", "item_notes", "PolygonReference",
           "StandardCertificate",
           "POLYGON_FACE_DEVIATIONS", "angle_factor", "embedded_pdfs", "parse_dcc", "parse_decimal_list",
           "place_polygon_standard", "polygon_standard", "read_polygon_dcc",
           "read_standard_dcc", "replace_face_deviations"]

D = f"{{{DCC_NAMESPACE}}}"
S = f"{{{SI_NAMESPACE}}}"
#: the largest DCC read (an embedded PDF makes a few MB; more is no certificate)
MAX_BYTES = 64 * 1024 * 1024

#: arcseconds per D-SI angle unit (exact: 1° = 3600", 1′ = 60", 1 rad = 648000/π ")
ARCSEC_PER_UNIT = {r"\arcsecond": 1.0, r"\arcminute": 60.0, r"\degree": 3600.0,
                   r"\radian": 648000.0 / math.pi}
_PREFIXES = {"": 1.0, r"\milli": 1e-3, r"\micro": 1e-6, r"\nano": 1e-9}
#: micrometres per D-SI length unit (a standard's U may be a length: gauge blocks, scales)
UM_PER_UNIT = {r"\metre": 1e6, r"\milli\metre": 1e3, r"\micro\metre": 1.0, r"\nano\metre": 1e-3}
_DECIMAL = re.compile(r"[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?")


class DccError(ValueError):
    """A DCC that cannot be read as the certificate asked for; the message says why."""


@dataclass(frozen=True)
class PolygonReference:
    """A polygon's face deviations from its DCC, in arcseconds, face 1…N."""

    deviations: dict[int, float]
    expanded_uncertainty: dict[int, float]  # U per face (")
    coverage_factor: float
    coverage_probability: float
    certificate_id: str
    calibration_date: str  # YYYY-MM-DD
    due_date: str  # YYYY-MM-DD, "" when the DCC states none
    source: str = ""
    signer: str = ""  # the signature's certificate subject, "" when unsigned
    notes: tuple = field(default_factory=tuple)  # what the caller should say (unsigned …)
    item_name: str = ""  # the item the DCC calibrates (dcc:items), "" when it names none
    item_serials: tuple = field(default_factory=tuple)  # its identifications' values

    @property
    def faces(self) -> int:
        return len(self.deviations)

    @property
    def largest_u(self) -> float:
        return max(self.expanded_uncertainty.values())


@dataclass(frozen=True)
class StandardCertificate:
    """What a standards table takes from a standard's DCC."""

    certificate_id: str
    calibration_date: str
    due_date: str  # "" when not stated
    uncertainty: float | None  # the largest expanded U of its errors' results, in ``unit``
    unit: str  # "arcsec" or "um" (keys of models.quantity.UNITS)
    coverage_factor: float | None
    coverage_probability: float | None
    source: str = ""
    signer: str = ""
    notes: tuple = field(default_factory=tuple)
    item_name: str = ""  # the item the DCC calibrates (dcc:items), "" when it names none
    item_serials: tuple = field(default_factory=tuple)  # its identifications' values
    applies_to: str = "reading"  # "from face 1" where its polygon's face 1 is exact
    polygon: bool = False  # its U is a polygon's face deviations', or its item a polygon

    def for_standard(self, description: str, serial: str) -> tuple[dict, tuple]:
        """The fields a standards row listed as ``description``, ``serial`` takes from this
        DCC (:meth:`as_standard` with the serial) and what to say; DccError, nothing to
        take, when the DCC is another item's: its serial differs (:func:`item_notes`), or it
        is a polygon's and the row names another standard."""
        taken, said = item_notes(serial, self.certificate_id, self.item_name,
                                 self.item_serials, self.source)
        if self.polygon and description.strip() and not _POLYGON_WORDS.search(description):
            raise DccError(message(QT_TR_NOOP(
                "{source}: certificate {id} calibrates a polygon ({item}); the row it is read "
                "into is {description}: it is not read (select the polygon's row)"),
                source=self.source, id=self.certificate_id, item=self.item_name or "?",
                description=description.strip()))
        return {**self.as_standard(), "serial": taken}, said

    def as_standard(self) -> dict:
        """The standards table's fields (a ReferenceStandard's keys), every one the DCC
        speaks to, so that a row takes them as a whole (nothing of the certificate it
        replaces stays): the number, the due date ("" none stated), U with its k as U95
        when k = 2, else as the standard uncertainty U/k (exact either way), what it is per
        — U, basis and unit empty where the DCC states no U."""
        out: dict = {"certificate_no": self.certificate_id, "due_date": self.due_date,
                     "uncertainty": "", "basis": "", "uncertainty_unit": "",
                     "applies_to": self.applies_to}
        if self.uncertainty is not None:
            k = self.coverage_factor or 2.0
            if is_u95(k, self.coverage_probability):
                out.update(uncertainty=self.uncertainty, basis="U95")
            else:
                out.update(uncertainty=self.uncertainty / k, basis="u")
            out["uncertainty_unit"] = self.unit
        return out


def is_u95(k: float, p: float | None) -> bool:
    """Whether a U stated with ``k`` and ``p`` is listed as U95 (k = 2 at about 95 %: p from
    0.945 to 0.955, 0.9545 the normal's): a k of 2 with another p (0.90, its effective
    degrees of freedom few) is listed as U/k with its k, never labelled 95 %."""
    return abs(k - 2.0) < 1e-12 and (p is None or 0.945 <= p <= 0.955)


# -- parsing -----------------------------------------------------------------------------
def _parser():
    from lxml import etree

    return etree.XMLParser(resolve_entities=False, no_network=True, huge_tree=False,
                           load_dtd=False, dtd_validation=False, remove_comments=True)


def parse_dcc(data: bytes, source: str = "") -> _Element:
    """The document's root element, parsed safely; DccError naming ``source`` for a file
    that is not XML, too large, or that declares a DTD (a DCC never does: entities, local
    files and network are never resolved)."""
    from lxml import etree

    if len(data) > MAX_BYTES:
        raise DccError(message(QT_TR_NOOP("{source}: {mb} MB: too large for a calibration "
                                          "certificate"), source=source,
                               mb=len(data) // (1024 * 1024)))
    try:
        root = etree.fromstring(data, _parser())
    except etree.XMLSyntaxError as exc:
        raise DccError(message(QT_TR_NOOP("{source}: not an XML document ({reason})"),
                               source=source, reason=str(exc))) from None
    docinfo = root.getroottree().docinfo
    if docinfo.doctype or docinfo.internalDTD is not None or docinfo.externalDTD is not None:
        raise DccError(message(QT_TR_NOOP(
            "{source}: the document declares a DTD (entities): a DCC has none; it is not read"),
            source=source))
    if root.tag != f"{D}digitalCalibrationCertificate":
        raise DccError(message(QT_TR_NOOP(
            "{source}: not a digital calibration certificate (the root is {tag}, not "
            "dcc:digitalCalibrationCertificate of {namespace})"), source=source,
            tag=_local(root.tag), namespace=DCC_NAMESPACE))
    return root


def _local(tag) -> str:
    return str(tag).rsplit("}", 1)[-1]


def _path(element) -> str:
    """The element's path, for messages (``dcc:measurementResults/…``)."""
    parts = []
    while element is not None:
        parts.append(_local(element.tag))
        element = element.getparent()
    return "/".join(reversed(parts))


def _has_reftype(element, reftype: str) -> bool:
    return reftype in (element.get("refType") or "").split()


def parse_decimal_list(text: str, where: str = "") -> list[float]:
    """A D-SI XML list of decimals (blank-separated) as floats; DccError for an entry that
    is not a finite decimal."""
    values = []
    for i, word in enumerate((text or "").split(), 1):
        if not _DECIMAL.fullmatch(word):
            raise DccError(message(QT_TR_NOOP("{where}: entry {i} '{word}' is not a decimal "
                                              "number"), where=where, i=i, word=word[:40]))
        value = float(word)
        if not math.isfinite(value):
            raise DccError(message(QT_TR_NOOP("{where}: entry {i} '{word}' is out of range"),
                                   where=where, i=i, word=word[:40]))
        values.append(value)
    return values


def angle_factor(unit: str) -> float | None:
    """Arcseconds per ``unit`` (a D-SI unit string: \\arcsecond, \\degree, \\micro\\radian …),
    None when it is no angle unit AngleBench converts."""
    unit = unit.strip()
    for prefix, scale in _PREFIXES.items():
        for name, factor in ARCSEC_PER_UNIT.items():
            if unit == prefix + name and (not prefix or name == r"\radian"):
                return scale * factor
    return None


def _broadcast(values: list[float], n: int, where: str) -> list[float]:
    """A list given once for all (length 1) or once per value (length n)."""
    if len(values) == n:
        return values
    if len(values) == 1:
        return values * n
    raise DccError(message(QT_TR_NOOP("{where}: {m} entries for {n} values"), where=where,
                           m=len(values), n=n))


def _units(element, n: int, where: str) -> list[str]:
    units = (element.findtext(f"{S}unitXMLList") or "").split()
    if not units:
        raise DccError(message(QT_TR_NOOP("{where}: no unit"), where=where))
    if len(units) == 1:
        return units * n
    if len(units) != n:
        raise DccError(message(QT_TR_NOOP("{where}: {m} units for {n} values"), where=where,
                               m=len(units), n=n))
    return units


@dataclass(frozen=True)
class _Uncertainty:
    values: list[float]  # expanded U, in the quantity's unit
    k: list[float]
    p: list[float]


def _expanded(element, n: int, where: str, source: str = "") -> _Uncertainty | None:
    """The expanded uncertainty of a si:realListXMLList (or of a si:real, n = 1): D-SI's
    expandedMU(XMLList), or the deprecated expandedUnc(XMLList)."""
    for mu, value, k, p in (
            ("expandedMUXMLList", "valueExpandedMUXMLList", "coverageFactorXMLList",
             "coverageProbabilityXMLList"),
            ("expandedUncXMLList", "uncertaintyXMLList", "coverageFactorXMLList",
             "coverageProbabilityXMLList"),
            ("expandedMU", "valueExpandedMU", "coverageFactor", "coverageProbability"),
            ("expandedUnc", "uncertainty", "coverageFactor", "coverageProbability")):
        found = element.find(f".//{S}{mu}")
        if found is None:
            continue
        here = f"{where}/{mu}"
        values = _broadcast(parse_decimal_list(found.findtext(f"{S}{value}") or "",
                                               f"{here}/{value}"), n, f"{here}/{value}")
        ks = _broadcast(parse_decimal_list(found.findtext(f"{S}{k}") or "", f"{here}/{k}"),
                        n, f"{here}/{k}")
        ps = _broadcast(parse_decimal_list(found.findtext(f"{S}{p}") or "", f"{here}/{p}"),
                        n, f"{here}/{p}")
        if any(v < 0 for v in values) or any(x <= 0 for x in ks) or any(
                not 0 < x <= 1 for x in ps):
            raise DccError(message(QT_TR_NOOP(
                "{where}: an expanded uncertainty below 0, a coverage factor not above 0 or a "
                "coverage probability outside (0, 1]"), where=here))
        for k_, p_ in dict.fromkeys(zip(ks, ps, strict=True)):
            _check_coverage(k_, p_, here, source)
        return _Uncertainty(values, ks, ps)
    return None


#: the fewest effective degrees of freedom a coverage factor is taken for (GUM G.3: t_p(ν)
#: with ν = 2 is the largest k a stated p can come with; ν → ∞ the normal's, the smallest)
_FEWEST_DEGREES = 2
#: how far below the normal's k(p) a stated k may be (p rounded: k = 1.96 with p = 0.9545)
_K_ROUNDING = 0.02


def _check_coverage(k: float, p: float, where: str, source: str = "") -> None:
    """DccError when a coverage factor is below 1 (an expanded uncertainty smaller than the
    standard uncertainty) or does not go with its coverage probability: below the normal
    distribution's k for p, or above Student's t for p with 2 degrees of freedom (k = 2
    with p = 0.5 or 0.68, k = 1 with p = 0.95). p = 1 (a bounded distribution) takes any
    k from 1."""
    if k < 1:
        raise DccError(message(QT_TR_NOOP(
            "{source}: {where}: the coverage factor k = {k:g} is below 1: an expanded "
            "uncertainty is never smaller than the standard uncertainty"), source=source,
            where=where, k=k))
    if p >= 1:
        return
    from models.uncertainty.budget import coverage_factor  # the budget's own k from p

    low = coverage_factor(math.inf, p) * (1 - _K_ROUNDING)
    high = coverage_factor(_FEWEST_DEGREES, p)
    if not low <= k <= high:
        raise DccError(message(QT_TR_NOOP(
            "{source}: {where}: the coverage factor k = {k:g} and the coverage probability "
            "p = {p:g} contradict each other (p = {p:g} goes with k from {low:.2f} to "
            "{high:.2f}): which one the certificate means cannot be told"), source=source,
            where=where, k=k, p=p,
            low=low / (1 - _K_ROUNDING), high=high))


def _real_list(quantity, where: str) -> tuple[list[float], list[str], _Element]:
    element = quantity.find(f"{S}realListXMLList")
    if element is None:
        raise DccError(message(QT_TR_NOOP("{where}: no si:realListXMLList"), where=where))
    values = parse_decimal_list(element.findtext(f"{S}valueXMLList") or "",
                                f"{where}/valueXMLList")
    if not values:
        raise DccError(message(QT_TR_NOOP("{where}: no values"), where=where))
    return values, _units(element, len(values), where), element


def _to_arcsec(values: list[float], units: list[str], source: str, where: str) -> list[float]:
    out = []
    for value, unit in zip(values, units, strict=True):
        factor = angle_factor(unit)
        if factor is None:
            raise DccError(message(QT_TR_NOOP(
                "{source}: {where}: the unit {unit} is not an angle (\\arcsecond, \\arcminute, "
                "\\degree or \\radian are read)"), source=source, where=where, unit=unit))
        converted = value * factor
        if not math.isfinite(converted):
            raise DccError(message(QT_TR_NOOP(
                "{source}: {where}: {value:g} {unit} is out of range"), source=source,
                where=where, value=value, unit=unit))
        out.append(converted)
    return out


#: the largest angle the reader takes as a polygon face's deviation or an angle standard's U
#: (as the readings' columns and the details' standards take, in arcseconds)
PLAUSIBLE_ARCSEC = 3600.0


def _check_plausible(values: dict[int, float], what: str, source: str, certificate_id: str,
                     positive: bool = False) -> None:
    """DccError naming the DCC, its certificate and the face when a value is beyond
    ±PLAUSIBLE_ARCSEC (or, ``positive``, an uncertainty not above 0 on every face)."""
    for face, value in sorted(values.items()):
        if abs(value) > PLAUSIBLE_ARCSEC:
            raise DccError(message(QT_TR_NOOP(
                "{source}: certificate {id}, face {face}: {what} {value:g}″ is beyond "
                "±{limit:g}″: not a polygon's; the DCC is not read"), source=source,
                id=certificate_id, face=face, what=message(what), value=value,
                limit=PLAUSIBLE_ARCSEC))
    if positive and not any(v > 0 for v in values.values()):
        raise DccError(message(QT_TR_NOOP(
            "{source}: certificate {id}: the expanded uncertainty is 0 on every face: no "
            "calibration achieves that; the DCC is not read"), source=source,
            id=certificate_id))


def _date(text: str | None, source: str, where: str) -> str:
    text = (text or "").strip()
    try:
        # a date (xs:date may carry a time zone: 2026-11-20Z, 2026-11-20+01:00), no more
        if text and not re.fullmatch(r"\d{4}-\d{2}-\d{2}(Z|[+-]\d{2}:\d{2})?", text):
            raise ValueError(text)
        return dt.date.fromisoformat(text[:10]).isoformat() if text else ""
    except ValueError:
        raise DccError(message(QT_TR_NOOP("{source}: {where}: '{text}' is not a date"),
                               source=source, where=where, text=text[:40])) from None


def _duration_days(text: str) -> tuple[int, int, int] | None:
    """(years, months, days) of an xs:duration of whole years, months and days (P1Y, P18M,
    P1Y6M, P365D); None for any other."""
    found = re.fullmatch(r"P(?:(\d+)Y)?(?:(\d+)M)?(?:(\d+)D)?", (text or "").strip())
    if not found or not any(found.groups()):
        return None
    return tuple(int(g or 0) for g in found.groups())  # type: ignore[return-value]


def _add(date: dt.date, years: int, months: int, days: int) -> dt.date:
    month = date.month - 1 + months + 12 * years
    year, month = date.year + month // 12, month % 12 + 1
    import calendar

    day = min(date.day, calendar.monthrange(year, month)[1])
    return dt.date(year, month, day) + dt.timedelta(days=days)


def _core(root, source: str) -> tuple[str, str]:
    core = root.find(f"{D}administrativeData/{D}coreData")
    if core is None:
        raise DccError(message(QT_TR_NOOP("{source}: no dcc:coreData"), source=source))
    certificate_id = (core.findtext(f"{D}uniqueIdentifier") or "").strip()
    if not certificate_id:
        raise DccError(message(QT_TR_NOOP("{source}: no dcc:uniqueIdentifier (the certificate "
                                          "number)"), source=source))
    return certificate_id, _date(core.findtext(f"{D}endPerformanceDate"), source,
                                 "coreData/endPerformanceDate")


def _item(root) -> tuple[str, tuple[str, ...]]:
    """The name of the item the DCC calibrates and the values of its identifications
    (serial numbers …); ("", ()) when dcc:items names none."""
    items = root.findall(f"{D}administrativeData/{D}items/{D}item")
    name = next((n for n in (_name_of(i) for i in items) if n), "")
    serials = tuple(dict.fromkeys(
        " ".join((ident.findtext(f"{D}value") or "").split())
        for item in items for ident in item.iterfind(f"{D}identifications/{D}identification")))
    return name, tuple(s for s in serials if s)


def _same_serial(a: str, b: str) -> bool:
    return "".join(a.split()).casefold() == "".join(b.split()).casefold()


def item_notes(serial: str, certificate_id: str, item_name: str, item_serials: tuple,
               source: str) -> tuple[str, tuple]:
    """The serial a standard read from a DCC is listed with, and what to say: the listed
    ``serial`` when the DCC's item names it; the DCC's own when none is listed (said). A
    DccError naming both when the DCC calibrates another item (the serials differ); a note
    when the DCC names no serial (nothing to compare)."""
    item = item_name or "?"
    if not item_serials:
        return serial, (message(QT_TR_NOOP(
            "{source}: certificate {id} names no serial number of its item ({item}): check "
            "that it is the standard's"), source=source, id=certificate_id, item=item),)
    if not serial.strip():
        taken = item_serials[0]
        return taken, (message(QT_TR_NOOP(
            "{source}: the standard's serial number was not listed: {serial} is taken from "
            "certificate {id} ({item})"), source=source, serial=taken, id=certificate_id,
            item=item),)
    if any(_same_serial(serial, s) for s in item_serials):
        return serial, ()
    raise DccError(message(QT_TR_NOOP(
        "{source}: certificate {id} calibrates {item}, serial {theirs}; the standard it is read "
        "for is serial {ours}: it is another item's certificate and is not read (correct the "
        "serial in the details if the DCC is this standard's)"), source=source,
        id=certificate_id, item=item, theirs=listed(item_serials), ours=serial))


def _due_date(root, calibration_date: str, source: str) -> str:
    """The due date a validity statement gives: its dcc:date, or the calibration date plus
    its dcc:period; "" when no statement gives one."""
    statements = root.findall(f"{D}administrativeData/{D}statements/{D}statement")
    for statement in statements:
        reftypes = (statement.get("refType") or "").split()
        if not (REFTYPE_VALIDITY in reftypes or REFTYPE_STANDARD_DUE in reftypes
                or any("validity" in r.lower() or "recalibration" in r.lower()
                       for r in reftypes)):
            continue
        date = _date(statement.findtext(f"{D}date"), source, "statement/date")
        if date:
            return date
        period = _duration_days(statement.findtext(f"{D}period") or "")
        if period and calibration_date:
            try:
                return _add(dt.date.fromisoformat(calibration_date), *period).isoformat()
            except (ValueError, OverflowError):
                raise DccError(message(QT_TR_NOOP(
                    "{source}: the validity period {period} from {date} ends after the "
                    "year 9999: no calibration is valid that long; the DCC is not read"),
                    source=source, period=(statement.findtext(f"{D}period") or "").strip()[:40],
                    date=calibration_date)) from None
    return ""


def _states_validity(root) -> bool:
    """Whether a statement of the DCC is its validity (AngleBench's own say: the results
    relate to the calibration's time, with no due date)."""
    return any(REFTYPE_VALIDITY in (s.get("refType") or "").split()
               for s in root.findall(f"{D}administrativeData/{D}statements/{D}statement"))


def _check_schema(data: bytes, schema_dir: str | Path | None, source: str) -> None:
    if not schema_dir:
        return
    problems = _schema_problems(data, Path(schema_dir))
    if problems:
        raise DccError(message(QT_TR_NOOP(
            "{source}: not a valid DCC 3.3.0 document ({problem})"), source=source,
            problem=problems[0]))


def _schema_problems(data: bytes, folder: Path) -> list[str]:
    """The schema's objections to ``data`` (element path and reason), from the schema set in
    ``folder`` read offline (models/dcc/schema.py, the one the writer validates with)."""
    from models.dcc.schema import DccSchemaError, validate

    try:
        return validate(data, folder)
    except DccSchemaError as exc:
        raise DccError(reason_of(exc)) from None


def _verify_signature(data: bytes, root, trusted_cert: bytes | None, source: str,
                      trust_named: bool = True) -> tuple[_Element, str, tuple]:
    """The root to read (what the signature covers) and the signer; DccError when a
    signature is there and does not verify, or is missing where ``trusted_cert`` is a trust
    named for the DCCs read (``trust_named``, models.dcc.signature.signature_demanded). A
    ``trusted_cert`` not so named (the lab's own signing certificate, the fallback) demands
    no signature and checks one it did not make against the certificate it carries.
    Unsigned otherwise: the root as parsed."""
    if root.find(f"{{{DS_NAMESPACE}}}Signature") is None and root.find(
            f".//{{{DS_NAMESPACE}}}Signature") is None:
        if trust_named and trusted_cert is not None:
            raise DccError(message(QT_TR_NOOP(
                "{source}: signature missing: a trusted certificate is configured, and this "
                "DCC is not signed (a signature removed is not seen otherwise); it is not "
                "read"), source=source))
        return root, "", ()
    from models.dcc.signature import verify

    check = verify(data, trusted_cert)
    if check.problems and trusted_cert is not None and not trust_named:
        # the lab's own signing certificate (the fallback, not a trust named for the DCCs
        # read) did not sign a supplier's DCC: its signature is checked against the
        # certificate it carries, as where none is set — unchanged since signed, the signer
        # named and said unchecked (a supplier's signed DCC was refused as not verifying)
        carried = verify(data, None)
        if not carried.problems:
            check = carried
    if check.problems:
        raise DccError(message(QT_TR_NOOP("{source}: {reason}; it is not read"),
                               source=source, reason=check.problems[0]))
    signed = parse_dcc(check.signed_xml, source) if check.signed_xml else root
    notes = () if check.trusted else (message(QT_TR_NOOP(
        "{source}: signed by {signer}; the document is unchanged since, but the signer was "
        "not checked against a trusted certificate"), source=source,
        signer=check.signer or "?"),)
    return signed, check.signer, notes


def _load(path: str | Path, schema_dir, trusted_cert, trust_named: bool = True
          ) -> tuple[_Element, str, str, tuple]:
    source = str(path)
    try:
        size = Path(path).stat().st_size
        if size > MAX_BYTES:  # told before the file is read
            raise DccError(message(QT_TR_NOOP("{source}: {mb} MB: too large for a calibration "
                                              "certificate"), source=source,
                                   mb=size // (1024 * 1024)))
        data = Path(path).read_bytes()
    except OSError as exc:
        raise DccError(message(QT_TR_NOOP("{source}: cannot read ({reason})"), source=source,
                               reason=exc.strerror or str(exc))) from None
    root = parse_dcc(data, source)
    _check_schema(data, schema_dir, source)
    root, signer, notes = _verify_signature(data, root, trusted_cert, source, trust_named)
    return root, source, signer, notes


def _check_due(due_date: str, measurement_date: str | dt.date | None, source: str,
               certificate_id: str, calibration_date: str = "",
               validity_stated: bool = False) -> tuple:
    """DccError for a calibration dated after the measurement or due before it; with no due
    date, a note saying the calibration's date and age (the lab's interval decides)."""
    when = ""
    if measurement_date:
        when = (measurement_date.isoformat() if isinstance(measurement_date, dt.date)
                else str(measurement_date))
    if when and calibration_date and calibration_date > when:
        raise DccError(message(QT_TR_NOOP(
            "{source}: certificate {id} was calibrated on {date}, after the measurement on "
            "{when}: it cannot be the calibration the measurement used"), source=source,
            id=certificate_id, date=calibration_date, when=when))
    if not due_date:
        if calibration_date:
            end = dt.date.fromisoformat(when[:10]) if when else dt.date.today()
            days = (end - dt.date.fromisoformat(calibration_date)).days
            age = message(QT_TR_NOOP("{years:.1f} years"), years=max(days, 0) / 365.25)
        why = (QT_TR_NOOP("its validity statement gives no due date") if validity_stated
               else QT_TR_NOOP("no validity statement"))
        if calibration_date:
            return (message(QT_TR_NOOP(
                "{source}: certificate {id} calibrated {date}, {age} before the measurement, "
                "states no due date ({why}): check it against the standard's calibration "
                "interval"), source=source, id=certificate_id, date=calibration_date,
                age=age, why=message(why)),)
        return (message(QT_TR_NOOP("{source}: certificate {id} states no due date ({why}) and "
                                   "no calibration date: check the calibration interval "
                                   "yourself"), source=source, id=certificate_id,
                        why=message(why)),)
    if when and due_date < when:
        raise DccError(message(QT_TR_NOOP(
            "{source}: certificate {id} was due for recalibration on {due}, before the "
            "measurement on {when}: the calibration had expired"), source=source,
            id=certificate_id, due=due_date, when=when))
    return ()


# -- a polygon's certificate -------------------------------------------------------------
def _names(element) -> set[str]:
    """Every language's dcc:name of ``element``, blanks collapsed."""
    return {" ".join((c.text or "").split()) for c in element.findall(f"{D}name/{D}content")}


def _is_reference_polygon(result) -> bool:
    """Whether a dcc:result is a reference polygon's face deviations (the polygon an encoder
    was calibrated against, as its own certificate states them), not a polygon calibrated:
    its refType says so; or, in a document of 0.8.11 and before (which gave it the calibrated
    polygon's refType), its name in any language is the one AngleBench gave it, or the
    measurement it belongs to is a polygon encoder test (no polygon is calibrated there)."""
    if _has_reftype(result, REFTYPE_REFERENCE_POLYGON_FACE_DEVIATIONS):
        return True
    if not _has_reftype(result, REFTYPE_POLYGON_FACE_DEVIATIONS):
        return False
    if _names(result) & set(REFERENCE_POLYGON_RESULT_NAMES):
        return True
    measurement = next(result.iterancestors(f"{D}measurementResult"), None)
    return measurement is not None and bool(_names(measurement)
                                            & set(POLYGON_ENCODER_TEST_NAMES))


_FROM_FACE_1 = re.compile(r"from face 1|以第 ?1 ?面为基准|相对第 ?1 ?面", re.IGNORECASE)


def _reference_polygon_certificates(root) -> list[str]:
    """The certificate numbers of the polygon the DCC lists among its standards (its
    measuringEquipments): the one whose stated uncertainty is per face from face 1 (the
    standard the polygon workbench takes the reference's U from), else one whose name
    names a polygon; [] when it lists none with a number."""
    by_face, by_name = [], []
    for equipment in root.iterfind(f"{D}measurementResults/{D}measurementResult/"
                                   f"{D}measuringEquipments/{D}measuringEquipment"):
        number = " ".join((equipment.findtext(f"{D}certificate/{D}referralID")
                           or equipment.findtext(f"{D}certificate/{D}value") or "").split())
        if not number:
            continue
        stated = [q for q in equipment.iter(f"{D}measuringEquipmentQuantity")
                  if any(_FROM_FACE_1.search(name) for name in _names(q))]
        if stated:
            by_face.append(number)
        elif any(_POLYGON_WORDS.search(name) for name in _names(equipment)):
            by_name.append(number)
    return list(dict.fromkeys(by_face or by_name))


def _an_encoders_dcc(root, source: str, certificate_id: str) -> DccError:
    """The refusal of a DCC whose polygon result is only the reference polygon's."""
    numbers = _reference_polygon_certificates(root)
    if numbers:
        return DccError(message(QT_TR_NOOP(
            "{source}: certificate {id} calibrates an encoder against a reference polygon, not "
            "the polygon: the face deviations in it are the reference polygon's, restated from "
            "its own certificate {reference} (as this DCC lists the standard); read that "
            "certificate's DCC as the polygon's"), source=source, id=certificate_id,
            reference=listed(numbers)))
    return DccError(message(QT_TR_NOOP(
        "{source}: certificate {id} calibrates an encoder against a reference polygon, not the "
        "polygon: the face deviations in it are the reference polygon's, restated from its own "
        "certificate, which this DCC does not name; read that certificate's DCC as the "
        "polygon's"), source=source, id=certificate_id))


def read_polygon_dcc(path: str | Path, schema_dir: str | Path | None = None, *,
                     measurement_date: str | dt.date | None = None,
                     faces: int | None = None,
                     trusted_cert: bytes | None = None,
                     trust_named: bool = True) -> PolygonReference:
    """A polygon's face deviations and their U (arcseconds) from its DCC. ``faces``: the
    readings' face count (refused when the DCC's differs); ``measurement_date``: refused
    when the calibration was due before it. DccError naming the file and why."""
    root, source, signer, notes = _load(path, schema_dir, trusted_cert, trust_named)
    certificate_id, calibration_date = _core(root, source)
    results = [r for r in root.iter(f"{D}result") if _has_reftype(
        r, REFTYPE_POLYGON_FACE_DEVIATIONS) and not _is_reference_polygon(r)]
    if not results and any(_is_reference_polygon(r) for r in root.iter(f"{D}result")):
        raise _an_encoders_dcc(root, source, certificate_id)
    if not results:
        raise DccError(message(QT_TR_NOOP(
            "{source}: no polygon result found (a dcc:result of refType {reftype} with the face "
            "indices and deviations)"), source=source, reftype=REFTYPE_POLYGON_FACE_DEVIATIONS))
    if len(results) > 1:
        raise DccError(message(QT_TR_NOOP(
            "{source}: {n} polygon results: which one is the polygon's is not clear"),
            source=source, n=len(results)))
    result = results[0]
    quantities = list(result.iter(f"{D}quantity"))
    index_q = [q for q in quantities if _has_reftype(q, REFTYPE_FACE_INDEX)]
    deviation_q = [q for q in quantities if _has_reftype(q, REFTYPE_FACE_DEVIATION)]
    if len(index_q) != 1 or len(deviation_q) != 1:
        raise DccError(message(QT_TR_NOOP(
            "{source}: the polygon result needs one quantity of refType {index} and one of "
            "{deviation} (found {i} and {d})"), source=source, index=REFTYPE_FACE_INDEX,
            deviation=REFTYPE_FACE_DEVIATION, i=len(index_q), d=len(deviation_q)))
    where_i, where_d = _path(index_q[0]), _path(deviation_q[0])
    indices, _units_i, _ = _real_list(index_q[0], where_i)
    values, units, element = _real_list(deviation_q[0], where_d)
    n = len(values)
    if len(indices) != n:
        raise DccError(message(QT_TR_NOOP(
            "{source}: {i} face indices for {n} deviations"), source=source, i=len(indices),
            n=n))
    if any(i != round(i) for i in indices) or sorted(int(i) for i in indices) != list(
            range(1, n + 1)):
        raise DccError(message(QT_TR_NOOP(
            "{source}: the face indices are not 1 to {n}, each once"), source=source, n=n))
    if n < 3:
        raise DccError(message(QT_TR_NOOP("{source}: {n} faces: a polygon has 3 or more"),
                               source=source, n=n))
    if faces and faces != n:
        raise DccError(message(QT_TR_NOOP(
            "{source}: certificate {id} gives {n} faces, the readings have {faces}: it is "
            "another polygon's"), source=source, id=certificate_id, n=n, faces=faces))
    arcsec = _to_arcsec(values, units, source, where_d)
    u = _expanded(element, n, where_d, source)
    if u is None:
        raise DccError(message(QT_TR_NOOP(
            "{source}: the face deviations carry no expanded uncertainty (si:expandedMUXMLList): "
            "a reference's deviations are used with their U"), source=source))
    u_arcsec = [abs(x) for x in _to_arcsec(u.values, units, source, where_d)]
    if len(set(u.k)) > 1 or len(set(u.p)) > 1:
        raise DccError(message(QT_TR_NOOP(
            "{source}: the faces' uncertainties are stated with different coverage factors or "
            "probabilities; AngleBench takes one k for the polygon"), source=source))
    faces_of = [int(i) for i in indices]
    deviations = dict(zip(faces_of, arcsec, strict=True))
    uncertainties = dict(zip(faces_of, u_arcsec, strict=True))
    _check_plausible(deviations, QT_TR_NOOP("the deviation"), source, certificate_id)
    _check_plausible(uncertainties, QT_TR_NOOP("the expanded uncertainty"), source,
                     certificate_id, positive=True)
    due_date = _due_date(root, calibration_date, source)
    notes = notes + _check_due(due_date, measurement_date, source, certificate_id,
                               calibration_date, _states_validity(root))
    item_name, item_serials = _item(root)
    return PolygonReference(
        deviations, uncertainties, u.k[0], u.p[0], certificate_id, calibration_date, due_date,
        source, signer, notes, item_name, item_serials)


def replace_face_deviations(rows: list[list[str]], position_index: int, deviation_index: int,
                            reference: PolygonReference) -> tuple[list[list[str]], bool]:
    """The readings' rows with each face's deviation cell replaced by the reference's (by
    the position column), and whether the column held other values before (typed values
    that differ by more than 0.0005"). DccError when a position is no face of the reference
    or the readings' face count differs."""
    out, differed, seen = [], False, set()
    for number, row in enumerate(rows, 1):
        row = list(row)
        text = row[position_index].strip() if position_index < len(row) else ""
        if not text:
            out.append(row)
            continue
        try:
            position = int(float(text))
        except ValueError:
            out.append(row)  # the parser names the bad cell
            continue
        if position not in reference.deviations:
            raise DccError(message(QT_TR_NOOP(
                "{source}: the readings' row {row} measures face {position}; certificate {id} "
                "gives faces 1 to {n}: another polygon's"), source=reference.source, row=number,
                position=position, id=reference.certificate_id, n=reference.faces))
        seen.add(position)
        before = row[deviation_index].strip()
        value = reference.deviations[position]
        if before:
            try:
                differed = differed or abs(float(before) - value) > 5e-4
            except ValueError:
                differed = True
        row[deviation_index] = f"{value:.6f}"
        out.append(row)
    if seen and max(seen) != reference.faces:
        raise DccError(message(QT_TR_NOOP(
            "{source}: the readings measure faces up to {read}, certificate {id} gives {n} "
            "faces: another polygon's"), source=reference.source, read=max(seen),
            id=reference.certificate_id, n=reference.faces))
    return out, differed


def polygon_standard(reference: PolygonReference) -> dict:
    """The polygon as a row of the standards table (a ReferenceStandard's fields): its
    largest face U (exact with its k: U95 when k = 2 at p ≈ 0.95, else u = U/k), per reading — or per
    face from face 1 when the DCC states face 1 as exactly 0 with no uncertainty (its
    deviations are then from face 1)."""
    k = reference.coverage_factor
    from_face_1 = (reference.deviations.get(1) == 0.0
                   and reference.expanded_uncertainty.get(1) == 0.0)
    standard: dict[str, str | float] = {"description": "polygon (face deviations from its DCC)",
                "serial": reference.item_serials[0] if reference.item_serials else "",
                "certificate_no": reference.certificate_id,
                "applies_to": "from face 1" if from_face_1 else "reading",
                "uncertainty_unit": "arcsec", "due_date": reference.due_date}
    if is_u95(k, reference.coverage_probability):
        standard.update(uncertainty=reference.largest_u, basis="U95")
    else:
        standard.update(uncertainty=reference.largest_u / k, basis="u")
    standard["coverage_factor"] = k  # printed as read: U with its k
    return standard


#: words that name the polygon among a certificate's standards (en, zh)
_POLYGON_WORDS = re.compile(r"polygon|多面棱体|棱体", re.IGNORECASE)
#: the reference a workbench takes from a polygon's DCC (models.workbench.AcceptsReference)
POLYGON_FACE_DEVIATIONS = "polygon face deviations"


def place_polygon_standard(standards: list[dict], standard: dict,
                           reference: PolygonReference | None = None
                           ) -> tuple[list[dict], tuple]:
    """The standards (ReferenceStandard dicts) with the polygon read from its DCC in place,
    and what to say: it replaces the standard with its certificate number, else the one
    whose description names a polygon (keeping that one's description and serial: the same
    polygon, now with its DCC's figures), else it is added. The polygon's U thus enters the
    budget once. With ``reference`` (the DCC read), the serial the row lists must be the
    DCC's item's (:func:`item_notes`: DccError naming both when it is another polygon's; an
    unlisted serial is taken from the DCC, said)."""
    out = [dict(s) for s in standards]
    number = standard.get("certificate_no", "")

    def checked(old: dict) -> tuple[dict, tuple]:
        if reference is None:
            return {}, ()
        serial, said = item_notes(str(old.get("serial") or ""), reference.certificate_id,
                                  reference.item_name, reference.item_serials, reference.source)
        return ({"serial": serial} if serial else {}), said

    for match in (lambda s: number and s.get("certificate_no") == number,
                  lambda s: _POLYGON_WORDS.search(str(s.get("description", ""))) is not None):
        for i, old in enumerate(out):
            if match(old):
                serial, said = checked(old)
                kept = {k: old[k] for k in ("description", "serial") if old.get(k)}
                out[i] = {**standard, **kept, **serial}
                return out, said
    serial, said = checked({})
    return [*out, {**standard, **serial}], said


# -- any standard's certificate ----------------------------------------------------------
#: what a result with an uncertainty is, in the order a standard's U is taken from: the
#: standard's error (PTB's basic_measurementError, or a name that says error or deviation),
#: a polygon's face deviations in AngleBench's vocabulary, its measured values
#: (basic_measuredValue); a result none of these is taken only when nothing is marked
_ERROR, _FACE, _MEASURED, _UNMARKED, _NOT_THE_STANDARDS = (
    "error", "face", "measured", "unmarked", "not the standard's")
_KIND_WORDS = {_ERROR: QT_TR_NOOP("measurement errors or deviations"),
               _FACE: QT_TR_NOOP("a polygon's face deviations"),
               _MEASURED: QT_TR_NOOP("measured values")}
#: refTypes of results that are no quantity the standard provides: AngleBench's set-up
#: (fitted nuisance) parameters, summary figures, budget, decided quantity; PTB's nominal
#: and reference values (the calibrating laboratory's, not the item's)
_NOT_THE_STANDARDS_REFTYPES = frozenset({
    REFTYPE_SETUP_PARAMETERS, "anglebench_setupParameter", REFTYPE_SUMMARY,
    "anglebench_summaryFigure", REFTYPE_BUDGET, "anglebench_budgetComponent",
    "anglebench_decidedQuantity", PTB_NOMINAL_VALUE, PTB_REFERENCE_VALUE})
#: names of an error or deviation (en, de, zh), and of a measured value, for a DCC that
#: marks its results with no refType; a standard deviation is a statistic, not an error
_ERROR_NAME = re.compile(r"\b(errors?|deviations?)\b|abweichung|fehler|误差|偏差|示值误差",
                         re.IGNORECASE)
_MEASURED_NAME = re.compile(r"\bmeasured values?\b|messwert|测量值|测得值", re.IGNORECASE)
_STATISTIC_NAME = re.compile(r"standard deviation|standardabweichung|标准偏差|标准差",
                             re.IGNORECASE)


@dataclass(frozen=True)
class _Figure:
    """One expanded uncertainty of a result, with what it is the uncertainty of."""

    u: float  # in ``unit``
    unit: str  # "arcsec", "um", or the D-SI unit when neither
    k: float
    p: float
    kind: str
    quantity: str  # the quantity's name ("" none)
    result: str  # its dcc:result's name ("" none)


def _name_of(element) -> str:
    """An element's dcc:name in English (else its first content), "" when it has none."""
    name = element.find(f"{D}name") if element is not None else None
    if name is None:
        return ""
    contents = name.findall(f"{D}content")
    english = [c for c in contents if c.get("lang") == "en"]
    return " ".join(((english or contents or [None])[0].text or "").split()) if contents else ""


def _kind(element, result, quantity_name: str) -> str:
    """What the figure at ``element`` is, by the refTypes on it and its parents up to its
    dcc:result (the DCC's own semantics), else by its quantity's and result's names."""
    reftypes: set[str] = set()
    parent = element
    while parent is not None:
        reftypes.update((parent.get("refType") or "").split())
        if parent is result:
            break
        parent = parent.getparent()
    if result is not None and _is_reference_polygon(result):
        return _NOT_THE_STANDARDS  # a reference polygon's (the encoder's DCC): not the item's
    if PTB_MEASUREMENT_ERROR in reftypes:
        return _ERROR
    if REFTYPE_FACE_DEVIATION in reftypes:
        return _FACE
    if PTB_MEASURED_VALUE in reftypes:
        return _MEASURED
    if reftypes & _NOT_THE_STANDARDS_REFTYPES:
        return _NOT_THE_STANDARDS
    for name in (quantity_name, _name_of(result)):
        if name and _STATISTIC_NAME.search(name):
            return _UNMARKED  # a statistic of the errors (their spread) is no error: the
            # whole name decides, never what is left once its statistic's words are cut out
        if name and _ERROR_NAME.search(name):
            return _ERROR
        if name and _MEASURED_NAME.search(name):
            return _MEASURED
    return _UNMARKED


def _figures(root, source: str = "") -> list[_Figure]:
    """Every expanded uncertainty of the results (those under dcc:results: not a
    measuringEquipment's — the standards the certificate used — nor an influence
    condition's), converted to arcseconds or micrometres where it is an angle or a length."""
    out: list[_Figure] = []
    results = root.find(f"{D}measurementResults")
    elements = [] if results is None else [
        element for block in results.iter(f"{D}results")
        for element in block.iter(f"{S}real", f"{S}realListXMLList")]
    for element in elements:
        where = _path(element)
        if element.tag == f"{S}realListXMLList":
            values = parse_decimal_list(element.findtext(f"{S}valueXMLList") or "",
                                        f"{where}/valueXMLList")
            units = _units(element, len(values), where) if values else []
        else:
            values = parse_decimal_list(element.findtext(f"{S}value") or "", f"{where}/value")
            units = [(element.findtext(f"{S}unit") or "").strip()] * len(values)
        if not values:
            continue
        u = _expanded(element, len(values), where, source)
        if u is None:
            continue
        quantity = next(element.iterancestors(f"{D}quantity"), None)
        result = next(element.iterancestors(f"{D}result"), None)
        quantity_name, result_name = _name_of(quantity), _name_of(result)
        kind = _kind(element, result, quantity_name)
        for value, unit, k, p in zip(u.values, units, u.k, u.p, strict=True):
            factor = angle_factor(unit)
            if factor is not None:
                figure, key = abs(value) * factor, "arcsec"
            elif unit in UM_PER_UNIT:
                figure, key = abs(value) * UM_PER_UNIT[unit], "um"
            else:
                figure, key = abs(value), unit
            out.append(_Figure(figure, key, k, p, kind, quantity_name, result_name))
    return out


def _named(figure: _Figure) -> str:
    """A figure's quantity within its result, as the DCC names them."""
    if figure.quantity and figure.result and figure.quantity != figure.result:
        return f"{figure.result} › {figure.quantity}"
    return figure.quantity or figure.result or "?"


def _not_used(figures: list[_Figure], taken: list[_Figure]) -> list[str]:
    """The results (or, within a result partly taken, the quantities) whose uncertainties
    were not taken, each named once; a figure that restates one taken (the same U, unit
    and k: a polygon's face deviations beside the same errors from face 1) is not named."""
    taken_results = {f.result for f in taken}
    restated = {(f.u, f.unit, f.k) for f in taken}
    out: list[str] = []
    for f in figures:
        if f in taken or (f.u, f.unit, f.k) in restated:
            continue
        name = _named(f) if f.result in taken_results else (f.result or f.quantity or "?")
        if name not in out:
            out.append(name)
    return out


def read_standard_dcc(path: str | Path, schema_dir: str | Path | None = None, *,
                      measurement_date: str | dt.date | None = None,
                      trusted_cert: bytes | None = None,
                      trust_named: bool = True) -> StandardCertificate:
    """A standard's certificate id, calibration date, due date and U from its DCC (any
    maker's). U is the U of the quantity the standard provides, not of a fitted set-up
    parameter: the largest (by U/k) among its results marked as measurement errors or
    deviations (refType ``basic_measurementError``, else a name saying error or deviation),
    else its polygon face deviations (``anglebench_faceDeviation``: the polygon reader's),
    else its measured values (``basic_measuredValue``); a DCC that marks none takes the
    largest of all its results, and says so. Set-up parameters, summary figures, budget,
    nominal and reference values, and a reference polygon's face deviations (an encoder's
    DCC restating them) are never taken. In arcseconds (an angle) or micrometres (a
    length), its k and p beside it; a note names the result U was taken from and those not
    used. DccError naming the file and why."""
    root, source, signer, notes = _load(path, schema_dir, trusted_cert, trust_named)
    certificate_id, calibration_date = _core(root, source)
    figures = _figures(root, source)
    due_date = _due_date(root, calibration_date, source)
    notes = notes + _check_due(due_date, measurement_date, source, certificate_id,
                               calibration_date, _states_validity(root))
    item = _item(root)
    if not figures:
        notes = notes + (message(QT_TR_NOOP(
            "{source}: no result states an expanded uncertainty: the standard's U is left "
            "empty"), source=source),)
        return StandardCertificate(certificate_id, calibration_date, due_date, None, "",
                                   None, None, source, signer, notes, *item, "reading",
                                   bool(_POLYGON_WORDS.search(item[0])))
    kind = next((k for k in (_ERROR, _FACE, _MEASURED, _UNMARKED)
                 if any(f.kind == k for f in figures)), None)
    if kind is None:  # set-up parameters, summary figures, … only
        notes = notes + (message(QT_TR_NOOP(
            "{source}: none of its results with an uncertainty is a measurement error, a "
            "deviation or a measured value of the standard (only {others}): the standard's U "
            "is left empty"), source=source, others=listed(_not_used(figures, []))),)
        return StandardCertificate(certificate_id, calibration_date, due_date, None, "",
                                   None, None, source, signer, notes, *item, "reading",
                                   bool(_POLYGON_WORDS.search(item[0])))
    candidates = [f for f in figures if f.kind == kind]
    found = [f for f in candidates if f.unit in ("arcsec", "um")]
    if not found:
        raise DccError(message(QT_TR_NOOP(
            "{source}: its uncertainties are in {units}: neither an angle nor a length"),
            source=source, units=", ".join(sorted({f.unit for f in candidates}))))
    if len({f.unit for f in found}) > 1:  # an angle standard with a length too: the angle
        found = [f for f in found if f.unit == "arcsec"]
    largest = max(found, key=lambda f: f.u / f.k)  # the largest standard uncertainty
    if not math.isfinite(largest.u) or (largest.unit == "arcsec"
                                        and largest.u > PLAUSIBLE_ARCSEC):
        raise DccError(message(QT_TR_NOOP(
            "{source}: certificate {id}: the expanded uncertainty of “{name}”, {u:g}″, is "
            "beyond {limit:g}″: not a standard's; the DCC is not read"), source=source,
            id=certificate_id, name=_named(largest), u=largest.u, limit=PLAUSIBLE_ARCSEC))
    others = _not_used(figures, [f for f in candidates if f.unit == largest.unit])
    if kind == _UNMARKED:
        said = message(QT_TR_NOOP(
            "{source}: none of its results is marked as a measurement error, a deviation or "
            "a measured value (by its refType or its name): U is the largest of all its "
            "results, that of “{name}”; check that it is the uncertainty of what the "
            "standard provides"), source=source, name=_named(largest))
    elif others:
        said = message(QT_TR_NOOP(
            "{source}: U is that of “{name}”, the largest of its results that are {kind}; "
            "not used: {others}"), source=source, name=_named(largest),
            kind=message(_KIND_WORDS[kind]), others=listed(others))
    else:
        said = message(QT_TR_NOOP(
            "{source}: U is that of “{name}”, the largest of its results that are {kind}"),
            source=source, name=_named(largest), kind=message(_KIND_WORDS[kind]))
    return StandardCertificate(certificate_id, calibration_date, due_date, largest.u,
                               largest.unit, largest.k, largest.p, source, signer,
                               notes + (said,), *item,
                               _applies_to(root),
                               kind == _FACE or bool(_POLYGON_WORDS.search(item[0])))


def _applies_to(root) -> str:
    """What a polygon's U in its DCC is per, as :func:`polygon_standard` says it: "from face
    1" where the polygon result states face 1 as exactly 0 with no uncertainty, else
    "reading"."""
    for result in root.iter(f"{D}result"):
        if not _has_reftype(result, REFTYPE_POLYGON_FACE_DEVIATIONS) or _is_reference_polygon(
                result):
            continue
        quantities = list(result.iter(f"{D}quantity"))
        index_q = [q for q in quantities if _has_reftype(q, REFTYPE_FACE_INDEX)]
        deviation_q = [q for q in quantities if _has_reftype(q, REFTYPE_FACE_DEVIATION)]
        if len(index_q) != 1 or len(deviation_q) != 1:
            continue
        where = _path(deviation_q[0])
        indices, _, _ = _real_list(index_q[0], _path(index_q[0]))
        values, _, element = _real_list(deviation_q[0], where)
        u = _expanded(element, len(values), where) if len(indices) == len(values) else None
        if u is None:
            continue
        first = {int(i): (v, w) for i, v, w in zip(indices, values, u.values, strict=True)}
        return "from face 1" if first.get(1) == (0.0, 0.0) else "reading"
    return "reading"


# -- the issued PDF inside ---------------------------------------------------------------
def embedded_pdfs(data: bytes) -> list[bytes]:
    """Every PDF the DCC embeds (dcc:document, or any byteData/file of mime type
    application/pdf), decoded; DccError when the document cannot be read."""
    root = parse_dcc(data, "DCC")
    out = []
    for element in root.iter(f"{D}document", f"{D}byteData", f"{D}file",
                             f"{D}descriptionData"):
        if (element.findtext(f"{D}mimeType") or "").strip().lower() != "application/pdf":
            continue
        try:
            out.append(base64.b64decode("".join((element.findtext(f"{D}dataBase64") or "")
                                                .split()), validate=True))
        except (binascii.Error, ValueError) as exc:
            raise DccError(message(QT_TR_NOOP("{where}: the embedded PDF is not base64 "
                                              "({reason})"), where=_path(element),
                                   reason=reason_of(exc))) from None
    return out
