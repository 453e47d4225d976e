"""The positioning test's plots, declared once for the window and the certificate."""

from __future__ import annotations

from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries
from models.positioning.model import DEVIATION_UNITS, PositioningResult

__all__ = ["deviation_figure", "in_progress_readings", "readings_figure", "reversal_figure"]

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


# one colour per run in the runs plot (dark enough to read on white), repeated past ten
RUN_COLOURS = ((31, 95, 191), (192, 57, 43), (39, 174, 96), (142, 68, 173), (211, 84, 0),
               (22, 160, 133), (52, 73, 94), (183, 149, 11), (199, 21, 133), (127, 140, 141))


def in_progress_readings(parsed: Any, result: PositioningResult) -> tuple[np.ndarray, np.ndarray]:
    """The readings of the run (or pilgrim-step target) in progress, as taken: (target,
    deviation in the deviation unit); empty when nothing is in progress. They enter no
    figure; the window draws them beside the runs."""
    unit = getattr(result, "incomplete", None)
    if unit is None or parsed is None or not unit.rows:
        return np.empty(0), np.empty(0)
    rows = np.asarray([i for i in unit.rows if i < parsed.n], dtype=int)
    target = parsed["target"][rows].astype(float)
    scale = DEVIATION_UNITS[result.deviation_unit][1]
    deviation = parsed["deviation"][rows].astype(float)
    measured = (parsed["measured"][rows].astype(float) - target) * scale
    return target, np.where(np.isfinite(deviation), deviation, measured)


def readings_figure(result: PositioningResult, parsed: Any = None) -> PlotFigure:
    """Every reading, one series per run and direction: each run its own colour, named by
    its number once; ↑ solid, ↓ dashed (markers on both); with ``parsed``, the readings of
    a run in progress as taken (grey markers, in no figure)."""
    series = []
    runs = [int(r) if float(r).is_integer() else r for r in np.unique(result.runs)]
    named = set()
    for direction in (1, -1):
        pick = result.directions == direction
        for run in np.unique(result.runs[pick]):
            rows = pick & (result.runs == run)
            order = np.argsort(result.targets[rows], kind="stable")
            number = int(run) if float(run).is_integer() else run
            colour = RUN_COLOURS[runs.index(number) % len(RUN_COLOURS)]
            label = "" if number in named else str(number)
            named.add(number)
            series.append(PlotSeries(label, result.targets[rows][order],
                                     result.deviations[rows][order], colour, True,
                                     dashed=direction < 0))
    x, y = in_progress_readings(parsed, result)
    if x.size:
        series.append(PlotSeries(QT_TR_NOOP("in progress (as taken)"), x, y, GREY, True,
                                 width=0, marker_size=8))
    return PlotFigure(QT_TR_NOOP("Readings, run by run (colour: run; ↑ solid, ↓ dashed)"),
                      _x_label(result), _y_label(result), tuple(series))
