"""The decided half range of a theodolite run with repeated passes: of the means over the
passes at each θ and direction, not of every reading.

Each reading's corrected error holds its pointing noise; the half range of every reading
of every pass is the widest of them all, and the noise's median excess the Monte Carlo
takes off grows with the number of readings. An independent audit (a 3-D rig, 2 and 4
runs × forward and backward, 11 and 41 θ) found the decided value 0.1–1.4″ above the truth
on average and its interval 1.1–2.3 times the value's own spread. The means over the
passes at each θ and direction keep the reversal (forward and backward apart, as ISO
230-2's E), and their noise is the passes' scatter over √n. Same audit's records, decided
on the means: bias halved, interval 17–46 % narrower, every cell covered (30 of 30).

The budget of a mean (one per θ and direction):

* the pointing noise: the pooled standard deviation of the corrected error over the passes
  (Type A, ν = Σ(n_i − 1)), over √n_i at each mean;
* the part of the stated theodolite u per reading that the readings do not show to scatter,
  √max(u_std² − s_pointing², 0) (models.theodolite.figures.pointing_per_reading): the
  circle's error where it reads that θ, the same in every pass, held in the measured means
  (Type B, :attr:`BudgetComponent.in_curve`; drawn independently for the two directions at
  a θ, which widens the simulated excess of the range a little);
* the set-up model's error (Type A, ν = points − 3): ψ, α, β are fitted once for the run, so
  ζ's error is one smooth curve over θ, the same in every pass and both directions; its
  three modes from the parameters' covariance (models.theodolite.model.model_error_modes),
  each one value for the run with its signed effect at every mean, as the figures' bootstrap
  draws it (until 0.8.8 drawn on its own at each mean; each mean's u is the same);
* the item's resolution, as in the run's budget (per reading, not divided: an envelope).

The reference reading θ₀ moves every error alike: a half range does not see it, and it is
left out. The laboratory's CMC floors each mean's U as it floors each reading's.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from models.certificate.document import resolution_component
from models.certificate.metadata import CertificateMetadata
from models.messages import QT_TR_NOOP, message, separated
from models.theodolite.figures import (
    circle_part,
    circle_part_not_excluded,
    figure_intervals_withheld,
    model_modes_at_each_theta,
    passes_scatter,
    per_angle_note,
    pointing_per_reading,
    readings_coarse,
    theodolite_figure_intervals,
)
from models.theodolite.model import TheodoliteResult
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import (
    DECISION_QUANTITIES,
    HalfRangeEstimate,
    half_range_monte_carlo,
)
from models.uncertainty.lab_scope import cmc_of

__all__ = ["COARSE_DECIDED", "MEANS_DECIDED", "decided_on_means", "means_half_range",
           "pass_means", "pass_means_budget", "withheld_half_range"]

#: what the decision names as its curve
MEANS_DECIDED = QT_TR_NOOP("corrected error, the mean over the passes at each θ and direction")

POINTING_INPUT = QT_TR_NOOP("Pointing noise of a mean over the passes")
MODEL_MODE_INPUT = QT_TR_NOOP("Set-up model ζ (ψ, α, β), direction {k} of their covariance")
MODEL_MODE_NOTE = QT_TR_NOOP(
    "the identified parameters' covariance propagated through ζ(θ), one of its three "
    "directions: one value for the run, with its signed effect at every θ (the model's "
    "error is one smooth curve, drawn as such)")
CIRCLE_INPUT = QT_TR_NOOP("Theodolite's circle error at each θ (the stated u less the passes' "
                          "scatter)")


def decided_on_means(result: TheodoliteResult) -> bool:
    """Whether the run's half range is decided on the means over the passes: the directions
    stated (a direction column; without it the passes back and forth would be averaged
    together and the reversal lost from the decided curve — a reviewer's rig: 9 of 15
    intervals missed), every θ read at least twice in each direction, with some scatter."""
    return (result.iso230 is not None and result.directions is not None
            and figure_intervals_withheld(result) is None)


#: why the decided half range of passes whose readings show no random scatter is withheld
COARSE_DECIDED = QT_TR_NOOP(
    "half the peak-to-peak of the corrected error, withheld: {reason}; the Monte Carlo that "
    "takes the noise's bias off the range would draw random noise these readings do not "
    "have, and each mean may be off by up to half a step in a way their scatter does not "
    "show")


def withheld_half_range(result: TheodoliteResult, probability: float
                        ) -> HalfRangeEstimate | None:
    """The decided half range withheld, with the reason, where the passes' readings are
    alike or entered coarser than they scatter (models.theodolite.figures.readings_coarse:
    the positioning workbench withholds its E/2 so); None where they scatter."""
    if not readings_coarse(result):
        return None
    reason = figure_intervals_withheld(result)
    # the curve it would be decided on: the means over the passes where the directions are
    # stated (half of E: a reviewer found every reading's 3.02″ stated where E/2 was 2.68″,
    # either side of T = 3″), else every reading
    curve = (pass_means(result)[0] if result.directions is not None
             else result.corrected_error_arcsec)
    measured = 0.5 * float(np.ptp(curve))
    return HalfRangeEstimate(measured=measured, bias=math.nan, value=math.nan,
                             u_upper=math.nan, u_lower=math.nan, probability=probability,
                             trials=0, seed=0,
                             method=message(COARSE_DECIDED, reason=message(reason or "")))


def _present(result: TheodoliteResult):
    iso = result.iso230
    assert iso is not None
    return [(name, stats) for name, stats in (("up", iso.forward), ("down", iso.backward))
            if stats is not None]


def pass_means(result: TheodoliteResult) -> tuple[np.ndarray, list[str]]:
    """The means (forward's θ, then backward's) and each one's name ("θ = 2° ↑")."""
    iso = result.iso230
    assert iso is not None
    means, names = [], []
    for name, stats in _present(result):
        arrow = "↑" if name == "up" else "↓"
        means.append(stats.mean)
        names += [f"θ = {t:g}° {arrow}" for t in iso.positions]
    return np.concatenate(means), names


def pass_means_budget(result: TheodoliteResult, metadata: CertificateMetadata,
                      stated_u: float, settings: Mapping[str, Any] | None = None
                      ) -> UncertaintyBudget:
    """The budget of :func:`pass_means` (see the module's note); ``stated_u``: the stated
    standards' u per reading (arcsec)."""
    iso = result.iso230
    assert iso is not None
    present = _present(result)
    runs = np.concatenate([stats.runs for _, stats in present]).astype(float)
    pooled, nu = passes_scatter(result)
    circle = circle_part(result, stated_u)
    # the set-up model's error: one smooth curve over θ (ψ, α, β fitted once for the run),
    # the same in both directions, as its three modes (models.theodolite.model
    # .model_error_modes), each one value for the run with its signed effect at every mean
    modes = np.concatenate([model_modes_at_each_theta(result)] * len(present), axis=1)
    points = runs.size
    dof = max(result.theta_deg.size - 3, 1)
    components = [
        BudgetComponent(POINTING_INPUT, "A", "normal", pooled / np.sqrt(runs), 1.0, 1.0, nu,
                        message(QT_TR_NOOP("s = {s} per reading, pooled over the passes at "
                                           "every θ and direction (ν = {dof}), over √n of "
                                           "each mean"), s=f"{pooled:.3f}\"", dof=f"{nu:.0f}"))]
    components += [
        BudgetComponent(message(MODEL_MODE_INPUT, k=k + 1), "A", "normal", np.abs(mode), 1.0,
                        np.where(mode < 0.0, -1.0, 1.0), dof, message(MODEL_MODE_NOTE),
                        common=True, dof_group="set-up model")
        for k, mode in enumerate(modes)]
    if circle > 0.0:
        note = message(QT_TR_NOOP("√(u² − s²) = {circle}: the stated u = {u} per reading less "
                                  "the theodolite's pointing noise the readings show, s = {s} "
                                  "(the smaller of the passes' scatter and the vertical "
                                  "readings' about the fit, or the repeats' at a point), the "
                                  "same at a θ in every pass"),
                       circle=f"{circle:.3f}\"", u=f"{stated_u:.3f}\"",
                       s=f"{pointing_per_reading(result):.3f}\"")
        note = per_angle_note(note, metadata.standards)
        components.append(BudgetComponent(CIRCLE_INPUT, "B", "normal", circle, 1.0, 1.0,
                                          math.inf, note, in_curve=True))
    components += resolution_component(metadata, math.sqrt(2.0))
    return UncertaintyBudget(tuple(components), points, metadata.coverage_probability,
                             floor=cmc_of(settings, "cmc_arcsec"))


#: how the decided half range is made where it is united with E's interval
MEANS_UNITED = QT_TR_NOOP(
    "{quantity}: {trials} trials, seed {seed}, of the means over the passes; the readings "
    "do not exclude a part of the stated theodolite u over their scatter (up to {circle} "
    "per reading, over the pointing noise's lower confidence bound), an error the same at a "
    "θ in every pass whose shape is not known, and a smooth one running against the curve "
    "lowers the measured range: the interval is united with ISO 230-2 {figure}'s halved, "
    "which holds a circle error of any shape up to that part. The union covers at least as "
    "often as the Monte Carlo (validated on errors independent at each θ); on once-a-turn "
    "circle errors it covered 40 of 40 and, in an independent audit, 200 of 200 runs, where "
    "the Monte Carlo alone covered 28 of 40 and 440 of 600")
#: where an end of that union is E's halved: the probability the union is stated at
MEANS_UNITED_PROBABILITY = QT_TR_NOOP(
    "an end of the interval is ISO 230-2 {figure}'s halved, whose interval holds at the "
    "{p} % its simulation study reached, so the interval is stated at {p} % and the "
    "probabilities of conformity and of a wrong decision are computed at it")


def means_half_range(result: TheodoliteResult, budget: UncertaintyBudget,
                     run_budget: UncertaintyBudget, stated_u: float,
                     pair_factor: float = 2.0) -> HalfRangeEstimate:
    """The decided half range of the means (:func:`pass_means`) with its interval: the Monte
    Carlo of the means' ``budget`` (models.uncertainty.conformity.half_range_monte_carlo),
    which draws the circle's error on its own at each θ. Where the readings do not exclude
    a circle error in the stated u (models.theodolite.figures.circle_part_not_excluded: until
    0.8.14, where they showed one at 95 %, and under 1.5″ pointing noise a 0.4″ circle error
    against the curve, 5 passes over 11 θ, was covered in 67 of 80 runs, now 80), its shape is
    not known, and a smooth one running against the curve lowers the measured range: an
    independent audit's rig (a once-a-turn circle error of 0.4″ under 0.15″ pointing, 300
    runs) found the truth above the interval in 84 and 76 of 300 runs. The interval is then
    united with ISO 230-2 E's halved (E↑'s or E↓'s with one direction; models.theodolite
    .figures, ``run_budget``'s probability and seed), which holds a circle error of any
    shape; the value stays the Monte Carlo's. The union covers at least as often as the
    Monte Carlo wherever that holds, and covered every run of the once-a-turn errors where
    it did not; where an end is E's halved, the probability stated is the lower of the
    Monte Carlo's and E's own (the one E's simulation study reached,
    models.uncertainty.figure_intervals.ACHIEVED: 92.5 % for E), and the decision's
    probabilities (models.uncertainty.conformity.probability_conforming) use it.
    ``pair_factor``: as in E's interval
    (models.theodolite.figures.theodolite_figure_intervals; 1 for a theodolite whose u is
    stated for any angle between two readings, whose circle errors at two θ then differ by
    at most its own u)."""
    means = pass_means(result)[0]
    estimate = half_range_monte_carlo(means, budget)
    circle = circle_part_not_excluded(result, stated_u, run_budget.probability)
    if not (circle > 0.0) or not all(
            math.isfinite(v) for v in (estimate.u_lower, estimate.u_upper)):
        return estimate
    present = [name for name, _ in _present(result)]
    key = "E" if len(present) == 2 else f"E_{present[0]}"
    e = theodolite_figure_intervals(result, run_budget, stated_u, pair_factor).get(key)
    if e is None or not (math.isfinite(e.low) and math.isfinite(e.high)):
        return estimate
    low = min(estimate.value - estimate.u_lower, 0.5 * e.low)
    high = max(estimate.value + estimate.u_upper, 0.5 * e.high)
    figure = {"E": "E", "E_up": "E↑", "E_down": "E↓"}[key]
    method = message(MEANS_UNITED, quantity=message(DECISION_QUANTITIES["half_range"]),
                     trials=estimate.trials, seed=str(estimate.seed),
                     circle=f"{circle:.3f}\"", figure=figure)
    probability = estimate.probability
    if low < estimate.value - estimate.u_lower or high > estimate.value + estimate.u_upper:
        # an end is E's halved, whose interval holds at the probability its study reached
        # (models.uncertainty.figure_intervals.ACHIEVED): the union is stated at the lower
        # of the two, and the decision's probabilities are computed at it
        probability = min(probability, float(e.probability))
        method = separated([method, message(MEANS_UNITED_PROBABILITY, figure=figure,
                                            p=f"{100 * probability:.2f}")], "; ")
    return dataclasses.replace(estimate, u_lower=estimate.value - low,
                               u_upper=high - estimate.value, probability=probability,
                               method=method)
