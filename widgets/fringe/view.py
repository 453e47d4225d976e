"""The fringe signal analysis' view: the shared readings and set-up, the interpolation
error before and after compensation with the table export button, the signals and
fits, the Lissajous figure with the fitted ellipse, the spectrum and the drift per
period, and the live signals of a read head being mounted (widgets/fringe/live_signals.py).
Widgets only: the presenter hands it arrays to draw."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel, QMessageBox, QPushButton, QVBoxLayout, QWidget

from models.fringe import TITLE
from widgets.error_plot import ErrorPlot
from widgets.figure_plot import FigureRenderer
from widgets.fringe.live_signals import LiveSignalsPanel
from widgets.fringe.signal_quality_plot import SignalQualityPlot
from widgets.i18n import declared, live, on_language_change, tr
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.plot_grid import IntegerAxis, show_grid
from widgets.save_file import ask_save_file
from widgets.screen_fit import fit_to_screen
from widgets.workbench_view import WorkbenchView


def _plot(left: str, bottom: str, legend: bool = True, downsample: bool = True,
          whole_x: bool = False) -> pg.PlotWidget:
    """A plot; ``downsample`` only for curves that are functions of x (never a Lissajous);
    ``whole_x``: x ticks at whole numbers only (a harmonic's order). Its titles and legend
    are in the window's language (``_relabel``)."""
    plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox(),
                         axisItems={"bottom": IntegerAxis("bottom")} if whole_x else None)
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
    """The fringe-specific plots, each drawn by a :class:`FigureRenderer` from its declared
    figure (models/fringe/plots.py); the curves are made once and updated after that."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.signals = _plot("signal (V)", "electrical phase θ (periods)")
        self.lissajous = _plot("u sin (V)", "u cos (V)", downsample=False)
        self.lissajous.setAspectLocked(True)
        self.spectrum = _plot("amplitude (V, log)", "harmonic order", downsample=False,
                              whole_x=True)
        self.spectrum.setLogMode(y=True)
        self.drift = _plot("amplitude (V)", "period")
        self.renderers = {
            "signals": FigureRenderer(self.signals, titles=False),
            "lissajous": FigureRenderer(self.lissajous, titles=False),
            "spectrum": FigureRenderer(self.spectrum, titles=False, bars=True, bar_width=0.35,
                                       log_bars=True),
            "drift": FigureRenderer(self.drift, titles=False),
        }
        on_language_change(self, self._relabel)

    def _relabel(self) -> None:
        for plot in (self.signals, self.lissajous, self.spectrum, self.drift):
            for axis, english in plot.english_labels.items():
                plot.setLabel(axis, declared(english))

    def show(self, figures: dict) -> None:
        for name, renderer in self.renderers.items():
            renderer.show(figures[name])

    def clear(self) -> None:
        for renderer in self.renderers.values():
            renderer.clear()

    # each curve by name, for tests (getData(), opts)
    sin_points = property(lambda self: self.renderers["signals"].curve(0))
    cos_points = property(lambda self: self.renderers["signals"].curve(1))
    sin_fit = property(lambda self: self.renderers["signals"].curve(2))
    cos_fit = property(lambda self: self.renderers["signals"].curve(3))
    liss_raw = property(lambda self: self.renderers["lissajous"].curve(0))
    liss_ellipse = property(lambda self: self.renderers["lissajous"].curve(1))
    liss_ideal = property(lambda self: self.renderers["lissajous"].curve(2))
    sin_bars = property(lambda self: self.renderers["spectrum"].curve(0))
    cos_bars = property(lambda self: self.renderers["spectrum"].curve(1))
    drift_a1 = property(lambda self: self.renderers["drift"].curve(0))
    drift_b1 = property(lambda self: self.renderers["drift"].curve(1))
    drift_a3 = property(lambda self: self.renderers["drift"].curve(2))
    drift_b3 = property(lambda self: self.renderers["drift"].curve(3))


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
        # the signals along the record against a preset's bands (#45)
        self.signal_quality = SignalQualityPlot()
        self.add_plot_tab(self.signal_quality, tr("Signal quality"))
        # a read head's signals watched live while it is mounted (#45): a window of its own
        # (the plot tabs are too small for a test set's display at 1280×720), opened from
        # its tab
        self.live_signals = LiveSignalsPanel(self)
        self.live_signals.setWindowFlag(Qt.WindowType.Window)
        live(self.live_signals.setWindowTitle, tr("Live signals — mounting a read head"))
        launcher = QWidget()
        self.live_button = QPushButton()
        live(self.live_button.setText, tr("Open the live signals…"))
        self.live_button.clicked.connect(self.open_live_signals)
        about = QLabel()
        about.setWordWrap(True)
        live(about.setText, tr("Watch a read head's sin/cos signals while you mount it: "
                               "amplitudes, their ratio, the phase between them and the offsets "
                               "as bars against the interface's tolerances, the Lissajous "
                               "figure and the interpolation error, live from an ADC or "
                               "oscilloscope stream (serial or TCP) or from a demonstration "
                               "head. Take puts the window's samples in the readings."))
        launcher_layout = QVBoxLayout(launcher)
        launcher_layout.addWidget(about)
        launcher_layout.addWidget(self.live_button, 0, Qt.AlignmentFlag.AlignLeft)
        launcher_layout.addStretch(1)
        self.add_plot_tab(launcher, tr("Live signals"))

    def open_live_signals(self) -> None:
        """The live signals' window, shown and raised (sized to the screen the first time)."""
        panel = self.live_signals
        panel.reload_presets()  # the lab's own as saved now
        if not panel.isVisible() and not getattr(panel, "placed", False):
            fit_to_screen(panel, 1240, 700)
            panel.placed = True
        panel.show()
        panel.raise_()
        panel.activateWindow()

    def subscribe(self, presenter) -> None:
        super().subscribe(presenter)
        self.export_button.clicked.connect(presenter.export_table_dialog)
        self.live_signals.taken.connect(presenter.take_live_signals)

    def show_figures(self, figures: dict) -> None:
        """The declared figures (models/fringe/plots.py)."""
        errors = figures["errors"]
        plot = self.error_plot
        plot.set_axis_label(plot.residual_plot, "bottom", errors.x_label)
        plot.set_axis_label(plot.main_plot, "left", errors.y_label)
        unit = errors.y_label[errors.y_label.rfind("("):]
        plot.set_axis_label(plot.corrected_plot, "left", f"compensated {unit}")
        self.error_plot.show_figure(errors, figures["residuals"])
        self.plots.show(figures)

    def show_signal_quality(self, compute) -> None:
        """The signal quality tab from ``compute(preset)`` (the presenter's)."""
        self.signal_quality.set_presets(self.live_signals.presets)
        self.signal_quality.compute = compute
        self.signal_quality.recompute()

    def clear_result(self) -> None:
        self.error_plot.clear()
        self.plots.clear()
        self.signal_quality.clear()

    def ask_table_path(self) -> str:
        return ask_save_file(self, tr("Export correction table"), "",
                             tr("CSV (*.csv);;C header (*.h)"))

    def tell(self, title: str, text: str) -> None:
        QMessageBox.warning(self, title, text)
