"""The polygon test's plots, declared once for the window and the certificate."""

from __future__ import annotations

import math

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries
from models.polygon.model import PolygonResult, frame_readings_arcsec

__all__ = ["corrected_with_uncertainty", "error_figure", "harmonics_figure", "residual_figure",
           "tilt_figure"]

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
    frame = (result.ac_alignment, math.radians(result.ac_roll_measured_arcmin / 60.0)
             if result.roll_corrected else 0.0)  # the readings the tilt was fitted with
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
