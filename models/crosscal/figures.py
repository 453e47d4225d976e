"""The encoder's figures of a cross-calibration (JJF 1115, ISO 230-2), for the JSON and the
certificate (imported by models.crosscal.analysis and models.crosscal.report, importing neither)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from models.messages import QT_TR_NOOP
from models.uncertainty.iso230 import iso230_evaluate

if TYPE_CHECKING:
    from models.crosscal.analysis import CrossCalResult

__all__ = ["ENCODER_FIGURES_NO_INTERVAL", "encoder_figures"]

#: the JSON's ``encoder_figures_arcsec`` (JJF 1115's division error and repeatability, ISO
#: 230-2's unidirectional figures, the mountings taken as runs): plain numbers, no interval
#: (audit 68 finding 4: a lab's system could not tell them from calibrated figures); the
#: reason beside them, ``encoder_figures_arcsec_reason``
ENCODER_FIGURES_NO_INTERVAL = QT_TR_NOOP(
    "indicative: no coverage interval evaluated; the figures are as computed from the "
    "readings (JJF 1115's repeatability and the ISO 230-2 figures take the mountings as repeat "
    "runs, although they are remountings), and a largest value or a range is biased high by "
    "the readings' noise; the calibration results are the errors at each step with their U")


def encoder_figures(result: CrossCalResult) -> dict[str, float]:
    """JJF 1115's division error and ISO 230-2's unidirectional figures of the encoder's
    error, its mountings taken as repeated runs (deviation = −error)."""
    runs = result.encoder_runs_arcsec()
    theta = np.tile(result.step_deg, runs.shape[0])
    keep = np.isfinite(runs.ravel())
    figures = iso230_evaluate(theta[keep], -runs.ravel()[keep]).figures
    out = {"division_error_jjf1115": float(np.ptp(result.solution.encoder_error_determined_arcsec)),
           "repeatability_jjf1115": float(np.nanmax(np.nanstd(runs, axis=0, ddof=1)))
           if runs.shape[0] > 1 else float("nan")}
    out.update({f"iso230_{k}": float(v) for k, v in figures.items()})
    return out
