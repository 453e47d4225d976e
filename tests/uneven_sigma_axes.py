"""Axes whose repeatability differs from target to target, simulated from first principles
(numpy only, nothing from the code it checks), for the coverage of every ISO 230-2 /
GB/T 17421.2 and VDI/DGQ 3441 summary figure's interval (#39: A covered 65–68 of 80 tests
against 93.5 % printed with one target's σ × 2 or × 3 at 3 runs each way).

Each reading of target i in direction d is its true mean deviation μ_d,i plus normal noise of
that target's and direction's own σ_d,i: μ↑ = c + β/2, μ↓ = c − β/2, c a smooth error curve
over the axis and β a smooth reversal (arcsec). The truth of every figure is computed from
the true μ and σ as ISO 230-2 and VDI/DGQ 3441 define it (:func:`truth`).

σ patterns (:data:`PATTERNS`): ``equal`` (σ the same everywhere), ``varying`` (1.0–1.3 ×
over the targets, up and down out of phase), ``double`` and ``triple`` (the varying σ with
one target's σ × 2 or × 3: the ↑ at the target where μ↑ is largest, the ↓ where μ↓ is
smallest, so that the noisiest targets make both ends of A)."""

from __future__ import annotations

import numpy as np

PATTERNS = ("equal", "varying", "double", "triple")
SIGMA = 0.6  # arcsec, the base repeatability


def true_means(m: int) -> tuple[np.ndarray, np.ndarray]:
    """μ↑_i, μ↓_i (arcsec) of m targets: a smooth curve c and a reversal β, μ = c ± β/2."""
    p = np.linspace(0.0, 1.0, m)
    curve = 3.0 * np.sin(2.0 * np.pi * 0.9 * p + 0.4) + 1.2 * p - 0.8 * np.cos(4.0 * np.pi * p)
    reversal = 1.6 + 0.5 * np.sin(np.pi * p)
    return curve + 0.5 * reversal, curve - 0.5 * reversal


def sigmas(pattern: str, m: int, sigma: float = SIGMA) -> tuple[np.ndarray, np.ndarray]:
    """σ↑_i, σ↓_i (arcsec) of the pattern over m targets."""
    if pattern == "equal":
        return np.full(m, sigma), np.full(m, sigma)
    phase = np.linspace(0.0, np.pi, m)
    up = sigma * (1.0 + 0.3 * np.sin(1.5 * phase) ** 2)
    down = sigma * (1.0 + 0.3 * np.cos(1.5 * phase) ** 2)
    factor = {"varying": 1.0, "double": 2.0, "triple": 3.0}[pattern]
    mu_up, mu_down = true_means(m)
    up[int(np.argmax(mu_up))] *= factor
    down[int(np.argmin(mu_down))] *= factor
    return up, down


def truth(mu_up: np.ndarray, mu_down: np.ndarray, s_up: np.ndarray, s_down: np.ndarray
          ) -> dict[str, float]:
    """Every figure of the true distribution (true means μ and standard deviations σ), as
    ISO 230-2 (E, M, B, B̄, R, A and their one-direction forms) and VDI/DGQ 3441 (Pa, U_max,
    Ps_max, P) define it."""
    out: dict[str, float] = {}
    for name, mu, s in (("up", mu_up, s_up), ("down", mu_down, s_down)):
        out[f"E_{name}"] = float(np.max(mu) - np.min(mu))
        out[f"R_{name}"] = float(np.max(4.0 * s))
        out[f"A_{name}"] = float(np.max(mu + 2.0 * s) - np.min(mu - 2.0 * s))
    both = np.concatenate([mu_up, mu_down])
    out["E"] = float(np.max(both) - np.min(both))
    middle = 0.5 * (mu_up + mu_down)
    out["M"] = float(np.max(middle) - np.min(middle))
    beta = mu_up - mu_down
    out["B"] = float(np.max(np.abs(beta)))
    out["B_mean"] = float(np.mean(beta))
    out["R"] = float(np.max(np.maximum.reduce([2.0 * s_up + 2.0 * s_down + np.abs(beta),
                                                4.0 * s_up, 4.0 * s_down])))
    out["A"] = float(max(np.max(mu_up + 2.0 * s_up), np.max(mu_down + 2.0 * s_down))
                     - min(np.min(mu_up - 2.0 * s_up), np.min(mu_down - 2.0 * s_down)))
    # VDI/DGQ 3441: Pa the range of the bidirectional means, U_max the largest reversal,
    # Ps_i = 6 × the mean of the two directions' σ, P the span of m_i ± (|U_i| + Ps_i)/2
    ps = 3.0 * (s_up + s_down)
    out["Pa"] = out["M"]
    out["U_max"] = out["B"]
    out["Ps_max"] = float(np.max(ps))
    half = 0.5 * (np.abs(beta) + ps)
    out["P"] = float(np.max(middle + half) - np.min(middle - half))
    return out


def positioning_test(pattern: str, m: int, runs: int, rng: np.random.Generator,
                     sigma: float = SIGMA) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """One ISO 230-2 test, ``runs`` runs each way over m targets: readings
    {"up": (runs, m), "down": (runs, m)} (arcsec) and the true figures."""
    mu_up, mu_down = true_means(m)
    s_up, s_down = sigmas(pattern, m, sigma)
    readings = {"up": mu_up + s_up * rng.standard_normal((runs, m)),
                "down": mu_down + s_down * rng.standard_normal((runs, m))}
    return readings, truth(mu_up, mu_down, s_up, s_down)


def summary_stats(readings: dict[str, np.ndarray]) -> tuple[dict, dict, dict]:
    """(x̄, s, n) per direction, as ISO 230-2 takes them (s with n − 1)."""
    means = {k: v.mean(axis=0) for k, v in readings.items()}
    stds = {k: v.std(axis=0, ddof=1) for k, v in readings.items()}
    runs = {k: np.full(v.shape[1], v.shape[0]) for k, v in readings.items()}
    return means, stds, runs
