"""The polygon encoder test's view: the shared readings and set-up, the error over the
circle, the vertical readings with the tilt model, the harmonics, the simulation
panel and the button that loads the polygon's certificate. Widgets only."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QFileDialog, QMessageBox, QPushButton, QVBoxLayout, QWidget

from models.polygon import TITLE
from widgets.error_plot import ErrorPlot
from widgets.i18n import declared, live, on_language_change, tr
from widgets.legend_placement import place_legend
from widgets.plot_grid import IntegerAxis, show_grid
from widgets.plot_range import follow_new_data
from widgets.polygon.simulation import PolygonSimulation
from widgets.workbench_view import WorkbenchView


class TiltPlot(QWidget):
    """Vertical autocollimator readings with the fitted tilt model."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w")
        self.left_label = "AC vertical − zero (\")"  # English: shown in the window's language
        self.plot.setLabel("left", declared(self.left_label))
        self.plot.setLabel("bottom", declared("θ (deg)"))
        show_grid(self.plot)
        self.plot.getAxis("left").enableAutoSIPrefix(False)
        self.plot.addLegend(offset=(-10, 10))
        self.readings = self.plot.plot(name=declared("readings"), pen=None, symbol="o",
                                       symbolSize=7,
                                       symbolBrush="#c0392b")
        self.model = self.plot.plot(name=declared("tilt model ε_y"),
                                    pen=pg.mkPen("#1f5fbf", width=2))
        on_language_change(self, self._relabel)
        layout = QVBoxLayout(self)
        layout.addWidget(self.plot)

    def _relabel(self) -> None:
        self.plot.setLabel("left", declared(self.left_label))
        self.plot.setLabel("bottom", declared("θ (deg)"))
        legend = self.plot.getPlotItem().legend
        for curve, english in ((self.readings, "readings"), (self.model, "tilt model ε_y")):
            label = legend.getLabel(curve)
            x = curve.getData()[0]
            if label is not None and (x is None or len(x) == 0):  # drawn: named by its figure
                label.setText(declared(english))


class HarmonicBars(QWidget):
    """Amplitude of each harmonic of the corrected error over the circle."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w", axisItems={"bottom": IntegerAxis("bottom")})
        self.left_label = "amplitude (\")"  # English: shown in the window's language
        self._relabel()
        on_language_change(self, self._relabel)
        show_grid(self.plot, x=False)
        self.plot.getAxis("left").enableAutoSIPrefix(False)
        self.bars = pg.BarGraphItem(x=[], height=[], width=0.6, brush="#1f5fbf")
        self.plot.addItem(self.bars)
        layout = QVBoxLayout(self)
        layout.addWidget(self.plot)

    def _relabel(self) -> None:
        self.plot.setLabel("left", declared(self.left_label))
        self.plot.setLabel("bottom", tr("harmonic order (1 = eccentricity, 2 = ellipticity)"))

    def set_spectrum(self, order, amplitude) -> None:
        self.bars.setOpts(x=np.asarray(order[1:]), height=np.asarray(amplitude[1:]), width=0.6)


class PolygonView(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__(TITLE, parent)
        self.error_plot = ErrorPlot(x_label="θ face angle (°)",
                                    residual_label="tilt fit res. (\")")
        self.tilt_plot = TiltPlot()
        self.harmonics = HarmonicBars()
        self.simulation = PolygonSimulation()
        self.certificate_button = QPushButton()
        live(self.certificate_button.setText, tr("Load polygon certificate…"))
        live(self.certificate_button.setToolTip, tr("Fill the deviation column from a CSV/XLSX "
                                                    "with position,deviation_arcsec"))
        self.add_plot_tab(self.error_plot, tr("Error over the circle"))
        self.add_plot_tab(self.tilt_plot, tr("Vertical readings / tilt"))
        self.add_plot_tab(self.harmonics, tr("Harmonics"))
        self.add_plot_tab(self.simulation, tr("What-if: set-up errors"))

    def subscribe(self, presenter) -> None:
        super().subscribe(presenter)
        self.settings.layout().addRow(self.certificate_button)
        self.certificate_button.clicked.connect(presenter.load_certificate_dialog)

    def show_figures(self, errors, residuals, tilt, harmonics) -> None:
        """The declared figures (models/polygon/plots.py); ``None`` leaves a plot empty."""
        self.error_plot.show_figure(errors, residuals)
        readings, model = tilt.series if tilt is not None else (None, None)
        if tilt is not None:
            self.tilt_plot.left_label = tilt.y_label
            self.tilt_plot.plot.setLabel("left", declared(tilt.y_label))
        self.harmonics.left_label = harmonics.y_label
        self.harmonics.plot.setLabel("left", declared(harmonics.y_label))
        item = self.tilt_plot.plot.getPlotItem()
        for curve, series in ((self.tilt_plot.readings, readings), (self.tilt_plot.model, model)):
            label = item.legend.getLabel(curve)  # named anew: the language may have changed
            if label is not None and series is not None:
                label.setText(declared(series.label))
        self.tilt_plot.readings.setData(*((readings.x, readings.y) if readings else ([], [])))
        self.tilt_plot.model.setData(*((model.x, model.y) if model else ([], [])))
        follow_new_data(item)
        place_legend(item, item.legend)
        bars = harmonics.series[0]
        self.harmonics.bars.setOpts(x=bars.x, height=bars.y, width=0.6)
        follow_new_data(self.harmonics.plot.getPlotItem())

    def clear_result(self) -> None:
        self.error_plot.clear()
        self.tilt_plot.readings.setData([], [])
        self.tilt_plot.model.setData([], [])
        self.harmonics.set_spectrum([0], [0])

    def ask_certificate_file(self) -> str:
        path, _ = QFileDialog.getOpenFileName(self, tr("Polygon calibration certificate"), "",
                                              tr("Deviations (*.csv *.txt *.xlsx);;All files (*)"))
        return path

    def tell(self, title: str, text: str) -> None:
        QMessageBox.warning(self, title, text)
