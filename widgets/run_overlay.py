"""A second run overlaid on a workbench's error plot (see models/run_overlay.py).

The other run's certified curve is drawn on the corrected panel as a dashed orange line
with its own legend entry, "other run: <name>", over today's; it follows the angle unit
the results are shown in, stays while today's readings change, and is removed on demand.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt

from models.display_units import figure_in_unit
from models.run_overlay import OverlayRun
from widgets.i18n import on_language_change, tr
from widgets.legend_placement import place_legend

__all__ = ["OVERLAY_PEN", "RunOverlay"]

OVERLAY_PEN = pg.mkPen("#e67e22", width=2, style=Qt.PenStyle.DashLine)


class RunOverlay:
    """The overlay of one workbench presenter (its view must have an ``error_plot``)."""

    def __init__(self, presenter: Any) -> None:
        self.presenter = presenter
        self.run: OverlayRun | None = None
        self.curve = pg.PlotDataItem(pen=OVERLAY_PEN, symbol="t", symbolSize=6,
                                     symbolBrush="#e67e22", symbolPen=None)
        self.curve.setZValue(-1)  # today's run is drawn over the other
        presenter.analysed.connect(self.redraw)  # a new unit or language redraws the result
        on_language_change(presenter.view, self.redraw)

    @property
    def plot(self):
        return self.presenter.view.error_plot.corrected_plot

    @property
    def legend(self):
        return self.presenter.view.error_plot.corrected_legend

    @property
    def shown(self) -> bool:
        return self.run is not None

    def name(self) -> str:
        return tr("other run: {name}").format(name=self.run.label) if self.run else ""

    def show(self, run: OverlayRun) -> None:
        """Draw ``run`` over today's curve (replacing an overlay already shown)."""
        self.remove()
        self.run = run
        self.plot.addItem(self.curve)
        self.legend.addItem(self.curve, self.name())
        self.redraw()

    def remove(self) -> None:
        if self.run is None:
            return
        self.legend.removeItem(self.curve)
        self.plot.removeItem(self.curve)
        self.curve.setData([], [])
        self.run = None
        place_legend(self.plot, self.legend)

    def redraw(self) -> None:
        if self.run is None:
            return
        figure = figure_in_unit(self.run.figure, self.presenter.angle_unit)
        series = figure.series[0]
        self.curve.setData(np.asarray(series.x, float), np.asarray(series.y, float))
        label = self.legend.getLabel(self.curve)
        if label is not None:
            label.setText(self.name())
        self._fit_y()
        place_legend(self.plot, self.legend)

    def _fit_y(self) -> None:
        """Both curves in view: the y range widened (never narrowed) to hold the overlay."""
        _, y = self.curve.getData()
        if y is None or not np.any(np.isfinite(y)):
            return
        vb = self.plot.getViewBox()
        lo, hi = vb.viewRange()[1]
        y_lo, y_hi = float(np.nanmin(y)), float(np.nanmax(y))
        if y_lo < lo or y_hi > hi:
            span = max(hi, y_hi) - min(lo, y_lo)
            vb.setYRange(min(lo, y_lo) - 0.05 * span, max(hi, y_hi) + 0.05 * span, padding=0.0)
