"""The shape every workbench's certificate shares, declared once.

A certificate (:class:`~models.certificate.document.CertificateDocument`) holds a results
table (a row per point, each figure to the decimal of its own U, GUM 7.2.6), a statistics
table with the decision rows in it (the decided quantity and the curve's largest U), a
statement of conformity decided on one error curve, the uncertainty budget shown at its
worst point, and the workbench's own statements. :func:`build_certificate` makes the
document from what is a workbench's own: its columns and their figures, its statistics
rows, the curve it decides on and its statements; it formats, decides and assembles the
rest the same way for every workbench.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from models.certificate.document import (
    CertificateDocument,
    PlotFigure,
    Table,
    decision_rows,
    rounded_cells,
    rounded_figure,
    table_decimals,
)
from models.certificate.metadata import CertificateMetadata
from models.certificate.traceability import (
    expired_withheld,
    standards_not_stated,
    traceability_withheld,
)
from models.messages import QT_TR_NOOP, Message, listed, message, separated
from models.quantity import unit as unit_of
from models.uncertainty.budget import UncertaintyBudget
from models.uncertainty.conformity import decide_conformity
from models.uncertainty.printed_figure import StatedLimit, converted_limit
from models.uncertainty.rounding import StatedNumber, fixed_places, uncertainty_decimals

__all__ = ["Column", "Decision", "PointTable", "Statistics", "build_certificate",
           "difference_column", "figure_column", "text_column", "uncertainty_column"]


@dataclass(frozen=True)
class Column:
    """A column of the results table: its header, and its cells given the table's reference
    decimal (the decimal a point whose U gives none is printed to: :func:`table_decimals`)."""

    header: str
    cells: Callable[[int], Sequence[str]]
    # a note the table adds under it, given the same decimal ("" for none): a difference
    # column's where a printed difference is not that of the printed figures beside it
    note: Callable[[int], str] | None = None


def text_column(header: str, cells: Sequence[str]) -> Column:
    """A column the workbench formats itself (the point's angle, its number …)."""
    listed = list(cells)
    return Column(header, lambda _shown: listed)


def figure_column(header: str, values, expanded) -> Column:
    """Each point's figure, signed, to the decimal of its U (two significant digits); a point
    whose U is zero (a reference point) or not finite to the table's reference decimal."""
    pairs = list(zip(values, expanded, strict=True))
    return Column(header, lambda shown: [rounded_figure(v, u, shown) for v, u in pairs])


def difference_column(header: str, values, less, expanded, less_expanded=None) -> Column:
    """The column of ``values`` − ``less`` (a correction: the corrected less the raw error;
    a reversal x̄↑ − x̄↓), each point's difference computed from the unrounded figures and
    rounded, as every figure is, on its own (GUM 7.2.6), to the coarser of the decimals
    the two figures are printed to (``less_expanded``: the second's U, if not the same). So
    a printed sum may differ from its printed parts by one in the last digit; the other
    way — the difference of the rounded figures — printed a correction of 0.00001″ as
    +0.01″ and one correction two ways in one table (#61 assessor's re-check, N1)."""
    less_expanded = expanded if less_expanded is None else less_expanded
    rows = list(zip(values, less, expanded, less_expanded, strict=True))
    made: dict[int, list[tuple[str, str, str, int]]] = {}  # the cells and the note's check

    def printed(shown: int) -> list[tuple[str, str, str, int]]:
        if shown in made:
            return made[shown]
        out = []
        for v, w, u, uw in rows:
            a, b = rounded_cells((v,), u, shown)[0][0], rounded_cells((w,), uw, shown)[0][0]
            # the coarser of the two figures' decimals (to the tens where a U is 100 or
            # more: assessment 76 M1), not read from their text
            d = min(_cell_decimals(u, shown), _cell_decimals(uw, shown))
            out.append((a, b, fixed_places(float(v) - float(w), d, "+"), d))
        made[shown] = out
        return out

    def cells(shown: int) -> list[str]:
        return [difference for _, _, difference, _ in printed(shown)]

    def note(shown: int) -> str:
        # assessment 70 L3: said where a row's printed figures do not add up (the polygon's
        # −0.27″ + 0.10″ beside a corrected −0.16″); printing the difference of the rounded
        # figures instead would change the correction (+0.01″ for 0.00001″)
        apart = any(round(float(a) - float(b), d) != round(float(c), d)
                    for a, b, c, d in printed(shown))
        return message(ROUNDED_APART) if apart else ""
    return Column(header, cells, note)


def _cell_decimals(expanded: float, reference_decimals: int) -> int:
    """The decimal :func:`models.certificate.document.rounded_cells` prints a point's figure
    to: its U's (two significant digits), a reference point's (U zero or not finite)
    ``reference_decimals``."""
    if expanded == 0 or not math.isfinite(expanded):
        return reference_decimals
    return uncertainty_decimals(expanded)


#: under a results table where a printed difference (a correction, B_i) is not the
#: difference of the figures printed beside it (assessment 70 L3)
ROUNDED_APART = QT_TR_NOOP("Each figure is rounded on its own from its unrounded value (GUM "
                           "7.2.6), so on some rows a printed difference (a correction) differs "
                           "by one in the last digit from the difference of the figures printed "
                           "beside it.")


def uncertainty_column(header: str, expanded, values=None) -> Column:
    """Each point's U to two significant digits, rounded up (GUM 7.2.6); beside ``values``
    (the figure the U is of: the corrected error) U as it is printed beside that figure,
    the figure's ± U holding its computed interval
    (:func:`models.uncertainty.rounding.stated_pair`): the U the statement of conformity
    prints and decides every point with (issue 39). "reference point, by definition" where it
    is zero, "—" where it is not finite."""
    figures = [None] * len(expanded) if values is None else list(values)
    pairs = list(zip(expanded, figures, strict=True))
    return Column(header, lambda shown: [rounded_cells(() if v is None else (v,), u, shown)[1]
                                         for u, v in pairs])


@dataclass(frozen=True)
class PointTable:
    """The results table: a row per point, from the workbench's columns."""

    title: str
    columns: Sequence[Column]
    note: str = ""

    def table(self, expanded) -> Table:
        """The printable table; ``expanded``: the certificate's U per point (its median
        positive value gives the reference decimal)."""
        shown = table_decimals(expanded)
        cells = [list(column.cells(shown)) for column in self.columns]
        rows = list(zip(*cells, strict=True)) if cells else []
        notes = [column.note(shown) for column in self.columns if column.note is not None]
        added = list(dict.fromkeys(n for n in notes if n))
        # the table's own note a template of its own (a plain declared text is translated
        # whole, not as a part of a joined text)
        own = (self.note if isinstance(self.note, Message) or not self.note else
               message(self.note))
        note = separated([own, *added], " ") if added else self.note
        return Table(self.title, tuple(c.header for c in self.columns), rows, note)


@dataclass(frozen=True)
class Decision:
    """The error curve the statement of conformity is made on (in the budget's unit), as
    models.uncertainty.conformity.decide_conformity takes it. ``budget``: the one that
    curve's U comes from (None: the certificate's); ``withheld``: why no statement is made
    ("" when one may be)."""

    errors: Any
    what: str = QT_TR_NOOP("corrected error")
    point_names: Sequence[str] | None = None
    not_stated: Sequence[str] = ()
    withheld: str = ""
    budget: UncertaintyBudget | None = None
    # the decided half range's estimate when the workbench makes its own (a
    # HalfRangeEstimate-like object with its method text: positioning's E/2 with E's
    # interval); None: models.uncertainty.conformity.half_range_monte_carlo
    estimate: Any = None


@dataclass(frozen=True)
class Statistics:
    """The statistics table: the workbench's rows, with the decision rows (the decided
    quantity with its U, the largest U over the ``points``) between ``before`` and
    ``after``. ``budget``: the one the decision rows state (None: the certificate's). A
    table wider than three columns gets the decision rows' note in its last column."""

    before: Sequence[tuple[str, ...]]
    points: str
    after: Sequence[tuple[str, ...]] = ()
    title: str = QT_TR_NOOP("Statistics")
    header: tuple[str, ...] = (QT_TR_NOOP("Quantity"), QT_TR_NOOP("Value"), "")
    budget: UncertaintyBudget | None = None

    def table(self, conformity, budget: UncertaintyBudget, unit: str,
              uncertainty_withheld: str = "") -> Table:
        if len(self.header) == 5:  # figure, value, coverage interval, probability, note
            decided = decision_rows(conformity, self.budget or budget, self.points, unit,
                                    uncertainty_withheld, interval_columns=True)
        else:
            padding = ("",) * (len(self.header) - 3)
            decided = [(name, value, *padding, note) for name, value, note in
                       decision_rows(conformity, self.budget or budget, self.points, unit,
                                     uncertainty_withheld)]
        return Table(self.title, self.header, [*self.before, *decided, *self.after])


class _FromDetails:
    """The tolerance of the certificate details, in the budget's unit."""


FROM_DETAILS = _FromDetails()


def _the_details(metadata: CertificateMetadata, budget: UncertaintyBudget, tol: float) -> bool:
    """Whether a workbench's own tolerance ``tol`` (in the budget's unit) is the one its
    details state, to a millionth (a grade's ±2″ stated as 0.5555556 mdeg)."""
    try:
        given = metadata.tolerance_in(unit_of(budget.unit).key)
    except Exception:  # noqa: BLE001 - a tolerance of another kind is not this one
        return False
    return given is not None and math.isclose(float(given), float(tol), rel_tol=1e-6)


def build_certificate(*, kind_key: str, kind_title: str, method: str,
                      metadata: CertificateMetadata, source_name: str, method_reference: str,
                      budget: UncertaintyBudget, parameters: Table, results: PointTable,
                      statistics: Statistics, decision: Decision,
                      budget_point: Callable[[int], str],
                      plots: Sequence[PlotFigure | None], warnings: Sequence[str],
                      statements: Sequence[str], point_columns: Sequence[tuple[str, Any]],
                      tolerance: float | None | _FromDetails = FROM_DETAILS,
                      unit: str = "\"", measurand_standards: Sequence[tuple[str, str]] = (),
                      standards_in_settings: bool = False, roles_stated_only: Sequence[str] = (),
                      **more: Any) -> CertificateDocument:
    """The certificate of a workbench's result: the results table from its columns, the
    conformity decided on ``decision`` against ``tolerance`` (the details' by default) with
    the details' decision rule and quantity, the statistics with the decision rows, the
    budget shown at its worst point (``budget_point`` names it from its index). ``plots``:
    a None (a figure the result has not) is left out. ``more``: further fields of
    :class:`CertificateDocument` (untraceable, standard …).

    The standards listed with no stated U are inputs not stated, so not in U, and no
    statement of conformity is made (:func:`standards_not_stated`; ``standards_in_settings``:
    the workbench takes a listed standard's figures as inputs of its settings and names the
    ones not stated itself, the fringe's ADC); nor is one made while traceability is not
    established (``measurand_standards``: the standards that carry the measurand, each to
    be listed with a certificate and a stated U: :func:`traceability_withheld`), the rule
    the fringe's untraceable error already followed (assessment 70 H1, H2)."""
    tol = (metadata.tolerance_in(unit_of(budget.unit).key) if isinstance(tolerance, _FromDetails)
           else tolerance)
    # a standard whose calibration had expired: no statement of conformity (the document is
    # also a test report, Workbench.certificate_document)
    expired = expired_withheld(metadata)
    unstated = [] if standards_in_settings else standards_not_stated(metadata)
    not_stated = (*decision.not_stated, *(n for n in unstated if n not in decision.not_stated))
    # traceability not established (a standard that carries the measurand not listed with a
    # certificate and a stated U): said as the reason where the workbench names no other
    # reason the results are not traceable (its untraceable inputs, an input not stated)
    untraced = "" if more.get("untraceable") or not_stated else traceability_withheld(
        metadata, tuple(measurand_standards), tuple(more.get("stated_inputs", ())),
        tuple(roles_stated_only))
    withheld = separated([decision.withheld, untraced, expired], "; ")
    # the details' tolerance as the customer stated it, for the texts (assessment 70 M4),
    # where the workbench gives its own that is the details' too (the fringe's, the
    # cross-calibration's, a polygon grade's the details agree with: assessment 72 M1),
    # decided with its conversion as printed (M2)
    stated = (metadata.tolerance_quantity if tol is not None and (
        isinstance(tolerance, _FromDetails) or _the_details(metadata, budget, tol)) else None)
    if stated is not None and tol is not None:
        # decided with its conversion as printed (M2); the number as typed (its decimals:
        # the place ASTM E29 rounds a value to)
        key = unit_of(budget.unit).key
        tol = StatedLimit(converted_limit(float(stated.value), stated.unit.key, key),
                          (stated.value if isinstance(stated.value, StatedNumber) else
                           float(stated.value), stated.unit.key))
        stated = None if not isinstance(tolerance, _FromDetails) else stated
    conformity = decide_conformity(decision.errors, decision.budget or budget,
                                   stated if stated is not None else tol,
                                   metadata.decision_rule, metadata.decision_quantity,
                                   withheld, what=decision.what,
                                   point_names=decision.point_names,
                                   not_stated=not_stated,
                                   estimate=decision.estimate,
                                   rule_agreed=metadata.decision_rule_agreed)
    more.setdefault("not_in_u", tuple(not_stated))
    if not_stated:
        # U declared incomplete: traceability needs every link's contribution in U (VIM
        # 2.41, ILAC-P10), so none is claimed; the same rule as the fringe's inputs with no
        # stated U (CertificateDocument.untraceable): with standards listed the document is a
        # test report, its traceability statement and the DCC's flag say so
        more["untraceable"] = (*more.get("untraceable", ()), message(
            QT_TR_NOOP("U is incomplete: inputs not stated, so not in U: {inputs}"),
            inputs=listed(message(name) for name in not_stated)))
    if more.get("uncertainty_withheld") and math.isfinite(conformity.expanded):
        # no U stated for the results: the decided value has no interval either (the fringe's
        # every-point decision on an estimated phase printed ±U of the incomplete budget)
        conformity = dataclasses.replace(conformity, expanded=math.nan,
                                         expanded_lower=math.nan, conforming_probability=math.nan,
                                         decision_risk=math.nan)
    return CertificateDocument(
        kind_key=kind_key, kind_title=kind_title, metadata=metadata, source_name=source_name,
        method=method, method_reference=method_reference, parameters=parameters,
        results=results.table(budget.expanded),
        statistics=statistics.table(conformity, budget, unit,
                                    more.get("uncertainty_withheld", "")), budget=budget,
        budget_point=budget_point(budget.worst_index), conformity=conformity, tolerance=tol,
        plots=tuple(p for p in plots if p is not None), warnings=tuple(warnings),
        statements=tuple(statements), point_columns=tuple(point_columns), unit=unit, **more)
