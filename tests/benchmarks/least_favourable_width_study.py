"""Where the per-target bounds of the positioning figures miss (#39's widths): R↑'s upper end
4 c max s_i and A↑'s max(x̄ + k s) − min(x̄ − k s) with one target's σ K × the others', and
A's lower end on a flat curve (models.positioning.figure_coverage's docstring quotes these
numbers). Numpy only, the bounds' factors as models.uncertainty.figure_intervals makes them;
12 targets (24 band ends for A's lower end), 5 runs, 95.45 %:

    nice -n 10 python tests/benchmarks/least_favourable_width_study.py

It prints, for R↑ and A↑, the miss of the end at K = 1 … 100 with the factor in use and the
least factor that would hold K ≤ 3 alone (the study's SIGMA_ALONG grid) with its miss at
K = 100; for A's lower end its miss on a flat curve of alike σ and where the bottom is one
target of σ → 0, at half Šidák's share each side (as now) and at the whole share.
"""

from __future__ import annotations

import sys

import numpy as np
from scipy.special import chdtri, nctdtrit

N, M, RUNS = 400_000, 12, 5
TAIL = 0.5 * (1.0 - 0.9545)
KS = (1, 1.5, 2, 2.5, 3, 4, 5, 8, 20, 100)


def r_up_miss(c: float, k: float, s: np.ndarray) -> float:
    """P(4 c max s_i < 4 σ_max), target 0's σ k × the others' (s in units of σ)."""
    drawn = s.copy()
    drawn[:, 0] *= k
    return float(np.mean(c * drawn.max(axis=1) < k))


def a_up_miss(f: float, k: float, z: np.ndarray, s: np.ndarray) -> float:
    """P(max(x̄ + f s) − min(x̄ − f s) < A) on a flat curve, target 0's σ k × the others'."""
    sigma = np.ones(M)
    sigma[0] = k
    mean, sd = z * sigma, s * sigma
    return float(np.mean((mean + f * sd).max(axis=1) - (mean - f * sd).min(axis=1) < 4.0 * k))


def main() -> None:
    rng = np.random.default_rng(1)
    nu = RUNS - 1
    s = np.sqrt(rng.chisquare(nu, (N, M)) / nu)
    z = rng.standard_normal((N, M)) / np.sqrt(RUNS)
    c_now = float(np.sqrt(nu / chdtri(nu, 1.0 - TAIL)))
    f_now = float(nctdtrit(nu, 2.0 * np.sqrt(RUNS), 1.0 - TAIL) / np.sqrt(RUNS))
    for name, now, miss, grid in (
            ("R_up  c", c_now, lambda c, k: r_up_miss(c, k, s), np.arange(1.6, 3.01, 0.1)),
            ("A_up  k", f_now, lambda f, k: a_up_miss(f, k, z, s), np.arange(3.0, 6.3, 0.2))):
        sys.stdout.write(f"{name} = {now:.3f}: miss by K " + ", ".join(
            f"{k:g}: {miss(now, k):.4f}" for k in KS) + "\n")
        for factor in grid:
            if max(miss(factor, k) for k in KS if k <= 3) <= TAIL:
                sys.stdout.write(f"  least holding K <= 3: {factor:.1f} (miss at K = 100: "
                                 f"{miss(factor, 100):.4f})\n")
                break
    count = 2 * M
    z2 = rng.standard_normal((N, count)) / np.sqrt(RUNS)
    s2 = np.sqrt(rng.chisquare(nu, (N, count)) / nu)
    for name, cut in (("half share (now)", 0.5 * (1.0 - (1.0 - TAIL) ** (1.0 / count))),
                      ("whole share", 1.0 - (1.0 - TAIL) ** (1.0 / count))):
        f = float(nctdtrit(nu, 2.0 * np.sqrt(RUNS), cut) / np.sqrt(RUNS))
        flat = np.mean((z2 + f * s2).max(axis=1) - (z2 - f * s2).min(axis=1) > 4.0)
        exact_bottom = np.mean((z2[:, 1:] + f * s2[:, 1:]).max(axis=1) > 2.0)
        sys.stdout.write(f"A lower end, {name}: x̄ + {f:.3f} s; miss flat {flat:.4f}, bottom "
                         f"one target of σ → 0 {exact_bottom:.4f} (tail {TAIL:.5f})\n")


if __name__ == "__main__":
    main()
