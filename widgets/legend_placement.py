"""Legends that never sit on the data: the legend goes to a corner of the plot where no
data point falls under it (top right first when several are free); when every corner has
data, the plot's top is raised to make room for it above the curves; and when the legend
would take over a third of a cramped plot (a small window, 200 % scale), or the plot's
aspect is locked (a Lissajous figure: raising its top pushed the figure out sideways),
its entries go above the plot, in its title line, outside the data area. Placed again whenever the
plot's view changes size (after the layout has settled, not before)."""

from __future__ import annotations

import html

import numpy as np
import pyqtgraph as pg

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
        # the data as given (getData would first thin it for display: tens of ms a curve)
        x, y = (item.xData, item.yData) if hasattr(item, "xData") else item.getData()
        if x is None or y is None or len(x) < 3:  # a two-point reference line (an envelope,
            continue                               # a mean) may run under the legend
        xs.append(np.asarray(x, float))
        ys.append(np.asarray(y, float))
    if not xs:
        return np.empty(0), np.empty(0)
    x, y = np.concatenate(xs), np.concatenate(ys)
    ok = np.isfinite(x) & np.isfinite(y)
    return x[ok], y[ok]


def _extent_y(plot_item) -> tuple[float, float] | None:
    """The lowest and highest y of everything drawn: the reference lines that ``_data``
    leaves out (an envelope) and the shaded ±bands too. Room made for the legend keeps
    them in view (the positioning plot in Chinese, whose wider legend had no free corner,
    cut off its lower envelope of A and the bottom of a band)."""
    ys = []
    for item in plot_item.listDataItems():
        y = item.yData if hasattr(item, "yData") else item.getData()[1]
        if y is not None and len(y):
            ys.append(np.asarray(y, float))
    for item in plot_item.items:
        if isinstance(item, pg.FillBetweenItem):
            for curve in getattr(item, "curves", None) or ():
                y = curve.getData()[1]
                if y is not None and len(y):
                    ys.append(np.asarray(y, float))
    if not ys:
        return None
    y = np.concatenate(ys)
    y = y[np.isfinite(y)]
    return (float(y.min()), float(y.max())) if y.size else None


def _entry_html(sample, label) -> str:
    opts = sample.item.opts
    if opts.get("pen") is not None:
        pen = pg.mkPen(opts["pen"])
        mark = "━━" if pen.style() == pg.QtCore.Qt.PenStyle.SolidLine else "╌╌"
        color = pen.color().name()
    else:
        mark, color = "●", pg.mkBrush(opts.get("symbolBrush")).color().name()
    return (f'<span style="color:{color}">{mark}</span>&nbsp;'
            f"{html.escape(label.text)}")


def _legend_above(plot_item, legend) -> None:
    """The legend's entries in the plot's title line (the figure's title kept above them)."""
    if not hasattr(plot_item, "title_before_legend"):
        title = plot_item.titleLabel
        plot_item.title_before_legend = title.text if title.isVisible() else None
    legend.setVisible(False)
    entries = "&nbsp;&nbsp; ".join(_entry_html(s, label) for s, label in legend.items
                                   if label.text)
    base = plot_item.title_before_legend
    plot_item.setTitle(f"{base}<br>{entries}" if base else entries, size="8pt")


def _legend_inside(plot_item, legend) -> None:
    if hasattr(plot_item, "title_before_legend"):
        base = plot_item.__dict__.pop("title_before_legend")
        plot_item.setTitle(base, size="9pt") if base else plot_item.setTitle(None)
    legend.setVisible(True)


def place_legend(plot_item, legend) -> str:
    """Move ``legend`` to the emptiest corner of ``plot_item`` (or above it); returns the
    corner, or ``"above"``."""
    if legend is None:
        return ""
    vb = plot_item.getViewBox()
    if not getattr(plot_item, "legend_follows_size", False):
        plot_item.legend_follows_size = True
        vb.sigResized.connect(lambda *_: place_legend(plot_item, legend))
    x, y = _data(plot_item)
    if x.size == 0:
        return ""
    (x0, x1), (y0, y1) = vb.viewRange()
    if vb.state["autoRange"][0] or not (x0 <= x.min() and x.max() <= x1):
        x0, x1 = float(x.min()), float(x.max())
    low, high = _extent_y(plot_item) or (float(y.min()), float(y.max()))
    low, high = min(low, float(y.min())), max(high, float(y.max()))
    if vb.state["autoRange"][1] or not (y0 <= low and high <= y1):
        y0, y1 = low, high
    width, height = max(vb.width(), 1.0), max(vb.height(), 1.0)
    locked = bool(vb.state.get("aspectLocked"))
    if locked:  # 1:1 (a Lissajous figure): the data's box widened to the plot's shape
        ratio = float(vb.state["aspectLocked"])
        per_pixel = max((x1 - x0) / width, (y1 - y0) * ratio / height, 1e-300)
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        x0, x1 = cx - per_pixel * width / 2, cx + per_pixel * width / 2
        y0, y1 = cy - per_pixel * height / ratio / 2, cy + per_pixel * height / ratio / 2
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
    # a cramped plot, or one whose aspect is locked (raising its top would shrink the
    # figure sideways out of the view): the legend goes above instead of hiding data
    if counts[corner] and (locked or fy >= 0.35 or y1 <= y0):
        _legend_above(plot_item, legend)  # a cramped plot: the legend would hide the data
        plot_item.legend_corner = "above"
        return "above"
    _legend_inside(plot_item, legend)
    if counts[corner]:
        # no corner is free: make room above the data (the legend then sits over nothing)
        corner = "top-right"
        vb.setYRange(y0, y0 + (y1 - y0) / (1.0 - fy), padding=0.02)
    anchor, offset = CORNERS[corner]
    legend.anchor(itemPos=anchor, parentPos=anchor, offset=offset)
    plot_item.legend_corner = corner
    return corner
