"""The resolution the results XLSX sheet and the results CSV write each point's figures to
(the same figures in both, since day review 65: the CSV wrote ``%.10g``).

The certificate prints a point's figures to the decimal of its U (two significant
digits, GUM 7.2.6; a point whose U is zero or not stated to the table's reference
decimal: :func:`models.certificate.document.table_decimals`). The *Results* sheet
writes them :data:`EXTRA_DECIMALS` decimals finer than that: every printed digit is
there, and three more, but no binary noise (a correction of −3.456836534665442e-05″
where the certificate prints +0.00″ is written −0.00003). The columns in the errors'
unit (those named with the unit of an ``expanded_uncertainty_*`` column) are rounded so;
the others (a face's number, a nominal angle in degrees, a reading) to
:data:`OTHER_SIGNIFICANT` significant digits (a reading typed with no more is written as
typed).

No printed figure is changed: rounded to the printed decimal (half up, half to even, as a
spreadsheet's ROUND or Python does), the sheet's figure is the certificate's. A figure
that three more decimals would put exactly half-way between two printed steps (−0.5949996
as −0.595, which reads as −0.60 where −0.59 is printed) is written with three more
decimals again (−0.5949996), until it is not."""

from __future__ import annotations

import math
from decimal import Decimal

import numpy as np

from models.certificate.document import table_decimals
from models.uncertainty.rounding import significant_decimals

__all__ = ["EXTRA_DECIMALS", "OTHER_SIGNIFICANT", "UNCERTAINTY_PREFIX", "printed_decimals",
           "rounded_point_columns"]

#: decimals the sheet keeps beyond those the certificate prints a point's figures to
EXTRA_DECIMALS = 3
#: significant digits of a column not in the errors' unit (as the CSV's ``%.10g`` was)
OTHER_SIGNIFICANT = 10
#: how an expanded uncertainty's column is named (``expanded_uncertainty_arcsec``, …)
UNCERTAINTY_PREFIX = "expanded_uncertainty"


def _unit_of(name: str) -> str:
    return name.rpartition("_")[2]


def printed_decimals(uncertainties: list[np.ndarray], points: int
                     ) -> tuple[np.ndarray, np.ndarray]:
    """Each point's printed decimals, coarsest and finest: those its U columns print it to
    (a U of zero or not finite: its column's reference decimal; no U column: two)."""
    coarsest = [99] * points
    finest = [-1] * points
    for u in uncertainties:
        reference = table_decimals(u)
        # a U repeats over the points (one per range, or one for all): each worked out once
        said: dict[float, int] = {}
        for k, value in enumerate(np.asarray(u, dtype=float).tolist()):
            d = said.get(value)
            if d is None:
                d = significant_decimals(value)
                d = said[value] = reference if d is None else d
            coarsest[k], finest[k] = min(coarsest[k], d), max(finest[k], d)
    if not uncertainties:
        coarsest = finest = [table_decimals(np.empty(0))] * points
    return np.array(coarsest, dtype=int), np.array(finest, dtype=int)


def _unambiguous(value: float, printed: tuple[int, int]) -> float:
    """``value`` to the finer of ``printed`` (the decimals its row's figures are printed
    to, coarsest and finest) + :data:`EXTRA_DECIMALS`, or more where that would put it
    exactly half-way between two steps of one of those decimals: such a figure, rounded
    again, could be read either way."""
    coarsest, finest = printed
    decimals = finest + EXTRA_DECIMALS
    while True:
        rounded = round(value, decimals)
        if decimals >= 15 or rounded == value:
            return rounded
        text = repr(rounded)
        if "e" not in text and not text.endswith("5"):
            return rounded  # its last digit is not a 5: half-way between no two steps
        digits = Decimal(text).normalize().as_tuple()
        half_way = (bool(digits.digits) and digits.digits[-1] == 5
                    and coarsest + 1 <= -int(digits.exponent) <= finest + 1)
        if not half_way:
            return rounded
        decimals += EXTRA_DECIMALS


def _significant(values: np.ndarray, digits: int) -> np.ndarray:
    out = values.copy()
    ok = np.isfinite(values) & (values != 0)
    if ok.any():
        exponents = np.floor(np.log10(np.abs(values[ok]))).astype(int)
        out[ok] = [round(float(v), digits - 1 - int(e)) for v, e in
                   zip(values[ok], exponents, strict=True)]
    return out


def rounded_point_columns(columns: list[tuple[str, np.ndarray]]
                          ) -> list[tuple[str, np.ndarray]]:
    """``columns`` (name, values: the certificate's point columns in the unit exported)
    with every value rounded to the sheet's resolution (module docstring); −0.0 is
    written 0."""
    points = len(columns[0][1]) if columns else 0
    uncertainties = [np.asarray(v, dtype=float) for name, v in columns
                     if name.startswith(UNCERTAINTY_PREFIX)]
    units = {_unit_of(name) for name, _ in columns if name.startswith(UNCERTAINTY_PREFIX)}
    coarsest, finest = printed_decimals(uncertainties, points)
    out = []
    for name, values in columns:
        values = np.asarray(values, dtype=float)
        if _unit_of(name) in units:
            # as Python numbers: a numpy scalar's test and conversion cost more than the
            # rounding (the CSV of a million points)
            rounded = np.array([_unambiguous(v, (lo, hi)) if math.isfinite(v) else v
                                for v, lo, hi in zip(values.tolist(), coarsest.tolist(),
                                                     finest.tolist(), strict=True)],
                               dtype=float)
        else:
            rounded = _significant(values, OTHER_SIGNIFICANT)
        out.append((name, rounded + 0.0))
    return out
