"""Regenerate the bundled sample files (deterministic): python -m resources.samples.make_samples

Run from the repository root (the polygon sample is made by the tests' 3-D rig).
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np

from models.readings.angles import format_dms
from models.theodolite.model import SetupParameters, simulate_readings
from models.validation.crosscal_rig import CrossCalRig
from models.validation.fringe_rig import FringeHead, equal_steps, wandering_motion
from models.validation.polygon_rig import PolygonRig
from models.validation.positioning_rig import AxisRig

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


def polygon_encoder_error(theta_deg: np.ndarray) -> np.ndarray:
    """A grade-3 encoder: eccentricity 0.35", ellipticity 0.15", a little 6th harmonic."""
    th = np.radians(theta_deg)
    return 0.35 * np.cos(th + 0.7) + 0.15 * np.cos(2 * th - 0.3) + 0.05 * np.sin(6 * th)


def polygon_sample() -> None:
    """24-face polygon, a forward set and a reverse set written in the order measured,
    on a levelled bench (autocollimator and rotary axis levelled, the polygon seated with a
    tilt ψ = 8' towards ω = 60°), 0.2" backlash, 0.12" autocollimator drift a set, 0.03"
    noise. Made by the exact 3-D rig of the tests (rotations only, no model code)."""
    rng = np.random.default_rng(2015)
    faces = 24
    theta = np.arange(faces) * 360.0 / faces
    dev = np.round(rng.normal(0, 0.15, faces), 2)
    rig = PolygonRig(faces, polygon_encoder_error(theta), psi_arcsec=480.0, omega_deg=60.0,
                     face_dev_arcsec=dev, noise_arcsec=0.03, backlash_arcsec=0.2,
                     encoder_zero_deg=123.4, ac_zero_x_arcsec=5.0, rng=rng, frame="levelled")
    rows = (rig.set_rows(1, closure_drift_arcsec=0.12)
            + rig.set_rows(2, reverse=True, closure_drift_arcsec=0.12))
    with open(HERE / "polygon_sample.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["position", "encoder_deg", "polygon_dev_arcsec", "ac_x_arcsec",
                         "ac_y_arcsec", "set", "direction"])
        for position, encoder, cert, ac_x, ac_y, set_id, direction in rows:
            writer.writerow([position, format_dms(float(encoder), 2), f"{float(cert):.2f}",
                             f"{float(ac_x):.2f}", f"{float(ac_y):.2f}", set_id, direction])


def crosscal_sample() -> None:
    """A 12-face polygon cross-calibrated with an encoder: the full rosette (mountings 0…11,
    each closed on its first face), mounting errors within ±20", the operator's stops within
    ±15" of null, 0.05" autocollimator drift a mounting, 0.03" noise. Made by the exact 3-D
    rig of the tests (rotations only, no model code)."""
    rng = np.random.default_rng(2023)
    faces = 12
    dev = np.round(rng.normal(0, 0.4, faces), 2)
    rig = CrossCalRig(faces, {1: (0.8, 0.7), 2: (0.3, -0.3), 3: (0.1, 1.2), 6: (0.05, 0.0)}, dev,
                      drift_arcsec=0.05, noise_arcsec=0.03, rng=rng)
    with open(HERE / "crosscal_sample.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["mounting", "position", "encoder_deg", "ac_x_arcsec"])
        for mounting, face, encoder, ac_x in rig.rows(range(faces)):
            writer.writerow([mounting, face, f"{encoder:.7f}", f"{ac_x:.3f}"])


# Table 1 of the seed, the cos channel's B1 read as +3.7346 (../shared/SPEC.md §3)
TABLE1 = FringeHead(offsets_v=(-0.0179, -0.0642), amplitudes_v=(3.7763, 3.7346), phase_rad=0.026,
                    quadrature_deg=float(np.degrees(1.5902 - 0.026)) - 90.0,
                    sin_harmonics={3: (-0.0796, 3.2261), 5: (0.0109, 0.4688)},
                    cos_harmonics={3: (0.079, 8.0719), 5: (-0.01, 2.0662)}, noise_v=0.002)


def fringe_sample() -> None:
    """Eight periods of 64 samples with the seed's Table 1 signals and 2 mV noise, with the
    phase of each sample from the reference (theta_deg)."""
    rng = np.random.default_rng(2013)
    theta = equal_steps(8 * 64, 64)
    u_sin, u_cos = TABLE1.channels(theta, rng)
    with open(HERE / "fringe_sample.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["u_sin", "u_cos", "theta_deg"])
        for s, c, t in zip(u_sin, u_cos, np.degrees(theta), strict=True):
            writer.writerow([f"{s:.5f}", f"{c:.5f}", f"{t:.4f}"])


def interferometer_sample() -> None:
    """A homodyne interferometer's two channels, no phase reference: a hand-driven motion
    (3 to 90 samples a fringe, two stops, one reversal), 8-bit ADC, offsets, unequal
    amplitudes, 2.5° quadrature error. Analyse with --period-nm 316.4 (λ/2 of a HeNe laser)."""
    rng = np.random.default_rng(1981)
    theta = wandering_motion(12_000, rng, min_samples=3.0, max_samples=90.0)
    head = FringeHead(offsets_v=(0.041, -0.027), amplitudes_v=(1.09, 1.03), quadrature_deg=2.5,
                      noise_v=0.003, adc_bits=8, full_scale_v=1.5)
    u_sin, u_cos = head.channels(theta, rng)
    with open(HERE / "fringe_interferometer_sample.csv", "w", newline="",
              encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["u_sin", "u_cos"])
        for s, c in zip(u_sin, u_cos, strict=True):
            writer.writerow([f"{s:.5f}", f"{c:.5f}"])


def rotary_table_error_deg(theta_deg: np.ndarray) -> np.ndarray:
    """A worm-driven rotary table: its encoder's eccentricity 6" and ellipticity 2"."""
    th = np.radians(theta_deg)
    return (6.0 * np.sin(th + 0.5) + 2.0 * np.sin(2 * th - 1.1)) / 3600.0


def positioning_sample() -> None:
    """A rotary table to 13 targets 0…360° every 30°, five bidirectional runs (ISO 230-2's
    standard cycle), lost motion 5", 0.3" drift a run, 0.8" scatter, read by a laser rotary
    calibrator with 0.2" noise; deviations in arcseconds, in the order measured."""
    rng = np.random.default_rng(2302)
    rig = AxisRig(rotary_table_error_deg, lost_motion=5.0 / 3600, drift_per_run=0.3 / 3600,
                  noise=0.8 / 3600, reference_noise=0.2 / 3600, rng=rng)
    with open(HERE / "positioning_sample.csv", "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle)
        writer.writerow(["target", "run", "direction", "deviation"])
        for target, run, direction, reading in rig.standard_cycle(np.arange(0, 361, 30)):
            writer.writerow([f"{target:g}", run, "+" if direction > 0 else "-",
                             f"{(reading - target) * 3600:.2f}"])


if __name__ == "__main__":
    theodolite_sample()
    polygon_sample()
    fringe_sample()
    interferometer_sample()
    positioning_sample()
    crosscal_sample()
