"""An axis's reversal measured by the ISO 230-2 standard test cycle, from first principles,
for the tests of B's interval (#39): numpy only, nothing from the code it checks.

At target i, approach j, direction d (+1 up, −1 down) the axis stops at
x = f_i + d·b_i/2 + σ·z, z ~ N(0, 1) new at every approach; each run goes up through every
target and back down. ISO 230-2:2014 defines the reversal at a target as x̄↑_i − x̄↓_i and
B = max_i |x̄↑_i − x̄↓_i|; the truth is the figure of the true distribution, max_i |b_i|
(VDI/DGQ 3441's U_max is the same maximum).
"""

from __future__ import annotations

import numpy as np


def readings_rows(reversal: np.ndarray, sigma: float, runs: int, rng: np.random.Generator
                  ) -> list[list[str]]:
    """The rows of a positioning readings file (target °, run, direction, deviation ″, note)
    of one test: targets equally spaced over a turn, a smooth systematic curve f."""
    m = reversal.size
    angles = np.linspace(0.0, 360.0, m, endpoint=False)
    t = np.radians(angles)
    f = np.sin(t) + 0.3 * np.sin(2 * t + 1.0)
    rows = []
    for run in range(1, runs + 1):
        for sign, d, order in (("+", 1.0, range(m)), ("-", -1.0, range(m - 1, -1, -1))):
            for i in order:
                x = f[i] + d * 0.5 * reversal[i] + sigma * rng.standard_normal()
                rows.append([f"{angles[i]:.6f}", str(run), sign, f"{x:.6f}", ""])
    return rows


def correct_width(reversal: np.ndarray, sigma: float, runs: int, rng: np.random.Generator,
                  probability: float = 0.9545, draws: int = 20000) -> float:
    """The width a correct interval of B needs: the spread of (measured B − true B) between
    the tails (1 ∓ p)/2, over tests simulated at the truth (x̄↑_i − x̄↓_i ~ N(b_i, 2σ²/n))."""
    u = sigma * np.sqrt(2.0 / runs)
    measured = np.max(np.abs(reversal + u * rng.standard_normal((draws, reversal.size))),
                      axis=1)
    tail = 0.5 * (1.0 - probability)
    low, high = np.quantile(measured - np.max(np.abs(reversal)), (tail, 1.0 - tail))
    return float(high - low)
