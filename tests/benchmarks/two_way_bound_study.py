"""The miss of R's two-way bound over the whole grid (#39), by simulation with scipy alone
(the fast version, a few points including the worst:
tests/models/uncertainty/test_two_way_repeatability_bound.py).

The upper bound of 2σ↑ + 2σ↓ + |β| is 2G s↑ + 2G s↓ + |b| + t·se (G the chi-square factor
of σ's upper bound, t Student's with Hsu's min(n↑, n↓) − 1 degrees of freedom,
se = √(s↑²/n↑ + s↓²/n↓)), each of the three at one level. For each design (n↑, n↓) it finds
the level at which the miss at the least favourable point (one direction's σ alone, |β| ≫ σ;
quadrature) is the tail, then simulates the miss (10⁶ draws a point: s↑, s↓ drawn, b's
normal law in closed form given them) over σ↓/σ↑ 10⁻³ … 10³ and |β|/max σ 0 … 20 and 10⁶,
with each bound at that level and at a third of the tail (Bonferroni, until 0.8.18).
Prints, per design, the level ÷ tail and the three worst points of each (miss ÷ tail):

    nice -n 10 python tests/benchmarks/two_way_bound_study.py [DRAWS]

this study's run (10⁶ draws; standard error of a miss ÷ tail about 0.005): the worst of every
design at σ↓/σ↑ 10⁻³ or 10³ (the direction of the fewer runs alone), its miss 0.978–1.007
of the tail at the level (1.14 × the tail at 2 runs, 1.32 at 3, 1.62 at 5, 2.03 at 10); the
thirds' worst 0.13–0.30 (10 to 2 runs). The lower end's part beyond its σ bounds at most
0.0012 of the share (2 runs, 2 targets; at most 0.0006 at 30 runs and 0.0003 elsewhere).
"""

from __future__ import annotations

import sys

import numpy as np
from scipy.optimize import brentq
from scipy.special import chdtri, ndtr, stdtrit

TAIL = 0.5 * (1.0 - 0.9545)
DESIGNS = ((2, 2), (3, 3), (5, 5), (10, 10), (3, 5), (5, 3), (2, 10))
RATIOS = np.exp(np.linspace(np.log(1e-3), np.log(1e3), 25))  # σ↓ / σ↑
BETAS = (0.0, 0.5, 1.0, 2.0, 4.0, 8.0, 20.0, 1e6)  # |β| / max σ
#: the lower end's grid (its tail a target's Šidák share of it over m targets)
LOW_RUNS = (2, 3, 5, 10, 30)
LOW_TARGETS = (2, 12, 72)
LOW_RATIOS = np.exp(np.linspace(np.log(1e-2), np.log(1e2), 13))
LOW_ROOM = 0.05  # the part of the share not given to the σ's bounds


def _g(n, level):
    return float(np.sqrt((n - 1.0) / chdtri(n - 1.0, 1.0 - level)))


def _t(n_up, n_down, level):
    return float(stdtrit(min(n_up, n_down) - 1.0, 1.0 - level))


def _least_favourable_miss(n, k):
    z = np.linspace(-8.0, 8.0, 1601)
    w = np.exp(-0.5 * z**2)
    w /= w.sum()
    q = np.where(z < 0, chdtri(n - 1.0, 1.0 - ndtr(z)), chdtri(n - 1.0, ndtr(-z)))
    s = np.sqrt(q / (n - 1.0))
    return float(np.sum(w * ndtr(np.sqrt(n) * (2.0 - s * k))))


def level(n_up, n_down, tail=TAIL):
    def excess(lv):
        return max(_least_favourable_miss(n, 2.0 * _g(n, lv) + _t(n_up, n_down, lv) / np.sqrt(n))
                   for n in (n_up, n_down)) - tail
    return brentq(excess, tail, 0.5, xtol=1e-12)


def miss(n_up, n_down, ratio, beta, lv, s_up, s_down):
    s_down = ratio * s_down
    se = np.sqrt(s_up**2 / n_up + s_down**2 / n_down)
    sd_b = np.sqrt(1.0 / n_up + ratio**2 / n_down)
    room = (2.0 + 2.0 * ratio + beta - 2.0 * _g(n_up, lv) * s_up - 2.0 * _g(n_down, lv) * s_down
            - _t(n_up, n_down, lv) * se)
    p = np.where(room > 0.0, ndtr((room - beta) / sd_b) - ndtr((-room - beta) / sd_b), 0.0)
    return float(p.mean()), float(p.std() / np.sqrt(p.size))


def lower_end_miss(n, m, ratio, beta, s_up, s_down):
    """A target's R_i lower bound above R_i (σ↑ = 1, σ↓ = ``ratio``, n runs each way): σ↑'s
    and σ↓'s lower bounds at once at 0.95 of the target's Šidák share (closed form), and
    the rest (neither σ bound above its σ, 2σ̌↑ + 2σ̌↓ + max(|b| − t·se, 0) above
    2σ↑ + 2σ↓ + |β|, t at the whole share) by simulation. (σ's part, the rest) ÷ share."""
    share = 1.0 - (1.0 - TAIL) ** (1.0 / m)
    cut = 1.0 - np.sqrt(1.0 - (1.0 - LOW_ROOM) * share)
    factor = float(np.sqrt((n - 1.0) / chdtri(n - 1.0, cut)))
    low_up, low_down = factor * s_up, factor * ratio * s_down
    se = np.sqrt(s_up**2 / n + (ratio * s_down) ** 2 / n)
    sd_b = np.sqrt((1.0 + ratio**2) / n)
    r_i = max(2.0 + 2.0 * ratio + beta, 4.0, 4.0 * ratio)
    room = r_i - 2.0 * low_up - 2.0 * low_down + _t(n, n, share) * se
    above = np.where(room > 0.0, 1.0 - (ndtr((room - beta) / sd_b) - ndtr((-room - beta) / sd_b)),
                     1.0)
    rest = np.where((low_up <= 1.0) & (low_down <= ratio), above, 0.0)
    return (1.0 - (1.0 - cut) ** 2) / share, float(rest.mean()) / share


def main(argv):
    draws = int(argv[0]) if argv else 1_000_000
    out = sys.stdout
    for n_up, n_down in DESIGNS:
        rng = np.random.default_rng(1000 * n_up + n_down)
        s_up = np.sqrt(rng.chisquare(n_up - 1, draws) / (n_up - 1))
        s_down = np.sqrt(rng.chisquare(n_down - 1, draws) / (n_down - 1))
        lv = level(n_up, n_down)
        for name, at in (("level", lv), ("thirds", TAIL / 3.0)):
            rows = sorted(((miss(n_up, n_down, r, b * max(1.0, r), at, s_up, s_down)[0] / TAIL,
                            float(r), b) for r in RATIOS for b in BETAS), reverse=True)
            out.write(f"upper n↑={n_up} n↓={n_down} {name} (level/tail {at / TAIL:.3f}): "
                      + ", ".join(f"{v:.3f} at σ↓/σ↑={r:.3g} |β|/σ={b:g}"
                                  for v, r, b in rows[:3]) + "\n")
            out.flush()
    for n in LOW_RUNS:
        rng = np.random.default_rng(77 + n)
        s_up = np.sqrt(rng.chisquare(n - 1, draws) / (n - 1))
        s_down = np.sqrt(rng.chisquare(n - 1, draws) / (n - 1))
        for m in LOW_TARGETS:
            worst = max((lower_end_miss(n, m, r, b * max(1.0, r), s_up, s_down)[1], float(r), b)
                        for r in LOW_RATIOS for b in BETAS[:-1])
            out.write(f"lower n={n} m={m}: σ's {1.0 - LOW_ROOM:.2f} of the share, the rest at "
                      f"most {worst[0]:.4f} (σ↓/σ↑={worst[1]:.3g} |β|/σ={worst[2]:g})\n")
            out.flush()


if __name__ == "__main__":
    main(sys.argv[1:])
