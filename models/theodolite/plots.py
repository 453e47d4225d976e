"""The theodolite run's plots, declared once for the window and the certificate."""

from __future__ import annotations

import numpy as np

from models.plots import PlotFigure, PlotSeries
from models.theodolite.model import TheodoliteResult

__all__ = ["corrected_with_uncertainty", "error_figure", "residual_figure"]

BLUE, ORANGE, GREEN, PURPLE = (31, 119, 180), (255, 127, 14), (44, 160, 44), (148, 103, 189)


def _order(result: TheodoliteResult) -> np.ndarray:
    return np.argsort(result.theta_deg, kind="stable")


def error_figure(result: TheodoliteResult) -> PlotFigure:
    o = _order(result)
    th = result.theta_deg[o]
    return PlotFigure("Raw error, set-up model and corrected error", "θ (°)", "error (\")", (
        PlotSeries("raw error θ − A", th, result.raw_error_arcsec[o], BLUE, True, role="raw"),
        PlotSeries("set-up share −ζ(θ)", th, result.model_error_arcsec[o], ORANGE, role="model"),
        PlotSeries("corrected = raw + ζ", th, result.corrected_error_arcsec[o], GREEN, True,
                   role="corrected"),
    ))


def corrected_with_uncertainty(result: TheodoliteResult, expanded) -> PlotFigure:
    o = _order(result)
    return PlotFigure("Corrected error with its expanded uncertainty U", "θ (°)", "error (\")", (
        PlotSeries("corrected ± U", result.theta_deg[o], result.corrected_error_arcsec[o], GREEN,
                   True, band=np.asarray(expanded)[o], role="corrected"),))


def residual_figure(result: TheodoliteResult) -> PlotFigure:
    o = _order(result)
    return PlotFigure("Fit residuals (vertical readings)", "θ (°)", "E residual (\")", (
        PlotSeries("residual", result.theta_deg[o], result.elevation_residuals_arcsec[o], PURPLE,
                   True, role="residual"),))
