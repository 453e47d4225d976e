"""A theodolite whose u is stated for any angle measured with it (the standards table's
*Per* = angle, ``"applies_to": "angle"``) widens its figures' intervals for the circle's error
by its own u, not by twice it, as the positioning workbench does for such a reference.

The part of the stated u the readings do not show to scatter is taken as the circle's error
at each θ, the same in every pass, its shape not known. A figure (a range) moves by the
difference of the circle's errors at two θ. Stated per reading, each θ's error has standard
deviation u_c and two of them may be opposite: the difference's up to 2 u_c, and the
interval is widened by z · 2 u_c each way. Stated for any angle, that difference is one more
angle the theodolite measured: within u_c, and the widening is z · u_c.

The largest circle error such a statement allows, as a once-a-turn error over the span
c(θ) = a sin(2π (θ − θ₁)/span + φ) of unknown phase φ: the difference at two θ a span
fraction δ apart is 2a sin(πδ) cos(…), of standard deviation √2 a |sin(πδ)| over φ, largest
(√2 a) half the span apart. "The difference of two readings' errors has standard
uncertainty ≤ u_c" allows a = u_c/√2 (the simulator's ``circle`` = a/√2 = u_c/2); stated
per reading (each θ's standard deviation a/√2 ≤ u_c), a = √2 u_c, twice that.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.special import ndtri
from scipy.stats import binom

from tests.models.theodolite.test_theodolite_figures import _analysed
from tests.theodolite_passes_simulator import passes_record
from tests.theodolite_run_json import run_json

SIGMA, U_C = 0.15, 0.4
STATED = math.hypot(SIGMA, U_C)


def _json(capsys, tmp_path, record, per: str) -> dict:
    return run_json(capsys, tmp_path, record, STATED, per=per, tolerance=10.0,
                    tolerance_unit="arcsec", decision_rule="guarded",
                    decision_quantity="half_range")


def test_stated_for_any_angle_the_circle_widening_is_u_not_2u(capsys, tmp_path):
    """The same readings (a once-a-turn circle error of 0.4″ under 0.15″ pointing, 3
    passes), analysed with the theodolite's u per reading and per angle: E's upper end
    (the circle's widening k · pair_u above the readings' own interval at the rest of the
    tail: the circle within its U) comes down from k · 2u_c to k · √2 u_c′ (k = 2 at
    p = 95.45 %, u_c the largest part of u the readings do not exclude, models.theodolite
    .figures.circle_part_not_excluded, u_c′ that of each reading's share u/√2 of an angle's
    u: the pointing of both readings taken out, #39), and so do M's and A's; the decided half range's, united
    with E's halved, by half that. Before, the *Per* was not read: both the same (pair_u =
    2 u_c always); until #39's widths, z(1 − tail/2) · pair_u, tail = (1 − γ)(1 − p)/2."""
    from models.theodolite.figures import circle_part_not_excluded

    rng = np.random.default_rng(5)
    record = tmp_path / "r.csv"
    passes_record(record, rng, 3, SIGMA, 0.6, circle=U_C, circle_shape="sine", curve="bow")
    reading, angle = _json(capsys, tmp_path, record, "reading"), _json(capsys, tmp_path,
                                                                         record, "angle")
    not_excluded = circle_part_not_excluded(_analysed(record), STATED, 0.9545)
    assert U_C - 0.05 < not_excluded < STATED  # the circle's part, not excluded
    # per angle, each reading's share of u is u/√2 (an angle is two readings): the part not
    # excluded of that, √2 times it between two θ (#39: u itself, the pointing counted once)
    per_angle = math.sqrt(2.0) * circle_part_not_excluded(_analysed(record),
                                                          STATED / math.sqrt(2.0), 0.9545)
    assert 0.0 < per_angle < not_excluded
    z = float(ndtri(0.5 * (1.0 + 0.9545)))  # k: the two-sided normal factor
    less = z * (2.0 * not_excluded - per_angle)
    for key in ("E", "M", "A"):
        r, a = reading["iso230_2_figures"][key], angle["iso230_2_figures"][key]
        assert r["value"] == a["value"]
        # the circle drawn at each θ is now smaller per angle too (its u/√2 over the
        # pointing): the bootstrap's own interval moves a little with it (E, M: 0.4 %, 4 %)
        assert r["interval_high"] - a["interval_high"] == pytest.approx(less, rel=0.05)
        width_r = r["interval_high"] - r["interval_low"]
        width_a = a["interval_high"] - a["interval_low"]
        assert width_a <= width_r - 0.99 * less, key  # narrower by at least that
    # B does not see the circle (the same at a θ both ways): its interval unchanged
    assert reading["iso230_2_figures"]["B"] == angle["iso230_2_figures"]["B"]
    dr, da = reading["decided_quantity"], angle["decided_quantity"]
    # the decided value takes off the excess of the noise the budget carries: less of the
    # circle's per angle, so a little less taken off
    assert dr["value"] <= da["value"] <= dr["value"] + 0.02
    assert dr["interval_high"] - da["interval_high"] == pytest.approx(0.5 * less, rel=0.05)


#: the suite's runs (the smoke version) and the long form's (tests/benchmarks/
#: test_theodolite_studies_full.py, ``make bench``): the same check at 40 runs
SMOKE_RUNS, FULL_RUNS = 12, 40


@pytest.mark.slow
def test_stated_for_any_angle_the_narrower_interval_holds_the_largest_circle_error_allowed(
        capsys, tmp_path):
    """The smoke version of :func:`check_narrower_interval_holds_the_largest_circle_error`:
    12 runs (seed 39), each interval's floor the binomial test's at 0.1 % (8 of 12 at
    95.45 %); the widths' ratio is what the *Per* not read gives away (1.0 then, 0.70 and
    0.77 here). The full 40 runs: tests/benchmarks/test_theodolite_studies_full.py."""
    check_narrower_interval_holds_the_largest_circle_error(capsys, tmp_path, SMOKE_RUNS, 0.001)


def check_narrower_interval_holds_the_largest_circle_error(capsys, tmp_path, runs: int,
                                                           false_alarm: float) -> None:
    """``runs`` runs of 5 passes of a bowed axis curve with the largest once-a-turn circle
    error a u_c = 0.4″ stated for any angle allows (amplitude u_c/√2, the module's note), the
    phase new in every run, 0.15″ pointing: E's and the decided half range's intervals with
    *Per* = angle cover at least as often as the binomial test (``false_alarm``: 1 % in the
    long form) allows at the probability printed, and are on average at most 0.8 times as
    wide as with *Per* = reading on the same readings (measured 0.70 and 0.77 at 40 runs, 40
    and 40 covered; 1.0 before, when the *Per* was not read)."""
    rng = np.random.default_rng(39)
    hits = {"E": 0, "decided": 0}
    probability = {"E": 1.0, "decided": 1.0}
    widths: dict[str, list[tuple[float, float]]] = {"E": [], "decided": []}
    for i in range(runs):
        record = tmp_path / f"a{i}.csv"
        truth = passes_record(record, rng, 5, SIGMA, 0.6, circle=0.5 * U_C,
                              circle_shape="sine", curve="bow")
        truth["decided"] = 0.5 * truth["E"]
        angle, reading = (_json(capsys, tmp_path, record, per) for per in ("angle", "reading"))
        for key in hits:
            a = angle["decided_quantity"] if key == "decided" else angle["iso230_2_figures"][key]
            r = (reading["decided_quantity"] if key == "decided"
                 else reading["iso230_2_figures"][key])
            hits[key] += a["interval_low"] - 1e-9 <= truth[key] <= a["interval_high"] + 1e-9
            probability[key] = min(probability[key], a["coverage_probability"])
            widths[key].append((a["interval_high"] - a["interval_low"],
                                r["interval_high"] - r["interval_low"]))
    for key in hits:
        assert hits[key] >= binom.ppf(false_alarm, runs, probability[key]), (key, hits[key])
        w = np.array(widths[key])
        assert float(np.mean(w[:, 0]) / np.mean(w[:, 1])) <= 0.8, (key, w.mean(axis=0))
