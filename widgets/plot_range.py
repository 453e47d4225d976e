"""Plots show their data: new data re-range the view; a user's zoom or drag is kept only
while the data stay the same (a redraw in another language or unit of the same readings,
a resize). Before #31 one accidental drag, or the legend's room made above the curves,
turned pyqtgraph's auto-range off for good: the next file, a Send to positioning or a
new run typed after File › New landed off-screen, and Print printed an empty plot."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg

from widgets.i18n import live, tr

__all__ = ["EMPTY_RANGE", "data_bounds", "follow_new_data", "has_data", "show_data_if_hidden",
           "show_if_empty"]

SAMPLED = 997  # values of a curve read for its fingerprint (a long record has millions)
#: the view of a plot with nothing to draw (x, y; x is pyqtgraph's): its auto-range of no
#: point showed a y axis of ±5e-05 (#41 review)
EMPTY_RANGE = ((0.0, 1.0), (-1.0, 1.0))


def _values(item) -> list[np.ndarray]:
    if isinstance(item, pg.BarGraphItem):
        return [np.asarray(item.opts.get(k) if item.opts.get(k) is not None else [], float)
                for k in ("x", "height", "y0")]
    x, y = (item.xData, item.yData) if hasattr(item, "xData") else item.getData()
    return [np.asarray(x if x is not None else [], float),
            np.asarray(y if y is not None else [], float)]


def _fingerprint(items) -> tuple:
    """A cheap stand-in for the data: sizes, ends and a strided sample of every array."""
    out = []
    for item in items:
        for values in _values(item):
            flat = values.ravel()
            if flat.size == 0:
                out.append(0)
                continue
            sample = flat[:: max(1, flat.size // SAMPLED)]
            out.append((flat.size, float(flat[0]), float(flat[-1]),
                        float(np.nansum(sample)), int(np.isnan(sample).sum())))
    return tuple(out)


def _items(plot_item) -> list:
    return [i for i in plot_item.items
            if isinstance(i, pg.PlotDataItem | pg.BarGraphItem)]


def has_data(plot_item) -> bool:
    """Whether any curve or bar of ``plot_item`` has a finite point to draw."""
    for item in _items(plot_item):
        values = _values(item)
        if isinstance(item, pg.BarGraphItem):
            x, height = values[0], values[1]
            if x.size and height.size and np.isfinite(height).any():
                return True
            continue
        x, y = (v.ravel() for v in values)
        if not x.size or x.size != y.size:
            continue
        stride = max(1, x.size // SAMPLED)  # a long record: a sample first
        if (np.isfinite(x[::stride]) & np.isfinite(y[::stride])).any() or \
                (np.isfinite(x) & np.isfinite(y)).any():
            return True
    return False


def show_if_empty(plot_item) -> bool:
    """With nothing to draw, ``plot_item`` shows a neutral view (:data:`EMPTY_RANGE`) and
    "No data" in its middle, not pyqtgraph's auto-range of no point (a y axis of ±5e-05);
    with data again, the placeholder hidden and the view ranged on them. Returns whether
    it is empty."""
    vb = plot_item.getViewBox()
    text = getattr(vb, "empty_text", None)
    if has_data(plot_item):
        if text is not None and text.isVisible():
            text.hide()
            vb.enableAutoRange(y=True)  # the data ranged afresh, as at the start
        return False
    if text is None:
        text = pg.TextItem(color=(128, 128, 128), anchor=(0.5, 0.5))
        live(text.setText, tr("No data"))
        plot_item.addItem(text, ignoreBounds=True)
        vb.empty_text = text
    # y only: x is left to pyqtgraph (an x range set here, on a panel x-linked to another,
    # clipped the other's curves to it)
    y0, y1 = EMPTY_RANGE[1]
    vb.enableAutoRange(y=False)
    vb.setYRange(y0, y1, padding=0.0)
    x0, x1 = vb.viewRange()[0]
    text.setPos((x0 + x1) / 2, (y0 + y1) / 2)
    text.show()
    return True


def follow_new_data(plot_item, y: bool = True) -> bool:
    """Call after giving ``plot_item``'s curves their data: when they differ from the data
    it last showed, the view is ranged on them again (pyqtgraph's auto-range on both
    axes; on x only with ``y=False``, for a plot that ranges y itself); the same data
    keep the view as the user left it. Returns whether the data were new."""
    vb = plot_item.getViewBox()
    now = _fingerprint(_items(plot_item))
    if getattr(vb, "data_fingerprint", None) == now:
        return False
    vb.data_fingerprint = now
    if show_if_empty(plot_item):
        return True
    vb.enableAutoRange(x=True, y=True) if y else vb.enableAutoRange(x=True)
    return True


def data_bounds(plot_item) -> tuple[float, float, float, float] | None:
    """(x0, x1, y0, y1) of every finite point of ``plot_item``'s curves, None when empty."""
    xs, ys = [], []
    for item in plot_item.listDataItems():
        x, y = (item.xData, item.yData) if hasattr(item, "xData") else item.getData()
        if x is None or y is None or len(x) == 0:
            continue
        x, y = np.asarray(x, float), np.asarray(y, float)
        ok = np.isfinite(x) & np.isfinite(y)
        if ok.any():
            xs.append(x[ok])
            ys.append(y[ok])
    if not xs:
        return None
    x, y = np.concatenate(xs), np.concatenate(ys)
    return float(x.min()), float(x.max()), float(y.min()), float(y.max())


def show_data_if_hidden(widget) -> int:
    """Every plot inside ``widget`` whose view shows none of its data is ranged on it (a
    printout never shows an empty frame); returns how many were."""
    count = 0
    for view in widget.findChildren(pg.GraphicsView):
        for item in view.scene().items():
            if not isinstance(item, pg.PlotItem):
                continue
            (vx0, vx1), (vy0, vy1) = item.getViewBox().viewRange()
            points = [(np.asarray(x, float), np.asarray(y, float)) for x, y in
                      ((d.xData, d.yData) if hasattr(d, "xData") else d.getData()
                       for d in item.listDataItems()) if x is not None and y is not None]
            if not any(np.any(np.isfinite(x) & np.isfinite(y)) for x, y in points):
                continue
            if not any(np.any((x >= vx0) & (x <= vx1) & (y >= vy0) & (y <= vy1))
                       for x, y in points):
                item.getViewBox().autoRange()
                count += 1
    return count
