"""A phase reference's per-sample errors carried through the fit to the fitted curve, counted
once with the readings' scatter.

The decided half range is the half peak-to-peak of the fitted model's error curve
atan2(S, C) − θ over the whole period (models.fringe.report.model_error_curve). A reference
whose error δ_i at each sample is independent from sample to sample (a standard stated per
reading, the sampling's timing) moves each reading as a phase error would:
u_s(θ_i + δ_i) ≈ S(θ_i) + S'(θ_i) δ_i, and the same δ_i in the cos channel through C'(θ_i).
The least-squares fit takes these as it takes noise: the parameters move by
β_s = (XᵀX)⁻¹ Xᵀ (S' ∘ δ) and β_c = (XᵀX)⁻¹ Xᵀ (C' ∘ δ), correlated between the channels
(one δ for both), and the curve's phase at θ by C/R² · x(θ)ᵀβ_s − S/R² · x(θ)ᵀβ_c.

With δ independent, of standard uncertainty u, the joint covariance of (β_s, β_c) is u²
times the 2p × 2p matrix [[A Aᵀ, A Bᵀ], [B Aᵀ, B Bᵀ]] (A = (XᵀX)⁻¹ Xᵀ diag(S'), B the
same with C'), worked out in O(n p²) without forming A. Its eigenvectors, each scaled by
the root of its eigenvalue, carried to the curve, are the independent directions a draw
of the reference's errors moves the curve in (one value each per trial, as the fitted
parameters' own directions, :func:`models.fringe.model.model_signal_modes`). A δ the same at
every sample (a common shift) moves the curve by δ everywhere and cancels in the half
range; independent ones do not: their share of the curve is about u·√(2p/n), not 0 (the
assessment 76 M3: a per-sample u of 0.001″ to 2″ stated left the decided interval
unchanged, "pass" every time).

Counted once (issue 39: every budget input once). Where the reference's errors are really
in the readings they also show in each channel's residual scatter: the fit's σ̂² holds their
share, E[σ̂²] = σ_n² + u²·m, m = Σ (1 − hᵢ)·S′ᵢ² / (n − p) (hᵢ the leverage of sample i;
:mod:`models.fringe.sampling_phase_noise`). The fit's own directions are then drawn with
the scatter beyond that share only, σ² = max(0, σ̂² − u²·m), and the reference's with its
stated u through its own directions: the readings' errors per sample are taken as the
larger of what the scatter shows and what the stated u implies, never their sum
(:func:`scatter_beyond_reference`), as a least-squares fit's stated uncertainties are scaled
up by the Birge ratio where the scatter exceeds them and never down (R. T. Birge, Phys. Rev.
40 (1932) 207; the Particle Data Group's scale factor S = max(1, √(χ²/ν)), Review of
Particle Physics, Introduction 5.2). Before, the two were summed: a simulation with the
reference's errors of the stated 0.2" in the readings had its interval twice the width a
correct one needs (0.118" against 0.061", 200 of 200 covered where 194 of 200 were).

What repeats at a phase in every period (a reference's error systematic at each sample
phase, not independent from sample to sample) is not averaged by the periods: with the
phases repeated, what the readings show is also taken from the phase means' scatter about
the fit, Σⱼ cⱼ·r̄ⱼ² / (J − p) (cⱼ readings at phase j, J phases: the lack-of-fit mean square
with the phases as the units, Draper & Smith, *Applied Regression Analysis*, 3rd ed., 2.1),
which an error repeated at every phase raises by the number of periods and independent
errors do not; taken where the lack-of-fit F test finds it larger at 95 % (else pooled), and
only with a reference stated (none stated, the fit's scatter is taken as it was). Where the
readings show the reference's share (else what repeats is not its errors, and the stated u
stays an envelope of independent ones), the reference's errors are then taken as repeated
too, the same at a phase in every period (each phase's cⱼ readings moving together: its
directions √cⱼ times larger), and its share of the phase means' scatter,
u²·Σ cⱼ(1 − hⱼ)·S′ⱼ² / (J − p), counted once as above.

Where the readings show the reference's share (:attr:`ChannelScatter.holds_reference`) its
directions are drawn as the fit's own are, noise the readings hold (their excess on the
range taken out); where they show less, the stated u is an envelope the errors may be
below, and the decided interval is also held with them at zero
(:attr:`models.uncertainty.budget.BudgetComponent.in_readings`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.fringe.model import fit_design, model_signal, model_slope
from models.fringe.rounding_at_phases import phase_groups

#: the phase means' scatter is taken for the readings' where the lack-of-fit F test finds it
#: larger at this level (Draper & Smith 2.1: pooled where the lack of fit is not significant)
LACK_OF_FIT_LEVEL = 0.95

__all__ = ["ChannelScatter", "reading_scatter_beyond", "reference_curve_modes",
           "scatter_beyond_reference"]


def reference_curve_modes(result, theta_rad: np.ndarray, repeated: bool = False) -> np.ndarray:
    """(len(theta_rad), 2p) changes of the fitted model's phase error at ``theta_rad`` per
    unit standard uncertainty of an independent per-sample phase error of the reference (a
    draw ξ ~ N(0, I) gives the curve's change u · (modes @ ξ), in u's unit), one column per
    independent direction. ``repeated``: the error the same at a phase in every period
    (one value a distinct phase, :func:`models.fringe.rounding_at_phases.phase_groups`),
    independent from phase to phase: each phase's cⱼ readings move together, cⱼ² in place
    of cⱼ (the periods do not average it)."""
    theta_fit = np.asarray(result.theta_rad, dtype=float)
    fits = (result.sin_fit, result.cos_fit)
    weights = np.ones(theta_fit.size)
    at = theta_fit
    if repeated:
        groups = _groups(result)
        at, weights = groups.phases, groups.counts ** 2
    designs = [fit_design(theta_fit, fit.orders) for fit in fits]
    inverses = [np.linalg.pinv(x.T @ x) for x in designs]
    designs = [fit_design(at, fit.orders) for fit in fits]
    slopes = [model_slope(at, fit) for fit in fits]
    # A Aᵀ, A Bᵀ, B Bᵀ: (XᵀX)⁻¹ Xᵀ diag(a b) X (XᵀX)⁻¹
    blocks = [[inverses[i] @ ((designs[i] * (weights * slopes[i] * slopes[j])[:, None]).T
                              @ designs[j]) @ inverses[j] for j in range(2)] for i in range(2)]
    joint = np.block(blocks)
    values, vectors = np.linalg.eigh(0.5 * (joint + joint.T))
    scaled = vectors * np.sqrt(np.clip(values, 0.0, None))
    theta = np.asarray(theta_rad, dtype=float)
    s, c = model_signal(theta, fits[0]), model_signal(theta, fits[1])
    r2 = s**2 + c**2
    along = np.hstack([(c / r2)[:, None] * fit_design(theta, fits[0].orders),
                       (-s / r2)[:, None] * fit_design(theta, fits[1].orders)])
    return along @ scaled


def _groups(result):
    per_period = result.samples_per_period if result.phase_source == "samples_per_period" \
        else 0
    return phase_groups(np.asarray(result.theta_rad, dtype=float), per_period)


@dataclass(frozen=True)
class ChannelScatter:
    """One channel's per-sample scatter (V) for the fit's own directions."""

    sigma_v: float  # what the fit's directions are drawn with: the scatter beyond the reference
    dof: int  # of the scatter shown (n − p, or J − p from the phase means)
    shown_v: float  # what the readings show: the larger of all readings' and phase means'
    reference_v: float  # what the stated reference's errors alone would show there: u·√m
    #: the phase means' scatter taken (larger beyond chance): what repeats at a phase in
    #: every period, the reference's errors taken as repeated too (reference_curve_modes)
    repeated: bool = False

    @property
    def holds_reference(self) -> bool:
        """Whether the readings show the stated reference's share: their scatter's variance
        not below it by more than twice its own relative standard deviation √(2/ν) (an
        estimate of ν degrees of freedom). Shown, the reference's errors are in the
        readings and bias their range as noise does; not shown, the reference is better
        than stated (a stated figure is an envelope) and its errors may not be there."""
        return _shows(self.shown_v ** 2, self.reference_v ** 2, self.dof)


def _shows(shown2: float, reference2: float, dof: int) -> bool:
    """Whether a scatter's variance ``shown2`` (of ``dof`` degrees of freedom) is not below
    ``reference2`` by more than twice its own relative standard deviation √(2/ν)."""
    return shown2 >= reference2 * (1.0 - 2.0 * math.sqrt(2.0 / max(dof, 1)))


def _reference_share2(theta: np.ndarray, fit, u_rad: float) -> float:
    """What independent per-sample phase errors of ``u_rad`` add to a channel's residual
    variance (V²): u²·Σ (1 − hᵢ)·S′ᵢ² / (n − p), hᵢ the leverage of sample i."""
    n, p = theta.size, 1 + 2 * len(fit.orders)
    if not (u_rad > 0.0 and math.isfinite(u_rad) and n > p):
        return 0.0
    x = fit_design(theta, fit.orders)
    leverage = np.einsum("ij,jk,ik->i", x, np.linalg.pinv(x.T @ x), x)
    return u_rad ** 2 * float(np.sum((1.0 - leverage) * model_slope(theta, fit) ** 2)) / (n - p)


def reading_scatter_beyond(result, u_rad: float, quantisation_v: float = 0.0
                           ) -> tuple[ChannelScatter, ChannelScatter]:
    """(sin, cos): each channel's scatter of one reading (every reading about the fit, n − p
    degrees of freedom) beyond what the stated inputs the readings hold show there, for a
    sample's own U: the phase reference's independent per-sample errors of standard
    uncertainty ``u_rad`` (rad of a signal period; 0: none stated, or not in the readings:
    an estimated phase follows them), their share u²·m, and the ADC's quantisation of
    standard uncertainty ``quantisation_v`` (V, LSB/√12: each reading's own rounding, in
    its residual as in its error), each entered as an input of its own. The readings'
    errors per sample are so the larger of what the scatter shows and what the stated
    inputs imply, never the scatter and the stated inputs summed (an input in the readings
    counted once, as :func:`scatter_beyond_reference` does for the decided half range; a
    sample's U summed them: the phase reference's u 1.22 times over at a reference
    dominating the noise, the LSB twice over where it dominates)."""
    theta = np.asarray(result.theta_rad, dtype=float)
    n = theta.size
    out = []
    for fit in (result.sin_fit, result.cos_fit):
        p = 1 + 2 * len(fit.orders)
        dof = max(n - p, 1)
        shown2 = fit.residual_rms ** 2 * n / dof
        reference2 = _reference_share2(theta, fit, u_rad)
        beyond2 = shown2 - reference2 - quantisation_v ** 2
        out.append(ChannelScatter(math.sqrt(max(beyond2, 0.0)), dof, math.sqrt(shown2),
                                  math.sqrt(reference2)))
    return out[0], out[1]


def scatter_beyond_reference(result, u_rad: float) -> tuple[ChannelScatter, ChannelScatter]:
    """(sin, cos): each channel's scatter the fit's own directions are drawn with, the
    reference's independent per-sample errors of standard uncertainty ``u_rad`` (rad of a
    signal period; 0: none stated) counted once (see the module's text)."""
    from scipy import stats  # imported late, as start-up pays it

    theta = np.asarray(result.theta_rad, dtype=float)
    n = theta.size
    groups = _groups(result)
    held = groups.counts > 0
    out = []
    for fit, readings in ((result.sin_fit, result.u_sin), (result.cos_fit, result.u_cos)):
        p = 1 + 2 * len(fit.orders)
        dof = max(n - p, 1)
        shown2 = fit.residual_rms ** 2 * n / dof
        stated = u_rad > 0.0 and math.isfinite(u_rad) and n > p
        reference2 = _reference_share2(theta, fit, u_rad) if stated else 0.0
        # a reference stated: what repeats at its phases (no reference stated, the fit's
        # scatter as before: the readings' rounding and the ADC's linearity, which repeat at
        # a phase too, have their own inputs, models.fringe.rounding_at_phases)
        means_dof = int(np.count_nonzero(held)) - p
        if stated and groups.repeats and means_dof > 0:
            residuals = fit.residuals if fit.residuals is not None and fit.residuals.size == n \
                else np.asarray(readings, dtype=float) - model_signal(theta, fit)
            sums = np.bincount(groups.index, weights=residuals, minlength=groups.phases.size)
            means2 = float(np.sum(sums[held] ** 2 / groups.counts[held])) / means_dof
            # taken where it is larger beyond chance (the lack-of-fit F test at 95 %): the
            # larger of two estimates of one independent scatter is biased high
            if means2 > shown2 * float(stats.f.ppf(LACK_OF_FIT_LEVEL, means_dof, dof)):
                # the reference's share there, its errors the same at a phase in every
                # period: u²·Σ cⱼ(1 − hⱼ)·S′ⱼ² / (J − p), hⱼ = cⱼ·xⱼᵀ(XᵀX)⁻¹xⱼ
                x_j, inverse = groups.design(fit.orders)
                c_j = groups.counts[held]
                h_j = c_j * np.einsum("ij,jk,ik->i", x_j[held], inverse, x_j[held])
                slope2 = model_slope(groups.phases[held], fit) ** 2
                repeated2 = u_rad ** 2 * float(np.sum(c_j * (1.0 - h_j) * slope2)) / means_dof
                if _shows(means2, repeated2, means_dof):  # what repeats may be its errors
                    out.append(ChannelScatter(math.sqrt(max(means2 - repeated2, 0.0)),
                                              means_dof, math.sqrt(means2),
                                              math.sqrt(repeated2), True))
                else:  # something repeats, less than the reference's errors would: not
                    # them (a reference better than stated), its u an envelope of
                    # independent ones, the fit's directions the means' scatter beyond it
                    out.append(ChannelScatter(math.sqrt(max(means2 - reference2, 0.0)),
                                              means_dof, math.sqrt(means2),
                                              math.sqrt(reference2)))
                continue
        out.append(ChannelScatter(math.sqrt(max(shown2 - reference2, 0.0)), dof,
                                  math.sqrt(shown2), math.sqrt(reference2)))
    return out[0], out[1]
