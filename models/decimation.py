"""Thin a long curve for drawing without losing its excursions."""

from __future__ import annotations

import numpy as np

__all__ = ["envelope"]


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
