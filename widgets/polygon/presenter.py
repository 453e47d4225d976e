"""Polygon encoder test workbench: set-up fields, error/tilt/harmonic plots, presenter."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QFileDialog, QMessageBox, QPushButton, QVBoxLayout, QWidget

from models.polygon.analysis import POLYGON
from models.polygon.certificate_reader import read_polygon_certificate
from models.polygon.model import PolygonResult
from models.polygon.model import pyramidal_readings_arcsec as pyramidal_readings
from models.readings.tabular_import import TableImportError
from widgets.error_plot import ErrorPlot
from widgets.polygon.simulation import PolygonSimulation
from widgets.workbench_presenter import WorkbenchPresenter
from widgets.workbench_view import WorkbenchView


class TiltPlot(QWidget):
    """Vertical autocollimator readings with the fitted tilt model."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w")
        self.plot.setLabel("left", "AC vertical − zero (\")")
        self.plot.setLabel("bottom", "θ (deg)")
        self.plot.showGrid(x=True, y=True, alpha=0.25)
        self.plot.getAxis("left").enableAutoSIPrefix(False)
        self.plot.addLegend(offset=(-10, 10))
        self.readings = self.plot.plot(name="readings", pen=None, symbol="o", symbolSize=7,
                                       symbolBrush="#c0392b")
        self.model = self.plot.plot(name="tilt model ε_y", pen=pg.mkPen("#1f5fbf", width=2))
        layout = QVBoxLayout(self)
        layout.addWidget(self.plot)


class HarmonicBars(QWidget):
    """Amplitude of each harmonic of the corrected error over the circle."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w")
        self.plot.setLabel("left", "amplitude (\")")
        self.plot.setLabel("bottom", "harmonic order (1 = eccentricity, 2 = ellipticity)")
        self.plot.showGrid(y=True, alpha=0.25)
        self.plot.getAxis("left").enableAutoSIPrefix(False)
        self.bars = pg.BarGraphItem(x=[], height=[], width=0.6, brush="#1f5fbf")
        self.plot.addItem(self.bars)
        layout = QVBoxLayout(self)
        layout.addWidget(self.plot)

    def set_spectrum(self, order, amplitude) -> None:
        self.bars.setOpts(x=np.asarray(order[1:]), height=np.asarray(amplitude[1:]), width=0.6)


class PolygonPresenter(WorkbenchPresenter):
    """Error per face, closure check and pyramidal correction on every edit."""

    def __init__(self, parent=None) -> None:
        view = WorkbenchView(POLYGON.title)
        self.error_plot = ErrorPlot(x_label="θ face angle (deg)", residual_label="tilt fit res. (\")")
        self.error_plot.set_curve_names("raw error e", "correction −(ε_x − ε_x,zero)",
                                        "corrected e − (ε_x − ε_x,zero)")
        self.tilt_plot = TiltPlot()
        self.harmonics = HarmonicBars()
        self.simulation = PolygonSimulation()
        self.certificate_button = QPushButton("Load polygon certificate…")
        self.certificate_button.setToolTip("Fill the deviation column from a CSV/XLSX with "
                                           "position,deviation_arcsec")
        view.add_plot_tab(self.error_plot, "Error over the circle")
        view.add_plot_tab(self.tilt_plot, "Vertical readings / tilt")
        view.add_plot_tab(self.harmonics, "Harmonics")
        view.add_plot_tab(self.simulation, "Simulation (Figs 3–6)")
        super().__init__(POLYGON, view, parent)
        view.settings.layout().addRow(self.certificate_button)
        self.certificate_button.clicked.connect(self.load_certificate_dialog)

    def show_result(self, result: PolygonResult) -> None:
        first = result.sets[0]
        self.table_model.set_highlight_rows(result.closure_rows)
        x = result.theta_deg
        self.error_plot.set_curves(x, result.mean_error_arcsec,
                                   -np.mean([r.pyramidal_error_arcsec for r in result.sets], axis=0),
                                   result.mean_corrected_arcsec)
        if first.tilt is not None:
            self.error_plot.set_residuals(x, first.tilt.residuals_arcsec)
            dense = np.linspace(0, 360, 361)  # face angle; the model runs in the counting sense
            _, ey = pyramidal_readings(result.counting * dense, first.tilt.psi_arcsec,
                                       first.tilt.omega_deg)
            _, ey_faces = pyramidal_readings(first.theta_deg, first.tilt.psi_arcsec,
                                             first.tilt.omega_deg)
            self.tilt_plot.readings.setData(x, ey_faces + first.tilt.residuals_arcsec)
            self.tilt_plot.model.setData(dense, ey)
        else:
            self.error_plot.set_residuals(x, None)
            self.tilt_plot.readings.setData([], [])
            self.tilt_plot.model.setData([], [])
        self.harmonics.set_spectrum(result.harmonics.order, result.harmonics.amplitude)
        if not result.valid:
            self.view.set_readings_caption(self.view.readings_label.text() +
                                           " — RUN INVALID (closure failed)")

    def load_certificate_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self.view, "Polygon calibration certificate", "",
                                              "Deviations (*.csv *.txt *.xlsx);;All files (*)")
        if path:
            try:
                self.load_certificate(path)
            except TableImportError as exc:
                QMessageBox.warning(self.view, "Cannot read certificate", str(exc))

    def load_certificate(self, path: str) -> int:
        """Fill the deviation column by position (one undo step); returns the cells changed.

        Raises TableImportError for a bad file and when a position has no deviation.
        """
        deviations = read_polygon_certificate(path)
        column = self.sheet.column_index("polygon_dev_arcsec")
        position_column = self.sheet.column_index("position")
        changes = []
        for row in range(self.sheet.row_count):
            text = self.sheet.text(row, position_column).strip()
            if not text:
                continue
            try:
                position = int(float(text))
            except ValueError:
                continue
            if position not in deviations:
                raise TableImportError(f"{path}: no deviation for position {position} "
                                       f"(row {row + 1} of the readings)")
            changes.append((row, column, f"{deviations[position]:g}"))
        self.table_model.set_cells(changes, "Load polygon certificate")
        return len(changes)

    def clear_result(self) -> None:
        self.table_model.set_highlight_rows(set())
        self.error_plot.clear()
        self.tilt_plot.readings.setData([], [])
        self.tilt_plot.model.setData([], [])
        self.harmonics.set_spectrum([0], [0])
