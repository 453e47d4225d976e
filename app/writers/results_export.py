"""The certificate's results as CSV or XLSX, safe to open in a spreadsheet.

CSV: every point's figures (UTF-8 with BOM so spreadsheets read Chinese text,
one header row with units in the names). XLSX: the same on a *Results* sheet,
plus *Parameters*, *Uncertainty budget* and *Certificate* sheets. Angles are
written in the unit the user chose to read them in (arcseconds unless told),
each header naming it.

Numbers are written as numbers; in the CSV and on the *Results* sheet each point's figures
three decimals finer than the certificate prints them, the same figures in both
(models/certificate/export_resolution.py). The
*Parameters*, *Statistics* and *Uncertainty budget* tables are printed text on the
certificate ("+3.77627 V", "-0.12\" … +0.34\""); on the sheets each figure becomes a
number cell, its unit goes to the column's header (or, where the rows' units differ, to a
unit column next to it), and a range, a pair or a value ± U is split into columns (see
:func:`split_figures`). Any text cell that starts with ``=``, ``+``, ``-``, ``@``, a tab
or a carriage return is prefixed with an apostrophe so a spreadsheet shows it as text
instead of running it as a formula (CSV/formula injection, OWASP). Files are written atomically.
"""

from __future__ import annotations

import csv
import io
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

import numpy as np

from models.certificate.document import (
    CertificateDocument,
    Table,
    budget_table,
    printed_decided_figures,
)
from models.certificate.export_resolution import rounded_point_columns
from models.certificate.interval_note import interval_cells
from models.display_units import ANGLE_UNITS, AngleUnit, header_in_unit, table_in_unit, text_in_unit
from models.messages import QT_TR_NOOP, Message, joined, listed, message, separated
from models.project.atomic_write import write_bytes_atomic
from models.quantity import UNITS
from models.register.wording import revision_words
from models.uncertainty.conformity import RISK_BOUND_NOTE
from models.uncertainty.printed_figure import PrintedFigure, printed
from models.uncertainty.probability_text import percent_text
from models.uncertainty.rounding import written_places

if TYPE_CHECKING:
    from models.register.store import CertificateRecord

__all__ = ["NOT_ISSUED", "XLSX_MAX_ROWS", "PrintedNumber", "issued_status", "neutralise",
           "not_issued", "number_format", "probability_cell", "results_bytes",
           "split_figures", "write_results_csv", "write_results_xlsx"]

XLSX_MAX_ROWS = 1_048_576
_FORMULA_STARTS = ("=", "+", "-", "@", "\t", "\r")


_XML_ILLEGAL = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f]")


def neutralise(text: object) -> str:
    """Text a spreadsheet will show, never evaluate; control characters (which no XLSX
    cell may hold, as in a file name typed with one) become U+FFFD."""
    s = _XML_ILLEGAL.sub("\ufffd", "" if text is None else str(text))
    return "'" + s if s.startswith(_FORMULA_STARTS) else s


ARCSEC = ANGLE_UNITS["arcsec"]

# a figure as the certificate prints it: a number, perhaps signed, perhaps with its unit
_UNIT = r"(?:\"|″|°|%|µrad|μrad|urad|mdeg|arcsec|deg|rad|mV|V|nm|µm|μm|um|mm)"
_FIGURE = re.compile(r"\s*([+\-−]?(?:\d+\.?\d*|\.\d+)(?:[eE][+\-−]?\d+)?)\s?(" + _UNIT + r")?\s*")
# what joins two figures in one cell, and what the two columns it becomes are called
_JOINS = {" … ": ("from", "to"), " ± ": ("", "U"), " / ": ("first", "second"),
          ", U = ": ("", "U"), "U−/U+": ("", "U−", "U+")}
_NUMBER = r"[+\-−]?(?:\d+\.?\d*|\.\d+)(?:[eE][+\-−]?\d+)?"
# a figure with its U as the certificate prints it: "12.34\", U = 0.81\"", or an asymmetric
# interval "12.34\", U = −0.62\"/+0.81\"" (also on a line of its own under the figure); a
# unit after a space, "4.9 µm\n−1.8 µm/+1.5 µm" (a linear axis: audit 69 finding 4, the
# figure was left a text cell)
_WITH_U = re.compile(r"\s*(?P<value>.+?)(?:, U = |\s*\n\s*)(?P<lower>−[^/\n]+?)/"
                     r"(?P<upper>\+[^/\n]+?)\s*")
# the same with a symmetric interval: "25.01\", U = ±1.35\"", or "0.407\"\n±0.094\"" (its U
# both below and above the value: the same columns as an asymmetric one)
_WITH_SYMMETRIC_U = re.compile(r"\s*(?P<value>.+?)(?:, U = |\s*\n\s*)±(?P<u>[^\n]+?)\s*")


def split_figures(text: str) -> tuple[tuple[float, ...], str, str] | None:
    """The figures a certificate's cell states, as (numbers, their unit, how they are
    joined): ``"+3.77627 V"`` → ((3.77627,), "V", ""); ``"-0.12\" … +0.34\""`` →
    ((-0.12, 0.34), "\"", " … "); ``None`` for a cell that is not figures alone (a word,
    a sentence, a checksum), which then stays text."""
    asymmetric = _WITH_U.fullmatch(text)
    symmetric = _WITH_SYMMETRIC_U.fullmatch(text)
    if asymmetric:  # value, U below it, U above it (both as positive half-widths)
        join = "U−/U+"
        parts = [asymmetric["value"], asymmetric["lower"].lstrip("−"), asymmetric["upper"]]
    elif symmetric:
        join = "U−/U+"
        parts = [symmetric["value"], symmetric["u"], symmetric["u"]]
    else:
        join = next((j for j in _JOINS if j in text), "")
        parts = text.split(join) if join else [text]
    values, units = [], set()
    for part in parts:
        found = _FIGURE.fullmatch(part)
        if found is None:
            return None
        values.append(PrintedNumber(found.group(1)))
        if found.group(2):
            units.add(found.group(2))
    if len(units) > 1 or not all(math.isfinite(v) for v in values):
        return None
    return tuple(values), units.pop() if units else "", join


class PrintedNumber(float):
    """A figure of a printed table as the number it is, with the ``decimals`` it was printed
    to (None: in exponent notation), so that its cell shows them: a U of "7.0 µrad" is the
    number 7.0 shown 7.0, not 7 (assessment 72 L6)."""

    decimals: int | None

    def __new__(cls, text: str) -> PrintedNumber:
        made = super().__new__(cls, float(text.replace("−", "-")))
        digits = text.lstrip("+-−")
        made.decimals = (None if "e" in digits.lower() else
                         len(digits.split(".")[1]) if "." in digits else 0)
        return made


def number_format(decimals: int | None) -> str:
    """The spreadsheet's number format that shows ``decimals`` decimals ("0.0"), "General"
    where they are not known."""
    return "General" if decimals is None else "0" if decimals == 0 else "0." + "0" * decimals


class _Column(NamedTuple):
    """A column's header on a sheet, to be said in the certificate's language
    (:meth:`_Words.column`): its name, what it holds of a cell's figures ("to" of a range,
    "U" of a value ± U), its figures' unit, or its being their unit column."""

    name: str
    held: tuple[str, ...] = ()
    unit: str | None = None
    unit_column: bool = False

    def said(self, say: Callable[[str], str] = str) -> str:
        """The heading with its words said by ``say`` (the unit as it is): "Deviation (to)
        (\")", "Value: unit"."""
        name = say(self.name)
        if self.unit_column:
            return say(message("{column}: unit", column=name))
        # a column that holds one figure of several kinds of cell says each, as a header
        # reads: "Value (to, second or U−)" (assessment 72 L6: "Value (to | second | U−)")
        words = [say(word) for word in self.held]
        held = say(message(QT_TR_NOOP("{items} or {item}"), items=listed(words[:-1]),
                           item=words[-1])) if len(words) > 1 else "".join(words)
        title = f"{name} ({held})" if held else name
        return f"{title} ({self.unit})" if self.unit else title


def _figure_columns(header: tuple[str, ...], rows: list[tuple[object, ...]],
                    heading: Callable[[_Column], str] = _Column.said,
                    ) -> tuple[list[str], list[list[object]]]:
    """A printed table made calculable: each column whose cells are figures becomes number
    columns (one per figure of a range or a pair) with the unit in its header, or in a unit
    column of its own where the rows' units differ; other cells stay as they are. The
    headers are said by ``heading`` (in English unless told)."""
    width = max([len(header), *map(len, rows)])
    out_header: list[str] = []
    out_rows: list[list[object]] = [[] for _ in rows]
    for j in range(width):
        name = header[j] if j < len(header) else ""
        cells = [row[j] if j < len(row) else None for row in rows]
        figures = [split_figures(c) if isinstance(c, str) else None for c in cells]
        found = [f for f in figures if f is not None]
        if not found:
            out_header.append(heading(_Column(name)))
            for out, cell in zip(out_rows, cells, strict=True):
                out.append(cell)
            continue
        count = max(len(f[0]) for f in found)
        joins = {f[2] for f in found if f[2]}
        units = {f[1] for f in found}
        # one kind of join: its two names; several (ranges and value ± U in one column):
        # the first column is the value or the range's start, the second says what it holds
        if len(joins) == 1:
            labels = tuple((held,) if held else () for held in _JOINS[joins.pop()])
        else:  # each column after the first says what it holds for each kind of cell
            labels = ((), *(tuple(dict.fromkeys(
                _JOINS[j][i] for j in _JOINS if j in joins and len(_JOINS[j]) > i))
                for i in range(1, count)))
        unit = units.pop() if len(units) == 1 else None
        base = name or "Value"
        for i in range(count):
            out_header.append(heading(_Column(base, () if count == 1 else labels[i],
                                              unit or None)))
        if unit is None:
            out_header.append(heading(_Column(base, unit_column=True)))
        for out, cell, figure in zip(out_rows, cells, figures, strict=True):
            if figure is None:
                out += [None if cell == "" else cell] + [None] * (count - 1)
            else:
                out += list(figure[0]) + [None] * (count - len(figure[0]))
            if unit is None:
                out.append(figure[1] if figure is not None else None)
    return out_header, out_rows


def _with_interval_columns(table: Table) -> Table:
    """A table whose figures state their coverage interval in a note beside them (the
    theodolite's ISO 230-2 figures: models/certificate/interval_note.py) with the columns
    "Coverage interval" and "Probability" before the notes' column, as positioning's table
    has them, so that the sheet holds each interval as numbers (from, to, probability) as it
    holds positioning's (audit 69 finding 5: they were in the note's text only); the notes
    stay. Any other table as it is."""
    found = {j for row in table.rows for j, cell in enumerate(row) if interval_cells(cell)}
    if not found:
        return table
    at = min(found)
    header = (*table.header[:at], QT_TR_NOOP("Coverage interval"), QT_TR_NOOP("Probability"),
              *table.header[at:])
    rows: list[tuple[str, ...]] = []
    for row in table.rows:
        cells = next(filter(None, map(interval_cells, row)), ("", ""))
        rows.append((*row[:at], *cells, *row[at:]))
    return Table(table.title, header, rows, table.note)


def _point_columns(document: CertificateDocument,
                   unit: AngleUnit) -> list[tuple[str, np.ndarray]]:
    out = []
    for name, values in document.point_columns:
        header, factor = header_in_unit(name, unit)
        out.append((header, np.asarray(values, dtype=float) * factor))
    return out


def _figure_text(value: float) -> str:
    """A figure rounded to the results' resolution as the CSV writes it: its shortest
    digits (the number the XLSX cell holds), in positional notation ("0.00003", not
    "3e-05"; "12", not "12.0"); "" when it is not finite."""
    if not math.isfinite(value):
        return ""
    text = repr(value)  # the shortest digits; positional unless very small or large
    if "e" in text:
        return np.format_float_positional(value, unique=True, trim="-")
    return text[:-2] if text.endswith(".0") else text


def results_csv_bytes(document: CertificateDocument, unit: AngleUnit = ARCSEC) -> bytes:
    """The point columns as the XLSX *Results* sheet holds them (day review 65: the CSV
    wrote every figure to ten significant digits, ``%.10g``, so a correction of
    −3.456836534665442e-05″ where +0.00″ is printed was −3.456836535e-05, while the sheet
    wrote −0.00003): the errors' columns three decimals beyond those the certificate
    prints them to, the others (a face's number, a nominal angle, a reading) to ten
    significant digits (models/certificate/export_resolution.py)."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\r\n")
    point_columns = rounded_point_columns(_point_columns(document, unit))
    writer.writerow([neutralise(h) for h, _ in point_columns])
    columns = [[_figure_text(v) for v in values.tolist()] for _, values in point_columns]
    if columns:
        writer.writerows(zip(*columns, strict=True))
    return ("\ufeff" + out.getvalue()).encode("utf-8")


def write_results_csv(path: str | Path, document: CertificateDocument,
                      unit: AngleUnit = ARCSEC) -> None:
    write_bytes_atomic(path, results_csv_bytes(document, unit))


#: the *Certificate* sheet's row naming the workbench's test: "Test" in English, its Chinese
#: its own (app/writers/certificate_pdf/wording.py SHEET_CHINESE: not the PDF's table title)
SHEET_TEST = "Test (the test performed)"

#: what the *Certificate* sheet says of results written with no certificate issued (a test
#: report's: :func:`not_issued`)
NOT_ISSUED = ("not issued: these results were written apart from any certificate's issue, "
              "so they are no certificate's record; a certificate number or date of issue "
              "typed in the details is not shown")
_NOT_ISSUED_REPORT = ("not issued: these results were written apart from any report's issue, "
                      "so they are no report's record; a report number or date of issue typed "
                      "in the details is not shown")


def not_issued(report: bool = False) -> Message:
    """What the *Certificate* sheet says of results written with no certificate (``report``:
    no test report) issued; in Chinese from the certificate's words (wording.CHINESE)."""
    return message(_NOT_ISSUED_REPORT if report else NOT_ISSUED)


def issued_status(number: str, report: bool = False) -> Message:
    """What the *Certificate* sheet says of results written with certificate (``report``:
    test report) ``number``."""
    return message(("issued: the results of test report {number}, written when the register "
                    "issued it; the register holds this file's SHA-256 ('anglebench register "
                    "verify FILE' checks it)") if report else
                   ("issued: the results of certificate {number}, written when the register "
                    "issued it; the register holds this file's SHA-256 ('anglebench register "
                    "verify FILE' checks it)"), number=number)


def _revision(issued: CertificateRecord) -> Message:
    """"amendment 1 of AB-2026-0001", "original": the register's words, as its window and
    command line say them (models/register/wording.py)."""
    revision = revision_words(issued.revision)
    if issued.supersedes:
        return message("{revision} of {certificate}", revision=revision,
                       certificate=issued.supersedes)
    return revision


def percent_cell(probability: float) -> float:
    """A coverage probability (0…1) as the sheet gives it, in percent: the number the
    certificate prints (:func:`models.uncertainty.probability_text.percent_text`: 95.45, 92.5),
    not the computed one's every digit (0.8.25: 95.44997361036415 beside the PDF's
    "95.45 %"); not a number: as it is."""
    if probability is None or not math.isfinite(probability):
        return probability
    return float(percent_text(probability))


def probability_cell(probability: float, bound: str = "") -> float | str | None:
    """A probability of conformity or of a wrong decision as the sheet gives it, in percent,
    by the certificate's rule (assessment 70 L1: "100" and "0" beside the PDF's "< 0.01 %"):
    to two decimals, a number; within 0.01 % of 0 or of 100 the bound as text, "< 0.01" or
    "> 99.99", as no such probability is certain (the JSON keeps it unrounded). ``bound``:
    the figure is a bound, not the probability ("≤" at most, "≥" at least: every point
    deciding, Boole's inequality), given as text with its sign, "≤ 79.91", "≥ 0.00"
    (assessment 73 M6: "< 0.01" of a lower bound of 0 read as a certain non-conformity)."""
    if probability is None or not math.isfinite(probability):
        return None
    if bound:
        figure = 100.0 * probability
        # the bound as printed never claims more than it bounds: at most rounded up, at
        # least rounded down
        shown = (math.ceil(figure * 100.0 - 1e-9) if bound == "≤"
                 else math.floor(figure * 100.0 + 1e-9)) / 100.0
        return f"{bound} {min(max(shown, 0.0), 100.0):.2f}"
    if probability < 1e-4:
        return "< 0.01"
    if probability > 1.0 - 1e-4:
        return "> 99.99"
    return round(100.0 * probability, 2)


def _conforming_bound(conformity) -> str:
    """How the probability of conformity bounds it where it is a bound: at least it after a
    pass (1 − the sum over the points), at most it after a fail (the deciding point's)."""
    if not conformity.risk_is_bound:
        return ""
    return "≥" if conformity.verdict in ("pass", "conditional pass") else "≤"


def _metadata_rows(document: CertificateDocument,
                   issued: CertificateRecord | None = None) -> list[tuple[str, object]]:
    """The *Certificate* sheet, its labels in English (a test report's own words and the
    certificate's language are given by :class:`_Words`): ``issued`` is the register's
    record of the certificate issued with these results (its number, date of issue and
    files' SHA-256); without it the results are said not to be issued, and no number or date
    of issue is given (one typed in the details is not the register's: review 61 F1)."""
    meta = document.metadata
    report = document.is_test_report
    q = document.budget.unit.symbol  # the unit of the errors, the budget and the tolerance
    # the decided figures as printed (none printed so: the computed ones, as before)
    decided: dict[str, object] = dict(printed_decided_figures(
        document.conformity, "", document.budget.unit.key) or {})
    rows: list[tuple[str, object]] = [
        ("Certificate number", issued.number if issued else None),
        ("Status", issued_status(issued.number, report) if issued else not_issued(report)),
        ("Revision", _revision(issued) if issued else None),
        # an original issued as a calibration of its own beside current certificates of the
        # same item and date of calibration (--separate-calibration): which, and why, as
        # the PDF and the DCC state it (ISO/IEC 17025 7.8.8)
        ("Separate calibration from certificate(s), which stay valid",
         meta.separate_from or None if issued else None),
        ("Why it is a calibration of its own",
         meta.change_note or None if issued and meta.separate_from else None),
        ("Certificate PDF SHA-256", issued.pdf_sha256 if issued else None),
        ("DCC SHA-256", issued.dcc_sha256 if issued else None),
        (SHEET_TEST, document.kind_title),  # "Test": 校准项目 or 检测项目 (not the PDF's 检测)
        ("Readings", document.source_name),
        # the instrument's raw output behind the captured rows, as the PDF gives it (day
        # review 64 P8: the sheet said nothing of it)
        ("Instrument output SHA-256", document.raw_data_sha256 or None),
        ("Laboratory", meta.lab_name),
        ("Customer", meta.customer_name), ("Item calibrated", meta.item_description),
        ("Serial number", meta.item_serial), ("Grade", meta.item_grade),
        ("Date of calibration", meta.calibration_date),
        ("Date of issue", issued.issue_date if issued else None),
        ("Operator", meta.operator), ("Approver", meta.approver),
        ("Temperature (°C)", meta.temperature_c), ("Relative humidity (%)", meta.humidity_pct),
        ("Sign convention", document.sign_convention),
        # U and the decided value's figures as the certificate prints them (GUM 7.2.6: U
        # rounded up to two significant digits, the value to its decimal), the figures this
        # sheet's certificate number and PDF SHA-256 certify (assessment 76 M4: U 1.4365″
        # unrounded here beside 1.5″ certified); the JSON and the DCC state them unrounded
        (f"Expanded uncertainty U, largest ({q})", _printed_u(document)),
        ("No U stated because", document.uncertainty_withheld),
        ("Coverage factor k there",
         math.nan if document.uncertainty_withheld else document.budget.coverage_factor),
        ("Coverage probability (%)", percent_cell(document.budget.probability)),
        (f"Tolerance ± ({q})", document.tolerance),
        ("Decided quantity", document.conformity.quantity),
        (f"Decided value ({q})", decided.get("value", document.conformity.value)),
        # both half-widths, as the certificate prints an asymmetric interval (−U₋/+U₊); one
        # "U" gave the upper only (review 61 F5)
        (f"U of the decided value, below it (U−) ({q})",
         decided.get("lower", document.conformity.lower_half_width)),
        (f"U of the decided value, above it (U+) ({q})",
         decided.get("upper", document.conformity.expanded)),
        (f"Decided value: interval low ({q})",
         decided.get("low", document.conformity.interval_low)),
        (f"Decided value: interval high ({q})",
         decided.get("high", document.conformity.interval_high)),
        ("Decided value: coverage probability (%)", percent_cell(document.conformity.probability)),
        # only with a statement of conformity, as the JSON (null) and the PDF: where none is
        # made (the error not traceable, U incomplete, U ≥ T) a probability would rest on
        # that U (audit 69 finding 3: "100" beside "not assessed")
        ("Probability of conformity (%)",
         probability_cell(document.conformity.conforming_probability,
                          _conforming_bound(document.conformity))
         if document.conformity.stated else None),
        ("Probability of a wrong decision (%)",
         probability_cell(document.conformity.decision_risk,
                          "≤" if document.conformity.risk_is_bound else "")
         if document.conformity.stated else None),
        # where the two are bounds, said so beside them (assessment 73 M6)
        ("Probabilities stated as",
         message(RISK_BOUND_NOTE) if document.conformity.stated
         and document.conformity.risk_is_bound else None),
        ("Verdict", document.conformity.verdict),
        ("No statement of conformity because", document.conformity.reason),
        ("Conformity", document.conformity.statement),
        ("Decision rule", document.conformity.rule), ("Zones", document.conformity.zones),
        ("Inputs not stated, so not in U", document.not_in_u_statement),
        *((message("Statement {i}", i=i), text) for i, text in enumerate(document.statements, 1)),
        *((message("Setting: {label}", label=message(label)), value)
          for label, value in document.settings),
        ("Notes", meta.notes),
    ]
    for i, s in enumerate(meta.standards, 1):
        # a part left empty (no serial, no certificate number) is left out, not printed as
        # "serial ;" (出厂编号 ；); typed text never looked up (joined: a text of its own)
        rows.append((message("Standard {i}", i=i), joined([separated((
            s.description, s.serial and message("serial {serial}", serial=s.serial),
            s.certificate_no and message("certificate {certificate}",
                                         certificate=s.certificate_no)), "; ")])))
        rows.append((joined([message("Standard {i} uncertainty", i=i),
                             f" ({UNITS[s.uncertainty_unit].symbol})"]), s.uncertainty))
    return rows


class _Words:
    """The sheets' words in the certificate's language, as its PDF says them (the same
    words, from app/writers/certificate_pdf/wording.py): English; Chinese throughout (the
    certificate's fixed words, else the window's catalogue; typed text, figures, units and
    symbols as they are); or, on a bilingual certificate, every label and column heading
    in Chinese beside the English and every text of ours on the *Certificate* sheet in
    Chinese above the English, the tables' cells in English as on its pages. A test report
    speaks in its own words ("Report number", 报告编号) in every language."""

    def __init__(self, document: CertificateDocument) -> None:
        from app.writers.certificate_pdf import wording  # the PDF's: loaded with the XLSX

        self.document, self.language = document, document.metadata.language
        self._wording = wording

    def _chinese(self, text) -> str:
        return self._wording.in_chinese(self.document, text)

    def _heading(self, text) -> str:
        """A table's heading in Chinese as the PDF's table prints it (the catalogue's), the
        words the sheet adds to it ("to", ": unit") from the certificate's."""
        said = self._wording._say("zh", self.document.is_test_report)(text)
        return said if said != str(text) else self._chinese(text)

    def label(self, english, unit: AngleUnit) -> tuple[str, float]:
        """A label (a row's of the *Certificate* sheet, a column's heading) with its angle
        unit in ``unit``, and the factor of its figures."""
        wording = self._wording
        said, factor = header_in_unit(str(wording.own_words(
            self.document, wording.SHEET_WORDS.get(english, english))), unit)
        if self.language not in ("zh", "zh+en"):
            return said, factor
        # a row of the sheet's own (SHEET_TEST), else as the certificate says it
        own = (wording.REPORT_SHEET_CHINESE if self.document.is_test_report
               else wording.SHEET_CHINESE).get(english)
        chinese = header_in_unit(own or self._chinese(english), unit)[0]
        if self.language == "zh" or chinese == said:
            return chinese, factor
        return f"{chinese} {said}", factor

    def column(self, column: _Column) -> str:
        """A column's heading: its name, what it holds of the cells' figures and their unit
        ("Deviation (to) (\")", 偏差 (止) (\"))."""
        english = column.said()
        if self.language not in ("zh", "zh+en"):
            return english
        chinese = column.said(self._heading)
        if self.language == "zh" or chinese == english:
            return chinese
        return f"{chinese} {english}"

    def text(self, value):
        """A text of the *Certificate* sheet: in Chinese on a Chinese certificate, in both
        on a bilingual one (Chinese above; once when it has no Chinese: typed text)."""
        if not isinstance(value, str) or self.language not in ("zh", "zh+en"):
            return value
        chinese = self._chinese(value)
        if self.language == "zh" or chinese == str(value):
            return chinese
        return f"{chinese}\n{value}"

    def verdict(self, value):
        """The *Verdict* row's word: in Chinese as the certificate's statement says it
        (:data:`~app.writers.certificate_pdf.wording.VERDICT_CHINESE`), above the English on
        a bilingual one; any other (not assessed) as :meth:`text` says it."""
        chinese = self._wording.VERDICT_CHINESE.get(str(value))
        if chinese is None or self.language not in ("zh", "zh+en"):
            return self.text(value)
        return chinese if self.language == "zh" else f"{chinese}\n{value}"

    def cell(self, value):
        """A text cell of a table: in Chinese on a Chinese certificate, else as printed (a
        bilingual certificate's tables keep the English below their two-language headings)."""
        if isinstance(value, str) and self.language == "zh":
            return self._wording._say("zh", self.document.is_test_report)(value)
        return value


def _printed_u(document: CertificateDocument) -> object:
    """The certificate's largest U as it prints it, rounded up to two significant digits
    (GUM 7.2.6), in any unit the sheet is read in; nan where no U is stated."""
    big_u = document.expanded_uncertainty
    if not (math.isfinite(big_u) and big_u > 0):
        return big_u
    return printed(big_u, "", rounding="up", unit_key=document.budget.unit.key)


def _printed_cell(ws, figure: PrintedFigure):
    """A figure as the certificate prints it (:class:`PrintedFigure`) as a number cell
    that shows the decimals it is printed to: 1.5 shown "1.5", 170 (a U of 168 nm rounded
    up to two significant digits) "170"."""
    from openpyxl.cell import WriteOnlyCell

    value = _cell(figure.shown)
    if value is None:
        return None
    cell = WriteOnlyCell(ws, value)
    cell.number_format = number_format(written_places(figure.places))
    return cell


def _cell(value: object) -> object:
    if value is None:
        return None
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, int | float | np.floating | np.integer):
        v = float(value)
        return v if np.isfinite(v) else None
    return neutralise(value)


def _shown(ws, figure: PrintedNumber):
    """A printed table's figure as a number cell that shows the decimals it was printed to
    (a float, its format "0.0" for "7.0 µrad": the number 7 in a General cell showed 7)."""
    from openpyxl.cell import WriteOnlyCell

    value = _cell(float(figure))
    if value is None or not figure.decimals:
        return value
    cell = WriteOnlyCell(ws, value)
    cell.number_format = number_format(figure.decimals)
    return cell


#: the *Certificate* sheet's texts of the decision, kept in the unit it was made in (the
#: certificate's) whatever the sheet's unit: their value, U₋, U₊, T and zones are the figures
#: the verdict was decided on as printed, and re-rounded in another unit they could give
#: another verdict (assessment 72 H2: "4.6 µrad, U = −4.6/+2.4 µrad … conditional pass
#: within 7.01 µrad", which those figures pass; zones 4.58 µrad beside 7.01 − 2.4)
DECISION_TEXTS = frozenset({"Conformity", "Zones", "No statement of conformity because"})


def _metadata_in_unit(rows: list[tuple[str, object]], unit: AngleUnit,
                      words: _Words) -> list[tuple[str, object]]:
    """The *Certificate* sheet's rows with their angle figures in ``unit``, said in the
    certificate's language (after the conversion: a message's figures are converted from
    the numbers it keeps); the decision's texts (:data:`DECISION_TEXTS`) in the unit the
    decision was made in, so that the sheet states one verdict, the certificate's, on
    figures that give it."""
    out: list[tuple[str, object]] = []
    for key, value in rows:
        header, factor = words.label(key, unit)
        stated = getattr(value, "stated", None)  # a tolerance as the customer stated it
        if isinstance(value, PrintedFigure):  # rounded in the sheet's unit, from its value
            value = value.to(unit.key)
        elif stated is not None and factor != 1.0 and stated[1] == unit.key:
            value = float(stated[0])  # in its own unit: as stated, not its conversion back
        elif isinstance(value, int | float) and not isinstance(value, bool):
            # a converted figure without the binary noise of the multiplication (a tolerance
            # of 3″ is 14.5444104332861 µrad, not …08 or 14.50000000000001: assessment 70 M4)
            value = float(f"{value * factor:.15g}") if factor != 1.0 else value
        elif isinstance(value, str):
            value = (words.verdict(value) if key == "Verdict" else
                     words.text(value if key in DECISION_TEXTS else text_in_unit(value, unit)))
        out.append((header, value))
    return out


def results_xlsx_bytes(document: CertificateDocument, unit: AngleUnit = ARCSEC,
                       issued: CertificateRecord | None = None) -> bytes:
    """The workbook; ``issued``: the register's record of the certificate issued with these
    results (see :func:`_metadata_rows`)."""
    from openpyxl import Workbook  # imported here: only the export needs it
    from openpyxl.cell import WriteOnlyCell
    from openpyxl.styles import Alignment

    points = len(document.point_columns[0][1]) if document.point_columns else 0
    if points + 1 > XLSX_MAX_ROWS:
        raise ValueError(f"{points} points do not fit on a spreadsheet ({XLSX_MAX_ROWS - 1} rows "
                         "at most): export CSV instead")
    words = _Words(document)
    book = Workbook(write_only=True)
    # the sheets keep their documented names in every language (docs: certificates-and-
    # register.md), as the Results sheet its columns' names (those of the JSON)
    sheet = book.create_sheet("Results")
    # each figure three decimals beyond those the certificate prints it to, not the binary
    # noise of its computation (-3.456836534665442e-05 where +0.00" is printed)
    point_columns = rounded_point_columns(_point_columns(document, unit))
    sheet.append([neutralise(name) for name, _ in point_columns])
    columns = [values for _, values in point_columns]
    if columns:
        block = np.column_stack(columns)
        for row in block.tolist():
            sheet.append([v if np.isfinite(v) else None for v in row])
    for title, table in (("Parameters", document.parameters),
                         ("Statistics", _with_interval_columns(document.statistics)),
                         # in the errors' unit, as the PDF's (a linear axis's µm was
                         # headed ″, and converted as arcseconds: audit 69 finding 4)
                         ("Uncertainty budget", budget_table(
                             document.budget, document.budget_point, document.unit,
                             withheld=bool(document.uncertainty_withheld)))):
        ws = book.create_sheet(title)
        # the statistics are printed to their intervals' decimal (GUM 7.2.6): in another
        # unit each keeps that resolution, no digits added (R = 3" in 0" … 30" was
        # 0.833 mdeg beside 0.0 … 8.33 mdeg)
        header, rows = _figure_columns(*table_in_unit(table.header, table.rows, unit,
                                                      resolution_only=title == "Statistics"),
                                       heading=words.column)
        ws.append([neutralise(h) for h in header])
        for row in rows:
            ws.append([_shown(ws, v) if isinstance(v, PrintedNumber) else _cell(words.cell(v))
                       for v in row])
        if table.note:
            ws.append([neutralise(words.cell(text_in_unit(table.note, unit)))])
    ws = book.create_sheet(details_sheet_name(document))
    wrapped = Alignment(wrap_text=True, vertical="top")  # a bilingual text: Chinese above
    for key, value in _metadata_in_unit(_metadata_rows(document, issued), unit, words):
        value = _printed_cell(ws, value) if isinstance(value, PrintedFigure) else _cell(value)
        if isinstance(value, str) and "\n" in value:
            value = WriteOnlyCell(ws, value)
            value.alignment = wrapped
        ws.append([neutralise(key), value])
    out = io.BytesIO()
    book.save(out)
    return out.getvalue()


#: the sheet of the document's details and statements, by what the document is: a
#: calibration certificate's, a test report's (assessment 73 L4: a test report's was named
#: *Certificate*); the same name in every language, as the other sheets keep theirs
DETAILS_SHEETS = {False: "Certificate", True: "Report"}


def details_sheet_name(document: CertificateDocument) -> str:
    """The name of the sheet of ``document``'s details: *Certificate*, or *Report* for a
    test report."""
    return DETAILS_SHEETS[bool(document.is_test_report)]


def write_results_xlsx(path: str | Path, document: CertificateDocument,
                       unit: AngleUnit = ARCSEC) -> None:
    """Results written apart from any issue (said so on the *Certificate* sheet)."""
    write_bytes_atomic(path, results_xlsx_bytes(document, unit))


def results_bytes(path: str | Path, document: CertificateDocument, unit: AngleUnit = ARCSEC,
                  issued: CertificateRecord | None = None) -> bytes:
    """The results file ``path`` names (XLSX for ``.xlsx``, else CSV)."""
    if str(path).lower().endswith(".xlsx"):
        return results_xlsx_bytes(document, unit, issued)
    return results_csv_bytes(document, unit)


#: where the *Certificate* sheet holds the register's record of the issue (the rows of
#: :func:`_metadata_rows`, from the first): the number, the PDF's and the DCC's SHA-256
_ISSUE_ROWS = {"number": 0, "pdf_sha256": 5, "dcc_sha256": 6}


def issue_stated(data: bytes) -> dict[str, str] | None:
    """What an XLSX results file says of the certificate it was written with (its
    *Certificate* sheet): ``number``, ``pdf_sha256`` and ``dcc_sha256`` ("" for none); None
    when it is no results workbook of ours (a CSV says nothing of it). ``register verify``
    compares them with the record it is found under (rev62 F7)."""
    import zipfile

    from openpyxl import load_workbook

    try:
        book = load_workbook(io.BytesIO(data), read_only=True, data_only=True)
    except (zipfile.BadZipFile, OSError, ValueError, KeyError):
        return None
    try:
        sheet = next((name for name in DETAILS_SHEETS.values() if name in book.sheetnames),
                     None)
        if sheet is None:
            return None
        rows = [tuple(r) + (None, None) for r in book[sheet].iter_rows(
            max_row=max(_ISSUE_ROWS.values()) + 1, max_col=2, values_only=True)]
    finally:
        book.close()
    if len(rows) <= max(_ISSUE_ROWS.values()):
        return None
    return {key: "" if rows[at][1] is None else str(rows[at][1]).strip()
            for key, at in _ISSUE_ROWS.items()}
