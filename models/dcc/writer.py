"""A certificate as a PTB Digital Calibration Certificate (DCC 3.3.0, D-SI 2.2.1).

One builder for every workbench, fed by the :class:`CertificateDocument` the PDF is printed
from (so the DCC carries the same figures): its metadata (administrative data), its
parameters, statistics and budget tables, its conformity, and its per-point columns
(``point_columns``: every curve the certificate tables). A column's U per point is the
one the certificate prints beside it (``expanded_uncertainty_…``, paired below), or else
the budget the JSON's ``expanded_uncertainty_NAME`` comes from
(``IssuesCertificates.uncertainty_budgets``); k per point from the same budget. The issued
PDF is embedded byte for byte as the root's ``dcc:document``.
"""

from __future__ import annotations

import base64
import math
import re
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

import numpy as np
from lxml import etree

from models.certificate.document import CertificateDocument, Table
from models.certificate.interval_note import interval_cells
from models.certificate.metadata import (
    readings_of_another_item_statement,
    revision_statement,
    separate_statement,
    withdrawn_statement,
)
from models.certificate.report_terms import report_translator
from models.dcc import vocabulary as v
from models.messages import QT_TR_NOOP, declared_text, message, rendered, translator
from models.software import SoftwareIdentity, software_identity
from models.uncertainty.budget import (
    BASIS_DIVISORS,
    DEFAULT_COVERAGE_PROBABILITY,
    divisor_for_basis,
)

if TYPE_CHECKING:
    from lxml.etree import _Element  # (lxml ships no types: pyproject.toml [tool.mypy])

__all__ = ["DccError", "build_dcc", "column_unit"]

D = f"{{{v.DCC_NAMESPACE}}}"
S = f"{{{v.SI_NAMESPACE}}}"


class DccError(ValueError):
    """The certificate cannot be written as a DCC (a field the schema requires is missing);
    the message names the field."""


#: a column's unit by its name's ending: D-SI unit
_UNIT_SUFFIXES = {"_deg": r"\degree", "_arcsec": r"\arcsecond", "_urad": r"\micro\radian",
                  "_mrad": r"\milli\radian", "_rad": r"\radian", "_nm": r"\nano\metre",
                  "_um": r"\micro\metre", "_mm": r"\milli\metre"}
#: a printed unit symbol (a table cell's ending) → D-SI unit
_SYMBOLS = {"°": r"\degree", '"': r"\arcsecond", "″": r"\arcsecond", "′": r"\arcminute",
            "µrad": r"\micro\radian", "μrad": r"\micro\radian", "urad": r"\micro\radian",
            "rad": r"\radian", "mdeg": r"\milli\degree", "nm": r"\nano\metre",
            "µm": r"\micro\metre", "μm": r"\micro\metre", "mm": r"\milli\metre",
            "V": r"\volt", "mV": r"\milli\volt", "%": r"\percent", "": r"\one"}
#: seconds of arc in one of each angle unit (a parameter's U printed in another unit)
_ARCSEC = {r"\degree": 3600.0, r"\arcminute": 60.0, r"\arcsecond": 1.0,
           r"\radian": 648000.0 / math.pi, r"\micro\radian": 0.648 / math.pi,
           r"\milli\degree": 3.6}
#: PTB's basic refTypes for a column's role
_NOMINAL = ("theta_deg", "nominal_deg", "step_deg", "phase_deg", "target")
_INDICATED = ("encoder_reading_deg",)
_NUMBER = re.compile(r"^([+\-−]?\d+(?:\.\d+)?(?:[eE][+\-]?\d+)?)\s*(.*)$")

#: "zh-report": a test report's Chinese, its item in the report's terms (被检测对象)
_WORDS = {"en": translator("en"), "zh": translator("zh_CN"),
          "zh-report": report_translator(translator("zh_CN"))}


def _say(text: Any, lang: str) -> str:
    """A text of the certificate in ``lang``: a message rendered, a QT_TR_NOOP text looked
    up, typed text as it is."""
    words = _WORDS[lang]
    if isinstance(text, _Cells):
        return text.said(lang)
    if hasattr(text, "template") or hasattr(text, "parts"):
        return rendered(text, words)
    return declared_text(str(text), words)  # a label ending in a unit: its words, the unit kept


def column_unit(name: str, error_unit: str, stated: Mapping[str, str] | None = None) -> str:
    """The D-SI unit of a per-point column from its name ("theta_deg": \\degree), or from
    the unit symbol ``stated`` for it (CertificateDocument.point_column_units: positioning's
    "target" in "mm" is \\milli\\metre)."""
    symbol = (stated or {}).get(name)
    if symbol is not None and symbol.strip() in _SYMBOLS:
        return _SYMBOLS[symbol.strip()]
    for suffix, unit in _UNIT_SUFFIXES.items():
        if name.endswith(suffix):
            return unit
    return r"\one"


def _camel(name: str) -> str:
    head, *rest = name.split("_")
    return head + "".join(p[:1].upper() + p[1:] for p in rest)


def _figure(x: float) -> str:
    """A number for xs:double / si:decimal: repr's shortest round trip, no "nan"."""
    x = float(x)
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "INF" if x > 0 else "-INF"
    if x == 0.0:  # -0.0 too (a reference point's error computed as −0.0): "0", never "-0"
        return "0"
    return f"{x:.12g}"  # 12 significant digits: beyond every printed figure, no float noise


@dataclass
class _Builder:
    document: CertificateDocument
    bilingual: bool
    own_reftypes: dict[str, str] = field(default_factory=dict)  # name → description (en)

    # -- primitives ------------------------------------------------------------
    def ref(self, name: str, description: str = "") -> str:
        if name.startswith(v.ANGLEBENCH_REFTYPE_PREFIX):
            self.own_reftypes.setdefault(name, description)
        return name

    def text(self, parent, tag: str, content: Any, translated: bool = True, **attrs):
        el = etree.SubElement(parent, D + tag, **attrs)
        self.contents(el, content, translated)
        return el

    def contents(self, el, content: Any, translated: bool = True) -> None:
        if not translated:
            etree.SubElement(el, D + "content").text = str(content)
            return
        en = _say(content, "en")
        etree.SubElement(el, D + "content", lang="en").text = en
        if self.bilingual:
            etree.SubElement(el, D + "content", lang="zh").text = _say(
                content, "zh-report" if self.document.is_test_report else "zh")

    def rich(self, parent, tag: str, content: Any, translated: bool = True, **attrs):
        return self.text(parent, tag, content, translated, **attrs)

    @staticmethod
    def leaf(parent, tag: str, value: str, ns: str = D):
        el = etree.SubElement(parent, ns + tag)
        el.text = value
        return el

    def real(self, parent, value: float, unit: str, expanded: float | None = None,
             k: float | None = None, p: float | None = None, label: str = ""):
        r = etree.SubElement(parent, S + "real")
        if label:
            self.leaf(r, "label", label, S)
        self.leaf(r, "value", _figure(value), S)
        self.leaf(r, "unit", unit, S)
        if expanded is not None and k is not None and p is not None:
            mu = etree.SubElement(etree.SubElement(r, S + "measurementUncertaintyUnivariate"),
                                  S + "expandedMU")
            self.leaf(mu, "valueExpandedMU", _figure(expanded), S)
            self.leaf(mu, "coverageFactor", _figure(k), S)
            self.leaf(mu, "coverageProbability", _figure(p), S)
        return r

    def real_list(self, parent, values, unit: str, expanded=None, k=None, p: float | None = None):
        r = etree.SubElement(parent, S + "realListXMLList")
        self.leaf(r, "valueXMLList", " ".join(_figure(x) for x in values), S)
        self.leaf(r, "unitXMLList", unit, S)
        if expanded is not None and k is not None and p is not None:
            mu = etree.SubElement(etree.SubElement(r, S + "measurementUncertaintyUnivariateXMLList"),
                                  S + "expandedMUXMLList")
            self.leaf(mu, "valueExpandedMUXMLList", " ".join(_figure(x) for x in expanded), S)
            self.leaf(mu, "coverageFactorXMLList", " ".join(_figure(x) for x in k), S)
            self.leaf(mu, "coverageProbabilityXMLList", _figure(p), S)
        return r

    def quantity(self, parent, name: Any, ref_type: str, translated: bool = True):
        q = etree.SubElement(parent, D + "quantity", refType=ref_type)
        self.text(q, "name", name, translated)
        return q


def _contact(b: _Builder, parent, tag: str, name: str, address: str, country: str = ""):
    c = etree.SubElement(parent, D + tag)
    b.text(c, "name", name, translated=False)
    loc = etree.SubElement(c, D + "location")
    if address:
        b.rich(loc, "further", address, translated=False)
    if country:
        b.leaf(loc, "countryCode", country)
    if not address and not country:
        b.rich(loc, "further", QT_TR_NOOP("not stated"))
    return c


def _required(value: str, name: str) -> str:
    if not value:
        raise DccError(message(QT_TR_NOOP(
            "no DCC written: the certificate's field '{field_name}' is empty and the DCC "
            "schema requires it"), field_name=name))
    return value


def _administrative(b: _Builder, root, software: SoftwareIdentity) -> _Element:
    """The administrative data; returns its refTypeDefinitions, filled at the end."""
    meta = b.document.metadata
    admin = etree.SubElement(root, D + "administrativeData")
    sw = etree.SubElement(etree.SubElement(admin, D + "dccSoftware"), D + "software")
    b.text(sw, "name", "AngleBench", translated=False)
    b.leaf(sw, "release", software.printed)
    b.leaf(sw, "type", "application")
    b.rich(sw, "description", message(QT_TR_NOOP("source: {source}"), source=software.source))
    refdefs = etree.SubElement(admin, D + "refTypeDefinitions")  # filled at the end
    core = etree.SubElement(admin, D + "coreData")
    country = (meta.lab_country or "").upper()
    if not re.fullmatch(r"[A-Z]{2}", country):
        raise DccError(message(QT_TR_NOOP(
            "no DCC written: the certificate's field 'lab_country' must be the laboratory's "
            "ISO 3166-1 country code (two letters, e.g. CN), not '{value}'"), value=country))
    b.leaf(core, "countryCodeISO3166_1", country)
    for lang in v.LANGUAGES if b.bilingual else ("en",):
        b.leaf(core, "usedLangCodeISO639_1", lang)
    for lang in v.MANDATORY_LANGUAGES:
        b.leaf(core, "mandatoryLangCodeISO639_1", lang)
    b.leaf(core, "uniqueIdentifier", _required(meta.certificate_number, "certificate_number"))
    date = _required(meta.calibration_date, "calibration_date")
    b.leaf(core, "beginPerformanceDate", date)
    b.leaf(core, "endPerformanceDate", date)
    b.leaf(core, "performanceLocation",
           "customer" if meta.calibration_place == "customer_site" else "laboratory")
    if meta.issue_date:
        b.leaf(core, "issueDate", meta.issue_date)
    if meta.supersedes:
        ch = etree.SubElement(core, D + "reportAmendedSubstituted")
        # DCC 3.3.0's enumeration (coreDataType): "amended" or "substituted"
        b.leaf(ch, "typeOfChange",
               "substituted" if meta.revision == "replacement" else "amended")
        b.leaf(ch, "replacedUniqueIdentifier", meta.supersedes)

    items = etree.SubElement(admin, D + "items")
    item = etree.SubElement(items, D + "item")
    b.text(item, "name", _required(meta.item_description, "item_description"), translated=False)
    if meta.item_grade:
        b.rich(item, "description", message(QT_TR_NOOP("grade: {grade}"), grade=meta.item_grade))
    if meta.item_manufacturer:
        m = etree.SubElement(item, D + "manufacturer")
        b.text(m, "name", meta.item_manufacturer, translated=False)
    if meta.item_model:
        b.leaf(item, "model", meta.item_model)
    ids = etree.SubElement(item, D + "identifications")
    ident = etree.SubElement(ids, D + "identification")
    b.leaf(ident, "issuer", "manufacturer")
    b.leaf(ident, "value", _required(meta.item_serial, "item_serial"))
    b.text(ident, "name", QT_TR_NOOP("Serial number"))

    lab = etree.SubElement(admin, D + "calibrationLaboratory")
    if meta.lab_accreditation:
        b.leaf(lab, "calibrationLaboratoryCode", meta.lab_accreditation)
    _contact(b, lab, "contact", _required(meta.lab_name, "lab_name"), meta.lab_address, country)

    persons = etree.SubElement(admin, D + "respPersons")
    for who, role, main, ref in ((meta.operator, QT_TR_NOOP("operator"), False, v.REFTYPE_OPERATOR),
                                 (meta.checker if meta.checker_role else "", QT_TR_NOOP("checker"),
                                  False, "anglebench_checker"),
                                 (meta.approver, QT_TR_NOOP("approver"), True, v.REFTYPE_APPROVER)):
        if not who:
            continue
        p = etree.SubElement(persons, D + "respPerson", refType=b.ref(ref, f"the {role}"))
        b.text(etree.SubElement(p, D + "person"), "name", who, translated=False)
        b.leaf(p, "role", _say(role, "en"))
        if main:
            b.leaf(p, "mainSigner", "true")
    if not len(persons):
        _required("", "approver")
    _contact(b, admin, "customer", _required(meta.customer_name, "customer_name"),
             meta.customer_address)
    _statements(b, admin)
    return refdefs


def _name_references(statement, numbers: str) -> None:
    """Each certificate number of ``numbers`` (comma-separated) named as a reference of
    ``statement``, before its declaration, in the order given."""
    declaration = statement.find(D + "declaration")
    for number in (n.strip() for n in numbers.split(",")):
        if number:
            reference = etree.Element(D + "reference")
            reference.text = number
            declaration.addprevious(reference)


def _statement(b: _Builder, parent, ref: str, description: str, *texts: Any, **fields):
    st = etree.SubElement(parent, D + "statement", refType=b.ref(ref, description))
    for key in ("convention", "traceable", "norm", "reference"):
        if key in fields and fields[key] not in (None, ""):
            b.leaf(st, key, fields[key])
    desc = etree.SubElement(st, D + "declaration")
    for t in texts:
        if t:
            b.contents(desc, t)
    if fields.get("conformity"):
        b.leaf(st, "conformity", fields["conformity"])
    return st


_CONFORMITY = {"pass": "pass", "fail": "fail", "conditional pass": "conditionalPass",
               "conditional fail": "conditionalFail"}


def _statements(b: _Builder, admin) -> None:
    doc = b.document
    sts = etree.SubElement(admin, D + "statements")
    if doc.specimen:
        # a specimen says so, as its PDF does, and claims no certificate, traceability or
        # conformity a machine reader could take as issued (assessment 70 M6: it declared
        # "This document is a calibration certificate.", traceable true, conformity pass)
        _statement(b, sts, v.REFTYPE_SPECIMEN,
                   "the document is a specimen: not a certificate, recorded in no register",
                   SPECIMEN, traceable="false")
    if doc.is_test_report:
        why = [*doc.untraceable, *doc.traceability_gaps]  # as the PDF's statement names them
        _statement(b, sts, v.REFTYPE_NOT_A_CALIBRATION,
                   "the document is a test report, not a calibration certificate",
                   QT_TR_NOOP("This document is a test report, not a calibration certificate: "
                              "its results are not stated as traceable to the SI."),
                   *why, traceable="false")
    elif not doc.specimen:
        _statement(b, sts, v.REFTYPE_CALIBRATION_CERTIFICATE,
                   "the document is a calibration certificate",
                   DOCS_CALIBRATION)
    c = doc.conformity
    _statement(b, sts, v.REFTYPE_CONFORMITY,
               "statement of conformity with its decision rule and the probability of false "
               "acceptance", c.statement, c.rule, c.quantity, c.zones,
               conformity="" if doc.specimen else _CONFORMITY.get(c.verdict, ""))
    # why traceability is not established (an input with no stated U, U incomplete, a
    # standard missing), never "traceable" beside traceable=false
    trace = [*doc.untraceable, *doc.traceability_gaps] or [
        SPECIMEN_TRACEABILITY if doc.specimen else doc.traceability_basis or QT_TR_NOOP(
            "The results are traceable to the SI through the reference standards listed with "
            "their calibration certificates (see measuringEquipments).")]
    _statement(b, sts, v.REFTYPE_TRACEABILITY, "metrological traceability", *trace,
               traceable="false" if doc.is_test_report or doc.untraceable or doc.specimen
               else "true")
    _statement(b, sts, v.REFTYPE_MEASURAND, "the measurand's definition and sign convention",
               doc.method, doc.sign_convention, convention=_say(doc.sign_convention, "en"),
               reference=_say(doc.method_reference, "en") if doc.method_reference else None)
    _statement(b, sts, v.REFTYPE_VALIDITY, "validity of the certificate",
               VALIDITY_REPORT if doc.is_test_report else VALIDITY)
    revision = revision_statement(doc.metadata)
    if revision:
        # an amendment or replacement identifies the change (ISO/IEC 17025 7.8.8.2), as the
        # PDF does under its title: coreData/reportAmendedSubstituted (DCC 3.3.0) holds the
        # type of change and the number only, so a statement says what changed, in each
        # language, the certificate it supersedes as its reference
        st = _statement(b, sts, v.REFTYPE_REVISION,
                        "what the amendment or replacement changed of the certificate it "
                        "supersedes, named as its reference (ISO/IEC 17025 7.8.8)", revision)
        _name_references(st, doc.metadata.supersedes)
    separate = separate_statement(doc.metadata)
    if separate:
        # a calibration of its own beside certificates of the same item and date that stay
        # valid (ISO/IEC 17025 7.8.8): not an amendment or a replacement, so not
        # coreData/reportAmendedSubstituted, and not coreData/previousReport (one report
        # only, a hash link to the item's previous calibration): a statement naming each
        # certificate it is separate from as a reference, and why, in each language
        st = _statement(b, sts, v.REFTYPE_SEPARATE_CALIBRATION,
                        "a calibration of its own, separate from the certificates of the same "
                        "item and date of calibration named as its references, which stay "
                        "valid; the declaration says why", separate)
        _name_references(st, doc.metadata.separate_from)
    withdrawn = withdrawn_statement(doc.metadata)
    if withdrawn:
        # an original in place of a withdrawn certificate of the same calibration (ISO/IEC
        # 17025 7.8.8.3; hostile78 F3): each withdrawn one named as a reference
        st = _statement(b, sts, v.REFTYPE_IN_PLACE_OF_WITHDRAWN,
                        "an original issued in place of the withdrawn certificates of the same "
                        "item and date of calibration named as its references; the declaration "
                        "says when and why each was withdrawn and what this one changes",
                        withdrawn)
        _name_references(st, doc.metadata.replaces_withdrawn)
    readings = readings_of_another_item_statement(doc.metadata)
    if readings:
        # the readings are another item's certificates', the user said why (hostile78 F7):
        # each of those certificates named as a reference
        st = _statement(b, sts, v.REFTYPE_READINGS_OF_ANOTHER_ITEM,
                        "the readings are those of the certificates of another item named as "
                        "its references; the declaration names their item and date of "
                        "calibration and says why", readings)
        _name_references(st, doc.metadata.readings_of_another_item)
    for extra in (*filter(None, [doc.not_in_u_statement]), *doc.statements, *doc.warnings):
        _statement(b, sts, "anglebench_remark", "a statement or warning of the certificate",
                   extra)


DOCS_CALIBRATION = QT_TR_NOOP("This document is a calibration certificate.")
#: a specimen's first statement, in place of :data:`DOCS_CALIBRATION` (its PDF's notice)
SPECIMEN = QT_TR_NOOP("This document is a SPECIMEN, made from example details for training or "
                      "demonstration: not a certificate, not recorded in any register. Its "
                      "results, traceability and statement of conformity are examples, issued "
                      "to no one: none may be relied on.")
#: a specimen's traceability statement (traceable false): nothing of it is issued
SPECIMEN_TRACEABILITY = QT_TR_NOOP("A specimen claims no metrological traceability for its "
                                   "results: it is issued to no one.")
VALIDITY = QT_TR_NOOP("The results relate only to the item calibrated, at the time and under "
                      "the conditions of the calibration. This digital certificate and the PDF "
                      "embedded in it are one certificate; the embedded PDF is its "
                      "human-readable form.")
#: a test report's (notACalibration): the item tested, one report (ISO/IEC 17025 7.8.2.1 a))
VALIDITY_REPORT = QT_TR_NOOP("The results relate only to the item tested, at the time and under "
                             "the conditions of the test. This digital document and the PDF "
                             "embedded in it are one test report; the embedded PDF is its "
                             "human-readable form.")


def _parse(cell: str) -> tuple[float, str] | None:
    """A printed figure "5.82625°", '6.3"', "-0.01782 V" as (value, D-SI unit); None when
    the cell is not one figure with a known unit."""
    m = _NUMBER.match(cell.strip().replace("−", "-"))
    if not m:
        return None
    unit = _SYMBOLS.get(m.group(2).strip())
    exact = getattr(cell, "exact", None)  # a figure printed rounded: stated at full precision
    value = float(exact) if isinstance(exact, int | float) else float(m.group(1))
    return (value, unit) if unit is not None else None


#: the one description of refType anglebench_coverageProbability (an interval's, a U's)
_COVERAGE_PROBABILITY = ("the coverage probability p of the figure it is listed with: of its "
                         "coverage interval, or of the expanded uncertainty U")


def _interval(b: _Builder, parent, name: Any, value: float, unit: str, low: float, high: float,
              p: float, ref: str, translated: bool = True) -> None:
    """A figure with its coverage interval (asymmetric, or from a simulation: no standard
    uncertainty to state) as a dcc:list: the value, the interval's ends, the probability."""
    lst = etree.SubElement(parent, D + "list", refType=b.ref(
        ref, "a figure with its coverage interval: value, intervalMin, intervalMax, p"))
    b.text(lst, "name", name, translated)
    for part, figure, part_unit in (("value", value, unit), ("intervalMin", low, unit),
                                    ("intervalMax", high, unit),
                                    ("coverageProbability", p, r"\one")):
        q = etree.SubElement(lst, D + "quantity", refType=b.ref(
            f"anglebench_{part}", _COVERAGE_PROBABILITY if part == "coverageProbability"
            else f"of a figure with its coverage interval: {part}"))
        b.text(q, "name", part, translated=False)
        b.real(q, figure, part_unit)


_K_IN_HEADER = re.compile(r"k\s*=\s*(\d+(?:\.\d+)?)")
_INTERVAL = re.compile(r"^(.+?)\s*…\s*(.+)$")
_PERCENT = re.compile(r"^(\d+(?:\.\d+)?)\s*%$")


def _printed_probability(percent: str, p: float) -> float:
    """A probability printed as a percentage ("95.45") as a number: the document's stated
    ``p`` itself when the printed figure is it rounded (one value in the whole DCC, not
    0.9545 beside 0.954499736104), else the figure printed (a probability reached)."""
    decimals = len(percent.partition(".")[2])
    if f"{100.0 * p:.{decimals}f}" == percent:
        return p
    return float(percent) / 100.0


def _table_result(b: _Builder, results, table: Table, ref: str, description: str,
                  row_ref: str, row_description: str, p: float) -> None:
    """A table of (label, value, U or interval or note …) rows as one result, each row as
    printed: a figure with its U (the k the table's header prints) as si:real with
    expandedMU, converted to the figure's unit; a figure with its coverage interval and
    probability as a list; a figure alone as si:real; any other row as its text."""
    if not table.rows:
        return
    res = etree.SubElement(results, D + "result", refType=b.ref(ref, description))
    b.text(res, "name", table.title)
    data = etree.SubElement(res, D + "data")
    header_k = _K_IN_HEADER.search(_say(table.header[2], "en")) if len(table.header) > 2 else None
    for row in table.rows:
        label, value = row[0], row[1] if len(row) > 1 else ""
        rest = [c for c in row[2:] if c]
        figure = _parse(value) if "\n" not in value else None
        u = _parse(rest[0]) if rest and header_k else None
        if figure and u and u[1] != figure[1] and u[1] in _ARCSEC and figure[1] in _ARCSEC:
            u = (u[0] * _ARCSEC[u[1]] / _ARCSEC[figure[1]], figure[1])
        # an interval in the note beside the figure (the theodolite's ISO 230-2 figures) as
        # positioning's in its columns: a list of numbers, not the note's text (audit 69 F5)
        noted = interval_cells(rest[0]) if rest else None
        spans = [*noted, *rest[1:]] if noted else rest
        span = _INTERVAL.match(spans[0].replace("−", "-")) if spans else None
        ends = (_parse(span.group(1)), _parse(span.group(2))) if span else (None, None)
        exact = getattr(spans[0], "exact", None) if spans else None  # the ends unrounded
        if isinstance(exact, tuple) and ends[0] and ends[1]:
            ends = ((float(exact[0]), ends[0][1]), (float(exact[1]), ends[1][1]))
        share = _PERCENT.match(spans[1].strip()) if len(spans) > 1 else None
        if figure and ends[0] and ends[1] and share and ends[0][1] == ends[1][1] == figure[1]:
            _interval(b, data, label, figure[0], figure[1], ends[0][0], ends[1][0],
                      _printed_probability(share.group(1), p), row_ref)
            continue
        q = etree.SubElement(data, D + "quantity", refType=b.ref(row_ref, row_description))
        b.text(q, "name", label)
        if figure and u and header_k and u[1] == figure[1]:  # (a u is read only under a k)
            if rest[1:]:
                b.rich(q, "description", _Cells(rest[1:], " · "))
            b.real(q, figure[0], figure[1], u[0], float(header_k.group(1)), p)
        elif figure and not rest:
            b.real(q, figure[0], figure[1])
        else:
            # each cell in each language of the document, as the PDF prints it (our texts
            # "not identified …", "peak-to-peak …" were English only up to 0.8.8)
            b.rich(q, "noQuantity", _Cells([c for c in (value, *rest) if c], " — "))


@dataclass(frozen=True)
class _Cells:
    """Cells of a table row as one text: each said in the language asked (a message
    rendered, a QT_TR_NOOP text looked up, typed text as it is), joined by ``separator``."""

    cells: list[Any]
    separator: str

    def said(self, lang: str) -> str:
        return self.separator.join(_say(c, lang) for c in self.cells)


def _k_lookup(budgets) -> Callable[[float], float | None]:
    """k of the budget point whose U is ``u`` (the certificate's U per point is one of the
    budgets' own)."""
    pairs: dict[float, float] = {}
    for budget in budgets:
        if budget is None:
            continue
        for u, k in zip(np.ravel(budget.expanded), np.ravel(budget.coverage_factors), strict=False):
            pairs.setdefault(round(float(u), 12), float(k))
    return lambda u: pairs.get(round(float(u), 12))


def _same_expanded(budget, expanded: np.ndarray) -> bool:
    """Whether ``budget`` (a budget or a PointUncertainty) gives ``expanded``, point by point."""
    return (budget is not None and np.size(budget.expanded) == expanded.size
            and np.allclose(np.asarray(budget.expanded, dtype=float), expanded, rtol=0.0,
                            atol=1e-12, equal_nan=True))


def _coverage_factors(expanded: np.ndarray, budgets) -> np.ndarray | None:
    """k of each point of a column whose U is ``expanded``: those of the budget that gives
    this very U array when one does (where the laboratory's CMC makes several points' U one
    figure, a lookup by value would take the first budget point of that U, another
    quantity's or another point's k), else each point's from the budget point of its U
    (:func:`_k_lookup`); None when a point's is not found."""
    held = next((budget for budget in budgets if _same_expanded(budget, expanded)), None)
    if held is not None:
        return np.asarray(held.coverage_factors, dtype=float).reshape(-1)
    k_of = _k_lookup(budgets)
    factors = [k_of(u) for u in expanded]
    return None if any(x is None for x in factors) else np.asarray(factors, dtype=float)


def _curves(b: _Builder, results, pairs: Mapping[str, str], budgets: Mapping[str, Any],
            p: float, notes: Mapping[str, Any] | None = None) -> None:
    doc = b.document
    columns = dict(doc.point_columns)
    if not columns:
        return
    res = etree.SubElement(results, D + "result", refType=b.ref(
        v.REFTYPE_CURVE, "the certificate's results per point, each error with its U, k and p"))
    b.text(res, "name", doc.results.title)
    lst = etree.SubElement(etree.SubElement(res, D + "data"), D + "list")
    # the certificate's column headers, when its table has one per column (not positioning's,
    # whose table puts the two directions side by side), or one per column up to U columns
    # only the results export has (the fringe's compensated error's U)
    printed = len(doc.results.header)
    headers = (dict(zip(list(columns)[:printed], doc.results.header, strict=True))
               if printed == len(columns) or (printed < len(columns) and all(
                   name.startswith("expanded_uncertainty_") for name in list(columns)[printed:]))
               else {})
    for name, values in doc.point_columns:
        if name.startswith("expanded_uncertainty_"):
            continue
        values = np.asarray(values)
        unit = column_unit(name, doc.unit, dict(doc.point_column_units))
        stem = next((name[:-len(s)] for s in _UNIT_SUFFIXES if name.endswith(s)), name)
        expanded: np.ndarray | None = None
        k: np.ndarray | None = None
        if stem in pairs:
            u_name = "expanded_uncertainty_" + pairs[stem] + name[len(stem) + 1:]
            if u_name in columns:
                expanded = np.asarray(columns[u_name], dtype=float)
                k = _coverage_factors(expanded, [doc.budget, *budgets.values()])
                if k is None:
                    raise DccError(message(QT_TR_NOOP(
                        "no DCC written: the coverage factor of a point of '{column}' is not "
                        "found in its budget"), column=name))
        elif name in budgets and budgets[name] is not None and \
                np.size(budgets[name].expanded) == values.size:
            expanded = np.asarray(budgets[name].expanded, dtype=float)
            k = np.asarray(budgets[name].coverage_factors, dtype=float)
        if values.dtype.kind not in "biuf":
            q = etree.SubElement(lst, D + "quantity", refType=b.ref("anglebench_" + _camel(name), name))
            _column_name(b, q, name, headers)
            chars = etree.SubElement(q, D + "charsXMLList")
            chars.text = " ".join(str(x) for x in values)
            continue
        if name in _NOMINAL:
            ref = v.PTB_NOMINAL_VALUE
        elif name in _INDICATED:
            ref = v.PTB_MEASURED_VALUE
        elif "error" in stem or "deviation" in stem and stem != "s":
            ref = v.PTB_MEASUREMENT_ERROR
        else:
            ref = b.ref("anglebench_" + _camel(stem), stem.replace("_", " "))
        q = etree.SubElement(lst, D + "quantity",
                             refType=f"{ref} {b.ref('anglebench_' + _camel(stem), stem)}"
                             if not ref.startswith("anglebench_") else ref)
        _column_name(b, q, name, headers)
        note = (notes or {}).get(name) or (notes or {}).get(stem)  # by key, or unit-free
        if expanded is not None and note:
            b.rich(q, "description", note)
        b.real_list(q, values.astype(float), unit, expanded, k, p)
        if expanded is not None:
            _raised_to_cmc(b, q, expanded, [doc.budget, *budgets.values()], unit)


def _raised_to_cmc(b: _Builder, q, expanded: np.ndarray, budgets, unit: str) -> None:
    """Where the laboratory's CMC holds a per-point quantity's U: which points' U is the CMC
    (the budget gave less; ILAC-P14 5.4), as a dcc:metaData whose validXMLList marks them
    (true: U is the CMC there) beside the CMC itself. The k of those points stays their
    coverage factor (coverageFactorXMLList), so U/k there is the CMC's standard uncertainty,
    not the budget's u_c; the declaration says so. Nothing where no CMC holds the U (no CMC
    set, or a U the CMC does not apply to, as a correction's own)."""
    held = next((budget for budget in budgets
                 if budget is not None and float(getattr(budget, "floor", 0.0) or 0.0) > 0
                 and getattr(budget, "below_floor", None) is not None
                 and _same_expanded(budget, expanded)), None)
    if held is None:
        return
    cmc = float(held.floor)
    raised = np.asarray(held.below_floor, dtype=bool)
    meta = etree.SubElement(etree.SubElement(q, D + "measurementMetaData"), D + "metaData",
                            refType=b.ref(v.REFTYPE_U_RAISED_TO_CMC, CMC_FLAGS_DESCRIPTION))
    b.text(meta, "name", QT_TR_NOOP("U raised to the laboratory's CMC"))
    count = int(np.count_nonzero(raised))
    b.rich(meta, "declaration", message(QT_TR_NOOP(
        "The laboratory's calibration and measurement capability (CMC) U = {cmc} holds this "
        "quantity's U. At the {count} of the {points} points marked true the U these readings "
        "give is below it, so their U is stated as the CMC, with the same coverage factor k "
        "(ILAC-P14 5.4); there U/k is the CMC's standard uncertainty, not the budget's u_c. "
        "At the points marked false U is the budget's own."),
        cmc=f"{cmc:g}{_UNIT_SIGNS.get(unit, '')}", count=count, points=raised.size))
    b.leaf(meta, "validXMLList", " ".join("true" if r else "false" for r in raised))
    cq = etree.SubElement(etree.SubElement(meta, D + "data"), D + "quantity", refType=b.ref(
        "anglebench_laboratoryCmc", "the laboratory's CMC for the quantity: its smallest U"))
    b.text(cq, "name", QT_TR_NOOP("Laboratory's CMC (smallest U)"))
    b.real(cq, cmc, unit)


CMC_FLAGS_DESCRIPTION = ("per point of the quantity it is in (validXMLList, in the order of its "
                         "values): true where the U stated is the laboratory's CMC because the "
                         "budget gave less (ILAC-P14 5.4), k unchanged; the CMC in its data")
#: a D-SI unit's sign in a sentence (the CMC's figure)
_UNIT_SIGNS = {r"\arcsecond": '"', r"\degree": "°", r"\arcminute": "′", r"\micro\radian": " µrad",
               r"\milli\radian": " mrad", r"\radian": " rad", r"\nano\metre": " nm",
               r"\micro\metre": " µm", r"\milli\metre": " mm", r"\milli\degree": " mdeg"}


def _column_name(b: _Builder, q, name: str, headers: Mapping[str, str]) -> None:
    """A per-point quantity's name: the certificate's column header in each language, and
    the column's key (that of the CSV/XLSX export)."""
    el = etree.SubElement(q, D + "name")
    if name in headers:
        b.contents(el, headers[name])
    etree.SubElement(el, D + "content").text = name


#: the refTypes of a polygon's face deviations: the polygon calibrated (the reader's), and a
#: reference polygon's as its own certificate states them (never read as the polygon's)
_FACE_RESULTS = {
    v.REFTYPE_POLYGON_FACE_DEVIATIONS: "a polygon's face deviations from face 1 with U: the "
    "polygon calibrated, this certificate's item",
    v.REFTYPE_REFERENCE_POLYGON_FACE_DEVIATIONS: "a reference polygon's face deviations from "
    "face 1 with U, as its own certificate states them: the polygon the item was calibrated "
    "against, not a result of this calibration (its certificate is the reference standard's "
    "listed in measuringEquipments)"}


def _face_form(b: _Builder, results, name: Any, dev, u, k, p: float,
               ref: str = v.REFTYPE_POLYGON_FACE_DEVIATIONS) -> Any:
    """Face deviations from face 1 in the shared vocabulary (the reader's form), as the
    result of refType ``ref`` (:data:`_FACE_RESULTS`); returns the deviations' quantity."""
    res = etree.SubElement(results, D + "result", refType=b.ref(ref, _FACE_RESULTS[ref]))
    b.text(res, "name", name)
    lst = etree.SubElement(etree.SubElement(res, D + "data"), D + "list")
    q = b.quantity(lst, QT_TR_NOOP("Face"), b.ref(v.REFTYPE_FACE_INDEX, "face number 1..N"))
    b.real_list(q, np.arange(1, len(dev) + 1, dtype=float), v.FACE_INDEX_UNIT)
    q = b.quantity(lst, QT_TR_NOOP("Face deviation"), b.ref(
        v.REFTYPE_FACE_DEVIATION, "face deviation from face 1, arcseconds, with U"))
    b.real_list(q, dev, v.FACE_DEVIATION_UNIT, u, k, p)
    return q


def _face_deviations(b: _Builder, results, column: str, pairs: Mapping[str, str],
                     budgets: Mapping[str, Any], p: float) -> None:
    """The polygon's face deviations from face 1 in the shared vocabulary (the reader's
    form), in arcseconds, with the U the certificate prints beside them."""
    columns = dict(b.document.point_columns)
    if column not in columns or not column.endswith("_arcsec"):
        return
    stem = column[:-len("_arcsec")]
    dev = np.asarray(columns[column], dtype=float)
    u = np.asarray(columns[f"expanded_uncertainty_{pairs.get(stem, '')}arcsec"], dtype=float)
    held = [b.document.budget, *budgets.values()]
    k = _coverage_factors(u, held)
    if k is None:
        raise DccError(message(QT_TR_NOOP("no DCC written: the coverage factor of a face "
                                          "deviation is not found in its budget")))
    q = _face_form(b, results, QT_TR_NOOP("Polygon face deviations (from face 1)"), dev, u, k, p)
    # where the laboratory's CMC holds these U (the certificate's column): the same marks
    _raised_to_cmc(b, q, u, held, v.FACE_DEVIATION_UNIT)


def _decided(b: _Builder, results, p: float) -> None:
    """The decided quantity: its value and coverage interval (from the simulation, or ± U),
    with the statement made on it."""
    c = b.document.conformity
    if not math.isfinite(c.value):
        return
    res = etree.SubElement(results, D + "result", refType=b.ref(
        "anglebench_decidedQuantity", "the decided quantity with its coverage interval"))
    b.text(res, "name", QT_TR_NOOP("Decided quantity"))
    if c.quantity:
        b.rich(res, "description", c.quantity)
    data = etree.SubElement(res, D + "data")
    unit = _SYMBOLS.get({"arcsec": '"', "urad": "µrad", "nm": "nm", "um": "µm", "mdeg": "mdeg"}
                        .get(c.unit, c.unit), r"\one")
    low, high = c.interval_low, c.interval_high
    if math.isfinite(low) and math.isfinite(high):
        _interval(b, data, QT_TR_NOOP("Decided quantity"), c.value, unit, low, high,
                  c.probability if math.isfinite(c.probability) else p,
                  "anglebench_decidedQuantity")
    else:
        q = etree.SubElement(data, D + "quantity", refType="anglebench_decidedQuantity")
        b.text(q, "name", QT_TR_NOOP("Decided quantity"))
        b.real(q, c.value, unit)
    _tolerance_stated(b, data)


def _tolerance_stated(b: _Builder, data) -> None:
    """The tolerance ±T as the customer stated it, beside the decided quantity: its number
    in its own unit, the number as typed (trailing zeros kept: the place ASTM E29 rounds a
    value compared with it to) its si:label, so that a machine reader redoes the decision
    from the DCC's figures (assessment 73 M4: T only inside the statement's text). None
    where the tolerance decided is not one the details state (a polygon's grade)."""
    from models.quantity import UNITS
    from models.uncertainty.rounding import stated_decimals

    stated = getattr(b.document.tolerance, "stated", None)
    if stated is None or stated[1] not in UNITS:
        return
    number, key = stated
    q = etree.SubElement(data, D + "quantity", refType=b.ref(
        "anglebench_toleranceStated", "the tolerance ±T as the customer stated it, in its "
        "unit; its si:label is the number as typed, to the places typed"))
    b.text(q, "name", QT_TR_NOOP("Tolerance as stated"))
    b.real(q, float(number), _SYMBOLS.get(UNITS[key].symbol, r"\one"),
           label=f"{float(number):.{stated_decimals(number)}f}")


def _budget(b: _Builder, results, unit: str) -> None:
    budget = b.document.budget
    if not budget.components:
        return
    res = etree.SubElement(results, D + "result", refType=b.ref(
        v.REFTYPE_BUDGET, "the uncertainty budget at the point with the largest U"))
    b.text(res, "name", QT_TR_NOOP("Uncertainty budget"))
    b.rich(res, "description", b.document.budget_point)  # ("position 9": in each language)
    lst = etree.SubElement(etree.SubElement(res, D + "data"), D + "list")
    for row in budget.table():
        q = etree.SubElement(lst, D + "quantity", refType=b.ref(
            "anglebench_budgetComponent", "one input of the budget: its standard uncertainty "
            "contribution c·u"))
        b.text(q, "name", row["name"])
        b.rich(q, "description",
               f"type {row['evaluation']}, {row['distribution']}, value {row['value']!r}, "
               f"divisor {row['divisor']!r}, u {row['u']!r}, c {row['sensitivity']!r}, "
               f"share {row['share']!r}, dof {row['dof']!r}", translated=False)
        b.real(q, row["contribution"], unit)
    i = budget.worst_index
    q = etree.SubElement(lst, D + "quantity", refType=b.ref(
        "anglebench_combinedStandardUncertainty",
        "the combined standard uncertainty u_c at the budget's point (k = 1)"))
    b.text(q, "name", QT_TR_NOOP("Combined standard u_c"))
    b.real(q, float(budget.combined[i]), unit)
    q = etree.SubElement(lst, D + "quantity", refType=b.ref(
        "anglebench_expandedUncertainty", "the expanded uncertainty U = k·u_c at the budget's "
        "point; its k and p are the quantities of refType anglebench_coverageFactor and "
        "anglebench_coverageProbability beside it"))
    # no U stated for the results (CertificateDocument.uncertainty_withheld): the budget's
    # figure is that of the inputs evaluated, a lower bound, and named so
    b.text(q, "name", QT_TR_NOOP("Expanded uncertainty U") if not b.document.uncertainty_withheld
           else QT_TR_NOOP("U of the inputs evaluated only (incomplete: a lower bound, not U)"))
    b.real(q, float(budget.coverage_factor * budget.combined[i]), unit)
    # U's k and p as numbers (U is itself an uncertainty: D-SI has no element that states
    # an uncertainty's own k), named as the coverage interval's parts are (_interval)
    for part, figure, ref, description in (
            ("coverageFactor", budget.coverage_factor, "anglebench_coverageFactor",
             "the coverage factor k of the expanded uncertainty U beside it"),
            ("coverageProbability", budget.probability, "anglebench_coverageProbability",
             _COVERAGE_PROBABILITY)):
        q = etree.SubElement(lst, D + "quantity", refType=b.ref(ref, description))
        b.text(q, "name", part, translated=False)
        b.real(q, float(figure), r"\one")
    if not b.document.uncertainty_withheld and bool(budget.below_floor[i]):
        # the U the results state there: the laboratory's CMC (ILAC-P14 5.4), with the same
        # k, so that U/k is the CMC's standard uncertainty, not the u_c above
        q = etree.SubElement(lst, D + "quantity", refType=b.ref(
            "anglebench_statedExpandedUncertainty", "the expanded uncertainty U the results "
            "state at the budget's point: the laboratory's CMC, the budget's U being below it"))
        b.text(q, "name", QT_TR_NOOP("U stated: raised to the laboratory's CMC"))
        b.real(q, float(budget.expanded[i]), unit)


#: what a standard's stated figure is the uncertainty of (metadata.APPLIES_TO), in the words
#: of the certificate's budget (models.certificate.document.reference_standard_components)
_PER = {"reading": QT_TR_NOOP("reading"), "angle": QT_TR_NOOP("angle between two readings"),
        "from face 1": QT_TR_NOOP("face, stated from face 1")}


def _standard_uncertainty(b: _Builder, parent, std) -> None:
    """A reference standard's stated uncertainty in D-SI form: the standard's error as the
    budget takes it, 0, with that uncertainty as its certificate states it — U95 as
    si:expandedMU (U, k = 2, p of k = 2 for a normal distribution), u as si:standardMU, a
    maximum permissible error ±a as si:coverageIntervalMU (−a … +a with p = 1, rectangular,
    u = a/√3). Named in each language as the budget names it ("expanded uncertainty U
    (k = 2) per reading")."""
    q = etree.SubElement(parent, D + "measuringEquipmentQuantity", refType=b.ref(
        v.REFTYPE_STANDARD_U, "a reference standard's error as the budget takes it, 0, with the "
        "uncertainty its certificate states (si:expandedMU for U with k and p, si:standardMU for "
        "u, si:coverageIntervalMU for a maximum permissible error ±a)"))
    b.text(q, "name", message(QT_TR_NOOP("{basis} per {per}"),
                              basis=message(BASIS_DIVISORS[std.basis][0]),
                              per=message(_PER.get(std.applies_to, std.applies_to))))
    unit = _SYMBOLS.get({"arcsec": '"', "urad": "µrad", "nm": "nm", "um": "µm", "mdeg": "mdeg",
                         "deg": "°"}.get(std.uncertainty_unit, ""), r"\one")
    figure = float(std.uncertainty)
    r = etree.SubElement(q, S + "real")
    b.leaf(r, "value", _figure(0.0), S)
    b.leaf(r, "unit", unit, S)
    mu = etree.SubElement(r, S + "measurementUncertaintyUnivariate")
    divisor, distribution = divisor_for_basis(std.basis)
    if std.basis == "U95":
        e = etree.SubElement(mu, S + "expandedMU")
        b.leaf(e, "valueExpandedMU", _figure(figure), S)
        b.leaf(e, "coverageFactor", _figure(divisor), S)
        b.leaf(e, "coverageProbability", _figure(DEFAULT_COVERAGE_PROBABILITY), S)
        b.leaf(e, "distribution", distribution, S)
    elif std.basis == "MPE":
        e = etree.SubElement(mu, S + "coverageIntervalMU")
        b.leaf(e, "valueStandardMU", _figure(figure / divisor), S)
        b.leaf(e, "intervalMin", _figure(-figure), S)
        b.leaf(e, "intervalMax", _figure(figure), S)
        b.leaf(e, "coverageProbability", "1", S)
        b.leaf(e, "distribution", distribution, S)
    else:  # "u": a standard uncertainty
        e = etree.SubElement(mu, S + "standardMU")
        b.leaf(e, "valueStandardMU", _figure(figure / divisor), S)
        b.leaf(e, "distribution", distribution, S)


def _measurement_results(b: _Builder, root, budgets, software, pairs: Mapping[str, str],
                         face_column: str, reference_faces,
                         notes: Mapping[str, Any] | None = None) -> None:
    doc, meta = b.document, b.document.metadata
    p = float(meta.coverage_probability)
    mrs = etree.SubElement(root, D + "measurementResults")
    mr = etree.SubElement(mrs, D + "measurementResult")
    b.text(mr, "name", doc.kind_title)
    methods = etree.SubElement(mr, D + "usedMethods")
    m = etree.SubElement(methods, D + "usedMethod", refType=b.ref(
        "anglebench_method", "the method of evaluation"))
    b.text(m, "name", doc.method)
    if doc.settings:  # each setting's name and value in each language (English only up to
        # 0.8.10: "faces n: from the readings; …" in a bilingual document)
        b.rich(m, "description", _Cells([_Cells([k, val], ": ") for k, val in doc.settings],
                                        "; "))
    if doc.standard:
        b.leaf(m, "norm", _say(doc.standard, "en"))
    if doc.method_reference:
        b.leaf(m, "reference", _say(doc.method_reference, "en"))
    used = etree.SubElement(etree.SubElement(mr, D + "usedSoftware"), D + "software")
    b.text(used, "name", "AngleBench", translated=False)
    b.leaf(used, "release", software.printed)
    b.leaf(used, "type", "application")
    if meta.standards:
        eqs = etree.SubElement(mr, D + "measuringEquipments")
        for std in meta.standards:
            eq = etree.SubElement(eqs, D + "measuringEquipment", refType=b.ref(
                "anglebench_referenceStandard", "a reference standard"))
            b.text(eq, "name", std.description or "reference standard", translated=False)
            if std.certificate_no:
                cert = etree.SubElement(eq, D + "certificate")
                b.text(cert, "referral", QT_TR_NOOP("Calibration certificate"))
                b.leaf(cert, "referralID", std.certificate_no)
                b.leaf(cert, "procedure", "certificate number (no hash stated)")
                b.leaf(cert, "value", std.certificate_no)
                if std.due_date:  # its due date, and whether it was valid on the calibration's
                    b.rich(cert, "description", message(QT_TR_NOOP(
                        "calibration due on {due}"), due=std.due_date))
                    b.leaf(cert, "inValidityRange",
                           "false" if meta.calibration_date and std.due_date < meta.calibration_date
                           else "true")
            if std.serial:
                ids = etree.SubElement(eq, D + "identifications")
                ident = etree.SubElement(ids, D + "identification")
                b.leaf(ident, "issuer", "manufacturer")
                b.leaf(ident, "value", std.serial)
            qs = None
            if std.due_date:
                qs = etree.SubElement(eq, D + "measuringEquipmentQuantities")
                q = etree.SubElement(qs, D + "measuringEquipmentQuantity",
                                     refType=b.ref(v.REFTYPE_STANDARD_DUE,
                                                   "the date the standard's calibration is due "
                                                   "(YYYY-MM-DD)"))
                b.text(q, "name", QT_TR_NOOP("Calibration due date"))
                b.leaf(q, "charsXMLList", std.due_date)
            if std.uncertainty is not None:
                if qs is None:
                    qs = etree.SubElement(eq, D + "measuringEquipmentQuantities")
                _standard_uncertainty(b, qs, std)
    conditions = [(QT_TR_NOOP("Temperature"), meta.temperature_c, r"\degreecelsius",
                   v.REFTYPE_TEMPERATURE),
                  (QT_TR_NOOP("Relative humidity"), meta.humidity_pct, r"\percent",
                   "anglebench_relativeHumidity")]
    if any(value is not None for _, value, _, _ in conditions):
        ics = etree.SubElement(mr, D + "influenceConditions")
        for name, value, unit, ref in conditions:
            if value is None:
                continue
            ic = etree.SubElement(ics, D + "influenceCondition", refType=b.ref(ref, "ambient"))
            b.text(ic, "name", name)
            q = etree.SubElement(etree.SubElement(ic, D + "data"), D + "quantity")
            b.real(q, value, unit)
    results = etree.SubElement(mr, D + "results")
    _curves(b, results, pairs, budgets, p, notes or {})
    if face_column:
        _face_deviations(b, results, face_column, pairs, budgets, p)
    if reference_faces is not None:
        dev, u, k = reference_faces
        # its own refType: the polygon reader must never take it as the polygon calibrated
        # (up to 0.8.11 it was anglebench_polygonFaceDeviations: an encoder's DCC read as the
        # polygon's certificate gave the reference's deviations under the encoder's number)
        _face_form(b, results, QT_TR_NOOP("Reference polygon face deviations (from face 1, as "
                                          "its certificate states them)"), dev, u, k,
                   DEFAULT_COVERAGE_PROBABILITY, v.REFTYPE_REFERENCE_POLYGON_FACE_DEVIATIONS)
    _table_result(b, results, doc.parameters, v.REFTYPE_SETUP_PARAMETERS,
                  "the certificate's parameters table: the identified set-up parameters with U",
                  "anglebench_setupParameter", "one row of the parameters table", p)
    _table_result(b, results, doc.statistics, v.REFTYPE_SUMMARY,
                  "the certificate's statistics table: the summary figures",
                  "anglebench_summaryFigure", "one row of the statistics table", p)
    _decided(b, results, p)
    unit = _SYMBOLS.get(doc.unit.strip(), r"\arcsecond")
    _budget(b, results, unit)


def build_dcc(document: CertificateDocument, pdf_bytes: bytes, pdf_name: str,
              budgets: Mapping[str, Any] | None = None, *,
              uncertainty_columns: Mapping[str, str] | None = None,
              face_deviations_column: str = "",
              reference_face_deviations: Any = None,
              column_notes: Mapping[str, Any] | None = None,
              software: SoftwareIdentity | None = None) -> bytes:
    """The DCC 3.3.0 of ``document`` (the certificate as printed into ``pdf_bytes``), with
    the PDF embedded byte for byte. ``budgets``: the workbench's
    ``uncertainty_budgets(result, metadata)`` (U and k per point of each curve);
    ``uncertainty_columns``: the workbench's ``dcc_uncertainty_columns`` (which column's U
    the certificate prints beside it); ``face_deviations_column``: its
    ``dcc_face_deviations_column``; ``reference_face_deviations``: its
    ``dcc_reference_face_deviations`` (a reference polygon's (deviations, U, k)). DccError
    naming a field the schema requires and the certificate lacks."""
    software = software or software_identity()
    meta = document.metadata
    if document.is_draft:  # a DRAFT is no certificate: its DCC would read as one
        # said of the document it is (a test report's "report number"; a specimen is no
        # draft: its details are incomplete) (assessment 73 L2: "the certificate is a DRAFT"
        # of a specimen test report)
        report = document.is_test_report
        missing = ", ".join(_say(m, "en") for m in meta.missing_fields(report))
        raise DccError(message(
            (QT_TR_NOOP("no DCC written: the specimen test report's details are incomplete "
                        "({missing} missing); a digital document is made only of complete "
                        "details") if report else
             QT_TR_NOOP("no DCC written: the specimen certificate's details are incomplete "
                        "({missing} missing); a digital certificate is made only of complete "
                        "details")) if document.specimen else
            QT_TR_NOOP("no DCC written: the test report is a DRAFT ({missing} missing); a "
                       "digital document is made only of a complete one") if report else
            QT_TR_NOOP("no DCC written: the certificate is a DRAFT ({missing} missing); a "
                       "digital certificate is made only of a complete one"),
            missing=missing))
    b = _Builder(document, bilingual=True)
    root = etree.Element(D + "digitalCalibrationCertificate", nsmap=v.NSMAP,
                         schemaVersion=v.SCHEMA_VERSION)
    refdefs = _administrative(b, root, software)
    _measurement_results(b, root, budgets or {}, software, uncertainty_columns or {},
                         face_deviations_column, reference_face_deviations, column_notes or {})
    pdf = etree.SubElement(root, D + "document", refType=b.ref(
        v.REFTYPE_ISSUED_PDF, "the issued PDF certificate, byte for byte"))
    b.text(pdf, "name", message(QT_TR_NOOP("Test report {number} (PDF)")
                                if document.is_test_report else
                                QT_TR_NOOP("Certificate {number} (PDF)"),
                                number=meta.certificate_number))
    b.leaf(pdf, "fileName", pdf_name)
    b.leaf(pdf, "mimeType", "application/pdf")
    b.leaf(pdf, "dataBase64", base64.b64encode(pdf_bytes).decode("ascii"))
    for name, description in sorted(b.own_reftypes.items()):
        d = etree.SubElement(refdefs, D + "refTypeDefinition")
        b.text(d, "name", name, translated=False)
        if description:
            b.rich(d, "description", description, translated=False)
        b.leaf(d, "namespace", v.ANGLEBENCH_REFTYPE_NAMESPACE)
        b.leaf(d, "link", v.ANGLEBENCH_REFTYPE_NAMESPACE)
        b.leaf(d, "release", v.ANGLEBENCH_REFTYPE_RELEASE)
        b.leaf(d, "value", name)
    return etree.tostring(root, xml_declaration=True, encoding="UTF-8", pretty_print=True)
