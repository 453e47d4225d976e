"""Error curves measured with noise, from first principles, for the tests of the decided
quantity's interval (half the peak-to-peak): numpy only, nothing from the code it checks.

A true curve of half peak-to-peak 1 — smooth (eccentricity and ellipticity: the 1st and
2nd harmonics), rough (ten harmonics falling as 1/k), a single spike (one bad line on a
flat curve) or flat (a perfect axis) — read at ``points`` equally spaced angles with
normal noise of standard deviation ``sigma`` at every point.
"""

from __future__ import annotations

import numpy as np

CURVES = ("smooth", "rough", "spike", "flat")


def true_curve(shape: str, points: int, rng: np.random.Generator) -> np.ndarray:
    theta = 2.0 * np.pi * np.arange(points) / points
    if shape == "flat":
        return np.zeros(points)
    if shape == "smooth":
        phase = rng.uniform(0.0, 2.0 * np.pi, 2)
        curve = np.sin(theta + phase[0]) + 0.5 * np.sin(2.0 * theta + phase[1])
    elif shape == "rough":
        phase = rng.uniform(0.0, 2.0 * np.pi, 10)
        curve = sum(np.sin(k * theta + phase[k - 1]) / k for k in range(1, 11))
    elif shape == "spike":
        curve = np.zeros(points)
        curve[rng.integers(points)] = 2.0
    else:
        raise ValueError(shape)
    return curve / (0.5 * np.ptp(curve))


def measured(shape: str, points: int, sigma: float, rng: np.random.Generator
             ) -> tuple[float, np.ndarray]:
    """(the true half range, the curve as read with noise σ)."""
    truth = true_curve(shape, points, rng)
    return 0.5 * float(np.ptp(truth)), truth + rng.normal(0.0, sigma, points)
