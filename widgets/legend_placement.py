"""Legends that never sit on the data: the legend goes to a corner of the plot where no
data point falls under it (top right first when several are free); when every corner has
data, the plot's top is raised to make room for it above the curves (unless the legend
would take over a third of a cramped plot: then the corner with the fewest points)."""

from __future__ import annotations

import numpy as np

__all__ = ["CORNERS", "place_legend"]

# corner -> (anchor of the legend and of the plot, offset in pixels)
CORNERS = {
    "top-right": ((1, 0), (-10, 10)),
    "top-left": ((0, 0), (10, 10)),
    "bottom-right": ((1, 1), (-10, -10)),
    "bottom-left": ((0, 1), (10, -10)),
}


def _data(plot_item) -> tuple[np.ndarray, np.ndarray]:
    xs, ys = [], []
    for item in plot_item.listDataItems():
        x, y = item.getData()
        if x is None or y is None or len(x) < 3:  # a two-point reference line (an envelope,
            continue                               # a mean) may run under the legend
        xs.append(np.asarray(x, float))
        ys.append(np.asarray(y, float))
    if not xs:
        return np.empty(0), np.empty(0)
    x, y = np.concatenate(xs), np.concatenate(ys)
    ok = np.isfinite(x) & np.isfinite(y)
    return x[ok], y[ok]


def place_legend(plot_item, legend) -> str:
    """Move ``legend`` to the emptiest corner of ``plot_item``; returns the corner."""
    x, y = _data(plot_item)
    vb = plot_item.getViewBox()
    if x.size == 0 or legend is None:
        return ""
    (x0, x1), (y0, y1) = vb.viewRange()
    if vb.state["autoRange"][0] or not (x0 <= x.min() and x.max() <= x1):
        x0, x1 = float(x.min()), float(x.max())
    if vb.state["autoRange"][1] or not (y0 <= y.min() and y.max() <= y1):
        y0, y1 = float(y.min()), float(y.max())
    width, height = max(vb.width(), 1.0), max(vb.height(), 1.0)
    box = legend.boundingRect()
    fx = min(0.9, (box.width() + 20) / width)  # the legend's share of the plot, with margin
    fy = min(0.9, (box.height() + 20) / height)
    u = (x - x0) / (x1 - x0) if x1 > x0 else np.full(x.size, 0.5)
    v = (y1 - y) / (y1 - y0) if y1 > y0 else np.full(y.size, 0.5)  # 0 at the top
    counts = {
        "top-right": int(np.sum((u >= 1 - fx) & (v <= fy))),
        "top-left": int(np.sum((u <= fx) & (v <= fy))),
        "bottom-right": int(np.sum((u >= 1 - fx) & (v >= 1 - fy))),
        "bottom-left": int(np.sum((u <= fx) & (v >= 1 - fy))),
    }
    corner = min(CORNERS, key=lambda c: counts[c])  # dict order breaks ties: top right first
    if counts[corner] and y1 > y0 and fy < 0.35:
        # no corner is free: make room above the data (the legend then sits over nothing)
        corner = "top-right"
        vb.setYRange(y0, y0 + (y1 - y0) / (1.0 - fy), padding=0.02)
    anchor, offset = CORNERS[corner]
    legend.anchor(itemPos=anchor, parentPos=anchor, offset=offset)
    plot_item.legend_corner = corner
    return corner
