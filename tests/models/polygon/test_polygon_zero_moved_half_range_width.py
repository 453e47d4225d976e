"""The decided half range where the autocollimator's zero moved between the polygon's sets
(issue 39's widths): its interval is no wider than where the zero held still, and it covers.

A set's offset moves every face of the set alike, so the mean over the sets moves by one
value at every face and the half range not at all: the budget's offsets inputs are the same
at every position (drawn once per trial in the Monte Carlo), and the zero reading's too. An
interval that took any of them per face, or added the zero's uncertainty to its ends, would
be wider with the zero moved than without. Paired runs: the same encoder curve, artefact and
noise read twice by tests/polygon_zero_jump_rig.py (numpy only, exact 3-D), once with the
zero still and once moved by N(0, 1″) at every set after the first (the audit's draw); the
rig draws the offsets with the same random numbers either way.

tests/benchmarks/polygon_zero_width_study.py is the study (smooth, rough, spike; noise 0.1,
0.5 and 2 times the half range; 12–72 faces; 200 runs a cell).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget
from models.readings.sheet import ReadingsSheet
from models.uncertainty.conformity import half_range_monte_carlo
from tests.benchmarks.polygon_zero_width_study import METADATA, SETTINGS, floor_count, rig


def _decided(lines: list[str]):
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, [r.split(",") for r in lines[1:]])
                             .parse(), SETTINGS)
    budget = polygon_budget(result, CertificateMetadata.from_dict(METADATA), SETTINGS)
    return result, half_range_monte_carlo(result.mean_corrected_arcsec, budget)


@pytest.mark.parametrize("shape, noise, faces", [("rough", 0.5, 24), ("smooth", 0.1, 12)])
def test_the_zero_moving_does_not_widen_the_decided_half_range(shape, noise, faces):
    runs = 40
    ratios, shifts, hits, moved_seen = [], [], 0, 0
    for run in range(runs):
        seed = 3900 + 17 * run
        still, truth = rig(shape, noise, faces, jump_sd=0.0).run(np.random.default_rng(seed))
        moved, truth_moved = rig(shape, noise, faces).run(np.random.default_rng(seed))
        assert np.array_equal(truth, truth_moved)  # one curve, one artefact, one noise
        _, a = _decided(still)
        result, b = _decided(moved)
        moved_seen += any("zero moved between the sets" in w for w in result.warnings)
        width_still = a.interval_high - max(0.0, a.interval_low)
        width_moved = b.interval_high - max(0.0, b.interval_low)
        assert math.isfinite(width_moved) and width_moved > 0
        ratios.append(width_moved / width_still)
        shifts.append(b.value - a.value)
        true_half = 0.5 * float(np.ptp(truth))
        hits += int(max(0.0, b.interval_low) <= true_half <= b.interval_high)
    # the zero really moved: the sets' means say so beyond their noise (at 0.5 times the
    # signal's noise a jump of N(0, 1″) is not always that far)
    assert moved_seen >= 0.75 * runs
    # the same width and value with the zero moved as with it still (the Monte Carlo's own
    # scatter apart: its seed is made from the readings, which the offsets change)
    assert 0.93 <= float(np.median(ratios)) <= 1.07, np.quantile(ratios, [0.1, 0.5, 0.9])
    assert abs(float(np.median(shifts))) <= 0.05  # of a true half range of 1″
    assert hits >= floor_count(runs, 0.9545)
