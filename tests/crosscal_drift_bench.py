"""The drift tests' bench and analysis (tests/models/crosscal/test_crosscal_unchecked_drift.py,
test_crosscal_drift_left_in.py): a 12-face polygon on tests/crosscal_simulator.py's bench
(numpy only), its readings analysed as a user's file would be, with no tilt and no scale
error so that the drift alone moves the results."""

from __future__ import annotations

import numpy as np

from models.readings.sheet import ReadingsSheet
from models.registry import KINDS
from tests.crosscal_simulator import Bench

KIND = KINDS["crosscal"]
HARMONICS = {1: (0.8, 0.3), 2: (0.6, 1.1), 3: (0.4, 2.0), 4: (0.3, 0.7), 5: (0.2, 1.5)}
N = 12


def bench(seed: int, **kw) -> Bench:
    """A bench of ``N`` faces whose deviations are drawn from ``seed`` (its own stream)."""
    dev = np.random.default_rng(800 + seed).normal(0.0, 0.5, N)
    return Bench(N, HARMONICS, dev, rng=np.random.default_rng(seed), **kw)


def analyze(rows, **settings):
    """The bench's ``rows`` analysed with the workbench's defaults and ``settings``."""
    text = [[str(j), str(i), f"{a:.9f}", f"{x:.6f}", ""] for j, i, a, x in rows]
    parsed = ReadingsSheet(KIND.columns, text).parse()
    # no tilt (the bench seats the polygon square), no scale error: the drift alone
    return KIND.analyze(parsed, {**KIND.default_settings, "ac_scale_pct": 0.0,
                                 "tilt_bound_arcsec": 0.0, **settings})
