"""The grid every plot of the window draws, in one place."""

from __future__ import annotations

import math

import pyqtgraph as pg
from PySide6.QtGui import QFontMetrics

__all__ = ["IntegerAxis", "TEXT_COLOUR", "axis_title_height", "end_label_room",
           "keep_axis_title_room", "make_end_labels_fit", "show_grid"]

#: the plots' text (axis titles, tick labels, legends, titles): 10:1 on white. pyqtgraph's
#: own grey (150, 150, 150) is 3:1, under WCAG's 4.5:1 for text (#31)
TEXT_COLOUR = "#404040"
pg.setConfigOptions(foreground=TEXT_COLOUR)


class IntegerAxis(pg.AxisItem):
    """An axis of whole numbers (a harmonic's order): ticks at integers only, never at
    1.5 or 2.5."""

    def tickSpacing(self, minVal, maxVal, size):  # noqa: N802, N803 - pyqtgraph's names
        levels = super().tickSpacing(minVal, maxVal, size)
        out = []
        for spacing, _offset in levels:
            whole = max(1.0, float(round(spacing)))
            if all(whole != s for s, _o in out):
                out.append((whole, 0.0))
        return out

GRID_ALPHA = 0.25
# Major and minor grid lines only (a third level costs most of a paint: BENCHMARKS.md, Notes)
GRID_TICK_LEVELS = 1


def show_grid(plot, x: bool = True, y: bool = True) -> None:
    """Grid lines on a PlotItem or PlotWidget, along ``x`` and/or ``y``; the x axis' tick
    labels at its ends drawn whole (:func:`make_end_labels_fit`)."""
    plot.showGrid(x=x, y=y, alpha=GRID_ALPHA)
    for name in ("left", "bottom"):
        plot.getAxis(name).setStyle(maxTickLevel=GRID_TICK_LEVELS)
    make_end_labels_fit(plot)


#: the widest tick label an x axis makes room for at its ends: an angle's "-330.5"
END_LABEL = "-000.00"


def axis_title_length(axis) -> int:
    """The length (px) of ``axis``' title along the axis (its text, the text item's margins
    aside); 0 when it shows none."""
    if not axis.isVisible() or not axis.labelText or not axis.label.isVisible():
        return 0
    label = axis.label
    return math.ceil(label.boundingRect().width() - 2 * label.document().documentMargin())


def axis_title_height(plot) -> int:
    """The least height (px) of ``plot`` (a PlotWidget) that shows its left axis' title whole:
    the title's length, plus what the plot holds above and below that axis (the bottom axis
    with its title, a legend placed above the view, margins) as laid out now — before its
    first layout, the bottom axis' height and 20 px. The title is drawn centred on the axis:
    on an axis shorter than it, both of its ends were cut ("…uced error (")" in the polygon's
    What-if beside the docked instrument panel at 1280×720, day review 65)."""
    item = plot.getPlotItem()
    axis = item.getAxis("left")
    length = axis_title_length(axis)
    if not length:
        return 0
    along = axis.geometry().height()
    # not laid out in the widget yet: the bottom axis and a margin
    around = (plot.height() - along if 0 < along < plot.height()
              else item.getAxis("bottom").height() + 20)
    return int(math.ceil(length + max(0.0, around))) + 2


def keep_axis_title_room(panel, floor: int) -> None:
    """``panel`` (a plot tab's widget holding one PlotWidget, or that PlotWidget) at least
    ``floor`` px tall and as tall as its plot's y axis title needs
    (:func:`axis_title_height`, with what the panel holds around the plot), followed as the
    plot is laid out again (its legend moved above it, a title in another language). At
    200 % on a 1280×720 screen beside the docked instrument panel the polygon's "AC vertical
    − zero (\")" had 62 px of axis for its 131 px (day review 65). A panel of several plots
    keeps its own heights (widgets/family_simulation.py)."""
    from PySide6.QtCore import QTimer

    plots = [panel] if isinstance(panel, pg.PlotWidget) else panel.findChildren(pg.PlotWidget)
    if len(plots) != 1:
        return
    plot = plots[0]
    pending = [False]

    def keep() -> None:
        pending[0] = False
        around = 0 if plot is panel else max(0, panel.height() - plot.height())
        want = max(int(floor), axis_title_height(plot) + around)
        if panel.minimumHeight() != want:
            panel.setMinimumHeight(want)

    def later(*_) -> None:  # once the plot's layout is done, not inside it
        if not pending[0]:
            pending[0] = True
            QTimer.singleShot(0, panel, keep)  # not after the panel is gone

    plot.getPlotItem().getViewBox().sigResized.connect(later)
    later()


def end_label_room(axis) -> int:
    """Half the width (px) of :data:`END_LABEL` in ``axis``' tick font, and two pixels."""
    font = axis.style["tickFont"] or axis.font()
    return QFontMetrics(font).horizontalAdvance(END_LABEL) // 2 + 2


def make_end_labels_fit(plot) -> None:
    """A tick label centred on a tick at either end of the x axis is drawn whole: pyqtgraph
    left out, or clipped to the view's edge, any label reaching past it ("330", the last
    face's angle, was cut to "3" at the right end). The axis may draw half a label past
    each end, and the plot keeps that room at its right (the left has the y axis)."""
    item = plot.getPlotItem() if hasattr(plot, "getPlotItem") else plot
    axis = item.getAxis("bottom")
    room = end_label_room(axis)
    if getattr(axis, "end_label_room", 0) == room:
        return
    axis.end_label_room = room
    axis.prepareGeometryChange()
    left, top, _right, bottom = item.layout.getContentsMargins()
    item.layout.setContentsMargins(left, top, room, bottom)
    axis.picture = None  # drawn again, with its end labels
    axis.update()


_axis_bounds = pg.AxisItem.boundingRect


def _bounds_with_end_labels(self):
    """pyqtgraph's bounds of an axis (its labels are left out past them, and clipped to
    them), along an x axis made room for by :func:`make_end_labels_fit` half a label wider
    at each end, also where the grid is drawn (pyqtgraph then gave the view's own edges)."""
    rect = _axis_bounds(self)
    room = getattr(self, "end_label_room", 0)
    if room and self.orientation in ("top", "bottom"):
        rect = rect.united(self.mapRectFromParent(self.geometry()).adjusted(-room, 0, room, 0))
    return rect


pg.AxisItem.boundingRect = _bounds_with_end_labels



# The mouse wheel zooms a plot only once it has been clicked (it has the keyboard focus):
# scrolling a panel with the wheel passed over a plot and zoomed it away (to 0–20000°,
# #31). Unfocused, the wheel goes on to the panel, which scrolls. A zoom is undone with
# the plot menu's View All (or the "A" button in its corner).
_zoom_by_wheel = pg.ViewBox.wheelEvent


def _wheel_zooms_a_focused_plot(self, ev, axis=None):
    scene = self.scene()
    views = scene.views() if scene is not None else []
    if views and not any(view.hasFocus() for view in views):
        ev.ignore()
        return
    _zoom_by_wheel(self, ev, axis)


pg.ViewBox.wheelEvent = _wheel_zooms_a_focused_plot
