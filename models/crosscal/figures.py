"""The encoder's figures of a cross-calibration (JJF 1115, ISO 230-2), for the JSON and the
certificate (imported by models.crosscal.analysis and models.crosscal.report, importing neither)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from models.uncertainty.iso230 import iso230_evaluate

if TYPE_CHECKING:
    from models.crosscal.analysis import CrossCalResult

__all__ = ["encoder_figures"]


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
