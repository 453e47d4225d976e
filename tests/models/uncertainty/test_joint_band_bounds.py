"""The level of the band figures' bounds, computed by numerical integration with scipy
alone (#39: the widths of A's, A↑'s, A↓'s, P's and Ps_max's intervals).

A's upper end is Û_i − L̂_j, Û_i = x̄_i + F s_i the one-sided tolerance bound of
U_i = μ_i + 2σ_i (noncentral t, Owen 1968) and L̂_j the one of L_j = μ_j − 2σ_j, at the two
targets (fixed, unknown) that make the figure. Until 0.8.17 each was taken at half the tail
(Bonferroni). The two are independent (two targets, or two directions) or the same target's
(A = 4σ_i), and the miss of their difference is a function of σ_j/σ_i alone: it tends to the
tail of one bound where one σ is much the larger (the other term's error then counts for
nothing) and is below it in between, so each bound at the WHOLE tail holds the pair at 1 −
tail, exactly at the least favourable ratio. Likewise P's band end μ_a + 1.5σ_a + 1.5σ_b
(one direction's tolerance bound plus 1.5 times the other direction's chi-square bound of
σ), which until 0.8.17 split its tail over its two terms (and over the two directions,
though only the direction that makes the end needs its bound), and Ps = 3(σ↑ + σ↓). The
integrals are over the chi distribution of s/σ on a grid of normal scores (both tails to
8 standard deviations), the normal part in closed form."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.special import chdtr, chdtri, nctdtrit, ndtr

from models.uncertainty.figure_intervals import figure_intervals

PROBABILITY = 0.9545
TAIL = 0.5 * (1.0 - PROBABILITY)
RATIOS = np.exp(np.linspace(-9.0, 9.0, 25))  # σ_b / σ_a
#: where the two terms are alike in law (A's pair, Ps) the miss at σ_b/σ_a is the one at its
#: inverse
HALF_RATIOS = RATIOS[RATIOS <= 1.0 + 1e-12]


def _chi_grid(nu: int) -> tuple[np.ndarray, np.ndarray]:
    """Nodes S = s/σ (χ_ν/√ν) at normal scores −8 … 8 and their probability weights."""
    z = np.linspace(-8.0, 8.0, 801)
    w = np.exp(-0.5 * z**2) / np.sqrt(2.0 * np.pi) * (z[1] - z[0])
    q = np.where(z < 0, chdtri(nu, 1.0 - ndtr(z)), chdtri(nu, ndtr(-z)))
    return np.sqrt(q / nu), w / w.sum()


def _tolerance_factor(n: int, reach: float, level: float) -> float:
    return float(nctdtrit(n - 1, reach * np.sqrt(n), level) / np.sqrt(n))


def _sigma_factor(n: int, tail: float, upper: bool) -> float:
    nu = n - 1
    return float(np.sqrt(nu / chdtri(nu, 1.0 - tail if upper else tail)))


def _miss_band_end(n: int, f: float, g: float, upper: bool, ratio: float) -> float:
    """P(the bound x̄_a + f s_a + 1.5 g s_b on the wrong side of μ_a + 1.5σ_a + 1.5σ_b),
    σ_a = 1, σ_b = ``ratio``. Up to ratio 1 the mean's error Z/√n in closed form (normal) and
    both S on the grid; above it, where the σ_b term makes the miss a step in S_b, S_b in
    closed form (chi-square) and Z, S_a on the grid."""
    s, w = _chi_grid(n - 1)
    nu = n - 1
    if ratio <= 1.0:
        gap = (f * s[:, None] + ratio * 1.5 * g * s[None, :] - 1.5 - 1.5 * ratio)
        p = ndtr(-gap * np.sqrt(n)) if upper else ndtr(gap * np.sqrt(n))
        return float(np.sum(w[:, None] * w[None, :] * p))
    z = np.linspace(-8.0, 8.0, 401)
    wz = np.exp(-0.5 * z**2)
    wz /= wz.sum()
    rest = (1.5 + 1.5 * ratio - z[:, None] / np.sqrt(n) - f * s[None, :]) / (ratio * 1.5 * g)
    below = np.where(rest > 0.0, chdtr(nu, nu * np.maximum(rest, 0.0) ** 2), 0.0)
    return float(np.sum(wz[:, None] * w[None, :] * (below if upper else 1.0 - below)))


def _miss_pair(n: int, factor: float, ratio: float) -> float:
    """A's pair: (x̄_i + F s_i) − (x̄_j − F s_j) below (μ_i + 2σ_i) − (μ_j − 2σ_j), σ_i = 1,
    σ_j = ratio, the two means' errors together normal with variance (1 + ratio²)/n."""
    s, w = _chi_grid(n - 1)
    sa, sb = s[:, None], s[None, :]
    gap = factor * (sa + ratio * sb) - 2.0 * (1.0 + ratio)
    return float(np.sum(w[:, None] * w[None, :]
                        * ndtr(-gap * np.sqrt(n) / np.sqrt(1.0 + ratio**2))))


@pytest.mark.parametrize("n", [3, 5, 10])
def test_a_pair_of_band_ends_each_at_the_whole_tail_holds_at_it_exactly(n):
    factor = _tolerance_factor(n, 2.0, 1.0 - TAIL)
    misses = np.array([_miss_pair(n, factor, r) for r in HALF_RATIOS])
    assert misses.max() <= TAIL * 1.002, misses.max() / TAIL
    assert misses[0] >= TAIL * 0.99  # exact: no slack left at the least favourable ratio
    # the same target and direction making both ends (A = 4σ): 2F s ≥ 4σ
    same = float(chdtr(n - 1, (n - 1) * (2.0 / factor) ** 2))
    assert same <= TAIL


@pytest.mark.parametrize("n", [3, 5, 10])
@pytest.mark.parametrize("tail", [TAIL, 1e-3])
def test_a_vdi_band_end_with_the_other_directions_sigma_holds_at_its_tail_exactly(n, tail):
    """μ_a + 1.5σ_a + 1.5σ_b by x̄_a + F s_a + 1.5 G s_b, F and G each at the whole tail:
    the upper bound (P's upper end, ``tail`` its half) and the lower one (its lower end,
    every target at once: a small tail)."""
    for upper in (True, False):
        level = 1.0 - tail if upper else tail
        f = _tolerance_factor(n, 1.5, level)
        g = _sigma_factor(n, tail, upper)
        misses = np.array([_miss_band_end(n, f, g, upper, r) for r in RATIOS])
        assert misses.max() <= tail * 1.002, (upper, misses.max() / tail)
        assert min(misses[0], misses[-1]) >= tail * 0.98, (upper, misses[0] / tail,
                                                          misses[-1] / tail)


@pytest.mark.parametrize("n", [3, 5, 10])
@pytest.mark.parametrize("tail", [TAIL, 1e-3])
def test_a_sum_of_two_sigmas_by_its_two_bounds_at_the_whole_tail_holds_at_it_exactly(n, tail):
    """Ps = 3(σ↑ + σ↓): G(s↑ + s↓), G the chi-square factor at the whole tail."""
    s, w = _chi_grid(n - 1)
    nu = n - 1
    for upper in (True, False):
        g = _sigma_factor(n, tail, upper)
        misses = []
        for r in HALF_RATIOS:
            edge = np.maximum((1.0 + r - r * g * s) / g, 0.0)  # S_a's side of the bound
            below = chdtr(nu, nu * edge**2)
            misses.append(float(np.sum(w * (below if upper else 1.0 - below))))
        worst = max(misses)
        assert worst <= tail * 1.002, (upper, worst / tail)
        assert misses[0] >= tail * 0.99


def _readings(runs: int, seed: int):
    rng = np.random.default_rng(seed)
    m = 12
    sig_up = 0.5 * (1.0 + 0.3 * rng.random(m))
    sig_down = 0.5 * (1.0 + 0.3 * rng.random(m))
    sig_up[4] *= 3.0
    curve = 2.0 * np.sin(np.linspace(0.0, 5.0, m))
    up = curve + 0.8 + sig_up * rng.standard_normal((runs, m))
    down = curve - 0.8 + sig_down * rng.standard_normal((runs, m))
    x = {"up": up.mean(axis=0), "down": down.mean(axis=0)}
    s = {"up": up.std(axis=0, ddof=1), "down": down.std(axis=0, ddof=1)}
    n = {"up": np.full(m, float(runs)), "down": np.full(m, float(runs))}
    return x, s, n


@pytest.mark.parametrize("runs", [3, 5])
def test_the_band_figures_upper_ends_are_the_bounds_at_the_whole_tail(runs):
    """The workbench's upper ends of A↑, A and P are the largest top bound less the smallest
    bottom bound, each bound at the whole tail (above), and Ps_max's the largest sum of a
    target's two σ bounds at it; the lower end of P every target's four band-end bounds
    at once (Šidák over the targets, a quarter each), of Ps_max every target's sum."""
    x, s, n = _readings(runs, 39 + runs)
    found = figure_intervals(x, s, n, PROBABILITY, seed=1, trials=200, outer=0, inner=0)
    f2 = _tolerance_factor(runs, 2.0, 1.0 - TAIL)
    top = {d: x[d] + f2 * s[d] for d in x}
    bottom = {d: x[d] - f2 * s[d] for d in x}
    assert found["A_up"].high == pytest.approx(top["up"].max() - bottom["up"].min(), rel=1e-9)
    assert found["A"].high == pytest.approx(
        max(top["up"].max(), top["down"].max()) - min(bottom["up"].min(),
                                                     bottom["down"].min()), rel=1e-9)

    def vdi(tail, outward):
        f = {k: _tolerance_factor(runs, 1.5, 1.0 - tail if outward else tail)
             for k in (1.5,)}[1.5]
        g = _sigma_factor(runs, tail, outward)
        v = np.maximum(x["up"] + f * s["up"] + 1.5 * g * s["down"],
                       x["down"] + f * s["down"] + 1.5 * g * s["up"])
        w_ = np.minimum(x["up"] - f * s["up"] - 1.5 * g * s["down"],
                        x["down"] - f * s["down"] - 1.5 * g * s["up"])
        return v, w_

    v, w_ = vdi(TAIL, True)
    assert found["P"].high == pytest.approx(v.max() - w_.min(), rel=1e-9)
    m = x["up"].size
    cut = (1.0 - (1.0 - TAIL) ** (1.0 / m)) / 4.0
    v, w_ = vdi(cut, False)
    assert found["P"].low == pytest.approx(max(v.max() - w_.min(), 0.0), rel=1e-9, abs=1e-12)
    g_hi = _sigma_factor(runs, TAIL, True)
    assert found["Ps_max"].high == pytest.approx(
        3.0 * g_hi * (s["up"] + s["down"]).max(), rel=1e-9)
    g_lo = _sigma_factor(runs, 1.0 - (1.0 - TAIL) ** (1.0 / m), False)
    assert found["Ps_max"].low == pytest.approx(
        3.0 * g_lo * (s["up"] + s["down"]).max(), rel=1e-9)
    for key in ("A", "A_up", "P", "Ps_max"):
        assert found[key].probability == PROBABILITY


@pytest.mark.parametrize("n", [3, 5])
def test_p_pair_of_band_ends_at_the_whole_tail_holds_at_it_by_simulation(n):
    """P's upper end V̂_i − Ŵ_j: V_i = μ_a + 1.5σ_a + 1.5σ_b, W_j = μ_c − 1.5σ_c − 1.5σ_d of
    two targets (four independent samples; three σ ratios, each 10⁻³, 1 or 10³) or of one
    (the same direction at both ends: 3σ_a + 3σ_b; the two directions: μ↑ − μ↓ + 3σ↑ + 3σ↓),
    every bound at the whole tail: the miss stays within the simulation's noise of the tail
    (4 standard errors, 4 × 10⁵ draws, seeded)."""
    rng = np.random.default_rng(3941 + n)
    draws = 400_000
    f = _tolerance_factor(n, 1.5, 1.0 - TAIL)
    g = _sigma_factor(n, TAIL, True)
    z = rng.standard_normal((4, draws)) / np.sqrt(n)
    s = np.sqrt(rng.chisquare(n - 1, (4, draws)) / (n - 1))
    allowed = TAIL + 4.0 * np.sqrt(TAIL * (1.0 - TAIL) / draws)
    ratios = (1e-3, 1.0, 1e3)
    worst = 0.0
    for r1 in ratios:  # σ_b/σ_a
        v = (z[0] + f * s[0] - 1.5) + r1 * 1.5 * (g * s[1] - 1.0)
        for r2 in ratios:  # σ_d/σ_c
            w = (-z[2] + f * s[2] - 1.5) + r2 * 1.5 * (g * s[3] - 1.0)
            for r3 in ratios:  # the second target's scale
                worst = max(worst, float(np.mean(v / (1 + r1) + r3 * w / (1 + r2) < 0.0)))
        # one target, one direction at both ends; one target, both directions
        worst = max(worst, float(np.mean(2 * f * s[0] + r1 * 3 * g * s[1] < 3 + 3 * r1)))
        both = (z[0] - r1 * z[1]) + (f + 1.5 * g) * (s[0] + r1 * s[1]) - 3 * (1 + r1)
        worst = max(worst, float(np.mean(both < 0.0)))
    assert worst <= allowed, worst / TAIL
