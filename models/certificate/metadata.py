"""What a test certificate says besides the numbers: lab, customer, item, reference
standards, environment, people and dates (ISO/IEC 17025 clause 7.8).

Entered in the metadata dialog, stored in the project file (per workbench),
with lab-wide defaults kept in the settings. Text is stored as typed (stripped, a tab as a
space); a field with a control or format character, or longer than its limit (200
characters, notes 2000), is refused naming the field: nothing is removed or cut unseen.
"""

from __future__ import annotations

import contextlib
import datetime as dt
import math
import re
import unicodedata
from dataclasses import asdict, dataclass, fields, replace
from typing import Any

from models.messages import QT_TR_NOOP, message, reason_of
from models.quantity import UNITS, Quantity, UnitError, unit
from models.uncertainty.budget import BASIS_DIVISORS, DEFAULT_COVERAGE_PROBABILITY
from models.uncertainty.conformity import DECISION_QUANTITIES, DECISION_RULES
from models.uncertainty.rounding import StatedNumber, stated_decimals

__all__ = [
    "APPLIES_TO_NAMES",
    "DECISION_QUANTITIES",
    "DECISION_RULES",
    "DOCUMENT_TYPES",
    "LANGUAGES",
    "LAB_DEFAULT_FIELDS",
    "NUMBER_FIELDS",
    "STANDARD_ROLES",
    "CertificateMetadata",
    "MetadataError",
    "PLACES",
    "ReferenceStandard",
    "clean_text",
    "format_certificate_number",
    "readable_standards",
    "revision_statement",
    "separate_statement",
    "withdrawn_statement",
]

MAX_FIELD_CHARS = 200
MAX_NOTES_CHARS = 2000

# Fields that are the same for every certificate a lab issues: the dialog can save them
# as the lab's defaults, and a new certificate starts from them.
LAB_DEFAULT_FIELDS = ("lab_name", "lab_address", "lab_accreditation", "number_scheme",
                      "standards", "operator", "approver", "decision_rule", "decision_quantity",
                      "coverage_probability_pct", "document_type", "checker_role", "checker")

#: What the document is: a calibration certificate, or a test report.
DOCUMENT_TYPES = {"calibration": QT_TR_NOOP("Calibration certificate"),
                  "test": QT_TR_NOOP("Test report")}
#: the document's number as a missing field names it: a calibration certificate's, a test
#: report's (``missing_fields(report=True)``)
NUMBER_FIELDS = {False: QT_TR_NOOP("certificate number"), True: QT_TR_NOOP("report number")}
#: where the calibration was made (ISO/IEC 17025 7.8.2.1 c): the laboratory's own premises, or
#: the customer's site (its address in ``calibration_site``)
PLACES = {"laboratory": QT_TR_NOOP("at the laboratory"),
          "customer_site": QT_TR_NOOP("at the customer's site")}
#: the certificate's language: English; Chinese throughout (JJF 1001 terms); or its headings
#: and labels in Chinese beside the English ("校准证书 Calibration certificate")
LANGUAGES = {"en": "English", "zh": "中文", "zh+en": "中文 + English (headings and labels)"}

#: what no field may hold: control (Cc) and format (Cf: U+200B, U+061C, bidi overrides,
#: U+FEFF) characters, line/paragraph separators, surrogates, private-use and unassigned
#: code points
_REFUSED_CATEGORIES = frozenset({"Cc", "Cf", "Zl", "Zp", "Cs", "Co", "Cn"})


#: What a reference standard carries of the measurand (ReferenceStandard.role; "" not stated:
#: told from its other fields where they tell it, models/certificate/traceability.py): the
#: reference the errors are measured against (the theodolite, the polygon, the positioning's
#: reference measuring system, the fringe's phase or angle reference), the polygon test's
#: autocollimator, the fringe's ADC. A workbench names the roles its measurand needs.
STANDARD_ROLES = ("reference", "autocollimator", "adc")

#: What a reference standard's uncertainty figure applies to (see ReferenceStandard).
APPLIES_TO = ("reading", "angle", "from face 1")
#: each as a certificate names it after "per" ("standard uncertainty u per angle between two
#: readings"), in the standards table as in the budget (day review 69 F2: the table said
#: "0.5″ (standard uncertainty u)" alike for both, and the budget took 0.354″ unexplained)
APPLIES_TO_NAMES = {"reading": QT_TR_NOOP("reading"),
                    "angle": QT_TR_NOOP("angle between two readings"),
                    "from face 1": QT_TR_NOOP("face, stated from face 1")}


class MetadataError(ValueError):
    """A metadata field cannot be used; the message names the field."""


def _refused_character(text: str) -> str:
    """The first character of ``text`` that may not be on a certificate: a control or
    format character (invisible: U+200B, U+061C, a bidi override…), a line or paragraph
    separator, a private-use or unassigned code point; "" when there is none. A newline is
    judged by the caller."""
    for ch in text:
        if ch != "\n" and unicodedata.category(ch) in _REFUSED_CATEGORIES:
            return ch
    return ""


def clean_text(value: Any, field_name: str, multiline: bool = False) -> str:
    """A field's text, stripped; a tab (and, in a one-line field, a line break) as a space.
    MetadataError, naming the field, for text longer than the field's limit (never cut) or
    with a control or format character (never removed unseen: an invisible character makes
    two texts that print alike differ)."""
    if value is None:
        return ""
    if not isinstance(value, str | int | float) or isinstance(value, bool):
        raise MetadataError(message(
            QT_TR_NOOP("certificate field '{field_name}' must be text"),
            field_name=field_name))
    try:
        text = str(value)
    except ValueError:  # an integer of thousands of digits
        raise MetadataError(message(
            QT_TR_NOOP("certificate field '{field_name}' must be text"),
            field_name=field_name)) from None
    text = text.replace("\r\n", "\n").replace("\r", "\n").replace("\t", " ")
    if not multiline:
        text = text.replace("\n", " ")
    text = "\n".join(line.rstrip() for line in text.split("\n")).strip()
    bad = _refused_character(text)
    if bad:
        raise MetadataError(message(QT_TR_NOOP(
            "certificate field '{field_name}' holds the invisible or control character "
            "U+{code} ({name}): delete it (retype the text if it was pasted)"),
            field_name=field_name, code=f"{ord(bad):04X}",
            name=unicodedata.name(bad, "unnamed").lower()))
    limit = MAX_NOTES_CHARS if multiline else MAX_FIELD_CHARS
    if len(text) > limit:
        raise MetadataError(message(QT_TR_NOOP(
            "certificate field '{field_name}' is {length} characters long; at most {limit} "
            "fit: shorten it (nothing is cut unseen)"), field_name=field_name,
            length=len(text), limit=limit))
    return text


def _optional_number(value: Any, field_name: str) -> float | None:
    if value is None or (isinstance(value, str) and not value.strip()):
        return None
    if isinstance(value, bool) or not isinstance(value, str | int | float):
        raise MetadataError(message(
            QT_TR_NOOP("certificate field '{field_name}' must be a number"),
            field_name=field_name))
    try:
        number = float(str(value).replace(",", ".")) if isinstance(value, str) else float(value)
    except (TypeError, ValueError, OverflowError):
        shown = value if isinstance(value, str) and len(value) < 40 else "the value"
        raise MetadataError(message(
            QT_TR_NOOP("certificate field '{field_name}': '{shown}' is not a number"),
            field_name=field_name, shown=shown)) \
            from None
    if not math.isfinite(number):
        raise MetadataError(message(
            QT_TR_NOOP("certificate field '{field_name}' must be a finite number"),
            field_name=field_name))
    return number


def _stated_limit(raw: Any, number: float | None) -> float | None:
    """A limit with the decimals it was typed with where they are known (a text "1.50", a
    number read with its digits, :class:`~models.uncertainty.rounding.StatedNumber`): its
    last significant place, which ASTM E29 §6.4 rounds a value compared with it to."""
    if number is None:
        return None
    if isinstance(raw, StatedNumber):
        return raw
    if isinstance(raw, str):
        try:
            return StatedNumber.from_text(raw)
        except ValueError:
            return number
    return number


def _date(value: Any, field_name: str) -> str:
    text = clean_text(value, field_name)
    if not text:
        return ""
    try:
        return dt.date.fromisoformat(text).isoformat()
    except ValueError:
        raise MetadataError(message(
            QT_TR_NOOP("certificate field '{field_name}': '{text}' is not a date (YYYY-MM-DD)"),
            field_name=field_name, text=text)) from None


@dataclass(frozen=True)
class ReferenceStandard:
    """A reference standard used in the test, with its calibration certificate.

    ``uncertainty`` (in ``uncertainty_unit``, converted to the unit of the errors)
    stated as ``basis`` (see BASIS_DIVISORS) enters the budget as a Type B component
    for each reading made with it; leave it empty for a standard whose uncertainty
    does not enter the result. ``applies_to`` says what the figure is the
    uncertainty of: each ``reading`` (the default), any ``angle`` between two readings
    (a certificate that states U for every angle measured with the standard, from any
    start: the difference of two readings' errors is then within it too; the positioning
    figures' intervals and the theodolite's circle-error widening use it), or each face's
    deviation ``from face 1`` (a polygon certificate that states its deviations from face 1,
    whose face 1 is then exact). ``role`` says which of the standards that carry the
    measurand it is (one of STANDARD_ROLES; "" not stated), so that a document missing one
    can name which (assessment 72 L2).
    """

    description: str = ""
    serial: str = ""
    certificate_no: str = ""
    uncertainty: float | None = None
    basis: str = "U95"
    applies_to: str = "reading"
    uncertainty_unit: str = "arcsec"  # a key of models.quantity.UNITS
    due_date: str = ""  # YYYY-MM-DD: when the standard's calibration is due (e.g. from its DCC)
    # the k its certificate states U with, where the figure was read from its DCC (basis
    # "u": U/k, exact; "U95": U with k = 2): the standards table prints U with this k, as
    # read, to two significant digits (GUM 7.2.6), not the figure's every digit
    coverage_factor: float | None = None
    role: str = ""  # one of STANDARD_ROLES, "" where not stated

    def uncertainty_in(self, unit: str, name: str = "standards") -> float | None:
        """The stated uncertainty as a number in ``unit`` (the errors'); MetadataError when
        it is not a quantity of the same kind."""
        if self.uncertainty is None:
            return None
        try:
            return float(Quantity(self.uncertainty, self.uncertainty_unit).in_unit(unit))
        except UnitError:
            raise MetadataError(message(
                QT_TR_NOOP("reference standard '{name}': its uncertainty is in {given}, but the "
                           "errors are in {unit}: state it in a unit of the same kind"),
                name=self.description or name, given=UNITS[self.uncertainty_unit].symbol,
                unit=UNITS[unit].symbol)) from None

    @classmethod
    def from_dict(cls, data: Any, index: int) -> ReferenceStandard:
        name = f"standards[{index + 1}]"
        if not isinstance(data, dict):
            raise MetadataError(message(
                QT_TR_NOOP("certificate field '{name}' must be an object"),
                name=name))
        basis = clean_text(data.get("basis", "U95"), f"{name}.basis") or "U95"
        if basis not in BASIS_DIVISORS:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field '{name}.basis' must be one of {join}, not '{basis}'"),
                name=name, join=', '.join(BASIS_DIVISORS), basis=basis))
        # "uncertainty_arcsec": written before the figure had its unit (arcseconds, or the
        # unit of the workbench's errors: a project file's migration says which)
        u = _optional_number(data.get("uncertainty", data.get("uncertainty_arcsec")),
                             f"{name}.uncertainty")
        unit_key = clean_text(data.get("uncertainty_unit", "arcsec"),
                              f"{name}.uncertainty_unit") or "arcsec"
        with contextlib.suppress(UnitError):  # a symbol typed in the table ("µrad", '"')
            unit_key = unit(unit_key).key
        if unit_key not in UNITS:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field '{key}' must be one of {join}, not '{unit}'"),
                key=f"{name}.uncertainty_unit", join=', '.join(UNITS), unit=unit_key))
        if u is not None and not 0 < Quantity(u, unit_key).to(
                "arcsec" if UNITS[unit_key].dimension == "angle" else "um").value <= 3600:
            # 0 is no figure a calibration states: taken as such, it made a run of exact
            # readings decide "pass" on an interval of ±0.0003″ (an audit); empty: not stated
            raise MetadataError(message(
                QT_TR_NOOP("certificate field '{name}.uncertainty' must be more than 0 and at "
                           "most 3600\" (or 3600 µm); leave it empty where the standard's "
                           "certificate states none"),
                name=name))
        applies_to = clean_text(data.get("applies_to", "reading"), f"{name}.applies_to") or "reading"
        if applies_to not in APPLIES_TO:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field '{name}.applies_to' must be one of {join}, not "
                           "'{applies_to}'"),
                name=name, join=', '.join(APPLIES_TO), applies_to=applies_to))
        role = clean_text(data.get("role"), f"{name}.role")
        if role and role not in STANDARD_ROLES:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field '{name}.role' must be one of {join} or empty, "
                           "not '{role}'"),
                name=name, join=', '.join(STANDARD_ROLES), role=role))
        k = _optional_number(data.get("coverage_factor"), f"{name}.coverage_factor")
        if k is not None and k <= 0:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field '{field_name}' must be a number above 0"),
                field_name=f"{name}.coverage_factor"))
        return cls(clean_text(data.get("description"), f"{name}.description"),
                   clean_text(data.get("serial"), f"{name}.serial"),
                   clean_text(data.get("certificate_no"), f"{name}.certificate_no"), u, basis,
                   applies_to, unit_key, _date(data.get("due_date"), f"{name}.due_date"), k,
                   role)


#: what a stored standard that does not read is said as (where: the lab defaults' standards
#: or a workbench's stored details); the entry alone is left out, the others kept
_SKIPPED_STANDARD = {
    True: QT_TR_NOOP("reference standard {number} of the lab defaults ({name}) cannot be read "
                     "and is left out, the others kept: {reason}"),
    False: QT_TR_NOOP("reference standard {number} of the stored certificate details ({name}) "
                      "cannot be read and is left out, the others kept: {reason}"),
}


def readable_standards(raw: Any, lab_defaults: bool = False) -> tuple[list[Any], dict[str, Any]]:
    """The entries of a stored standards list (``raw``: the lab defaults' when
    ``lab_defaults``, else a workbench's stored details) that read, as stored, and for each
    that does not a message keyed ``standards[N]`` (N its place in ``raw``) that says which
    (its number and name) and why: one bad entry (a name too long, a figure out of range, an
    entry that is no object) leaves out itself only, never the whole list unseen. ``raw``
    that is not a list: ([], {"standards": why})."""
    if raw is None:
        return [], {}
    if not isinstance(raw, list):
        return [], {"standards": message(QT_TR_NOOP(
            "certificate field 'standards' must be a list"))}
    good: list[Any] = []
    skipped: dict[str, Any] = {}
    for index, entry in enumerate(raw):
        try:
            ReferenceStandard.from_dict(entry, index)
        except MetadataError as exc:
            name = entry.get("description") if isinstance(entry, dict) else None
            name = (f"“{name[:40]}…”" if len(name) > 40 else f"“{name}”") \
                if isinstance(name, str) and name.strip() else "—"
            skipped[f"standards[{index + 1}]"] = message(
                _SKIPPED_STANDARD[lab_defaults], number=index + 1, name=name,
                reason=reason_of(exc))
        else:
            good.append(entry)
    return good, skipped


#: keys written before their figures had a unit (project schema 1) → the keys now
_UNITLESS_KEYS = {"tolerance_arcsec": "tolerance", "item_resolution_arcsec": "item_resolution"}


@dataclass(frozen=True)
class CertificateMetadata:
    certificate_number: str = ""
    number_scheme: str = "AB-{year}-{seq:04d}"
    lab_name: str = ""
    lab_address: str = ""
    lab_accreditation: str = ""
    # the laboratory's ISO 3166-1 alpha-2 country code (CN, DE …): the DCC's coreData states it
    lab_country: str = ""
    customer_name: str = ""
    customer_address: str = ""
    item_description: str = ""
    item_manufacturer: str = ""
    item_serial: str = ""
    item_model: str = ""  # the item's model / type designation
    item_grade: str = ""
    tolerance: float | None = None  # ± limit for the conformity statement, in tolerance_unit
    tolerance_unit: str = "arcsec"  # a key of models.quantity.UNITS
    item_resolution: float | None = None  # the item's indication resolution, in its unit
    item_resolution_unit: str = "arcsec"  # a key of models.quantity.UNITS
    standards: tuple[ReferenceStandard, ...] = ()
    calibration_place: str = "laboratory"  # see PLACES
    calibration_site: str = ""  # the customer's site: where
    temperature_c: float | None = None
    humidity_pct: float | None = None
    calibration_date: str = ""
    issue_date: str = ""
    created: str = ""  # ISO date-time written into the PDF; empty: the time of export
    operator: str = ""
    approver: str = ""
    # the lab's template asks for a checker (核验员, JJF 1071's model): the signature block has
    # operator / checker / approver, and the checker is required like the approver
    checker_role: bool = False
    checker: str = ""
    decision_rule: str = "guarded"
    # the decision rule was agreed with the customer (ISO/IEC 17025 7.1.3: "communicated to,
    # and agreed with, the customer"); false: the rule requested, no agreement recorded. Of
    # this certificate, not a lab default (each customer's agreement is its own)
    decision_rule_agreed: bool = False
    decision_quantity: str = "half_range"
    coverage_probability_pct: float = 100.0 * DEFAULT_COVERAGE_PROBABILITY
    document_type: str = "calibration"
    language: str = "en"  # see LANGUAGES
    # fringe: the checksum of the correction table the lab states it loaded into the encoder
    as_left_table_sha256: str = ""
    notes: str = ""
    # set by the register on an amendment or a replacement (ISO/IEC 17025 7.8.8)
    supersedes: str = ""  # the number of the certificate this one amends or replaces
    revision: str = ""  # "amendment N" or "replacement"; empty for an original
    change_note: str = ""  # what changed, and why
    # set by the register on an original issued for an item and date of calibration that a
    # current certificate already reports (a calibration of its own, e.g. as left after an
    # adjustment): those certificates' numbers; ``change_note`` says why it is separate
    separate_from: str = ""
    # set by the register on an original issued for an item and date of calibration whose
    # certificate was withdrawn (hostile78 F3: a fail withdrawn and issued again as a pass,
    # neither naming the other): those certificates' numbers, and ``withdrawn_note`` when
    # and why each was withdrawn and what this one changes against it
    replaces_withdrawn: str = ""
    withdrawn_note: str = ""
    # set by the register on a certificate whose readings (their values: readings_identity)
    # are those of certificates of another item, the user having said why (hostile78 F7:
    # one item's 41 readings issued as another's): those certificates' numbers, and
    # ``readings_note`` naming each with its item and date of calibration, and the reason;
    # absent in older records
    readings_of_another_item: str = ""
    readings_note: str = ""
    # the bundled example details (resources/samples/certificate_*.json): never recorded in
    # the user's register (the command line issues them into a register of their own)
    example: bool = False

    _NUMBERS = ("tolerance", "item_resolution", "temperature_c", "humidity_pct",
                "coverage_probability_pct")
    _DATES = ("calibration_date", "issue_date")

    @classmethod
    def from_dict(cls, data: Any) -> CertificateMetadata:
        """Metadata from a project file or a JSON file; unknown keys are ignored."""
        if data is None:
            return cls()
        if not isinstance(data, dict):
            raise MetadataError(message(
                QT_TR_NOOP("certificate metadata must be a JSON object")))
        for old, new in _UNITLESS_KEYS.items():
            if old in data and new not in data:
                # details written before these figures had their unit (project schema 1, a
                # JSON file of the command line): arcseconds, as the key says; a project
                # file's migration states the unit of each workbench's errors instead
                data = {**data, new: data[old]}
        values: dict[str, Any] = {}
        for f in fields(cls):
            if f.name.startswith("_") or f.name not in data:
                continue
            raw = data[f.name]
            if f.name == "standards":
                if not isinstance(raw, list):
                    raise MetadataError(message(
                        QT_TR_NOOP("certificate field 'standards' must be a list")))
                values[f.name] = tuple(ReferenceStandard.from_dict(s, i) for i, s in enumerate(raw))
            elif f.name == "tolerance":
                values[f.name] = _stated_limit(raw, _optional_number(raw, f.name))
            elif f.name in cls._NUMBERS:
                values[f.name] = _optional_number(raw, f.name)
            elif f.name in ("example", "checker_role", "decision_rule_agreed"):
                if not isinstance(raw, bool):
                    raise MetadataError(message(QT_TR_NOOP(
                        "certificate field '{name}' must be true or false"), name=f.name))
                values[f.name] = raw
            elif f.name in cls._DATES:
                values[f.name] = _date(raw, f.name)
            else:
                values[f.name] = clean_text(raw, f.name, multiline=f.name in ("notes", "change_note",
                                                                   "withdrawn_note",
                                                                   "readings_note"))
        meta = cls(**values)
        if meta.language not in LANGUAGES:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'language' must be one of {join}, not '{language}'"),
                join=', '.join(LANGUAGES), language=meta.language))
        if not meta.calibration_place:
            meta = replace(meta, calibration_place="laboratory")
        if meta.calibration_place not in PLACES:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'calibration_place' must be one of {join}, not "
                           "'{place}'"), join=', '.join(PLACES), place=meta.calibration_place))
        if meta.calibration_date and meta.issue_date and meta.calibration_date > meta.issue_date:
            raise MetadataError(message(
                QT_TR_NOOP("certificate fields 'calibration_date' {calibration} and 'issue_date' "
                           "{issue}: a certificate cannot be issued before the calibration it "
                           "reports"), calibration=meta.calibration_date, issue=meta.issue_date))
        if meta.decision_rule not in DECISION_RULES:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'decision_rule' must be one of {join}, not "
                           "'{decision_rule}'"),
                join=', '.join(DECISION_RULES), decision_rule=meta.decision_rule))
        if meta.tolerance is not None and meta.tolerance <= 0:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'tolerance' must be positive")))
        for key in ("tolerance_unit", "item_resolution_unit"):
            if getattr(meta, key) not in UNITS:
                raise MetadataError(message(
                    QT_TR_NOOP("certificate field '{key}' must be one of {join}, not '{unit}'"),
                    key=key, join=', '.join(UNITS), unit=getattr(meta, key)))
        if meta.humidity_pct is not None and not 0 <= meta.humidity_pct <= 100:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'humidity_pct' must be 0 to 100 %")))
        if meta.item_resolution is not None and not 0 <= Quantity(
                meta.item_resolution, meta.item_resolution_unit).to(
                "arcsec" if UNITS[meta.item_resolution_unit].dimension == "angle" else "um"
                ).value <= 3600:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'item_resolution' must be 0 to 3600\" (or 0 to "
                           "3600 µm)")))
        if meta.coverage_probability_pct is None:
            meta = replace(meta, coverage_probability_pct=100.0 * DEFAULT_COVERAGE_PROBABILITY)
        if not 50.0 <= meta.coverage_probability_pct <= 99.9:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'coverage_probability_pct' must be 50 to 99.9 %")))
        if meta.decision_quantity not in DECISION_QUANTITIES:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'decision_quantity' must be one of {join}, not "
                           "'{decision_quantity}'"),
                join=', '.join(DECISION_QUANTITIES), decision_quantity=meta.decision_quantity))
        if meta.document_type not in DOCUMENT_TYPES:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'document_type' must be one of {join}, not "
                           "'{document_type}'"),
                join=', '.join(DOCUMENT_TYPES), document_type=meta.document_type))
        return meta

    @property
    def tolerance_quantity(self) -> Quantity | None:
        """The tolerance with its unit (None when none is stated)."""
        return None if self.tolerance is None else Quantity(self.tolerance, self.tolerance_unit)

    def item_resolution_in(self, unit: str) -> float | None:
        """The item's resolution as a number in ``unit`` (its errors'); MetadataError when
        it is not a quantity of the same kind."""
        if self.item_resolution is None:
            return None
        try:
            return float(Quantity(self.item_resolution, self.item_resolution_unit).in_unit(unit))
        except UnitError:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'item_resolution' is in {given}, but the errors "
                           "are in {unit}: state the resolution in a unit of the same kind"),
                given=UNITS[self.item_resolution_unit].symbol, unit=UNITS[unit].symbol)) from None

    def tolerance_in(self, unit: str) -> float | None:
        """The tolerance as a number in ``unit`` (the unit of the errors it is judged
        against); MetadataError when it is not a quantity of the same kind (a tolerance in
        nm for errors in arcseconds)."""
        if self.tolerance is None:
            return None
        try:
            converted = float(Quantity(self.tolerance, self.tolerance_unit).in_unit(unit))
            # to 15 significant digits: the number the customer stated, converted, without
            # the binary noise of the multiplication (0.01 µm is 10 nm, not
            # 9.999999999999998 nm: assessment 70 M4)
            return float(f"{converted:.15g}")
        except UnitError:
            raise MetadataError(message(
                QT_TR_NOOP("certificate field 'tolerance' is in {given}, but the errors are in "
                           "{unit}: state the tolerance in a unit of the same kind"),
                given=UNITS[self.tolerance_unit].symbol, unit=UNITS[unit].symbol)) from None

    @property
    def coverage_probability(self) -> float:
        return self.coverage_probability_pct / 100.0

    @classmethod
    def from_dict_lenient(cls, data: Any) -> tuple[CertificateMetadata, dict[str, str]]:
        """Every field that reads, and a message for each that does not (by key): a stored
        detail gone bad must not blank all the others."""
        if not isinstance(data, dict):
            try:
                return cls.from_dict(data), {}
            except MetadataError as exc:
                return cls(), {"": str(exc)}
        good: dict[str, Any] = {}
        problems: dict[str, str] = {}
        for key, value in data.items():
            if key == "standards" and isinstance(value, list):  # each entry on its own
                good[key], skipped = readable_standards(value)
                problems.update(skipped)
                continue
            try:
                cls.from_dict({key: value})
            except MetadataError as exc:
                problems[str(key)] = str(exc)
            else:
                good[key] = value
        try:
            return cls.from_dict(good), problems
        except MetadataError as exc:  # a check across fields
            return cls(), {**problems, "": str(exc)}

    def to_dict(self) -> dict[str, Any]:
        out = asdict(self)
        # a standard's k only where one was read, its role where stated (the files of
        # standards typed stay as were)
        out["standards"] = [{k: v for k, v in asdict(s).items()
                             if not (k == "coverage_factor" and v is None or k == "role" and not v)}
                            for s in self.standards]
        if isinstance(self.tolerance, StatedNumber) and self.tolerance.decimals > stated_decimals(
                float(self.tolerance)):
            # typed with trailing zeros ("1.50"): kept as typed, a text, which a number
            # would drop in the file (its last place is the one ASTM E29 rounds to)
            out["tolerance"] = f"{float(self.tolerance):.{self.tolerance.decimals}f}"
        return out

    def lab_defaults(self) -> dict[str, Any]:
        data = self.to_dict()
        return {k: data[k] for k in LAB_DEFAULT_FIELDS}

    def with_lab_defaults(self, defaults: dict[str, Any]) -> CertificateMetadata:
        """This metadata with the lab's defaults filled into the fields left empty."""
        lab = CertificateMetadata.from_dict({k: v for k, v in (defaults or {}).items()
                                             if k in LAB_DEFAULT_FIELDS})
        updates = {k: getattr(lab, k) for k in LAB_DEFAULT_FIELDS
                   if not getattr(self, k) and getattr(lab, k)}
        return replace(self, **updates)

    def missing_fields(self, report: bool = False) -> list[str]:
        """What a signed certificate must state and this one does not (it is then a draft);
        ``report``: the document is a test report, whose number is its "report number"
        (ISO/IEC 17025 7.8.2.1 a): it calls itself what it is)."""
        required = {
            NUMBER_FIELDS[report]: self.certificate_number,
            QT_TR_NOOP("laboratory"): self.lab_name, QT_TR_NOOP("customer"): self.customer_name,
            QT_TR_NOOP("item under test"): self.item_description,
            QT_TR_NOOP("item serial number"): self.item_serial,
            QT_TR_NOOP("date of calibration"): self.calibration_date,
            QT_TR_NOOP("operator"): self.operator,
            QT_TR_NOOP("approver"): self.approver,
        }
        if self.checker_role:
            required[QT_TR_NOOP("checker")] = self.checker
        missing = [name for name, value in required.items() if not value]
        if not self.standards:
            missing.append(QT_TR_NOOP("reference standards"))
        if self.calibration_place == "customer_site" and not self.calibration_site:
            missing.append(QT_TR_NOOP("the customer's site where it was calibrated"))
        return missing


_SCHEME_FIELD = re.compile(r"\{(year|month|day|seq)(?::0?(\d)d)?\}")


def format_certificate_number(scheme: str, sequence: int, date: dt.date) -> str:
    """Certificate number from a scheme such as ``AB-{year}-{seq:04d}``.

    Known fields: {year}, {month}, {day}, {seq} with an optional zero-padded
    width (``{seq:04d}``). Other braces are kept as typed.
    """
    values = {"year": date.year, "month": date.month, "day": date.day, "seq": int(sequence)}

    def sub(match: re.Match) -> str:
        width = int(match.group(2) or (2 if match.group(1) in ("month", "day") else 0))
        return f"{values[match.group(1)]:0{width}d}" if width else str(values[match.group(1)])

    return clean_text(_SCHEME_FIELD.sub(sub, scheme or ""), "certificate_number")


def separate_statement(meta: CertificateMetadata) -> Any:
    """An original for the item and date of calibration of certificates still valid
    (``meta.separate_from``): it names them and says why it is a calibration of its own
    (``meta.change_note``; ISO/IEC 17025 7.8.8: a reader of either learns of the other; two
    originals of one calibration are never issued). The PDF prints it under the title, the
    DCC states it (refType anglebench_separateCalibration). "" for any other certificate."""
    if not meta.separate_from:
        return ""
    if "," in meta.separate_from:  # more than one still valid
        return message(QT_TR_NOOP("A calibration of its own, separate from certificates "
                                  "{numbers} of the same item and date of calibration, which "
                                  "stay valid: {reason}"),
                       numbers=meta.separate_from, reason=meta.change_note)
    return message(QT_TR_NOOP("A calibration of its own, separate from certificate {numbers} "
                              "of the same item and date of calibration, which stays valid: "
                              "{reason}"), numbers=meta.separate_from, reason=meta.change_note)


def withdrawn_statement(meta: CertificateMetadata) -> Any:
    """An original issued for the item and date of calibration of certificates withdrawn
    (``meta.replaces_withdrawn``): it names them, when and why they were withdrawn and what
    it changes against them (``meta.withdrawn_note``; ISO/IEC 17025 7.8.8.3: a new report
    in place of another refers to it — hostile78 F3). The PDF prints it under the title,
    the DCC states it (refType anglebench_inPlaceOfWithdrawn). "" for any other
    certificate."""
    if not meta.replaces_withdrawn:
        return ""
    if not meta.withdrawn_note:
        return message(QT_TR_NOOP("Issued in place of withdrawn certificate(s) {numbers} of the "
                                  "same item and date of calibration"),
                       numbers=meta.replaces_withdrawn)
    return message(QT_TR_NOOP("Issued in place of a withdrawn certificate of the same item and "
                              "date of calibration: {note}"), note=meta.withdrawn_note)


def readings_of_another_item_statement(meta: CertificateMetadata) -> Any:
    """A certificate whose readings are those of certificates of another item in the
    register (``meta.readings_of_another_item``), issued because the user said why
    (``meta.readings_note``, the register's words: "The readings are those of certificate N
    (item X, calibrated D): REASON"; hostile78 F7). The PDF prints it under the title, the
    DCC states it (refType anglebench_readingsOfAnotherItem). "" for any other
    certificate."""
    if not meta.readings_of_another_item:
        return ""
    return meta.readings_note or message(QT_TR_NOOP(
        "The readings are those of certificate(s) {numbers} of another item"),
        numbers=meta.readings_of_another_item)


def revision_statement(meta: CertificateMetadata) -> Any:
    """ISO/IEC 17025 7.8.8: an amendment says what changed and which certificate it amends; a
    replacement identifies the one it replaces. The PDF prints it under the title, the DCC
    states it (refType anglebench_revision) beside coreData/reportAmendedSubstituted, which
    has no room for it. "" for an original."""
    if not meta.supersedes:
        return ""
    number = meta.revision.removeprefix("amendment").strip()
    if meta.revision.startswith("amendment") and number:
        what = message(QT_TR_NOOP("Amendment {number} to certificate {certificate}"),
                       number=number, certificate=meta.supersedes)
    elif meta.revision.startswith("amendment"):
        what = message(QT_TR_NOOP("Amendment to certificate {certificate}"),
                       certificate=meta.supersedes)
    else:
        what = message(QT_TR_NOOP("This certificate replaces certificate {certificate}"),
                       certificate=meta.supersedes)
    if meta.change_note:
        return message(QT_TR_NOOP("{what}, which it supersedes; the original stays on record "
                                  "unchanged. Changed: {change}"), what=what,
                       change=meta.change_note)
    return message(QT_TR_NOOP("{what}, which it supersedes; the original stays on record "
                              "unchanged."), what=what)
