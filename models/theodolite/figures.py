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
  once for the run, so ζ's error at a θ repeats in every pass), drawn as the fit's
  covariance correlates it from θ to θ (:func:`model_modes_at_each_theta`; it was drawn on
  its own at each θ and, as an envelope of unknown correlation, widened E, M and A by
  z·2 max u(ζ) each way), and the part of the stated theodolite's u per reading that the
  readings do not show to scatter, √max(u_std² − s², 0) (:func:`circle_part`): the circle's
  error at the position it reads for that θ, the same in every pass. Where the stated u is
  all pointing noise, the scatter shows it and nothing is left over; where it is the
  circle's error, the scatter does not. Its shape is not known: the interval is also
  widened for one shaped as the curve's worst, by the largest part the readings do not
  exclude (:func:`circle_part_not_excluded`, u over the pointing noise's one-sided lower
  confidence bound at :data:`CIRCLE_NUISANCE_SHARE` of the tail, the widened interval at the
  rest: Berger & Boos 1994). Until 0.8.14 it was sized by the part the readings show to be
  there at 95 % (over the upper bound): where the pointing noise hides the circle's part
  (σ = 1.5″, u_c = 0.4″, the circle's error flattening the curve) that is 0 in nearly every
  run, and E covered 56–76 of 80 runs, M 45–70 (floor 68; now 80 of 80 in each of the 4
  cells, #39). The price: with u stated at exactly the pointing noise, which no readings
  can tell from a circle error hidden under it, E's interval became 1.9–2.9 times as wide,
  M's 2.2–3.0, A's 1.8–2.3 (σ = 0.5″, 2 and 5 passes, 11 and 41 θ; the study of #39
  in docs/user-guide/theodolite.md).
  The circle's error is taken within its U at the probability of the interval at every θ,
  whatever its shape (the statement taken at its U: ±2u_c per reading at 95.45 %), so it
  moves E, M and A (and E↑, E↓, A↑, A↓: a largest value less a smallest one) by at most its
  range, k · pair (k · 2u_c per reading, k · √2 u_c for a theodolite stated for any angle,
  u_c then of each reading's share u/√2 of the angle's u, #39): a
  bias, not a scatter. The readings' own interval at the whole rest of the tail each side,
  widened by that, holds at the probability printed (models.uncertainty.figure_intervals,
  ``pair_envelope``). Until 0.8.15 the circle was taken as a normal error and the widening
  was a union bound, z(1 − tail′/2) · pair (≈ 2.39 pair) on the readings' interval at half
  the rest of the tail: E's, M's, A's and the decided half range's intervals are now 0.84–0.95
  of that width (median of the runs; 0.88–0.89 the median cell), and every figure covered at
  least its binomial floor in every cell (the study of #39's widths, 62 cells of 60 runs, in
  docs/user-guide/theodolite.md). Combining the circle's widening with
  the readings' half-width in quadrature (the circle taken as a normal error) is narrower
  still, 0.63–0.94, but does not hold such a bias: A covered 47 of 60 (floor 51) under
  σ = 0.5″ with u_c = 0.8″ running with the curve, 5 passes.
  The reference reading θ₀ is one value for the run: it moves every error alike and no
  figure (a range, a reversal, a scatter) sees it.
* A, A↑ and A↓ (as R, R↑ and R↓) take bounds from each θ's own mean and s over the passes in
  place of the bootstrap's interval (models.uncertainty.figure_intervals._band_span_bounds,
  #39), which hold however the scatter changes from θ to θ; the set-up model's error enters
  them at a tenth of the tail, as the largest difference of its errors at two θ. They are
  wide at few passes (a θ's μ + 2σ up to x̄ + 13.7 s from 3 passes, x̄ + 70 s from 2; each
  bound at the whole tail, the pair exact at the least favourable σ, #39's widths; until
  0.8.17 at half the tail, x̄ + 19.4 s and 140 s): at 0.8.17, 19.5 times the width the
  figure's spread needs at 3 passes, against 2.8 for the bootstrap's.

Where the laboratory states its CMC (the setting *cmc_arcsec*, the axis error's, in
arcsec as the figures), a certificate, its JSON and DCC state the intervals held to it
(:func:`stated_theodolite_figure_intervals`: each half-width at least the CMC, by the rule
of the decided quantity's, models.uncertainty.lab_scope.held_to_cmc); the decided half range
is made from the computed ones and held once.

The probability printed beside a figure is the lower of the one asked for and the one the
positioning study reached (models.uncertainty.figure_intervals.ACHIEVED); the theodolite's
own studies (models.theodolite.validation_cases, tests/models/theodolite/
test_theodolite_figures.py, and an independent audit of 2,800 runs in 14 cells) reached at
least it in every cell.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, Message, message, separated
from models.readings.repeats import RepeatedReadings
from models.readings.resolution import coarse, readings_step
from models.theodolite.model import MODEL_INPUT, TheodoliteResult, model_error_modes
from models.uncertainty.budget import UncertaintyBudget, divisor_for_basis
from models.uncertainty.conformity import readings_seed
from models.uncertainty.figure_intervals import (
    FIGURE_VALUE_NOTE,
    FigureInterval,
    figure_intervals,
    figure_objects,
    held_to_cmc_figures,
    pair_widening,
)
from models.uncertainty.rounding import interval_decimals, without_interval_decimals
from models.uncertainty.stated_excess import excess_not_excluded
from models.uncertainty.undetermined_repeatability import (
    PASSES_UNDETERMINED,
    PASSES_UNDETERMINED_READINGS,
    undetermined_repeatability,
)

__all__ = ["CIRCLE_NUISANCE_SHARE", "MODEL_INPUT", "PER_ANGLE_NOTE", "PER_ANGLE_STANDARD", "circle_part",
           "per_angle_note",
           "circle_part_not_excluded", "figure_intervals_withheld", "figures_scatter",
           "least_passes",
           "theodolite_figure_decimals",
           "model_at_each_theta", "model_modes_at_each_theta", "pointing_and_dof",
           "pointing_in_figures", "pointing_in_figures_note", "pointing_per_reading",
           "pooled_repeats", "readings_coarse", "readings_theodolite_figure_intervals",
           "stated_theodolite_figure_intervals", "withheld_theodolite_figure_reasons",
           "theodolite_figure_intervals", "theodolite_figures_json"]

# the budget's name of the set-up model's error, in models.theodolite.model (light: a plain
# analyze imports it without this module's scipy)

ONCE_ONLY = QT_TR_NOOP("a θ was read fewer than twice in a direction: its standard deviation "
                       "over the passes is unknown, so no ISO 230-2 figure has a coverage "
                       "interval")
NO_SCATTER = QT_TR_NOOP("the corrected errors of every θ came out identical over the passes in "
                        "a direction: their scatter cannot be told (readings rounded coarser "
                        "than they scatter?), so no ISO 230-2 figure has a coverage interval")
COARSE = QT_TR_NOOP("the readings were entered coarser than they scatter over the passes (step "
                    "{step}, s pooled {s}): the rounding of each mean is not random, and the "
                    "model the intervals are drawn from (random scatter about each θ's true "
                    "mean) does not hold, so no ISO 230-2 figure has a coverage interval")


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
    if any(np.all(stats.std == 0.0) for _, stats in present):  # one direction is enough:
        return NO_SCATTER  # its figures would get a zero-width interval
    step, pooled = readings_step(result.raw_error_arcsec), passes_scatter(result)[0]
    if coarse(step, pooled):  # as the positioning's (models.readings.resolution)
        return message(COARSE, step=f"{step:g}\"", s=f"{pooled:.3g}\"")
    return None


def readings_coarse(result: TheodoliteResult) -> bool:
    """Whether the passes' readings cannot hold the noise model of the decided half range:
    every θ's readings alike over the passes in a direction, or entered coarser than they
    scatter (models.readings.resolution.coarse, the raw error's step: the azimuth readings'
    as typed). A Monte Carlo that removes the noise's bias from the range then removes what
    the readings show is not there (an audit: exact readings, u = 0.5″ stated, the half range
    decided 1.68″ … [0.88″, 2.12″] where 2.32″ was measured and true)."""
    withheld = figure_intervals_withheld(result)
    return withheld is not None and withheld != ONCE_ONLY


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


def pooled_repeats(result: TheodoliteResult) -> tuple[float, int, int] | None:
    """With n readings per point, the pooled standard deviation of a point's mean azimuth,
    s_repeat/√n (arcsec; the points' s/√n pooled, every point having n readings), its
    ν = points · (n − 1) and n; None with one reading a point."""
    repeats = result.repeats
    if not isinstance(repeats, RepeatedReadings):
        return None
    s_mean = 3600.0 * np.asarray(repeats.s_mean["azimuth_deg"], dtype=float)
    return float(np.sqrt(np.mean(s_mean**2))), int(s_mean.size * repeats.dof), repeats.n


def passes_scatter(result: TheodoliteResult) -> tuple[float, float]:
    """The corrected error's standard deviation over the passes, pooled over every θ and
    direction, and its ν."""
    present = _directions(result)
    nu = sum(float(np.sum(stats.runs - 1)) for _, stats in present)
    ss = sum(float(np.nansum((stats.runs - 1) * stats.std**2)) for _, stats in present)
    return (math.sqrt(ss / nu) if nu > 0 else 0.0), nu


def figures_scatter(result: TheodoliteResult) -> tuple[float, bool]:
    """The scatter that sets the place of a figure with no interval at all
    (models.uncertainty.rounding.without_interval_decimals), and whether it is the
    readings' about the set-up fit: the corrected error's pooled s over the passes; with
    one pass each way (no ν) the vertical readings' residual RMS about the fit, each
    reading's pointing noise (leftovers 80: such figures were printed to 0.001″ beside a U
    of 1.5″)."""
    s, nu = passes_scatter(result)
    if nu > 0 and s > 0:
        return s, False
    rms = float(result.identification.residual_rms_arcsec)
    return (rms, True) if math.isfinite(rms) and rms > 0 else (s, False)


def pointing_per_reading(result: TheodoliteResult) -> float:
    """The theodolite's own pointing noise per reading, as the readings show it, for what
    of its stated u averages: with n readings a point, the repeats' s_repeat (the axis does
    not move between them); else the smaller of the passes' scatter and the vertical
    readings' scatter about the fit (an autocollimating theodolite sets on the mirror as
    repeatably in elevation as in azimuth). The passes' scatter alone also holds the axis'
    own non-repeatability: where the axis scatters more than the theodolite points, taking
    it for the pointing noise left the circle's error out (a reviewer's rig: pointing 0.1″,
    axis 0.5″, circle 0.4″ — 4 of 20 decided intervals missed)."""
    return pointing_and_dof(result)[0]


def pointing_and_dof(result: TheodoliteResult) -> tuple[float, float]:
    """:func:`pointing_per_reading` and its degrees of freedom."""
    repeats = pooled_repeats(result)
    if repeats is not None:
        s_mean, dof_repeats, n = repeats
        return s_mean * math.sqrt(n), float(dof_repeats)
    passes, nu = passes_scatter(result)
    dof = result.elevation_residuals_arcsec.size - 3
    if dof < 1:
        return passes, nu
    fit = math.sqrt(float(np.sum(result.elevation_residuals_arcsec**2)) / dof)
    return (passes, nu) if passes <= fit else (fit, float(dof))


#: what R and A (and their one-direction forms) of a run with passes are: the axis' as read
#: with this theodolite, their standard deviations at each θ holding its pointing noise (the
#: certificate's statements, the JSON beside the figures' note, the summary)
POINTING_IN_FIGURES = QT_TR_NOOP(
    "ISO 230-2 R and A (and R↑, R↓, A↑, A↓) are of the axis as read with this theodolite: "
    "the standard deviations over the passes they are made of hold its pointing noise, {s} "
    "per reading as the readings show it (ν = {dof}); a perfectly repeatable axis read with "
    "it has R ≈ {r}, and their coverage intervals are of the figures as so read. E, M, B "
    "and B̄ are of the means over the passes: the axis' own.")


def pointing_in_figures(result: TheodoliteResult) -> tuple[float, float, float] | None:
    """What the theodolite's pointing noise alone puts into ISO 230-2 R: (s per reading,
    its ν, R = 4 s/√n), s and ν :func:`pointing_and_dof`, n the readings averaged into a
    pass's value at a θ (1 without repeated readings); R = 4 s_i for an axis that repeats
    perfectly, R↑ and R↓ the same. None where no R is evaluated (no passes, or a θ read
    once in a direction)."""
    present = _directions(result)
    if not present or not all(np.all(stats.runs >= 2) for _, stats in present):
        return None
    s, dof = pointing_and_dof(result)
    repeats = pooled_repeats(result)
    n = 1 if repeats is None else repeats[2]
    return s, dof, 4.0 * s / math.sqrt(n)


def pointing_in_figures_note(result: TheodoliteResult) -> str | None:
    """:data:`POINTING_IN_FIGURES` with the run's figures (:func:`pointing_in_figures`), or
    None where no R is evaluated."""
    found = pointing_in_figures(result)
    if found is None:
        return None
    s, dof, r = found
    return message(POINTING_IN_FIGURES, s=f"{s:.2g}\"", dof=f"{dof:.0f}", r=f"{r:.2g}\"")


#: the share of the coverage interval's tail spent on the pointing noise's lower confidence
#: bound, which sizes the widening for a circle error of the curve's worst shape
#: (:func:`circle_part_not_excluded`); the widened interval is held at the rest (Berger &
#: Boos 1994). 0.25: the expected half-width z(1 − (1 − γ) tail/2) · s_E + 2k √(u² − s_lo(γ)²)
#: (s_E the figure's own spread, about 1.2 σ/√passes) is within 1.3 % of its least over γ in
#: every case of the study of #39 (σ 0.1–1.5″, u_c 0–0.8″, ν 22–328; 0.4–0.5 the least where
#: the circle hides under the pointing noise, 0.1 where it stands above it)
CIRCLE_NUISANCE_SHARE = 0.25


#: a budget note where a standard is stated for any angle between two readings: the stated
#: u per reading is then its figure over √2 (models.theodolite.report.stated_reading_uncertainty);
#: each such standard named with its figure and its share a reading (day review 69 F2: "u =
#: 0.354″ per reading" beside "0.5″" in the table, and the reader left to find 0.5/√2)
PER_ANGLE_NOTE = QT_TR_NOOP("{note}; {standards}: a standard stated for any angle between two "
                            "readings enters each reading at u/√2, since an angle is the "
                            "difference of two readings, each with its own error, so a point "
                            "(its reading less θ₀'s) takes u once")
#: one standard stated per angle in :data:`PER_ANGLE_NOTE`
PER_ANGLE_STANDARD = QT_TR_NOOP("{standard} u = {u} per angle, u/√2 = {share} per reading")


def per_angle_note(note, standards) -> Any:
    """``note`` with :data:`PER_ANGLE_NOTE` where any of ``standards`` (the certificate's)
    states a u for any angle between two readings, each such standard named with its u (its
    basis's divisor applied) and u/√2; ``note`` as it is where none does."""
    named = []
    for std in standards:
        if std.applies_to != "angle" or std.uncertainty is None:
            continue
        u = std.uncertainty_in("arcsec") / divisor_for_basis(std.basis)[0]
        named.append(message(PER_ANGLE_STANDARD, u=f"{u:.3f}\"",
                             share=f"{u / math.sqrt(2.0):.3f}\"",
                             standard=std.description or message(QT_TR_NOOP("standard"))))
    if not named:
        return note
    return message(PER_ANGLE_NOTE, note=note, standards=separated(named, ", "))


def circle_part(result: TheodoliteResult, stated_u: float) -> float:
    """The part of the stated u per reading that the readings do not show to scatter, the
    circle's error at the position it reads for a θ, the same in every pass:
    √max(u² − s², 0), s = :func:`pointing_per_reading` (the budgets' and the figures' draws
    at each θ)."""
    return math.sqrt(max(stated_u**2 - pointing_per_reading(result) ** 2, 0.0))


def circle_part_not_excluded(result: TheodoliteResult, stated_u: float,
                             probability: float) -> float:
    """The largest part of the stated u per reading that the readings do not exclude, at the
    share :data:`CIRCLE_NUISANCE_SHARE` of the tail of a ``probability`` interval:
    √max(u² − s_lo², 0), s_lo the pointing noise's one-sided lower confidence bound
    (models.uncertainty.stated_excess.scatter_lower_bound, σ ≥ s_lo at 1 − γ(1 − p)); 0
    where u is at or below s_lo, or no u is stated. It sizes the figures' widening for a
    circle error shaped as the curve's worst (k · 2 u each way, k the two-sided normal
    factor of ``probability``; k · √2 u for a theodolite stated for any angle, u then each
    reading's share u/√2,
    models.theodolite.report.stated_pair_factor), whose interval is held at the rest of the
    tail. :func:`circle_part` (the point estimate) stays the draw at each θ
    and the budgets'."""
    if not stated_u > 0.0:
        return 0.0
    s, nu = pointing_and_dof(result)
    return excess_not_excluded(stated_u, s, nu, CIRCLE_NUISANCE_SHARE * (1.0 - probability))


def model_at_each_theta(result: TheodoliteResult) -> np.ndarray:
    """The set-up model's standard uncertainty at each θ of the ISO evaluation."""
    return _per_theta(result, result.model_uncertainty_arcsec)


def model_modes_at_each_theta(result: TheodoliteResult) -> np.ndarray:
    """The set-up model's error at each θ of the ISO evaluation as modes (3, positions),
    arcsec: error = z @ modes, z ~ N(0, I₃) (models.theodolite.model.model_error_modes at
    the rotations from the reference reading)."""
    iso = result.iso230
    assert iso is not None
    rotation = np.asarray(iso.positions, dtype=float) - result.reference_theta_deg
    return model_error_modes(rotation, result.identification).T


def theodolite_figure_intervals(result: TheodoliteResult, budget: UncertaintyBudget,
                                stated_u: float = 0.0, pair_factor: float = 2.0
                                ) -> dict[str, FigureInterval]:
    """The coverage interval of every ISO 230-2 figure of ``result`` at the ``budget``'s
    probability (``stated_u``: the stated standards' u per reading, arcsec); empty when
    :func:`figure_intervals_withheld` says why, or when the run has no figures.
    ``pair_factor``: how many times its own u the difference of the circle's errors at two
    θ can have as its standard deviation (models.theodolite.report.stated_pair_factor: 2 for
    a theodolite stated per reading, √2 for one stated for any angle between two readings,
    whose ``stated_u`` is each reading's share u/√2)."""
    present = _directions(result)
    if not present or figure_intervals_withheld(result) is not None:
        return {}
    iso = result.iso230
    assert iso is not None
    # the stated theodolite's error that repeats at a θ in every pass, an envelope whose
    # correlation from θ to θ is not known: drawn at each θ at the part the scatter does not
    # show, and its worst shape (2 u between two θ; u where the theodolite's u is stated
    # for any angle; within k times that, its U) sized by the largest part the readings do
    # not exclude, at a share of the tail (the widened interval at the rest)
    circle = circle_part(result, stated_u)
    pair = pair_factor * circle_part_not_excluded(result, stated_u, budget.probability)
    modes = model_modes_at_each_theta(result)
    # seeded from the curve on a coarse grid (models.uncertainty.conformity.readings_seed):
    # a fitted curve's last digits differ between processors; in the key, so that the
    # intervals do not depend on which budget asked first (the summary's or a certificate's)
    seed = readings_seed(result.corrected_error_arcsec, budget)
    key = (budget.probability, circle, pair, seed)  # the modes: from the readings
    cache = result.__dict__.setdefault("_theodolite_figure_intervals", {})
    if key not in cache:
        figures = {k: v for k, v in iso.figures.items() if math.isfinite(v)}
        found = figure_intervals({name: stats.mean for name, stats in present},
                                 {name: stats.std for name, stats in present},
                                 {name: stats.runs for name, stats in present},
                                 budget.probability, circle, seed, figures=figures, pair_u=pair,
                                 model_modes=modes, pair_spent=CIRCLE_NUISANCE_SHARE,
                                 pair_envelope=True)
        cache[key] = {k: v for k, v in found.items() if k in figures}
    return cache[key]


def stated_theodolite_figure_intervals(result: TheodoliteResult, budget: UncertaintyBudget,
                                       stated_u: float = 0.0, pair_factor: float = 2.0
                                       ) -> dict[str, FigureInterval]:
    """The intervals of :func:`theodolite_figure_intervals` as a certificate, its JSON and
    DCC state them: each half-width held to the laboratory's CMC, the ``budget``'s
    ``floor`` (the setting *cmc_arcsec*, in arcsec as the figures), each marked with what
    was raised (models.uncertainty.figure_intervals.held_to_cmc_figures)."""
    return undetermined_repeatability(
        held_to_cmc_figures(theodolite_figure_intervals(result, budget, stated_u, pair_factor),
                            float(budget.floor)),
        _passes(result), PASSES_UNDETERMINED)[0]


def _passes(result: TheodoliteResult) -> dict[str, np.ndarray]:
    return {name: stats.runs for name, stats in _directions(result)}


def withheld_theodolite_figure_reasons(result: TheodoliteResult, budget: UncertaintyBudget,
                                       stated_u: float = 0.0, pair_factor: float = 2.0,
                                       readings_alone: bool = False) -> dict[str, Message]:
    """Why R, R↑ or R↓ has no interval where the other figures have theirs, by figure:
    every θ read at most twice in a direction (two passes: ν = 1,
    models.uncertainty.undetermined_repeatability), quoting the interval withheld (that of
    :func:`stated_theodolite_figure_intervals`, the same arguments); ``readings_alone``:
    said to be the readings' own, without the stated standards' u (the summary's)."""
    return undetermined_repeatability(
        held_to_cmc_figures(theodolite_figure_intervals(result, budget, stated_u, pair_factor),
                            float(budget.floor)),
        _passes(result),
        PASSES_UNDETERMINED_READINGS if readings_alone else PASSES_UNDETERMINED)[1]


def least_passes(result: TheodoliteResult) -> int:
    """The fewest passes any θ was read in, in either direction (0 without passes)."""
    present = _directions(result)
    return min((int(np.min(stats.runs)) for _, stats in present), default=0)


def theodolite_figure_decimals(result: TheodoliteResult, budget: UncertaintyBudget,
                               stated_u: float = 0.0, pair_factor: float = 2.0,
                               held: bool = True) -> dict[str, int]:
    """Each ISO 230-2 figure's printed decimal: that of its coverage interval's half-width
    (GUM 7.2.6; ``held``: held to the laboratory's CMC, as a certificate states it), for a
    figure whose interval two passes withhold that of the interval its reason quotes, and
    for one with no interval at all (a θ read once, readings alike or coarser than they
    scatter) that which its own readings support: their pooled s to its first digit, no
    finer than their step (models.uncertainty.rounding.without_interval_decimals). The
    certificate and the summary alike (day review 68 F5: the summary's "R_up = 4.24″" beside
    the certificate's "4″", a figure with no interval at all "5.10″" on both)."""
    if result.iso230 is None:
        return {}
    intervals = theodolite_figure_intervals(result, budget, stated_u, pair_factor)
    if held:
        intervals = held_to_cmc_figures(intervals, float(budget.floor))
    decimals = {key: interval_decimals(iv.low, iv.high) for key, iv in intervals.items()}
    alone = without_interval_decimals(figures_scatter(result)[0],
                                      readings_step(result.raw_error_arcsec))
    return {key: alone for key, value in result.iso230.figures.items()
            if math.isfinite(value) and key not in decimals} | decimals


def readings_theodolite_figure_intervals(result: TheodoliteResult, budget: UncertaintyBudget
                                         ) -> dict[str, FigureInterval]:
    """:func:`theodolite_figure_intervals` without the repeatability figures' intervals that
    two passes leave undetermined (the command line's summary, the window's)."""
    return undetermined_repeatability(theodolite_figure_intervals(result, budget),
                                      _passes(result), PASSES_UNDETERMINED)[0]


#: where the figures' intervals are widened for a circle error the readings do not exclude:
#: the true reason a lower end of E, M or A reaches 0 where the scatter alone would not
CIRCLE_WIDENING_NOTE = QT_TR_NOOP(
    "Here the interval of E, M and A (E↑, E↓, A↑, A↓) reaches at least {shift} beyond the "
    "scatter's own at each end (that at the rest of the tail), for a circle error the "
    "readings do not exclude: up to {circle} per reading (the stated theodolite u over the "
    "pointing noise's lower confidence bound), the same at a θ in every pass, whose shape is not "
    "known and may be the curve's worst ({pair} between two θ); "
    "that widening, not the scatter, takes such a lower end to 0 where the figure is "
    "smaller than it.")
#: the figures' note in the JSON followed by that one
FIGURE_NOTE_WITH_WIDENING = QT_TR_NOOP("{note}. {widening}")


def circle_widening_note(result: TheodoliteResult, budget: UncertaintyBudget,
                         stated_u: float = 0.0, pair_factor: float = 2.0) -> str:
    """:data:`CIRCLE_WIDENING_NOTE` with its sizes, as :func:`theodolite_figure_intervals`
    widens (the same arguments); "" where the readings exclude a circle error (nothing is
    widened for one) or the figures have no intervals."""
    if not theodolite_figure_intervals(result, budget, stated_u, pair_factor):
        return ""
    circle = circle_part_not_excluded(result, stated_u, budget.probability)
    if not circle > 0.0:
        return ""
    pair = pair_factor * circle
    shift = pair_widening(budget.probability, pair, CIRCLE_NUISANCE_SHARE, envelope=True)
    return message(CIRCLE_WIDENING_NOTE, shift=f"{shift:.2f}\"", circle=f"{circle:.3f}\"",
                   pair=f"{pair:.3f}\"")


def theodolite_figures_json(result: TheodoliteResult, budget: UncertaintyBudget,
                            stated_u: float = 0.0, pair_factor: float = 2.0) -> dict[str, Any]:
    """The ISO 230-2 figures as the JSON states them, each {value, interval_low,
    interval_high, coverage_probability}, beside ``iso230_arcsec`` (whose plain values keep
    their meaning), and why there are no intervals; {} for a run with no figures
    (``stated_u``, ``pair_factor``: as :func:`theodolite_figure_intervals`). With the
    laboratory's CMC set (the ``budget``'s floor) the intervals are held to it, and each
    object says which half-width was raised (``raised_to_cmc``)."""
    if result.iso230 is None:
        return {}
    intervals = stated_theodolite_figure_intervals(result, budget, stated_u, pair_factor)
    # every figure of the directions measured, null where the standard does not evaluate it
    # (A and R of a θ read once), so that the keys do not depend on the readings
    present = [name for name, _ in _directions(result)]
    keys = [f"{f}_{name}" for name in present for f in ("E", "R", "A")]
    if len(present) == 2:
        keys += ["E", "M", "B", "B_mean", "R", "A"]
    # R, R↑, R↓ of two passes: the value, no interval, and why (audit 68 finding 3)
    out = figure_objects(keys, result.iso230.figures, intervals, float(budget.floor) > 0,
                         withheld_theodolite_figure_reasons(result, budget, stated_u,
                                                            pair_factor))
    withheld = figure_intervals_withheld(result)
    widening = circle_widening_note(result, budget, stated_u, pair_factor)
    pointing = pointing_in_figures(result)
    return {"iso230_2_figures": out,
            "iso230_2_figures_reason": None if withheld is None else message(withheld),
            "iso230_2_figures_note": message(FIGURE_NOTE_WITH_WIDENING,
                                             note=message(FIGURE_VALUE_NOTE),
                                             widening=widening)
            if widening else message(FIGURE_VALUE_NOTE),
            # R and A are of the axis as read with this theodolite: its pointing noise and the
            # R it alone gives (null where no R is evaluated)
            "iso230_2_pointing": None if pointing is None else {
                "pointing_per_reading_arcsec": pointing[0], "pointing_dof": pointing[1],
                "R_from_pointing_arcsec": pointing[2]},
            "iso230_2_pointing_note": pointing_in_figures_note(result)}
