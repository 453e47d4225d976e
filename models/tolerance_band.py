"""The tolerance band (±T) and the U band on an error plot, where a tolerance is set (#41).

The certificate judges conformity of a curve (its decided curve: the corrected error, the
mean positional deviations) against ±T with each point's expanded uncertainty U. The
window draws the same: beside the figure's own series, each decided curve with its U as a
shaded band (the U the certificate and ``--json``'s ``expanded_uncertainty_*`` give) and
the two limits of ±T — about the decided curve's mid-range when the decision is on half
the peak-to-peak error (the curve is inside exactly when half its peak-to-peak is within
T), about zero when every point is judged against ±T. Without a tolerance, no band.

API: ``with_tolerance(figure, tolerance, curves, quantity)``; ``curves`` are
(label, x, y, U or None) in the figure's unit.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Sequence

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries

__all__ = ["TOLERANCE_ROLE", "UNCERTAINTY_ROLE", "tolerance_limits", "with_tolerance"]

RED = (192, 57, 43)
BAND_GREY = (110, 110, 110)
#: the roles of the added series (the window's error plot draws them on the decided panel)
TOLERANCE_ROLE, UNCERTAINTY_ROLE = "tolerance", "uncertainty"


def tolerance_limits(tolerance: float, ys: Sequence[np.ndarray],
                     quantity: str = "half_range") -> tuple[float, float]:
    """(lower, upper) limit drawn: ±T about the mid-range of the curves' values
    (``half_range``) or about zero (``points``)."""
    values = np.concatenate([np.asarray(y, dtype=float).ravel() for y in ys]) if ys else \
        np.empty(0)
    values = values[np.isfinite(values)]
    centre = 0.5 * (float(values.max()) + float(values.min())) \
        if quantity == "half_range" and values.size else 0.0
    return centre - tolerance, centre + tolerance


def with_tolerance(figure: PlotFigure, tolerance: float | None,
                   curves: Sequence[tuple[str, np.ndarray, np.ndarray, np.ndarray | None]],
                   quantity: str = "half_range") -> PlotFigure:
    """``figure`` with each decided curve's U band and the ±T limits added; ``figure``
    itself when no (positive, finite) tolerance is set or there is no curve."""
    if tolerance is None or not math.isfinite(tolerance) or tolerance <= 0 or not curves:
        return figure
    extra = []
    for label, x, y, expanded in curves:
        if expanded is None:
            continue
        expanded = np.asarray(expanded, dtype=float)
        if expanded.shape != np.shape(y) or not np.any(np.isfinite(expanded)):
            continue
        extra.append(PlotSeries(label, np.asarray(x, dtype=float), np.asarray(y, dtype=float),
                                BAND_GREY, band=expanded, role=UNCERTAINTY_ROLE, width=0))
    xs = np.concatenate([np.asarray(c[1], dtype=float).ravel() for c in curves])
    xs = xs[np.isfinite(xs)]
    if not xs.size:
        return figure
    low, high = tolerance_limits(tolerance, [c[2] for c in curves], quantity)
    ends = np.array([xs.min(), xs.max()])
    title = (QT_TR_NOOP("tolerance ±T about the mid-range") if quantity == "half_range"
             else QT_TR_NOOP("tolerance ±T"))
    extra.append(PlotSeries(title, ends, np.full(2, high), RED, dashed=True, width=1,
                            role=TOLERANCE_ROLE))
    extra.append(PlotSeries("", ends, np.full(2, low), RED, dashed=True, width=1,
                            role=TOLERANCE_ROLE))
    return dataclasses.replace(figure, series=tuple(figure.series) + tuple(extra))
