"""The log after compensation on the positioning workbench (models/positioning/before_after.py):
its mean deviation per target and direction drawn dashed orange over today's on the
"Deviation per target" plot, labelled "after compensation: <name>", and one line in the
results text with A, B, E (M, R) before → after. It follows the angle unit, stays while
today's readings change (compared again each time) and is removed on demand."""

from __future__ import annotations

from typing import Any

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt

from models.positioning.before_after import AFTER_COLOUR, after_figure, before_after
from models.positioning.model import PositioningResult
from widgets.i18n import explained, tr
from widgets.legend_placement import place_legend

__all__ = ["AfterCompensation"]


class AfterCompensation:
    """The comparison of one positioning presenter (``curves``: the drawn PlotDataItems,
    ↑ then ↓, for tests)."""

    def __init__(self, presenter: Any) -> None:
        self.presenter = presenter
        self.after: PositioningResult | None = None
        self.label = ""
        self.curves: list[pg.PlotDataItem] = []
        self.line = ""  # the results text's line, as last shown
        presenter.analysed.connect(self.redraw)  # new readings, unit or language

    @property
    def shown(self) -> bool:
        return self.after is not None

    @property
    def _figure_plot(self):
        return self.presenter.view.deviation_plot

    def show(self, after: PositioningResult, label: str) -> None:
        self.remove()
        self.after, self.label = after, label
        self.redraw()

    def remove(self) -> None:
        if self.after is None:
            return
        self._clear_curves()
        self.after, self.label = None, ""
        if self.line:
            view = self.presenter.view
            view.set_summary(view.summary.toPlainText().replace("\n" + self.line, ""))
            self.line = ""

    def _clear_curves(self) -> None:
        if not self.curves:
            return
        plot = self._figure_plot
        for curve in self.curves:
            plot.legend.removeItem(curve)
            plot.plot.removeItem(curve)
        self.curves = []

    def redraw(self) -> None:
        """Draw the curves again and add the comparison line to the results text (which
        the presenter has just written afresh)."""
        self._clear_curves()
        self.line = ""
        if self.after is None:
            return
        figure = self.presenter.in_unit(after_figure(self.after))[0]
        plot = self._figure_plot
        for s in figure.series:
            curve = pg.PlotDataItem(np.asarray(s.x, float), np.asarray(s.y, float),
                                    pen=pg.mkPen(pg.mkColor(*AFTER_COLOUR), width=2,
                                                 style=Qt.PenStyle.DashLine),
                                    symbol="t1" if s.label == "↑" else "t", symbolSize=6,
                                    symbolBrush=pg.mkColor(*AFTER_COLOUR), symbolPen=None,
                                    connect="finite")
            curve.setZValue(-1)  # today's run over the other
            plot.plot.addItem(curve)
            plot.legend.addItem(curve, tr("after compensation: {name}").format(name=self.label)
                                + f" {s.label}")
            self.curves.append(curve)
        place_legend(plot.plot.getPlotItem(), plot.legend)
        result = self.presenter.result
        if result is None:
            return
        try:
            text = before_after(result, self.after).text(self.label)
        except ValueError as exc:
            text = tr("Not compared with the log after compensation: {reason}").format(
                reason=explained(exc))
        self.line = self.presenter.in_unit_text(text)
        view = self.presenter.view
        view.set_summary(view.summary.toPlainText() + "\n" + self.line)
