"""The window's renderer of declared figures (models/plots.py), and a plot widget that holds one.

:class:`FigureRenderer` draws a :class:`~models.plots.PlotFigure` into a pyqtgraph plot:
each series as a line in the style decided for it in models/plot_style.py (the PDF
writer draws from the same decisions), with markers where asked and its ±band shaded,
or as bars; the legend names every labelled series in the window's language. The
curves are made on the first figure and updated with ``setData`` after that, so a plot
set to clip and decimate its curves (the fringe plots: a million samples) keeps doing so.
"""

from __future__ import annotations

import dataclasses
import functools

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QVBoxLayout, QWidget

from models.plot_style import ROLE_STYLES, SeriesStyle, drawing_order, series_style
from widgets.i18n import declared, on_language_change
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.legend_placement import place_legend
from widgets.plot_grid import show_grid
from widgets.plot_range import follow_new_data, show_if_empty

__all__ = ["FigurePlot", "FigureRenderer", "legend_name"]

BAND_ALPHA = 50  # of 255


def legend_name(label: str) -> str | None:
    """A series' legend entry in the window's language (a run's number as it is)."""
    if not label:
        return None
    return label if label.isdigit() else declared(label)


@functools.lru_cache(maxsize=256)
def _curve_style(style: SeriesStyle) -> dict:
    """A series' style as PlotDataItem's options."""
    colour = pg.mkColor(*style.colour)
    pen = None if style.width == 0 else pg.mkPen(
        colour, width=style.width,
        style=Qt.PenStyle.DashLine if style.dashed else Qt.PenStyle.SolidLine)
    return {"pen": pen, "symbol": style.symbol, "symbolSize": style.symbol_size,
            "symbolBrush": colour, "symbolPen": None}


class FigureRenderer:
    """Draws declared figures into ``plot`` (a PlotWidget or PlotItem).

    ``titles``: the figure's title and axis titles are shown (otherwise the plot keeps its
    own); ``bars``: each series is drawn as bars of ``bar_width`` (offset as declared),
    rising from ``0`` or, with ``log_bars``, from a decade below the smallest value (the
    values are log10 amplitudes: the tallest bar is then the largest). ``curves`` holds the
    drawn series (PlotDataItems or BarGraphItems) in the figure's order, for tests.

    The error plot's panels (widgets/error_plot.py) ask for more: ``role_markers``, a series
    with a role is drawn with all of its role's style, markers too; ``max_symbol_points``,
    a series of more points is drawn without markers (they would overlap, and 1000 symbols
    cost ~10 ms per redraw); ``dense_points``, a series of markers of more points is a band
    of envelope points drawn with a 1-px pen (a 2-px pen adds nothing to a band and a third
    to the panel's paint); ``steady_y``, the y range moves only when the data leave it or
    fill less than 60 % of it (with ``y_includes`` always in view: the zero line), so an
    edit that moves a curve a little leaves the axes alone; ``z_order=False`` draws the
    series in the figure's order, each over the one before."""

    def __init__(self, plot, titles: bool = True, bars: bool = False, bar_width: float = 0.6,
                 log_bars: bool = False, *, role_markers: bool = False,
                 max_symbol_points: int | None = None, dense_points: int | None = None,
                 steady_y: bool = False, y_includes: tuple[float, ...] = (),
                 z_order: bool = True) -> None:
        self.item: pg.PlotItem = plot.getPlotItem() if hasattr(plot, "getPlotItem") else plot
        self.titles, self.bars, self.bar_width, self.log_bars = titles, bars, bar_width, log_bars
        self.role_markers, self.z_order = role_markers, z_order
        self.max_symbol_points, self.dense_points = max_symbol_points, dense_points
        self.steady_y, self.y_includes = steady_y, tuple(y_includes)
        self._sticky_y = True  # the y range is ours to move (False: the user zoomed or dragged)
        if steady_y:
            self.item.getViewBox().sigRangeChangedManually.connect(self._user_ranged)
        self.curves: list = []
        self.bands: list[pg.FillBetweenItem] = []  # the ±bands drawn
        self._names: list[str] = []  # each curve's label, in English
        self._figure = None
        on_language_change(self.item, self.relabel)

    @property
    def legend(self):
        return self.item.legend

    def clear(self) -> None:
        """Nothing drawn and no legend entry (the curves stay, empty: the next figure drawn
        reuses them)."""
        for index, curve in enumerate(self.curves):
            if self.bars:
                curve.setOpts(x=[], height=[], width=self.bar_width)
            else:
                curve.setData([], [])
            self._name(index, "")
        self._remove_bands()
        show_if_empty(self.item)  # a neutral view and "No data", not an axis of ±5e-05

    def _remove_bands(self) -> None:
        for band in self.bands:
            self.item.removeItem(band)
        self.bands = []

    def curve(self, index: int):
        """The ``index``-th curve, made when first needed."""
        while len(self.curves) <= index:
            if self.bars:
                bars = pg.BarGraphItem(x=[], height=[], width=self.bar_width)
                self.item.addItem(bars)
                self.curves.append(bars)
            else:
                self.curves.append(self.item.plot())
            self._names.append("")
        return self.curves[index]

    def rename(self, index: int, label: str) -> None:
        """Curve ``index``'s legend entry, by the English ``label`` ("": none)."""
        self.curve(index)
        self._name(index, label)

    def _name(self, index: int, label: str) -> None:
        """The legend entry of curve ``index``: added, renamed or removed as its label says."""
        curve, legend = self.curves[index], self.legend
        self._names[index] = label
        if legend is None:
            return
        name = legend_name(label)
        curve.opts["name"] = name
        entry = legend.getLabel(curve)
        if entry is not None and name:
            entry.setText(name)
        elif entry is not None:
            legend.removeItem(curve)
        elif name:
            legend.addItem(curve, name)

    def _user_ranged(self, _mask) -> None:
        self._sticky_y = False

    def style(self, series, points: int | None = None) -> SeriesStyle:
        """How ``series`` is drawn here: as decided in models/plot_style.py, with its role's
        markers on a panel drawn with ``role_markers``, and fewer of them or thinner pens
        on a long series (of ``points``, by default its own)."""
        role = ROLE_STYLES.get(series.role) if self.role_markers else None
        style = series_style(series) if role is None else role
        points = np.size(series.x) if points is None else points
        if style.symbol is not None and self.dense_points is not None and points > self.dense_points:
            style = dataclasses.replace(style, width=1.0)
        if (style.symbol is not None and self.max_symbol_points is not None
                and points > self.max_symbol_points):
            style = dataclasses.replace(style, symbol=None)
        return style

    def show(self, figure, follow: bool = True, points: int | None = None) -> None:
        """Draw ``figure`` (``None``: nothing); with ``follow=False`` the view's range is
        left as it is (curves declared before there is any data, or panels that follow
        their new data together once all are drawn: :meth:`follow_x`, :meth:`follow_y`);
        ``points``: the count the markers and pens go by (a hidden curve's legend entry
        then looks like its panel's others), by default each series' own."""
        if figure is None:
            self.clear()
            return
        self._figure = figure
        if self.titles:
            self._set_title(declared(figure.title))
            self.item.setLabel("bottom", declared(figure.x_label))
            self.item.setLabel("left", declared(figure.y_label))
        self._remove_bands()
        floor = 0.0
        if self.bars and self.log_bars:
            logs = np.concatenate([np.asarray(s.y, float) for s in figure.series] or [np.empty(0)])
            floor = float(np.floor(np.min(logs[np.isfinite(logs)], initial=0.0))) - 1.0
        order = {id(s): i for i, s in enumerate(drawing_order(figure))}
        for index, s in enumerate(figure.series):
            curve = self.curve(index)
            style = self.style(s, points)
            colour = pg.mkColor(*style.colour)
            if self.bars:
                curve.setOpts(x=s.x, y0=floor, height=np.asarray(s.y) - floor,
                              width=self.bar_width, brush=colour)
                self._name(index, s.label)
                continue
            if self.z_order:  # the set-up model under the rest
                curve.setZValue(order[id(s)] - len(figure.series))
            if s.band is not None:
                ok = np.isfinite(s.y) & np.isfinite(s.band)
                upper = pg.PlotCurveItem(s.x[ok], (s.y + s.band)[ok])
                lower = pg.PlotCurveItem(s.x[ok], (s.y - s.band)[ok])
                fill = pg.FillBetweenItem(upper, lower, brush=pg.mkBrush(*style.colour, BAND_ALPHA))
                fill.setZValue(-2 * len(figure.series))
                self.item.addItem(fill)
                self.bands.append(fill)
            # the style goes with the data: one redraw (pen None: markers only, no line drawn)
            curve.setData(s.x, s.y, connect="finite", **_curve_style(style))
            self._name(index, s.label)
        for index in range(len(figure.series), len(self.curves)):  # fewer series than before
            curve = self.curves[index]
            if self.bars:
                curve.setOpts(x=[], height=[], width=self.bar_width)
            else:
                curve.setData([], [])
            self._name(index, "")
        # nothing to draw: a neutral view and "No data" (data again: the placeholder hidden)
        empty = show_if_empty(self.item)
        if follow and self.steady_y and not empty:
            self.follow_x()
            self.follow_y()
        elif follow and not empty:
            follow_new_data(self.item)  # new data: shown whole again
        self._settle_legend()

    def follow_x(self) -> None:
        """New data are shown whole along x again (``steady_y``: y is :meth:`follow_y`'s)."""
        if not self.steady_y:
            follow_new_data(self.item)
        elif follow_new_data(self.item, y=False):  # new data: a user's zoom of the old is given up
            self._sticky_y = True

    def follow_y(self) -> None:
        """``steady_y``: move the y range only if the data left it or fill less than 60 % of
        it. A user's zoom is left alone until the plot's auto-range button ("A") is pressed
        or the data change (:meth:`follow_x`)."""
        if not self.steady_y or self._figure is None:
            return
        arrays = [s.y for s in self._figure.series]
        vb = self.item.getViewBox()
        if vb.state["autoRange"][1]:  # pyqtgraph's own auto-range (start, or "A" pressed)
            vb.enableAutoRange(y=False)
            self._sticky_y = True
        if not self._sticky_y:
            return
        values = [np.asarray(a, dtype=float).ravel() for a in arrays]
        if not any(np.isfinite(v).any() for v in values):
            return  # nothing drawn: show_if_empty's view (the zero line alone gave ±8e-05)
        values = np.concatenate([*values, np.asarray(self.y_includes, dtype=float)])
        values = values[np.isfinite(values)]
        lo, hi = float(values.min()), float(values.max())
        span = hi - lo if hi > lo else max(abs(hi), 1e-3)
        view_lo, view_hi = vb.viewRange()[1]
        if lo < view_lo or hi > view_hi or span < 0.6 * (view_hi - view_lo):
            pad = 0.08 * span
            vb.setYRange(lo - pad, hi + pad, padding=0.0)

    def _settle_legend(self) -> None:
        """The legend laid out at once with its new names, then placed: its size is then
        the new one (and no layout is left pending on a plot that may be deleted before
        the event loop comes round: a window closed just after a change of language)."""
        if self.legend is not None:
            self.legend.layout.activate()
            place_legend(self.item, self.legend)

    def _set_title(self, title: str) -> None:
        """The figure's title; a legend placed in the title line is placed again under this
        one (widgets/legend_placement.py keeps the title it found there: rev62day F14, the
        English title stayed above the Chinese legend after a change of language)."""
        self.item.__dict__.pop("title_before_legend", None)
        self.item.setTitle(title, size="9pt")

    def relabel(self) -> None:
        """The titles and legend again in the window's language."""
        if self._figure is not None and self.titles:
            self._set_title(declared(self._figure.title))
            self.item.setLabel("bottom", declared(self._figure.x_label))
            self.item.setLabel("left", declared(self._figure.y_label))
        if self.legend is None:
            return
        for curve, english in zip(self.curves, self._names, strict=True):
            entry = self.legend.getLabel(curve)
            if entry is not None and english:
                entry.setText(legend_name(english))
        self._settle_legend()


class FigurePlot(QWidget):
    """A plot widget showing one declared figure at a time, with its title, axis titles and
    legend. ``curves`` holds the drawn series (PlotDataItems) in the figure's order, for
    tests (``getData()``)."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w", viewBox=LazyMenuViewBox())
        show_grid(self.plot)
        for axis in ("left", "bottom"):
            self.plot.getAxis(axis).enableAutoSIPrefix(False)
        self.legend = self.plot.addLegend(offset=(-10, 10))
        self.renderer = FigureRenderer(self.plot)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.plot)

    @property
    def curves(self) -> list[pg.PlotDataItem]:
        return self.renderer.curves

    @property
    def bands(self) -> list[pg.FillBetweenItem]:
        """The shaded ±bands drawn (for tests)."""
        return self.renderer.bands

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        place_legend(self.plot.getPlotItem(), self.legend)

    def clear(self) -> None:
        self.renderer.clear()

    def show_figure(self, figure) -> None:
        self.renderer.show(figure)
