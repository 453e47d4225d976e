"""The polygon encoder test workbench's reference cases for the method validation report
(``anglebench validate``): moved here from models/validation/cases.py, which keeps the
shared machinery (models.validation.run gathers every workbench's)."""

from __future__ import annotations

import math

import numpy as np

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.messages import QT_TR_NOOP
from models.polygon.analysis import POLYGON
from models.polygon.model import WORST_CASE_COEFFICIENT, pyramidal_readings_arcsec
from models.polygon.report import polygon_budget
from models.readings.sheet import ReadingsSheet
from models.validation.cases import (
    CHECK_FIGURE,
    EXACT_SIMULATION,
    ValidationCase,
    agreement_case,
    at_most_case,
    close_case,
)
from models.validation.polygon_rig import PolygonRig

__all__ = ["validation_cases"]


def polygon_budget_trials(trials: int, rng: np.random.Generator, directions=(1, -1, 1, -1)
                          ) -> tuple[np.ndarray, np.ndarray]:
    """Mean corrected error − truth and the budget's u for sets run in ``directions``;
    the polygon's true deviations are drawn about its certificate."""
    faces = 24
    theta = np.arange(faces) * 360.0 / faces
    truth = 1.5 * np.sin(np.radians(theta) + 0.3) + 0.4 * np.sin(2 * np.radians(theta))
    certificate_dev = np.random.default_rng(5).normal(0.0, 0.2, faces)
    u_polygon, noise = 0.10, 0.08
    meta = CertificateMetadata(standards=(ReferenceStandard("polygon", uncertainty=0.20,
                                                            basis="U95"),))
    settings = {"grade": 5, "ac_roll_arcmin": 0.0}  # the rig's reticle has no roll
    if len(directions) == 1:  # one set cannot evaluate its noise: the lab states it
        settings["reading_noise_arcsec"] = noise
    deviations, budgets = [], []
    for _ in range(trials):
        true_dev = certificate_dev + rng.normal(0.0, u_polygon, faces)
        rig = PolygonRig(faces, truth, psi_arcsec=60.0, omega_deg=70.0, face_dev_arcsec=true_dev,
                         certificate_error_arcsec=certificate_dev - true_dev, noise_arcsec=noise,
                         rng=rng)
        rows = []
        for k, d in enumerate(directions):
            rows += rig.set_rows(k + 1, reverse=d < 0, start_face=1 if d > 0 else 7)
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), settings)
        deviations.append(result.mean_corrected_arcsec - rig.truth_arcsec())
        budgets.append(polygon_budget(result, meta).combined)
    # face 1 is the zero: its error is zero by definition in set 1 (one set: U = 0 there,
    # no ratio to take); the mean's U there is checked against its scatter in
    # tests/models/polygon/test_polygon_zero_reading.py
    return np.array(deviations)[:, 1:], np.array(budgets)[:, 1:]


def polygon_cases(trials: int) -> list[ValidationCase]:
    w = POLYGON.title
    theta = np.arange(0.0, 360.0, 1.0)
    eps_x, eps_y = pyramidal_readings_arcsec(theta, 600.0, 90.0)
    fine = np.arange(0.0, 360.0, 0.5)
    worst = max(float(np.max(np.abs(pyramidal_readings_arcsec(fine, 600.0, om)[0])))
                for om in np.arange(0.0, 360.0, 0.5)) / 600.0**2
    cases = [
        close_case(w, QT_TR_NOOP("largest |ε_x| at ψ = 10′, ω = 90°"), CHECK_FIGURE, 1.921,
               float(np.max(np.abs(eps_x))), 0.0005),
        close_case(w, QT_TR_NOOP("ε_x/ψ² at θ = 111° (×1e-5)"), CHECK_FIGURE, 0.5337,
               float(eps_x[111] / 600.0**2 * 1e5), 0.0002, unit="", digits=4),
        close_case(w, QT_TR_NOOP("ε_x/ψ² at θ = 179° (×1e-6)"), CHECK_FIGURE, 0.1269,
               float(eps_x[179] / 600.0**2 * 1e6), 0.0002, unit="", digits=4),
        close_case(w, QT_TR_NOOP("ε_y spans 2ψ"), CHECK_FIGURE, 1200.0, float(np.ptp(eps_y)), 0.1, digits=1),
        close_case(w, QT_TR_NOOP("largest ε_x/ψ² over every direction (×1e-6)"), CHECK_FIGURE,
               WORST_CASE_COEFFICIENT * 1e6, worst * 1e6, 0.002, unit="", digits=3),
    ]
    faces = 24
    nominal = np.arange(faces) * 360.0 / faces
    truth = 0.35 * np.cos(np.radians(nominal) + 0.7) + 0.15 * np.cos(2 * np.radians(nominal))
    rig = PolygonRig(faces, truth, psi_arcsec=480.0, omega_deg=60.0, backlash_arcsec=2.0,
                     encoder_zero_deg=359.99, counting=-1, vertical_sense=-1)
    result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rig.set_rows(1) + rig.set_rows(
        2, reverse=True, start_face=7)).parse(), {"grade": 7})
    forward = result.sets[0].corrected_error_arcsec
    cases += [
        at_most_case(w, QT_TR_NOOP("3-D simulation (ψ = 480″, counting against the faces, zero through "
                                   "360°): "
                 "|corrected − true error|"), EXACT_SIMULATION, 1e-3,
                 float(np.max(np.abs(forward - rig.truth_arcsec())))),
        close_case(w, QT_TR_NOOP("3-D simulation: a constant 2″ backlash is the reversal B"),
                   EXACT_SIMULATION,
               2.0, (math.nan if result.reversal_arcsec is None  # no reversal found: fails
                     else float(np.max(np.abs(result.reversal_arcsec)))), 0.002),
    ]
    seed_rig = PolygonRig(faces, truth, psi_arcsec=900.0, omega_deg=75.0, frame="polygon")
    seed_run = POLYGON.analyze(ReadingsSheet(POLYGON.columns, seed_rig.set_rows()).parse(),
                               {"grade": 7, "ac_alignment": "polygon"})
    rolled = PolygonRig(faces, truth, psi_arcsec=900.0, omega_deg=75.0, ac_pitch_deg=0.5,
                        ac_roll_arcsec=120.0, ac_zero_y_arcsec=1800.0)
    rolled_run = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rolled.set_rows()).parse(), {
        "grade": 7, "ac_roll_measured_arcmin": rolled.tilt_test_roll_arcmin(),
        "u_ac_roll_arcmin": 0.05})
    cases += [
        at_most_case(w, QT_TR_NOOP("3-D simulation in the frame of Tian et al. 2015 (ψ = 900″), "
                               "set as such: |corrected − true error|"), EXACT_SIMULATION, 1e-3,
                 float(np.max(np.abs(seed_run.sets[0].corrected_error_arcsec
                                     - seed_rig.truth_arcsec())))),
        at_most_case(w, QT_TR_NOOP("3-D simulation, levelled, autocollimator pitched 0.5° and rolled "
                               "2′ (measured by a tilt test): |corrected − true error|"),
                 EXACT_SIMULATION, 5e-3,  # the pitch acts at second order with the ±20″ stops
                 float(np.max(np.abs(rolled_run.sets[0].corrected_error_arcsec
                                     - rolled.truth_arcsec())))),
    ]
    residuals = []
    for i in range(16):
        n = (12, 24, 36, 72)[i % 4]
        nom = np.arange(n) * 360.0 / n
        noisy = PolygonRig(n, 0.3 * np.cos(np.radians(nom)), psi_arcsec=300.0 + 60 * i,
                           omega_deg=37.0 * i, noise_arcsec=0.03, rng=np.random.default_rng(i))
        rows = noisy.set_rows(1) + noisy.set_rows(2, reverse=True, start_face=1 + i % n)
        r = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), {"grade": 7})
        residuals += [s.corrected_error_arcsec - noisy.truth_arcsec() for s in r.sets]
    rms = float(np.sqrt(np.mean(np.concatenate(residuals) ** 2)))
    cases.append(at_most_case(w, QT_TR_NOOP("3-D simulations, 16 set-ups of 12–72 faces, ψ 300–1200″, σ = "
                          "0.03″: RMS of corrected − true error (2σ)"), EXACT_SIMULATION, 0.06,
                          rms))
    cases.append(agreement_case(w, polygon_budget_trials, trials, 6))
    return cases


def validation_cases(trials: int) -> list[ValidationCase]:
    """Every reference case of this workbench (``trials`` Monte Carlo runs a comparison)."""
    return polygon_cases(trials)
