"""The cross-calibration's plots, declared once for the window and the certificate."""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries

__all__ = ["closure_figure", "encoder_figure", "polygon_figure", "residual_figure"]

BLUE, ORANGE, GREEN, GREY, RED = ((31, 119, 180), (255, 127, 14), (44, 160, 44),
                                  (130, 130, 130), (192, 57, 43))


def _or_nan(values, n: int) -> np.ndarray:
    return np.full(n, np.nan) if values is None else np.asarray(values, dtype=float)


def encoder_figure(result) -> PlotFigure | None:
    s = result.solution
    if s.encoder_error_arcsec is None:
        return None
    return PlotFigure(QT_TR_NOOP("Encoder error at its steps with U"), QT_TR_NOOP("encoder step (°)"),
                      QT_TR_NOOP("error (\")"), (
        PlotSeries(QT_TR_NOOP("encoder error ± U"), result.step_deg, s.encoder_error_arcsec, BLUE,
                   True, band=result.expanded_u_arcsec[0], role="corrected"),))


def polygon_figure(result) -> PlotFigure | None:
    s = result.solution
    if s.polygon_deviation_arcsec is None:
        return None
    faces = np.arange(1, result.faces + 1, dtype=float)
    return PlotFigure(QT_TR_NOOP("Polygon face deviations with U"), QT_TR_NOOP("face"),
                      QT_TR_NOOP("deviation (\")"), (
        PlotSeries(QT_TR_NOOP("face deviation ± U"), faces, s.polygon_deviation_arcsec, GREEN, True,
                   band=result.expanded_u_arcsec[1], role="corrected"),))


def residual_figure(result) -> PlotFigure:
    """The residual map: each mounting's residuals over the faces (one line each), the
    outliers marked."""
    r, s = result.readings, result.solution
    series = []
    for q, j in enumerate(r.mountings):
        rows = np.flatnonzero((r.mounting == j) & ~r.closure)
        order = rows[np.argsort(r.position[rows])]
        series.append(PlotSeries(QT_TR_NOOP("residual per mounting") if q == 0 else "",
                                 r.position[order].astype(float), s.residuals_arcsec[order],
                                 GREY, True))
    for q, i in enumerate(result.outliers):
        series.append(PlotSeries(QT_TR_NOOP("outlier (> 3σ)") if q == 0 else "",
                                 np.array([float(r.position[i])]),
                                 np.array([s.residuals_arcsec[i]]), RED, True))
    return PlotFigure(QT_TR_NOOP("Residuals per mounting and face"), QT_TR_NOOP("face"),
                      QT_TR_NOOP("residual (\")"), tuple(series))


def closure_figure(result) -> PlotFigure:
    mountings = np.asarray(result.readings.mountings, dtype=float)
    series = [PlotSeries(QT_TR_NOOP("closure (x′ − x) − (a′ − a)"), mountings,
                         _or_nan(result.closure_arcsec, mountings.size), ORANGE, True)]
    drift = result.solution.drift_arcsec
    if np.any(np.isfinite(drift)):
        series.append(PlotSeries(QT_TR_NOOP("drift fitted"), mountings, drift, BLUE, True,
                                 dashed=True))
    return PlotFigure(QT_TR_NOOP("Closure per mounting"), QT_TR_NOOP("mounting"),
                      QT_TR_NOOP("closure (\")"), tuple(series))
