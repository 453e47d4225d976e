"""Axes for the width study of R's and B's intervals (#39: R 8–18 times the width a correct
interval needs, B 2.4–2.9 times), simulated from first principles: numpy only, nothing from
the code it checks.

Each reading of target i in direction d is its true mean deviation μ_d,i plus normal noise
of that target's and direction's own σ_d,i; μ↑ = c + β/2, μ↓ = c − β/2 (arcsec). Curves
(:data:`CURVES`): ``smooth`` (a slow sine and a tilt) and ``rough`` (plus a fixed irregular
component 0.8″ rms and a reversal that changes from target to target, drawn once per number
of targets from its own seed). Reversals (:data:`REVERSALS`): ``none`` (β = 0: R made by
4σ or 2σ↑ + 2σ↓) and ``large`` (β 1.6–2.1″ + the rough part, about 3σ: R made by the
two-way term). σ patterns (:data:`PATTERNS`): ``constant`` (0.6″ everywhere), ``varying``
(1.0–1.3 × 0.6″ over the targets, up and down out of phase) and ``triple`` (varying, with
one target's σ↑ × 3). The truth of R and B from the true μ and σ, as ISO 230-2 defines them
(:func:`truth`)."""

from __future__ import annotations

import numpy as np

CURVES = ("smooth", "rough")
REVERSALS = ("none", "large")
PATTERNS = ("constant", "varying", "triple")
SIGMA = 0.6  # arcsec
KEYS = ("R", "R_up", "R_down", "B")


def true_means(curve: str, reversal: str, m: int) -> tuple[np.ndarray, np.ndarray]:
    p = np.linspace(0.0, 1.0, m)
    c = 3.0 * np.sin(2.0 * np.pi * 0.9 * p + 0.4) + 1.2 * p
    beta = (1.6 + 0.5 * np.sin(np.pi * p)) if reversal == "large" else np.zeros(m)
    if curve == "rough":
        fixed = np.random.default_rng(7300 + m)
        c = c + 0.8 * fixed.standard_normal(m)
        if reversal == "large":
            beta = beta + 0.4 * fixed.standard_normal(m)
    return c + 0.5 * beta, c - 0.5 * beta


def sigmas(pattern: str, m: int) -> tuple[np.ndarray, np.ndarray]:
    if pattern == "constant":
        return np.full(m, SIGMA), np.full(m, SIGMA)
    phase = np.linspace(0.0, np.pi, m)
    up = SIGMA * (1.0 + 0.3 * np.sin(1.5 * phase) ** 2)
    down = SIGMA * (1.0 + 0.3 * np.cos(1.5 * phase) ** 2)
    if pattern == "triple":
        up[m // 3] *= 3.0
    return up, down


def truth(mu_up, mu_down, s_up, s_down) -> dict[str, float]:
    """R↑ = 4 max σ↑, R↓, R = max of max(2σ↑ + 2σ↓ + |β|, 4σ↑, 4σ↓), B = max |β|."""
    size = np.abs(mu_up - mu_down)
    return {"R_up": float(4 * s_up.max()), "R_down": float(4 * s_down.max()),
            "R": float(np.max(np.maximum(np.maximum(2 * s_up + 2 * s_down + size, 4 * s_up),
                                         4 * s_down))),
            "B": float(size.max())}


def axis_test(curve, reversal, pattern, m, runs, rng):
    """One test, ``runs`` runs each way over m targets: readings {"up", "down"} (runs, m)
    and the true figures."""
    mu_up, mu_down = true_means(curve, reversal, m)
    s_up, s_down = sigmas(pattern, m)
    readings = {"up": mu_up + s_up * rng.standard_normal((runs, m)),
                "down": mu_down + s_down * rng.standard_normal((runs, m))}
    return readings, truth(mu_up, mu_down, s_up, s_down)
