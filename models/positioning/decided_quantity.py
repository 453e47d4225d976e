"""The positioning workbench's decided quantity: half the peak-to-peak of the mean positional
deviations of the directions measured — E/2 of ISO 230-2 (E↑/2 or E↓/2 for one direction) —
with E's own coverage interval halved (models.uncertainty.figure_intervals), so that the
certificate, the JSON and the DCC state one interval for one quantity, at the probability
that interval reached in the validation study.

The shared estimator of the other workbenches (models.uncertainty.conformity
.half_range_monte_carlo, the two-step bound of Romano, Shaikh & Wolf) covers here too, but
at 3.4–8.3 times the width a correct interval needs: it must hold for the least favourable
curve the data allow and draws the repeatability's t-distribution with the fewest runs'
four degrees of freedom, where E's parametric bootstrap models the axis itself.
"""

from __future__ import annotations

import math

from models.messages import QT_TR_NOOP, message
from models.positioning.model import PositioningResult
from models.uncertainty.budget import UncertaintyBudget
from models.uncertainty.conformity import HalfRangeEstimate
from models.uncertainty.figure_intervals import INTERVAL_TRIALS, FigureInterval, readings_seed

__all__ = ["COARSE_DECIDED", "DECIDED_METHOD", "decided_figure", "decided_half_range"]

DECIDED_METHOD = QT_TR_NOOP(
    "half the peak-to-peak of the mean positional deviations of {directions}, {figure}/2 "
    "(ISO 230-2), with the coverage interval of {figure} halved: a parametric bootstrap of "
    "the figure's error from a model of the axis whose true means have the distribution the "
    "readings show (triple-goal estimates, Shen & Louis 1998), united with the one from the "
    "measured means taken as the truth (Berger & Boos 1994), {trials} trials, seed {seed}; "
    "the probability stated is the one its validation reached (anglebench validate: smooth, "
    "rough, single-spike and real curves, repeatability 0.1 to 2 times the signal, 12, 36 and 72 "
    "targets). The measured range is biased high by the scatter, so the interval may lie "
    "below the measured value (its upper end then shown with a minus sign)")


COARSE_DECIDED = QT_TR_NOOP(
    "half the peak-to-peak of the mean positional deviations, withheld: the readings were "
    "entered coarser than they scatter, so each mean may be off by up to half a step in a "
    "way their scatter does not show, and the range with it")


def decided_figure(result: PositioningResult) -> str:
    """The ISO 230-2 figure whose half is decided: E with both directions, else E↑ or E↓."""
    present = [name for name, _, _ in result.directions_present()]
    return "E" if len(present) == 2 else f"E_{present[0]}"


def decided_half_range(result: PositioningResult, budget: UncertaintyBudget,
                       intervals: dict[str, FigureInterval]) -> HalfRangeEstimate | None:
    """E/2 (or E↑/2, E↓/2) and its interval from ``intervals`` (models.positioning.report
    .figure_uncertainties with the certificate's ``budget``); None when the figure has no
    interval (a target approached fewer than twice: the repeatability unknown)."""
    key = decided_figure(result)
    if result.coarse_readings:
        # the rounding of each mean may have flattened the curve by up to half a step at
        # either extreme, which no model of random scatter holds: withheld, with the reason
        measured = 0.5 * float(result.iso.figures.get(key, math.nan))
        return HalfRangeEstimate(measured=measured, bias=math.nan, value=math.nan,
                                 u_upper=math.nan, u_lower=math.nan,
                                 probability=budget.probability, trials=0, seed=0,
                                 method=message(COARSE_DECIDED))
    interval = intervals.get(key)
    if interval is None or not all(math.isfinite(v) for v in (interval.value, interval.low,
                                                              interval.high)):
        return None
    value = 0.5 * interval.value
    directions = (message(QT_TR_NOOP("both directions")) if key == "E" else
                  message(QT_TR_NOOP("the forward direction")) if key == "E_up" else
                  message(QT_TR_NOOP("the backward direction")))
    seed = readings_seed(result.targets, result.directions, result.deviations)
    figure = {"E": "E", "E_up": "E↑", "E_down": "E↓"}[key]
    return HalfRangeEstimate(
        measured=value, bias=0.0, value=value,
        u_upper=0.5 * interval.high - value, u_lower=value - 0.5 * interval.low,
        probability=interval.probability, trials=INTERVAL_TRIALS, seed=seed,
        method=message(DECIDED_METHOD, directions=directions, figure=figure,
                       trials=INTERVAL_TRIALS, seed=seed))
