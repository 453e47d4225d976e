"""The polygon test's plots, declared once for the window and the certificate."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries
from models.polygon.model import (
    PolygonResult,
    counting_residuals_deg,
    face_errors_arcsec,
    frame_readings_arcsec,
    split_sets,
)

__all__ = ["corrected_with_uncertainty", "error_figure", "faces_read_figure", "harmonics_figure",
           "in_progress_errors", "residual_figure", "sets_figure", "tilt_figure"]

BLUE, ORANGE, GREEN, PURPLE, RED = ((31, 119, 180), (255, 127, 14), (44, 160, 44),
                                    (148, 103, 189), (192, 57, 43))
ANGLE = QT_TR_NOOP("position angle (°)")
WINDOW_RED, WINDOW_BLUE = (192, 57, 43), (31, 95, 191)  # the tilt and harmonics plots' own


def error_figure(result: PolygonResult) -> PlotFigure:
    th = result.theta_deg
    correction = result.mean_corrected_arcsec - result.mean_error_arcsec
    return PlotFigure(QT_TR_NOOP("Raw and corrected error"), ANGLE, QT_TR_NOOP("error (\")"), (
        PlotSeries(QT_TR_NOOP("raw error e (mean)"), th, result.mean_error_arcsec, BLUE, True, role="raw"),
        PlotSeries("correction −(ε_x − ε_x,zero)", th, correction, ORANGE, role="model"),
        PlotSeries("corrected e − (ε_x − ε_x,zero)", th, result.mean_corrected_arcsec, GREEN, True,
                   role="corrected"),
    ))


def corrected_with_uncertainty(result: PolygonResult, expanded) -> PlotFigure:
    return PlotFigure(QT_TR_NOOP("Corrected error with its expanded uncertainty U"), ANGLE,
                      QT_TR_NOOP("error (\")"), (
        PlotSeries(QT_TR_NOOP("corrected ± U"), result.theta_deg, result.mean_corrected_arcsec, GREEN, True,
                   band=np.asarray(expanded), role="corrected"),))


def residual_figure(result: PolygonResult) -> PlotFigure | None:
    tilt = result.sets[0].tilt
    if tilt is None:
        return None
    return PlotFigure(QT_TR_NOOP("Tilt fit residuals (vertical readings, set 1)"), ANGLE,
                      QT_TR_NOOP("residual (\")"), (
        PlotSeries(QT_TR_NOOP("residual"), result.theta_deg, tilt.residuals_arcsec, PURPLE, True,
                   role=QT_TR_NOOP("residual")),))


def tilt_figure(result: PolygonResult) -> PlotFigure | None:
    """The vertical readings (less their zero) with the fitted tilt model, set 1."""
    first = result.sets[0]
    tilt = first.tilt
    if tilt is None:
        return None
    dense = np.linspace(0.0, 360.0, 361)  # face angle; the model runs in the counting sense
    roll = result.ac_roll_measured_arcmin  # None: not measured, not corrected
    frame = (result.ac_alignment, math.radians(roll / 60.0)
             if roll is not None else 0.0)  # the readings the tilt was fitted with
    _, model = frame_readings_arcsec(result.counting * dense, tilt.psi_arcsec, tilt.omega_deg, *frame)
    _, at_faces = frame_readings_arcsec(first.theta_deg, tilt.psi_arcsec, tilt.omega_deg, *frame)
    return PlotFigure(QT_TR_NOOP("Vertical readings and the tilt model (set 1)"), "θ (deg)",
                      "AC vertical − zero (\")", (
        PlotSeries("readings", result.theta_deg, at_faces + tilt.residuals_arcsec, WINDOW_RED, True,
                   width=0, marker_size=7),
        PlotSeries("tilt model ε_y", dense, model, WINDOW_BLUE),
    ))


def harmonics_figure(result: PolygonResult) -> PlotFigure:
    h = result.harmonics
    return PlotFigure(QT_TR_NOOP("Harmonics of the corrected error"), "harmonic order", "amplitude (\")", (
        PlotSeries("amplitude", h.order[1:].astype(float), h.amplitude[1:], WINDOW_BLUE),))


# one colour per set (dark enough to read on white), repeated past eight
SET_COLOURS = ((31, 95, 191), (192, 57, 43), (142, 68, 173), (211, 84, 0), (22, 160, 133),
               (52, 73, 94), (183, 149, 11), (199, 21, 133))
GREY = (120, 120, 120)


def in_progress_errors(parsed: Any, result: PolygonResult) -> tuple[np.ndarray, np.ndarray]:
    """The raw error of each face the set in progress has read (result.incomplete), against
    the first set's reference: set 1's raw error at that face plus the change of the
    encoder reading less the change of the autocollimator's (the polygon's face angle and
    deviation are the same face's, so they cancel). (θ in °, error in ″); empty arrays
    when no set is in progress."""
    unit = getattr(result, "incomplete", None)
    if unit is None or parsed is None or not unit.rows:
        return np.empty(0), np.empty(0)
    _, first_rows, _ = split_sets(parsed)[0]
    face_row = {int(parsed["position"][i]): int(i) for i in first_rows}
    a, x = parsed["encoder_deg"], parsed["ac_x_arcsec"]
    theta, error = [], []
    for i in unit.rows:
        if i >= parsed.n:
            continue
        face = int(parsed["position"][i])
        ref = face_row.get(face)
        if ref is None or not 1 <= face <= result.faces:
            continue
        change = float((a[i] - a[ref] + 180.0) % 360.0 - 180.0) * 3600.0 - (x[i] - x[ref])
        theta.append(result.theta_deg[face - 1])
        error.append(result.sets[0].error_arcsec[face - 1] + change)
    return np.asarray(theta, dtype=float), np.asarray(error, dtype=float)


def sets_figure(result: PolygonResult, parsed: Any = None,
                tolerance_arcsec: float | None = None) -> PlotFigure:
    """Each set's corrected error as its own curve beside their mean, the set in progress
    as taken (raw error against set 1's reference, markers only) and the tolerance ±T
    (dashed, about the mid-range of the mean) when one is given."""
    th = result.theta_deg
    series = [PlotSeries(f"{k} ({'+' if s.direction > 0 else '−'})", th,
                         s.corrected_error_arcsec, SET_COLOURS[(k - 1) % len(SET_COLOURS)], True,
                         width=1)
              for k, s in enumerate(result.sets, 1)]
    series.append(PlotSeries(QT_TR_NOOP("mean of the sets"), th, result.mean_corrected_arcsec,
                             GREEN, False, width=3))
    x, y = in_progress_errors(parsed, result)
    if x.size:
        series.append(PlotSeries(QT_TR_NOOP("set in progress (raw error)"), x, y, GREY, True,
                                 width=0, marker_size=8))
    if tolerance_arcsec:
        # about the mean error's mid-range: the curve stays inside exactly when half its
        # peak-to-peak is within ±T (the grade's rule)
        mid = 0.5 * (float(np.max(result.mean_corrected_arcsec))
                     + float(np.min(result.mean_corrected_arcsec)))
        ends = np.array([0.0, 360.0])
        series.append(PlotSeries(QT_TR_NOOP("tolerance ±T about the mid-range"), ends,
                                 np.full(2, mid + tolerance_arcsec), RED, dashed=True, width=1))
        series.append(PlotSeries("", ends, np.full(2, mid - tolerance_arcsec), RED, dashed=True,
                                 width=1))
    return PlotFigure(QT_TR_NOOP("Corrected error of each set (set number, direction)"), ANGLE,
                      QT_TR_NOOP("error (\")"), tuple(series))


def faces_read_figure(parsed: Any, settings: Any) -> PlotFigure | None:
    """While set 1 is read (no set complete: no result yet), what the faces read so far
    show, so the set-up is judged from the first faces (gui77; the plot said "No data"
    until the closure): with the number of faces known (the *faces* setting), each face's
    raw error e against the first reading of the set — the encoder's step less the face's
    nominal angle and deviation, less the autocollimator's change (eq 1, as the analysis
    takes it, the encoder counting the way the setting says or, on auto, the way the
    readings fit best); without it, the autocollimator's x reading at each encoder reading.
    None when no reading of set 1 can be read, or set 1 is no longer in progress (closed,
    or a later set begun: a result, or a reason there is none, stands for it)."""
    if parsed is None or parsed.n == 0:
        return None
    sets = split_sets(parsed)
    _, rows, closure = sets[0]
    if closure is not None or len(sets) > 1 or rows.size == 0:
        return None
    a = np.asarray(parsed["encoder_deg"], dtype=float)[rows]
    x = np.asarray(parsed["ac_x_arcsec"], dtype=float)[rows]
    faces = int(settings.get("faces", 0) or 0)
    if not faces:
        return PlotFigure(QT_TR_NOOP("Faces read so far (set 1 in progress)"),
                          QT_TR_NOOP("encoder reading a (°)"), QT_TR_NOOP("AC x (\")"), (
            PlotSeries(QT_TR_NOOP("autocollimator x (set the number of faces for the error)"),
                       a % 360.0, x, GREY, True, width=0, marker_size=8, role="raw"),))
    position = np.asarray(parsed["position"], dtype=float)[rows]
    nominal = (position - 1.0) * 360.0 / faces
    deviation = np.nan_to_num(np.asarray(parsed["polygon_dev_arcsec"], dtype=float)[rows])
    counting = {"with": 1, "against": -1}.get(str(settings.get("counting", "auto")))
    if counting is None:  # auto: the way the encoder's readings fit the faces best
        counting = min((1, -1), key=lambda c: float(np.max(np.abs(
            counting_residuals_deg(a, nominal, c)))))
    zero = (a[0], nominal[0], deviation[0], x[0])
    error = face_errors_arcsec(a, deviation, x, nominal, zero, counting)
    return PlotFigure(QT_TR_NOOP("Faces read so far (set 1 in progress)"), ANGLE,
                      QT_TR_NOOP("error (\")"), (
        PlotSeries(QT_TR_NOOP("raw error e (faces read so far)"), nominal % 360.0, error, GREY,
                   True, width=0, marker_size=8, role="raw"),))
