"""Axes for the width study of the band figures' intervals (ISO 230-2's A, A↑, A↓; VDI/DGQ
3441's P and Ps_max) where the repeatability differs from target to target (#39), simulated
from first principles: numpy only, nothing from the code it checks.

Each reading of target i in direction d is its true mean deviation μ_d,i plus normal noise
of that target's and direction's own σ_d,i; μ↑ = c + β/2, μ↓ = c − β/2 (arcsec), c an error
curve over the axis, β a reversal. Curves (:data:`CURVES`): ``smooth`` (a slow sine and a
tilt) and ``rough`` (the smooth curve plus a fixed irregular component 0.8″ rms, drawn once
per number of targets from its own seed, and a reversal that changes from target to target).
σ patterns (:data:`PATTERNS`): ``varying`` (σ 1.0–1.3 × 0.6″ over the targets, up and down
out of phase) and ``triple`` (the same with one target's σ × 3: the ↑ at the target where
μ↑ is largest, the ↓ at the one where μ↓ is smallest, so that they make both ends of A and
P). The truth of every figure from the true μ and σ, as the standards define it
(:func:`band_truth`)."""

from __future__ import annotations

import numpy as np

CURVES = ("smooth", "rough")
PATTERNS = ("varying", "triple")
SIGMA = 0.6  # arcsec, the base repeatability
BAND_KEYS = ("A", "A_up", "A_down", "P", "Ps_max")


def true_means(curve: str, m: int) -> tuple[np.ndarray, np.ndarray]:
    """μ↑_i, μ↓_i (arcsec) of m targets."""
    p = np.linspace(0.0, 1.0, m)
    c = 3.0 * np.sin(2.0 * np.pi * 0.9 * p + 0.4) + 1.2 * p
    beta = 1.6 + 0.5 * np.sin(np.pi * p)
    if curve == "rough":
        fixed = np.random.default_rng(7100 + m)
        c = c + 0.8 * fixed.standard_normal(m)
        beta = beta + 0.4 * fixed.standard_normal(m)
    return c + 0.5 * beta, c - 0.5 * beta


def sigmas(curve: str, pattern: str, m: int) -> tuple[np.ndarray, np.ndarray]:
    """σ↑_i, σ↓_i (arcsec)."""
    phase = np.linspace(0.0, np.pi, m)
    up = SIGMA * (1.0 + 0.3 * np.sin(1.5 * phase) ** 2)
    down = SIGMA * (1.0 + 0.3 * np.cos(1.5 * phase) ** 2)
    if pattern == "triple":
        mu_up, mu_down = true_means(curve, m)
        up[int(np.argmax(mu_up))] *= 3.0
        down[int(np.argmin(mu_down))] *= 3.0
    return up, down


def band_truth(mu_up, mu_down, s_up, s_down) -> dict[str, float]:
    """A↑, A↓, A (ISO 230-2: max(μ + 2σ) − min(μ − 2σ)), Ps_max = max 3(σ↑ + σ↓) and
    P = max(m + (|β| + Ps)/2) − min(m − (|β| + Ps)/2) (VDI/DGQ 3441) of the truth."""
    out = {"A_up": float(np.max(mu_up + 2 * s_up) - np.min(mu_up - 2 * s_up)),
           "A_down": float(np.max(mu_down + 2 * s_down) - np.min(mu_down - 2 * s_down))}
    out["A"] = float(max(np.max(mu_up + 2 * s_up), np.max(mu_down + 2 * s_down))
                     - min(np.min(mu_up - 2 * s_up), np.min(mu_down - 2 * s_down)))
    ps = 3.0 * (s_up + s_down)
    middle, half = 0.5 * (mu_up + mu_down), 0.5 * (np.abs(mu_up - mu_down) + ps)
    out["Ps_max"] = float(np.max(ps))
    out["P"] = float(np.max(middle + half) - np.min(middle - half))
    return out


def axis_test(curve: str, pattern: str, m: int, runs: int, rng: np.random.Generator
              ) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """One test, ``runs`` runs each way over m targets: readings {"up", "down"} of shape
    (runs, m) and the true figures."""
    mu_up, mu_down = true_means(curve, m)
    s_up, s_down = sigmas(curve, pattern, m)
    readings = {"up": mu_up + s_up * rng.standard_normal((runs, m)),
                "down": mu_down + s_down * rng.standard_normal((runs, m))}
    return readings, band_truth(mu_up, mu_down, s_up, s_down)
