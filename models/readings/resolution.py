"""The step of readings as they were entered: the finest difference the digits typed can show.

A reading typed as 12.3 cannot tell 12.26 from 12.34; its rounding error lies within ±δ/2 of
the step δ. While the readings scatter by more than about δ/2 the rounding errors are random
from reading to reading, their variance δ²/12 is part of the observed s and averaging reduces
them (Sheppard's correction; the bias of a rounded normal mean is below 0.003 δ at σ = δ/2).
Below that the rounding is no longer random: readings of one point come out alike, their s
shrinks towards 0 and their mean carries a rounding error up to δ/2 that s does not show.
The evaluation then has to count the step as an input of its own (rectangular, half-width
δ/2; GUM 4.3.7 and F.2.2.1).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["GRID", "coarse", "readings_step", "step_counts"]

#: the finest step recognised: readings typed to at most six decimals lie on this grid
GRID = 1e-6


def readings_step(values: np.ndarray) -> float | None:
    """The step δ of readings as entered: the largest δ (a multiple of :data:`GRID`) of which
    every difference between two readings is a whole multiple; None when the readings do not
    lie on the grid (more than six decimals, or values converted from another unit) or are
    all equal (no difference to measure it by).

    With few distinct values the step found may be a multiple of the one the instrument
    shows (readings 0.1, 0.3, 0.5 give 0.2): it is then the step of what was entered, which
    is what the evaluation can use."""
    v = np.asarray(values, dtype=float)
    v = v[np.isfinite(v)]
    if v.size < 2 or np.any(np.abs(v) >= 2.0**53 * GRID):  # beyond whole steps of the grid
        return None
    scaled = v / GRID
    whole = np.round(scaled)
    if np.any(np.abs(scaled - whole) > 1e-3):
        return None
    steps = np.abs(whole - whole[0]).astype(np.int64)
    g = int(np.gcd.reduce(steps))
    return g / round(1.0 / GRID) if g else None  # (g * GRID: 3.5999999999999996)


def step_counts(step: float | None, pooled_s: float) -> bool:
    """Whether the step of readings whose pooled standard deviation is ``pooled_s`` is to be
    counted in U as an input of its own (s < δ): between δ/2 and δ the rounding is random
    but a target's few readings still come out alike often enough (five at σ = δ/2: s = 0 at
    many targets, and U covered 85–91 % of means without the step)."""
    return step is not None and math.isfinite(pooled_s) and pooled_s < step


def coarse(step: float | None, pooled_s: float) -> bool:
    """Whether readings of step ``step`` whose pooled standard deviation is ``pooled_s`` are
    rounded coarser than they scatter (s < δ/2): their rounding is then not random."""
    return step is not None and math.isfinite(pooled_s) and pooled_s < 0.5 * step
