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

    def show_result(self, result: TheodoliteResult) -> None:
        order = np.argsort(result.theta_deg, kind="stable")
        x = result.theta_deg[order]
        self.error_plot.set_curves(x, result.raw_error_arcsec[order],
                                   result.model_error_arcsec[order],
                                   result.corrected_error_arcsec[order])
        self.error_plot.set_residuals(x, result.elevation_residuals_arcsec[order])

    def clear_result(self) -> None:
        self.error_plot.clear()
