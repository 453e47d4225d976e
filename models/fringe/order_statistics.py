"""numpy's median and unique of a 1-D float array, computed as numpy computes them, without
the masked arrays that numpy's own functions import to check for one (numpy.ma: a tenth of
numpy's import, at the start-up of every command line run on a fringe record;
tests/app/test_cli_imports.py). The same values bit for bit, NaN and infinities included
(tests/models/fringe/test_fringe_records.py)."""

from __future__ import annotations

import math

import numpy as np

__all__ = ["distinct", "median"]


def median(values: np.ndarray) -> float:
    """``float(np.median(values))``: the middle of a partition, the mean of the two middle
    values of an even count, NaN when a value is NaN."""
    n = values.size
    half = n // 2
    part = np.partition(values, [half - 1, half, -1] if n % 2 == 0 else [half, -1])
    if np.isnan(part[-1]):
        return math.nan
    return float(part[half] if n % 2 else (part[half - 1] + part[half]) / 2.0)


def distinct(values: np.ndarray) -> np.ndarray:
    """``np.unique(values)``: the distinct values, sorted (an array holding NaN is left to
    numpy, which keeps one NaN)."""
    ordered = np.sort(np.ravel(values))
    if not ordered.size:
        return ordered
    if np.isnan(ordered[-1]):  # NaN sorts last
        return np.unique(ordered)
    return ordered[np.concatenate(([True], ordered[1:] != ordered[:-1]))]
