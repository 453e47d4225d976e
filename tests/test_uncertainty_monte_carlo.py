"""Each workbench's GUM budget against a Monte Carlo simulation (GUM Supplement 1).

A simulated run with known truth is repeated with fresh draws of every input
the budget names (reading noise, the reference standards' errors); the spread
of (corrected error − truth) over the trials is compared, point by point, with
the budget's combined standard uncertainty.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from rigs.polygon_rig import PolygonRig

from models.certificate_metadata import CertificateMetadata, ReferenceStandard
from models.fringe import phase_of_samples
from models.fringe_analysis import FRINGE
from models.fringe_report import fringe_budget
from models.polygon_analysis import POLYGON
from models.polygon_report import polygon_budget
from models.readings import ParsedReadings, ReadingsSheet
from models.theodolite import SetupParameters, analyze_run, simulate_readings
from models.theodolite_report import theodolite_budget

TRIALS = 500


def _agreement(spread: np.ndarray, budget_u: np.ndarray) -> tuple[float, float]:
    """(ratio of the RMS spread to the RMS budget, worst single-point ratio deviation)."""
    ratio = float(np.sqrt(np.mean(spread**2) / np.mean(budget_u**2)))
    worst = float(np.max(np.abs(spread / budget_u - 1.0)))
    return ratio, worst


def test_theodolite_budget_matches_monte_carlo():
    rng = np.random.default_rng(11)
    theta = np.arange(-60.0, 60.1, 5.0)
    setup = SetupParameters(2.0, 40.0, 3.0)
    truth = 3.0 * np.sin(np.radians(3.0 * theta))  # zero at the reference θ = 0
    noise, u_standard = 0.5, 0.3
    meta = CertificateMetadata(standards=(ReferenceStandard("theodolite", uncertainty_arcsec=0.6,
                                                            basis="U95"),))
    deviations, budgets = [], []
    for _ in range(TRIALS):
        az, el = simulate_readings(theta, setup, truth, noise, rng)
        az = az + rng.normal(0.0, u_standard, theta.size) / 3600.0  # the standard's error
        result = analyze_run(theta, az, el)
        deviations.append(result.corrected_error_arcsec - truth)
        budgets.append(theodolite_budget(result, meta).combined_arcsec)
    keep = theta != 0.0
    spread = np.std(deviations, axis=0, ddof=1)[keep]
    budget_u = np.sqrt(np.mean(np.square(budgets), axis=0))[keep]
    ratio, worst = _agreement(spread, budget_u)
    assert abs(ratio - 1.0) < 0.10, ratio
    assert worst < 0.20, worst
    # the reference point carries no uncertainty in either
    assert np.max(np.abs(np.array(deviations)[:, ~keep])) < 1e-9


@pytest.mark.parametrize("directions", [(1,), (1, 1, 1), (1, -1, 1, -1)])
def test_polygon_budget_matches_monte_carlo(directions):
    """Exact 3-D rig (tests/rigs): noise, the polygon's true deviations drawn about its
    certificate; every set shares one zero, so its reading's noise is in every error."""
    rng = np.random.default_rng(5 + len(directions))
    faces = 24
    theta = np.arange(faces) * 360.0 / faces
    truth = 1.5 * np.sin(np.radians(theta) + 0.3) + 0.4 * np.sin(2 * np.radians(theta))
    certificate_dev = rng.normal(0.0, 0.2, faces)
    u_polygon = 0.10  # standard uncertainty of each face's certified deviation
    noise = 0.08
    meta = CertificateMetadata(standards=(ReferenceStandard("polygon", uncertainty_arcsec=0.20,
                                                            basis="U95"),))
    settings = {"grade": 5, "ac_roll_arcmin": 0.0}  # the rig's reticle has no roll
    deviations, budgets = [], []
    for _ in range(TRIALS // 2):
        true_dev = certificate_dev + rng.normal(0.0, u_polygon, faces)
        rig = PolygonRig(faces, truth, psi_arcsec=60.0, omega_deg=70.0, face_dev_arcsec=true_dev,
                         certificate_error_arcsec=certificate_dev - true_dev, noise_arcsec=noise,
                         rng=rng)
        rows = []
        for k, d in enumerate(directions):
            rows += rig.set_rows(k + 1, reverse=d < 0, start_face=1 if d > 0 else 7)
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), settings)
        deviations.append(result.mean_corrected_arcsec - rig.truth_arcsec())
        budgets.append(polygon_budget(result, meta).combined_arcsec)
    spread = np.std(deviations, axis=0, ddof=1)[1:]
    budget_u = np.sqrt(np.mean(np.square(budgets), axis=0))[1:]
    ratio, worst = _agreement(spread, budget_u)
    assert abs(ratio - 1.0) < 0.10, ratio
    assert worst < 0.25, worst


def test_fringe_budget_matches_monte_carlo():
    rng = np.random.default_rng(3)
    per, periods = 64, 4
    theta = phase_of_samples(per * periods, per)
    clean_s = 0.02 + 1.0 * np.sin(theta) + 0.012 * np.sin(3 * theta + 0.4) + 0.004 * np.sin(5 * theta)
    clean_c = -0.015 + 0.97 * np.cos(theta) + 0.009 * np.sin(3 * theta + 2.0)
    noise = 0.004
    settings = FRINGE.settings_with_defaults({"samples_per_period": per, "lines_per_rev": 16384})
    meta = CertificateMetadata()
    deviations, budgets = [], []
    for _ in range(TRIALS):
        values = {"u_sin": clean_s + rng.normal(0, noise, theta.size),
                  "u_cos": clean_c + rng.normal(0, noise, theta.size),
                  "theta_deg": np.full(theta.size, np.nan)}
        result = FRINGE.analyze(ParsedReadings(values, np.arange(theta.size)), settings)
        deviations.append(result.compensated_error_arcsec)  # the truth after compensation is 0
        budgets.append(fringe_budget(result, meta).combined_arcsec)
    spread = np.std(deviations, axis=0, ddof=1)
    budget_u = np.sqrt(np.mean(np.square(budgets), axis=0))
    ratio, worst = _agreement(spread, budget_u)
    assert abs(ratio - 1.0) < 0.10, ratio
    assert worst < 0.25, worst
    # the figure is the size expected: σ/A of a radian, as shaft angle
    expected = noise / 1.0 * 1_296_000 / 16384 / (2 * math.pi)
    assert budget_u.mean() == pytest.approx(expected, rel=0.15)
