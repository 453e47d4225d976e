"""The theodolite run workbench's reference cases for the method validation report
(``anglebench validate``): moved here from models/validation/cases.py, which keeps the
shared machinery (models.validation.run gathers every workbench's)."""

from __future__ import annotations

import numpy as np

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.messages import QT_TR_NOOP
from models.theodolite.analysis import THEODOLITE
from models.theodolite.model import analyze_run, induced_error_arcsec
from models.theodolite.report import theodolite_budget
from models.validation.cases import (
    CHECK_FIGURE,
    EXACT_SIMULATION,
    ValidationCase,
    agreement_case,
    at_most_case,
    close_case,
)
from models.validation.theodolite_rig import theodolite_readings

__all__ = ["validation_cases"]


THEODOLITE_SETUP = (2.0, 40.0, 3.0)  # ψ, α, β in degrees


def theodolite_budget_trials(trials: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Corrected error − truth and the budget's u, per trial and point (arcsec). Each
    reading (azimuth and elevation) has one error, σ = 0.5″, and the theodolite is stated
    consistently with it, u = σ per reading (U = 1.0″, k = 2): the budget's one reading
    input, max(s, u), is checked against the spread (issue 39: before, the rig drew the
    standard as a second, azimuth-only error beside the noise, the budget's double count)."""
    theta = np.arange(-60.0, 60.1, 5.0)
    truth = 3.0 * np.sin(np.radians(3.0 * theta))  # error of indication, 0 at θ = 0
    noise = 0.5
    meta = CertificateMetadata(standards=(ReferenceStandard("theodolite", uncertainty=2 * noise,
                                                            basis="U95"),))
    clean_az, clean_el = theodolite_readings(theta - truth / 3600.0, *THEODOLITE_SETUP)
    deviations, budgets = [], []
    for _ in range(trials):
        az = clean_az + rng.normal(0.0, noise, theta.size) / 3600.0
        el = clean_el + rng.normal(0.0, noise, theta.size) / 3600.0
        result = analyze_run(theta, az, el)
        deviations.append(result.corrected_error_arcsec - truth)
        budgets.append(theodolite_budget(result, meta).combined)
    return np.array(deviations), np.array(budgets)


def theodolite_cases(trials: int) -> list[ValidationCase]:
    w = THEODOLITE.title
    theta = np.arange(-20.0, 21.0, 1.0)
    zeta = induced_error_arcsec(theta, 3.0, 45.0, 2.0)
    alphas = np.arange(0.0, 360.0, 1.0)
    spread = max(float(np.ptp([induced_error_arcsec(np.array([t]), 3.0, a, 2.0)[0]
                               for a in alphas])) for t in theta)
    experiment = induced_error_arcsec(theta, 5.8249, 43.4965, -0.0395)
    cases = [
        close_case(w, QT_TR_NOOP("ζ spans ±187.9\" (ψ = 3°, α = 45°, β = 2°, θ = −20…20°)"), CHECK_FIGURE,
               187.9, float(np.max(zeta)), 0.05, digits=2),
        close_case(w, QT_TR_NOOP("largest spread of ζ over α at one θ"), CHECK_FIGURE, 270.1, spread, 0.05,
               digits=2),
        close_case(w, QT_TR_NOOP("the published experiment (Tian et al. 2017): ζ from −301\""),
                   CHECK_FIGURE, -301.1,
               float(np.min(experiment)), 0.5, digits=1),
        close_case(w, QT_TR_NOOP("the published experiment (Tian et al. 2017): ζ to +423\""),
                   CHECK_FIGURE, 422.6,
               float(np.max(experiment)), 0.5, digits=1),
    ]
    truth = 0.05 * theta + 0.8 * np.sin(np.radians(theta) * 9)  # error of indication
    az, el = theodolite_readings(theta - truth / 3600.0, 5.8249, 43.4965, -0.0395)
    result = analyze_run(theta, az, el)
    s = result.identification.setup
    cases += [
        at_most_case(w, QT_TR_NOOP("3-D simulation, no noise: |corrected − true error|"), EXACT_SIMULATION,
                 1e-4, float(np.max(np.abs(result.corrected_error_arcsec - truth)))),
        at_most_case(w, QT_TR_NOOP("3-D simulation, no noise: |ψ, α, β − set-up| (°)"),
                     EXACT_SIMULATION, 1e-6,
                 float(max(abs(s.psi_deg - 5.8249), abs(s.alpha_deg - 43.4965),
                           abs(s.beta_deg + 0.0395))), unit="°"),
    ]
    scale = theodolite_readings(theta / (1 + 1e-5), 3.0, 45.0, 2.0)
    scaled = analyze_run(theta, *scale)
    cases.append(close_case(w, QT_TR_NOOP("sign: an axis indicating 1e-5 too much reads + at +20°"),
                        EXACT_SIMULATION, 0.72, float(scaled.corrected_error_arcsec[-1]), 0.005))
    cases.append(agreement_case(w, theodolite_budget_trials, trials, 11))
    return cases


def validation_cases(trials: int) -> list[ValidationCase]:
    """Every reference case of this workbench (``trials`` Monte Carlo runs a comparison)."""
    return theodolite_cases(trials)
