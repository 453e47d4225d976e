"""The theodolite run's plots, declared once for the window and the certificate."""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries
from models.theodolite.model import TheodoliteResult

__all__ = ["corrected_with_uncertainty", "error_figure", "passes_figure", "residual_figure"]

BLUE, ORANGE, GREEN, PURPLE = (31, 119, 180), (255, 127, 14), (44, 160, 44), (148, 103, 189)


def _order(result: TheodoliteResult) -> np.ndarray:
    return np.argsort(result.theta_deg, kind="stable")


def error_figure(result: TheodoliteResult) -> PlotFigure:
    o = _order(result)
    th = result.theta_deg[o]
    return PlotFigure(QT_TR_NOOP("Raw error, set-up model and corrected error"), "θ (°)",
                      QT_TR_NOOP("error (\")"), (
        PlotSeries(QT_TR_NOOP("raw error θ − A"), th, result.raw_error_arcsec[o], BLUE, True, role="raw"),
        PlotSeries(QT_TR_NOOP("set-up share −ζ(θ)"), th, result.model_error_arcsec[o], ORANGE,
                   role="model"),
        PlotSeries(QT_TR_NOOP("corrected = raw + ζ"), th, result.corrected_error_arcsec[o], GREEN, True,
                   role="corrected"),
    ))


def corrected_with_uncertainty(result: TheodoliteResult, expanded) -> PlotFigure:
    o = _order(result)
    return PlotFigure(QT_TR_NOOP("Corrected error with its expanded uncertainty U"), "θ (°)",
                      QT_TR_NOOP("error (\")"), (
        PlotSeries(QT_TR_NOOP("corrected ± U"), result.theta_deg[o], result.corrected_error_arcsec[o], GREEN,
                   True, band=np.asarray(expanded)[o], role="corrected"),))


def residual_figure(result: TheodoliteResult) -> PlotFigure:
    o = _order(result)
    return PlotFigure(QT_TR_NOOP("Fit residuals (vertical readings)"), "θ (°)",
                      QT_TR_NOOP("E residual (\")"), (
        PlotSeries(QT_TR_NOOP("residual"), result.theta_deg[o], result.elevation_residuals_arcsec[o], PURPLE,
                   True, role=QT_TR_NOOP("residual")),))


# one colour per pass (dark enough to read on white), repeated past eight
PASS_COLOURS = ((31, 95, 191), (192, 57, 43), (142, 68, 173), (211, 84, 0), (22, 160, 133),
                (52, 73, 94), (183, 149, 11), (199, 21, 133))


def passes_figure(result: TheodoliteResult) -> PlotFigure | None:
    """Each pass (run and direction) as its own corrected-error curve, ↓ dashed, beside the
    mean over the passes at each θ; None with one pass only."""
    runs = result.runs
    directions = result.directions if result.directions is not None else \
        np.ones(result.theta_deg.size)
    if runs is None or np.unique(np.stack([runs, directions]), axis=1).shape[1] < 2:
        return None
    series = []
    for k, (run, direction) in enumerate(np.unique(np.stack([runs, directions]), axis=1).T):
        pick = (runs == run) & (directions == direction)
        o = np.argsort(result.theta_deg[pick], kind="stable")
        series.append(PlotSeries(f"{int(run)} {'↑' if direction > 0 else '↓'}",
                                 result.theta_deg[pick][o], result.corrected_error_arcsec[pick][o],
                                 PASS_COLOURS[k % len(PASS_COLOURS)], True,
                                 dashed=bool(direction < 0), width=1))
    key = np.round(result.theta_deg, 9)
    thetas = np.unique(key)
    mean = np.array([np.mean(result.corrected_error_arcsec[key == t]) for t in thetas])
    series.append(PlotSeries(QT_TR_NOOP("mean of the passes"), thetas, mean, GREEN, width=3))
    return PlotFigure(QT_TR_NOOP("Corrected error of each pass (pass number, direction)"),
                      "θ (°)", QT_TR_NOOP("error (\")"), tuple(series))
