"""Harmonics the signals hold beyond the orders the model was asked to fit (a lack-of-fit
test on the residuals).

The interpolation error between the samples, and so the decided quantity over the whole
period, is the fitted model's. A model that leaves out a harmonic the signals hold (a 2nd
harmonic with the odd orders of the method's paper asked for, a 7th above the highest
order asked for) has the error at the sampled phases right and the curve through them
wrong: an audit found the decided quantity's interval covering 6–22 of 35 tests, every
miss an interval below or above the truth, with nothing said.

The test: each channel's residuals (reading − fitted model) are averaged per phase (the N
phases of equal steps, or :data:`PHASE_BINS` bins of a period along θ), and the orders
1 … :data:`TESTED_UP_TO` (as many as the phases resolve) are fitted to those means by
weighted least squares (weights: the readings a phase). An order not asked for is found
when the residual sum of squares it takes away, against the variance of one reading,
passes the F test at the level that keeps the risk of naming any order in a record whose
signals hold none at :data:`SIGNIFICANCE` (Šidák over the orders tested on both channels,
:func:`order_level`), and its amplitude is above the ADC's step: an ADC's rounding is the same at a
phase in every period, so the per-phase means keep it however many periods are averaged,
and it passed for harmonics (a 12-bit ADC with noise below its step: orders named in 10 of
10 records); but a rounding within ±δ/2 has no harmonic above δ (each amplitude is at most
the mean of |2 q| over the phases). The variance of a reading is the scatter within the phases when they hold
repeats (pure error, as the classical lack-of-fit test: Draper & Smith, Applied Regression
Analysis, 3rd ed., §2.1), else (one period, or repeats that came out alike) the residual
variance of the fit with every order tested.
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

import numpy as np

from models.fringe.model import ChannelFit, model_signal
from models.fringe.order_separation import separated_up_to
from models.fringe.order_statistics import distinct as _distinct

__all__ = ["PHASE_BINS", "SIGNIFICANCE", "TESTED_UP_TO", "UnmodelledHarmonic", "order_level",
           "quantisation_step", "unmodelled_harmonics"]

TWO_PI = 2.0 * math.pi

#: the highest order tested
TESTED_UP_TO = 16
#: the risk, a record, of naming an order its signals do not hold (over the orders tested on
#: both channels: :func:`order_level`); by simulation (tests/fringe_jitter_rig.py, the
#: audit's head with orders 1, 3, 5 only, 2000 records each of six designs) 0.05–0.2 % of
#: the records had one named (0.1–0.35 % with α / m a channel)
SIGNIFICANCE = 1e-3
#: bins of a period when the phases are not N equal steps
PHASE_BINS = 64
#: the least gaps between distinct readings the step is sought in, among the first readings
STEP_GAPS = 2000
STEP_SAMPLES = 50_000
#: the least degrees of freedom of the variance a test is made against
MIN_DOF = 10
#: an order whose amplitude is below this share of the channel's first harmonic is not
#: named, however clear it stands above the scatter: 1e-6 rad of phase at most (under
#: 0.0001" at 16384 lines), below what any ADC resolves; a record computed without noise
#: otherwise showed its rounding as an 11th harmonic
NEGLIGIBLE_SHARE = 1e-6


@dataclass(frozen=True)
class UnmodelledHarmonic:
    """An order the residuals of one channel hold: its amplitude (V) and that amplitude's
    standard uncertainty, and the test's p value."""

    order: int
    channel: str
    amplitude_v: float
    u_v: float
    p_value: float
    #: the orders looked at over the channels (the family :func:`order_level` is over)
    tested: int = 0


def order_level(tested: int) -> float:
    """The level each of ``tested`` orders (over both channels of a record) is tested at
    for a record whose signals hold none of them to have one named at a risk of
    :data:`SIGNIFICANCE` (Šidák: 1 − (1 − α)^(1/m); the F tests of one record are nearly
    independent, the orders' terms orthogonal over the phases). It was α / m a channel
    (Bonferroni), twice the risk a record; the warning said 0.1 % "each"."""
    if tested < 1:
        return 0.0
    return -math.expm1(math.log1p(-SIGNIFICANCE) / tested)


def f_survival_2(x: float, dof: float) -> float:
    """P(F > ``x``) for Fisher's F with 2 and ``dof`` degrees of freedom: the closed form
    (1 + 2x/ν)^(−ν/2) (the regularised incomplete beta I_z(ν/2, 1) = z^(ν/2)), what
    ``scipy.stats.f.sf(x, 2, dof)`` gives (to 1e-14 relative down to p = 1e-6, where the
    test decides; tests/models/fringe/test_unmodelled_harmonics.py) without importing
    scipy.stats, half a second of a command line's start-up."""
    if not x > 0.0:
        return 1.0 if x <= 0.0 else math.nan
    return math.exp(-0.5 * dof * math.log1p(2.0 * x / dof))


def quantisation_step(values) -> float:
    """The step the readings come in (an ADC's least significant bit, in the readings' unit):
    the greatest step of which the differences between distinct readings are whole
    multiples (Euclid's algorithm with a tolerance, on the least of them), when every reading
    is a whole number of it from the least; 0 when there is none above a 10⁻⁹ of their span
    (a record with the digits of its noise)."""
    distinct = _distinct(np.asarray(values, dtype=float))
    if distinct.size < 3:
        return 0.0
    span = float(distinct[-1] - distinct[0])
    gaps = np.diff(distinct)
    gaps = np.partition(gaps, min(STEP_GAPS, gaps.size) - 1)[:STEP_GAPS]
    step = float(np.min(gaps))
    for _ in range(60):
        if not step > 1e-9 * span:
            return 0.0
        rest = np.mod(gaps, step)
        rest = np.minimum(rest, step - rest)
        beyond = rest[rest > 1e-3 * step]
        if beyond.size == 0:
            break
        step = float(np.min(beyond))
    else:
        return 0.0
    whole = (distinct - distinct[0]) / step
    return step if float(np.max(np.abs(whole - np.rint(whole)))) < 0.01 else 0.0


def _phase_means(theta: np.ndarray, residual: np.ndarray, index: np.ndarray | None,
                 per_period: int):
    """(phase of each non-empty bin, its count, its mean residual, the within-bin sum of
    squares)."""
    if index is None:
        phase = np.mod(theta, TWO_PI)
        index = np.minimum((phase * (PHASE_BINS / TWO_PI)).astype(np.intp), PHASE_BINS - 1)
        bins = PHASE_BINS
        phase_sum = np.bincount(index, phase, bins)
    else:
        bins = per_period
        phase_sum = None
    count = np.bincount(index, minlength=bins).astype(float)
    total = np.bincount(index, residual, bins)
    full = count > 0
    means = np.zeros(bins)
    means[full] = total[full] / count[full]
    mean = means[full]
    # about each bin's own mean (not Σr² − n·mean², whose rounding passed for a scatter in a
    # record without noise, against which every order stood out)
    within = float(np.sum((residual - means[index]) ** 2))
    at = (np.flatnonzero(full) * (TWO_PI / bins) if phase_sum is None
          else phase_sum[full] / count[full])
    return at, count[full], mean, within


#: a design whose condition number exceeds this resolves its orders no better than the
#: readings' digits (1e8: 1e-8 of a volt-sized signal, below any ADC's step)
MAX_CONDITION = 1e8


def _ill_conditioned(x: np.ndarray) -> bool:
    """Whether the columns of ``x`` are (nearly) dependent: its condition number above
    :data:`MAX_CONDITION`, or fewer rows than columns."""
    if x.shape[0] < x.shape[1]:
        return True
    return not float(np.linalg.cond(x)) <= MAX_CONDITION


def _design(phase: np.ndarray, orders) -> np.ndarray:
    columns = [np.ones_like(phase)]
    for k in orders:
        columns += [np.cos(k * phase), np.sin(k * phase)]
    return np.column_stack(columns)


def _rss(x: np.ndarray, y: np.ndarray, w: np.ndarray) -> tuple[float, np.ndarray]:
    root = np.sqrt(w)
    coef, *_ = np.linalg.lstsq(x * root[:, None], y * root, rcond=None)
    r = y - x @ coef
    return float(np.sum(w * r * r)), coef


def unmodelled_harmonics(theta_rad, channels: dict[str, tuple[np.ndarray, ChannelFit]],
                         phase_index: np.ndarray | None = None, samples_per_period: int = 0,
                         stated_step: float = 0.0, phase_u_rad: float = 0.0
                         ) -> list[UnmodelledHarmonic]:
    """The orders, not among the fitted ones, that a channel's residuals hold (see the
    module's note); ``channels`` maps a name to (readings, fit) at the phases ``theta_rad``;
    ``phase_index`` (with ``samples_per_period``) when the phases are N equal steps;
    ``stated_step``: the ADC's step as stated (the larger of it and the step the readings
    come in bounds what its rounding can show). Empty
    when the phases cannot resolve an order beyond the fitted ones with a variance of at
    least :data:`MIN_DOF` degrees of freedom. Only orders the sample phases tell apart from
    every lower one are tested (:func:`~models.fringe.order_separation.separated_up_to`,
    ``phase_u_rad`` the phases' noise): a θ column jittered about 16 steps a period, its
    phases split between bins, had order 15 (order 1's alias) "found" in 11 of 20 records,
    by the jitter alone."""
    theta = np.asarray(theta_rad, dtype=float)
    candidates: list[UnmodelledHarmonic] = []
    looked_at = 0  # orders tested, over both channels
    if phase_index is not None:  # N equal steps: the N phases, weighted by their samples
        separable = separated_up_to(
            np.arange(samples_per_period) * (TWO_PI / samples_per_period), TESTED_UP_TO,
            phase_u_rad, np.bincount(phase_index, minlength=samples_per_period).astype(float))
    else:
        separable = separated_up_to(theta, TESTED_UP_TO, phase_u_rad)
    for name, (readings, fit) in channels.items():
        values = np.asarray(readings, dtype=float)
        step = max(stated_step, quantisation_step(values[:STEP_SAMPLES]))
        if phase_index is not None:  # the model is one value a phase: the readings' means
            # and scatter per phase, the model taken at the N phases only (a million samples:
            # no million-long model)
            at, count, mean, within = _phase_means(theta, values, phase_index,
                                                   samples_per_period)
            mean = mean - model_signal(at, fit)
        else:
            at, count, mean, within = _phase_means(theta, values - model_signal(theta, fit),
                                                   None, 0)
        phases = at.size
        # orders the phases resolve without aliasing, leaving a variance to test against
        top = min(TESTED_UP_TO, (phases - 1) // 2, separable)
        dof_within = theta.size - phases
        pure = dof_within >= MIN_DOF and within > 0.0  # repeats that scatter
        if not pure:
            top = min(top, (phases - 1 - MIN_DOF) // 2)
        # phases that only look distinct (0 and 2π − 1e-15 in bins of their own, a θ column
        # jittered about N steps) resolve no more orders than the N steps: the design's
        # conditioning says how many (at 4 steps a period, order 2 was "heard" at 6e13 mV)
        while top >= 1 and _ill_conditioned(_design(at, range(1, top + 1)) * np.sqrt(
                count)[:, None]):
            top -= 1
        tested = [k for k in range(1, top + 1) if k not in fit.orders]
        if not tested:
            continue
        every = sorted(set(range(1, top + 1)) | set(o for o in fit.orders if o <= top))
        x_full = _design(at, every)
        rss_full, coef = _rss(x_full, mean, count)
        if pure:
            variance, dof = within / dof_within, dof_within
        else:
            dof = phases - x_full.shape[1]
            variance = rss_full / dof
        if not variance > 0.0:
            continue
        # the residual sum of squares that leaving order k out adds: β_kᵀ (V_kk)⁻¹ β_k, V the
        # inverse of the weighted normal matrix (the same as refitting without the order)
        inverse = np.linalg.pinv((x_full * count[:, None]).T @ x_full)
        for k in tested:
            j = 1 + 2 * every.index(k)
            beta = coef[j:j + 2]
            added = float(beta @ np.linalg.solve(inverse[j:j + 2, j:j + 2], beta))
            statistic = max(added, 0.0) / 2.0 / variance
            p = f_survival_2(statistic, dof)
            amplitude = float(math.hypot(coef[j], coef[j + 1]))
            looked_at += 1
            if amplitude > max(step, NEGLIGIBLE_SHARE * float(fit.amplitude[1])):
                # the amplitude's standard uncertainty from the fit's covariance, along the
                # amplitude's direction (where the phases spread evenly: a reading's
                # variance over half the readings)
                along = beta / amplitude if amplitude > 0.0 else np.array([1.0, 0.0])
                u = math.sqrt(variance * max(float(along @ inverse[j:j + 2, j:j + 2] @ along),
                                             0.0))
                candidates.append(UnmodelledHarmonic(k, name, amplitude, u, p))
    level = order_level(looked_at)
    return [dataclasses.replace(h, tested=looked_at) for h in candidates if h.p_value < level]
