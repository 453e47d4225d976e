"""A circle error hidden under the pointing noise (#39): the theodolite stated at u =
√(σ² + u_c²) per reading, σ = 1.5″ pointing noise and u_c = 0.4″ of circle error the same
at a θ in every pass, shaped against the axis' curve (±2u_c at its extremes: the measured
range 4u_c lower than the axis'). The readings cannot show the circle's part there (their
scatter's upper bound is above u in nearly every run), but they do not exclude it either:
the figures' widening for a circle error of the curve's worst shape is sized by the largest
part they do not exclude (models.theodolite.figures.circle_part_not_excluded)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import binom

from tests.theodolite_passes_simulator import passes_record
from tests.theodolite_run_json import run_json

SIGMA, U_C = 1.5, 0.4
RUNS = 20


@pytest.mark.slow
def test_a_circle_error_hidden_under_the_pointing_noise_is_covered(capsys, tmp_path):
    """20 runs of 5 passes (forward and backward) over 11 θ of a smooth axis curve with a
    0.6″ reversal, through ``anglebench analyze theodolite --json``: E's, M's and the decided
    half range's intervals hold the axis' true figure at least as often as the binomial
    test (1 %) allows at the probability printed (floors 15, 15 and 16 of 20). Before (the
    widening sized by the part the readings show at 95 %, 0 in nearly every run here): E
    covered 13, M 7, the half range 15 of 20; now 20, 20, 20 (the study of #39, 80 runs of
    this cell: 56, 45, 67 of 80 before, 80, 80, 80 now)."""
    rng = np.random.default_rng(391)
    theta = np.linspace(-20.0, 20.0, 11)
    hits = {"E": 0, "M": 0, "decided": 0}
    probability = dict.fromkeys(hits, 1.0)
    for i in range(RUNS):
        record = tmp_path / f"g{i}.csv"
        truth = passes_record(record, rng, 5, SIGMA, 0.6, circle=U_C,
                              circle_shape="against_2u", curve="smooth", theta=theta)
        truth["decided"] = 0.5 * truth["E"]
        out = run_json(capsys, tmp_path, record, math.hypot(SIGMA, U_C), tolerance=3.0,
                       tolerance_unit="arcsec", decision_rule="guarded",
                       decision_quantity="half_range")
        for key in hits:
            f = out["decided_quantity"] if key == "decided" else out["iso230_2_figures"][key]
            hits[key] += f["interval_low"] - 1e-9 <= truth[key] <= f["interval_high"] + 1e-9
            probability[key] = min(probability[key], f["coverage_probability"])
    for key in hits:
        assert hits[key] >= binom.ppf(0.01, RUNS, probability[key]), (key, hits)
