"""Coverage intervals of the axis figures (ISO 230-2 / GB/T 17421.2 and VDI/DGQ 3441).

The figures are maxima and ranges over the targets (E, M, B, R, A, P …): the measured
figure is biased, high when several targets are near the extreme, and a Monte Carlo run
about the measured values (JCGM 101 as such) puts the interval about the biased value.
Its coverage fell to 20–53 % for R and B. The interval here handles the estimator's own
bias with a parametric bootstrap of the pivot (basic bootstrap interval, Davison & Hinkley
1997, §5.2.1; Efron & Tibshirani 1993, §13) drawn from a *world* fitted to the readings
whose spread over the targets is that of the truth, not that of the noisy means:

* the per-target means are shrunk towards their average by the constrained empirical-Bayes
  factor √c, c = τ̂² / (τ̂² + se²) (Louis 1984, JASA 79:393; Ghosh 1992, JASA 87:533: the
  ensemble estimate whose spread matches the parameters' own, made for extremes and
  ranks), separately for the bidirectional mean M_i and the reversal B_i;
* the per-target log variances likewise, their sampling variance ψ′(ν/2) known
  (the moderated variances of Smyth 2004, Stat. Appl. Genet. Mol. Biol. 3:3);
* each trial draws every target's mean x̄ ~ N(μ, σ²/n) and s² ~ σ² χ²_ν/ν (ν = n − 1),
  every Type B input of the budget once per target (the reference's error at a position
  is the same in both approach directions and in every run), and evaluates the figures
  as the standard does;
* the interval is [F − q_hi, F − q_lo], q the quantiles of (figure drawn − the world's
  true figure) at (1 ∓ p)/2, clipped at 0 for the figures that cannot be negative;
* for the ranges of the means (E, E↑, E↓, :data:`RANGE_FIGURES`) the world's true means are
  instead the triple-goal estimates (Shen & Louis 1998, JRSS B 60:455): the distribution of
  the true means by its nonparametric maximum likelihood and each target given its quantile
  by rank (:func:`_ensemble`). A range's bias is set by how many targets lie near its
  extremes; the constrained Bayes world matches only the spread and puts too few there on a
  smooth curve, and the iterated bootstrap that corrected it widened E's interval to 2–2.7
  times what a correct one needs at 36–72 targets. Their interval is not calibrated;
* for the figures of the means (E, M, B, R, A, P and their forms, :data:`UNION_FIGURES`) it is
  united with the same interval from the *unshrunk* world (the measured means as the truth):
  where the scatter hides one target far off (a spike twice as small as the scatter), the
  shrunk world flattens it, its figure's bias comes out too large and its interval fell
  short above (E covered 35 % of such axes at 72 targets). The curve's spread over the
  targets is a nuisance the readings do not fix; the union takes it at both ends of what
  they allow (Berger & Boos 1994, JASA 89:1012: an interval maximised over a set of the
  nuisance);
* the upper end of the ranges of the means (E, E↑, E↓) is taken at least to the unshrunk
  world's pivot at :data:`RANGE_UPPER_TAIL_SHARE` of the tail (:func:`_range_upper_reach`):
  a spike whose mean came out low reads as one of a crowd at the top, both worlds put a
  crowd there, and the truth lay above E's interval in 10 % of an audit's tests (cov76 F3:
  25 targets, a 5″ spike on a random curve, σ at random per target); so is the upper end of
  M's and Pa's (the range of the bidirectional means, :data:`UPPER_REACH_FIGURES`), whose
  crest and trough stood alone on a rough curve with σ at random per target and where the
  truth lay above M's interval in 17 % of 150 tests (pos77);
* where a target's scatter stands out from the others' (a family-wise F test of each s²
  against its direction's others', :func:`_scatter_outliers`), the same ranges' upper end is
  taken at least to that target's own pairs' bound, and their lower end moved down by its
  Student excess where it makes the measured extreme (:func:`_noisy_target_bounds`): the
  worlds fit σ alike, and a spike at a target of 3 × the others' σ drawn low passed for one
  of the crowd (E↑ and E↓ covered 79–86 % of 150 tests, M 84–95 %, against 92–93.5 % printed,
  spike78);
* B's (and U's) lower end is the larger of a bound from the mean reversal, which holds
  whatever the reversal's shape, and the lowest of the bootstrap's and a simultaneous bound
  over the targets, the tail split between them; its upper end is taken up to the largest
  of the targets' own one-sided bounds (:func:`_reversal_guard`);
* R↑, R↓, R and Ps_max (maxima of the targets' σ) take bounds from each target's own s
  by the chi-square distribution in place of the bootstrap's interval
  (:func:`_repeatability_bounds`: the upper end the largest of the targets' one-sided
  bounds, the lower end every target's at once, Šidák; R's two-way term 2σ↑ + 2σ↓ + |β|
  by the sum of its three bounds, each at the level at which the sum misses at the tail
  at its least favourable point, :func:`_two_way_level`, until 0.8.18 at a third each),
  which hold however σ changes from target to target; the bootstrap's world shrinks the σ
  toward a common one, and an audit (one target's σ doubled) found R↑ covering 42 of 80;
* A↑, A↓, A and P (spans of the targets' bands μ ± 2σ, VDI/DGQ 3441's μ ± (|β|/2 + 3σ̄))
  likewise take bounds from each target's own x̄ and s in place of the bootstrap's interval
  (:func:`_band_span_bounds`: each band's end by the noncentral t, the upper end the
  intersection–union bound of the two targets that make the figure, each bound at the
  whole tail, the pair exact at the least favourable σ; the lower end every target's at
  once, Šidák): with one target's σ × 2 or × 3 the bootstrap's A covered 45–70 of 80
  tests (#39);
* with Type B inputs, the interval of the figures of the means (:data:`TYPE_B_FIGURES`) is
  also united with the one from the same readings without them: the reference's errors at
  the targets are in the measured curve, and a reference better than its certificate states
  leaves less of them there than the world draws.

The world's truth is the figure of the true distribution, as ISO 230-2 defines it:
E↑ = range of the true mean deviations μ↑, R↑ = 4 max σ↑, A↑ = max(μ↑ + 2σ↑) −
min(μ↑ − 2σ↑), B = max |μ↑ − μ↓|, B̄ = mean(μ↑ − μ↓), M = range of (μ↑ + μ↓)/2,
R = max of max(2σ↑ + 2σ↓ + |μ↑ − μ↓|, 4σ↑, 4σ↓); VDI/DGQ 3441: Pa = M, U_max = B,
Ps_max = max 3(σ↑ + σ↓), P = max(m + (|b| + Ps)/2) − min(m − (|b| + Ps)/2).

The coverage reached is measured by the study in ``anglebench validate`` and the
benchmark (tests/benchmarks/test_positioning_figures.py); where it is below the
probability asked for, the probability stated beside a figure is the one reached
(:data:`ACHIEVED`), never the one asked for.

Where the laboratory states a CMC for the workbench's quantity, a certificate's intervals
are held to it (:func:`held_to_cmc_figures`, by the rule of the decided quantity's:
models.uncertainty.lab_scope.held_to_cmc, which says why a point's CMC holds a range or a
scatter of points): the intervals computed here are the readings' own, the window's.
"""

from __future__ import annotations

import functools
import hashlib
import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.optimize import brentq
from scipy.special import chdtri, fdtri, nctdtrit, ndtr, ndtri, polygamma, stdtrit

from models.messages import QT_TR_NOOP
from models.uncertainty.lab_scope import held_to_cmc

__all__ = ["ACHIEVED", "FIGURE_VALUE_NOTE", "FigureInterval", "INTERVAL_TRIALS", "pair_widening",
           "SIGNED_FIGURES", "bias_aware_tail", "axis_figures", "figure_intervals", "figure_objects",
           "figures_raised_to_cmc", "held_to_cmc_figures", "readings_seed", "world_truth"]

#: bootstrap trials per analysis (2000: the 2.3 % quantiles to about ±0.35 % of probability)
INTERVAL_TRIALS = 2000

#: figures that may be negative (the others are clipped at 0)
SIGNED_FIGURES = frozenset({"B_mean"})

#: The coverage the study reached for each figure at 95.45 % asked for, where below it:
#: figure_coverage.achieved_probability, the highest probability (95.45 % or a multiple of
#: 0.5 %) that the pooled coverage reaches and that none of the axes falls short of beyond
#: the binomial test (1 %); 4 shapes × 12, 36 and 72 targets × repeatability 0.1, 0.5, 1, 2 ×
#: the signal × constant or varying (96 axes), each test through the whole analysis. 0.8.2
#: (the ranges' triple-goal world, B's upper bound, the axes of 36 targets and of
#: repeatability 1 ×): figure_coverage.axis_hits(STUDY_CASES, 20, seed) for the seeds 391
#: to 394, 80 tests an axis, pooled; for the figures whose interval 0.8.2 did not change,
#: the lower of that and 0.7.0's derivation (the 48 axes of 12 and 72 targets, 40 tests an
#: axis). Pooled: E 95.0 % (its lowest axis, a rough curve at 36
#: targets and repeatability 0.1 varying along the axis, 68 of 80), E↑ 94.8 % (a real curve
#: at 12 targets, 67 of 80), E↓ 95.0 %, M and Pa 94.6 % (a spike at 72 targets, repeatability
#: 1 × varying, 68 of 80), A 98.0 % (69 of 80 at the same axis as E), B and U 98.8 % (0.8.14, B's lower end
#: from the mean reversal: 99.2 %, the lowest axis 37 of 40, seeds 391–392); the
#: others 96.6–98.6 %. R↑ and R↓ stated 93.5 % until their intervals took the per-target
#: chi-square bounds (:func:`_repeatability_bounds`), which hold at the probability asked for;
#: A, A↑, A↓ (93.5 %, 94.5 %) and P (94.5 %) likewise until theirs took the per-target
#: noncentral t bounds (:func:`_band_span_bounds`: with one target's σ × 2 or × 3, A had
#: covered 45–70 of 80 tests at 3 and 5 runs, 12 and 36 targets, #39).
#: The figure's interval states this one instead. Before 0.8.2, B stated
#: 93 % and one axis (a rough reversal whose largest value stands clear of the others)
#: reached 59 of 80; before 0.7.0's union with the unshrunk world E reached 92.1 % (35 % on a
#: spike hidden in scatter twice its size at 72 targets) and R 72 % on a reversal changing at
#: random from target to target.
ACHIEVED: dict[str, float] = {"E": 0.925, "E_up": 0.92, "E_down": 0.935, "M": 0.925,
                              "Pa": 0.925}


#: what a figure's value and interval are, beside them in the JSON: a value above its own
#: interval is no error (an audit counted R↑ above its interval in 82 % of 2-pass runs)
FIGURE_VALUE_NOTE = QT_TR_NOOP(
    "value: the figure as the standard computes it from the readings; interval_low … "
    "interval_high: the coverage interval of the TRUE figure (of the true mean deviations "
    "and standard deviations of the axis as this measuring instrument reads it: R and A, and "
    "their one-direction forms, are made of the standard deviations and include the "
    "instrument's own repeatability) at coverage_probability. A largest value or a range "
    "over the targets (R, A, E, M, B) is biased high by the scatter, so the interval may lie below "
    "the value, and it reaches 0 where the scatter could hide the whole figure")


@dataclass(frozen=True)
class FigureInterval:
    """A figure, its coverage interval and the probability that interval covers;
    ``raised_to_cmc``: whether the interval's (lower, upper) half-width was raised to the
    laboratory's CMC (:func:`held_to_cmc_figures`), None where no CMC holds it."""

    value: float
    low: float
    high: float
    probability: float
    raised_to_cmc: tuple[bool, bool] | None = None

    def as_dict(self) -> dict[str, float]:
        return {"value": self.value, "interval_low": self.low, "interval_high": self.high,
                "coverage_probability": self.probability}

    @property
    def minus(self) -> float:
        return max(self.value - self.low, 0.0)

    @property
    def plus(self) -> float:
        return max(self.high - self.value, 0.0)


def held_to_cmc_figures(intervals: Mapping[str, FigureInterval], cmc: float
                        ) -> dict[str, FigureInterval]:
    """``intervals`` with each half-width held to at least the laboratory's CMC ``cmc`` (in
    the figures' unit; ILAC-P14 5.4), by the rule of the decided quantity's interval
    (models.uncertainty.lab_scope.held_to_cmc: the value not moved, the lower end of a
    figure that cannot be negative not below 0, the probability kept, as the interval only
    grew), each marked with which half-width was raised; an end not raised is kept as it
    was. No CMC (0): the intervals as they are, unmarked."""
    if not cmc > 0:
        return dict(intervals)
    out = {}
    for key, interval in intervals.items():
        held = held_to_cmc(interval.value, interval.value - interval.low,
                           interval.high - interval.value, cmc,
                           non_negative=key not in SIGNED_FIGURES)
        if held.raised is None:
            out[key] = interval
            continue
        before = interval.raised_to_cmc or (False, False)
        raised = (held.raised[0] or before[0], held.raised[1] or before[1])
        out[key] = FigureInterval(interval.value,
                                  float(held.low) if held.raised[0] else interval.low,
                                  float(held.high) if held.raised[1] else interval.high,
                                  interval.probability, raised)
    return out


def figures_raised_to_cmc(intervals: Mapping[str, FigureInterval]) -> list[str]:
    """The keys of the figures whose interval was raised to the CMC on either side."""
    return [key for key, interval in intervals.items()
            if interval.raised_to_cmc is not None and any(interval.raised_to_cmc)]


def figure_objects(keys, values: Mapping[str, Any], intervals: Mapping[str, FigureInterval],
                   cmc_set: bool = False, reasons: Mapping[str, Any] | None = None
                   ) -> dict[str, Any]:
    """{figure: {value, interval_low, interval_high, coverage_probability}}; nulls where the
    readings do not determine it. With ``cmc_set`` (the laboratory's CMC holds the
    intervals: :func:`held_to_cmc_figures`) also ``raised_to_cmc``: {low, high}, whether each
    half-width is the CMC because the readings gave less, as the decided quantity's (null
    where the figure has no interval). With ``reasons`` also ``interval_reason``: why this
    figure alone has no interval (models.uncertainty.undetermined_repeatability), or no
    value (the reason given for it), null where it has one or where every figure's is
    withheld (the JSON's own ``*_reason``)."""
    out: dict[str, dict[str, Any]] = {}
    for key in keys:
        value = values.get(key)
        value = None if value is None or not math.isfinite(value) else float(value)
        interval = intervals.get(key) if value is not None else None
        out[key] = {"value": value,
                    "interval_low": None if interval is None else interval.low,
                    "interval_high": None if interval is None else interval.high,
                    "coverage_probability": None if interval is None else interval.probability}
        if reasons is not None:
            # a figure withheld has its reason too (one direction measured: assessment 72 M6)
            out[key]["interval_reason"] = reasons.get(key)
        if cmc_set:
            raised = None if interval is None else interval.raised_to_cmc or (False, False)
            out[key]["raised_to_cmc"] = (None if raised is None else
                                         {"low": bool(raised[0]), "high": bool(raised[1])})
    return out


def readings_seed(*arrays: np.ndarray) -> int:
    """A seed from the readings themselves: the same readings give the same intervals."""
    h = hashlib.sha256()
    for a in arrays:
        h.update(np.ascontiguousarray(np.asarray(a, dtype=float)).tobytes())
    return int.from_bytes(h.digest()[:8], "little")


#: how many values (tests × targets) :func:`axis_figures` takes at a time: a block's
#: arrays (128 KiB in single precision) stay in the processor's cache through the ~40
#: operations made of them; the whole of 2000 tests × 72 targets went out to memory at each
AXIS_BLOCK = 32768


def axis_figures(stats: dict[str, tuple[np.ndarray, np.ndarray]]) -> dict[str, np.ndarray]:
    """The ISO 230-2 and VDI/DGQ 3441 figures of many tests at once: ``stats`` maps a
    direction ("up", "down") to (mean, s), arrays (tests…, targets) with every target
    approached at least twice. The formulas of models.uncertainty.iso230 and
    models.positioning.model, row by row (a test checks they agree).

    Every bootstrap trial and inner draw of :func:`figure_intervals` passes here (much of
    its time). Each test's figures are its own row's, so the tests are taken in blocks of
    :data:`AXIS_BLOCK` values (:func:`_block_figures`), each block with the targets first:
    a largest value over 12 targets along the last axis cost numpy one call of its inner
    loop per test (2000 of them), over the first axis one elementwise maximum of rows per
    target. A largest or smallest value is the same whatever the order it is found in, the
    elementwise operations are each value's own, and the mean reversal (B_mean, a sum whose
    rounding depends on its order) is summed along the targets as before: the same figures,
    bit for bit (a test checks them against the formulas row by row), in 0.25–0.5 of the
    time at 12–72 targets."""
    first = next(iter(stats.values()))[0]
    lead, m = np.shape(first)[:-1], np.shape(first)[-1]
    rows = math.prod(lead)
    flat = {name: (np.reshape(mean, (rows, m)), np.reshape(s, (rows, m)))
            for name, (mean, s) in stats.items()}
    step = max(1, AXIS_BLOCK // max(m, 1))
    if rows <= step:
        out = _block_figures(flat)
    else:
        blocks = [_block_figures({name: (mean[i:i + step], s[i:i + step])
                                  for name, (mean, s) in flat.items()})
                  for i in range(0, rows, step)]
        out = {key: np.concatenate([block[key] for block in blocks]) for key in blocks[0]}
    if not lead:  # one test given as (targets,): its figures as numbers, as before
        return {key: value[0] for key, value in out.items()}
    return {key: value.reshape(lead) for key, value in out.items()}


def _targets_first(values: np.ndarray) -> np.ndarray:
    """(tests, targets) as a contiguous (targets, tests)."""
    return np.ascontiguousarray(np.asarray(values).T)


def _block_figures(stats: dict[str, tuple[np.ndarray, np.ndarray]]) -> dict[str, np.ndarray]:
    """:func:`axis_figures` of a block of tests, arrays (tests, targets): each direction's
    extremes are taken once and the bidirectional figures' made from them (the largest of
    two maxima is the maximum of both directions' values, exactly: no rounding), not over the
    directions' values joined again; the reductions over the targets along the first axis of
    the values turned targets first (:func:`_targets_first`)."""
    out: dict[str, np.ndarray] = {}
    ends: dict[str, tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]] = {}
    turned: dict[str, tuple[np.ndarray, np.ndarray]] = {}
    for name, (mean_rows, s_rows) in stats.items():
        mean, s = _targets_first(mean_rows), _targets_first(s_rows)
        turned[name] = (mean, s)
        high, low = mean.max(axis=0), mean.min(axis=0)
        upper, lower = (mean + 2 * s).max(axis=0), (mean - 2 * s).min(axis=0)
        ends[name] = (high, low, upper, lower)
        out[f"E_{name}"] = high - low
        out[f"R_{name}"] = (4.0 * s).max(axis=0)
        out[f"A_{name}"] = upper - lower
    if "up" in stats and "down" in stats:
        (up, s_up), (down, s_down) = turned["up"], turned["down"]
        high_up, low_up, upper_up, lower_up = ends["up"]
        high_down, low_down, upper_down, lower_down = ends["down"]
        reversal = up - down
        size = np.abs(reversal)
        middle = 0.5 * (up + down)
        out["E"] = np.maximum(high_up, high_down) - np.minimum(low_up, low_down)
        out["M"] = middle.max(axis=0) - middle.min(axis=0)
        out["B"] = size.max(axis=0)
        # a sum: along each test's row of targets, in the order (and so the rounding) of
        # numpy's pairwise sum of a row, as it always was
        out["B_mean"] = np.mean(stats["up"][0] - stats["down"][0], axis=-1)
        out["R"] = np.maximum(np.maximum(2 * s_up + 2 * s_down + size, 4 * s_up),
                              4 * s_down).max(axis=0)
        out["A"] = np.maximum(upper_up, upper_down) - np.minimum(lower_up, lower_down)
        scatter = 6.0 * 0.5 * (s_up + s_down)
        half = 0.5 * (size + scatter)
        out["Pa"] = out["M"].copy()
        out["P"] = (middle + half).max(axis=0) - (middle - half).min(axis=0)
        out["Ps_max"] = scatter.max(axis=0)
        out["U_max"] = out["B"].copy()
    else:
        name, (mean, s) = next(iter(turned.items()))
        out["Pa"] = out[f"E_{name}"].copy()
        out["Ps_max"] = (6.0 * s).max(axis=0)
    return out


def world_truth(means: dict[str, np.ndarray], sigmas: dict[str, np.ndarray]
                ) -> dict[str, float]:
    """The figures of a true distribution (true means μ and standard deviations σ per
    target and direction), as ISO 230-2 and VDI/DGQ 3441 define them."""
    stats = {k: (np.asarray(means[k], float)[None, :], np.asarray(sigmas[k], float)[None, :])
             for k in means}
    return {k: float(v[0]) for k, v in axis_figures(stats).items()}


def _shrunk(values: np.ndarray, se2: np.ndarray) -> np.ndarray:
    """Constrained empirical Bayes (Louis 1984): values (…, targets) with sampling
    variances ``se2`` pulled towards their precision-weighted mean by √c_i,
    c_i = τ̂²/(τ̂² + se_i²), so that the spread of the result estimates the spread of the
    true values; τ̂² the between-target variance by DerSimonian & Laird (1986, Control.
    Clin. Trials 7:177), which weights each target by its precision (one target that
    scatters much does not pass for a rough curve)."""
    se2 = np.broadcast_to(np.asarray(se2, dtype=float), values.shape)
    # a target whose readings came out alike (s = 0) floored at 1e-12 of the largest: its
    # weight stays finite, and τ̂²'s denominator (Σw − Σw²/Σw) does not cancel to 0 (it did,
    # and τ̂² overflowed to NaN intervals)
    se2 = np.maximum(se2, np.maximum(1e-12 * np.max(se2, axis=-1, keepdims=True), 1e-150))
    w = 1.0 / se2
    sw = np.sum(w, axis=-1, keepdims=True)
    centre = np.sum(w * values, axis=-1, keepdims=True) / sw
    q = np.sum(w * (values - centre) ** 2, axis=-1, keepdims=True)
    k = values.shape[-1]
    denominator = sw - np.sum(w**2, axis=-1, keepdims=True) / sw
    tau2 = np.maximum((q - (k - 1)) / np.maximum(denominator, 1e-300), 0.0)
    return centre + np.sqrt(tau2 / (tau2 + se2)) * (values - centre)


def _world_sigmas(s: dict[str, np.ndarray], n: dict[str, np.ndarray]) -> dict[str, np.ndarray]:
    """Per direction, the standard deviations (…, targets) with their spread over the
    targets shrunk as the means' (log s², sampling variance ψ′(ν/2)); the pooled variance
    kept."""
    out = {}
    for key, sd in s.items():
        nu = n[key] - 1.0
        pooled = np.sum(nu * sd**2, axis=-1, keepdims=True) / np.sum(nu)
        # a zero s (readings of one target alike, by rounding) floored at a tenth of the
        # pooled s: 5.7 standard deviations of log s² below it at ν = 4, so its log is no
        # evidence of a target that does not scatter (at 1e-30, −138, it passed for one and
        # its mean for exact); and where float32 draws hold it (log 0 warns; warnings are
        # errors)
        log_s2 = 2.0 * np.log(np.maximum(sd, np.maximum(0.1 * np.sqrt(pooled), 1e-30)))
        spread = _shrunk(log_s2, polygamma(1, nu / 2.0)) - np.mean(log_s2, axis=-1,
                                                                   keepdims=True)
        weights = np.exp(spread)
        out[key] = np.sqrt(pooled * weights / np.mean(weights, axis=-1, keepdims=True))
    return out


@dataclass(frozen=True)
class SharedErrors:
    """The errors that are the same at a target in every run and both directions (Type B
    inputs): ``u`` (targets,), each target's drawn on its own; ``modes`` (k, targets) or
    None, errors correlated over the targets, z @ modes with z ~ N(0, I_k) (a fitted model's
    error, from its parameters' covariance). Both are in the measured curve."""

    u: np.ndarray
    modes: np.ndarray | None = None

    @property
    def variance(self) -> np.ndarray:
        var = self.u**2
        return var if self.modes is None else var + np.sum(self.modes**2, axis=0)

    def draw(self, shape: tuple[int, ...], rng: np.random.Generator):
        """One error per target of each test, ``shape + (targets,)`` (0 with none)."""
        m = self.u.size
        out = (rng.standard_normal(shape + (m,), dtype=np.float32) * self.u.astype(np.float32)
               if np.any(self.u) else np.float32(0.0))
        if self.modes is not None:
            k = self.modes.shape[0]
            out = out + rng.standard_normal(shape + (k,), dtype=np.float32) @ \
                self.modes.astype(np.float32)
        return out


def _world_means(means: dict[str, np.ndarray], sigmas: dict[str, np.ndarray],
                 n: dict[str, np.ndarray], shared: SharedErrors, level=_shrunk
                 ) -> dict[str, np.ndarray]:
    """The true means of the world: bidirectional, the mean M_i by ``level`` (values,
    sampling variances → the world's values: :func:`_shrunk`, or :func:`_ensemble` for the
    ranges) and the reversal B_i shrunk (the reference's Type B error is in M only: it is
    the same both ways); one direction, its means by ``level``."""
    if "up" in means and "down" in means:
        var_up = sigmas["up"] ** 2 / n["up"]
        var_down = sigmas["down"] ** 2 / n["down"]
        mid = 0.5 * (means["up"] + means["down"])
        rev = means["up"] - means["down"]
        mid_w = level(mid, 0.25 * (var_up + var_down) + shared.variance)
        rev_w = _shrunk(rev, var_up + var_down)
        return {"up": mid_w + 0.5 * rev_w, "down": mid_w - 0.5 * rev_w}
    return {k: level(v, sigmas[k] ** 2 / n[k] + shared.variance) for k, v in means.items()}


#: the scatter of the world's means: each target's own s where it is above the moderated σ
#: (a maximum of means follows the targets that scatter most; moderating their s would
#: narrow it), else the moderated σ
MEANS_FROM_OWN_S = True


def _world(means, stds, n, shared):
    """(μ, σ, σ of the means) of the world fitted to measured means and s."""
    sig_w = _world_sigmas(stds, n)
    sig_mean = ({k: np.maximum(stds[k], v) for k, v in sig_w.items()} if MEANS_FROM_OWN_S
                else sig_w)
    return _world_means(means, sig_mean, n, shared), sig_w, sig_mean


def _draw(mu_w, sig_w, sig_mean, n, shared, shape, rng):
    """Tests drawn from a world: means and s of shape ``shape + (targets,)`` (single
    precision: the draws' own scatter is far above its rounding)."""
    m = shared.u.size
    common = shared.draw(shape, rng)
    drawn = {}
    for k, mu in mu_w.items():
        nu = n[k] - 1.0
        half = nu[0] / 2.0 if np.all(nu == nu[0]) else np.broadcast_to(
            nu / 2.0, shape + (m,)).astype(np.float32)
        chi2 = rng.standard_gamma(half, shape + (m,), dtype=np.float32)
        mean = (np.float32(mu) + np.float32(sig_mean[k] / np.sqrt(n[k]))
                * rng.standard_normal(shape + (m,), dtype=np.float32) + common)
        drawn[k] = (mean, np.float32(sig_w[k] * np.sqrt(2.0 / nu)) * np.sqrt(chi2))
    return drawn


#: the figures of the means whose interval is the union of the shrunk world's and the
#: unshrunk world's (the nuisance, the curve's spread over the targets, is taken at both
#: ends of what the readings allow: Berger & Boos 1994, JASA 89:1012)
UNION_FIGURES = frozenset({"E", "E_up", "E_down", "M", "Pa", "B", "U_max", "A", "A_up",
                           "A_down", "P", "R"})

#: the ranges of the means (the decided quantity's figure among them), whose interval comes
#: from the world whose targets' values have the distribution of the true means (the
#: triple-goal world, :func:`_ensemble` in :func:`_world_means`), not only their spread,
#: united with the unshrunk world's and not calibrated (see :func:`figure_intervals`)
RANGE_FIGURES = frozenset({"E", "E_up", "E_down"})

#: the figures of the means, where the Type B inputs (drawn once per target) enter; their
#: interval is united with the one from the same readings without them. The reference's
#: error at each target is in the readings as part of the curve and cannot be told from it;
#: the world draws it as noise of the stated u at each target, and the pivot takes the
#: excess that noise gives a range out of the measured one. A certificate's U is an
#: envelope: where the reference is better than stated, that takes out an excess the readings
#: do not hold, and the interval fell below the truth (an axis of E = 0.68", scatter 0.1",
#: with a perfect reference stated at U = 1": E's interval 0 … 0.2–0.3", 0 of 40 tests
#: covered).
#: The union holds the reference anywhere between perfect and as bad as stated (Berger &
#: Boos 1994 again: the reference's actual errors are a nuisance the readings do not fix).
#: A reference's errors need not be independent from target to target: a once-a-turn error
#: of 0.7" (its u at each target 0.5", as stated) lowers E where it opposes the curve, and an
#: audit found E covered 55–73 % of tests. The figure's error from them is the difference
#: of two targets' errors, whose standard deviation is at most u_i + u_j whatever their
#: correlation; the interval is also united with the one without them at half the tail,
#: widened by z(1 − tail/2) · 2 max u each way (a union bound: it holds at 1 − tail). A
#: reference whose U is stated for any angle between two readings (applies_to "angle") has
#: that difference within its own u: 1 × u, not 2 × (``pair_u``). The positioning workbench
#: now takes them within their U (``pair_envelope``, as the theodolite's circle error, #39's
#: widths): the interval without them at the whole tail moved out by k · pair, E's, M's and
#: the decided half range's 0.88–0.95 of the union bound's width, A's 0.80–0.83, every figure
#: still at its floor in 8 cells of 30 runs (scale, constant, per target, once a turn, the
#: curve's own shape at U against and with it; per angle and per reading). With
#: ``pair_bias_level`` (the positioning workbench's) the readings' interval of E, E↑ and E↓
#: so moved is the one at :func:`bias_aware_tail`, not at the tail: the two bounds at the
#: probability added covered about 1 − tail at the least favourable bias (#39's widths:
#: tests/benchmarks/standard_width_study.py).
TYPE_B_FIGURES = frozenset({"E", "E_up", "E_down", "M", "Pa", "A", "A_up", "A_down", "P"})

#: the grid and the most EM steps of the true means' distribution (:func:`_ensemble`)
ENSEMBLE_GRID = 80
ENSEMBLE_STEPS = 3000
#: EM steps made before their changes are compared with the bound (:func:`_ensemble`)
ENSEMBLE_BATCH = 64


def _ensemble(values: np.ndarray, se2: np.ndarray) -> np.ndarray:
    """The triple-goal estimates of Shen & Louis (1998, JRSS B 60:455) of true values measured
    as ``values`` (targets) with sampling variances ``se2``: the distribution G of the true
    values by its nonparametric maximum likelihood (Kiefer & Wolfowitz 1956; Laird 1978,
    JASA 73:805: EM on a grid over the measured span, :data:`ENSEMBLE_STEPS` steps from the
    uniform), and the target of rank r given G's quantile at (r − ½)/m. Where the range's
    bias is set by how many targets lie near the extremes (a smooth curve's crests hold
    many), this world has as many as the readings show; the constrained Bayes world of
    :func:`_shrunk` matches only the spread and puts too few there (its interval fell short
    below: 8–15 % on smooth curves at 72 targets)."""
    v = np.asarray(values, dtype=float)
    se2 = np.maximum(np.broadcast_to(se2, v.shape), 1e-150)
    lo, hi = float(np.min(v)), float(np.max(v))
    if not hi > lo:
        return v.copy()
    grid = np.linspace(lo, hi, ENSEMBLE_GRID)
    d = (v[:, None] - grid[None, :]) ** 2 / se2[:, None]
    likelihood = np.exp(-0.5 * (d - np.min(d, axis=1, keepdims=True)))
    transposed = likelihood.T
    # an EM step is a few operations on vectors of m and of the grid: most of its time is
    # numpy's per-call overhead, so a step is the fewest calls that make it: the same
    # operations in the same order into arrays made once, the products by np.dot (numpy's
    # matmul of a matrix and a vector calls the same BLAS gemv, at twice the overhead), and
    # the steps' changes found a batch of :data:`ENSEMBLE_BATCH` steps at a time, each step
    # kept in a row of ``history``; the first step whose change is below the bound ends the
    # EM there, as when each step was tested on its own (the same weights, bit for bit, in
    # 0.6 of the time: tests/models/uncertainty/test_figure_intervals_speed.py)
    density = np.empty(v.size)
    step = np.empty(grid.size)
    size = np.float64(v.size)
    history = np.empty((ENSEMBLE_BATCH + 1, grid.size))  # [0]: before the batch's first step
    history[0] = 1.0 / grid.size
    weights = history[0]
    done = 0
    while done < ENSEMBLE_STEPS:
        steps = min(ENSEMBLE_BATCH, ENSEMBLE_STEPS - done)
        for j in range(1, steps + 1):
            before, after = history[j - 1], history[j]
            np.dot(likelihood, before, out=density)
            np.divide(1.0, density, out=density)
            np.dot(transposed, density, out=step)
            np.multiply(before, step, out=after)
            np.divide(after, size, out=after)
        change = np.abs(history[1:steps + 1] - history[:steps]).max(axis=1)
        below = np.flatnonzero(change < 1e-9)
        if below.size:
            weights = history[below[0] + 1]
            break
        done += steps
        weights = history[steps]
        history[0] = weights
    cdf = np.cumsum(weights)
    ranks = np.argsort(np.argsort(v, kind="stable"), kind="stable")
    index = np.searchsorted(cdf, (ranks + 0.5) / v.size)
    return grid[np.minimum(index, grid.size - 1)]


#: calibration (Beran 1987): outer tests drawn from the world, and inner draws from each
#: outer test's own world
OUTER_TRIALS = 300
INNER_TRIALS = 40
_CHUNK = 25


def pair_widening(probability: float, pair_u: float, pair_spent: float = 0.0,
                  envelope: bool = False) -> float:
    """How far :func:`figure_intervals` moves each end of a figure's interval (of
    :data:`TYPE_B_FIGURES`) out for the reference's errors shaped as the curve's worst:
    z · ``pair_u``, z the normal factor of the half of the tail left after ``pair_spent``;
    with ``envelope``, k · ``pair_u``, k the two-sided normal factor of ``probability``
    (2 at 95.45 %: the errors within their U, a bias; the same arguments as there)."""
    if envelope:
        return float(ndtri(0.5 * (1.0 + probability))) * float(pair_u)
    tail = 0.5 * (1.0 - probability) * (1.0 - pair_spent)
    return float(ndtri(1.0 - 0.5 * tail)) * float(pair_u)


def figure_intervals(means: dict[str, np.ndarray], stds: dict[str, np.ndarray],
                     runs: dict[str, np.ndarray], probability: float,
                     type_b_u: np.ndarray | float | None = None, seed: int = 0,
                     trials: int = INTERVAL_TRIALS, figures: dict[str, float] | None = None,
                     outer: int = OUTER_TRIALS, inner: int = INNER_TRIALS,
                     pair_u: float | None = None, model_modes: np.ndarray | None = None,
                     cache: dict | None = None, pair_spent: float = 0.0,
                     pair_envelope: bool = False, pair_bias_level: bool = False
                     ) -> dict[str, FigureInterval]:
    """The coverage interval of every axis figure.

    Parameters
    ----------
    means, stds, runs : dict direction ("up"/"down") → array over the targets
        The measured x̄, s (n − 1) and number of runs of every target; every target
        approached at least twice in every direction given.
    probability : float
        The coverage probability asked for (e.g. 0.9545).
    type_b_u : array, optional
        The combined standard uncertainty of the Type B inputs at each target, in the
        deviation unit (the same for both directions); none if omitted.
    seed : int
        Seed of the bootstrap (:func:`readings_seed` of the readings).
    figures : dict, optional
        The measured figures (as the standard computes them); computed if omitted.
    outer, inner : int
        Trials of the calibration (0: no calibration, the plain basic interval).
    pair_u : float, optional
        The largest standard deviation the Type B inputs' errors can give the difference of
        two targets' errors, whatever their correlation from target to target (the
        reference's, the stated misalignment and temperature; not the roundings, which are
        independent): it sets the widening of :data:`TYPE_B_FIGURES`. 2 max ``type_b_u`` if
        omitted (each target's error within its u, two of them possibly opposite). Given
        above 0, the widening is made even where ``type_b_u`` is 0 at every target (a
        statement whose part over the scatter the readings do not show, but do not exclude).
    pair_spent : float
        The share of the tail already spent on the bound ``pair_u`` is sized by (a
        nuisance's confidence bound, Berger & Boos 1994): the widened interval is held at the
        rest, (1 − pair_spent) of the tail, so that the whole holds at ``probability``.
    pair_envelope : bool
        How the errors ``pair_u`` sizes are taken. False: random, the difference of two
        targets' errors normal with standard deviation up to ``pair_u``, and the widening a
        union bound, z(1 − rest/2) · ``pair_u`` on the readings' interval at half the rest of
        the tail each side. True: within their expanded uncertainty at ``probability`` at
        every target, whatever their shape (the statement taken at its U, a bias and not a
        scatter): a figure of :data:`TYPE_B_FIGURES` is a largest value less a smallest one
        of the targets' values, which such errors move by at most their range, k · ``pair_u``
        (k the two-sided normal factor of ``probability``, 2 at 95.45 %); the readings'
        interval at the whole rest of the tail widened by that holds at ``probability``
        without a share of the tail spent on the errors (:func:`pair_widening`; the
        theodolite's circle error, models.theodolite.figures).
    pair_bias_level : bool
        With ``pair_envelope``: the readings' interval of E, E↑ and E↓
        (:data:`BIAS_LEVEL_FIGURES`) that is moved out by k · ``pair_u`` is taken at the level
        at which the widened interval misses at exactly the tail asked for when the errors
        make their largest bias, +k · pair or −k · pair (:func:`bias_aware_tail`), not at the
        tail itself: adding the readings' bound at the probability to the errors' bound at it
        is two bounds at the probability added, and covers more than asked for at every
        bias. False: at the tail (the theodolite's).
    model_modes : array (k, targets), optional
        A fitted model's error at the targets, the same in every run and both directions,
        correlated from target to target as its parameters' covariance makes it: error =
        z @ model_modes, z ~ N(0, I_k) (a set-up model whose fit left parameter errors).
        Drawn so in every trial, and, unlike ``type_b_u`` (a certificate's envelope whose
        correlation is not known), no union: its covariance is the fit's own.
    cache : dict, optional
        Where the bootstrap of these readings is kept (kept with the result they are of:
        models.positioning.report.figure_uncertainties). The draws do not depend on the
        probability, and the readings without the Type B inputs are drawn for the window's
        intervals and again inside a certificate's (twice: at the probability and at its
        half tail): with a cache each is drawn once, the same draws as without it.
    """
    drawn = _simulation(means, stds, runs, type_b_u, seed, trials, figures, outer, inner,
                        model_modes, cache)
    out = _intervals(drawn, probability)
    u_b = drawn.shared.u
    if np.any(u_b) or (pair_u is not None and pair_u > 0.0):
        # the reference perfect: the same readings without the Type B inputs
        plain = drawn if not np.any(u_b) else _simulation(
            means, stds, runs, None, seed, trials, figures, outer, inner, drawn.shared.modes,
            cache)
        bare = _intervals(plain, probability)
        # the reference's errors shaped as the curve's worst (a once-a-turn error that lowers
        # the crests and raises the troughs): the figure of the readings without them, at
        # half the tail each side, widened by the largest difference of two targets' errors
        # (the rest of the tail where a share of it sized the pair: Berger & Boos); within
        # their U (``pair_envelope``) the errors are a bias of at most k · pair, and the
        # readings' interval takes the whole rest of the tail each side
        tail = 0.5 * (1.0 - probability) * (1.0 - pair_spent)
        pair = 2.0 * float(np.max(u_b)) if pair_u is None else float(pair_u)
        outside = 2.0 * tail if pair_envelope else tail  # both sides together
        wide = _intervals(plain, 1.0 - outside) if pair > 0.0 else bare
        shift = pair_widening(probability, pair, pair_spent, pair_envelope)
        for key in TYPE_B_FIGURES & out.keys() & bare.keys() & wide.keys():
            here, there, far = out[key], bare[key], wide[key]
            far_high = far.high
            if pair_envelope and pair_bias_level and shift > 0.0 and \
                    key in BIAS_LEVEL_FIGURES:
                level = bias_aware_tail(tail, shift, _pivot_spread(far, tail))
                far = _intervals(plain, 1.0 - 2.0 * level, frozenset({key}))[key]
                far_high = far.high
            elif pair_envelope and pair_bias_level and shift > 0.0 and \
                    key in UPPER_REACH_FIGURES:
                # M, Pa: the bootstrap's interval stays at the tail (BIAS_LEVEL_FIGURES), but
                # a named target's own pairs' bound, a Student bound of its own, shares the
                # tail with the envelope as E's interval does (bias_aware_tail): at the bias
                # that lowers the figure, the one its upper end must hold, the lower end has
                # 2 k · pair to spare (until 0.8.28 at the tail, added to the envelope whole:
                # cov78's MEDIUM, M +5.5 % where the inputs' widening had covered alone)
                level = bias_aware_tail(tail, shift, _pivot_spread(far, tail))
                pairs = _noisy_target_bounds(plain.x, plain.s, plain.n, level,
                                             frozenset({key}))
                if key in pairs and level > tail:
                    bare_far = _intervals(plain, 1.0 - outside, frozenset({key}),
                                          noisy_high=False)[key]
                    far_high = max(bare_far.high, pairs[key][1])
            out[key] = FigureInterval(here.value, max(min(here.low, there.low,
                                                          far.low - shift), 0.0),
                                      max(here.high, there.high, far_high + shift),
                                      here.probability)
    return out


#: the figures (the ranges of the means) whose readings' interval :func:`figure_intervals`
#: takes at :func:`bias_aware_tail` under ``pair_bias_level``. At the least favourable bias
#: the whole miss is the readings' interval's on one side, at up to twice the tail, so the
#: level holds only where that one-sided quantile is right: E's (the triple-goal world's)
#: is. M's and Pa's (the calibrated bootstrap's, 92.5 % where 95.45 % is asked for) is not:
#: with the curve's shape at its full U against the curve, M's interval at the level covered
#: 173 of 200 tests on the real curve at 12 targets (floor 176; 180 with the bias added to
#: the interval at the tail), so M and Pa keep theirs at the tail (#39's widths:
#: tests/benchmarks/standard_width_study.py). A, A↑, A↓ and P (per-target bounds) likewise
BIAS_LEVEL_FIGURES = frozenset({"E", "E_up", "E_down"})


def _pivot_spread(interval: FigureInterval, tail: float) -> float:
    """A figure's error's standard deviation as its interval at ``tail`` each side shows it
    (the larger half-width, or half the width, over the normal factor of the tail): the
    larger of them, so that the level of :func:`bias_aware_tail` errs toward the tail."""
    z = float(ndtri(1.0 - tail))
    half = max(interval.high - interval.value, interval.value - interval.low,
               0.5 * (interval.high - interval.low))
    return max(half, 0.0) / z if z > 0.0 else 0.0


def bias_aware_tail(tail: float, bias: float, spread: float) -> float:
    """The tail t (each side) at which the readings' interval of a figure, each end then
    moved out by ``bias`` (errors of the reference within their U: a bias of at most that on
    the figure, of either sign), misses at ``tail`` each side at the least favourable bias,
    ± ``bias`` (the fixed-length interval under a bounded bias: Armstrong & Kolesár 2020,
    Quant. Econ. 11:1, here with the readings' own quantiles).

    With the bias +b the interval's lower end misses at t (the figure's own error beyond the
    readings' bound) and its upper end when the error is below its bound by more than 2b,
    Φ(−z_t − 2b/σ), σ the error's standard deviation (``spread``); their sum, the interval's
    whole miss, is set to 2 · ``tail``: t + Φ(−z_t − 2b/σ) = 2 tail. With no bias t is the
    tail; with a bias large against σ it tends to twice the tail (the bias is on one side
    only: the other end does not miss), where adding the readings' bound at the probability
    to the bias covers at 1 − tail at the least favourable bias, more than asked for. For a
    normal error the largest miss over the biases within ±b is at ±b, so the interval holds
    at 1 − 2 tail for every bias within them (the readings' quantiles in place of the normal
    one's: tests/benchmarks/standard_width_study.py measures the coverage)."""
    if not bias > 0.0 or not tail > 0.0:
        return tail
    if not spread > 0.0:
        return 2.0 * tail
    ratio = 2.0 * bias / spread

    def excess(t: float) -> float:
        return t + float(ndtr(-float(ndtri(1.0 - t)) - ratio)) - 2.0 * tail

    if excess(2.0 * tail) <= 0.0:
        return 2.0 * tail
    return float(brentq(excess, tail, 2.0 * tail, xtol=1e-12))


@dataclass(frozen=True)
class _Simulation:
    """The bootstrap of one set of readings (:func:`_simulation`): all that
    :func:`figure_intervals` draws, none of which depends on the probability."""

    x: dict[str, np.ndarray]
    s: dict[str, np.ndarray]  # the measured s, each target's own
    sig_mean: dict[str, np.ndarray]
    n: dict[str, np.ndarray]
    shared: SharedErrors
    measured: dict[str, float]
    pivots: dict[str, np.ndarray]  # the ranges' (RANGE_FIGURES) from the triple-goal world
    scores: dict[str, np.ndarray] | None  # the calibration's (None: not calibrated)
    raw_pivots: dict[str, np.ndarray]  # the unshrunk world's


def _simulation(means, stds, runs, type_b_u, seed, trials, figures, outer, inner,
                model_modes, cache: dict | None) -> _Simulation:
    """The bootstrap of :func:`figure_intervals`' readings (its arguments), from ``cache``
    when these were drawn before (kept there by everything they are drawn from)."""
    keys = list(means)
    m = means[keys[0]].size
    n = {k: np.asarray(runs[k], float) for k in keys}
    s = {k: np.asarray(stds[k], float) for k in keys}
    x = {k: np.asarray(means[k], float) for k in keys}
    u_b = np.zeros(m) if type_b_u is None else np.broadcast_to(
        np.asarray(type_b_u, float), (m,)).copy()
    modes = None if model_modes is None else np.asarray(model_modes, float).reshape(-1, m)
    key = None
    if cache is not None:
        key = ("figure_intervals", tuple((k, x[k].tobytes(), s[k].tobytes(), n[k].tobytes())
                                         for k in keys),
               u_b.tobytes(), None if modes is None else (modes.shape, modes.tobytes()),
               int(seed), int(trials), int(outer), int(inner),
               None if figures is None else tuple(sorted(figures.items())))
        if key in cache:
            return cache[key]
    shared = SharedErrors(u_b, modes)
    measured = figures if figures is not None else world_truth(x, s)
    mu_w, sig_w, sig_mean = _world(x, s, n, shared)
    truth = world_truth(mu_w, sig_w)
    rng = np.random.default_rng(seed)
    drawn = _draw(mu_w, sig_w, sig_mean, n, shared, (trials,), rng)
    sims = axis_figures(drawn)
    pivots = {k: sims[k] - truth[k] for k in sims}
    scores = (_calibration_scores(drawn, pivots, n, shared, outer, inner, rng)
              if outer and inner else None)
    # the unshrunk world (the measured means as the truth): where the scatter hides one
    # target far off, the shrunk world flattens it and its interval falls short above
    raw_truth = world_truth(x, sig_w)
    raw_sims = axis_figures(_draw(x, sig_w, sig_mean, n, shared, (trials,), rng))
    # the ranges of the means: the triple-goal world's plain basic interval
    ens_mu = _world_means(x, sig_mean, n, shared, level=_ensemble)
    ens_truth = world_truth(ens_mu, sig_w)
    ens_sims = axis_figures(_draw(ens_mu, sig_w, sig_mean, n, shared, (trials,), rng))
    for k in RANGE_FIGURES & ens_sims.keys():
        pivots[k] = ens_sims[k] - ens_truth[k]
    out = _Simulation(x, s, sig_mean, n, shared, dict(measured), pivots, scores,
                      {k: raw_sims[k] - raw_truth[k] for k in raw_sims})
    if cache is not None:
        cache[key] = out
    return out


#: the figures whose interval :func:`_intervals` takes from :func:`_repeatability_bounds`
#: and :func:`_band_span_bounds` (made only where one of them is asked for)
BOUND_FIGURES = frozenset({"R", "R_up", "R_down", "Ps_max", "A", "A_up", "A_down", "P"})


def _intervals(drawn: _Simulation, probability: float, keys: frozenset[str] | None = None,
               noisy_high: bool = True) -> dict[str, FigureInterval]:
    """The intervals at ``probability`` of a bootstrap (without the union with the
    readings' own without the Type B inputs, which :func:`figure_intervals` makes); with
    ``keys``, of those figures only. ``noisy_high`` False: the upper end of the ranges of the
    means without a named target's own pairs' bound (:func:`_noisy_target_bounds`; the
    lower end moved as with it), which :func:`figure_intervals` then takes at a level of its
    own."""
    x, sig_mean, n, shared, pivots = drawn.x, drawn.sig_mean, drawn.n, drawn.shared, drawn.pivots
    tail = 0.5 * (1.0 - probability)
    levels = {k: (tail, 1.0 - tail) for k in pivots}
    if drawn.scores is not None:
        levels = _calibrated_levels(drawn.scores, tail)
    guard = (_reversal_guard(x, drawn.s, sig_mean, n, tail) if "up" in x and "down" in x
             else None)
    # B's lower end at half the tail (_reversal_guard)
    half_levels = ({k: (0.5 * tail, 1.0 - 0.5 * tail) for k in pivots} if drawn.scores is None
                   else _calibrated_levels(drawn.scores, 0.5 * tail))
    for key in RANGE_FIGURES & pivots.keys():
        levels[key] = (tail, 1.0 - tail)
    bounds: dict[str, tuple[float, float]] = {}
    if keys is None or keys & BOUND_FIGURES:
        bounds = _repeatability_bounds(x, drawn.s, n, tail)
        bounds.update(_band_span_bounds(x, drawn.s, n, tail, shared.modes))
    noisy_bounds = _noisy_target_bounds(x, drawn.s, n, tail, keys)
    out = {}
    for key, value in drawn.measured.items():
        if key not in pivots or value is None or not math.isfinite(value):
            continue
        if keys is not None and key not in keys:
            continue
        q_lo, q_hi = np.quantile(pivots[key], levels[key])
        low, high = value - q_hi, value - q_lo
        if key in UNION_FIGURES:
            r_lo, r_hi = np.quantile(drawn.raw_pivots[key], (tail, 1.0 - tail))
            low, high = min(low, value - r_hi), max(high, value - r_lo)
        if key in UPPER_REACH_FIGURES:
            # the upper end also from the unshrunk world's pivot deep in its lower tail: a
            # target far off (a spike) drawn low passes for one of a crowd (_range_upper_reach)
            high = max(high, value - _range_upper_reach(drawn.raw_pivots[key], tail))
            if key in noisy_bounds:
                # a target whose scatter stands out (_scatter_outliers): its own pairs' bounds
                # (_noisy_target_bounds), which the worlds' alike σ do not give
                shift, pairs_high = noisy_bounds[key]
                low, high = low - shift, max(high, pairs_high) if noisy_high else high
        if guard is not None and key in ("B", "U_max"):
            # half the tail each: the mean reversal's bound, and the lowest of the bootstrap's
            # (both worlds) and the simultaneous bound, as the lower end was before 0.8.14
            mean_low, simultaneous, upper = guard
            before = min(value - float(np.quantile(pivots[key], half_levels[key][1])),
                         value - float(np.quantile(drawn.raw_pivots[key], 1.0 - 0.5 * tail)),
                         simultaneous)
            low, high = max(mean_low, before), max(high, upper)
        if key in RANGE_FIGURES and low > 0.0 and \
                _range_within_noise(key, x, drawn.s, n, value, 2.0 * tail):
            low = 0.0
        if key not in SIGNED_FIGURES:
            low, high = max(low, 0.0), max(high, 0.0)
        if key in bounds:
            # the per-target bounds of the standard deviations alone, which hold however σ
            # changes from target to target (:func:`_repeatability_bounds`); the bootstrap's
            # interval of these figures is not valid then, and the hull with it would only
            # lower the lower end
            low, high = bounds[key]
        if high <= low and key in RANGE_BOUNDS:
            high = _range_bound(*_range_terms(key, x, sig_mean, n, shared), tail)
        out[key] = FigureInterval(float(value), float(low), float(high),
                                  min(probability, ACHIEVED.get(key, probability)))
    return out


#: the ranges whose upper end :func:`_intervals` takes at least to the unshrunk world's pivot
#: deep in its lower tail (:func:`_range_upper_reach`): E, E↑, E↓ and the range of the
#: bidirectional means, M and Pa (the calibrated bootstrap's). Until 0.8.26 M and Pa did not:
#: on a rough curve of 25 targets whose crest and trough each stood alone (1 standard
#: uncertainty clear of the next target), σ drawn at random in 1–2 × for each target and
#: direction, M's interval held the truth in 255 of 300 tests against 92.5 % printed, the truth
#: above it in every miss (one of them read low passes for one of a crowd, as E's spike);
#: with the reach 281 of 300, its mean width 1.08 × (pos77's rig, through the command line)
UPPER_REACH_FIGURES = RANGE_FIGURES | frozenset({"M", "Pa"})

#: the share of the tail at which the upper end of the ranges of the means
#: (:data:`RANGE_FIGURES`) also takes the unshrunk world's pivot (:func:`_range_upper_reach`)
RANGE_UPPER_TAIL_SHARE = 1.0 / 8.0


def _range_upper_reach(raw_pivot: np.ndarray, tail: float) -> float:
    """The lower quantile of a range's pivot in the unshrunk world taken at
    :data:`RANGE_UPPER_TAIL_SHARE` of ``tail``, extrapolated from its median and its quantile
    at ``tail`` by the normal factors (the bootstrap's 2000 trials hold few draws that deep):
    median − z(share · tail) · (median − q(tail)) / z(tail).

    Why deeper than the tail: a range's pivot is not pivotal. Its lower tail is longest where
    the curve's extreme is one target alone (the figure's error is then that target's), and
    shorter the more targets crowd the extreme. Where one target stands far off (a spike,
    cov76 F3: 25 targets, a 5″ spike on a random 1.5″ curve, σ 1.5–2″ at random per target)
    and its mean comes out low, the readings show a crowd at the top, and both worlds (the
    triple-goal and the unshrunk) put one there: their pivot's lower quantile is too short,
    and the truth lay above the interval in 10 % of 250 tests (E 88.8 %, E↓ 87.6 % covered
    against 92.5 % and 93.5 % printed). With the unshrunk world's lower spread stretched by
    z(tail/8)/z(tail) (1.38 × at 95.45 %) the audit's tests covered E 93.6 %, E↑ 95.6 %,
    E↓ 93.6 % (at tail/4: E↓ 92.4 %; at tail/16: 94.8 %, but E's interval on a spike in
    scatter at 72 targets 1.73 × the width needed, over the 1.7 × that
    tests/models/positioning/test_figure_intervals.py allows, check_e_not_wider_than_needed;
    1.68 × here, 1.49 × before). An upper end that holds for any curve (the largest pair's
    own bound, :func:`_range_bound`) covered the audit's axis at 98.8 % but was 2.5–3.9 × the
    width a correct interval needs where noise hides a smooth curve among 72 targets."""
    q_tail, median = np.quantile(raw_pivot, (tail, 0.5))
    z_tail = float(ndtri(1.0 - tail))
    if not z_tail > 0.0:
        return float(q_tail)
    reach = float(ndtri(1.0 - RANGE_UPPER_TAIL_SHARE * tail)) / z_tail
    return float(median - reach * (median - q_tail))


#: the family-wise level of the test that names a target whose scatter stands out from the
#: others' (:func:`_scatter_outliers`; spike78: 0.01 left one cell of the spike at the
#: noisiest target below its printed probability, 0.05 widened E's interval where σ is
#: drawn at random in 1–2 × by up to 17 %, 0.02 by up to 11 %)
SCATTER_OUTLIER_LEVEL = 0.02


def _scatter_outliers(s: dict[str, np.ndarray], n: dict[str, np.ndarray],
                      level: float) -> np.ndarray:
    """Per target, whether its scatter stands out from the other targets': in each direction,
    a target's s² against the pooled variance of the direction's other targets,
    F = s_i² / s²_rest with (ν_i, ν_rest) degrees of freedom (Cochran's C for equal ν,
    C = s_i² / Σ s², is monotone in it; Cochran 1941, Ann. Eugen. 11:47), each at Šidák's
    share of ``level`` over the targets of both directions, so that where σ is the same at
    every target of a direction some target is named in at most ``level`` of tests (the two
    directions may scatter differently). A target is named where either direction's F is
    above its critical value."""
    m = np.size(next(iter(s.values())))
    if m < 2 or not level > 0.0:
        return np.zeros(m, dtype=bool)
    cut = 1.0 - (1.0 - level) ** (1.0 / (m * len(s)))
    named = np.zeros(m, dtype=bool)
    for key, sd in s.items():
        s2 = np.asarray(sd, float) ** 2
        nu = np.broadcast_to(np.asarray(n[key], float), s2.shape) - 1.0
        nu_rest = np.sum(nu) - nu
        rest = (np.sum(nu * s2) - nu * s2) / np.maximum(nu_rest, 1e-300)
        critical = fdtri(nu, nu_rest, 1.0 - cut)
        named |= np.where(rest > 0.0, s2 > critical * rest, s2 > 0.0)
    return named


def _welch_t(parts: np.ndarray, nus: np.ndarray, tail: float) -> np.ndarray:
    """Student's one-sided quantile at ``tail`` for a sum of independent variance terms
    ``parts`` (…, terms), each with its degrees of freedom ``nus``, by Welch–Satterthwaite
    (Welch 1947, Biometrika 34:28); 0 where the sum is 0."""
    total = np.sum(parts, axis=-1)
    denominator = np.sum(parts**2 / nus, axis=-1)
    df = np.where(denominator > 0.0, total**2 / np.where(denominator > 0.0, denominator, 1.0),
                  1.0)
    return np.where(total > 0.0, stdtrit(np.maximum(df, 1.0), 1.0 - tail), 0.0)


def _range_values(key: str, x, s, n) -> tuple[np.ndarray, np.ndarray, np.ndarray,
                                              np.ndarray] | None:
    """(values, target of each, variance terms (values, 2), their degrees of freedom) of the
    means a range figure spans, the terms from each target's own s (a bidirectional mean's
    two directions' quarters); None where the figure is not a range of them."""
    def own(d):
        var = np.asarray(s[d], float) ** 2 / np.asarray(n[d], float)
        nu = np.broadcast_to(np.asarray(n[d], float) - 1.0, var.shape)
        return var, nu

    both = "up" in x and "down" in x
    m = np.size(next(iter(x.values())))
    index = np.arange(m)
    zero = np.zeros(m)
    if key in ("E_up", "E_down") and key[2:] in x or key == "Pa" and not both:
        d = key[2:] if key != "Pa" else next(iter(x))
        var, nu = own(d)
        return (np.asarray(x[d], float), index, np.stack([var, zero], axis=-1),
                np.stack([nu, np.ones(m)], axis=-1))
    if key == "E" and both:
        (v_up, nu_up), (v_down, nu_down) = own("up"), own("down")
        var = np.concatenate([v_up, v_down])
        return (np.concatenate([np.asarray(x["up"], float), np.asarray(x["down"], float)]),
                np.concatenate([index, index]), np.stack([var, np.zeros(2 * m)], axis=-1),
                np.stack([np.concatenate([nu_up, nu_down]), np.ones(2 * m)], axis=-1))
    if key in ("M", "Pa") and both:
        (v_up, nu_up), (v_down, nu_down) = own("up"), own("down")
        return (0.5 * (np.asarray(x["up"], float) + np.asarray(x["down"], float)), index,
                np.stack([0.25 * v_up, 0.25 * v_down], axis=-1),
                np.stack([nu_up, nu_down], axis=-1))
    return None


#: draws of the flat axis's range (:func:`_range_within_noise`): its quantile at the tail to
#: about ±0.1 of a standard uncertainty of a mean
FLAT_RANGE_DRAWS = 4000


def _range_within_noise(key: str, x, s, n, value: float, tail: float) -> bool:
    """Whether the measured range ``value`` of the means that E, E↑ or E↓ spans is no more
    than the scatter of the means makes on an axis with no systematic deviation at all (every
    μ the same): at most the (1 − ``tail``) quantile of the range of independent normal
    means, each with its own target's s/√n (a parametric bootstrap of that axis, seeded from
    the readings). Where it is, nothing in the readings excludes a truth of 0, and the
    interval's lower end is 0.

    Without it the lower end came from the bootstrap's worlds, whose means are the measured
    ones: on a flat axis they carry the noise's range as a curve, and the lower end stood
    above the truth, 0, in 39 of 300 tests of E (allowed 7.5 %), 34 of E↓ (6.5 %), 24 of E↑
    (8 %), 12 targets × 5 runs (width81b: 90 of 800 of E); with it, at ``tail`` the whole
    two-sided share (on a flat axis the upper end cannot miss: the truth 0 is below it), 6,
    9 and 5 of 300, the mean widths 1–2 % wider (tests/models/positioning/
    test_flat_axis_lower_end.py). Where the range of many means is within the noise's
    (a small curve under a scatter as large, 72 targets) the lower end is 0 more often: the
    readings do not tell that axis from a flat one (E's width there 1.93 × the spread of
    measured − truth, 1.7 before: tests/models/positioning/test_figure_intervals.py).
    Each s scatters about its σ (4 degrees of freedom at 5 runs): the largest of the s-scaled
    means spreads further than the σ-scaled ones, so the quantile is, if anything, high, and
    the rule holds the truth 0 at least at the probability."""
    found = _range_values(key, x, s, n)
    if found is None:
        return False
    values, _, var, _ = found
    se = np.sqrt(np.sum(var, axis=-1))
    rng = np.random.default_rng(readings_seed(np.asarray(values, float), se))
    drawn = rng.standard_normal((FLAT_RANGE_DRAWS, se.size)) * se
    ranges = drawn.max(axis=1) - drawn.min(axis=1)
    return bool(value <= float(np.quantile(ranges, 1.0 - tail)))


def _noisy_target_bounds(x, s, n, tail: float, keys: frozenset[str] | None = None
                         ) -> dict[str, tuple[float, float]]:
    """(how far the lower end moves down, the least upper end) of the ranges of the means
    (:data:`UPPER_REACH_FIGURES`) where a target's scatter stands out from the others'
    (:func:`_scatter_outliers` at :data:`SCATTER_OUTLIER_LEVEL`), from that target's own mean
    and s, never pooled or shrunk. Empty where no target is named.

    * upper: max over the other values i of |v_j − v_i| + t·√(se_j² + se_i²) for each named
      target j (each of its directions for E), t Student's at the whole tail with the
      pair's Welch–Satterthwaite degrees of freedom (Welch 1947, Biometrika 34:28). Where
      the range's true extreme is at j, its other extreme is at one fixed value i*, so the
      pair (j, i*)'s own bound holds at 1 − tail and the largest over i is above it (the
      intersection–union bound, Berger 1982, as :func:`_range_bound`, here over j's pairs
      only: where j is not the true extreme, the bootstrap's end holds as before);
    * lower: where a named target's value is the measured extreme of the figure, the
      bootstrap's lower end moves down by (t − z)·se_j, t Student's and z the normal
      quantile at the tail: the figure's error is then that target's, which the worlds draw
      normal about its own s (a plug-in) where the readings give it Student's distribution
      of few degrees of freedom (z 2.00, t 2.87 at 4 and 95.45 %).

    Why: the worlds of the bootstrap fit σ alike from target to target (moderated, the
    means' own s at most), and their pivots of a range take its extreme for the crowd the
    readings show. Where one target's σ is 3 × the others' and the curve's extreme (a spike)
    is there, its mean drawn low passes for one of the crowd: the truth lay above E↑'s, E↓'s
    and M's interval in up to 15 % of 150 tests through the command line (spike78's rig, 13,
    25 and 36 targets; E↑ and E↓ 79–86 % covered, M 84–95 %, against 92–93.5 % printed); its
    mean drawn high (its s low), below it in up to 7 %. With both: 93.3–99.3 % covered, at
    1.27–1.98 × a correct interval's width (0.87–1.43 before); where σ is alike the intervals
    0–1.4 % wider on average, with σ at random in 1–2 × 1–11 %. Not adopted: a lower end
    |v_j − v̄_rest| − t·se, which holds for any curve (E's interval up to 14 % wider with σ
    at random, against 8 %, at the test's 1 %)."""
    named = np.flatnonzero(_scatter_outliers(s, n, SCATTER_OUTLIER_LEVEL))
    out: dict[str, tuple[float, float]] = {}
    if named.size == 0:
        return out
    z = float(ndtri(1.0 - tail))
    for key in UPPER_REACH_FIGURES:
        if keys is not None and key not in keys:
            continue
        terms = _range_values(key, x, s, n)
        if terms is None or terms[0].size < 2:
            continue
        values, target, parts, nus = terms
        high, shift = -math.inf, 0.0
        for j in np.flatnonzero(np.isin(target, named)):
            rest = np.arange(values.size) != j
            pair_parts = np.concatenate([np.broadcast_to(parts[j], parts[rest].shape),
                                         parts[rest]], axis=-1)
            pair_nus = np.concatenate([np.broadcast_to(nus[j], nus[rest].shape), nus[rest]],
                                      axis=-1)
            t = _welch_t(pair_parts, pair_nus, tail)
            high = max(high, float(np.max(np.abs(values[j] - values[rest])
                                          + t * np.sqrt(np.sum(pair_parts, axis=-1)))))
            if values[j] >= np.max(values) or values[j] <= np.min(values):
                own = float(_welch_t(parts[j][None, :], nus[j][None, :], tail)[0])
                shift = max(shift, (own - z) * math.sqrt(float(np.sum(parts[j]))))
        out[key] = (shift, high)
    return out


def _sigma_bound(s: np.ndarray, n: np.ndarray, tail: float | np.ndarray, upper: bool
                 ) -> np.ndarray:
    """Each target's one-sided confidence bound of σ from its s with ν = n − 1 (the readings
    normal: ν s²/σ² ~ χ²_ν): upper s √(ν / χ²_ν(tail)), lower s √(ν / χ²_ν(1 − tail)), each
    holding at 1 − ``tail`` (ISO 230-2's s_i: n runs at a target, ν = n − 1)."""
    nu = np.asarray(n, float) - 1.0
    quantile = chdtri(nu, 1.0 - tail) if upper else chdtri(nu, tail)
    return np.asarray(s, float) * np.sqrt(nu / quantile)


def _reversal_t(n_up: np.ndarray, n_down: np.ndarray, tail: float | np.ndarray) -> np.ndarray:
    """Student's quantile at one-sided ``tail`` for (b_i − β_i) / √(s↑²/n↑ + s↓²/n↓) with
    min(n↑, n↓) − 1 degrees of freedom: Hsu's conservative solution of the Behrens–Fisher
    problem (Hsu 1938; Mickey & Brown 1966, Ann. Math. Statist. 37:639: the tail is at most
    the one of t with that ν, whatever σ↑/σ↓)."""
    nu = np.minimum(np.asarray(n_up, float), np.asarray(n_down, float)) - 1.0
    return stdtrit(nu, 1.0 - tail)


#: the part of a target's share of the tail at R's lower end (:func:`_repeatability_bounds`)
#: left for the misses of the two-way term that the σ's bounds do not make (found below
#: 0.002 of the share: tests/benchmarks/two_way_bound_study.py), the rest to σ↑ and σ↓
TWO_WAY_LOW_ROOM = 0.05


def _two_way_miss(level: float, n: float, n_t: float) -> float:
    """P(2G s + |b| + t·se < 2σ + |β|) for one direction's σ alone (the other's σ → 0) and
    |β| ≫ σ, G and t at ``level`` (G by χ² with n − 1, t by Student with n_t − 1, se = s/√n):
    P(Z/√n + S (2G + t/√n) < 2), S = s/σ, by quadrature over the chi distribution of S at
    normal scores −8 … 8 (the normal part in closed form)."""
    nu = n - 1.0
    z = np.linspace(-8.0, 8.0, 1601)
    w = np.exp(-0.5 * z**2)
    w /= w.sum()
    q = np.where(z < 0, chdtri(nu, 1.0 - ndtr(z)), chdtri(nu, ndtr(-z)))
    big_s = np.sqrt(q / nu)
    g = math.sqrt(nu / float(chdtri(nu, 1.0 - level)))
    t = float(stdtrit(n_t - 1.0, 1.0 - level))
    root = math.sqrt(n)
    return float(np.sum(w * ndtr(2.0 * root - big_s * (2.0 * g * root + t))))


@functools.lru_cache(maxsize=512)
def _two_way_level(n_up: float, n_down: float, tail: float) -> float:
    """The level at which R's two-way term 2σ↑ + 2σ↓ + |β| takes its three bounds
    (:func:`_repeatability_bounds`) so that their sum misses at most at ``tail``: the
    level whose miss at the least favourable point, one direction's σ alone and |β| ≫ σ
    (:func:`_two_way_miss`, the larger of the two directions'), is ``tail``.

    The sum's miss is below the level: the mean's error b − β is independent of the s and
    leaves the σ bounds room, so each bound at the whole tail misses at 0.44–0.88 of it
    at 10 to 2 runs (tests/benchmarks/two_way_bound_study.py). Why that point is the least favourable:
    |b| ≥ b·sign β, so the miss at any β is at most the one of the linear form
    2(G s↑ − σ↑) + 2(G s↓ − σ↓) + (b − β)·sign β + t·se < 0, which |β| ≫ σ reaches; and
    over σ↓/σ↑ the miss grows toward either end (the other direction's bound then adds
    nothing), found by simulation over σ↓/σ↑ 10⁻³ … 10³, |β|/σ 0 … 10⁶, n↑, n↓ 2 … 10
    (10⁶ draws a point: tests/benchmarks/two_way_bound_study.py; a few points of it
    including the worst in tests/models/uncertainty/test_two_way_repeatability_bound.py).
    t's degrees of freedom are Hsu's, min(n↑, n↓) − 1 (:func:`_reversal_t`), whichever
    direction's σ is the one left."""
    n_t = min(n_up, n_down)

    def excess(level: float) -> float:
        return max(_two_way_miss(level, n_up, n_t), _two_way_miss(level, n_down, n_t)) - tail

    if excess(tail) >= 0.0:  # never narrower than each bound at the whole tail would allow
        return tail
    return float(brentq(excess, tail, 0.5, xtol=1e-9 * tail))


def _repeatability_bounds(x: dict[str, np.ndarray], s: dict[str, np.ndarray],
                          n: dict[str, np.ndarray], tail: float
                          ) -> dict[str, tuple[float, float]]:
    """(lower, upper) bounds of the figures made of the standard deviations, each holding at
    1 − ``tail`` whatever σ does from target to target (the readings normal), from each
    target's own x̄ and s (:func:`_sigma_bound`), never pooled or shrunk.

    The bootstrap's world shrinks the targets' σ toward a common one, and its pivot of a
    maximum of s_i allows for the bias of the largest of alike s_i: where one target's σ is
    larger than the rest and its s came out low, its interval lay below the truth (an audit,
    one target's σ doubled: R↑ covered 42 of 80 tests at 93.5 % printed). Here:

    * upper end: a maximum over the targets is attained at one fixed target (and term), so
      that target's own one-sided bound holds at 1 − tail, with no correction for the m
      targets, and the largest of the m bounds is above it (the intersection–union bound,
      Berger 1982, Technometrics 24:295, as B's upper end): R↑ ≤ 4 max_i σ↑_i,upper;
    * lower end: every target's lower bound at once, the tail split over the targets (Šidák
      1967, JASA 62:626: the s_i are independent), so their largest is below the maximum;
    * R = max_i max(2σ↑ + 2σ↓ + |β_i|, 4σ↑, 4σ↓): 4σ↑ and 4σ↓ as above. The two-way term's
      upper bound is the sum of σ↑'s, σ↓'s and |β_i|'s upper bounds, |β_i| by
      |b_i| + t·√(s↑²/n↑ + s↓²/n↓) (:func:`_reversal_t`), b_i = x̄↑ − x̄↓, all three at the
      one level (:func:`_two_way_level`) at which the sum misses at exactly the tail at the
      least favourable point (one direction's σ alone, |β| ≫ σ): 1.14–2.4 times the tail
      at 2–20 runs, as the three share s↑ and s↓ and b − β is independent of them (until
      0.8.18 each at a third of the tail, Bonferroni: the sum missed at 0.13–0.30 of the
      tail at most, at 10 to 2 runs; R's interval is now 0.61–0.79 of that width, 0.87–0.95
      where one target's 4σ makes R, its bound as before: #39's study,
      tests/benchmarks/repeatability_width_study.py, 191–200 of 200 covered in every
      cell). The lower end: R is at least every target's R_i made of lower bounds where
      none of them is above its own R_i, each target's at Šidák's share of the tail over
      the m targets. A target's misses when σ↑'s
      or σ↓'s lower bound is above σ (the two at once, Šidák over the two directions, at all
      but :data:`TWO_WAY_LOW_ROOM` of the share), or when neither is and 2σ̌↑ + 2σ̌↓ +
      max(|b_i| − t·se, 0) is above 2σ↑ + 2σ↓ + |β_i|: with t at the whole share (one-sided)
      that is below 0.002 of the share over σ↓/σ↑ 10⁻² … 10², |β|/σ 0 … 20, 2–30 runs and
      2–72 targets (the σ's bounds lie far below the σ's there, which leaves the reversal
      room; tests/benchmarks/two_way_bound_study.py). Until 0.8.18 3m bounds at tail/(3m)
      each (the reversal's two-sided). A sum of lower bounds each at the target's whole
      share, as Ps_max's, does not hold here: where σ↑ = σ↓ and β = 0, 4σ↑ and 4σ↓ are
      both R_i, and either σ's bound above its own makes the target's bound miss: twice
      the share;
    * Ps_max = max 3(σ↑ + σ↓) (VDI/DGQ 3441) likewise: a target's σ↑ + σ↓ by the sum of its
      two bounds, each at the whole tail (upper end) or at Šidák's share of the targets
      (lower end): the sum holds at that tail whatever σ↓/σ↑, exact where one σ is far the
      larger (tests/models/uncertainty/test_joint_band_bounds.py; until 0.8.17 at half the
      tail each, and the lower end's Šidák over both directions' 2m bounds).

    :func:`_intervals` states them in place of the bootstrap's interval, which holds only
    where σ is the same at every target (the hull of the two, tried first, covered as these
    do and was wider: its lower end was the lower of the two)."""
    out: dict[str, tuple[float, float]] = {}
    m = next(iter(s.values())).size
    if m == 0:
        return out
    sidak = 1.0 - (1.0 - tail) ** (1.0 / m)
    high_one: dict[str, np.ndarray] = {}
    for key in s:
        high_one[key] = 4.0 * _sigma_bound(s[key], n[key], tail, upper=True)
        lows = 4.0 * _sigma_bound(s[key], n[key], sidak, upper=False)
        out[f"R_{key}"] = (float(np.max(lows)), float(np.max(high_one[key])))
    if len(s) == 1:  # one direction: Ps_max = 6 max σ
        r_low, r_high = next(iter(out.values()))
        out["Ps_max"] = (1.5 * r_low, 1.5 * r_high)
    if "up" in s and "down" in s:
        s_up, s_down = s["up"], s["down"]
        n_up = np.broadcast_to(np.asarray(n["up"], float), s_up.shape)
        n_down = np.broadcast_to(np.asarray(n["down"], float), s_down.shape)
        reversal = np.abs(x["up"] - x["down"])
        se = np.sqrt(s_up**2 / n_up + s_down**2 / n_down)
        level = np.array([_two_way_level(float(a), float(b), float(tail))
                          for a, b in zip(n_up, n_down, strict=True)])
        two_way_high = (2.0 * _sigma_bound(s_up, n_up, level, upper=True)
                        + 2.0 * _sigma_bound(s_down, n_down, level, upper=True)
                        + reversal + _reversal_t(n_up, n_down, level) * se)
        # the lower end: a target's share of the tail (Šidák over the targets), its σ↑ and
        # σ↓ at once (Šidák over the two) at all but TWO_WAY_LOW_ROOM of it, |β_i|'s bound
        # (one-sided) at the whole share: the σ's bounds' slack keeps its own misses below
        # the room
        sigma_cut = 1.0 - math.sqrt(1.0 - (1.0 - TWO_WAY_LOW_ROOM) * sidak)
        low_up = _sigma_bound(s_up, n_up, sigma_cut, upper=False)
        low_down = _sigma_bound(s_down, n_down, sigma_cut, upper=False)
        low_reversal = np.maximum(reversal - _reversal_t(n_up, n_down, sidak) * se, 0.0)
        two_way_low = np.maximum(np.maximum(2.0 * low_up + 2.0 * low_down + low_reversal,
                                            4.0 * low_up), 4.0 * low_down)
        out["R"] = (float(np.max(two_way_low)),
                    float(max(np.max(two_way_high), np.max(high_one["up"]),
                              np.max(high_one["down"]))))
        # σ↑ + σ↓ of a target by the sum of its two bounds at the whole tail, upper at the
        # tail, lower at Šidák's over the targets (:func:`_band_span_bounds`: the joint bound)
        out["Ps_max"] = (3.0 * float(np.max(_sigma_bound(s_up, n_up, sidak, upper=False)
                                           + _sigma_bound(s_down, n_down, sidak, upper=False))),
                         3.0 * float(np.max(_sigma_bound(s_up, n_up, tail, upper=True)
                                           + _sigma_bound(s_down, n_down, tail, upper=True))))
    return out


def _band_edge_bound(x: np.ndarray, s: np.ndarray, n: np.ndarray, reach: float, tail: float,
                     upper: bool) -> np.ndarray:
    """Each target's one-sided confidence bound of μ + ``reach`` · σ (``reach`` of either
    sign: μ ± 2σ, the ends of ISO 230-2's band x̄ ± 2s) from its own x̄, s and n readings,
    holding at 1 − ``tail`` whatever μ and σ (the readings normal): the one-sided tolerance
    bound by the noncentral t distribution (Owen 1968, Technometrics 10:445; ISO 16269-6's
    one-sided intervals): √n (μ + r σ − x̄) / s for r ≥ 0 is noncentral t with ν = n − 1
    and noncentrality r √n, so μ + r σ ≤ x̄ + s t′_ν,r√n(1 − tail) / √n (upper) and
    ≥ x̄ + s t′(tail) / √n (lower); μ − r σ by the same with the readings' sign turned."""
    n = np.asarray(n, float)
    root = np.sqrt(n)
    grows = reach >= 0.0
    level = (1.0 - tail) if upper == grows else tail
    factor = nctdtrit(n - 1.0, abs(reach) * root, level) / root
    return np.asarray(x, float) + (1.0 if grows else -1.0) * np.asarray(s, float) * factor


#: the share of a band figure's tail (:func:`_band_span_bounds`) spent on the set-up model's
#: error at the targets (``model_modes``: the same in every run and both directions), where
#: there is one
MODEL_SHARE = 0.1


def _model_pair(modes: np.ndarray | None) -> float:
    """The largest standard deviation of the difference of the model's errors at two targets
    (error = z @ modes, z ~ N(0, I_k)): max ‖modes_i − modes_j‖; 0 with none."""
    if modes is None or not np.any(modes):
        return 0.0
    diff = modes[:, :, None] - modes[:, None, :]
    return float(np.sqrt(np.max(np.sum(diff**2, axis=0))))


def _band_span_bounds(x: dict[str, np.ndarray], s: dict[str, np.ndarray],
                      n: dict[str, np.ndarray], tail: float, modes: np.ndarray | None = None
                      ) -> dict[str, tuple[float, float]]:
    """(lower, upper) bounds of the figures that span the targets' bands μ ± 2σ (A↑, A↓, A)
    and μ ± (|β|/2 + 3σ̄) (VDI/DGQ 3441's P), each end holding at 1 − ``tail`` whatever μ and
    σ do from target to target (the readings normal), from each target's own x̄ and s, never
    pooled or shrunk: the interval holds at 1 − 2 ``tail``, the probability asked for, by
    construction.

    The bootstrap's world shrinks the targets' σ toward a common one: where one target
    scatters more than the rest its band's end, which makes the figure, is drawn too short,
    and the interval fell below the truth (#39: with one target's σ × 2 or × 3, A covered
    45–70 of 80 tests, A↑ and A↓ 43–72, P 49–72, at 93.5–94.5 % printed; 12 and 36 targets,
    3 and 5 runs each way). Here, with U_i = μ_i + 2σ_i and L_i = μ_i − 2σ_i over the
    targets (and directions) of the figure, A = max U_i − min L_i:

    * upper end: the maximum and the minimum are attained at two fixed targets, so their own
      one-sided bounds (:func:`_band_edge_bound`) bound A with no correction for the m
      targets, and max Û_i − min L̂_i is above them (the intersection–union bound, Berger
      1982, Technometrics 24:295, as R's and B's upper ends). Each bound is at the WHOLE
      tail, not half (Bonferroni, until 0.8.17): the miss of Û_i − L̂_j is a function of
      σ_j/σ_i alone, tends to the tail of one bound where one σ is much the larger (the
      other term's error counts for nothing there) and is below it in between; where one
      target and direction makes both ends (A = 4σ_i) it is P(2F s_i < 4σ_i), 0.93 of the
      tail at 3 runs. The level is exact at the least favourable σ (computed by numerical
      integration: tests/models/uncertainty/test_joint_band_bounds.py);
    * lower end: every target's lower bound of U_i and upper bound of L_i at once (Šidák
      1967, JASA 62:626, over the independent targets and directions; Bonferroni between a
      target's two bounds), so max Ǔ_i − min Ľ_i is below A; where every target is alike
      this is exact but for the two bounds' overlap (negligible);
    * P = max V_i − min W_i, V_i = max(μ↑ + 1.5σ↑, μ↓ + 1.5σ↓) + 1.5σ of the other direction
      (m_i + (|β_i| + 3(σ↑ + σ↓))/2), W_i likewise below: each direction's band end by the
      bound of μ ± 1.5σ (:func:`_band_edge_bound`) with 1.5 times the bound of the other
      direction's σ (:func:`_sigma_bound`) added, both at the same tail. The sum holds at
      that tail whatever σ↓/σ↑ (exact at the least favourable ratio, as A's pair above), only
      the direction that makes V_i (W_i) needs its bound, and the pair V̂_i − Ŵ_j holds at the
      tail as A's does (a simulation over the three σ ratios of two targets' four samples,
      2 × 10⁶ draws each: at most 0.996 of the tail): the upper end takes every bound at
      the whole tail (until 0.8.17, 8 at tail/8: P's interval 1.8–3.1 times as wide). The
      lower end: every target's four band ends at once, Šidák over the targets and a quarter
      within (until 0.8.17, each term on its own, six a target);
    * with a set-up model's error at the targets (``modes``: the same in every run and both
      directions, error = z @ modes), :data:`MODEL_SHARE` of the tail goes to it: the upper
      end is widened by the normal quantile times the largest standard deviation of the
      difference of two targets' errors (a fixed pair), the lower end by √χ²_k of the
      same (every pair at once, ‖z‖ bounded).

    The price is width where the runs are few: the bound of μ + 2σ from a target's own 3
    readings is x̄ + 13.7 s at 97.7 % (x̄ + 6.2 s from 5), and the readings cannot tell which
    target scatters most; at the least favourable σ (one target's far the largest) these
    bounds miss at exactly the tail, so no interval of this form that holds one noisier
    target the readings do not name is narrower. The study of #39's widths (smooth and rough
    curves, σ varying 1.0–1.3 × or one target's × 3, 12 and 36 targets, 3 and 5 runs, 200
    tests a cell: tests/benchmarks/band_width_study.py): every cell 199–200 of 200 before and
    after, widths against 0.8.17's A, A↑, A↓ 0.67–0.81, P 0.32–0.55, Ps_max 0.69–0.80."""
    out: dict[str, tuple[float, float]] = {}
    pair = _model_pair(modes)
    share = MODEL_SHARE if pair > 0.0 else 0.0
    rest = tail * (1.0 - share)
    k = 0 if modes is None else modes.shape[0]
    widen_high = float(ndtri(1.0 - tail * share)) * pair if share else 0.0
    widen_low = math.sqrt(float(chdtri(k, tail * share))) * pair if share else 0.0
    groups: dict[str, tuple[str, ...]] = {f"A_{d}": (d,) for d in x}
    if "up" in x and "down" in x:
        groups["A"] = ("up", "down")
    for key, directions in groups.items():
        count = sum(x[d].size for d in directions)
        if count == 0:
            continue
        top = max(float(np.max(_band_edge_bound(x[d], s[d], n[d], 2.0, rest, True)))
                  for d in directions)
        bottom = min(float(np.min(_band_edge_bound(x[d], s[d], n[d], -2.0, rest, False)))
                     for d in directions)
        cut = 0.5 * (1.0 - (1.0 - rest) ** (1.0 / count))
        top_low = max(float(np.max(_band_edge_bound(x[d], s[d], n[d], 2.0, cut, False)))
                      for d in directions)
        bottom_high = min(float(np.min(_band_edge_bound(x[d], s[d], n[d], -2.0, cut, True)))
                          for d in directions)
        out[key] = (max(top_low - bottom_high - widen_low, 0.0),
                    top - bottom + widen_high)
    if "up" in x and "down" in x and x["up"].size:
        cut = (1.0 - (1.0 - rest) ** (1.0 / x["up"].size)) / 4.0
        v_high = _vdi_band_edge(x, s, n, 1.5, rest, outward=True)
        w_low = _vdi_band_edge(x, s, n, -1.5, rest, outward=True)
        v_low = _vdi_band_edge(x, s, n, 1.5, cut, outward=False)
        w_high = _vdi_band_edge(x, s, n, -1.5, cut, outward=False)
        out["P"] = (max(float(np.max(v_low) - np.min(w_high)) - widen_low, 0.0),
                    float(np.max(v_high) - np.min(w_low)) + widen_high)
    return out


def _vdi_band_edge(x, s, n, k: float, tail: float, outward: bool) -> np.ndarray:
    """Per target, a bound of VDI/DGQ 3441's band edge x̄ + k·σ (k = +1.5: the top, −1.5:
    the bottom) with the other direction's σ added to it, the larger of the two directions'
    (top) or the smaller (bottom): each direction's own tolerance bound of μ + kσ at ``tail``
    plus k times the other direction's chi-square bound of σ. ``outward``: the bound that
    moves the edge away from the band's middle (upper for the top, lower for the bottom),
    else the one toward it."""
    pick = np.maximum if k > 0 else np.minimum
    band_upper = outward if k > 0 else not outward
    return pick(_band_edge_bound(x["up"], s["up"], n["up"], k, tail, band_upper)
                + k * _sigma_bound(s["down"], n["down"], tail, outward),
                _band_edge_bound(x["down"], s["down"], n["down"], k, tail, band_upper)
                + k * _sigma_bound(s["up"], n["up"], tail, outward))


#: the ranges of the means whose interval, where the bootstrap's collapses to a point, takes
#: the bound of :func:`_range_bound` as its upper end
RANGE_BOUNDS = frozenset({"E", "E_up", "E_down", "M", "Pa"})


def _range_terms(key, x, sig_mean, n, shared) -> tuple[np.ndarray, np.ndarray]:
    """The means a range figure spans and their standard uncertainties (the scatter of the
    mean and the Type B inputs)."""
    def u(k):
        return np.sqrt(sig_mean[k] ** 2 / n[k] + shared.variance)
    if key in ("E_up", "E_down"):
        k = key[2:]
        return x[k], u(k)
    if key == "E":
        return np.concatenate([x["up"], x["down"]]), np.concatenate([u("up"), u("down")])
    if "up" in x and "down" in x:  # M, Pa: the bidirectional mean
        return (0.5 * (x["up"] + x["down"]),
                np.sqrt(0.25 * (sig_mean["up"] ** 2 / n["up"]
                                + sig_mean["down"] ** 2 / n["down"]) + shared.variance))
    k = next(iter(x))
    return x[k], u(k)


def _range_bound(values: np.ndarray, u: np.ndarray, tail: float) -> float:
    """An upper bound of a range of true values that holds whatever the curve:
    max over pairs (x_i − x_j + z·√(u_i² + u_j²)), z the one-sided normal quantile at
    ``tail``. The two targets where the true range is attained are one fixed pair, so its
    own bound holds at 1 − tail, and the largest over the pairs is above it. It is wide (the
    noise's whole excess is left in), so it is used only where the bootstrap interval
    collapses to a point: readings more alike than their scatter allows (every mean equal,
    each target's readings the same pattern), where the pivot put both ends below 0 and the
    interval printed was 0 … 0 while s > 0."""
    z = float(ndtri(1.0 - tail))
    spread = values[:, None] - values[None, :] + z * np.sqrt(u[:, None] ** 2 + u[None, :] ** 2)
    return float(max(np.max(spread), 0.0))


def _reversal_guard(x, s, sig_mean, n, tail) -> tuple[float, float, float]:
    """(mean's lower bound, simultaneous lower bound, upper bound) of B = max |μ↑ − μ↓|.

    Lower: B's lower end (:func:`_intervals`) is the larger of two lower ends, each at half
    the tail (Bonferroni: the larger holds at 1 − tail if each holds at 1 − tail/2):

    * |B̄| − t·se(B̄), B̄ the mean of the reversals B_i, se from the targets' own s and runs
      (the errors that are the same both ways, the reference's, cancel in a reversal), t the
      two-sided Student quantile at the half tail with the Welch–Satterthwaite degrees of
      freedom: |mean β_i| ≤ mean |β_i| ≤ max |β_i| = B, so it is a lower bound of B for
      any shape (B ≥ each of a set of bounds: intersection bounds, Chernozhukov, Lee &
      Rosen 2013, Econometrica 81:667, here with a fixed average among them). Where the
      reversal is nearly the same at every target (a machine's common backlash) it lies
      about 2.5 u/√m below B;
    * the lower end B had before 0.8.14, at the half tail: the lowest of the bootstrap's
      (both worlds) and max_i (|B_i| − c·u(B_i)), c the two-sided normal quantile at the
      Šidák-corrected half tail over the m targets. On an even reversal it lay 0.4–3.2 u
      below B. The simultaneous bound alone is not enough: its u(B_i) are the moderated
      σ's, which where σ changes along the axis are too small at the noisiest targets (a
      benchmark axis of 72 targets, σ 2–3 × the reversal: 6 of 40 tests missed below).

    A study with its own rig (even reversals, even with one target 2, 3 or 4 u above, a
    ramp, random from target to target, a single spike, the bundled sample's; 12, 36 and 72
    targets at 5 runs and 13 at 2 and 3; repeatability 0.1, 0.5, 1 and 2 × B; 20 tests a
    cell, 3200 tests, the study of #39): every cell within the binomial floor,
    pooled 99.6 %; on an even reversal the interval 2.1–2.9 times the width a correct one
    needs (up to 4.6 before), the median cell 2.0 times (2.18).

    Upper: max_i (|B_i| + z·u(B_i)), z the one-sided normal quantile at ``tail``. The target
    where the true reversal is largest is one fixed target, so its own bound, one-sided and
    with no correction for the m targets, holds at 1 − tail, and the largest of the m bounds
    is above it (the intersection-union bound, Berger 1982). The bootstrap's upper end is
    taken up to it: where the true reversal's largest value stands clear of the others, the
    worlds fitted to the readings (shrunk or not) put too many targets near it and their
    upper end fell short (a rough reversal at 72 targets, repeatability 0.1 × the signal:
    20–30 % of tests missed above). No adaptive upper end is narrower and holds an even
    reversal with one target 2–4 u above it, whose readings an even one gives too."""
    se = np.sqrt(sig_mean["up"] ** 2 / n["up"] + sig_mean["down"] ** 2 / n["down"])
    m = se.size
    half = 0.5 * tail
    per_target = 1.0 - (1.0 - half) ** (1.0 / m)
    c = float(ndtri(1.0 - 0.5 * per_target))
    signed = x["up"] - x["down"]
    reversal = np.abs(signed)
    simultaneous = float(np.max(reversal - c * se))
    # the mean reversal's variance from each target's own s (unbiased; the moderated σ
    # only where every s is 0), its degrees of freedom by Welch–Satterthwaite
    terms = np.concatenate([s["up"] ** 2 / n["up"], s["down"] ** 2 / n["down"]])
    nu = np.concatenate([n["up"] - 1.0, n["down"] - 1.0])
    if not np.sum(terms) > 0.0:
        terms = np.concatenate([sig_mean["up"] ** 2 / n["up"], sig_mean["down"] ** 2 / n["down"]])
    total = float(np.sum(terms))
    df = max(total**2 / float(np.sum(terms**2 / nu)), 1.0)
    mean_bound = abs(float(np.mean(signed))) - float(stdtrit(df, 1.0 - 0.5 * half)) * (
        math.sqrt(total) / m)
    return (mean_bound, simultaneous, float(np.max(reversal + float(ndtri(1.0 - tail)) * se)))


def _calibration_scores(drawn, pivots, n, shared, outer, inner, rng) -> dict[str, np.ndarray]:
    """The levels of the pivot's quantiles that make the interval cover at the probability
    asked for, by the iterated bootstrap (prepivoting, Beran 1987, Biometrika 74:457;
    Hall & Martin 1988): each outer test drawn from the world gets its own world and its
    own inner bootstrap; its pivot (its figure − the world's figure), standardised by its
    inner pivots' mean and standard deviation, is N(0, 1) when the interval is exact. The
    mean and the standard deviation of those standardised pivots over the outer tests (the
    normal form of the prepivot: two moments, steadier than its tail quantiles) give the
    levels that correct it (:func:`_calibrated_levels`): here each figure's standardised
    pivots over the outer tests."""
    scores: dict[str, list[np.ndarray]] = {}
    outer = min(outer, next(iter(pivots.values())).size)
    for start in range(0, outer, _CHUNK):
        sl = slice(start, min(start + _CHUNK, outer))
        means = {k: v[0][sl] for k, v in drawn.items()}
        sds = {k: v[1][sl] for k, v in drawn.items()}
        mu_o, sig_o, sig_mean_o = _world(means, sds, n, shared)
        truth_o = axis_figures({k: (mu_o[k], sig_o[k]) for k in mu_o})
        inner_draw = _draw({k: v[:, None, :] for k, v in mu_o.items()},
                           {k: v[:, None, :] for k, v in sig_o.items()},
                           {k: v[:, None, :] for k, v in sig_mean_o.items()},
                           n, shared, (sl.stop - sl.start, inner), rng)
        for key, sim in axis_figures(inner_draw).items():
            inner_pivot = sim - truth_o[key][:, None]
            centre = np.mean(inner_pivot, axis=1)
            spread = np.std(inner_pivot, axis=1, ddof=1)
            z = np.divide(pivots[key][sl] - centre, spread,
                          out=np.zeros_like(centre), where=spread > 0)
            scores.setdefault(key, []).append(z)
    return {key: np.concatenate(parts) for key, parts in scores.items()}


def _calibrated_levels(scores: dict[str, np.ndarray], tail: float
                       ) -> dict[str, tuple[float, float]]:
    """The levels of the pivot's quantiles, each side ``tail`` asked for, from the mean and
    the standard deviation of the standardised pivots (:func:`_calibration_scores`)."""
    z_tail = float(ndtri(1.0 - tail))
    levels = {}
    for key, z in scores.items():
        shift, scale = float(np.mean(z)), max(float(np.std(z, ddof=1)), 1.0)
        levels[key] = (float(ndtr(shift - z_tail * scale)), float(ndtr(shift + z_tail * scale)))
    return levels
