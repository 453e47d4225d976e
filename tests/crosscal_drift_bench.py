"""The drift tests' bench and analysis (tests/models/crosscal/test_crosscal_unchecked_drift.py,
test_crosscal_drift_left_in.py): a 12-face polygon on tests/crosscal_simulator.py's bench
(numpy only), its readings analysed as a user's file would be, with no tilt and no scale
error so that the drift alone moves the results. The bench's vertical readings are given
(its own, noise and all): they identify each mounting's tilt (none: the polygon is seated
square), so no tilt bound enters U — a bound of 0 where a tilt is not identified is
refused, and any real bound would widen the U these tests hold to the drift."""

from __future__ import annotations

import numpy as np

from models.readings.sheet import ReadingsSheet
from models.registry import KINDS
from tests.crosscal_simulator import Bench

KIND = KINDS["crosscal"]
HARMONICS = {1: (0.8, 0.3), 2: (0.6, 1.1), 3: (0.4, 2.0), 4: (0.3, 0.7), 5: (0.2, 1.5)}
N = 12


class VerticalBench(Bench):
    """The bench read in both axes: its rows carry the vertical readings too (the same
    random stream: the bench draws both readings' noise either way)."""

    def rows(self, mountings, closure=True, vertical: bool = True) -> list[tuple]:
        return super().rows(mountings, closure, vertical)


def bench(seed: int, **kw) -> Bench:
    """A bench of ``N`` faces whose deviations are drawn from ``seed`` (its own stream)."""
    dev = np.random.default_rng(800 + seed).normal(0.0, 0.5, N)
    return VerticalBench(N, HARMONICS, dev, rng=np.random.default_rng(seed), **kw)


def analyze(rows, **settings):
    """The bench's ``rows`` analysed with the workbench's defaults and ``settings``."""
    text = [[str(j), str(i), f"{a:.9f}", f"{x:.6f}", f"{y:.6f}"] for j, i, a, x, y in rows]
    parsed = ReadingsSheet(KIND.columns, text).parse()
    # no tilt (the bench seats the polygon square; its vertical readings show it), no scale
    # error: the drift alone
    return KIND.analyze(parsed, {**KIND.default_settings, "ac_scale_pct": 0.0, **settings})
