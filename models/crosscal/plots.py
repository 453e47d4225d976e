"""The cross-calibration's plots, declared once for the window and the certificate."""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries

__all__ = ["closure_figure", "encoder_figure", "in_progress_errors", "polygon_figure",
           "residual_figure"]

BLUE, ORANGE, GREEN, GREY, RED = ((31, 119, 180), (255, 127, 14), (44, 160, 44),
                                  (130, 130, 130), (192, 57, 43))


def _or_nan(values, n: int) -> np.ndarray:
    return np.full(n, np.nan) if values is None else np.asarray(values, dtype=float)


def in_progress_errors(parsed, result) -> tuple[np.ndarray, np.ndarray]:
    """The mounting in progress (result.incomplete) as taken: at each of its readings the
    reading the model sees, y = (a − a_start − k·360°/n)·3600 − c, less the complete
    mountings' face deviation d_i, offset so its first reading sits on the encoder error
    at that step (the mounting's own offset is not known until it is complete). (encoder
    step in °, error in ″); empty arrays when no mounting is in progress, when the complete
    mountings do not determine E and d, or when a reading's face or step is not the
    polygon's. The readings as written: no tilt correction, no drift."""
    unit = getattr(result, "incomplete", None)
    s = result.solution
    if (unit is None or parsed is None or not unit.rows or s.encoder_error_arcsec is None
            or s.polygon_deviation_arcsec is None):
        return np.empty(0), np.empty(0)
    n = result.faces
    step = 360.0 / n
    start = result.encoder_start_deg
    steps, values = [], []
    for i in unit.rows:
        if i >= parsed.n:
            continue
        face, mounting = parsed["position"][i], parsed["mounting"][i]
        a, c = float(parsed["encoder_deg"][i]), float(parsed["ac_x_arcsec"][i])
        if not (np.isfinite(face) and np.isfinite(mounting) and np.isfinite(a)
                and np.isfinite(c)) or not 1 <= int(face) <= n:
            continue
        k = (int(face) - 1 - int(mounting)) % n
        y = ((a - start - k * step + 180.0) % 360.0 - 180.0) * 3600.0 - c
        steps.append(k)
        values.append(y - s.polygon_deviation_arcsec[int(face) - 1])
    if not steps:
        return np.empty(0), np.empty(0)
    k = np.asarray(steps, dtype=int)
    v = np.asarray(values, dtype=float)
    return result.step_deg[k], v - v[0] + s.encoder_error_arcsec[k[0]]


def _band(result, item: int, u) -> np.ndarray:
    """The ±U band of item ``item`` (0: E, 1: d): ``u`` when given (the certificate's U, its
    details in: models.crosscal.analysis CrossCal.uncertainty_budgets), else the readings' own
    (result.expanded_u_arcsec, no certificate details)."""
    return np.asarray(result.expanded_u_arcsec[item] if u is None else u, dtype=float)


def encoder_figure(result, parsed=None, u=None) -> PlotFigure | None:
    """The encoder's error with U (``u``: the U its certificate states, :func:`_band`); with
    ``parsed`` (the readings given the analysis), the mounting in progress as taken beside it
    (grey markers: in_progress_errors)."""
    s = result.solution
    if s.encoder_error_arcsec is None:
        return None
    if result.encoder_u_withheld is not None:  # no closure reading, no drift bound: no band
        series = [PlotSeries(QT_TR_NOOP("encoder error (U withheld: drift not measured)"),
                             result.step_deg, s.encoder_error_arcsec, BLUE, True,
                             role="corrected")]
    else:
        series = [PlotSeries(QT_TR_NOOP("encoder error ± U"), result.step_deg,
                             s.encoder_error_arcsec, BLUE, True, band=_band(result, 0, u),
                             role="corrected")]
    x, y = in_progress_errors(parsed, result)
    if x.size:
        series.append(PlotSeries(QT_TR_NOOP("mounting in progress (as taken)"), x, y, GREY, True,
                                 width=0, marker_size=8))
    return PlotFigure(QT_TR_NOOP("Encoder error at its steps with U"), QT_TR_NOOP("encoder step (°)"),
                      QT_TR_NOOP("error (\")"), tuple(series))


def polygon_figure(result, u=None) -> PlotFigure | None:
    """The face deviations with U (``u``: the U their certificate states, :func:`_band`)."""
    s = result.solution
    if s.polygon_deviation_arcsec is None:
        return None
    faces = np.arange(1, result.faces + 1, dtype=float)
    if result.polygon_u_withheld is not None:  # no closure reading, no drift bound: no band
        series = PlotSeries(QT_TR_NOOP("face deviation (U withheld: drift not measured)"), faces,
                            s.polygon_deviation_arcsec, GREEN, True, role="corrected")
    else:
        series = PlotSeries(QT_TR_NOOP("face deviation ± U"), faces, s.polygon_deviation_arcsec,
                            GREEN, True, band=_band(result, 1, u), role="corrected")
    return PlotFigure(QT_TR_NOOP("Polygon face deviations with U"), QT_TR_NOOP("face"),
                      QT_TR_NOOP("deviation (\")"), (series,))


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
        series.append(PlotSeries(QT_TR_NOOP("outlier") if q == 0 else "",
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
