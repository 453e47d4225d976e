"""The decided half range where one input is a bounded systematic error of a known shape family.

A set-up error the readings do not identify (a theodolite's or a polygon's axis tilt up to a
stated bound) is ONE unknown value for the whole run: a bias of the error curve whose shape
is known for every value it may take (the tilt's effect at each θ for any direction and any
magnitude up to the bound). It is not scatter. Drawn per point as noise in the half range's
Monte Carlo (models.uncertainty.conformity.half_range_monte_carlo) it is taken as widening
the measured range and subtracted: an audit (72, finding 1) found a theodolite's decided half
range printed as 0.00″, interval 0.00 … 0.00″, "pass", where 0.4–2.0″ was true and 1.9–2.9″
measured.

Here the half range is estimated from the other inputs alone (the readings' noise: the
Monte Carlo's value and interval are those of the half range of the curve the readings
measure, the systematic error in it), and the interval is widened at both ends by the
largest change the systematic error can make to a half range, ``change`` = max over the
family of half the peak-to-peak of its effect. The half range is half a seminorm, so
|h(f + b) − h(f)| ≤ h(b) for every curve f and bias b: the widened interval holds the true
half range at least as often as the Monte Carlo's holds the measured curve's, for every
systematic error within the family (a worst-case treatment, as bias_aware_tail in
models/uncertainty/figure_intervals.py for a standard's error, with the whole tail on each
side). The value stays the Monte Carlo's: nothing is taken off the measured range for an
error whose sign on the range is not known.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Container

from models.uncertainty.budget import UncertaintyBudget
from models.uncertainty.conformity import HalfRangeEstimate, half_range_monte_carlo
from models.uncertainty.tilt_bound_words import (
    BOUND_UNCHECKED,
    TILT_BOUND_ZERO,
    TILT_BOUNDED,
    TILT_BOUNDED_DEFAULT,
    tilt_bound_origin,
)

__all__ = ["BOUND_UNCHECKED", "TILT_BOUNDED", "TILT_BOUNDED_DEFAULT", "TILT_BOUND_ZERO",
           "half_range_with_bounded_systematic", "tilt_bound_origin", "tilt_bounded",
           "widened_by_systematic", "without_inputs"]

def tilt_bounded(bound: float, change: float, default: float) -> str:
    """What the decision says of a tilt up to ``bound`` (″) not identified, changing the half
    range by ``change`` (″) at most: the bound stated, or the workbench's ``default`` where
    it is that (the setting left as the program gives it)."""
    from models.messages import message

    return message(TILT_BOUNDED_DEFAULT if bound == default else TILT_BOUNDED,
                   bound=f"{bound:g}\"", change=f"{change:.3g}\"")


def without_inputs(budget: UncertaintyBudget, names: Container[str]) -> UncertaintyBudget:
    """``budget`` less the inputs named ``names`` (the same points, probability, unit and
    floor)."""
    return UncertaintyBudget(tuple(c for c in budget.components if c.name not in names),
                             budget.points, budget.probability, budget.unit, budget.floor)


def half_range_with_bounded_systematic(errors, budget: UncertaintyBudget,
                                       systematic: Container[str], change: float,
                                       method: str = "") -> HalfRangeEstimate:
    """Half the peak-to-peak of ``errors`` with its coverage interval when the inputs named
    ``systematic`` are one bounded systematic error whose largest change to a half range is
    ``change`` (in the budget's unit; see the module's note): the Monte Carlo of the other
    inputs (:func:`widened_by_systematic`). ``method``: the decision's text of how it was
    made ("": the Monte Carlo's)."""
    return widened_by_systematic(
        half_range_monte_carlo(errors, without_inputs(budget, systematic)), change, method)


def widened_by_systematic(estimate: HalfRangeEstimate, change: float,
                          method: str = "") -> HalfRangeEstimate:
    """``estimate`` (of the half range of the curve the readings measure, a bounded
    systematic error in it) with its interval widened by ``change`` at both ends, the lower
    end not below 0, its value kept; ``method``: the decision's text ("": the estimate's).
    One with no interval (NaN ends) is returned as it is."""
    low = estimate.value - estimate.u_lower
    high = estimate.value + estimate.u_upper
    if not change > 0.0 or not (math.isfinite(low) and math.isfinite(high)):
        return estimate
    low = max(0.0, low - change)
    high = high + change
    return dataclasses.replace(estimate, u_lower=estimate.value - low,
                               u_upper=high - estimate.value,
                               method=method or estimate.method)
