"""Coverage intervals of the ISO 230-2 figures of a theodolite run with repeated passes.

With the axis measured in several passes (a run column and a direction, or θ repeated),
the corrected error at each θ and direction has a mean and a standard deviation over the
passes, and the certificate states the ISO 230-2 figures of them (E, M, B, B̄, R, A and
their one-direction forms). Their intervals come from the positioning workbench's
parametric bootstrap of the axis (models.uncertainty.figure_intervals: the world fitted to
the readings, the estimator's own bias handled, united with the unshrunk world and, with
inputs that are one value at a θ, with the readings without them), fed with:

* the means and standard deviations of the corrected error over the passes: the pointing
  noise (new in every reading) is in them;
* per θ, the inputs whose error is the same at that θ in every pass and both directions
  (the positioning's "Type B per target"): the set-up model's error (ψ, α, β are identified
  once for the run, so ζ's error at a θ repeats in every pass), and the part of the stated
  theodolite's u per reading that the passes' own scatter does not show,
  √max(u_std² − s_pooled², 0): the circle's error at the position it reads for that θ, the
  same in every pass. Where the stated u is all pointing noise, the scatter shows it and
  nothing is left over; where it is the circle's error, the scatter does not.
  The reference reading θ₀ is one value for the run: it moves every error alike and no
  figure (a range, a reversal, a scatter) sees it.

The probability printed beside a figure is the lower of the one asked for and the one the
positioning study reached (models.uncertainty.figure_intervals.ACHIEVED) and the theodolite
study (:data:`THEODOLITE_ACHIEVED`, tests/models/theodolite/test_theodolite_figures.py and
the closing note of 0.8.6).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.theodolite.model import TheodoliteResult
from models.uncertainty.budget import UncertaintyBudget
from models.uncertainty.conformity import readings_seed
from models.uncertainty.figure_intervals import FigureInterval, figure_intervals

__all__ = ["THEODOLITE_ACHIEVED", "figure_intervals_withheld", "theodolite_figure_intervals",
           "theodolite_figures_json"]

#: ISO 230-2 figure → the coverage the theodolite study reached at 95.45 % asked for, where
#: below it (the probability printed is then this one)
THEODOLITE_ACHIEVED: dict[str, float] = {}

ONCE_ONLY = QT_TR_NOOP("a θ was read fewer than twice in a direction: its standard deviation "
                       "over the passes is unknown, so no ISO 230-2 figure has a coverage "
                       "interval")
NO_SCATTER = QT_TR_NOOP("the corrected errors of every θ came out identical in each direction "
                        "over the passes: their scatter cannot be told, so no ISO 230-2 figure "
                        "has a coverage interval")


def _directions(result: TheodoliteResult):
    iso = result.iso230
    if iso is None:
        return []
    return [(name, stats) for name, stats in (("up", iso.forward), ("down", iso.backward))
            if stats is not None]


def figure_intervals_withheld(result: TheodoliteResult) -> str | None:
    """Why the ISO 230-2 figures get no interval (a message template), or None (also None
    where the run has no ISO 230-2 figures at all)."""
    present = _directions(result)
    if not present:
        return None
    if not all(np.all(stats.runs >= 2) and np.all(np.isfinite(stats.std))
               for _, stats in present):
        return ONCE_ONLY
    if all(np.all(stats.std == 0.0) for _, stats in present):
        return NO_SCATTER
    return None


def _per_theta(result: TheodoliteResult, values) -> np.ndarray:
    """A per-reading array's root mean square at each θ of the ISO evaluation."""
    iso = result.iso230
    assert iso is not None
    v = np.broadcast_to(np.asarray(values, dtype=float), result.theta_deg.shape)
    key = np.searchsorted(iso.positions, np.round(result.theta_deg, 6))
    key = np.clip(key, 0, iso.positions.size - 1)
    out = np.zeros(iso.positions.size)
    for i in range(iso.positions.size):
        here = v[key == i]
        out[i] = math.sqrt(float(np.mean(here**2))) if here.size else 0.0
    return out


def repeated_at_each_theta(result: TheodoliteResult, stated_u: float
                           ) -> tuple[np.ndarray, float, float]:
    """The standard uncertainty at each θ of the inputs that repeat in every pass (the
    set-up model's error; the stated u's part the passes do not show), ``pair_u`` (the
    largest standard deviation they give the difference of two θ's errors: u_i + u_j for
    each, whatever their correlation) and that part of the stated u."""
    present = _directions(result)
    nu = sum(float(np.sum(stats.runs - 1)) for _, stats in present)
    ss = sum(float(np.nansum((stats.runs - 1) * stats.std**2)) for _, stats in present)
    pooled = math.sqrt(ss / nu) if nu > 0 else 0.0
    circle = math.sqrt(max(stated_u**2 - pooled**2, 0.0))
    model = _per_theta(result, result.model_uncertainty_arcsec)
    u_b = np.sqrt(model**2 + circle**2)
    pair = math.hypot(2.0 * float(np.max(model)) if model.size else 0.0, 2.0 * circle)
    return u_b, pair, circle


def theodolite_figure_intervals(result: TheodoliteResult, budget: UncertaintyBudget,
                                stated_u: float = 0.0) -> dict[str, FigureInterval]:
    """The coverage interval of every ISO 230-2 figure of ``result`` at the ``budget``'s
    probability (``stated_u``: the stated standards' u per reading, arcsec); empty when
    :func:`figure_intervals_withheld` says why, or when the run has no figures."""
    present = _directions(result)
    if not present or figure_intervals_withheld(result) is not None:
        return {}
    iso = result.iso230
    assert iso is not None
    u_b, pair, _ = repeated_at_each_theta(result, stated_u)
    key = (budget.probability, u_b.tobytes(), pair)
    cache = result.__dict__.setdefault("_figure_intervals", {})
    if key not in cache:
        figures = {k: v for k, v in iso.figures.items() if math.isfinite(v)}
        # seeded from the curve on a coarse grid (models.uncertainty.conformity.readings_seed):
        # a fitted curve's last digits differ between processors
        seed = readings_seed(result.corrected_error_arcsec, budget)
        found = figure_intervals({name: stats.mean for name, stats in present},
                                 {name: stats.std for name, stats in present},
                                 {name: stats.runs for name, stats in present},
                                 budget.probability, u_b, seed, figures=figures, pair_u=pair)
        cache[key] = {k: FigureInterval(v.value, v.low, v.high,
                                        min(v.probability, THEODOLITE_ACHIEVED.get(k, 1.0)))
                      for k, v in found.items() if k in figures}
    return cache[key]


def theodolite_figures_json(result: TheodoliteResult, budget: UncertaintyBudget,
                            stated_u: float = 0.0) -> dict[str, Any]:
    """The ISO 230-2 figures as the JSON states them, each {value, interval_low,
    interval_high, coverage_probability}, beside ``iso230_arcsec`` (whose plain values keep
    their meaning), and why there are no intervals; {} for a run with no figures
    (``stated_u``: the stated standards' u per reading, arcsec)."""
    if result.iso230 is None:
        return {}
    intervals = theodolite_figure_intervals(result, budget, stated_u)
    out: dict[str, Any] = {}
    for k, v in result.iso230.figures.items():
        found = intervals.get(k)
        iv: Mapping[str, Any] | None = found.as_dict() if found is not None else None
        out[k] = {"value": v if math.isfinite(v) else None,
                  "interval_low": None if iv is None else iv["interval_low"],
                  "interval_high": None if iv is None else iv["interval_high"],
                  "coverage_probability": None if iv is None else iv["coverage_probability"]}
    withheld = figure_intervals_withheld(result)
    return {"iso230_2_figures": out,
            "iso230_2_figures_reason": None if withheld is None else message(withheld)}
