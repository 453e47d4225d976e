"""Simulation panel of the polygon workbench (the seed's Figs 3–6): the induced
horizontal error ε_x over the circle for a family of tilt directions or sizes."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QHBoxLayout, QLineEdit, QVBoxLayout, QWidget

from models.polygon import pyramidal_readings_arcsec
from widgets.settings_form import SettingsForm


class PolygonSimulation(QWidget):
    """``x_curves`` / ``y_curves``: ε_x and ε_y for each swept value (created once)."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._setup_ui()
        self._layout()
        self.update_curves()

    def _setup_ui(self) -> None:
        self.form = SettingsForm()
        self.form.add_float("psi_arcsec", "tilt ψ", 0, 7200, 1, "\"", 30)
        self.form.add_float("omega_deg", "direction ω", 0, 360, 1, "°", 15)
        self.form.add_choice("sweep", "sweep", [("omega_deg", "direction ω (Fig 3)"),
                                                ("psi_arcsec", "tilt ψ (Fig 4)")])
        self.form.set_values({"psi_arcsec": 300, "omega_deg": 90})
        self.sweep_values = QLineEdit("0, 45, 90, 135, 180")
        self.sweep_values.setToolTip("Values of the swept parameter, separated by commas")
        self.form.layout().addRow("sweep values", self.sweep_values)
        self.form.changed.connect(self.update_curves)
        self.sweep_values.editingFinished.connect(self.update_curves)
        self.x_plot = pg.PlotWidget(background="w")
        self.x_plot.setLabel("left", "ε_x induced error (\")")
        self.y_plot = pg.PlotWidget(background="w")
        self.y_plot.setLabel("left", "ε_y vertical (\")")
        for plot in (self.x_plot, self.y_plot):
            plot.setLabel("bottom", "θ (deg)")
            plot.showGrid(x=True, y=True, alpha=0.25)
            plot.getAxis("left").enableAutoSIPrefix(False)
            plot.addLegend(offset=(-10, 10))
        self.x_curves: list[pg.PlotDataItem] = []
        self.y_curves: list[pg.PlotDataItem] = []

    def _layout(self) -> None:
        plots = QVBoxLayout()
        plots.addWidget(self.x_plot)
        plots.addWidget(self.y_plot)
        layout = QHBoxLayout(self)
        layout.addWidget(self.form)
        layout.addLayout(plots, 1)

    def _values(self) -> list[float]:
        out = []
        for part in self.sweep_values.text().replace(";", ",").split(","):
            try:
                out.append(float(part))
            except ValueError:
                continue
        return out[:12]

    def update_curves(self) -> None:
        params = self.form.values()
        sweep = params["sweep"]
        values = self._values() or [params[sweep]]
        theta = np.linspace(0.0, 360.0, 361)
        while len(self.x_curves) < len(values):
            pen = pg.mkPen(pg.intColor(len(self.x_curves), hues=9), width=2)
            self.x_curves.append(self.x_plot.plot(pen=pen, name=" "))
            self.y_curves.append(self.y_plot.plot(pen=pen, name=" "))
        unit = "\"" if sweep == "psi_arcsec" else "°"
        for i, (xc, yc) in enumerate(zip(self.x_curves, self.y_curves, strict=True)):
            if i >= len(values):
                xc.setData([], [])
                yc.setData([], [])
                continue
            p = dict(params)
            p[sweep] = values[i]
            ex, ey = pyramidal_readings_arcsec(theta, p["psi_arcsec"], p["omega_deg"])
            xc.setData(theta, ex)
            yc.setData(theta, ey)
            name = f"{'ψ' if sweep == 'psi_arcsec' else 'ω'} = {values[i]:g}{unit}"
            for plot, curve in ((self.x_plot, xc), (self.y_plot, yc)):
                label = plot.getPlotItem().legend.getLabel(curve)
                if label is not None:
                    label.setText(name)
