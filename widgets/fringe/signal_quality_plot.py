"""The fringe workbench's *Signal quality* tab: one figure of the signals (amplitude,
ratio, phase, offset, harmonic content) along the record — over the revolution — per
window of periods (models/fringe/signal_quality.py), against the chosen preset's bands:
the inside band green, the outer band amber, a window beyond them marked red. A read head
in tolerance at one place and out at another shows where."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QComboBox, QHBoxLayout, QLabel, QSizePolicy, QVBoxLayout, QWidget

from models.fringe.signal_quality import SignalQuality
from models.fringe.signal_tolerance import BUILTIN_PRESETS, TolerancePreset
from widgets.fringe.live_signals import preset_name
from widgets.i18n import live, on_language_change, tr, translated
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.plot_grid import show_grid
from widgets.plot_range import show_if_empty

__all__ = ["SignalQualityPlot"]


def _titles() -> dict[str, str]:
    return {"amplitude_a": tr("Amplitude A (sin)"), "amplitude_b": tr("Amplitude B (cos)"),
            "amplitude_ratio": tr("Ratio B/A"), "phase_deviation": tr("Phase B − A − 90°"),
            "offset_a": tr("Offset A"), "offset_b": tr("Offset B"),
            "harmonic_content": tr("Harmonic content")}


class SignalQualityPlot(QWidget):
    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.presets: list[TolerancePreset] = list(BUILTIN_PRESETS)
        #: ``compute(preset)`` gives the SignalQuality of the result shown (the presenter's)
        self.compute: Callable[[TolerancePreset | None], SignalQuality | None] = lambda _p: None
        self.quality: SignalQuality | None = None
        self.preset = QComboBox()
        self.quantity = QComboBox()
        self.preset_label, self.quantity_label = QLabel(), QLabel()
        for combo, length in ((self.preset, 16), (self.quantity, 12)):
            # they shrink with the tab instead of widening it (1280×720: the tab is ~720 px)
            combo.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
            combo.setMinimumContentsLength(length)
        self.plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox())
        show_grid(self.plot)
        self.plot.getAxis("left").enableAutoSIPrefix(False)
        self.inside = pg.LinearRegionItem(orientation="horizontal", movable=False,
                                          brush=pg.mkBrush(200, 230, 201, 160),
                                          pen=pg.mkPen("#2e7d32"))
        self.outer = pg.LinearRegionItem(orientation="horizontal", movable=False,
                                         brush=pg.mkBrush(255, 224, 178, 120),
                                         pen=pg.mkPen("#ef8f00"))
        for region in (self.outer, self.inside):
            region.setZValue(-10)
            self.plot.addItem(region)
        self.curve = self.plot.plot(pen=pg.mkPen("#1565c0", width=1.5), symbol="o",
                                    symbolSize=4, symbolBrush="#1565c0", symbolPen=None)
        self.beyond = self.plot.plot(pen=None, symbol="o", symbolSize=7, symbolBrush="#c62828",
                                     symbolPen=None)
        self.note = QLabel()
        # one line (a wrapped label would make the tab ask for its plot's preferred height and
        # scroll at 1280×720); the whole text is its tooltip
        self.note.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Fixed)
        self.note.setStyleSheet("QLabel { color: #5d4037; }")
        top = QHBoxLayout()
        top.addWidget(self.preset_label)
        top.addWidget(self.preset, 2)
        top.addWidget(self.quantity_label)
        top.addWidget(self.quantity, 1)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addLayout(top)
        layout.addWidget(self.plot, 1)
        layout.addWidget(self.note)
        live(self.preset_label.setText, tr("Tolerances"))
        live(self.quantity_label.setText, tr("Figure"))
        self._fill()
        self.preset.currentIndexChanged.connect(self.recompute)
        self.quantity.currentIndexChanged.connect(self.redraw)
        on_language_change(self, self._fill)

    def _fill(self) -> None:
        for combo in (self.preset, self.quantity):
            combo.blockSignals(True)
        key, quantity = self.preset.currentData(), self.quantity.currentData()
        self.preset.clear()
        self.preset.addItem(tr("none (the record's units)"), "")
        for p in self.presets:
            self.preset.addItem(preset_name(p), p.key)
        self.preset.setCurrentIndex(max(0, self.preset.findData(key)) if key else 1)
        self.quantity.clear()
        for q, title in _titles().items():
            self.quantity.addItem(title, q)
        self.quantity.setCurrentIndex(max(0, self.quantity.findData(quantity or "phase_deviation")))
        for combo in (self.preset, self.quantity):
            combo.blockSignals(False)
        self.redraw()

    def set_presets(self, presets: list[TolerancePreset]) -> None:
        self.presets = list(presets)
        self._fill()

    @property
    def current_preset(self) -> TolerancePreset | None:
        key = self.preset.currentData()
        return next((p for p in self.presets if p.key == key), None)

    def recompute(self, *_args) -> None:
        self.quality = self.compute(self.current_preset)
        self.redraw()

    def clear(self) -> None:
        self.quality = None
        self.redraw()

    def redraw(self, *_args) -> None:
        quantity = self.quantity.currentData() or "phase_deviation"
        quality = self.quality
        if quality is None or not quality.windows:
            self.curve.setData([], [])
            self.beyond.setData([], [])
            self.inside.hide()
            self.outer.hide()
            self.note.setText("")
            self.note.setToolTip("")
            show_if_empty(self.plot.getPlotItem())  # "No data", not an axis of no point
            return
        windows = quality.windows
        along_revolution = all("revolution_deg" in w for w in windows)
        x = np.array([w["revolution_deg"] if along_revolution else w["first_period"]
                      for w in windows], dtype=float)
        y = np.array([w.get(quantity, math.nan) for w in windows], dtype=float)
        self.curve.setData(x, y)
        states = [w.get("states", {}).get(quantity, "") for w in windows]
        bad = np.array([s in ("outer", "outside") for s in states], dtype=bool)
        self.beyond.setData(x[bad], y[bad])
        show_if_empty(self.plot.getPlotItem())  # the placeholder hidden, ranged on the data
        band = quality.preset.band(quantity) if quality.preset is not None else None
        self.inside.setVisible(band is not None)
        self.outer.setVisible(band is not None and band.outer is not None)
        if band is not None:
            self.inside.setRegion(band.inside)
            if band.outer is not None:
                self.outer.setRegion(band.outer)
        unit = quality.units.get(quantity, "")
        self.plot.setLabel("left", f"{self.quantity.currentText()} ({unit})" if unit
                           else self.quantity.currentText())
        self.plot.setLabel("bottom", tr("along the revolution (°)") if along_revolution
                           else tr("period of the record"))
        text = tr("{windows} windows of {n} period(s)").format(
            windows=len(windows), n=quality.periods_per_window)
        lines = [translated(line) for line in quality.summary()]
        self.note.setText(" — ".join([text, *lines]))
        self.note.setToolTip("\n".join([text, *lines]))
