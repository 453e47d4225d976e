"""Positioning test: uncertainty budget and certificate content.

The certified quantity is the mean positional deviation x̄ at each target in each
approach direction measured. Its inputs (GUM):

* each reference standard's stated figure, in the deviation unit: one stated per reading
  (theodolite, autocollimator) with sensitivity √2, as each deviation is the difference of
  two readings, at the target and at the datum set at the start; one stated for any angle
  measured with it from its own datum (laser rotary calibrator, interferometer: applies_to
  "angle") or a polygon's stated from face 1, with sensitivity 1, its U being the
  deviation's;
* the repeatability of the mean: s/√n of that target and direction (Type A), with
  the fewest runs' n − 1 degrees of freedom (conservative: one ν for every point);
* the resolution of the indication, if stated (rectangular, half-width r/2).

A target approached only once in a direction has no repeatability: no certificate
is issued for it (the budget would leave out the scatter) — the figures are still
shown in the window and the JSON.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from models.certificate.builder import (
    Decision,
    PointTable,
    Statistics,
    build_certificate,
    difference_column,
    figure_column,
    text_column,
    uncertainty_column,
)
from models.certificate.document import (
    CertificateDocument,
    Exact,
    Table,
    opinion,
    reference_standard_components,
    resolution_component,
    table_decimals,
)
from models.certificate.metadata import CertificateMetadata, MetadataError
from models.messages import QT_TR_NOOP, Message, listed, message
from models.positioning import KEY, MEASURAND_STANDARDS, TITLE
from models.positioning.decided_quantity import decided_half_range
from models.positioning.model import (
    MIN_RUNS,
    SIGN_CONVENTION_TEXT,
    STANDARDS,
    PositioningResult,
    figure_text,
)
from models.positioning.plots import deviation_figure, reversal_figure
from models.readings.resolution import step_counts
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import interval_decimals, significant_decimals
from models.uncertainty.figure_intervals import (
    INTERVAL_TRIALS,
    FigureInterval,
    axis_figures,
    figure_intervals,
    figures_raised_to_cmc,
    held_to_cmc_figures,
    readings_seed,
)
from models.uncertainty.lab_scope import cmc_of
from models.uncertainty.printed_figure import interval_range, printed
from models.uncertainty.probability_text import percent_text
from models.uncertainty.rounding import fixed_places, without_interval_decimals
from models.uncertainty.undetermined_repeatability import (
    RUNS_UNDETERMINED,
    RUNS_UNDETERMINED_READINGS,
    undetermined_repeatability,
)
from models.uncertainty.wide_intervals import wide_intervals_statement
from models.uncertainty.without_interval_note import (
    figures_without_interval_note,
    rounding_place,
)

__all__ = ["FIGURE_NAMES", "axis_figures", "figure_decimals", "figure_uncertainties",
           "axis_figure_values", "without_interval",
           "intervals_determined", "intervals_withheld", "readings_figure_intervals",
           "readings_step_component",
           "stated_figure_intervals", "withheld_figure_reasons", "withheld_figure_notes",
           "figures_withheld_notes",
           "rounding_place", "one_direction_reasons",
           "DIRECTION_NOT_MEASURED", "NEEDS_BOTH_DIRECTIONS",
           "positioning_budget", "positioning_certificate", "repeated_readings_components"]

METHOD = QT_TR_NOOP(
    "The axis is sent to each target position in turn, in runs that approach every target "
    "from one direction and then from the other, as logged; the reference instrument reads "
    "the actual position reached. The positional deviation is x = actual position − target "
    "(ISO 230-2). Per target and direction: the mean x̄, the standard deviation s (n − 1) and "
    "the reversal value B_i = x̄↑ − x̄↓; for the axis the figures of the standard applied "
    "below, the others beside them. A compensation table for the axis controller is the "
    "negative of the mean deviation."
)

#: ISO 230-2 figure → (English name, GB/T 17421.2 name)
FIGURE_NAMES: dict[str, tuple[str, str]] = {
    "A": (QT_TR_NOOP("bidirectional accuracy of positioning"), "双向定位精度"),
    "A_up": (QT_TR_NOOP("unidirectional accuracy of positioning ↑"), "单向定位精度 ↑"),
    "A_down": (QT_TR_NOOP("unidirectional accuracy of positioning ↓"), "单向定位精度 ↓"),
    "R": (QT_TR_NOOP("bidirectional repeatability of positioning"), "双向重复定位精度"),
    "R_up": (QT_TR_NOOP("unidirectional repeatability of positioning ↑"), "单向重复定位精度 ↑"),
    "R_down": (QT_TR_NOOP("unidirectional repeatability of positioning ↓"), "单向重复定位精度 ↓"),
    "E": (QT_TR_NOOP("bidirectional systematic positional deviation"), "双向定位系统偏差"),
    "E_up": (QT_TR_NOOP("unidirectional systematic positional deviation ↑"), "单向定位系统偏差 ↑"),
    "E_down": (QT_TR_NOOP("unidirectional systematic positional deviation ↓"), "单向定位系统偏差 ↓"),
    "M": (QT_TR_NOOP("range of the mean bidirectional positional deviation"), "平均双向位置偏差范围"),
    "B": (QT_TR_NOOP("reversal value of the axis"), "反向差值"),
    "B_mean": (QT_TR_NOOP("mean reversal value of the axis"), "平均反向差值"),
}
VDI_NAMES = {"P": QT_TR_NOOP("position uncertainty"),
             "Ps_max": QT_TR_NOOP("largest position scatter"),
             "Pa": QT_TR_NOOP("position deviation"), "U_max": QT_TR_NOOP("largest reversal span")}


def _points(result: PositioningResult) -> list[tuple[str, np.ndarray, np.ndarray, np.ndarray]]:
    """(direction, mean, s, n) for each direction measured, over the targets."""
    return [(name, stats.mean, stats.std, stats.runs)
            for name, _, stats in result.directions_present()]


def uncertainty_refusal(result: PositioningResult):
    """Why no U can be stated for ``result``, whatever the certificate's details (None when
    it can be): readings that show neither scatter nor a step, or a target approached fewer
    than twice in a direction, every direction's targets named (day review 69 F6: 1 run
    named only the forward targets, and only after the whole details dialog)."""
    points = _points(result)
    if result.without_scatter and result.readings_step is None:
        return message(QT_TR_NOOP(
            "the readings of every target came out identical in each direction and show no "
            "step of their display: their repeatability, part of U, cannot be told, so U "
            "cannot be stated"))
    once = {name: result.positions[(n < 2) | ~np.isfinite(s)] for name, _, s, n in points}
    once = {name: targets for name, targets in once.items() if targets.size}
    if len(once) > 1:
        return message(
            QT_TR_NOOP("target(s) {forward} forward and {backward} backward were approached "
                       "fewer than twice: their repeatability, part of U, is unknown, so U "
                       "cannot be stated"),
            forward=", ".join(f"{t:g}" for t in once["up"]),
            backward=", ".join(f"{t:g}" for t in once["down"]))
    for name, targets in once.items():
        return message(
            # what is refused (a certificate, the results) the caller says (day review
            # 67 F9: an export of results was refused with "no certificate is issued")
            QT_TR_NOOP("target(s) {targets} forward were approached fewer than twice: their "
                       "repeatability, part of U, is unknown, so U cannot be stated")
            if name == "up" else
            QT_TR_NOOP("target(s) {targets} backward were approached fewer than twice: their "
                       "repeatability, part of U, is unknown, so U cannot be stated"),
            targets=", ".join(f"{t:g}" for t in targets))
    return None


def positioning_budget(result: PositioningResult, metadata: CertificateMetadata,
                       settings: Mapping[str, Any] | None = None) -> UncertaintyBudget:
    """The budget of the mean deviations, held to the laboratory's CMC of the ``settings``
    ``result`` was analysed with (None: none)."""
    points = _points(result)
    refusal = uncertainty_refusal(result)
    if refusal:
        raise MetadataError(refusal)
    # a target whose runs read alike while the others scatter: the pooled s (models
    # .positioning.model.PositioningResult.repeatability), not 0
    s = np.concatenate([result.repeatability(stats) for _, _, stats in
                        result.directions_present()])
    n = np.concatenate([p[3] for p in points]).astype(float)
    # a deviation is the reading at the target less the datum reading set at the start: a
    # standard stated per reading takes √2 (both readings' errors), one stated for any angle
    # measured from its own datum (a rotary calibrator, an interferometer) or from face 1
    # (a polygon) takes 1, its U being the deviation's (the statement says so)
    components = reference_standard_components(
        metadata, math.sqrt(2.0), QT_TR_NOOP("reading, the deviation a difference of two "
                                             "readings"),
        sensitivity_from_first=1.0, unit=result.deviation_unit, sensitivity_per_angle=1.0,
        from_datum=True)
    note = message(QT_TR_NOOP("s of the runs at each target and direction, n = {n}; ν of the "
                              "fewest runs"),
                   n=f"{int(np.min(n))}" if np.min(n) == np.max(n)
                   else f"{int(np.min(n))}…{int(np.max(n))}")
    alike = [f"{t:g}{arrow}" for _, sign, stats in result.directions_present()
             for t, a in zip(result.positions, result.alike_targets(stats), strict=True) if a
             for arrow in ("↑" if sign > 0 else "↓",)]
    if alike:  # the s column still shows 0 there: say why U does not
        note = message(QT_TR_NOOP("{note}; at {targets}, where every run read alike, the s "
                                  "pooled over the targets ({s}), not 0"), note=note,
                       targets=", ".join(alike), s=f"{result.pooled_s():.3g}{result.symbol}")
    components.append(BudgetComponent(
        QT_TR_NOOP("Repeatability of the mean (s/√n)"), "A", "normal", s / np.sqrt(n), 1.0, 1.0,
        float(np.min(n) - 1), note))
    components += repeated_readings_components(result)
    components += resolution_component(metadata, 1.0, result.deviation_unit)
    components += _stated_inputs(result)
    components += readings_step_component(result)
    # every Type B input is one value at each target for the whole run, in the measured
    # curve (as the figures' intervals draw it: once per target)
    components = [dataclasses.replace(c, in_curve=True) if c.evaluation == "B" else c
                  for c in components]
    return UncertaintyBudget(tuple(components), s.size, metadata.coverage_probability,
                             result.deviation_unit, floor=cmc_of(settings, "cmc"))


def repeated_readings_components(result: PositioningResult) -> list[BudgetComponent]:
    """With n readings at each approach (setting *readings per point*): the standard deviation
    of the mean of those readings, s/√n, carried to each target and direction's x̄ over its
    runs (√(Σ u²)/runs), Type A with ν = n − 1. The runs' scatter, a separate input, already
    holds what of it varies from run to run: counted again here, on the safe side."""
    if result.repeats is None or result.repeat_s_mean is None:
        return []
    key = np.round(result.targets, 9)
    positions = np.round(result.positions, 9)
    values = []
    for _, sign, _ in result.directions_present():
        for target in positions:
            here = (key == target) & (np.sign(result.directions) == sign)
            u = result.repeat_s_mean[here]
            values.append(float(np.sqrt(np.sum(u**2)) / u.size) if u.size else 0.0)
    n = result.repeats.n
    return [BudgetComponent(
        QT_TR_NOOP("Repeated readings (s/√n)"), "A", "normal", np.array(values), 1.0, 1.0,
        float(n - 1), message(QT_TR_NOOP("s/√n of the {n} readings at each approach, over the "
                                         "runs of the target; ν = {dof}"), n=n, dof=n - 1))]


STEP_INPUT = QT_TR_NOOP("Step of the readings as entered")
REFERENCE_RESOLUTION = QT_TR_NOOP("Resolution of the reference")
#: the Type B inputs that are roundings (of the readings, of the reference's or the item's
#: display): independent from target to target, unlike the reference's own errors
ROUNDINGS = (STEP_INPUT, REFERENCE_RESOLUTION, QT_TR_NOOP("Item resolution"))

#: the inputs the readings cannot show: (setting, name, distribution, divisor of the figure)
_STATED = (("misalignment_u", QT_TR_NOOP("Misalignment of the reference"), "normal", 1.0),
           ("reference_resolution", REFERENCE_RESOLUTION, "rectangular",
            2.0 * math.sqrt(3.0)),
           ("temperature_u", QT_TR_NOOP("Temperature"), "normal", 1.0))


def _stated_inputs(result: PositioningResult) -> list[BudgetComponent]:
    """Misalignment, the reference's resolution and the temperature, as the settings state
    them (Type B, per target and direction, c = 1)."""
    inputs = result.inputs or {}
    out = []
    for key, name, distribution, divisor in _STATED:
        value = inputs.get(key, 0.0)
        if value:
            out.append(BudgetComponent(
                name, "B", distribution, value, divisor, 1.0, math.inf,
                message(QT_TR_NOOP("resolution {r}: rectangular, half-width r/2")
                        if key == "reference_resolution" else
                        QT_TR_NOOP("u = {r} at every target (stated)"),
                        r=f"{value:g}{result.symbol}")))
    return out


def readings_step_component(result: PositioningResult) -> list[BudgetComponent]:
    """The step of the readings as entered, when the runs scatter by less than it
    (models.readings.resolution.step_counts): rectangular, half-width δ/2, one value per target and
    direction (Type B: the rounding of a mean that every run rounds alike), unless the
    reference's resolution stated is at least as coarse (it then holds it)."""
    step = result.readings_step
    stated = (result.inputs or {}).get("reference_resolution", 0.0)
    if not step_counts(step, result.pooled_s()) or step is None or stated >= step:
        return []
    return [BudgetComponent(
        STEP_INPUT, "B", "rectangular", step,
        2.0 * math.sqrt(3.0), 1.0, math.inf,
        message(QT_TR_NOOP("readings entered to {step}, a step not small against their "
                           "scatter (s pooled {s}): rectangular, half-width {half}"),
                step=f"{step:g}{result.symbol}", s=f"{result.pooled_s():.3g}{result.symbol}",
                half=f"{0.5 * step:g}{result.symbol}"))]


def not_stated(result: PositioningResult) -> list[str]:
    """The budget inputs the settings leave unstated (so not in U)."""
    inputs = result.inputs or {}
    return [name for key, name, _, _ in _STATED if not inputs.get(key)]


def _per_target(result: PositioningResult, contribution: np.ndarray) -> np.ndarray:
    """An input's standard uncertainty at each target: the reference's error at a position is
    one value for both approach directions and every run (the quadratic mean over the
    directions where the budget differs)."""
    squared = np.asarray(contribution, dtype=float) ** 2
    return np.sqrt(np.mean(squared.reshape(-1, result.positions.size), axis=0))


def _type_b_per_target(result: PositioningResult, budget: UncertaintyBudget
                       ) -> tuple[np.ndarray, float]:
    """The Type B inputs' combined standard uncertainty at each target (of an input stated for
    any angle, the part that can differ from target to target, u/√2), and ``pair_u``: the
    largest standard deviation they can give the difference of two targets' errors, whatever
    their correlation from target to target: 2 max u of an input stated for each reading
    (its errors at two targets may be opposite), max u of one stated for any angle between
    two readings (that difference is one more angle it measured), the inputs in quadrature
    (independent of one another). The roundings (:data:`ROUNDINGS`) are independent from
    target to target and not in ``pair_u``: the model's draws hold them."""
    # a standard stated per reading (datum_reading) holds, in its c = √2, the datum
    # reading's error, one value for the run at every target: every figure is a difference
    # of targets (a range, a reversal), from which it drops out, so the figures take the
    # target reading's part alone, its u (c = 1)
    inputs = [(c, _per_target(result, c.standard_uncertainty(budget.points) if c.datum_reading
                              else u))
              for c, u in zip(budget.components, budget.contributions(), strict=True)
              if c.evaluation == "B"]
    # the part of an input stated for any angle that can differ from target to target on its
    # own is at most u/√2: two targets' errors differ by one more angle, u, so their parts
    # independent of each other have half its variance each (the rest is common to every
    # target, and no figure, a difference of targets, sees it). Drawn at the whole u at each
    # target, the bootstrap's world gave two targets' errors √2 u apart, more than the
    # statement allows, and E's and M's intervals the excess range of that (#39's widths)
    combined = (np.sqrt(np.sum([(0.5 if c.per_angle else 1.0) * u**2 for c, u in inputs],
                               axis=0)) if inputs else np.zeros(result.positions.size))
    pair = math.sqrt(sum(((1.0 if c.per_angle else 2.0) * float(np.max(u))) ** 2
                         for c, u in inputs if c.name not in ROUNDINGS))
    return combined, pair


#: why the figures have no coverage interval
ONCE_ONLY = QT_TR_NOOP("a target was approached fewer than twice in a direction: its standard "
                       "deviation is unknown, so no figure has a coverage interval")
NO_SCATTER = QT_TR_NOOP("the readings of every target came out identical in each direction: "
                        "their scatter cannot be told, so no figure has a coverage interval")
ALIKE_DIRECTION = QT_TR_NOOP("every run of one direction read alike at every target while the "
                             "other direction scatters: that direction's scatter cannot be "
                             "told from these readings (copied?), so no figure has a coverage "
                             "interval")
COARSE = QT_TR_NOOP("the readings were entered coarser than they scatter: the rounding of each "
                    "mean is not random, and the model the intervals are drawn from (random "
                    "scatter about each target's true mean) does not hold, so no figure has a "
                    "coverage interval")


def intervals_withheld(result: PositioningResult) -> str | None:
    """Why the figures get no coverage interval (a message template), or None: a target
    approached fewer than twice in a direction (its s unknown), or readings entered coarser
    than they scatter (models.readings.resolution: the rounded means are not a normal draw
    about the truth; a simulated 0.3 × δ scatter about a curve of 0.6 δ gave E's interval 51 %
    coverage)."""
    if not all(np.all(stats.runs >= 2) and np.all(np.isfinite(stats.std))
               for _, _, stats in result.directions_present()):
        return ONCE_ONLY
    if result.without_scatter and result.readings_step is None:
        return NO_SCATTER
    if result.coarse_readings:
        return COARSE
    if any(np.all(result.alike_targets(stats)) for _, _, stats in result.directions_present()):
        # one direction read alike at every target, the other scattering: that direction's
        # figures had intervals of width 1e-15 about R↑ = 0 (a hostile tester)
        return ALIKE_DIRECTION
    return None


def intervals_determined(result: PositioningResult) -> bool:
    """Whether the figures get coverage intervals (:func:`intervals_withheld`)."""
    return intervals_withheld(result) is None


def figure_uncertainties(result: PositioningResult, budget: UncertaintyBudget | None = None
                         ) -> dict[str, FigureInterval]:
    """The coverage interval of every ISO 230-2 and VDI/DGQ 3441 figure
    (models.uncertainty.figure_intervals), seeded from the readings; ``budget`` gives the
    Type B inputs (the reference standards, the stated inputs) and the probability; without
    it, the result's own stated inputs at 95.45 %. The readings' own intervals, not held to
    the laboratory's CMC (:func:`stated_figure_intervals`). Empty when some target was
    approached fewer than twice in a direction."""
    if not intervals_determined(result):
        return {}
    if budget is None:
        budget = positioning_budget(result, CertificateMetadata())
    u_b, pair = _type_b_per_target(result, budget)
    key = (budget.probability, u_b.tobytes(), pair)
    cache = result.__dict__.setdefault("_figure_intervals", {})
    if key not in cache:
        present = result.directions_present()
        figures = {k: v for k, v in result.iso.figures.items() if math.isfinite(v)}
        figures.update({k: v for k, v in result.vdi.as_dict().items()
                        if v is not None and math.isfinite(v)})
        cache[key] = figure_intervals(
            {name: stats.mean for name, _, stats in present},
            {name: stats.std for name, _, stats in present},
            {name: stats.runs for name, _, stats in present},
            budget.probability, u_b,
            readings_seed(result.targets, result.directions, result.deviations),
            figures=figures, pair_u=pair,
            # the reference's errors within their U at every target, whatever their shape: a
            # bias of at most k · pair on a range, the readings' interval at the whole tail
            # moved out by it (as the theodolite's circle error; #39's widths: it was a union
            # bound, z(1 − tail/2) · pair on the interval at half the tail)
            pair_envelope=True,
            # the readings' interval of E, E↑ and E↓ at the level at which the
            # widened interval misses at the tail at the least favourable bias ±k · pair, not
            # the readings' bound at the probability and the bias's added (#39's widths)
            pair_bias_level=True,
            # the bootstrap without the Type B inputs, drawn once for the window's intervals
            # and the certificate's (which unites them with its own)
            cache=result.__dict__.setdefault("_figure_bootstraps", {}))
    return cache[key]


def stated_figure_intervals(result: PositioningResult, budget: UncertaintyBudget
                            ) -> dict[str, FigureInterval]:
    """The figures' intervals as a certificate, its JSON, exports and DCC state them:
    :func:`figure_uncertainties` with each half-width held to the laboratory's CMC, the
    ``budget``'s ``floor`` (the setting *cmc*, in the deviations' unit, which is the figures':
    µm on a linear axis, arcsec on a rotary one), as the decided quantity's interval is
    (models.uncertainty.lab_scope.held_to_cmc), each marked with what was raised."""
    return undetermined_repeatability(
        held_to_cmc_figures(figure_uncertainties(result, budget), float(budget.floor)),
        _runs(result), RUNS_UNDETERMINED, result.symbol)[0]


def figure_decimals(result: PositioningResult, budget: UncertaintyBudget | None = None
                    ) -> dict[str, int]:
    """Each figure's printed decimal: that of its coverage interval's half-width, two
    significant digits (GUM 7.2.6) — for a figure whose interval is withheld (two runs:
    :func:`withheld_figure_reasons`) that of the interval its reason quotes, the figure's
    own scatter as the readings show it, as the window's verdict line prints it (day 68 F5:
    "A 19.866″ —" on the certificate beside the window's "A = 20″", its interval withheld
    at 14″ … 974″). ``budget``: the certificate's (its reference standards' U, held to the
    laboratory's CMC); None: the readings' own. A figure with no interval at all (a target
    approached once, readings alike or coarser than they scatter: :func:`intervals_withheld`;
    a figure whose interval the study does not give) to the decimal its own readings support,
    their pooled s to two significant digits and no finer than their step
    (models.uncertainty.rounding.without_interval_decimals; day review 68 F5: "P = 21.151″"
    beside figures printed to 1″)."""
    intervals = (figure_uncertainties(result) if budget is None else held_to_cmc_figures(
        figure_uncertainties(result, budget), float(budget.floor)))
    decimals = {key: interval_decimals(iv.low, iv.high) for key, iv in intervals.items()}
    alone = without_interval_decimals(result.pooled_s(), result.readings_step)
    return {key: alone for key in without_interval(result, decimals)} | decimals


def axis_figure_values(result: PositioningResult) -> dict[str, float]:
    """Every figure of ``result`` evaluated, ISO 230-2's and VDI/DGQ 3441's, by key."""
    figures = (*result.iso.figures.items(), *result.vdi.as_dict().items())
    return {key: float(value) for key, value in figures
            if value is not None and math.isfinite(value)}


def without_interval(result: PositioningResult, intervals) -> tuple[str, ...]:
    """The figures of ``result`` (ISO 230-2's, then VDI/DGQ 3441's) that were evaluated but
    are not keys of ``intervals``: those printed with no coverage interval."""
    figures = (*result.iso.figures.items(), *result.vdi.as_dict().items())
    return tuple(key for key, value in figures
                 if key not in intervals and value is not None and math.isfinite(value))


def _runs(result: PositioningResult) -> dict[str, np.ndarray]:
    return {name: stats.runs for name, _, stats in result.directions_present()}


def withheld_figure_reasons(result: PositioningResult, budget: UncertaintyBudget | None = None
                            ) -> dict[str, Message]:
    """Why a repeatability figure (R, R↑, R↓, Ps_max) has no interval where the others have
    theirs, by figure: every target approached at most twice in a direction
    (models.uncertainty.undetermined_repeatability), quoting the interval withheld (that of
    :func:`stated_figure_intervals` for ``budget``; without it the readings' own)."""
    intervals = (figure_uncertainties(result) if budget is None else held_to_cmc_figures(
        figure_uncertainties(result, budget), float(budget.floor)))
    # the readings' own interval said so: a certificate's, with the standards' U, is wider
    return undetermined_repeatability(
        intervals, _runs(result), RUNS_UNDETERMINED if budget is not None else
        RUNS_UNDETERMINED_READINGS, result.symbol)[1]


#: why a figure of both directions is not evaluated where one direction was measured (the
#: JSON's ``interval_reason``, the statistics' cell: assessment 72 M6)
NEEDS_BOTH_DIRECTIONS = QT_TR_NOOP("not evaluated: it needs both approach directions, and the "
                                   "readings have one only")
#: the figures of both directions (ISO 230-2's bidirectional ones, VDI/DGQ 3441's P and U)
BOTH_DIRECTIONS_KEYS = ("A", "E", "M", "R", "B", "B_mean", "P", "U_max")


#: why a figure of one direction is null where that direction was not measured (the JSON's
#: ``interval_reason``: assessment 73 M3, A↓, E↓ and R↓ null with no reason)
DIRECTION_NOT_MEASURED = {
    "up": QT_TR_NOOP("not evaluated: the readings have no approach in the ↑ direction"),
    "down": QT_TR_NOOP("not evaluated: the readings have no approach in the ↓ direction")}
#: the figures of one direction (ISO 230-2), by the suffix of their keys
ONE_DIRECTION_KEYS = ("A", "E", "R")


def one_direction_reasons(result: PositioningResult) -> dict[str, Message]:
    """Why each figure of both directions, and each figure of the direction not measured,
    is null where one approach direction only was measured ({} where both were)."""
    if result.bidirectional:
        return {}
    present = {name for name, _, _ in result.directions_present()}
    out = {key: message(NEEDS_BOTH_DIRECTIONS) for key in BOTH_DIRECTIONS_KEYS}
    for direction, template in DIRECTION_NOT_MEASURED.items():
        if direction not in present:
            out.update({f"{key}_{direction}": message(template) for key in ONE_DIRECTION_KEYS})
    return out


#: the cell of a figure whose interval is withheld (two runs), beside the figure printed to
#: the place of that interval (assessment 78 L1: R↑ = R↓ = R = 10″ with nothing saying so)
WITHHELD_INTERVAL_CELL = QT_TR_NOOP("— (withheld; value rounded to {place})")
#: the note on a figure whose interval is withheld, and the place its value is printed to
WITHHELD_FIGURE_NOTE = QT_TR_NOOP(
    "No coverage interval is given for {figure}: {reason}; {figure} is printed rounded to "
    "{place}, the last place of that interval's half-width to two significant digits (GUM "
    "7.2.6): the two runs do not give it more closely.")


def withheld_figure_notes(result: PositioningResult, decimals: Mapping[str, int],
                          budget: UncertaintyBudget | None = None) -> list[Message]:
    """For each figure whose interval is withheld (:func:`withheld_figure_reasons`), why,
    and the place its value is printed to (``decimals``: :func:`figure_decimals`)."""
    return [message(WITHHELD_FIGURE_NOTE, figure=key, reason=reason,
                    place=rounding_place(decimals[key], result.symbol))
            for key, reason in withheld_figure_reasons(result, budget).items()]


def figures_withheld_notes(result: PositioningResult, decimals: Mapping[str, int],
                           budget: UncertaintyBudget | None = None) -> list[Message]:
    """The certificate's notes on the figures printed with their coverage interval withheld:
    why none has one (:func:`intervals_withheld`), or, for each whose interval two runs
    withhold, why and the place it is printed to (:func:`withheld_figure_notes`). The
    summary the command line prints and the window shows says the same (leftovers 79: "R =
    10″" there with nothing beside it)."""
    withheld = intervals_withheld(result)
    if withheld is not None:
        # every figure is then printed to the one place its readings support (figure_decimals)
        return [figures_without_interval_note(message(withheld), result.pooled_s(),
                                              result.readings_step, result.symbol)]
    return withheld_figure_notes(result, decimals, budget)


def readings_figure_intervals(result: PositioningResult) -> dict[str, FigureInterval]:
    """:func:`figure_uncertainties` of the readings alone, without the repeatability
    figures' intervals that two runs leave undetermined (:func:`withheld_figure_reasons`)."""
    return undetermined_repeatability(figure_uncertainties(result), _runs(result),
                                      RUNS_UNDETERMINED, result.symbol)[0]


def _deviation_text(s: float) -> str:
    """A standard deviation s as the results table prints it: two significant digits, as
    an uncertainty is (GUM 7.2.6); "—" where the readings give none."""
    if s == 0:
        return "0"  # readings alike (their display's step is then an input of U)
    d = significant_decimals(s)
    return "—" if d is None else fixed_places(s, d)  # 151 nm is "150" (assessment 76 M1)


def _figure_cells(value: float | None, interval: FigureInterval | None,
                  sym: str, withheld: int | None = None,
                  rounded_as_withheld: bool = False) -> tuple[str, str, str]:
    """The figure, its interval "10.2″ … 12.0″" and the interval's probability "95.45 %":
    the figure and the interval's ends to the decimal of the interval's half-width, two
    significant digits (GUM 7.2.6); without an interval the figure to ``withheld`` (the
    decimal of the interval withheld: :func:`figure_decimals`; None: 0.001) and "—", which
    says the place the value is rounded to where that is the interval withheld's
    (``rounded_as_withheld``: two runs, :func:`withheld_figure_reasons`)."""
    if interval is None:
        text = figure_text(value, sym, 3 if withheld is None else withheld)
        # the DCC states the figure at full precision, as the JSON does
        figure = (Exact(text, float(value)) if isinstance(text, str) and value is not None
                  and math.isfinite(value) else text)
        if rounded_as_withheld and withheld is not None and isinstance(text, str):
            return figure, message(WITHHELD_INTERVAL_CELL,
                                   place=rounding_place(withheld, sym)), ""
        return figure, "—", ""
    # the figure and its interval's ends (rounded outwards) to the decimal of its half-width,
    # in any unit they are read in, converted from their values (assessment 70 H3); each
    # keeps its value (``exact``) for the DCC, which states them at full precision
    half = (interval.high - interval.low) / 2.0
    text = (printed(value, sym, u=half, stated_exactly=True) if value is not None and math.isfinite(value) and
            half > 0 else figure_text(value, sym, interval_decimals(interval.low,
                                                                     interval.high)))
    return (text, interval_range(interval.low, interval.high, sym) if half > 0 else
            Exact(f"{interval.low:.2f}{sym} … {interval.high:.2f}{sym}",
                  (float(interval.low), float(interval.high))),
            f"{percent_text(interval.probability)} %")


def _figure_rows(result: PositioningResult,
                 uncertainty: dict[str, FigureInterval] | None = None,
                 decimals: dict[str, int] | None = None,
                 withheld: Mapping[str, Any] | None = None) -> list[tuple[str, ...]]:
    """The statistics' rows; ``withheld``: the figures whose interval is withheld (their
    reasons), whose cell says the place their value is rounded to."""
    uncertainty, decimals, withheld = uncertainty or {}, decimals or {}, withheld or {}
    sym, f = result.symbol, result.iso.figures
    gb = result.standard == "gb17421.2"
    present = {name for name, _, _ in result.directions_present()}
    iso_rows = []
    for key, (english, chinese) in FIGURE_NAMES.items():
        direction = key.rsplit("_", 1)[1] if key.endswith(("_up", "_down")) else None
        if direction not in present if direction else not result.bidirectional:
            continue
        name = f"{chinese} {key}" if gb else message("{key}: {name}", key=key,
                                                     name=message(english))
        iso_rows.append((name, *_figure_cells(f.get(key), uncertainty.get(key), sym,
                                                  decimals.get(key), key in withheld),
                         "GB/T 17421.2" if gb else "ISO 230-2"))
    # a figure of both directions with one measured: said why, not only "not evaluated"
    why = one_direction_reasons(result)
    vdi_rows = [(message("{key}: {name}", key=k, name=message(VDI_NAMES[k])),
                 *((message(why[k]), "—", "") if k in why and (v is None or not math.isfinite(v))
                   else _figure_cells(v, uncertainty.get(k), sym, decimals.get(k),
                                      k in withheld)),
                 "VDI/DGQ 3441")
                for k, v in result.vdi.as_dict().items()]
    return vdi_rows + iso_rows if result.standard == "vdi3441" else iso_rows + vdi_rows


def _result_columns(result: PositioningResult, u_by_dir: Mapping[str, np.ndarray]) -> list:
    """The results table's columns after the target: x̄, s and U of each direction, then B_i
    and M_i; the window's per-target table shows the same cells (:func:`printed_per_target`)."""
    columns = []
    for name, mean, s, _ in _points(result):
        arrow = "↑" if name == "up" else "↓"
        columns += [figure_column(f"x̄{arrow}", mean, u_by_dir[name]),
                    text_column(f"s{arrow}", [_deviation_text(v) for v in s]),
                    uncertainty_column(f"U{arrow}", u_by_dir[name], mean)]
    if result.bidirectional:
        # B_i = x̄↑ − x̄↓ of the means as printed (it adds up as printed) and M_i = (x̄↑ +
        # x̄↓)/2, each to the decimal of the coarser of the two means (GUM 7.2.6: no more
        # digits than their U gives)
        means = {name: mean for name, mean, *_ in _points(result)}
        columns += [difference_column("B_i", means["up"], means["down"], u_by_dir["up"],
                                      u_by_dir["down"]),
                    figure_column("M_i", result.iso.bidirectional_mean,
                                  np.fmax(u_by_dir["up"], u_by_dir["down"]))]
    return columns


def expanded_by_direction(result: PositioningResult, budget: UncertaintyBudget
                          ) -> dict[str, np.ndarray]:
    """The budget's U of each direction's mean deviations, over the targets."""
    m = result.positions.size
    return {name: budget.expanded[k * m:(k + 1) * m]
            for k, (name, *_) in enumerate(_points(result))}


def printed_per_target(result: PositioningResult, budget: UncertaintyBudget
                       ) -> dict[str, list[str]]:
    """The results table's cells as the certificate with ``budget`` prints them, by its
    column's header ("x̄↑", "s↑", "U↑", …, "B_i", "M_i"): what the window's per-target table
    shows (PositioningResult.per_target_table), never more digits than printed."""
    shown = table_decimals(budget.expanded)
    return {column.header: list(column.cells(shown))
            for column in _result_columns(result, expanded_by_direction(result, budget))}


def positioning_certificate(result: PositioningResult, metadata: CertificateMetadata,
                            source_name: str = "", method_reference: str = "",
                            settings: Mapping[str, Any] | None = None) -> CertificateDocument:
    budget = positioning_budget(result, metadata, settings)
    big_u = budget.expanded
    sym = result.symbol
    points = _points(result)
    m = result.positions.size
    u_by_dir = expanded_by_direction(result, budget)
    standard = STANDARDS[result.standard]
    runs = listed(message(QT_TR_NOOP("forward {n}") if k == "up" else
                          QT_TR_NOOP("backward {n}"), n=n)
                  for k, n in result.least_runs.items())
    rows_p = [(QT_TR_NOOP("Standard applied"), standard, ""),
              (QT_TR_NOOP("Targets"), f"{m}: {result.positions.min():g} … "
                                      f"{result.positions.max():g}{result.target_symbol}", ""),
              (QT_TR_NOOP("Readings"), f"{result.deviations.size}", ""),
              (QT_TR_NOOP("Fewest runs at a target"), runs,
               "" if result.minimum_runs_met else
               message(QT_TR_NOOP("fewer than {n}: flagged"), n=MIN_RUNS))]
    parameters = Table(QT_TR_NOOP("Test"), (QT_TR_NOOP("Item"), QT_TR_NOOP("Value"),
                                            QT_TR_NOOP("Note")), rows_p)
    columns = [text_column(QT_TR_NOOP("Target"), [f"{target:g}" for target in result.positions]),
               *_result_columns(result, u_by_dir)]
    results = PointTable(message(QT_TR_NOOP("Results per target ({unit}; target in {target})"),
                                 unit=sym.strip(), target=result.target_symbol.strip()),
                         columns,
                         QT_TR_NOOP("x = actual position − target. U is the expanded uncertainty "
                                    "of the mean x̄."))
    curve = np.concatenate([p[1] for p in points])
    names = [message(QT_TR_NOOP("target {target} ({arrow})"),
                     target=f"{target:g}{result.target_symbol}",
                     arrow="↑" if name == "up" else "↓")
             for name, *_ in points for target in result.positions]
    intervals = figure_uncertainties(result, budget)
    # the half range decided is E/2 with E's own interval: one quantity, one interval (the
    # computed one, held to the CMC once, as the decided quantity, by the conformity)
    decision = Decision(curve, QT_TR_NOOP("mean positional deviation"), names,
                        not_stated(result),
                        estimate=decided_half_range(result, budget, intervals))
    stated = stated_figure_intervals(result, budget)
    decimals = figure_decimals(result, budget)
    statistics = Statistics(_figure_rows(result, stated, decimals,
                                         withheld_figure_reasons(result, budget)),
                            QT_TR_NOOP("targets and directions"),
                            title=QT_TR_NOOP("Figures of the axis"),
                            header=(QT_TR_NOOP("Quantity"), QT_TR_NOOP("Value"),
                                    QT_TR_NOOP("Coverage interval"), QT_TR_NOOP("Probability"),
                                    QT_TR_NOOP("Standard")))
    statements = [
        message(QT_TR_NOOP("Evaluated to {standard}; the figures of the other standard are given "
                           "beside them from the same readings."), standard=message(standard)),
        QT_TR_NOOP("Conformity, when a tolerance is stated, is judged on the mean positional "
                   "deviations (each with its own U, or half their range, E/2, with the "
                   "coverage interval of E above halved); a specification of A, R or P is read "
                   "against the figures above."),
        opinion(QT_TR_NOOP("Compensation = −mean deviation: a controller adding it to the "
                           "commanded position is expected to reach the target, within the "
                           "repeatability and the U stated, if the axis behaves as in this "
                           "test.")),
    ]
    # which figure's interval comes from which method, so that an assessor can reproduce
    # each (models.uncertainty.figure_intervals: _intervals, _repeatability_bounds,
    # _band_span_bounds); it said A and P were the bootstrap's (day review 68 F1, F6)
    statements.append(message(QT_TR_NOOP(
        "Coverage interval of each figure of the axis: a figure is a largest value or a range "
        "over the targets, biased high by the scatter. The interval of E, E↑, E↓, M, B and B̄ "
        "(and of Pa and U) is a parametric bootstrap "
        "of the figure's error (basic bootstrap interval, calibrated by the iterated bootstrap, "
        "Beran 1987) from a model of the axis whose spread over the targets is estimated "
        "without the scatter's (constrained empirical Bayes, Louis 1984), {trials} trials "
        "seeded from the readings; each Type B input drawn once per target, the same in both "
        "directions (one stated for any angle at u/√2, the part of its errors that can differ "
        "from target to target). For E, E↑, E↓, M and B (and Pa and U) it is united "
        "with the interval from the measured means taken as the truth, so that a target far off "
        "that the scatter hides is still covered (the curve's spread taken at both ends of "
        "what the readings allow, Berger & Boos 1994). For the ranges of the mean deviations "
        "(E, E↑, E↓) the model's true means have the distribution the readings show (triple-goal "
        "estimates, Shen & Louis 1998) and the interval is not calibrated; B's lower end is the "
        "larger of the mean reversal's bound |B̄| − t·u(B̄) (the mean reversal is never above "
        "the largest) and the one above, each at half the tail, and its upper end is at "
        "least the largest of the targets' own one-sided bounds: both hold whatever the "
        "reversal's shape. The intervals of the other figures use no bootstrap: they are "
        "bounds from each target's own readings, never pooled. The interval of R, R↑, R↓ and "
        "Ps is the bounds from each target's own standard deviation (chi-square, ν = n − 1): "
        "its upper end the largest of the targets' upper bounds, its lower end the largest of "
        "their lower bounds taken at once over the targets (Šidák), so that it holds however "
        "the repeatability changes from target to target. The interval of A, A↑, A↓ and P is "
        "the bounds from each target's own mean and standard deviation: each end of a "
        "target's band (x̄ ± 2s for A; for P, x̄ ± 1.5s of one direction with 1.5 times the "
        "other direction's σ added, that σ bounded by chi-square) by its one-sided tolerance "
        "bound, from the noncentral t distribution with ν = n − 1 (Owen 1968; ISO 16269-6); "
        "its upper end the largest bound of a band's top less the smallest bound of a band's "
        "bottom (the figure is made by two targets, whose own bounds hold with no correction "
        "for the number of targets: the intersection–union bound, Berger 1982; each bound at "
        "the whole tail, as the two targets' bounds together, and a band end with the other "
        "direction's σ added, hold at it whatever the σ, exactly where one σ is far the "
        "largest), its lower end from every target's bounds in both directions taken at once "
        "(Šidák over the targets and directions, for P over the targets, Bonferroni within "
        "each). These intervals of R, A and P are "
        "wide at few runs, because "
        "each target's σ is known only from its own readings (at 3 runs each σ has 2 degrees "
        "of freedom), so a specification of R, A or P may not be decidable. With Type B "
        "inputs (the reference standard, the stated inputs), the "
        "interval of E, M, A and P is also united with the one from the same readings without "
        "them (A's and P's bounds are of the readings alone: for them only the widened "
        "interval below adds to theirs): the reference's errors at the targets are part of "
        "the measured curve, and "
        "where "
        "the reference is better than its certificate states the range holds less of them; "
        "and, as the reference's errors need not be independent from target to target (a "
        "once-a-turn error lowers the crests and raises the troughs), with that interval "
        "(for E, E↑ and E↓ taken at the level at which the moved interval misses at "
        "the tail when that bias is at its largest, of either sign: the two bounds at the "
        "probability added would cover more than asked for at every bias) "
        "moved out each way by k · 2 max u (k the two-sided normal factor of the probability, "
        "2 at 95.45 %), the largest range errors within their U can give a largest value less "
        "a smallest one, a bias and not a scatter, whatever their correlation (u of those "
        "inputs but the roundings, which are independent from target to target; k · u for a "
        "standard whose U is stated for any angle between two readings, as the difference of "
        "two targets' errors is one more such angle). The truth it "
        "covers is the figure of "
        "the axis's true mean deviations and true standard deviations (R = 4σ at the worst "
        "target). The interval may lie below the measured value. Its probability is the one "
        "a simulation study reached (anglebench validate: smooth, rough, single-spike and real "
        "curves, repeatability 0.1 to 2 times the signal, 12, 36 and 72 targets), where that is "
        "below {p} %."), trials=INTERVAL_TRIALS,
        p=f"{100 * budget.probability:.2f}"))
    statements += figures_withheld_notes(result, decimals, budget)
    statements.append(QT_TR_NOOP(
        "A specification of A, R, E, B or P conforms when the upper end of the figure's "
        "coverage interval is within it, does not conform when the lower end exceeds it, and "
        "is not decided in between (ISO 14253-1)."))
    # where an upper end lies far above its figure (few runs), why, and what it means for
    # a specification of it (day review 68 F6: "P 22″: 16″ … 218″" at 3 runs, unsaid)
    wide = wide_intervals_statement(axis_figure_values(result), stated,
                                    min(result.least_runs.values()), sym)
    if wide is not None:
        statements.append(wide)
    statements.append(QT_TR_NOOP(
        "Each deviation is the difference of two readings of the reference, at the target and "
        "at the datum set at the start. A reference standard whose certificate states its U "
        "per reading (a theodolite, an autocollimator) enters each mean deviation with "
        "sensitivity √2, both readings' errors; the datum reading's is one value for the run, "
        "common to every target, so it drops out of the figures, differences of targets. A "
        "standard whose U is stated for any angle measured with it from its own datum (a laser "
        "rotary calibrator, an interferometer) and a polygon stated from face 1 enter with "
        "sensitivity 1: their U is that of the deviation itself."))
    # the inputs not stated are named under the budget (CertificateDocument.not_in_u, from
    # the decision's not_stated)
    if not result.minimum_runs_met:
        statements.append(message(QT_TR_NOOP("ISO 230-2 asks for at least {n} runs in each "
                                             "direction at every target; this test has fewer "
                                             "({runs}). The figures are evaluated and "
                                             "flagged."), n=MIN_RUNS, runs=runs))
    directions = np.concatenate([np.full(m, 1.0 if name == "up" else -1.0)
                                 for name, *_ in points])
    return build_certificate(
        measurand_standards=MEASURAND_STANDARDS,
        kind_key=KEY, kind_title=TITLE, method=METHOD, metadata=metadata,
        source_name=source_name, method_reference=method_reference, budget=budget,
        parameters=parameters, results=results, statistics=statistics, decision=decision,
        budget_point=lambda worst: names[worst],
        plots=(deviation_figure(result), reversal_figure(result)),
        warnings=result.warnings, unit=sym, statements=statements,
        standard=standard, sign_convention=SIGN_CONVENTION_TEXT,
        figures_raised_to_cmc=tuple(figures_raised_to_cmc(stated)),
        point_column_units=(("target", result.target_symbol.strip()),),
        point_columns=(
            ("target", np.tile(result.positions, len(points))), ("direction", directions),
            (f"mean_deviation_{result.deviation_unit}", curve),
            (f"s_{result.deviation_unit}", np.concatenate([p[2] for p in points])),
            ("runs", np.concatenate([p[3] for p in points]).astype(float)),
            (f"expanded_uncertainty_{result.deviation_unit}", big_u)))
