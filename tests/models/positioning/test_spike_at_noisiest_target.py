"""Issue 39's open shape: the curve's spike (its extreme) at the target whose σ is 3 × the
others'. The worlds of the bootstrap fit alike σ, and a spike whose mean came out low passed
for one of the crowd: E↑, E↓ and M covered 81–87 % of 150 tests through the command line
(spike78's rig) against 92–93.5 % printed, the truth above the interval in every extra miss.
The readings show that target's scatter (s ≈ 3 × the others'), and where a family-wise test
names it, its own pairs' bounds enter the upper end of the ranges of the means
(figure_intervals._noisy_target_bounds)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import binom

from models.uncertainty import figure_intervals as fi
from models.uncertainty.figure_intervals import figure_intervals

TARGETS = 13
RUNS = 5


def _axis(targets: int = TARGETS, sigma: float = 2.0):
    """The true means (up, down) and σ of an axis of ``targets`` over 0…360° (numpy only): a
    low sine of 0.2 with a spike of 1 at target m // 3, scaled to 4″ peak to peak, a constant
    reversal of 0.6 × the scale's half; σ ``sigma`` up and 1.1 × down, × 3 at the spike."""
    t = np.radians(np.linspace(0.0, 360.0, targets))
    curve = 0.2 * np.sin(t)
    spike = targets // 3
    curve[spike] += 1.0
    scale = 4.0 / np.ptp(curve)
    curve, reversal = curve * scale, 0.3 * scale
    sigma_up = np.full(targets, sigma)
    sigma_down = np.full(targets, 1.1 * sigma)
    sigma_up[spike] *= 3.0
    sigma_down[spike] *= 3.0
    return ({"up": curve + 0.5 * reversal, "down": curve - 0.5 * reversal},
            {"up": sigma_up, "down": sigma_down})


def _truth(mu) -> dict[str, float]:
    """E, E↑, E↓ and M (= Pa) of the true means, as ISO 230-2 defines them."""
    both = np.concatenate([mu["up"], mu["down"]])
    middle = 0.5 * (mu["up"] + mu["down"])
    return {"E": float(np.ptp(both)), "E_up": float(np.ptp(mu["up"])),
            "E_down": float(np.ptp(mu["down"])), "M": float(np.ptp(middle)),
            "Pa": float(np.ptp(middle))}


def _readings(mu, sigma, rng):
    """x̄, s and n per direction of one test of RUNS runs each way."""
    means, sds, runs = {}, {}, {}
    for d in ("up", "down"):
        x = mu[d] + sigma[d] * rng.standard_normal((RUNS, mu[d].size))
        means[d], sds[d] = x.mean(axis=0), x.std(axis=0, ddof=1)
        runs[d] = np.full(mu[d].size, RUNS)
    return means, sds, runs


def test_spike_at_the_noisiest_target_is_covered_above():
    """A seeded smoke of the shape (16 tests, 13 targets, σ 2″ and 6″ at the spike, 5 runs):
    before, the truth lay above the interval of E, E↑, E↓, M or Pa in 15 of the 80 figure
    tests (E 2, E↑ 2, E↓ 3, M 4, Pa 4; a correct interval misses above in about 3); with the
    spike's own bounds in none. The lower end moved down only where the spike made the
    figure: the 2 misses below (E, E↑) are as before."""
    mu, sigma = _axis()
    truth = _truth(mu)
    assert truth["E_up"] == pytest.approx(4.0) and truth["M"] == pytest.approx(4.0)
    rng = np.random.default_rng(3978)
    above = {key: 0 for key in truth}
    below = {key: 0 for key in truth}
    for test in range(16):
        intervals = figure_intervals(*_readings(mu, sigma, rng), 0.9545, seed=test)
        for key, value in truth.items():
            above[key] += value > intervals[key].high
            below[key] += value < intervals[key].low
    assert sum(above.values()) <= 2, above
    assert sum(below.values()) <= 2, below


def test_the_family_wise_test_names_an_alike_axis_at_its_level():
    """σ alike at every target of a direction (the directions 1.1 × apart): some target is
    named in at most :data:`SCATTER_OUTLIER_LEVEL` of 4000 tests beyond the binomial
    scatter, and not in far fewer (Šidák over 26 tests is near exact); one target at 3 × is
    named in most tests at 5 runs (80 % or more; each other target seldom)."""
    rng = np.random.default_rng(39)
    n = {"up": np.full(TARGETS, RUNS), "down": np.full(TARGETS, RUNS)}

    def s_drawn(factor):
        return np.sqrt(rng.chisquare(RUNS - 1, TARGETS) / (RUNS - 1)) * factor

    level = fi.SCATTER_OUTLIER_LEVEL
    named = sum(bool(np.any(fi._scatter_outliers({"up": s_drawn(1.0), "down": s_drawn(1.1)}, n,
                                                 level))) for _ in range(4000))
    assert binom.ppf(0.001, 4000, 0.5 * level) <= named <= binom.ppf(0.999, 4000, level)
    spike = np.ones(TARGETS)
    spike[TARGETS // 3] = 3.0
    found = [fi._scatter_outliers({"up": s_drawn(spike), "down": s_drawn(1.1 * spike)}, n, level)
             for _ in range(400)]
    assert sum(bool(f[TARGETS // 3]) for f in found) >= 0.8 * 400
    assert sum(int(np.sum(f)) - int(f[TARGETS // 3]) for f in found) <= 0.05 * 400


def test_nothing_changes_where_no_target_stands_out(monkeypatch):
    """σ alike and no target named: the intervals are the ones without the rule, bit for
    bit (the rule only ever acts on a named target)."""
    mu, sigma = _axis()
    sigma = {d: np.full(TARGETS, 2.0) for d in sigma}
    readings = _readings(mu, sigma, np.random.default_rng(7))
    assert not np.any(fi._scatter_outliers(readings[1], readings[2], fi.SCATTER_OUTLIER_LEVEL))
    with_rule = figure_intervals(*readings, 0.9545, seed=1)
    monkeypatch.setattr(fi, "SCATTER_OUTLIER_LEVEL", 0.0)
    without = figure_intervals(*readings, 0.9545, seed=1)
    for key in ("E", "E_up", "E_down", "M", "Pa"):
        assert (with_rule[key].low, with_rule[key].high) == (without[key].low,
                                                            without[key].high), key
