"""The grid every plot of the window draws, in one place."""

from __future__ import annotations

__all__ = ["show_grid"]

GRID_ALPHA = 0.25
# Major and minor grid lines only: pyqtgraph's third level of ticks drew as many faint
# lines again, and the grid was most of a panel's paint (the fringe error panels: 70 ms
# a repaint with it, 27 ms without, on the benchmark machine).
GRID_TICK_LEVELS = 1


def show_grid(plot, x: bool = True, y: bool = True) -> None:
    """Grid lines on a PlotItem or PlotWidget, along ``x`` and/or ``y``."""
    plot.showGrid(x=x, y=y, alpha=GRID_ALPHA)
    for name in ("left", "bottom"):
        plot.getAxis(name).setStyle(maxTickLevel=GRID_TICK_LEVELS)

