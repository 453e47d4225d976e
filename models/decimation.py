"""Thin a long curve for drawing without losing its excursions."""

from __future__ import annotations

import numpy as np

__all__ = ["envelope", "one_per_cell"]


def envelope(x, y, bins: int = 1500) -> tuple[np.ndarray, np.ndarray]:
    """A curve thinned for drawing: the samples are split into ``bins`` consecutive runs
    and each run keeps its lowest and its highest point, in their order, so the drawn
    line covers every sample's excursion. Curves of up to 2·bins points come back as is.
    """
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if x.size <= 2 * bins:
        return x, y
    run = -(-x.size // bins)  # ceil: the last run may be shorter
    bins = -(-x.size // run)
    pad = run * bins - x.size
    ys = np.concatenate([y, np.full(pad, y[-1])]) if pad else y  # repeat the last sample
    ys = ys.reshape(bins, run)
    lo, hi = np.argmin(ys, axis=1), np.argmax(ys, axis=1)
    start = np.arange(bins) * run
    first = np.minimum(start + np.minimum(lo, hi), x.size - 1)
    second = np.minimum(start + np.maximum(lo, hi), x.size - 1)
    index = np.column_stack([first, second]).ravel()
    return x[index], y[index]


def one_per_cell(x, y, cells: int = 256) -> np.ndarray:
    """The indices of a scatter thinned for drawing: one sample of each occupied cell of a
    ``cells`` × ``cells`` grid over the points' range, in their order. Every point lands
    in a drawn cell, so an outlier (a spike typed over one sample) is always drawn, and a
    million samples on a ring become about a thousand points."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    if x.size <= 2 * cells:
        return np.arange(x.size)

    def cell(v: np.ndarray) -> np.ndarray:
        low, span = float(np.min(v)), float(np.ptp(v))
        if not span > 0:
            return np.zeros(v.size, dtype=np.intp)
        return np.minimum(((v - low) * (cells / span)).astype(np.intp), cells - 1)
    index = cell(x) * cells + cell(y)
    chosen = np.full(cells * cells, x.size, dtype=np.intp)
    chosen[index] = np.arange(x.size)  # one of each cell's samples (which one is numpy's)
    return np.sort(chosen[chosen < x.size])
