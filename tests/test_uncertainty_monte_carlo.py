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

from models.certificate_metadata import CertificateMetadata, ReferenceStandard
from models.fringe import phase_of_samples
from models.fringe_analysis import FRINGE
from models.fringe_report import fringe_budget
from models.polygon import simulate_set
from models.polygon_analysis import POLYGON
from models.polygon_report import polygon_budget
from models.readings import ParsedReadings
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


def _polygon_parsed(sets: list) -> ParsedReadings:
    cols: dict[str, list] = {k: [] for k in ("position", "encoder_deg", "polygon_dev_arcsec",
                                              "ac_x_arcsec", "ac_y_arcsec", "set", "direction")}
    for set_id, s in enumerate(sets, 1):
        n = s.encoder_deg.size
        for i in list(range(n)) + [0]:
            cols["position"].append(i + 1)
            cols["encoder_deg"].append(s.encoder_deg[i])
            cols["polygon_dev_arcsec"].append(s.polygon_dev_arcsec[i])
            cols["ac_x_arcsec"].append(s.closure_ac_x_arcsec if len(cols["set"]) % (n + 1) == n
                                       else s.ac_x_arcsec[i])
            cols["ac_y_arcsec"].append(s.ac_y_arcsec[i])
            cols["set"].append(set_id)
            cols["direction"].append("")
    values = {k: np.array(v, dtype=object if k == "direction" else float) for k, v in cols.items()}
    return ParsedReadings(values, np.arange(len(cols["set"])))


@pytest.mark.parametrize("sets", [1, 3])
def test_polygon_budget_matches_monte_carlo(sets):
    rng = np.random.default_rng(5 + sets)
    faces = 24
    theta = np.arange(faces) * 360.0 / faces
    truth = 1.5 * np.sin(np.radians(theta) + 0.3) + 0.4 * np.sin(2 * np.radians(theta))
    truth = truth - truth[0]
    certificate_dev = rng.normal(0.0, 0.2, faces)
    u_polygon = 0.10  # standard uncertainty of each face's certified deviation
    noise = 0.08
    meta = CertificateMetadata(standards=(ReferenceStandard("polygon", uncertainty_arcsec=0.20,
                                                            basis="U95"),))
    deviations, budgets = [], []
    for _ in range(TRIALS // 2):
        true_dev = certificate_dev + rng.normal(0.0, u_polygon, faces)
        runs = []
        for _ in range(sets):
            s = simulate_set(faces, truth, psi_arcsec=60.0, omega_deg=70.0,
                             polygon_dev_arcsec=true_dev, noise_arcsec=noise, rng=rng)
            s.polygon_dev_arcsec = certificate_dev.copy()  # the analysis knows the certificate
            runs.append(s)
        result = POLYGON.analyze(_polygon_parsed(runs), POLYGON.settings_with_defaults(
            {"grade": 5}))
        deviations.append(result.mean_corrected_arcsec - truth)
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
