"""Legends that never sit on the data: the legend goes to a corner of the plot where no
data point falls under it (top right first when several are free); when every corner has
data, the plot's top is raised to make room for it above the curves; and when the legend
would take over a third of a cramped plot (a small window, 200 % scale), or the plot's
aspect is locked (a Lissajous figure: raising its top pushed the figure out sideways),
its entries go above the plot, in its title line, outside the data area. Placed again whenever the
plot's view changes size (after the layout has settled, not before)."""

from __future__ import annotations

import html
import math

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QTimer
from PySide6.QtGui import QFont, QFontMetricsF
from PySide6.QtWidgets import QApplication

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


def _entry(sample, label) -> tuple[str, str]:
    """(the entry as HTML, as plain text: what its width is measured by)."""
    opts = sample.item.opts
    if opts.get("pen") is not None:
        pen = pg.mkPen(opts["pen"])
        mark = "━━" if pen.style() == pg.QtCore.Qt.PenStyle.SolidLine else "╌╌"
        color = pen.color().name()
    else:
        mark, color = "●", pg.mkBrush(opts.get("symbolBrush")).color().name()
    return (f'<span style="color:{color}">{mark}</span>&nbsp;{html.escape(label.text)}',
            f"{mark} {label.text}")


def _title_width(plot_item) -> float:
    """The width the title line may take: the view's less the plot's y axis and margins
    (a title is never wider than its plot may be: pyqtgraph widens the plot to its title,
    and the view then cuts off its right, the last targets with it — review 62, F13; the
    margins include the room kept at the right for the x axis' last tick label,
    widgets/plot_grid.py make_end_labels_fit)."""
    scene = plot_item.scene()
    views = scene.views() if scene is not None else []
    width = views[0].viewport().width() if views else plot_item.width()
    left, _top, right, _bottom = plot_item.layout.getContentsMargins()
    axis = plot_item.getAxis("left")
    beside = axis.width() if axis.isVisible() else 0.0
    return max(float(width) - beside - left - right - 4.0, 60.0)


def _wrapped(entries: list[tuple[str, str]], width: float) -> str:
    """The entries on as many lines as fit ``width`` (HTML), in their order."""
    font = QFont(QApplication.font())
    font.setPointSizeF(8.0)
    metrics = QFontMetricsF(font)
    gap = metrics.horizontalAdvance("   ")
    lines: list[list[str]] = []
    used = 0.0
    for markup, plain in entries:
        need = metrics.horizontalAdvance(plain)
        if lines and used + gap + need <= width:
            lines[-1].append(markup)
            used += gap + need
        else:
            lines.append([markup])
            used = need
    return "<br>".join("&nbsp;&nbsp; ".join(line) for line in lines)


def _legend_above(plot_item, legend) -> None:
    """The legend's entries in the plot's title line (the figure's title kept above them),
    on more lines where one would be wider than the plot."""
    if not hasattr(plot_item, "title_before_legend"):
        title = plot_item.titleLabel
        plot_item.title_before_legend = title.text if title.isVisible() else None
    legend.setVisible(False)
    entries = [_entry(s, label) for s, label in legend.items if label.text]
    base = plot_item.title_before_legend
    available = width = _title_width(plot_item)
    for _ in range(4):  # measured as plain text, drawn as HTML: narrowed until it fits
        lines = _wrapped(entries, width)
        plot_item.setTitle(f"{base}<br>{lines}" if base else lines, size="8pt")
        drawn = plot_item.titleLabel.item.boundingRect().width()
        if drawn <= available or "<br>" not in lines and len(entries) < 2:
            break
        width *= 0.97 * available / drawn
    # the title's row as tall as its lines (PlotItem.setTitle holds it at 30 px, one line's:
    # the two lines of title and legend were cut at the top, gui78 / live78's positioning
    # plot "Mean positional deviation with ±2s")
    height = max(30, math.ceil(plot_item.titleLabel.item.boundingRect().height()) + 2)
    plot_item.titleLabel.setMaximumHeight(height)
    plot_item.layout.setRowFixedHeight(0, height)
    _refit(plot_item)


def _refit(plot_item) -> None:
    """The view's plots laid out to its size again, once the layout pass that placed the
    legend is over (not inside it): a plot held wider by its title's former width (the view
    clamps it to its minimum) shrinks back into view now that the title is narrower;
    nothing changes where it fits already."""
    if getattr(plot_item, "refit_pending", False):
        return
    plot_item.refit_pending = True

    def refit() -> None:
        try:
            plot_item.refit_pending = False
            scene = plot_item.scene()
        except RuntimeError:  # the plot is gone
            return
        for view in scene.views() if scene is not None else []:
            central, rect = getattr(view, "centralWidget", None), getattr(view, "range", None)
            if central is not None and rect is not None and central.geometry() != rect:
                central.setGeometry(rect)

    QTimer.singleShot(0, refit)


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
