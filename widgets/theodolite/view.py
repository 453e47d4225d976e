"""The theodolite run's view: the shared readings and set-up, the error curves and the
simulation panel. Widgets only; the presenter calls ``show_curves`` and ``clear_result``."""

from __future__ import annotations

from models.theodolite import TITLE
from widgets.error_plot import ErrorPlot
from widgets.figure_plot import FigurePlot
from widgets.i18n import tr
from widgets.theodolite.simulation import TheodoliteSimulation
from widgets.workbench_view import WorkbenchView


class TheodoliteView(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__(TITLE, parent)
        self.error_plot = ErrorPlot(residual_label="E residual (\")")
        self.simulation = TheodoliteSimulation()
        self.passes_plot = FigurePlot()  # each pass beside the mean (runs in the readings)
        self.add_plot_tab(self.error_plot, tr("Error curves"))
        self.add_plot_tab(self.passes_plot, tr("Each pass"))
        self.add_plot_tab(self.simulation, tr("What-if: set-up errors"))

    def show_figures(self, errors, residuals, passes=None) -> None:
        """The declared figures (models/theodolite/plots.py); ``passes`` None: one pass."""
        self.error_plot.show_figure(errors, residuals)
        if passes is None:
            self.passes_plot.clear()
        else:
            self.passes_plot.show_figure(passes)

    def clear_result(self) -> None:
        self.error_plot.clear()
        self.passes_plot.clear()
