"""The fringe signal analysis' view: the shared readings and set-up, the interpolation
error before and after compensation with the table export button, the signals and
fits, the Lissajous figure with the fitted ellipse, the spectrum and the drift per
period. Widgets only: the presenter hands it arrays to draw."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QFileDialog, QPushButton, QVBoxLayout, QWidget

from models.fringe import TITLE
from widgets.error_plot import ErrorPlot
from widgets.i18n import declared, live, on_language_change, tr
from widgets.legend_placement import place_legend
from widgets.plot_grid import IntegerAxis, show_grid
from widgets.plot_range import follow_new_data
from widgets.workbench_view import WorkbenchView


def _plot(left: str, bottom: str, legend: bool = True, downsample: bool = True,
          whole_x: bool = False) -> pg.PlotWidget:
    """A plot; ``downsample`` only for curves that are functions of x (never a Lissajous);
    ``whole_x``: x ticks at whole numbers only (a harmonic's order). Its titles and legend
    are in the window's language (``_relabel``)."""
    plot = pg.PlotWidget(background="w", axisItems={"bottom": IntegerAxis("bottom")}
                         if whole_x else None)
    plot.english_labels = {"left": left, "bottom": bottom}
    plot.setLabel("left", declared(left))
    plot.setLabel("bottom", declared(bottom))
    show_grid(plot)
    for axis in ("left", "bottom"):
        plot.getAxis(axis).enableAutoSIPrefix(False)
    if downsample:
        plot.setClipToView(True)
        plot.setDownsampling(auto=True, mode="peak")
    if legend:
        plot.addLegend(offset=(-10, 10))
    return plot


class FringePlots(QWidget):
    """The fringe-specific plots; every curve is created once."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.signals = _plot("signal (V)", "electrical phase θ (periods)")
        self.sin_points = self.signals.plot(name="u sin", pen=pg.mkPen("#e6b0aa", width=3))
        self.cos_points = self.signals.plot(name="u cos", pen=pg.mkPen("#a9cce3", width=3))
        self.sin_fit = self.signals.plot(name="fit", pen=pg.mkPen("#7b241c", width=1.5))
        self.cos_fit = self.signals.plot(pen=pg.mkPen("#154360", width=1.5))
        self.lissajous = _plot("u sin (V)", "u cos (V)", downsample=False)
        self.lissajous.setAspectLocked(True)
        self.liss_raw = self.lissajous.plot(name="measured", pen=None, symbol="o", symbolSize=2,
                                            symbolPen=None, symbolBrush="#c0392b")
        self.liss_ellipse = self.lissajous.plot(name="fitted ellipse (Heydemann)",
                                                pen=pg.mkPen("#27ae60", width=2,
                                                             style=pg.QtCore.Qt.PenStyle.DashLine))
        self.liss_ideal = self.lissajous.plot(name="compensated (unit circle × A1)",
                                              pen=pg.mkPen("#1f5fbf", width=1.5))
        self.spectrum = _plot("amplitude (V, log)", "harmonic order", downsample=False,
                              whole_x=True)
        self.spectrum.setLogMode(y=True)
        self.sin_bars = pg.BarGraphItem(x=[], height=[], width=0.35, brush="#c0392b", name="sin")
        self.cos_bars = pg.BarGraphItem(x=[], height=[], width=0.35, brush="#1f5fbf", name="cos")
        self.spectrum.addItem(self.sin_bars)
        self.spectrum.addItem(self.cos_bars)
        self.drift = _plot("amplitude (V)", "period")
        self.drift_a1 = self.drift.plot(name="A1 (sin)", pen=pg.mkPen("#c0392b", width=1.5))
        self.drift_b1 = self.drift.plot(name="B1 (cos)", pen=pg.mkPen("#1f5fbf", width=1.5))
        self.drift_a3 = self.drift.plot(name="A3 × 10", pen=pg.mkPen("#e67e22", width=1.5))
        self.drift_b3 = self.drift.plot(name="B3 × 10", pen=pg.mkPen("#16a085", width=1.5))
        self._names = {}  # legend label -> English name
        for plot in (self.signals, self.lissajous, self.drift):
            for _sample, label in plot.getPlotItem().legend.items:
                self._names[label] = label.text
        self._relabel()
        on_language_change(self, self._relabel)

    def _relabel(self) -> None:
        for plot in (self.signals, self.lissajous, self.spectrum, self.drift):
            for axis, english in plot.english_labels.items():
                plot.setLabel(axis, declared(english))
        for label, english in self._names.items():
            label.setText(declared(english))


class FringeView(WorkbenchView):
    def __init__(self, parent=None) -> None:
        super().__init__(TITLE, parent)
        self.error_plot = ErrorPlot(x_label="electrical phase θ (periods)",
                                    residual_label="sin fit res. (mV)")
        self.error_plot.set_axis_label(self.error_plot.main_plot, "left", "interp. error (\")")
        self.error_plot.set_axis_label(self.error_plot.corrected_plot, "left",
                                       "compensated (\")")
        for plot in (self.error_plot.main_plot, self.error_plot.corrected_plot,
                     self.error_plot.residual_plot):
            plot.setClipToView(True)
            plot.setDownsampling(auto=True, mode="peak")
        self.plots = FringePlots()
        self.export_button = QPushButton()
        live(self.export_button.setText, tr("Export table (CSV / C header)…"))
        error_tab = QWidget()
        layout = QVBoxLayout(error_tab)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.error_plot, 1)
        layout.addWidget(self.export_button)
        self.add_plot_tab(error_tab, tr("Interpolation error"))
        self.add_plot_tab(self.plots.signals, tr("Signals and fit"))
        self.add_plot_tab(self.plots.lissajous, tr("Lissajous"))
        self.add_plot_tab(self.plots.spectrum, tr("Spectrum"))
        self.add_plot_tab(self.plots.drift, tr("Drift per period"))

    def subscribe(self, presenter) -> None:
        super().subscribe(presenter)
        self.export_button.clicked.connect(presenter.export_table_dialog)

    def show_figures(self, figures: dict) -> None:
        """The declared figures (models/fringe/plots.py)."""
        errors = figures["errors"]
        plot = self.error_plot
        plot.set_axis_label(plot.residual_plot, "bottom", errors.x_label)
        plot.set_axis_label(plot.main_plot, "left", errors.y_label)
        unit = errors.y_label[errors.y_label.rfind("("):]
        plot.set_axis_label(plot.corrected_plot, "left", f"compensated {unit}")
        self.error_plot.show_figure(errors, figures["residuals"])
        p = self.plots
        for curve, series in zip((p.sin_points, p.cos_points, p.sin_fit, p.cos_fit),
                                 figures["signals"].series, strict=True):
            curve.setData(series.x, series.y)
        for curve, series in zip((p.liss_raw, p.liss_ellipse, p.liss_ideal),
                                 figures["lissajous"].series, strict=True):
            curve.setData(series.x, series.y)
        sin_bars, cos_bars = figures["spectrum"].series
        # log10 amplitudes: bars rise from a decade below the smallest, so the tallest bar
        # is the largest harmonic (from 0, i.e. 1 V, the smallest would hang longest)
        logs = np.concatenate([sin_bars.y, cos_bars.y])
        floor = float(np.floor(np.min(logs[np.isfinite(logs)], initial=0.0))) - 1.0
        p.sin_bars.setOpts(x=sin_bars.x, y0=floor, height=sin_bars.y - floor, width=0.35)
        p.cos_bars.setOpts(x=cos_bars.x, y0=floor, height=cos_bars.y - floor, width=0.35)
        drift = figures["drift"].series
        for i, curve in enumerate((p.drift_a1, p.drift_b1, p.drift_a3, p.drift_b3)):
            curve.setData(*((drift[i].x, drift[i].y) if i < len(drift) else ([], [])))
        for plot in (p.signals, p.lissajous, p.spectrum, p.drift):
            follow_new_data(plot.getPlotItem())  # new data: shown whole again
        for plot in (p.signals, p.lissajous, p.drift):
            item = plot.getPlotItem()
            place_legend(item, item.legend)

    def clear_result(self) -> None:
        self.error_plot.clear()
        p = self.plots
        for curve in (p.sin_points, p.cos_points, p.sin_fit, p.cos_fit, p.liss_raw, p.liss_ellipse,
                      p.liss_ideal, p.drift_a1, p.drift_b1, p.drift_a3, p.drift_b3):
            curve.setData([], [])

    def ask_table_path(self) -> str:
        path, _ = QFileDialog.getSaveFileName(self, tr("Export correction table"), "",
                                              tr("CSV (*.csv);;C header (*.h)"))
        return path
