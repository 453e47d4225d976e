"""The polygon encoder test's view: the shared readings and set-up, the error over the
circle, the vertical readings with the tilt model, the harmonics, the simulation
panel and the button that loads the polygon's certificate. Widgets only."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtWidgets import QMessageBox, QPushButton, QVBoxLayout, QWidget

from models.polygon import TITLE
from widgets.error_plot import ErrorPlot
from widgets.figure_plot import FigurePlot, FigureRenderer
from widgets.i18n import declared, live, on_language_change, tr
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.open_file import ask_open_file
from widgets.plot_grid import IntegerAxis, show_grid
from widgets.polygon.simulation import PolygonSimulation
from widgets.reference_notice import ReferenceNotice
from widgets.workbench_view import WorkbenchView


class TiltPlot(QWidget):
    """Vertical autocollimator readings with the fitted tilt model (the declared figure,
    drawn by a :class:`FigureRenderer`)."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox())
        self.left_label = "AC vertical − zero (\")"  # English: shown in the window's language
        show_grid(self.plot)
        self.plot.getAxis("left").enableAutoSIPrefix(False)
        self.plot.addLegend(offset=(-10, 10))
        self.renderer = FigureRenderer(self.plot, titles=False)
        self._relabel()
        on_language_change(self, self._relabel)
        layout = QVBoxLayout(self)
        layout.addWidget(self.plot)

    readings = property(lambda self: self.renderer.curve(0))  # for tests (getData())
    model = property(lambda self: self.renderer.curve(1))

    def _relabel(self) -> None:
        self.plot.setLabel("left", declared(self.left_label))
        self.plot.setLabel("bottom", declared("θ (deg)"))

    def show_figure(self, figure) -> None:
        if figure is not None:
            self.left_label = figure.y_label
            self.plot.setLabel("left", declared(figure.y_label))
        self.renderer.show(figure)


class HarmonicBars(QWidget):
    """Amplitude of each harmonic of the corrected error over the circle (the declared
    figure, drawn as bars by a :class:`FigureRenderer`)."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox(),
                                 axisItems={"bottom": IntegerAxis("bottom")})
        self.left_label = "amplitude (\")"  # English: shown in the window's language
        self._relabel()
        on_language_change(self, self._relabel)
        show_grid(self.plot, x=False)
        self.plot.getAxis("left").enableAutoSIPrefix(False)
        self.renderer = FigureRenderer(self.plot, titles=False, bars=True, bar_width=0.6)
        layout = QVBoxLayout(self)
        layout.addWidget(self.plot)

    bars = property(lambda self: self.renderer.curve(0))  # for tests (opts)

    def _relabel(self) -> None:
        self.plot.setLabel("left", declared(self.left_label))
        self.plot.setLabel("bottom", tr("harmonic order (1 = eccentricity, 2 = ellipticity)"))

    def show_figure(self, figure) -> None:
        self.left_label = figure.y_label
        self.plot.setLabel("left", declared(figure.y_label))
        self.renderer.show(figure)

    def clear(self) -> None:
        self.renderer.clear()


class PolygonView(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__(TITLE, parent)
        self.error_plot = ErrorPlot(x_label="θ face angle (°)",
                                    residual_label="tilt fit res. (\")")
        self.tilt_plot = TiltPlot()
        self.harmonics = HarmonicBars()
        self.sets_plot = FigurePlot()  # each set beside the mean, the set in progress, ±T
        self.simulation = PolygonSimulation()
        # a sent reference (a cross-calibration's face deviations) gone stale: said under
        # the result's warnings, where the technician looks (not the set-up's last row)
        self.reference_notice = ReferenceNotice()
        self.certificate_button = QPushButton()
        live(self.certificate_button.setText, tr("Load polygon certificate…"))
        live(self.certificate_button.setToolTip, tr("Fill the deviation column from a CSV/XLSX "
                                                    "with position,deviation_arcsec, or from "
                                                    "the polygon's digital calibration "
                                                    "certificate (DCC, .xml)"))
        self.add_plot_tab(self.error_plot, tr("Error over the circle"))
        self.add_plot_tab(self.sets_plot, tr("Each set"))
        self.add_plot_tab(self.tilt_plot, tr("Vertical readings / tilt"))
        self.add_plot_tab(self.harmonics, tr("Harmonics"))
        self.add_plot_tab(self.simulation, tr("What-if: set-up errors"))

    def subscribe(self, presenter) -> None:
        super().subscribe(presenter)
        self.settings.layout().addRow(self.certificate_button)
        self.add_result_notice(self.reference_notice)
        self.certificate_button.clicked.connect(presenter.load_certificate_dialog)

    def show_figures(self, errors, residuals, tilt, harmonics, sets=None) -> None:
        """The declared figures (models/polygon/plots.py); ``None`` leaves a plot empty."""
        self.error_plot.show_figure(errors, residuals)
        if sets is None:
            self.sets_plot.clear()
        else:
            self.sets_plot.show_figure(sets)
        self.tilt_plot.show_figure(tilt)
        self.harmonics.show_figure(harmonics)

    def show_faces_read(self, figure) -> None:
        """The faces of set 1 read so far (no result yet): their raw error on the error
        plot and beside the sets (models/polygon/plots.faces_read_figure)."""
        self.error_plot.show_figure(figure)
        self.sets_plot.show_figure(figure)

    def clear_result(self) -> None:
        self.error_plot.clear()
        self.sets_plot.clear()
        self.tilt_plot.show_figure(None)
        self.harmonics.clear()

    def ask_certificate_file(self) -> str:
        return ask_open_file(self, tr("Polygon calibration certificate"), "",
                             tr("Deviations (*.csv *.txt *.xlsx);;Digital "
                                "calibration certificate (*.xml);;All files (*)"))

    def tell(self, title: str, text: str) -> None:
        QMessageBox.warning(self, title, text)
