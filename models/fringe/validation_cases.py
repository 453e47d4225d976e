"""The fringe signal analysis workbench's reference cases for the method validation report
(``anglebench validate``): moved here from models/validation/cases.py, which keeps the
shared machinery (models.validation.run gathers every workbench's)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.fringe.analysis import FRINGE
from models.fringe.report import fringe_budget
from models.messages import QT_TR_NOOP
from models.readings.sheet import ParsedReadings
from models.validation.cases import (
    CHECK_FIGURE,
    EXACT_SIMULATION,
    ValidationCase,
    agreement_case,
    at_most_case,
    close_case,
)
from models.validation.fringe_rig import FringeHead, equal_steps

__all__ = ["validation_cases"]


def fringe_budget_trials(trials: int, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
    """Compensated error (the truth after compensation is 0) and the budget's u."""
    per, periods = 64, 4
    theta = equal_steps(per * periods, per)
    head = FringeHead(offsets_v=(0.02, -0.015), amplitudes_v=(1.0, 0.97),
                      sin_harmonics={3: (0.012, 0.4), 5: (0.004, 0.0)},
                      cos_harmonics={3: (0.009, 2.0)}, noise_v=0.004)
    settings = FRINGE.settings_with_defaults({"samples_per_period": per, "lines_per_rev": 16384})
    meta = CertificateMetadata()
    deviations, budgets = [], []
    for _ in range(trials):
        u_sin, u_cos = head.channels(theta, rng)
        values = {"u_sin": u_sin, "u_cos": u_cos, "theta_deg": np.full(theta.size, np.nan)}
        result = FRINGE.analyze(ParsedReadings(values, np.arange(theta.size)), settings)
        deviations.append(result.compensated_error)
        budgets.append(fringe_budget(result, meta).combined)
    return np.array(deviations), np.array(budgets)


def fringe_cases(trials: int) -> list[ValidationCase]:
    w = FRINGE.title
    per = 64
    theta = equal_steps(8 * per, per)
    # Table 1, the cos channel's B1 read as +3.7346 (../shared/SPEC.md §3)
    table1 = FringeHead(offsets_v=(-0.0179, -0.0642), amplitudes_v=(3.7763, 3.7346),
                        phase_rad=0.026, quadrature_deg=np.degrees(1.5902 - 0.026) - 90.0,
                        sin_harmonics={3: (-0.0796, 3.2261), 5: (0.0109, 0.4688)},
                        cos_harmonics={3: (0.079, 8.0719), 5: (-0.01, 2.0662)})
    u_sin, u_cos = table1.channels(theta)
    values = {"u_sin": u_sin, "u_cos": u_cos, "theta_deg": np.full(theta.size, np.nan)}
    settings = FRINGE.settings_with_defaults({"samples_per_period": per})
    result = FRINGE.analyze(ParsedReadings(values, np.arange(theta.size)), settings)
    raw = result.raw_error
    cases = [
        close_case(w, QT_TR_NOOP("Table 1's signals: peak-to-peak interpolation error"), CHECK_FIGURE, 0.973,
               float(np.ptp(raw)), 0.005),
        at_most_case(w, QT_TR_NOOP("Table 1's signals: error left after compensation (peak-to-peak)"),
                 EXACT_SIMULATION, 0.01, float(np.ptp(result.compensated_error))),
    ]
    head = FringeHead(offsets_v=(0.03, -0.02), amplitudes_v=(1.0, 0.95), quadrature_deg=2.0,
                      sin_harmonics={3: (0.01, 0.5)}, cos_harmonics={3: (0.008, 1.0)})
    u_sin, u_cos = head.channels(theta)
    values = {"u_sin": u_sin, "u_cos": u_cos, "theta_deg": np.full(theta.size, np.nan)}
    fitted = FRINGE.analyze(ParsedReadings(values, np.arange(theta.size)), settings)
    measured = np.arctan2(u_sin, u_cos)
    truth = (np.angle(np.exp(1j * (measured - theta))) * 1_296_000 / 16384 / (2 * math.pi))
    truth = truth - truth.mean()
    cases.append(at_most_case(w, QT_TR_NOOP("sampled signals with a true phase: |raw error − true error|"),
                          EXACT_SIMULATION, 1e-6,
                          float(np.max(np.abs(fitted.raw_error - truth)))))
    cases.append(at_most_case(w, QT_TR_NOOP("sampled signals with a true phase: |offsets − truth| (V)"),
                          EXACT_SIMULATION, 1e-9,
                          max(abs(fitted.sin_fit.offset - 0.03), abs(fitted.cos_fit.offset + 0.02)),
                          unit=" V"))
    cases.append(agreement_case(w, fringe_budget_trials, trials, 3))
    cases += _unmodelled_and_half_period_cases(w, settings)
    return cases


def _true_half_range(head: FringeHead) -> float:
    """Half the peak-to-peak of the noise-free signals' own error over a period (″)."""
    grid = np.arange(8192) * (2 * math.pi / 8192)
    u_sin, u_cos = dataclasses.replace(head, noise_v=0.0).channels(grid)
    error = np.angle(np.exp(1j * (np.arctan2(u_sin, u_cos) - grid)))
    return 0.5 * float(np.ptp(error)) * 1_296_000 / 16384 / (2 * math.pi)


def _unmodelled_and_half_period_cases(w, settings) -> list[ValidationCase]:
    """A 2nd harmonic that the odd orders asked for leave out (found in the residuals and
    fitted: the half range over the whole period is the signals'), and a record whose first
    sample lies at half a period (its error straddles ±π)."""
    from models.fringe.report import model_error_curve

    per = 64
    theta = equal_steps(8 * per, per)
    head = FringeHead(offsets_v=(0.01, -0.02), amplitudes_v=(1.0, 0.98), quadrature_deg=1.0,
                      sin_harmonics={2: (0.006, 0.3), 3: (0.004, 0.4)},
                      cos_harmonics={2: (0.0035, 2.0), 3: (0.003, 1.2)}, noise_v=0.001)
    u_sin, u_cos = head.channels(theta, np.random.default_rng(3))
    values = {"u_sin": u_sin, "u_cos": u_cos, "theta_deg": np.full(theta.size, np.nan)}
    result = FRINGE.analyze(ParsedReadings(values, np.arange(theta.size)), settings)
    half = 0.5 * float(np.ptp(model_error_curve(result)[1]))
    truth = _true_half_range(head)
    cases = [close_case(w, QT_TR_NOOP("a 2nd harmonic the odd orders leave out, found and "
                                      "fitted: half range over the whole period"),
                        EXACT_SIMULATION, truth, half, round(0.01 * truth, 3))]
    start = math.pi
    u_sin, u_cos = head.channels(theta + start, np.random.default_rng(4))
    values = {"u_sin": u_sin, "u_cos": u_cos, "theta_deg": np.full(theta.size, np.nan)}
    result = FRINGE.analyze(ParsedReadings(values, np.arange(theta.size)), settings)
    error = np.angle(np.exp(1j * (np.arctan2(u_sin, u_cos) - theta - start)))
    error = np.angle(np.exp(1j * (error - np.angle(np.mean(np.exp(1j * error))))))
    truth_arcsec = error * 1_296_000 / 16384 / (2 * math.pi)
    cases.append(at_most_case(w, QT_TR_NOOP("a record starting at half a period: |raw error − "
                                            "true error|"), EXACT_SIMULATION, 1e-6,
                              float(np.max(np.abs(result.raw_error - truth_arcsec)))))
    return cases


def validation_cases(trials: int) -> list[ValidationCase]:
    """Every reference case of this workbench (``trials`` Monte Carlo runs a comparison)."""
    return fringe_cases(trials)
