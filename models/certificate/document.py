"""The content of a test certificate, independent of how it is printed.

Each workbench's report module fills one :class:`CertificateDocument` from its
analysis result and the certificate metadata; the PDF writer and the CSV/XLSX
export print it. Numbers are formatted here, once, so every output shows the
same figures.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.certificate.metadata import DOCUMENT_TYPES, CertificateMetadata
from models.messages import QT_TR_NOOP, joined, listed, message, separated
from models.plots import PlotFigure, PlotSeries
from models.quantity import Quantity, UnitError
from models.quantity import unit as unit_named
from models.sign_convention import SIGN_CONVENTION_TEXT
from models.uncertainty.budget import (
    BASIS_DIVISORS,
    BudgetComponent,
    UncertaintyBudget,
    divisor_for_basis,
)
from models.uncertainty.conformity import (
    REFERENCE_POINT_TEXT,
    Conformity,
    asymmetric_figures,
    held_at_zero_note,
    printed_half_widths,
    significant_decimals,
    uncertainty_decimals,
)
from models.uncertainty.printed_figure import (
    PrintedFigure,
    printed,
    printed_interval_figures,
    rounded_to,
)
from models.uncertainty.probability_text import percent_text
from models.uncertainty.rounding import fixed_places, printed_range, stated_pair

__all__ = ["CertificateDocument", "Exact", "decision_rows", "PlotFigure", "PlotSeries", "Table",
           "budget_table", "format_uncertain", "gum_pair", "printed_decided_figures",
           "range_cells", "rounded_cells", "rounded_figure", "table_decimals", "opinion",
           "reference_standard_components", "resolution_component"]


class Exact(str):
    """A cell as printed, rounded as GUM 7.2.6 asks ("22.4″", "16.2″ … 26.4″"), that keeps
    its figures at full precision (``exact``: a number, or an interval's two ends) for the
    machine-readable outputs: the DCC states these, not the digits printed."""

    exact: float | tuple[float, float]

    def __new__(cls, text: str, exact: float | tuple[float, float]) -> Exact:
        cell = super().__new__(cls, text)
        cell.exact = exact
        return cell

    def __getnewargs__(self) -> tuple[str, float | tuple[float, float]]:  # copied, pickled
        return str(self), self.exact


@dataclass(frozen=True)
class Table:
    title: str
    header: tuple[str, ...]
    rows: list[tuple[str, ...]]
    note: str = ""


@dataclass(frozen=True, kw_only=True)
class CertificateDocument:
    kind_key: str
    kind_title: str
    metadata: CertificateMetadata
    source_name: str
    method: str
    method_reference: str
    parameters: Table
    results: Table
    statistics: Table
    budget: UncertaintyBudget
    budget_point: str  # where the budget table is evaluated, e.g. "θ = 30°"
    conformity: Conformity
    tolerance: float | None  # the tolerance in the unit of the errors (`unit`)
    plots: tuple[PlotFigure, ...]
    warnings: tuple[str, ...] = ()
    # every point's figures, for the CSV/XLSX export: (column header, values)
    point_columns: tuple[tuple[str, np.ndarray], ...] = ()
    # the unit symbol of a point column whose key names none (positioning's "target": "mm"
    # on a linear axis, "°" on a rotary one), as (key, symbol): the DCC states it (it said
    # \one: audit 69 finding 4); a key ending in its unit ("theta_deg") needs none
    point_column_units: tuple[tuple[str, str], ...] = ()
    # statements of this workbench's own (why U is zero somewhere, a specification's
    # source, as found / as left …), printed with the shared ones
    statements: tuple[str, ...] = ()
    unit: str = "\""  # the errors' unit symbol: arcsec, or " nm" for an interferometer
    settings: tuple[tuple[str, str], ...] = ()  # (label, value) of the analysis' settings
    standard: str = ""  # the standard the evaluation follows (empty: a published method)
    sign_convention: str = SIGN_CONVENTION_TEXT  # how the certificate's deviations are signed
    # inputs of the result with no stated uncertainty: not traceable through them (said so)
    untraceable: tuple[str, ...] = ()
    # inputs of the budget stated in the analysis settings (a standard listed with its
    # certificate and no U in the table stands behind them: the ADC's figures, say)
    stated_inputs: tuple[str, ...] = ()
    # SHA-256 of the instrument's raw frames behind the readings (models/capture/raw_record)
    raw_data_sha256: str = ""
    # captured readings edited in the sheet since (models/capture/edits.py), one text each:
    # "reading of row 3 edited after capture: 21.56 → 26.56"
    edited_readings: tuple[str, ...] = ()
    # what the results are traceable through when no reference standard enters them
    # (IssuesCertificates.traceability_basis); "": through the standards listed
    traceability_basis: str = ""
    # why traceability is not established although standards are listed (a standard that
    # carries the measurand not listed with a certificate and a stated U, say): the document
    # is then a test report, not a calibration certificate (traceability_gaps)
    traceability_gaps: tuple[str, ...] = ()
    # the register's chain head before this certificate (the previous record's chain
    # value), printed short on every page's foot and in full on the last page: every copy
    # anchors the register's history up to it (models/register/chain.py); "" unissued
    register_head: str = ""
    #: the digest of the register record's content (models/register/chain.content_digest),
    #: carried in the PDF's keywords: a record rewritten after issue is found from the PDF
    register_content: str = ""
    #: the register's proof that it issued this certificate (models/register/signing.proof),
    #: carried in the PDF's keywords; "" without the lab's key
    register_proof: str = ""
    # a specimen (the bundled example details, or the window's training switch):
    # watermarked SPECIMEN, numbered SPECIMEN-…, never recorded in a register
    specimen: bool = False
    # why no U is stated for the results although a budget was evaluated (the budget then
    # holds only the inputs that could be; the fringe's phase estimated from the signals):
    # the results table, the statistics, the exports and the DCC state none; "" when U is
    uncertainty_withheld: str = ""
    # the inputs the budget leaves out because their uncertainty is not stated (untranslated
    # names): named under the budget, so that U is never read as complete (GUM 7.2.7);
    # by default the decision's (models.certificate.builder.Decision.not_stated)
    not_in_u: tuple[str, ...] = ()
    # the figures (their keys as the statistics table prints them: "R", "E_up" …) whose
    # coverage interval was raised to the laboratory's CMC (models.uncertainty.lab_scope
    # .held_to_cmc): named in its scope statement
    figures_raised_to_cmc: tuple[str, ...] = ()
    # what one reading is called here (the fringe's "sample"): the standards table says a
    # standard's figure stated per reading per it, as the budget's note does (assessment 78
    # L4: "per reading" in the table, "per sample" in the budget, for one figure)
    reading_name: str = QT_TR_NOOP("reading")

    @property
    def is_test_report(self) -> bool:
        """A test report: asked for, or a calibration certificate that cannot state
        traceability (not every standard that carries the measurand listed with a
        certificate and a stated U; or an input with no stated uncertainty, whether or not
        a standard is listed: a cross-calibration with no comparator listed, assessment 73
        M2, was titled a calibration certificate while its U lacked the comparator's
        calibration)."""
        return (self.metadata.document_type == "test" or bool(self.traceability_gaps)
                or bool(self.untraceable))

    @property
    def not_in_u_statement(self) -> str:
        """"Inputs not stated, so not in U: …" ("" when the budget holds every input)."""
        if not self.not_in_u:
            return ""
        return message(QT_TR_NOOP("Inputs not stated, so not in U: {inputs}. U covers only the "
                                  "inputs in the budget."),
                       inputs=listed(message(name) for name in self.not_in_u))

    @property
    def expanded_uncertainty(self) -> float:
        """The certificate's U: the largest over the curve's points (nan where it is
        withheld, :attr:`uncertainty_withheld`)."""
        return math.nan if self.uncertainty_withheld else self.budget.max_expanded

    @property
    def title(self) -> str:
        return DOCUMENT_TYPES["test" if self.is_test_report else self.metadata.document_type]

    @property
    def is_draft(self) -> bool:
        return bool(self.metadata.missing_fields())


def _fmt(value: float, digits: int = 3) -> str:
    if not np.isfinite(value):
        return "—"
    return f"{value:.{digits}f}"


def _before_rounding(expanded: float) -> str:
    """k·u_c as the budget prints it before rounding: to three decimals, or to as many more
    (up to 12) as show why it is rounded up to the U stated below it: 360.000001, not
    "360.000" above a U of 370 (two significant digits rounded up, GUM 7.2.6; the
    0.000001 is the small inputs' share in quadrature, not noise: assessment 76 M1)."""
    text = _fmt(expanded)
    if not (math.isfinite(expanded) and expanded > 0):
        return text
    decimals = uncertainty_decimals(expanded)
    stated = rounded_to(expanded, decimals, "up")
    for digits in range(3, 13):
        text = _fmt(expanded, digits)
        if rounded_to(float(text), decimals, "up") == stated:
            break
    return text


def _dof_text(nu: float) -> str:
    if not np.isfinite(nu):
        return "∞"
    return f"{nu:.0f}" if nu < 1e4 else "≥ 10⁴"


def _unit_key_of(symbol: str) -> str:
    """The unit key of a figure's symbol ('"', " µrad"), "" where it names none."""
    try:
        return unit_named(symbol.strip()).key if symbol.strip() else ""
    except UnitError:
        return ""


def budget_table(budget: UncertaintyBudget, point: str, unit: str = "\"",
                 withheld: bool = False) -> Table:
    """The budget at its worst point as a printable table, with the combined line
    (``withheld``: no U is stated for the results, so its last line is named as what it
    is, the inputs evaluated only)."""
    rows = []
    for r in budget.table():
        dof = _dof_text(r["dof"])
        rows.append((r["name"], str(r["evaluation"]), r["distribution"],
                     _fmt(r["value"]), f"{r['divisor']:.3g}", _fmt(r["u"]),
                     f"{r['sensitivity']:.3g}", _fmt(r["contribution"]),
                     f"{100 * r['share']:.1f}", dof))
    i = budget.worst_index
    nu_text = _dof_text(budget.truncated_dof())
    raw = budget.effective_dof()
    uc = float(budget.combined[i]) if budget.points else float("nan")
    rows.append((QT_TR_NOOP("Combined standard u_c"), "", "", "", "", "", "", _fmt(uc), "100.0",
                 nu_text))
    k = budget.coverage_factor
    # k·u_c as computed, named as that: the U stated comes on the next line, rounded up (day
    # 74 finding 12: "Expanded U (k = 2.01) 0.018" above "Expanded uncertainty U (p = 95.45 %)
    # 0.019" did not say which was which)
    rows.append((message(QT_TR_NOOP("U of the inputs evaluated only (k = {k}): a lower bound, "
                                    "not U") if withheld else
                         QT_TR_NOOP("Expanded uncertainty k·u_c (k = {k}), before rounding"),
                         k=f"{k:.2f}"), "", "", "", "", "", "", _before_rounding(k * uc), "", ""))
    stated_u = float(budget.expanded[i]) if budget.points else math.nan
    if not withheld and math.isfinite(stated_u) and stated_u > 0 and not bool(
            budget.below_floor[i]):
        # the U the certificate states there: the line above rounded up to two significant
        # digits (GUM 7.2.6), so that the table ends on the figure printed (assessment 72
        # L6: "Expanded U (k = 2.00) 1.436" beside "U = 1.5″")
        # (named as the statistics name the U stated, rounded up there too), a figure that
        # rounds itself again where the table is read in another unit (7.0 µrad for 1.436″,
        # not 1.5″ converted to 7.27 µrad)
        rows.append((message(QT_TR_NOOP("U stated (p = {p} %): k·u_c rounded up to two "
                                        "significant digits"),
                             p=f"{100 * budget.probability:.2f}"), "", "", "", "",
                     "", "", PrintedFigure(stated_u, "", rounding="up",
                                           unit_key=_unit_key_of(unit)), "", ""))
    if not withheld and budget.points and bool(budget.below_floor[i]):
        # the U stated there is the laboratory's CMC (ILAC-P14 5.4): the table's last line is
        # the U the certificate states, not the smaller one the inputs give
        rows.append((message(QT_TR_NOOP("U stated: raised to the laboratory's CMC (k = {k})"),
                             k=f"{k:.2f}"), "", "", "", "", "", "",
                     _fmt(float(budget.expanded[i])), "", ""))
    # ν as the table's line says it (day review 66 F8: the note's "1.0×10⁸" beside its "≥ 10⁴")
    note = message(QT_TR_NOOP("Budget at {point}, the point with the largest U. k = {k} is "
                              "Student's t for ν ≥ 10⁴, the effective degrees of freedom "
                              "(Welch–Satterthwaite), and a coverage probability of {p} %; "
                              "each point's U uses its own ν.")
                   if nu_text == "≥ 10⁴" else
                   QT_TR_NOOP("Budget at {point}, the point with the largest U. k = {k} is "
                              "Student's t for ν = {nu}, the effective degrees of freedom "
                              "(Welch–Satterthwaite: {raw}) truncated to the lower integer "
                              "(GUM G.6.4), and a coverage probability of {p} %; each point's U "
                              "uses its own ν."),
                   point=point, k=f"{k:.2f}", nu=nu_text,
                   raw=f"{raw:.2f}" if math.isfinite(raw) else "∞",
                   p=f"{100 * budget.probability:.2f}")
    u = unit.strip()
    return Table(QT_TR_NOOP("Uncertainty budget"), (
        QT_TR_NOOP("Input"), QT_TR_NOOP("Type"), QT_TR_NOOP("Distribution"),
        message(QT_TR_NOOP("Value ({unit})"), unit=u), QT_TR_NOOP("Divisor"),
        f"u ({u})", "c", f"c·u ({u})", QT_TR_NOOP("Share %"), "ν"), rows, note)


def opinion(text) -> str:
    """Advice on a certificate, marked as an opinion and interpretation (ISO/IEC 17025
    7.8.7): what the results suggest, not what was measured."""
    return message(QT_TR_NOOP("Opinion and interpretation (ISO/IEC 17025 7.8.7), not a "
                              "measured result: {text}"), text=message(text))


def reference_standard_components(metadata: CertificateMetadata, sensitivity,
                                  reading: str, sensitivity_from_first=None,
                                  unit: str = "arcsec", common: bool = False,
                                  sensitivity_per_angle=None, from_datum: bool = False
                                  ) -> list[BudgetComponent]:
    """One Type B input per reference standard with a stated uncertainty.

    ``sensitivity`` per point of a standard stated per reading (√2 where the error is the
    difference of two readings, 0 at the reference point); ``reading`` says what one
    reading is. ``sensitivity_from_first`` is used for a standard whose figure applies to
    each face's deviation from face 1 (polygon), ``sensitivity_per_angle`` for one whose
    figure applies to any angle measured with it (applies_to "angle": a rotary
    calibrator's, an interferometer's), where the workbench has one (else ``sensitivity``).
    ``from_datum``: a standard stated per reading enters as a reading at the point less the
    datum reading of the run (BudgetComponent.datum_reading). Each standard's figure is
    converted to ``unit``, the budget's. ``common``: the standard's calibration error is one
    unknown value for the whole run (drawn once per trial in a Monte Carlo of the curve),
    otherwise one per point.
    """
    out = []
    for std in metadata.standards:
        if std.uncertainty is None:
            continue
        divisor, distribution = divisor_for_basis(std.basis)
        name = std.description or QT_TR_NOOP("Reference standard")
        per, c, datum = reading, sensitivity, from_datum
        if std.applies_to == "from face 1" and sensitivity_from_first is not None:
            per, c, datum = (QT_TR_NOOP("face, stated from face 1"), sensitivity_from_first,
                             False)
        elif std.applies_to == "angle":
            per, datum = QT_TR_NOOP("angle between two readings"), False
            if sensitivity_per_angle is not None:
                c = sensitivity_per_angle
        basis = message(BASIS_DIVISORS[std.basis][0])
        note = (message(QT_TR_NOOP("{basis} per {per}, certificate {certificate}"), basis=basis,
                        per=message(per), certificate=std.certificate_no)
                if std.certificate_no else
                message(QT_TR_NOOP("{basis} per {per}"), basis=basis, per=message(per)))
        out.append(BudgetComponent(
            name, "B", distribution, std.uncertainty_in(unit), divisor, c, math.inf, note,
            common=common, per_angle=std.applies_to == "angle", datum_reading=datum))
    return out


def resolution_component(metadata: CertificateMetadata, sensitivity,
                         unit: str = "arcsec") -> list[BudgetComponent]:
    """The item's indication resolution r: rectangular, half-width r/2, per reading, in
    ``unit`` (the budget's)."""
    r = metadata.item_resolution_in(unit)
    if not r:
        return []
    return [BudgetComponent(QT_TR_NOOP("Item resolution"), "B", "rectangular", r / 2.0,
                            math.sqrt(3.0), sensitivity, math.inf,
                            message(QT_TR_NOOP("resolution {r} of the item's indication"),
                                    r=Quantity(r, unit)))]


def decided_interval_probability(conformity: Conformity) -> float | None:
    """The coverage probability of the decided value's interval as its row prints it, the
    JSON's ``decided_quantity.coverage_probability``: None where no interval is stated (the
    value alone, or U withheld)."""
    if not (math.isfinite(conformity.value) and math.isfinite(conformity.expanded)
            and math.isfinite(conformity.interval_low) and math.isfinite(conformity.interval_high)
            and math.isfinite(conformity.probability)):
        return None
    return float(conformity.probability)


#: the decided quantity's row where every point decides: which point its value is
DECIDING_POINT = QT_TR_NOOP("the deciding point: {point}")


def printed_decided_figures(conformity: Conformity, unit: str = "\"", unit_key: str = ""
                            ) -> dict[str, PrintedFigure] | None:
    """The decided value, its U₋ and U₊ and its interval's ends as the certificate prints
    them ("value", "lower", "upper", "low", "high"), each in any unit it is read in: the
    value to the nearest, each U rounded up to two significant digits at most (GUM 7.2.6),
    the ends the printed value ∓ the printed U (assessment 70 M1); a half range's interval
    asymmetric, its lower end held at 0 (U₋ then the value less it). None where nothing is
    printed so (the value not a number, U not a positive number). The statistics' row and
    the XLSX's *Certificate* sheet state these (assessment 76 M4: the sheet gave U = 1.4365″
    unrounded where the certificate it records states 1.5″)."""
    if not math.isfinite(conformity.value):
        return None
    lower = conformity.expanded_lower
    if conformity.monte_carlo is not None and math.isfinite(lower) and lower > 0:
        # U₋, U₊ the value to the interval's ends, after clipping (the statement's)
        minus, plus = printed_half_widths(conformity.value, lower, conformity.expanded)
        return printed_interval_figures(conformity.value, minus, plus, unit, clip=True,
                                        unit_key=unit_key)
    if significant_decimals(conformity.expanded) is None:
        return None
    return printed_interval_figures(conformity.value, conformity.expanded,
                                    conformity.expanded, unit, unit_key=unit_key)


def decision_rows(conformity: Conformity, budget: UncertaintyBudget,
                  points: str, unit: str = "\"", uncertainty_withheld: str = "",
                  interval_columns: bool = False) -> list[tuple[str, ...]]:
    """The statistics rows every certificate has: the decided quantity with its own U,
    and the curve's largest U with its coverage factor (``uncertainty_withheld``: why no U
    is stated, said in its place). The decided interval's own coverage probability is in
    its row (an audit: a decided "6.0″ −1.1″/+1.0″" at 92.5 % sat above "U (p = 95.45 %)"
    with no probability of its own): in its name, "Decided quantity (p = 92.5 %)", or with
    ``interval_columns`` (a table with a coverage interval and a probability column, as
    positioning's) in those, each row then (name, value, interval, probability, note)."""
    big_u = budget.max_expanded
    digits = uncertainty_decimals(big_u)
    rows: list[tuple[str, ...]] = []
    p_decided = decided_interval_probability(conformity)
    if math.isfinite(conformity.value):
        lower = conformity.expanded_lower
        # a half range's interval (asymmetric, its lower end held at 0), printed as such; a
        # point's error is signed, its interval ±U of that point (0.8.17 printed a point at
        # −6″ as "6″ −6″/+18″, 0″ … 25″, … as a half range is not negative")
        if conformity.monte_carlo is not None and math.isfinite(lower) and lower > 0:
            # two significant digits at most on either side (GUM 7.2.6): the larger's decimal
            d = significant_decimals(max(lower, conformity.expanded)) or digits
            plus = printed_half_widths(conformity.value, lower, conformity.expanded)[1]
            shown = printed_decided_figures(conformity, unit)
            assert shown is not None  # a half range with its interval
            value = joined([shown["value"], "\n",  # a line each: never broken
                            asymmetric_figures(shown)])
            low, high = shown["low"], shown["high"]
            measured = conformity.measured
            raised = conformity.raised_to_cmc
            # what the value was made from and the interval's ends, first in the note (the
            # figure's cell stays figures, which the results workbook reads as numbers)
            note = separated([message(QT_TR_NOOP("interval {low} … {high}"),
                                      low=low, high=high),
                              held_at_zero_note(conformity.value, lower, d, unit,
                                                float(budget.floor), bool(raised and raised[0])),
                              message(QT_TR_NOOP("measured {measured}"),
                                      measured=printed(measured, unit, u=max(lower, plus)))
                              if fixed_places(measured, d) != fixed_places(conformity.value, d)
                              else "",
                              conformity.quantity], "; ")
        else:
            value = format_uncertain(conformity.value, conformity.expanded, unit)
            shown = printed_decided_figures(conformity, unit)
            if shown is not None:  # value ± U the printed interval (assessment 70 M1)
                value = joined([shown["value"], " ± ", shown["upper"]])
                low, high = shown["low"], shown["high"]
            else:
                low, high = math.nan, math.nan
            note = separated([message(DECIDING_POINT, point=conformity.point)
                              if conformity.point else "", conformity.quantity], "; ")
        if interval_columns:
            stated = (p_decided is not None and math.isfinite(float(getattr(low, "value", low)))
                      and math.isfinite(float(getattr(high, "value", high))))
            rows.append((QT_TR_NOOP("Decided quantity"), value,
                         joined([low, " … ", high]) if stated else "—",
                         f"{percent_text(p_decided)} %" if stated and p_decided else "", note))
        elif p_decided is not None:
            rows.append((message(QT_TR_NOOP("Decided quantity (p = {p} %)"),
                                 p=percent_text(p_decided)), value, note))
        else:
            rows.append((QT_TR_NOOP("Decided quantity"), value, note))
    padding = ("", "") if interval_columns else ()
    if uncertainty_withheld:
        rows.append((QT_TR_NOOP("Expanded uncertainty U"), message(QT_TR_NOOP("not stated")),
                     *padding,
                     message(QT_TR_NOOP("the inputs evaluated give {u} at most, but U is "
                                        "incomplete: {reason}"),
                             u=printed(big_u, unit, rounding="up"), reason=uncertainty_withheld)))
        return rows
    rows.append((message(QT_TR_NOOP("Expanded uncertainty U (p = {p} %)"),
                         p=f"{100 * budget.probability:.2f}"),
                 printed(big_u, unit, rounding="up") if digits is not None and big_u > 0 else
                 f"{fixed_places(big_u, digits)}{unit}", *padding,
                 message(QT_TR_NOOP("largest over the {points}; k = {k} there"),
                         points=message(points), k=f"{budget.coverage_factor:.2f}")))
    return rows


def format_uncertain(value: float, expanded: float, unit: str, digits: int = 2) -> str:
    """``value ± U`` with U rounded up to two significant digits and the value to match."""
    decimals = significant_decimals(expanded)
    if decimals is None:
        return f"{value:.{digits}f}{unit}"
    return joined([printed(value, unit, u=expanded), " ± ",
                   printed(expanded, unit, rounding="up")])


def range_cells(low: float, high: float, expanded: float, unit: str = "\"",
                fallback: int = 2) -> tuple[str, str, int]:
    """A curve's range as the statistics print it, ("-1.6″ … +1.3″", "2.9″", decimals): its
    ends to the decimal of ``expanded`` (the curve's largest U, two significant digits: GUM
    7.2.6; ``fallback`` decimals where U is not a positive number) and the peak-to-peak the
    difference of the ends as printed, so that it adds up as printed."""
    d = significant_decimals(expanded)
    if d is None:
        a, b, ptp = printed_range(low, high, fallback)
        return f"{a}{unit} … {b}{unit}", f"{ptp}{unit}", fallback
    # the window's rule too (its headline, summary), in any unit it is read in: each end
    # signed, to the decimal of U there, the peak-to-peak the ends' difference as printed
    ends = joined([printed(low, unit, u=expanded, sign="+"), " … ",
                   printed(high, unit, u=expanded, sign="+")])
    return ends, PrintedFigure(high, unit, u=expanded, less=low), d


def table_decimals(expanded, fallback: int = 2) -> int:
    """The decimal a table's points are printed to where a point's own U gives none (a
    reference point, U = 0): that of the median positive U."""
    u = np.asarray(expanded, dtype=float)
    positive = u[np.isfinite(u) & (u > 0)]
    return uncertainty_decimals(float(np.median(positive))) if positive.size else fallback


def rounded_cells(values, expanded: float, reference_decimals: int,
                  signed: bool = True) -> tuple[list[str], str]:
    """A point's figures and its U as GUM 7.2.6 asks: U to two significant digits at most,
    rounded up, each figure to the same decimal, the same U beside one figure or several
    (:func:`models.uncertainty.rounding.stated_pair`, the U its decision uses: issue 39, and
    every other document gives: assessment 72 H1);
    U = 0 (a reference point, zero by definition) printed so, its figures to
    ``reference_decimals``."""
    if expanded == 0 or not math.isfinite(expanded):
        d = reference_decimals
        u_text = message(REFERENCE_POINT_TEXT) if expanded == 0 else "—"
    else:
        d = uncertainty_decimals(expanded)
        shown_u = (stated_pair(float(values[0]), expanded)[1] if len(values) == 1 else
                   rounded_to(expanded, d, "up"))
        u_text = fixed_places(shown_u, d)
    # a zero unsigned, as in every column (assessment 76 L6)
    return [fixed_places(float(v), d, "+" if signed else "") for v in values], u_text


def rounded_figure(value: float, expanded: float, reference_decimals: int) -> str:
    """:func:`rounded_cells`' cell of one figure, signed, without its U: to the decimal of
    ``expanded`` (two significant digits), or ``reference_decimals`` where U is zero or not
    finite (a results table's column of figures: no U worked out for each cell)."""
    d = (reference_decimals if expanded == 0 or not math.isfinite(expanded)
         else uncertainty_decimals(expanded))
    return fixed_places(float(value), d, "+")


def gum_pair(value: float, expanded: float, unit: str, signed: bool = False,
             fallback: int = 5) -> tuple[str, str]:
    """A parameter and its U, each with ``unit`` (" V", " rad"): U to two significant digits
    at most and the value to its decimal (GUM 7.2.6); without a U, the value to
    ``fallback`` decimals and U "—"."""
    spec = "+" if signed else ""
    if not (math.isfinite(expanded) and expanded > 0):
        return f"{value:{spec}.{fallback}f}{unit}", "—"
    return (printed(value, unit, u=expanded, sign=spec),  # in any unit, rounded there
            printed(expanded, unit, rounding="up"))
