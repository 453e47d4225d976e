"""The cross-calibration workbench's reference cases for the method validation report
(``anglebench validate``): moved here from models/validation/cases.py, which keeps the
shared machinery (models.validation.run gathers every workbench's)."""

from __future__ import annotations

import math

import numpy as np

from models.crosscal.solve import solve_crosscal
from models.crosscal.uncertainty import design_uncertainty, estler_full_rosette, monte_carlo_check
from models.messages import QT_TR_NOOP, message
from models.validation.cases import (
    BUDGET_VS_MONTE_CARLO,
    CHECK_FIGURE,
    EXACT_SIMULATION,
    ValidationCase,
    at_most_case,
    close_case,
)
from models.validation.crosscal_rig import CrossCalRig

__all__ = ["validation_cases"]


def crosscal_cases(trials: int) -> list[ValidationCase]:
    """Cross-calibration: Estler's closed form, exact simulations of full and partial
    rosettes by the rig (mounting errors, stops, drift, tilt), the harmonics a design
    cannot see, and the stated u against a Monte Carlo of the same design."""
    w = QT_TR_NOOP("Cross-calibration (polygon + encoder)")
    u, _, _ = estler_full_rosette(24, 0.02)
    planned = design_uncertainty(24, range(24), 0.02, closure=False)
    cases = [close_case(w, QT_TR_NOOP("full rosette, 24 faces, σ = 0.02\": u = σ√(n − 1)/n (Estler)"),
                    CHECK_FIGURE, u, float(planned.encoder_error_u_arcsec.max()), 1e-7, digits=5)]
    harmonics = {1: (2.0, 0.3), 2: (1.0, 1.1), 3: (0.5, 2.0), 6: (0.3, 0.5)}
    for mountings, name in ((list(range(12)), QT_TR_NOOP("3-D simulation, full rosette of 12 faces, "
                                                         "no noise: |result − truth|")),
                            ([0, 1, 5], QT_TR_NOOP("3-D simulation, mountings 0, 1, 5 of 12, no "
                                                   "noise: |result − truth|"))):
        rig = CrossCalRig(12, harmonics, np.random.default_rng(33).normal(0.0, 1.5, 12),
                          drift_arcsec=0.5, tilt_arcsec=30.0, rng=np.random.default_rng(34))
        j, i, a, c = (np.array(col) for col in zip(*rig.rows(mountings), strict=True))
        result = solve_crosscal(j, i, a, c, faces=12, noise_arcsec=0.01)
        true_e, true_d = rig.truth()
        cases.append(at_most_case(w, name, EXACT_SIMULATION, 0.002, float(max(
            np.abs(result.encoder_error_arcsec - true_e).max(),
            np.abs(result.polygon_deviation_arcsec - true_d).max()))))
    rig = CrossCalRig(12, harmonics, np.zeros(12), rng=np.random.default_rng(35))
    j, i, a, c = (np.array(col) for col in zip(*rig.rows([0, 4, 8]), strict=True))
    unseen = solve_crosscal(j, i, a, c, faces=12, noise_arcsec=0.01)
    cases.append(ValidationCase(
        w, QT_TR_NOOP("mountings 0, 4, 8 of 12: the harmonics not determined are named and "
                      "withheld"), EXACT_SIMULATION, "3, 6",
        ", ".join(map(str, unseen.undetermined_encoder_harmonics)),
        unseen.undetermined_encoder_harmonics == (3, 6) and unseen.encoder_error_arcsec is None))
    rig = CrossCalRig(6, {1: (2.0, 0.3)}, np.random.default_rng(36).normal(0.0, 1.5, 6),
                      drift_arcsec=0.5, noise_arcsec=0.2, rng=np.random.default_rng(37))
    j, i, a, c = (np.array(col) for col in zip(*rig.rows([0, 1, 3]), strict=True))
    check = monte_carlo_check(j, i, a, c, runs=trials, seed=38, faces=6)
    tolerance = max(0.10, 3.0 / math.sqrt(2.0 * trials))
    cases.append(ValidationCase(
        w, message(QT_TR_NOOP("stated u against the spread of {trials} simulated runs (ν = {dof})"),
                   trials=trials, dof=f"{check.dof:g}"),
        BUDGET_VS_MONTE_CARLO, message(QT_TR_NOOP("ratio 1 ± {tolerance}"), tolerance=f"{tolerance:.2f}"),
        message(QT_TR_NOOP("ratio {ratio}, U covers {coverage} %"), ratio=f"{check.ratio:.3f}",
                coverage=f"{100 * check.coverage:.1f}"),
        abs(check.ratio - 1.0) <= tolerance))
    return cases


def validation_cases(trials: int) -> list[ValidationCase]:
    """Every reference case of this workbench (``trials`` Monte Carlo runs a comparison)."""
    return crosscal_cases(trials)
