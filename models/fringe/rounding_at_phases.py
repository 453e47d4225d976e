"""The readings' rounding in the fitted signal parameters: the ADC's step (or, none stated, the
step the readings come in: the last digit typed), a rectangular error of ±δ/2 a reading, and
how much of it the fit's scatter does not show.

The least-squares covariance (:class:`ChannelFit`'s ``u_*``) takes every reading's error as
independent, so it averages the rounding over all n readings. That holds while the noise
dithers the rounding (σ above about δ/2: the rounding error is then random from reading to
reading). Below that the reading of a phase rounds alike in every period, so a record of
whole periods sampled at N equal steps repeats the same N rounding errors, and averaging
over the periods removes none of them: a first-principles study
(tests/benchmarks/fringe_rounding_study.py: N = 8–64, 10 periods, σ = 0) found the
parameters' U covering 39–54 % of 1000 records (the worst parameter 33–39 %), 70–77 % at
σ = δ/10, 93–94 % at δ/4; an audit's rig (σ = 0.33 δ with a clock's jitter) cos c3 1883 and
sin c5 1885 of 2000 at 95.45 %.

The rounding error of a reading x + noise is e = Q(x + n) − x − n; its mean at x over the
noise, b(x), is the part repeated at a phase. For normal noise σ, b is the sawtooth's Fourier
series with each term damped by the noise: b(x) = Σₘ (−1)ᵐ (δ/πm) sin(2πmx/δ) e^(−2π²m²σ²/δ²),
so over phases whose signal falls anywhere within a step its variance is

    v(σ) = δ²/(2π²) Σₘ e^(−4π²m²σ²/δ²) / m²     (δ²/12 at σ = 0, 5 % of it at δ/4, 3·10⁻⁵ of it at δ/2)

The readings repeated at a phase show the rest: their scatter about the phase's mean (pure
error) has the variance w = σ² + δ²/12 − v(σ) (σ² + δ²/12 when dithered: Sheppard), which
rises with σ, so σ, and v with it, is found from w; from its one-sided 84 % lower bound
(Wilson–Hilferty), so that a w that came out large by chance does not take the repeated
part for dithered. Without repeats (one period, or a θ column's phases all distinct) the
rounding of each reading is its own and the fit's scatter holds it.

With b independent from phase to phase (the signal at each phase anywhere within a step),
the parameters' covariance from the repeated part is v·(XᵀX)⁻¹(Σⱼ cⱼ² xⱼxⱼᵀ)(XᵀX)⁻¹ (xⱼ the
design at distinct phase j, cⱼ its readings; X the whole record's design), of which the fit's
scatter shows v·(XᵀX)⁻¹: the rest is added (:attr:`RoundingAtPhases.cases`). With N equal
steps over P periods that is (1 − 1/P)·v·(XₙᵀXₙ)⁻¹, the rounding averaged over the N phases
only. Two things bend that independence, each taken on the safe side: readings half a period
apart mirror each other about the offset where the signal has odd harmonics only, and so do
their roundings (:func:`mirrored_correlation`: up to twice the variance of every odd order,
or 1.5 times the offset's, by where twice the offset falls on the steps, which the offset's
own u leaves open); and the rounding's pattern follows the signal's own shape
(:data:`REPEATED_MARGIN`).

And the fit's scatter cannot show what falls in the model itself: readings typed to four
decimals from a noise-free signal, whose rounding the fitted harmonics take up whole, left a
residual of 10⁻¹⁷ V and printed "± 0.000000000000000023 V". The rounding alone, δ²/12 a
reading, v of it repeated at the phases, is a floor under each parameter's variance
(the second of each pair in :attr:`RoundingAtPhases.cases`; GUM F.2.2.1: the resolution is
an input of its own).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from models.fringe.model import ChannelFit, fit_design
from models.fringe.unmodelled_harmonics import quantisation_step
from models.readings.resolution import readings_step

__all__ = ["REPEATED_MARGIN", "PhaseGroups", "RoundingAtPhases", "mirrored_correlation",
           "parameter_variances", "phase_groups", "readings_resolution", "repeated_bound",
           "repeated_variance", "rounding_at_phases", "within_phase_variance"]

TWO_PI = 2.0 * math.pi

#: the terms of the sawtooth's series summed (the rest below 0.3 % of δ²/12 at σ = 0, and
#: nothing beyond m ≈ 20 once σ ≥ δ/20)
_TERMS = np.arange(1, 201, dtype=float)
#: the one-sided normal quantile of the lower bound on the within-phase variance (84 %:
#: v(σ) is steep; at N = 8, σ = δ/4 the median U/oracle was 1.51 with the 95 % bound, 1.39
#: with this one, 1.21 with none, which leaves a w of few degrees of freedom that came out
#: large taking the repeated part for dithered)
_LOWER_Z = 1.0
#: the repeated rounding's variance is taken this many times v(σ): its pattern over the
#: phases is the sawtooth of the signal itself, not quite independent from phase to phase
#: (4000 draws of the start phase at N = 32, 2A₀ a whole number of steps: the variance of
#: an odd order's coefficient 0.90–1.10 of the model's; the rig's N = 32 cell, 500 records:
#: sin A3, cos A5 at 1.18–1.2 of it, covered 92–93 %)
REPEATED_MARGIN = 1.25


def repeated_variance(sigma: float, step: float) -> float:
    """v(σ): the variance over the phases of the rounding's mean at a phase (V²), for normal
    noise ``sigma`` and the step ``step`` (δ²/12 at σ = 0)."""
    if not step > 0.0:
        return 0.0
    if not sigma > 0.0:
        return step * step / 12.0
    damped = np.exp(-4.0 * math.pi ** 2 * (sigma / step) ** 2 * _TERMS ** 2)
    return float(step * step / (2.0 * math.pi ** 2) * np.sum(damped / _TERMS ** 2))


def repeated_bound(sigma: float, step: float) -> float:
    """The bound of the rounding's mean at a phase, max |b(x)| (V): δ/2 at σ = 0 (and where
    σ is not known, NaN), as an ADC's LSB stated, falling as the noise ``sigma`` dithers the
    step ``step`` (0.15 δ at σ = δ/5, 10⁻⁸ δ at σ = δ). The series is capped at δ/2, which
    b, a sawtooth smoothed by the noise, never exceeds (its partial sums overshoot by
    Gibbs' 9 % where σ is below about δ/100)."""
    if not step > 0.0:
        return 0.0
    if not sigma > 0.0:  # undithered, or not known: the whole half step
        return 0.5 * step
    damped = (np.exp(-2.0 * math.pi ** 2 * (sigma / step) ** 2 * _TERMS ** 2)
              * np.where(_TERMS % 2, -1.0, 1.0) / (math.pi * _TERMS))
    where = np.linspace(0.0, 1.0, 2049)  # x/δ over one step
    mean_at = np.sin(TWO_PI * np.outer(where, _TERMS)) @ damped
    return float(min(step * np.max(np.abs(mean_at)), 0.5 * step))


def _noise_from_scatter(w: float, step: float) -> float:
    """σ whose rounded readings scatter about their phase's mean by the variance ``w``:
    the root of σ² + δ²/12 − v(σ) = w (increasing in σ, 0 at σ = 0)."""
    if not w > 0.0:
        return 0.0
    low, high = 0.0, math.sqrt(w)  # (δ²/12 − v(σ) ≥ 0, so σ² ≤ w)
    for _ in range(40):
        mid = 0.5 * (low + high)
        if mid * mid + step * step / 12.0 - repeated_variance(mid, step) < w:
            low = mid
        else:
            high = mid
    return 0.5 * (low + high)


def within_phase_variance(index: np.ndarray, phases: int, values: np.ndarray
                          ) -> tuple[float, int]:
    """(pooled variance of the readings about their phase's mean, its degrees of freedom):
    ``index`` the distinct phase of each reading, 0 … ``phases`` − 1; (NaN, 0) when no phase
    holds two readings."""
    counts = np.bincount(index, minlength=phases).astype(float)
    dof = int(values.size - np.count_nonzero(counts))
    if dof < 1:
        return math.nan, 0
    held = counts > 0
    centre = np.bincount(index, weights=values, minlength=phases)[held] / counts[held]
    means = np.zeros(phases)
    means[held] = centre
    deviation = values - means[index]
    return float(deviation @ deviation) / dof, dof


def _lower_bound(w: float, dof: int) -> float:
    """The one-sided 95 % lower bound of a variance ``w`` of ``dof`` degrees of freedom
    (Wilson–Hilferty's cube-root normal form of χ²)."""
    a = 2.0 / (9.0 * dof)
    return w * max(1.0 - a - _LOWER_Z * math.sqrt(a), 0.0) ** 3


def mirrored_correlation(offset_v, sigma: float, step: float) -> np.ndarray:
    """ρ: the correlation of the rounding's mean at readings x and 2·A₀ − x (``offset_v``
    A₀, V, an array of them), the readings half a period apart of a signal with odd
    harmonics only: −R(2A₀)/v, R(τ) = δ²/(2π²) Σₘ e^(−4π²m²σ²/δ²) cos(2πmτ/δ)/m² (−1 where
    2A₀ is a whole number of steps, +½ half-way between)."""
    offsets = np.atleast_1d(np.asarray(offset_v, dtype=float))
    if not step > 0.0:
        return np.zeros(offsets.shape)
    damped = np.exp(-4.0 * math.pi ** 2 * (sigma / step) ** 2 * _TERMS ** 2) / _TERMS ** 2
    total = float(np.sum(damped))
    if not total > 0.0:  # dithered through: nothing repeats, nothing correlates
        return np.zeros(offsets.shape)
    waves = np.cos(TWO_PI * np.outer(2.0 * offsets / step, _TERMS))
    return -(waves @ damped) / total


@dataclass(frozen=True)
class RoundingAtPhases:
    """One channel's rounding and its part in the fitted parameters (V, V²; the covariance
    matrices over the fit's coefficients 1, sin kθ, cos kθ …), one pair (excess, floor) for
    each correlation of the readings half a period apart the offset allows: a parameter's
    variance is the largest they give."""

    step_v: float  # δ: the ADC's step stated, else the step the readings come in (0: none)
    step_stated: bool
    noise_v: float  # σ the scatter at repeated phases shows (NaN: no phase repeated)
    repeated_v2: float  # v(σ): the rounding's variance repeated at each phase
    #: (what the repeated rounding adds beyond the fit's scatter, the rounding's own
    #: covariance: its diagonal a floor under the u²), for each correlation ρ considered
    cases: tuple[tuple[np.ndarray, np.ndarray], ...]
    correlations: tuple[float, ...] = (0.0,)
    #: a floor as a multiple of the fit's own variances (phases that do not repeat: the
    #: rounding's δ²/12 against the fit's s²; 0 where the cases hold it)
    fit_floor: float = 0.0


def readings_resolution(values) -> float:
    """The step the readings come in (V; 0: none): the last digit typed
    (:func:`models.readings.resolution.readings_step`, readings of at most six decimals),
    else an ADC's step in readings converted to volts with more digits
    (:func:`models.fringe.unmodelled_harmonics.quantisation_step`)."""
    typed = readings_step(values)
    return float(typed) if typed else quantisation_step(values)


@dataclass
class PhaseGroups:
    """The distinct phases of a record: each reading's (``index``, 0 … J − 1), the J phases
    (rad, in [0, 2π)) and the readings at each (``counts``); with N equal steps the step's
    index, else the phases as analysed folded into one period (to 10⁻¹⁰ rad). Shared by
    the two channels, with the design at the phases and its normal matrix's inverse."""

    index: np.ndarray
    phases: np.ndarray
    counts: np.ndarray
    #: whether the phases repeat: N equal steps, or a θ column with two readings a phase
    #: or more on average (not the odd coincidence of two phases to 10⁻¹⁰ rad)
    repeats: bool
    _designs: dict = field(default_factory=dict, repr=False)

    def design(self, orders: tuple[int, ...]) -> tuple[np.ndarray, np.ndarray]:
        """(the design at the distinct phases, (XᵀX)⁻¹ of the whole record's design)."""
        if orders not in self._designs:
            x = fit_design(self.phases, orders)
            self._designs[orders] = (x, _inverse(x.T @ (x * self.counts[:, None])))
        return self._designs[orders]


def phase_groups(theta_rad, per_period: int = 0) -> PhaseGroups:
    """The distinct phases of the readings at ``theta_rad`` (N = ``per_period`` equal steps,
    or 0)."""
    theta = np.asarray(theta_rad, dtype=float)
    if per_period:
        index = np.rint(theta / (TWO_PI / per_period)).astype(np.intp) % per_period
        phases = np.arange(per_period) * (TWO_PI / per_period)
    else:
        folded = np.round(np.mod(theta, TWO_PI), 10) % round(TWO_PI, 10)
        phases, index = np.unique(folded, return_inverse=True)
        index = index.astype(np.intp)
    counts = np.bincount(index, minlength=phases.size).astype(float)
    return PhaseGroups(index, phases, counts, bool(per_period) or 2 * phases.size <= theta.size)


def _inverse(gram: np.ndarray) -> np.ndarray:
    try:
        return np.linalg.inv(gram)
    except np.linalg.LinAlgError:
        return np.linalg.pinv(gram)


def _mirrors(phases: np.ndarray) -> np.ndarray | None:
    """Each distinct phase's partner half a period on (its index), None unless every phase
    (rad, sorted, in [0, 2π)) has one (N even equal steps, or a θ column that repeats them)."""
    if phases.size < 2 or phases.size % 2:
        return None
    opposite = np.mod(phases + math.pi, TWO_PI)
    where = np.clip(np.searchsorted(phases, opposite), 0, phases.size - 1)
    below = np.clip(where - 1, 0, phases.size - 1)
    nearest = np.where(np.abs(phases[below] - opposite) < np.abs(phases[where] - opposite),
                       below, where)
    gap = np.abs(phases[nearest] - opposite)
    gap = np.minimum(gap, TWO_PI - gap)
    return nearest if bool(np.all(gap < 1e-9)) else None


def rounding_at_phases(theta_rad, values, orders: tuple[int, ...], per_period: int = 0,
                       stated_step_v: float = 0.0, offset_v: float = math.nan,
                       u_offset_v: float = 0.0, residual_variance: float = 0.0,
                       groups: PhaseGroups | None = None) -> RoundingAtPhases:
    """The rounding of one channel's readings ``values`` at the phases ``theta_rad`` (N =
    ``per_period`` equal steps, or 0; ``groups`` their :func:`phase_groups` if known) in the
    parameters of the orders ``orders``: δ the step ``stated_step_v`` (the ADC's LSB), else
    the step the readings come in; nothing (zero matrices) where there is none.

    With phases half a period apart (N even) and odd orders only, the readings there mirror
    each other about the offset (x and 2A₀ − x), and so do their roundings' means, with a
    correlation ρ set by where 2A₀ falls on the steps (:func:`mirrored_correlation`): −1
    doubles the variance of every odd order's coefficients and cancels the offset's, +½
    the reverse. ρ is taken over the fitted offset ``offset_v`` ± 2 u (u from the fit's
    ``u_offset_v`` and the repeated rounding; the offset itself is off by that much) and 0
    (where even harmonics the model leaves out break the mirror), each parameter at its
    worst.

    A θ column whose phases do not repeat: the floor is δ²/12 a reading over the fit's own
    design, that is the fit's variances times (δ²/12)/s², ``residual_variance`` the fit's s²
    (:attr:`RoundingAtPhases.fit_floor`; the design of a million phases is not made again)."""
    y = np.asarray(values, dtype=float)
    p = 1 + 2 * len(orders)
    stated = bool(stated_step_v and stated_step_v > 0.0)
    step = float(stated_step_v) if stated else readings_resolution(y)
    zero = np.zeros((p, p))
    if not step > 0.0 or y.size <= p:
        return RoundingAtPhases(step, stated, math.nan, 0.0, ((zero, zero),))
    groups = groups if groups is not None else phase_groups(theta_rad, per_period)
    if not groups.repeats and residual_variance > 0.0:
        return RoundingAtPhases(step, stated, math.nan, step * step / 12.0, ((zero, zero),),
                                fit_floor=REPEATED_MARGIN * step * step / 12.0
                                / residual_variance)
    x, inv = groups.design(orders)
    counts = groups.counts
    w, dof = (within_phase_variance(groups.index, groups.phases.size, y) if groups.repeats
              else (math.nan, 0))
    if dof:
        sigma = _noise_from_scatter(_lower_bound(w, dof), step)
        repeated = repeated_variance(sigma, step)
    else:  # each reading its own phase: the fit's scatter holds its rounding, and only
        # the rounding's own floor is added, as if not dithered (σ unknown)
        sigma, repeated = math.nan, step * step / 12.0
    weighted = x * counts[:, None]  # cⱼ xⱼ
    mirror = _mirrors(groups.phases)
    correlations = [0.0]
    if mirror is not None and all(k % 2 for k in orders) and math.isfinite(offset_v):
        # the offset's own u: the fit's and the repeated rounding's (at most 1.5 v: ρ ≤ ½)
        averaged = float((inv @ (weighted.T @ weighted) @ inv)[0, 0])
        u_offset = math.sqrt((u_offset_v if math.isfinite(u_offset_v) else step) ** 2
                             + 1.5 * REPEATED_MARGIN * repeated * averaged)
        around = offset_v + np.linspace(-2.0 * u_offset, 2.0 * u_offset, 65)
        rhos = mirrored_correlation(around, 0.0 if math.isnan(sigma) else sigma, step)
        correlations += [float(np.min(rhos)), float(np.max(rhos))]
    cases = []
    for rho in correlations:
        shared = weighted.T @ weighted
        if rho:
            shared = shared + rho * (weighted.T @ weighted[mirror])
        spread_m = inv @ shared @ inv  # (XᵀX)⁻¹ Σ cⱼcₗ Cov(bⱼ, bₗ)/v xⱼxₗᵀ (XᵀX)⁻¹
        excess = repeated * (REPEATED_MARGIN * spread_m - inv) if dof else zero
        floor = (REPEATED_MARGIN * repeated * spread_m
                 + (step * step / 12.0 - repeated) * inv)
        cases.append((excess, floor))
    return RoundingAtPhases(step, stated, sigma, repeated, tuple(cases), tuple(correlations))


def parameter_variances(fit: ChannelFit, covariance: np.ndarray) -> dict[str, float]:
    """The variances a covariance of the fit's coefficients (1, sin kθ, cos kθ …) gives its
    parameters: {"A0", "A1", "c1", …} (V², rad²), linearised as the fit's own."""
    out = {"A0": float(covariance[0, 0])}
    for i, k in enumerate(fit.orders):
        amplitude, phase = fit.amplitude[k], fit.phase[k]
        s, c = amplitude * math.cos(phase), amplitude * math.sin(phase)
        v_ss = covariance[1 + 2 * i, 1 + 2 * i]
        v_sc = covariance[1 + 2 * i, 2 + 2 * i]
        v_cc = covariance[2 + 2 * i, 2 + 2 * i]
        if amplitude > 0:  # gradients of the amplitude (s, c)/A and of the phase (−c, s)/A²
            out[f"A{k}"] = max(float(s * s * v_ss + 2 * s * c * v_sc + c * c * v_cc)
                               / amplitude ** 2, 0.0)
            out[f"c{k}"] = max(float(c * c * v_ss - 2 * s * c * v_sc + s * s * v_cc)
                               / amplitude ** 4, 0.0)
        else:
            out[f"A{k}"], out[f"c{k}"] = max(float(v_ss), 0.0), math.inf
    return out
