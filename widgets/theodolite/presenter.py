"""Theodolite run workbench: view fields, plots and the presenter that fills them."""

from __future__ import annotations

import numpy as np

from models.theodolite.analysis import THEODOLITE
from models.theodolite.model import TheodoliteResult
from widgets.error_plot import ErrorPlot
from widgets.theodolite.simulation import TheodoliteSimulation
from widgets.workbench_presenter import WorkbenchPresenter
from widgets.workbench_view import WorkbenchView


class TheodolitePresenter(WorkbenchPresenter):
    """Runs the set-up identification on every edit and draws raw, model and corrected error."""

    def __init__(self, parent=None) -> None:
        view = WorkbenchView(THEODOLITE.title)
        self.error_plot = ErrorPlot(residual_label="E residual (\")")
        self.error_plot.set_curve_names("raw error θ − A", "set-up share −ζ(θ)",
                                        "corrected = raw + ζ")
        self.simulation = TheodoliteSimulation()
        view.add_plot_tab(self.error_plot, "Error curves")
        view.add_plot_tab(self.simulation, "Simulation (Figs 3–6)")
        super().__init__(THEODOLITE, view, parent)

    def build_settings(self) -> None:
        form = self.view.settings
        form.add_int("reference_row", "reference row", 0, 100000, special="auto (θ nearest 0)",
                     tooltip="Row where the theodolite was zeroed on the mirror")
        form.add_choice("vertical_reading", "vertical reading",
                        [("elevation", "elevation E"), ("zenith", "zenith angle V (E = V − 90°)")])
        form.add_choice("method", "identify from",
                        [("elevation", "elevations (recommended)"),
                         ("azimuth", "azimuth errors (absorbs axis error!)")])
        form.add_float("psi_max_deg", "bound |ψ| ≤", 0.1, 89.0, 1, "°", 5.0)
        form.add_float("beta_max_deg", "bound |β| ≤", 0.1, 89.0, 1, "°", 5.0)
        form.add_float("accuracy_arcsec", "theodolite accuracy (1σ)", 0.0, 100.0, 2, "\"", 0.1)

    def show_result(self, result: TheodoliteResult) -> None:
        order = np.argsort(result.theta_deg, kind="stable")
        x = result.theta_deg[order]
        self.error_plot.set_curves(x, result.raw_error_arcsec[order],
                                   result.model_error_arcsec[order],
                                   result.corrected_error_arcsec[order])
        self.error_plot.set_residuals(x, result.elevation_residuals_arcsec[order])

    def clear_result(self) -> None:
        self.error_plot.clear()
