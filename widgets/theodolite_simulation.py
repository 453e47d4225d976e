"""Simulation panel of the theodolite workbench (the seed's Figs 3–6).

Set ψ, α, β and a range of θ; sweep one parameter over a list of values to
see the family of induced-error ζ(θ) and elevation E(θ) curves.
"""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QHBoxLayout, QLineEdit, QVBoxLayout, QWidget

from models.theodolite import forward_readings, induced_error_arcsec
from widgets.settings_form import SettingsForm

SWEEPS = {"beta_deg": "β", "alpha_deg": "α", "psi_deg": "ψ"}


class TheodoliteSimulation(QWidget):
    """``zeta_curves`` and ``elevation_curves`` hold the PlotDataItems of the family."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._setup_ui()
        self._layout()
        self.update_curves()

    def _setup_ui(self) -> None:
        self.form = SettingsForm()
        self.form.add_float("psi_deg", "axis tilt ψ", -10, 10, 4, "°", 0.5)
        self.form.add_float("alpha_deg", "tilt direction α", 0, 360, 3, "°", 15)
        self.form.add_float("beta_deg", "mirror normal β", -10, 10, 4, "°", 0.5)
        self.form.add_float("half_range_deg", "θ range ±", 1, 180, 1, "°", 5)
        self.form.add_choice("sweep", "sweep", [(k, v) for k, v in SWEEPS.items()])
        self.form.set_values({"psi_deg": 3, "alpha_deg": 45, "beta_deg": 2, "half_range_deg": 20})
        self.sweep_values = QLineEdit("-2, -1, 0, 1, 2")
        self.sweep_values.setToolTip("Values of the swept parameter (deg), separated by commas")
        self.form.layout().addRow("sweep values (°)", self.sweep_values)
        self.form.changed.connect(self.update_curves)
        self.sweep_values.editingFinished.connect(self.update_curves)
        self.zeta_plot = pg.PlotWidget(background="w")
        self.zeta_plot.setLabel("left", "ζ (\")")
        self.elevation_plot = pg.PlotWidget(background="w")
        self.elevation_plot.setLabel("left", "E (deg)")
        for plot in (self.zeta_plot, self.elevation_plot):
            plot.setLabel("bottom", "θ (deg)")
            plot.showGrid(x=True, y=True, alpha=0.25)
            plot.getAxis("left").enableAutoSIPrefix(False)
            plot.addLegend(offset=(10, 10))
        self.zeta_curves: list[pg.PlotDataItem] = []
        self.elevation_curves: list[pg.PlotDataItem] = []

    def _layout(self) -> None:
        plots = QVBoxLayout()
        plots.addWidget(self.zeta_plot)
        plots.addWidget(self.elevation_plot)
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
        theta = np.linspace(-params["half_range_deg"], params["half_range_deg"], 241)
        while len(self.zeta_curves) < len(values):  # created once, reused
            color = pg.intColor(len(self.zeta_curves), hues=9)
            self.zeta_curves.append(self.zeta_plot.plot(pen=pg.mkPen(color, width=2), name=" "))
            self.elevation_curves.append(
                self.elevation_plot.plot(pen=pg.mkPen(color, width=2), name=" "))
        for i, (zc, ec) in enumerate(zip(self.zeta_curves, self.elevation_curves, strict=True)):
            if i >= len(values):
                zc.setData([], [])
                ec.setData([], [])
                continue
            p = dict(params)
            p[sweep] = values[i]
            args = (p["psi_deg"], p["alpha_deg"], p["beta_deg"])
            zc.setData(theta, induced_error_arcsec(theta, *args))
            ec.setData(theta, forward_readings(theta, *args)[1])
            name = f"{SWEEPS[sweep]} = {values[i]:g}°"
            for plot, curve in ((self.zeta_plot, zc), (self.elevation_plot, ec)):
                label = plot.getPlotItem().legend.getLabel(curve)
                if label is not None:
                    label.setText(name)
