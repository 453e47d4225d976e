"""Fringe signal analysis workbench: signals and fits, Lissajous figure, spectrum,
interpolation error before and after compensation, per-period drift."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtWidgets import QFileDialog, QPushButton, QVBoxLayout, QWidget

from models.decimation import envelope
from models.fringe.analysis import FRINGE, FringeResult
from models.fringe.export import write_correction_table
from models.fringe.model import model_signal
from widgets.error_plot import ErrorPlot
from widgets.workbench_presenter import WorkbenchPresenter
from widgets.workbench_view import WorkbenchView

MAX_LISSAJOUS_POINTS = 5_000
PLOT_BINS = 2000  # runs per curve; each keeps its min and max


def _plot(left: str, bottom: str, legend: bool = True, downsample: bool = True) -> pg.PlotWidget:
    """A plot; ``downsample`` only for curves that are functions of x (never a Lissajous)."""
    plot = pg.PlotWidget(background="w")
    plot.setLabel("left", left)
    plot.setLabel("bottom", bottom)
    plot.showGrid(x=True, y=True, alpha=0.25)
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
        self.spectrum = _plot("amplitude (V, log)", "harmonic order", downsample=False)
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


class FringePresenter(WorkbenchPresenter):
    """Fits both channels, builds the correction table and shows before/after errors."""

    def __init__(self, parent=None) -> None:
        view = WorkbenchView(FRINGE.title)
        self.error_plot = ErrorPlot(x_label="electrical phase θ (periods)",
                                    residual_label="sin fit res. (mV)")
        self.error_plot.set_curve_names("before compensation", "", "after compensation")
        self.error_plot.main_plot.setLabel("left", "interp. error (\")")
        self.error_plot.corrected_plot.setLabel("left", "compensated (\")")
        for plot in (self.error_plot.main_plot, self.error_plot.corrected_plot,
                     self.error_plot.residual_plot):
            plot.setClipToView(True)
            plot.setDownsampling(auto=True, mode="peak")
        self.plots = FringePlots()
        self.export_button = QPushButton("Export table (CSV / C header)…")
        error_tab = QWidget()
        layout = QVBoxLayout(error_tab)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.error_plot, 1)
        layout.addWidget(self.export_button)
        view.add_plot_tab(error_tab, "Interpolation error")
        view.add_plot_tab(self.plots.signals, "Signals and fit")
        view.add_plot_tab(self.plots.lissajous, "Lissajous")
        view.add_plot_tab(self.plots.spectrum, "Spectrum")
        view.add_plot_tab(self.plots.drift, "Drift per period")
        super().__init__(FRINGE, view, parent)
        self.export_button.clicked.connect(self.export_table_dialog)

    def prepare_display(self, result: FringeResult) -> dict[str, tuple[np.ndarray, np.ndarray]]:
        """The curves thinned for drawing (worker thread for a large run). A revolution has
        a million samples: each curve keeps its envelope (every excursion, ~4000 points),
        which Qt draws in a few ms instead of ~100. When the motion stood or turned back
        the curves run over the phase within a period instead, in phase order."""
        x = result.theta_rad / (2 * np.pi)
        order = np.arange(x.size)
        if x.size > 1 and not np.all(np.diff(x) > 0):
            x = np.degrees(np.mod(result.theta_rad, 2 * np.pi))
            order = np.argsort(x, kind="stable")
            x = x[order]
        step = max(1, x.size // (2 * PLOT_BINS))
        theta = result.theta_rad[order][::step]
        raw, comp = result.raw_error[order], result.compensated_error[order]
        residual = (result.u_sin - model_signal(result.theta_rad, result.sin_fit))[order]
        raw_x, _ = envelope(x, raw, PLOT_BINS)
        comp_x, _ = envelope(x, comp, PLOT_BINS)
        # raw and compensated on one sampling that keeps the extremes of both
        pick = np.union1d(np.searchsorted(x, raw_x), np.searchsorted(x, comp_x))
        pick = np.clip(pick, 0, x.size - 1)
        return {
            "errors": (x[pick], order[pick]),
            "residual": envelope(x, residual * 1000.0, PLOT_BINS),
            "sin": envelope(x, result.u_sin[order], PLOT_BINS),
            "cos": envelope(x, result.u_cos[order], PLOT_BINS),
            "sin_fit": (x[::step], model_signal(theta, result.sin_fit)),
            "cos_fit": (x[::step], model_signal(theta, result.cos_fit)),
            "drift": [envelope(np.arange(result.sin_periods.shape[0]), values, PLOT_BINS // 2)
                      for values in (result.sin_periods[:, 1], result.cos_periods[:, 1],
                                     result.sin_periods[:, min(3, result.sin_periods.shape[1] - 1)]
                                     * 10, result.cos_periods[:, min(3, result.cos_periods.shape[1]
                                                                     - 1)] * 10)],
        }

    def show_result(self, result: FringeResult) -> None:
        d = self.display if isinstance(self.display, dict) else self.prepare_display(result)
        x, pick = d["errors"]
        unit = result.unit_symbol.strip()
        along = ("electrical phase θ (periods)" if np.all(np.diff(result.theta_rad) > 0)
                 else "phase within the period (°); the motion stood or turned back")
        self.error_plot.residual_plot.setLabel("bottom", along)
        self.error_plot.main_plot.setLabel(
            "left", ("error, est. phase" if result.phase_source == "estimated"
                     else "interp. error") + f" ({unit})")
        self.error_plot.corrected_plot.setLabel("left", f"compensated ({unit})")
        self.error_plot.set_curves(x, result.raw_error[pick], None,
                                   result.compensated_error[pick])
        self.error_plot.set_residuals(*d["residual"])
        p = self.plots
        p.sin_points.setData(*d["sin"])
        p.cos_points.setData(*d["cos"])
        p.sin_fit.setData(*d["sin_fit"])
        p.cos_fit.setData(*d["cos_fit"])
        # a parametric curve cannot be peak-downsampled; a stride keeps its shape
        step = max(1, result.u_sin.size // MAX_LISSAJOUS_POINTS)
        u_sin, u_cos = result.u_sin[::step], result.u_cos[::step]
        p.liss_raw.setData(u_cos, u_sin)
        if result.ellipse is not None:
            e = result.ellipse
            t = np.linspace(0.0, 2 * np.pi, 361)
            p.liss_ellipse.setData(e.offset_cos + e.amplitude_cos * np.cos(t + e.quadrature_rad),
                                   e.offset_sin + e.amplitude_sin * np.sin(t))
        circle = np.linspace(0.0, 2 * np.pi, 361)
        radius = 0.5 * (result.sin_fit.amplitude[1] + result.cos_fit.amplitude[1])
        p.liss_ideal.setData(radius * np.cos(circle), radius * np.sin(circle))
        orders = np.array(result.sin_fit.orders, dtype=float)
        p.sin_bars.setOpts(x=orders - 0.18, height=np.log10(
            [max(result.sin_fit.amplitude[k], 1e-9) for k in result.sin_fit.orders]), width=0.35)
        p.cos_bars.setOpts(x=orders + 0.18, height=np.log10(
            [max(result.cos_fit.amplitude[k], 1e-9) for k in result.cos_fit.orders]), width=0.35)
        a1, b1, a3, b3 = d["drift"]
        p.drift_a1.setData(*a1)
        p.drift_b1.setData(*b1)
        if result.sin_periods.shape[1] > 3:
            p.drift_a3.setData(*a3)
            p.drift_b3.setData(*b3)

    def clear_result(self) -> None:
        self.error_plot.clear()
        p = self.plots
        for curve in (p.sin_points, p.cos_points, p.sin_fit, p.cos_fit, p.liss_raw, p.liss_ellipse,
                      p.liss_ideal,
                      p.drift_a1, p.drift_b1, p.drift_a3, p.drift_b3):
            curve.setData([], [])

    def export_table_dialog(self) -> None:
        if self.result is None:
            return
        path, _ = QFileDialog.getSaveFileName(self.view, "Export correction table", "",
                                              "CSV (*.csv);;C header (*.h)")
        if path:
            write_correction_table(path, self.result)
