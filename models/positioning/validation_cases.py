"""The positioning (ISO 230-2) workbench's reference cases for the method validation report
(``anglebench validate``): moved here from models/validation/cases.py, which keeps the
shared machinery (models.validation.run gathers every workbench's)."""

from __future__ import annotations

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.messages import QT_TR_NOOP, message
from models.positioning.analysis import POSITIONING
from models.positioning.compensation import compensation_table
from models.positioning.figure_coverage import figure_coverage_cases
from models.positioning.report import positioning_budget
from models.readings.sheet import ParsedReadings, ReadingsSheet
from models.validation.cases import (
    EXACT_SIMULATION,
    HAND_COMPUTED,
    ValidationCase,
    agreement_case,
    at_most_case,
    close_case,
)
from models.validation.positioning_rig import AxisRig

__all__ = ["validation_cases"]


POSITIONING_TARGETS = np.arange(0.0, 361.0, 45.0)


def _axis_error_deg(theta_deg: np.ndarray) -> np.ndarray:
    th = np.radians(theta_deg)
    return (5.0 * np.sin(th + 0.4) + 1.5 * np.sin(2 * th)) / 3600.0


def positioning_readings(rig: AxisRig, runs: int = 5) -> ParsedReadings:
    """The rig's standard test cycle as the workbench reads it (deviations in arcsec)."""
    rows = [[f"{t:.6f}", str(run), "+" if d > 0 else "-", f"{(reading - t) * 3600:.6f}", ""]
            for t, run, d, reading in rig.standard_cycle(POSITIONING_TARGETS, runs)]
    return ReadingsSheet(POSITIONING.columns, rows).parse()


def positioning_budget_trials(trials: int, rng: np.random.Generator
                              ) -> tuple[np.ndarray, np.ndarray]:
    """Mean deviation − truth per target and direction, and the budget's u (arcsec)."""
    meta = CertificateMetadata()
    deviations, budgets = [], []
    for _ in range(trials):
        rig = AxisRig(_axis_error_deg, lost_motion=4.0 / 3600, noise=0.7 / 3600,
                      reference_noise=0.3 / 3600, rng=rng)
        result = POSITIONING.analyze(positioning_readings(rig), {})
        truth = np.concatenate([[rig.true_mean_deviation(t, d, 5) * 3600
                                 for t in result.positions] for d in (1, -1)])
        mean = np.concatenate([result.iso.forward.mean, result.iso.backward.mean])
        deviations.append(mean - truth)
        budgets.append(positioning_budget(result, meta).combined)
    return np.array(deviations), np.array(budgets)


def positioning_cases(trials: int) -> list[ValidationCase]:
    w = POSITIONING.title
    lost = 4.0  # arcsec
    rig = AxisRig(_axis_error_deg, lost_motion=lost / 3600)  # no scatter: every figure known
    result = POSITIONING.analyze(positioning_readings(rig), {})
    f, v = result.iso.figures, result.vdi
    e = _axis_error_deg(POSITIONING_TARGETS) * 3600
    cases = [
        close_case(w, QT_TR_NOOP("axis without scatter: reversal B = lost motion"), EXACT_SIMULATION, lost,
               f["B"], 1e-4),
        close_case(w, QT_TR_NOOP("axis without scatter: mean reversal B̄ = −lost motion (axis lags)"),
               EXACT_SIMULATION, -lost, f["B_mean"], 1e-4),
        close_case(w, QT_TR_NOOP("axis without scatter: E↑ = range of the axis error"), EXACT_SIMULATION,
               float(np.ptp(e)), f["E_up"], 1e-4),
        close_case(w, QT_TR_NOOP("axis without scatter: A = range of the axis error + lost motion"),
               EXACT_SIMULATION, float(np.ptp(e)) + lost, f["A"], 1e-4),
        close_case(w, QT_TR_NOOP("axis without scatter: VDI 3441 P = Pa + U"), EXACT_SIMULATION,
               float(np.ptp(e)) + lost, float(v.P), 1e-4),
    ]
    table = compensation_table(result)
    forward = dict(zip(table.positions.tolist(), table.forward.tolist(), strict=True))
    backward = dict(zip(table.positions.tolist(), table.backward.tolist(), strict=True))

    def controller(target: float, direction: int) -> float:
        return target + (forward if direction > 0 else backward)[target] / 3600.0

    compensated = AxisRig(_axis_error_deg, lost_motion=lost / 3600, controller=controller)
    left = POSITIONING.analyze(positioning_readings(compensated), {})
    cases.append(at_most_case(w, QT_TR_NOOP("compensation table loaded into the rig's controller: largest "
                          "|mean deviation| left"), EXACT_SIMULATION, 0.01,
                          float(np.nanmax(np.abs(np.concatenate(
                              [left.iso.forward.mean, left.iso.backward.mean]))))))
    cases.append(agreement_case(w, positioning_budget_trials, trials, 4))
    return cases + positioning_hand_cases() + figure_coverage_cases(trials, ValidationCase)


#: ISO 230-2 by hand: two targets, three runs each way, s = 1" everywhere. Forward means 2"
#: and 4", backward 0" and 1": E↑ = 2, E = 4 − 0 = 4, B = max(|2 − 0|, |4 − 1|) = 3,
#: B̄ = (2 + 3)/2 = 2.5, M = 2.5 − 1 = 1.5, R = max(2s↑ + 2s↓ + |B_i|, 4s) = 4 + 3 = 7,
#: A = max(x̄ + 2s) − min(x̄ − 2s) = (4 + 2) − (0 − 2) = 8.
HAND_EXAMPLE = {"positions": [0.0] * 6 + [10.0] * 6,
                "deviations": [1, 2, 3, -1, 0, 1, 3, 4, 5, 0, 1, 2],
                "directions": [1, 1, 1, -1, -1, -1] * 2}
HAND_FIGURES = {"A": 8.0, "R": 7.0, "E": 4.0, "E_up": 2.0, "M": 1.5, "B": 3.0, "B_mean": 2.5}


def positioning_hand_cases() -> list[ValidationCase]:
    """The hand-computed examples the positioning certificate cites: ISO 230-2's figures of
    a run small enough to work out on paper (see HAND_EXAMPLE)."""
    from models.uncertainty.iso230 import iso230_evaluate

    w = POSITIONING.title
    figures = iso230_evaluate(np.array(HAND_EXAMPLE["positions"]),
                              np.array(HAND_EXAMPLE["deviations"], float),
                              np.array(HAND_EXAMPLE["directions"])).figures
    return [close_case(w, message(QT_TR_NOOP("ISO 230-2 worked by hand (2 targets, 3 runs each "
                                         "way): {figure}"), figure=name.replace("_mean", "̄")
                              .replace("_up", "↑")), HAND_COMPUTED, value, figures[name], 1e-9,
                   digits=2)
            for name, value in HAND_FIGURES.items()]


def validation_cases(trials: int) -> list[ValidationCase]:
    """Every reference case of this workbench (``trials`` Monte Carlo runs a comparison)."""
    return positioning_cases(trials)
