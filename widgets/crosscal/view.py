"""The cross-calibration's view: the shared readings and set-up, the encoder's error and
the polygon's deviations with their U bands, the residual map and the closures, and the
button that saves the face deviations for the polygon workbench. Widgets only."""

from __future__ import annotations

from PySide6.QtWidgets import QMessageBox, QPushButton

from widgets.figure_plot import FigurePlot
from widgets.i18n import live, tr
from widgets.save_file import ask_save_file
from widgets.workbench_view import WorkbenchView


class CrossCalView(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__("Cross-calibration (polygon + encoder)", parent)
        self.encoder_plot = FigurePlot()
        self.polygon_plot = FigurePlot()
        self.residual_plot = FigurePlot()
        self.closure_plot = FigurePlot()
        self.reference_button = QPushButton()
        live(self.reference_button.setText, tr("Save face deviations for the polygon workbench…"))
        live(self.reference_button.setToolTip, tr(
            "The polygon's face deviations from face 1 with their U, as a file the polygon "
            "workbench loads with 'Load polygon certificate…'"))
        self.reference_button.setEnabled(False)
        self.add_plot_tab(self.encoder_plot, tr("Encoder error"))
        self.add_plot_tab(self.polygon_plot, tr("Face deviations"))
        self.add_plot_tab(self.residual_plot, tr("Residuals"))
        self.add_plot_tab(self.closure_plot, tr("Closure"))

    def subscribe(self, presenter) -> None:
        super().subscribe(presenter)
        self.settings.layout().addRow(self.reference_button)
        self.reference_button.clicked.connect(presenter.save_polygon_reference_dialog)

    def show_figures(self, encoder, polygon, residuals, closure) -> None:
        """The declared figures (models/crosscal/plots.py); ``None`` leaves a plot empty."""
        self.encoder_plot.show_figure(encoder)
        self.polygon_plot.show_figure(polygon)
        self.residual_plot.show_figure(residuals)
        self.closure_plot.show_figure(closure)

    def clear_result(self) -> None:
        for plot in (self.encoder_plot, self.polygon_plot, self.residual_plot, self.closure_plot):
            plot.clear()

    def set_reference_enabled(self, enabled: bool) -> None:
        self.reference_button.setEnabled(enabled)

    def ask_reference_path(self) -> str:
        return ask_save_file(self, tr("Save face deviations"), "polygon_deviations.csv",
                             tr("CSV (*.csv)"))

    def tell(self, title: str, text: str) -> None:
        QMessageBox.warning(self, title, text)
