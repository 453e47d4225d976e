"""The theodolite run's view: the shared readings and set-up, the error curves and the
simulation panel. Widgets only; the presenter calls ``show_curves`` and ``clear_result``."""

from __future__ import annotations

from widgets.error_plot import ErrorPlot
from widgets.theodolite.simulation import TheodoliteSimulation
from widgets.workbench_view import WorkbenchView


class TheodoliteView(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__("Theodolite run", parent)
        self.error_plot = ErrorPlot(residual_label="E residual (\")")
        self.error_plot.set_curve_names("raw error θ − A", "set-up share −ζ(θ)",
                                        "corrected = raw + ζ")
        self.simulation = TheodoliteSimulation()
        self.add_plot_tab(self.error_plot, "Error curves")
        self.add_plot_tab(self.simulation, "Simulation (Figs 3–6)")

    def show_curves(self, theta, raw, model, corrected, residual) -> None:
        self.error_plot.set_curves(theta, raw, model, corrected)
        self.error_plot.set_residuals(theta, residual)

    def clear_result(self) -> None:
        self.error_plot.clear()
