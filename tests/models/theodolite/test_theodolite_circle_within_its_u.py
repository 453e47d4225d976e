"""The theodolite's circle error, of a shape not known, taken within its U (#39's widths).

The part of the stated u per reading the readings do not exclude, u_c, is the circle's error
at the position it reads for a θ, the same in every pass. Taken at its U (within ±k·u_c at
every θ at the probability printed, k = 2 at 95.45 %; within k·u_c between any two θ for a
theodolite stated for any angle), it moves E, M and A, each a largest value less a smallest
one, by at most its range: 2k·u_c per reading, k·u_c per angle, in either direction. That
is a bias, not a scatter: the readings' own interval at the whole rest of the tail, moved
out by it, holds at the probability printed. Until then it was taken as a normal error and
sized by a union bound, z(1 − tail′/2) · 2u_c ≈ 4.8 u_c on the readings' interval at half
the rest of the tail, the widest where the theodolite is stated at exactly its pointing
noise (no circle error, readings that cannot tell it from one hidden under that noise).

The rig is tests/theodolite_passes_simulator.py (numpy only, nothing from the code it
checks); the truths are the axis' figures (the circle's errors are the measurement's).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy.stats import binom

from tests.theodolite_passes_simulator import passes_record
from tests.theodolite_run_json import run_json


def _json(capsys, tmp_path, record, stated: float, per: str = "reading") -> dict:
    return run_json(capsys, tmp_path, record, stated, per=per, tolerance=10.0,
                    tolerance_unit="arcsec", decision_rule="guarded",
                    decision_quantity="half_range")


def _widening(note: str) -> tuple[float, float, float]:
    """(shift, circle part, pair) as the figures' note states them, arcsec."""
    found = re.search(r'at least ([0-9.]+)" beyond.*?up to ([0-9.]+)" per reading.*?'
                      r'\(([0-9.]+)" between two', note)
    assert found, note
    return float(found[1]), float(found[2]), float(found[3])


@pytest.mark.parametrize("per, pair_factor", [("reading", 2.0), ("angle", math.sqrt(2.0))])
def test_the_widening_is_the_largest_range_a_circle_error_within_its_u_can_have(
        capsys, tmp_path, per, pair_factor):
    """A theodolite stated at exactly its pointing noise (0.5″ per reading, or 0.5·√2″ for
    any angle, two readings; no circle error, 2 passes over 11 θ): the widening the figures'
    note states is the range of a circle error within its U at 95.45 % at every θ, 2 · 2u_c
    per reading and 2 · √2 u_c per angle (u_c the part not excluded of a reading's share,
    as printed; #39: an angle's u is two readings'). Before: z(1 − tail′/2) · pair, 2.39 ·
    2u_c and 2.39 · u_c."""
    record = tmp_path / "r.csv"
    passes_record(record, np.random.default_rng(7), 2, 0.5, 0.6, curve="smooth",
                  theta=np.linspace(-20.0, 20.0, 11))
    stated = 0.5 if per == "reading" else 0.5 * math.sqrt(2.0)
    note = _json(capsys, tmp_path, record, stated, per)["iso230_2_figures_note"]
    shift, circle, pair = _widening(note)
    assert circle > 0.1  # a circle error of that size not excluded by 22 degrees of freedom
    assert pair == pytest.approx(pair_factor * circle, abs=2e-3)
    assert shift == pytest.approx(2.0 * pair, abs=0.011)  # printed to 0.01″


def _spread_of_e(d: np.ndarray, reversal: float, sigma: float, passes: int,
                 rng: np.random.Generator, draws: int = 4000) -> float:
    """The standard deviation of the measured E of the means over the passes: the true
    forward and backward errors plus the mean of ``passes`` readings' pointing noise at
    each θ (first principles; no circle error)."""
    true = np.concatenate([d + 0.5 * reversal, d - 0.5 * reversal])
    noisy = true + rng.normal(0.0, sigma / math.sqrt(passes), (draws, true.size))
    return float(np.std(np.ptp(noisy, axis=1), ddof=1))


def test_stated_at_its_pointing_noise_the_figures_intervals_are_narrower(capsys, tmp_path):
    """The theodolite stated at exactly its pointing noise σ = 0.5″ (no circle error), 2
    passes over 11 θ of a smooth curve, 12 runs: E's interval, whose width is mostly the
    widening for a circle error the readings cannot exclude, is at most 3.5 times (median of
    the runs) ±2 standard deviations of E itself (4 s_E, s_E by first principles from the
    rig's curve: 3.27 measured, 3.45 since E's upper end reaches the unshrunk world's pivot
    at 1/8 of the tail: cov76 F3, a spike whose mean came out low missed above), and so is
    the decided half range's against ±2 of its own (E/2; here E's interval halved). Before
    (the circle taken as a normal error, the union bound): 3.61 and 3.61 on these runs (the
    study of #39 in this cell, 60 runs: E 3.67 before, 3.31 then; the decided half range
    2.88 and 2.60)."""
    rng = np.random.default_rng(391)
    theta = np.linspace(-20.0, 20.0, 11)
    ratios: dict[str, list[float]] = {"E": [], "decided": []}
    for i in range(12):
        record = tmp_path / f"s{i}.csv"
        curves: dict = {}
        passes_record(record, rng, 2, 0.5, 0.6, curve="smooth", theta=theta, curves=curves)
        spread = _spread_of_e(curves["d"], 0.6, 0.5, 2, rng)
        out = _json(capsys, tmp_path, record, 0.5)
        e, decided = out["iso230_2_figures"]["E"], out["decided_quantity"]
        ratios["E"].append((e["interval_high"] - e["interval_low"]) / (4.0 * spread))
        ratios["decided"].append((decided["interval_high"] - decided["interval_low"])
                                 / (2.0 * spread))
    assert float(np.median(ratios["E"])) <= 3.5, ratios["E"]
    assert float(np.median(ratios["decided"])) <= 3.5, ratios["decided"]


#: the runs of the hidden circle error study in the suite: against the curve its smoke
#: version (the full 20 in tests/benchmarks/test_theodolite_studies_full.py, ``make bench``),
#: with it its whole size (no break of the product shown to fail a smaller one)
HIDDEN_RUNS = {"against_2u": 10, "with_2u": 20}
HIDDEN_FULL_RUNS = 20


@pytest.mark.slow
@pytest.mark.parametrize("shape", ["against_2u", "with_2u"])
def test_a_circle_error_at_its_u_hidden_under_the_pointing_noise_is_covered(
        capsys, tmp_path, shape):
    """:func:`check_circle_at_its_u_hidden_covered` in the suite. Against the curve, its smoke
    version: 10 runs (seed 3949), each interval's floor the binomial test's at 0.1 % (6 of
    10 at the 92.5 % printed for E and M); it still fails with no widening for the circle
    error (models.theodolite.figures.circle_part_not_excluded returning 0 in a scratch
    copy: M 3 of 10; 6 of 20 in the full form, E 11). With the curve, its whole 20 runs at
    the 1 % floor: neither that break nor the lower ends left unwidened fails it even at 20
    (E 17, M 18 of 20, floor 15), so no smaller size was shown to guard what it does."""
    runs = HIDDEN_RUNS[shape]
    check_circle_at_its_u_hidden_covered(capsys, tmp_path, shape, runs,
                                         0.001 if runs < HIDDEN_FULL_RUNS else 0.01)


def check_circle_at_its_u_hidden_covered(capsys, tmp_path, shape: str, runs: int,
                                         false_alarm: float) -> None:
    """The cell of #39's gap, with the narrower widening: pointing noise 1.5″, a circle
    error of u_c = 0.4″ at ±2u_c at the curve's extremes, against it (the measured range
    4u_c low: the upper ends) or with it (4u_c high: the lower ends), the theodolite stated
    at √(σ² + u_c²); ``runs`` runs of 5 passes over 11 θ. E's, M's, A's and the decided half
    range's intervals cover at least as often as the binomial test (``false_alarm``: 1 % in
    the long form) allows at the probability printed (the study of #39, 60 runs: 60 of 60
    in each)."""
    sigma, u_c = 1.5, 0.4
    rng = np.random.default_rng(3939 + len(shape))
    theta = np.linspace(-20.0, 20.0, 11)
    hits = {"E": 0, "M": 0, "A": 0, "decided": 0}
    probability = dict.fromkeys(hits, 1.0)
    for i in range(runs):
        record = tmp_path / f"g{i}.csv"
        truth = passes_record(record, rng, 5, sigma, 0.6, circle=u_c, circle_shape=shape,
                              curve="smooth", theta=theta)
        truth["decided"] = 0.5 * truth["E"]
        out = _json(capsys, tmp_path, record, math.hypot(sigma, u_c))
        for key in hits:
            f = out["decided_quantity"] if key == "decided" else out["iso230_2_figures"][key]
            hits[key] += f["interval_low"] - 1e-9 <= truth[key] <= f["interval_high"] + 1e-9
            probability[key] = min(probability[key], f["coverage_probability"])
    for key in hits:
        assert hits[key] >= binom.ppf(false_alarm, runs, probability[key]), (key, hits)
