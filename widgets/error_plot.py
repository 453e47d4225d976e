"""Error-curve plot shared by the workbenches: raw error with the model over it,
the corrected error on its own scale, a residual plot beneath; legends, arcsec
axes and a crosshair readout. Each panel's curves are drawn by a FigureRenderer
(widgets/figure_plot.py), the code that draws every other figure, in the colour, line
and markers the certificate draws each role with (models/plot_style.py); this widget
lays out the panels, names their axes and legends, and reads the curves under the cursor."""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLabel, QVBoxLayout, QWidget

from models.plot_style import ROLE_STYLES
from models.plots import PlotFigure, PlotSeries
from models.tolerance_band import TOLERANCE_ROLE, UNCERTAINTY_ROLE
from models.uncertainty.rounding import fixed_places, significant_decimals
from widgets.figure_plot import FigureRenderer
from widgets.i18n import declared, on_language_change
from widgets.lazy_menu_view_box import LazyMenuViewBox
from widgets.legend_placement import place_legend
from widgets.plot_grid import show_grid


def _pen(role: str) -> pg.QtGui.QPen:
    """The pen of a role's curve, as decided for the window and the certificate alike
    (models/plot_style.py)."""
    style = ROLE_STYLES[role]
    return pg.mkPen(pg.mkColor(*style.colour), width=style.width,
                    style=Qt.PenStyle.DashLine if style.dashed else Qt.PenStyle.SolidLine)


RAW_PEN, MODEL_PEN, CORRECTED_PEN, RESIDUAL_PEN = (_pen(role) for role in (
    "raw", "model", "corrected", "residual"))
MAX_SYMBOL_POINTS = 500  # beyond this, points are drawn as lines only (they would overlap,
#                            and 1000 symbols cost ~10 ms per redraw)
DENSE_POINTS = 2000  # beyond this a curve is a band of envelope points: drawn with 1-px pens
#                      (a 2-px pen adds nothing to a band and a third to the panel's paint)


def _unit_of(label: str) -> str:
    """The unit a title states in its last parentheses: ``error (µrad)`` → ``µrad``."""
    start, end = label.rfind("("), label.rfind(")")
    return label[start + 1:end] if 0 <= start < end else ""


def _with_unit(label: str, unit: str) -> str:
    start = label.rfind("(")
    return f"{label[:start].rstrip()} ({unit})" if start >= 0 else f"{label} ({unit})"


class ErrorPlot(QWidget):
    """Three x-linked plots; the curves are created once and updated with ``setData``.

    ``raw_curve``, ``model_curve``, ``corrected_curve`` and ``residual_curve``
    are public so tests can read their data with ``getData()``.
    """

    def __init__(self, parent=None, x_label: str = "θ (deg)",
                 residual_label: str = "residual (\")") -> None:
        super().__init__(parent)
        self.unit = "\""  # of the errors drawn, for the readout under the cursor
        #: the decimals the readout shows the errors to: the certificate's (None: the data's)
        self.decimals: int | None = None
        self._setup_ui(x_label, residual_label)
        self._layout()

    def _setup_ui(self, x_label: str, residual_label: str) -> None:
        self.graphics = pg.GraphicsLayoutWidget()
        self.graphics.setBackground("w")
        self.main_plot = self.graphics.addPlot(row=0, col=0, viewBox=LazyMenuViewBox())
        self.corrected_plot = self.graphics.addPlot(row=1, col=0, viewBox=LazyMenuViewBox())
        self.residual_plot = self.graphics.addPlot(row=2, col=0, viewBox=LazyMenuViewBox())
        for row, stretch in enumerate((3, 3, 2)):
            self.graphics.ci.layout.setRowStretchFactor(row, stretch)
        for plot in (self.main_plot, self.corrected_plot, self.residual_plot):
            show_grid(plot)
            plot.getAxis("left").setWidth(58)
            for axis in ("left", "bottom"):
                plot.getAxis(axis).enableAutoSIPrefix(False)  # arcsec stay arcsec
        self.corrected_plot.setXLink(self.main_plot)
        self.residual_plot.setXLink(self.main_plot)
        self._labels: dict[tuple[object, str], str] = {}  # (panel, axis) -> English title
        self.set_axis_label(self.residual_plot, "bottom", x_label)
        self.set_axis_label(self.main_plot, "left", "raw error (\")")
        self.set_axis_label(self.corrected_plot, "left", "corrected (\")")
        self.set_axis_label(self.residual_plot, "left", residual_label)
        on_language_change(self, self._relabel)
        self.legend = self.main_plot.addLegend(offset=(-10, 10))
        self.corrected_legend = self.corrected_plot.addLegend(offset=(-10, 10))
        # each panel's renderer: the roles' own markers, none on a long curve, thin pens on a
        # dense one; y ranges that follow the data only when it leaves the view or shrinks
        # well inside it (an edit that moves the curve a little leaves the axes, and their
        # tick labels, ~2 ms each to re-render, alone: the plot does not jitter); the
        # curves drawn in the order made, the model over the raw error
        panel = {"titles": False, "role_markers": True, "max_symbol_points": MAX_SYMBOL_POINTS,
                 "dense_points": DENSE_POINTS, "steady_y": True, "z_order": False}
        self.main_renderer = FigureRenderer(self.main_plot, **panel)
        self.corrected_renderer = FigureRenderer(self.corrected_plot, y_includes=(0.0,), **panel)
        self.residual_renderer = FigureRenderer(self.residual_plot, y_includes=(0.0,), **panel)
        # the legend's names in English, shown again in the window's language by the
        # renderers (an empty plot's legend too: it stayed "raw / model / corrected" in Chinese)
        self._curve_names = {"raw": "raw", "model": "model", "corrected": "corrected"}
        self.main_renderer.show(self._figure("raw", "model"), follow=False)
        self.raw_curve, self.model_curve = self.main_renderer.curves
        self.corrected_renderer.show(self._figure("corrected"), follow=False)
        (self.corrected_curve,) = self.corrected_renderer.curves
        self.corrected_plot.addItem(pg.InfiniteLine(0, angle=0, pen=pg.mkPen("#999")))
        self.residual_renderer.show(self._figure("residual"), follow=False)
        (self.residual_curve,) = self.residual_renderer.curves
        self.residual_plot.addItem(pg.InfiniteLine(0, angle=0, pen=pg.mkPen("#999")))
        self.vline = pg.InfiniteLine(angle=90, movable=False, pen=pg.mkPen("#888", width=1))
        self.main_plot.addItem(self.vline, ignoreBounds=True)
        self.readout = QLabel(" ")
        self.readout.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        # on as many lines as the plot's width needs: on one line the readout of three
        # curves (738 px in Chinese, 790 in English) held the plot wider than its area
        # beside the docked instrument panel at 1280 px, which then scrolled sideways and
        # cut off the legend and the curves past ~200° (day review 64 P5)
        self.readout.setWordWrap(True)
        self.graphics.scene().sigMouseMoved.connect(self._on_mouse_moved)

    def _layout(self) -> None:
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.graphics, 1)
        layout.addWidget(self.readout)

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        """The legend's share of the plot changes with its size (and the screen's scale)."""
        super().resizeEvent(event)
        place_legend(self.main_plot, self.legend)
        place_legend(self.corrected_plot, self.corrected_legend)

    def _figure(self, *roles: str, curves: dict[str, tuple[Any, Any]] | None = None
                ) -> PlotFigure:
        """The figure a panel draws: a series per role, each over its own x (``curves``:
        role → (x, y); empty where y is ``None`` or the role is not given), named as the
        legend names it."""
        series = []
        for role in roles:
            x, y = (curves or {}).get(role, ((), None))
            series.append(PlotSeries(
                self._curve_names.get(role, ""),
                np.asarray(x, dtype=float) if y is not None else np.empty(0),
                np.asarray(y, dtype=float) if y is not None else np.empty(0), role=role))
        return PlotFigure("", "", "", tuple(series))

    def set_curve_names(self, raw: str, model: str, corrected: str) -> None:
        """The legend's names of the three curves ("": none), in English."""
        self._curve_names.update(raw=raw, model=model, corrected=corrected)
        for renderer, roles in ((self.main_renderer, ("raw", "model")),
                                (self.corrected_renderer, ("corrected",))):
            for index, role in enumerate(roles):
                renderer.rename(index, self._curve_names[role])

    def set_curves(self, x, raw=None, model=None, corrected=None, beside=()) -> None:
        """Update the curves (arcsec over x, one x for the three); ``None`` hides a curve.
        ``beside``: series drawn with the corrected error on its panel (its U band and the
        tolerance ±T, models/tolerance_band.py)."""
        self._draw({"raw": (x, raw), "model": (x, model), "corrected": (x, corrected)},
                   beside)

    def _draw(self, curves: dict[str, tuple[Any, Any]], beside=()) -> None:
        """The raw, model and corrected curves, each ``(x, y)`` over its own x (``y`` None:
        hidden). ValueError naming the series whose x and y differ in length."""
        for role, (x, y) in curves.items():
            if y is not None and np.size(x) != np.size(y):
                raise ValueError(f"error plot: the {role} series "
                                 f"{self._curve_names.get(role, '')!r} has {np.size(y)} values "
                                 f"over {np.size(x)} x values; each series needs one x per value")
        for series in beside:
            if np.size(series.x) != np.size(series.y):
                raise ValueError(f"error plot: the {series.role} series {series.label!r} has "
                                 f"{np.size(series.y)} values over {np.size(series.x)} x values")
        # a hidden curve's legend sample drawn as its panel's others
        points = max((np.size(x) for x, y in curves.values() if y is not None), default=0)
        self.main_renderer.show(self._figure("raw", "model", curves=curves), follow=False,
                                points=points)
        corrected_figure = self._figure("corrected", curves=curves)
        if beside:
            corrected_figure = dataclasses.replace(
                corrected_figure, series=corrected_figure.series + tuple(beside))
        self.corrected_renderer.show(corrected_figure, follow=False, points=points)
        # both panels drawn, then ranged: x-linked, they follow their new data together
        for renderer in (self.main_renderer, self.corrected_renderer):
            renderer.follow_x()
        for renderer in (self.main_renderer, self.corrected_renderer):
            renderer.follow_y()
        place_legend(self.main_plot, self.legend)
        place_legend(self.corrected_plot, self.corrected_legend)

    def show_figure(self, figure, residuals=None) -> None:
        """Draw a declared figure (models/plots.py): its ``raw`` and ``model`` series on the
        upper panel, ``corrected`` on its own, the residual figure on the lowest. Each series
        is drawn over its own x (a model on a fine grid beside the readings is fine);
        ValueError naming a series whose x and y differ in length."""
        self._state_units(figure.y_label, residuals.y_label if residuals is not None else "")
        parts = {role: figure.by_role(role) for role in ("raw", "model", "corrected")}
        self.set_curve_names(*(s.label if s is not None else "" for s in parts.values()))
        beside = tuple(s for s in figure.series if s.role in (UNCERTAINTY_ROLE, TOLERANCE_ROLE))
        self._draw({role: (s.x, s.y) if s is not None else ((), None)
                    for role, s in parts.items()}, beside)
        series = residuals.by_role("residual") if residuals is not None else None
        self.set_residuals(series.x if series is not None else [],
                           series.y if series is not None else None)

    def set_axis_label(self, plot, axis: str, english: str) -> None:
        """A panel's axis title, shown in the window's language (kept in English to be
        translated again and to have its unit rewritten)."""
        self._labels[(plot, axis)] = english
        plot.setLabel(axis, declared(english))

    def axis_label(self, plot, axis: str = "left") -> str:
        return self._labels.get((plot, axis), "")

    def _relabel(self) -> None:
        for (plot, axis), english in self._labels.items():
            plot.setLabel(axis, declared(english))

    def _state_units(self, errors_label: str, residuals_label: str) -> None:
        """Each panel's title names the unit of the figure it draws (the unit results are
        read in: ″, µrad, mdeg or nm)."""
        unit = _unit_of(errors_label)
        if unit:
            self.unit = unit
            for plot in (self.main_plot, self.corrected_plot):
                self.set_axis_label(plot, "left", _with_unit(self.axis_label(plot), unit))
        if _unit_of(residuals_label):
            self.set_axis_label(self.residual_plot, "left", _with_unit(
                self.axis_label(self.residual_plot), _unit_of(residuals_label)))

    def set_readout_decimals(self, decimals: int | None) -> None:
        """The decimals the readout under the cursor shows the errors to: those the
        certificate prints them to, in the unit drawn (None: three significant digits of
        the curves' span, :meth:`readout_decimals`)."""
        self.decimals = decimals

    def readout_decimals(self) -> int:
        """The decimals of the readout: the certificate's when told; else three significant
        digits of the span of the curves drawn (a 0.98″ curve to 0.001″, a 723″ one to 0.1″;
        it showed 0.001″ of every curve, and of µrad or mdeg as well)."""
        if self.decimals is not None:
            return self.decimals
        values = [np.asarray(curve.getData()[1], dtype=float) for curve in
                  (self.raw_curve, self.model_curve, self.corrected_curve)
                  if curve.getData()[1] is not None]
        values = np.concatenate(values) if values else np.empty(0)
        values = values[np.isfinite(values)]
        span = float(values.max() - values.min()) if values.size else 0.0
        decimals = significant_decimals(span)  # two significant digits of the span: a third
        # a span of 100 or more (negative decimals) still to 0.1, as before 0.8.25
        return 2 if decimals is None else max(0, decimals) + 1

    def set_residuals(self, x, residuals) -> None:
        if residuals is None:
            self.residual_renderer.clear()
        else:
            self.residual_renderer.show(self._figure("residual", curves={"residual": (x, residuals)}))

    def clear(self) -> None:
        """No data: the curves emptied and the crosshair's line and readout with them (it
        kept the old values after File › New)."""
        self.set_curves([], None, None, None)
        self.set_residuals([], None)
        self.vline.hide()
        self.readout.setText(" ")

    def _on_mouse_moved(self, pos) -> None:
        if not self.main_plot.sceneBoundingRect().contains(pos):
            return
        point = self.main_plot.vb.mapSceneToView(pos)
        self.vline.setPos(point.x())
        self.vline.show()
        parts = [f"x = {point.x():.4g}"]
        decimals = self.readout_decimals()
        for curve in (self.raw_curve, self.model_curve, self.corrected_curve):
            xs, ys = curve.getData()
            if xs is None or len(xs) == 0:
                continue
            i = int(np.argmin(np.abs(xs - point.x())))
            gap = "" if self.unit == "\"" else " "
            value = fixed_places(float(ys[i]), decimals, "+")  # a zero unsigned, as printed
            parts.append(f"{curve.opts['name']} {value}{gap}{self.unit} @ {xs[i]:.4g}")
        self.readout.setText("   ".join(parts))
