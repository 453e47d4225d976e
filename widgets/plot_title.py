"""A plot's title wrapped to the plot's width: pyqtgraph draws it on one line, centred over
the figure, and a title wider than the plot is cut at both ends (day review 67: the Live
signals window's "Rings: amplitude band (green inside, amber outer)", 305 px in a 271 px
plot on a 1280×720 screen at 150 %)."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import Qt, QTimer
from PySide6.QtGui import QTextOption

__all__ = ["TITLE_LINES", "fit_title", "set_fitting_title", "wrap_title"]

#: pyqtgraph's height of a title's row (PlotItem.setTitle), kept when one line fits
_ROW_PX = 30
#: the lines a title may take before its shorter wording is used (:func:`set_fitting_title`)
TITLE_LINES = 2


def fit_title(plot: pg.PlotWidget) -> None:
    """``plot``'s title (PlotItem.setTitle) in lines no wider than the figure below it,
    centred, its row as tall as they are; one line, as before, when it fits. Call it
    again after each ``setTitle`` (which sets the row's height back)."""
    item = plot.getPlotItem()
    label = item.titleLabel
    if not label.isVisible() or getattr(plot, "_fitting_title", False):
        return
    text = label.item
    option = QTextOption(Qt.AlignmentFlag.AlignHCenter)
    option.setWrapMode(QTextOption.WrapMode.WordWrap)  # and between CJK characters
    text.document().setDefaultTextOption(option)
    # the figure's width: the plot widget's less its y axes (not the plot item's, nor the
    # title's column: a title wider than the plot widens them past the widget)
    axes = sum(item.getAxis(side).width() for side in ("left", "right")
               if item.getAxis(side).isVisible())
    left, _top, right, _bottom = item.layout.getContentsMargins()
    room = max(40.0, plot.viewport().width() - axes - left - right - 2)
    plot._fitting_title = True  # the label's new text lays the plot out again
    try:
        for candidate in getattr(plot, "title_texts", None) or [label.text]:
            if label.text != candidate:
                label.setText(candidate)  # its size and colour kept
            text.document().setDefaultTextOption(option)
            text.setTextWidth(-1)
            natural, line = text.boundingRect().width(), text.boundingRect().height()
            text.setTextWidth(min(natural, room))
            if text.boundingRect().height() <= TITLE_LINES * line + 1:
                break
    finally:
        plot._fitting_title = False
    height = max(_ROW_PX, int(text.boundingRect().height()) + 2)
    label.setMaximumHeight(height)
    item.layout.setRowFixedHeight(0, height)
    label.updateMin()
    label.resizeEvent(None)
    if item.geometry().width() > plot.range.width() + 0.5:
        # held wider than the widget by the title's former width: laid out in it again,
        # once this layout is done
        QTimer.singleShot(0, plot, lambda: item.setGeometry(plot.range))


def set_fitting_title(plot: pg.PlotWidget, texts: list[str], **options) -> None:
    """``plot``'s title: the first of ``texts`` that :func:`fit_title` wraps to at most
    :data:`TITLE_LINES` lines of the figure's width, else the last (a shorter wording):
    at 200 % on a 1280×720 screen the Live signals' "Rings: amplitude band (green inside,
    amber outer)" wrapped to four lines in its 183 px plot and took half of it (day review
    68 F10). ``options``: PlotItem.setTitle's (size, color)."""
    plot.title_texts = list(texts)
    plot.setTitle(texts[0], **options)
    fit_title(plot)


def wrap_title(plot: pg.PlotWidget) -> None:
    """:func:`fit_title` now and whenever the plot or its item is resized."""
    plot.getPlotItem().geometryChanged.connect(lambda: fit_title(plot))
    plot.getPlotItem().getViewBox().sigResized.connect(lambda *_: fit_title(plot))
    fit_title(plot)
