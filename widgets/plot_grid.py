"""The grid every plot of the window draws, in one place."""

from __future__ import annotations

import pyqtgraph as pg

__all__ = ["IntegerAxis", "TEXT_COLOUR", "show_grid"]

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
    """Grid lines on a PlotItem or PlotWidget, along ``x`` and/or ``y``."""
    plot.showGrid(x=x, y=y, alpha=GRID_ALPHA)
    for name in ("left", "bottom"):
        plot.getAxis(name).setStyle(maxTickLevel=GRID_TICK_LEVELS)



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
