"""The theodolite run's plots, declared once for the window and the certificate."""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP
from models.plots import PlotFigure, PlotSeries
from models.theodolite.model import TheodoliteResult

__all__ = ["corrected_with_uncertainty", "error_figure", "residual_figure"]

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
