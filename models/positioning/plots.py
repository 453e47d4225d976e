"""The positioning test's plots, declared once for the window and the certificate."""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries
from models.positioning.model import PositioningResult

__all__ = ["deviation_figure", "readings_figure", "reversal_figure"]

FORWARD, BACKWARD, MEAN, ENVELOPE, GREY = ((192, 57, 43), (31, 95, 191), (44, 160, 44),
                                           (120, 120, 120), (150, 150, 150))
ARROWS = {"up": "↑", "down": "↓"}


def _x_label(result: PositioningResult) -> str:
    return f"target position ({result.target_symbol.strip()})"


def _y_label(result: PositioningResult, what: str = "deviation") -> str:
    return f"{what} ({result.symbol.strip()})"


def deviation_figure(result: PositioningResult) -> PlotFigure:
    """Mean deviation per direction with its ±2s band, the bidirectional mean and the
    envelope whose height is A (x̄ ± 2s over the axis)."""
    x = result.positions
    series = []
    upper, lower = [], []
    for name, _, stats in result.directions_present():
        band = 2.0 * stats.std if np.any(np.isfinite(stats.std)) else None
        series.append(PlotSeries(f"x̄{ARROWS[name]}" + (f" ± 2s{ARROWS[name]}" if band is not None
                                                      else ""),
                                 x, stats.mean, FORWARD if name == "up" else BACKWARD, True,
                                 band=band, role="raw" if name == "up" else "corrected"))
        if band is not None:
            upper.append(np.nanmax(stats.mean + band))
            lower.append(np.nanmin(stats.mean - band))
    if result.iso.bidirectional_mean is not None:
        series.append(PlotSeries(QT_TR_NOOP("bidirectional mean M_i"), x, result.iso.bidirectional_mean, MEAN,
                                 role="model"))
    if upper:
        ends = np.array([x[0], x[-1]], dtype=float)
        series.append(PlotSeries(QT_TR_NOOP("envelope of A"), ends, np.full(2, max(upper)), ENVELOPE))
        series.append(PlotSeries("", ends, np.full(2, min(lower)), ENVELOPE))
    return PlotFigure(QT_TR_NOOP("Mean positional deviation with ±2s"), _x_label(result), _y_label(result),
                      tuple(series))


def reversal_figure(result: PositioningResult) -> PlotFigure | None:
    if result.iso.reversal is None:
        return None
    x = result.positions
    mean = float(result.iso.figures.get("B_mean", np.nan))
    return PlotFigure("Reversal value B_i = x̄↑ − x̄↓", _x_label(result),
                      _y_label(result, "reversal"),
                      (PlotSeries("B_i", x, result.iso.reversal, MEAN, True, role="residual"),
                       PlotSeries(QT_TR_NOOP("mean reversal B̄"), np.array([x[0], x[-1]], dtype=float),
                                  np.full(2, mean), ENVELOPE)))


def readings_figure(result: PositioningResult) -> PlotFigure:
    """Every reading, one series per run and direction (markers; the window draws them as
    points)."""
    series = []
    for direction, name in ((1, "up"), (-1, "down")):
        pick = result.directions == direction
        for k, run in enumerate(np.unique(result.runs[pick])):
            rows = pick & (result.runs == run)
            order = np.argsort(result.targets[rows], kind="stable")
            label = f"runs {ARROWS[name]} (one line each)" if k == 0 else ""
            series.append(PlotSeries(label, result.targets[rows][order],
                                     result.deviations[rows][order],
                                     FORWARD if direction > 0 else BACKWARD, True))
    return PlotFigure(QT_TR_NOOP("Readings, run by run"), _x_label(result), _y_label(result), tuple(series))
