"""An assessor reproduces A's, A↑'s, A↓'s, P's and R↑'s intervals from the certificate's own
words (day review 68 F1: the certificate described the bootstrap and the numbers came from
each target's bounds; models/positioning/report.py states the method now).

The certificate says, for A, A↑, A↓ and P: "each end of a target's band (x̄ ± 2s for A; for
P, x̄ ± 1.5s of one direction with 1.5 times the other direction's σ added, that σ bounded
by chi-square) by its one-sided tolerance bound, from the noncentral t distribution with
ν = n − 1 (Owen 1968; ISO 16269-6); its upper end the largest bound of a band's top less the
smallest bound of a band's bottom (… each bound at the whole tail …), its lower end from
every target's bounds in both directions taken at once (Šidák over the targets and
directions, for P over the targets, Bonferroni within each)"; for R↑ and Ps: "the bounds
from each target's own standard deviation (chi-square, ν = n − 1): its upper end the largest
of the targets' upper bounds, its lower end the largest of their lower bounds taken at once
over the targets (Šidák)", Ps = 3(σ↑ + σ↓) by the sum of a target's two bounds. Computed
here from those words with scipy alone, from readings simulated by
tests/uneven_sigma_axes.py, and compared with the intervals the workbench prints (no Type B
input: no widening)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import chi2, nct

from models.uncertainty.figure_intervals import figure_intervals
from tests.uneven_sigma_axes import positioning_test, summary_stats

PROBABILITY = 0.9545
TAIL = 0.5 * (1.0 - PROBABILITY)


def _end(x, s, n, reach: float, tail: float, upper: bool) -> np.ndarray:
    """One-sided tolerance bound of μ + reach·σ (Owen 1968): √n (μ + rσ − x̄)/s ~ t′(ν, r√n)."""
    root = np.sqrt(n)
    if reach >= 0:
        return x + s * nct.ppf(1 - tail if upper else tail, n - 1, reach * root) / root
    return x - s * nct.ppf(tail if upper else 1 - tail, n - 1, -reach * root) / root


def _sigma(s, n, tail: float, upper: bool) -> np.ndarray:
    """One-sided chi-square bound of σ: ν s²/σ² ~ χ²_ν."""
    nu = n - 1
    return s * np.sqrt(nu / chi2.ppf(tail if upper else 1 - tail, nu))


def _a(x, s, n, directions) -> tuple[float, float]:
    count = sum(x[d].size for d in directions)
    top = max(_end(x[d], s[d], n[d], 2, TAIL, True).max() for d in directions)
    bottom = min(_end(x[d], s[d], n[d], -2, TAIL, False).min() for d in directions)
    each = 1 - (1 - TAIL) ** (1 / count)  # Šidák over the targets and directions
    top_low = max(_end(x[d], s[d], n[d], 2, each / 2, False).max() for d in directions)
    bottom_high = min(_end(x[d], s[d], n[d], -2, each / 2, True).min() for d in directions)
    return max(top_low - bottom_high, 0.0), top - bottom


def _p(x, s, n) -> tuple[float, float]:
    def edge(k, tail, outward):
        toward_upper = outward if k > 0 else not outward
        terms = [_end(x[d], s[d], n[d], k, tail, toward_upper)
                 + k * _sigma(s[o], n[o], tail, outward)
                 for d, o in (("up", "down"), ("down", "up"))]
        return np.maximum(*terms) if k > 0 else np.minimum(*terms)

    each = (1 - (1 - TAIL) ** (1 / x["up"].size)) / 4  # four band ends a target
    high = edge(1.5, TAIL, True).max() - edge(-1.5, TAIL, True).min()
    low = edge(1.5, each, False).max() - edge(-1.5, each, False).min()
    return max(low, 0.0), high


@pytest.mark.parametrize(("pattern", "runs"), [("triple", 3), ("varying", 5)])
def test_the_band_figures_intervals_are_reproduced_from_the_words_of_the_certificate(
        pattern, runs):
    readings, _ = positioning_test(pattern, 12, runs, np.random.default_rng(6868))
    x, s, n = summary_stats(readings)
    n = {k: v.astype(float) for k, v in n.items()}
    found = figure_intervals(x, s, n, PROBABILITY, seed=68, trials=200, outer=0, inner=0)
    each_target = 1 - (1 - TAIL) ** (1 / x["up"].size)
    expected = {"A": _a(x, s, n, ("up", "down")), "A_up": _a(x, s, n, ("up",)),
                "A_down": _a(x, s, n, ("down",)), "P": _p(x, s, n),
                "R_up": (4 * _sigma(s["up"], n["up"],
                                    1 - (1 - TAIL) ** (1 / x["up"].size), False).max(),
                         4 * _sigma(s["up"], n["up"], TAIL, True).max()),
                "Ps_max": (3 * (_sigma(s["up"], n["up"], each_target, False)
                                + _sigma(s["down"], n["down"], each_target, False)).max(),
                           3 * (_sigma(s["up"], n["up"], TAIL, True)
                                + _sigma(s["down"], n["down"], TAIL, True)).max())}
    for key, (low, high) in expected.items():
        assert found[key].low == pytest.approx(low, rel=1e-9, abs=1e-12), key
        assert found[key].high == pytest.approx(high, rel=1e-9, abs=1e-12), key
        assert found[key].probability == PROBABILITY  # held by construction, as printed
