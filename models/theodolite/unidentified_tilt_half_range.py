"""The theodolite's decided half range where the elevations do not identify the axis tilt.

The tilt is then not removed and a tilt up to the stated bound enters each point's U
(models.theodolite.model.model_error_modes). For the decided half range it is ONE unknown
systematic error for the whole run, of a known shape family (its effect ζ(θ) for any tilt
direction and magnitude up to the bound), not scatter: drawn as noise it was taken off the
measured range (audit 72, finding 1: "0.00″, the measured 1.88″ less 1.88″", interval
0.00 … 0.00″, "pass", where the true half range was 0.4–2.0″). The half range is decided on
the readings' noise alone and its interval widened at both ends by the largest change such a
tilt can make to a half range (models.uncertainty.bounded_systematic_half_range).
"""

from __future__ import annotations

import numpy as np

from models.messages import QT_TR_NOOP, message, separated
from models.theodolite.model import (
    DEFAULT_TILT_BOUND_ARCSEC,
    TILT_BOUND_INPUT,
    TheodoliteResult,
    tilt_half_range_change,
)
from models.uncertainty.bounded_systematic_half_range import tilt_bounded, widened_by_systematic
from models.uncertainty.conformity import DECISION_QUANTITIES, HalfRangeEstimate

__all__ = ["TILT_WIDENED", "TILT_WIDENED_DEFAULT", "tilt_change_arcsec", "tilt_not_removed", "tilt_widened"]

#: how the decided half range is made where the tilt is not identified
TILT_WIDENED = QT_TR_NOOP(
    "{quantity}: {trials} trials, seed {seed}, of the reading noise alone. The axis tilt, not "
    "identified by the elevations and not removed, is one unknown error for the whole run, "
    "not noise: nothing is taken off the measured range for it. A tilt up to {bound} (stated) "
    "in any direction changes the half range by at most {change} (its exact effect ζ(θ) at "
    "these rotations with β = {beta}), so the interval is widened by that at both ends and "
    "holds for any such tilt; the elevations cannot check the bound (a larger tilt is not "
    "covered)")
#: the same where no bound was stated: the program's default, not the laboratory's figure
#: (audit 73 finding 3: it was printed "(stated)")
TILT_WIDENED_DEFAULT = QT_TR_NOOP(
    "{quantity}: {trials} trials, seed {seed}, of the reading noise alone. The axis tilt, not "
    "identified by the elevations and not removed, is one unknown error for the whole run, "
    "not noise: nothing is taken off the measured range for it. A tilt up to {bound} (the "
    "program's default: no bound was stated) in any direction changes the half range by at "
    "most {change} (its exact effect ζ(θ) at these rotations with β = {beta}), so the "
    "interval is widened by that at both ends and holds for any such tilt; the elevations "
    "cannot check the bound (a larger tilt is not covered)")


def tilt_not_removed(result: TheodoliteResult) -> bool:
    """Whether the run's tilt is not identified and a bound for it is stated (> 0)."""
    ident = result.identification
    return not ident.tilt_identified and ident.tilt_bound_arcsec > 0


def tilt_change_arcsec(result: TheodoliteResult) -> float:
    """The largest change (″) a tilt up to the run's bound makes to the half range of its
    errors: over every reading's rotation from the reference (the azimuth: ψ = 0 is removed,
    so the azimuth is the rotation), a superset of any curve decided on (the means over the
    passes are at the same θ)."""
    ident = result.identification
    theta_rel = result.theta_deg - result.reference_theta_deg
    rotation = theta_rel - np.asarray(result.raw_error_arcsec, dtype=float) / 3600.0
    return tilt_half_range_change(rotation, ident.setup.beta_deg, ident.tilt_bound_arcsec)


def tilt_widened(result: TheodoliteResult, estimate: HalfRangeEstimate) -> HalfRangeEstimate:
    """``estimate`` (the reading noise's alone) widened by the tilt's largest change, with
    its method said."""
    ident = result.identification
    change = tilt_change_arcsec(result)
    bound, changed = f"{ident.tilt_bound_arcsec:g}\"", f"{change:.3g}\""
    default = ident.tilt_bound_arcsec == DEFAULT_TILT_BOUND_ARCSEC  # none stated
    # after the method of an estimate that says its own (the means' united with E's, and
    # the probability that gives), else the whole of it
    method = (separated([estimate.method, tilt_bounded(ident.tilt_bound_arcsec, change,
                                                       DEFAULT_TILT_BOUND_ARCSEC)],
                        "; ") if estimate.method else
              message(TILT_WIDENED_DEFAULT if default else TILT_WIDENED,
                      quantity=message(DECISION_QUANTITIES["half_range"]),
                      trials=estimate.trials, seed=str(estimate.seed), bound=bound,
                      change=changed, beta=f"{ident.setup.beta_deg:.4f}°"))
    return widened_by_systematic(estimate, change, method)


#: the budget's input that is the tilt's bound (one systematic, not noise)
TILT_INPUTS = frozenset({TILT_BOUND_INPUT})
