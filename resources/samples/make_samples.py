"""Regenerate the bundled sample files (deterministic): python -m resources.samples.make_samples"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from models.angles import format_dms
from models.theodolite import SetupParameters, simulate_readings

HERE = Path(__file__).resolve().parent


def theodolite_sample() -> None:
    """The seed's experiment set-up (ψ = 5.8249°, α = 43.4965°, β = −0.0395°) on a 2"
    turntable, θ = −20°…20° step 1°, theodolite noise 0.5" (1σ)."""
    rng = np.random.default_rng(2017)
    theta = np.arange(-20.0, 21.0, 1.0)
    true_error = 0.9 * np.sin(np.radians(theta) * 12 + 0.4) + 0.012 * theta
    setup = SetupParameters(5.8249, 43.4965, -0.0395)
    azimuth, elevation = simulate_readings(theta, setup, true_error, noise_arcsec=0.5, rng=rng)
    with open(HERE / "theodolite_sample.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["theta_deg", "azimuth_deg", "elevation_deg"])
        for t, a, e in zip(theta, azimuth, elevation, strict=True):
            writer.writerow([f"{t:g}", format_dms(a, 1), format_dms(e, 1)])


if __name__ == "__main__":
    theodolite_sample()
