"""A plot that draws any declared figure (models/plots.py): each series as a line, with
markers where asked and its ±band shaded; the legend names every labelled series."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QVBoxLayout, QWidget

from widgets.i18n import declared
from widgets.legend_placement import place_legend
from widgets.plot_grid import show_grid
from widgets.plot_range import follow_new_data


class FigurePlot(QWidget):
    """``curves`` holds the drawn series (PlotDataItems) in the figure's order, for tests
    (``getData()``)."""

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.plot = pg.PlotWidget(background="w")
        show_grid(self.plot)
        for axis in ("left", "bottom"):
            self.plot.getAxis(axis).enableAutoSIPrefix(False)
        self.legend = self.plot.addLegend(offset=(-10, 10))
        self.curves: list[pg.PlotDataItem] = []
        self._bands: list[pg.FillBetweenItem] = []
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.plot)

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        super().resizeEvent(event)
        place_legend(self.plot.getPlotItem(), self.legend)

    def clear(self) -> None:
        self.legend.clear()
        for item in self.curves + self._bands:
            self.plot.removeItem(item)
        self.curves, self._bands = [], []

    @staticmethod
    def _name(label: str) -> str | None:
        """A series' legend entry in the window's language (a run's number as it is)."""
        if not label:
            return None
        return label if label.isdigit() else declared(label)

    def show_figure(self, figure) -> None:
        self.clear()
        if figure is None:
            return
        self.plot.setTitle(declared(figure.title), size="9pt")
        self.plot.setLabel("bottom", declared(figure.x_label))
        self.plot.setLabel("left", declared(figure.y_label))
        for s in figure.series:
            colour = pg.mkColor(*s.color)
            if s.band is not None:
                ok = np.isfinite(s.y) & np.isfinite(s.band)
                upper = pg.PlotCurveItem(s.x[ok], (s.y + s.band)[ok])
                lower = pg.PlotCurveItem(s.x[ok], (s.y - s.band)[ok])
                fill = pg.FillBetweenItem(upper, lower, brush=pg.mkBrush(*s.color, 50))
                self.plot.addItem(fill)
                self._bands.append(fill)
            symbol = {"symbol": "o", "symbolSize": 6, "symbolBrush": colour,
                      "symbolPen": None} if s.markers else {}
            pen = pg.mkPen(colour, width=2, style=Qt.PenStyle.DashLine if s.dashed
                           else Qt.PenStyle.SolidLine)
            curve = self.plot.plot(s.x, s.y, pen=pen, connect="finite",
                                   name=self._name(s.label), **symbol)
            self.curves.append(curve)
        follow_new_data(self.plot.getPlotItem())
        place_legend(self.plot.getPlotItem(), self.legend)
