"""Axes whose repeatability changes from target to target, simulated from first principles
(numpy only, nothing from the code it checks), for the coverage of the ISO 230-2
repeatability figures' intervals (R↑, R↓, R): each reading of a target is its true mean
deviation (a curve, ± half a reversal by direction) plus normal noise of that target's and
direction's own σ; the truth is the figure of the true distribution, as ISO 230-2 defines it
(R↑ = max 4σ↑_i, R↓ = max 4σ↓_i, R = max max(2σ↑_i + 2σ↓_i + |β_i|, 4σ↑_i, 4σ↓_i)).

Cells: ``equal`` (σ the same everywhere), ``varying`` (1.0–1.3 × over the targets, up and
down out of phase), ``double`` and ``triple`` (the varying σ with one target's σ × 2 or × 3:
the ↑ at a third of the axis, the ↓ at two thirds)."""

from __future__ import annotations

import numpy as np

PATTERNS = ("equal", "varying", "double", "triple")


def sigmas(pattern: str, m: int, sigma: float) -> tuple[np.ndarray, np.ndarray]:
    """σ↑_i, σ↓_i of the pattern over m targets."""
    phase = np.linspace(0.0, np.pi, m)
    if pattern == "equal":
        return np.full(m, sigma), np.full(m, sigma)
    up = sigma * (1.0 + 0.3 * np.sin(phase) ** 2)
    down = sigma * (1.0 + 0.3 * np.cos(phase) ** 2)
    factor = {"varying": 1.0, "double": 2.0, "triple": 3.0}[pattern]
    up[m // 3] *= factor
    down[(2 * m) // 3] *= factor
    return up, down


def true_means(m: int) -> tuple[np.ndarray, np.ndarray]:
    """μ↑_i, μ↓_i (arcsec): a smooth curve and a reversal of 2″ ± 0.5″."""
    p = np.linspace(0.0, 2.0 * np.pi, m)
    curve = 5.0 * np.sin(p + 0.3) + 3.0 * np.sin(2.0 * p + 1.0)
    reversal = 2.0 + 0.5 * np.cos(p)
    return curve + 0.5 * reversal, curve - 0.5 * reversal


def truth(mu_up, mu_down, s_up, s_down) -> dict[str, float]:
    """The ISO 230-2 figures of the true distribution."""
    size = np.abs(mu_up - mu_down)
    both = np.concatenate([mu_up, mu_down])
    return {"R_up": float(np.max(4 * s_up)), "R_down": float(np.max(4 * s_down)),
            "R": float(np.max(np.maximum.reduce([2 * s_up + 2 * s_down + size,
                                                  4 * s_up, 4 * s_down]))),
            "E": float(np.ptp(both)),
            "A": float(max(np.max(mu_up + 2 * s_up), np.max(mu_down + 2 * s_down))
                       - min(np.min(mu_up - 2 * s_up), np.min(mu_down - 2 * s_down)))}


def positioning_test(pattern: str, m: int, runs: int, sigma: float, rng: np.random.Generator
                     ) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """One test: readings {"up": (runs, m), "down": (runs, m)} and the true figures."""
    mu_up, mu_down = true_means(m)
    s_up, s_down = sigmas(pattern, m, sigma)
    readings = {"up": mu_up + s_up * rng.standard_normal((runs, m)),
                "down": mu_down + s_down * rng.standard_normal((runs, m))}
    return readings, truth(mu_up, mu_down, s_up, s_down)


def _rotation(axis: np.ndarray, angle: float) -> np.ndarray:
    k = axis / np.linalg.norm(axis)
    cross = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(angle) * cross + (1 - np.cos(angle)) * cross @ cross


def theodolite_passes_csv(pattern: str, m: int, passes: int, pointing: float,
                          rng: np.random.Generator, span: float = 20.0,
                          psi_deg: float = 2.0, beta_deg: float = 0.3, reversal: float = 0.6
                          ) -> tuple[str, dict[str, float]]:
    """A theodolite record with ``passes`` forward and backward passes over m θ in ±span°
    (a CSV text) and its true figures "as read": a mirror (normal β off the plane) on an
    axis tilted ψ toward a random α, turned by θ less the axis' error (a smooth curve,
    ± half the reversal by direction, and the axis' own non-repeatability at each θ, new at
    every approach); the theodolite reads the normal's azimuth and elevation, each with
    pointing noise. The pattern's σ_i (× ``pointing``) is the scatter as read:
    √(pointing² + axis_i²)."""
    theta = np.linspace(-span, span, m)
    x = theta / span
    error = 1.2 * np.sin(np.pi * x + 0.4) + 0.8 * np.cos(2 * np.pi * x)  # arcsec
    s_up, s_down = sigmas(pattern, m, pointing)
    axis_up = np.sqrt(np.maximum(s_up**2 - pointing**2, 0.0))
    axis_down = np.sqrt(np.maximum(s_down**2 - pointing**2, 0.0))
    psi, alpha, beta = np.radians(psi_deg), rng.uniform(0, 2 * np.pi), np.radians(beta_deg)
    tilt_axis = np.array([np.sin(psi) * np.cos(alpha), np.sin(psi) * np.sin(alpha),
                          np.cos(psi)])
    normal = np.array([np.cos(beta), 0.0, np.sin(beta)])
    lines = ["theta_deg,azimuth_deg,elevation_deg,run,direction"]
    for run in range(1, passes + 1):
        for sign, order, axis_noise in ((1, np.arange(m), axis_up),
                                        (-1, np.arange(m)[::-1], axis_down)):
            for i in order:
                e = error[i] + sign * 0.5 * reversal + rng.normal(0.0, axis_noise[i])
                n = _rotation(tilt_axis, np.radians(theta[i] - e / 3600.0)) @ normal
                az = np.degrees(np.arctan2(n[1], n[0])) + rng.normal(0, pointing) / 3600
                el = np.degrees(np.arcsin(n[2])) + rng.normal(0, pointing) / 3600
                lines.append(f"{theta[i]:.6f},{az:.9f},{el:.9f},{run},{'+' if sign > 0 else '-'}")
    mu_up = error + 0.5 * reversal
    mu_down = error - 0.5 * reversal
    return "\n".join(lines) + "\n", truth(mu_up, mu_down, s_up, s_down)


def iso230_rows(angles: np.ndarray, mu: dict[str, np.ndarray], runs: int, noise: float,
                rng: np.random.Generator) -> tuple[list[list[str]], dict]:
    """The readings sheet's rows of an ISO 230-2 test of a rotary axis whose approaches read
    ``mu`` ("+" and "-": each target's true mean deviation by direction) plus normal noise
    ``noise``, each run up through the targets and back down, rounded to 0.001 as typed;
    and the readings by (target, direction)."""
    rows, readings = [], {}
    for run in range(1, runs + 1):
        for sign, order in (("+", range(angles.size)), ("-", range(angles.size - 1, -1, -1))):
            for i in order:
                x = round(float(mu[sign][i] + noise * rng.standard_normal()), 3)
                rows.append([f"{angles[i]:.6f}", str(run), sign, f"{x:.3f}", ""])
                readings.setdefault((float(angles[i]), sign), []).append(x)
    return rows, readings
