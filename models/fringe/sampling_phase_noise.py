"""The noise of each sample's phase (the stated phase reference u: with N equal steps the
timing jitter of the sampling, with a θ column its reference's noise): what a θ column's
phases show of it (:func:`phase_noise_rad`), and what it leaves in the fitted harmonic phases
c_k beyond what the fit's scatter shows (:func:`phase_excess_variance`).

A sample taken at θᵢ + εᵢ instead of θᵢ reads the channel's value there: U(θᵢ) + U′(θᵢ)·εᵢ.
The error U′·ε is in the residuals, so the fit's σ² holds its mean, σ_ε²·mean(U′²), as if it
were spread evenly over the samples. It is not: it is largest where the channel is steepest,
which for the fundamental is where a shift of its phase moves the signal most. The phase
of the fundamental then scatters by σ_ε²·Σcos⁴/(Σcos²)² = 1.5·σ_ε²/n (equal steps), where
the fit's covariance gives σ_ε²/n for that part: at a stated 0.05° (N = 64, 20 periods, noise
0.2 mV, a coarse ADC) the phases c1 of both channels scattered 1.12–1.13× their u and their U
covered 92.2 % and 92.6 % of 2000 runs (tests/benchmarks/fringe_phase_study.py). The whole
of it, from the least squares of the design X with (XᵀX)⁻¹ = V:

    cov(β̂) = σ_n²·V + σ_ε²·V·Xᵀ diag(U′²) X·V,   E[σ̂²] = σ_n² + σ_ε²·m,
    m = Σ (1 − hᵢ)·U′ᵢ² / (n − p)   (hᵢ the leverage of sample i),

so beyond the fit's σ̂²·V the phase noise adds σ_ε²·(V·Xᵀ diag(U′²) X·V − m·V). Along a
harmonic's phase this is positive for the fundamental (half the jitter's share again) and
about zero for the others; along an offset or amplitude it is negative (the scatter
overstates the jitter there) and is not taken off: only a phase is given the excess, where
it is positive. The slope U′ is the fitted channel's.
"""

from __future__ import annotations

import math

import numpy as np

from models.fringe.order_statistics import median

__all__ = ["EVEN_STEPS", "phase_excess_variance", "phase_noise_rad"]

TWO_PI = 2.0 * math.pi
#: a θ column's record of more samples than this is taken as its phases binned, :data:`_BINS`
#: a period (what the sums lose is of the order of the bin's width squared: ~1e-7 of them)
_EXACT_MAX = 65536
_BINS = 8192


#: a record steps evenly when the noise its second differences show is at most this share
#: of its median step
EVEN_STEPS = 0.05


def phase_noise_rad(theta_rad: np.ndarray) -> float:
    """The noise of each phase of a record read at even steps (a θ column of a motion at a
    steady or slowly changing speed), from its second differences θᵢ₊₁ − 2θᵢ + θᵢ₋₁ (√6 σ
    for white noise; the steps themselves cancel): their median absolute value / 0.6745 /
    √6. 0 when the record does not step evenly (the noise so found above
    :data:`EVEN_STEPS` of the median step: random phases, a motion that changes speed from
    sample to sample, whose second differences are no noise), or has fewer than 3 samples."""
    theta = np.asarray(theta_rad, dtype=float)
    if theta.size < 3:
        return 0.0
    noise = median(np.abs(np.diff(theta, 2))) / 0.6745 / math.sqrt(6.0)
    step = median(np.abs(np.diff(theta)))
    return noise if noise <= EVEN_STEPS * step else 0.0


def _design(phase: np.ndarray, orders: tuple[int, ...]) -> np.ndarray:
    """Columns 1, sin kθ, cos kθ for k in ``orders`` (the fit's order of parameters)."""
    x = np.empty((phase.size, 1 + 2 * len(orders)))
    x[:, 0] = 1.0
    for i, k in enumerate(orders):
        x[:, 1 + 2 * i] = np.sin(k * phase)
        x[:, 2 + 2 * i] = np.cos(k * phase)
    return x


def _slope(phase: np.ndarray, fit) -> np.ndarray:
    """dU/dθ of the fitted channel ``fit`` (V/rad)."""
    slope = np.zeros_like(phase)
    for k in fit.orders:
        slope += k * fit.amplitude[k] * np.cos(k * phase + fit.phase[k])
    return slope


def _phases_and_counts(theta_rad: np.ndarray, samples_per_period: int
                       ) -> tuple[np.ndarray, np.ndarray]:
    """The design's phases, each with how many samples it stands for: the N phases of equal
    steps with their counts; a θ column's every sample (a count of 1 each), or of a long
    record the centres of :data:`_BINS` bins a period with the samples in each."""
    theta = np.asarray(theta_rad, dtype=float)
    if samples_per_period:
        n = int(samples_per_period)
        index = np.rint(theta / (TWO_PI / n)).astype(np.intp) % n
        return np.arange(n) * (TWO_PI / n), np.bincount(index, minlength=n).astype(float)
    if theta.size <= _EXACT_MAX:
        return theta, np.ones(theta.size)
    index = np.floor(np.mod(theta, TWO_PI) / (TWO_PI / _BINS)).astype(np.intp) % _BINS
    counts = np.bincount(index, minlength=_BINS).astype(float)
    held = np.flatnonzero(counts)
    return (held + 0.5) * (TWO_PI / _BINS), counts[held]


def phase_excess_variance(theta_rad, samples_per_period: int, fits, phase_u_rad: float
                          ) -> list[dict[int, float]]:
    """For each fit of ``fits`` (the channels fitted at the phases ``theta_rad``; N equal steps
    when ``samples_per_period``), {k: the variance (rad²) a phase noise of ``phase_u_rad`` per
    sample adds to the phase c_k beyond the fit's own u, 0 where none}."""
    if not (phase_u_rad > 0 and math.isfinite(phase_u_rad)) or not fits:
        return [{k: 0.0 for k in fit.orders} for fit in fits]
    orders = fits[0].orders
    phase, counts = _phases_and_counts(theta_rad, samples_per_period)
    n_par = 1 + 2 * len(orders)
    samples = float(counts.sum())
    if samples <= n_par:
        return [{k: 0.0 for k in fit.orders} for fit in fits]
    x = _design(phase, orders)
    inverse = np.linalg.pinv(x.T @ (x * counts[:, None]))
    leverage = np.einsum("ij,jk,ik->i", x, inverse, x)
    out = []
    for fit in fits:
        square = _slope(phase, fit) ** 2 * counts
        weighted = x.T @ (x * square[:, None])  # Xᵀ diag(U′²) X
        shown = float(np.sum((1.0 - leverage) * square))  # Σ (1 − hᵢ)·U′ᵢ²: the residuals'
        excess = inverse @ weighted @ inverse - (shown / (samples - n_par)) * inverse
        excess *= phase_u_rad ** 2
        extra: dict[int, float] = {}
        for i, k in enumerate(orders):
            a = fit.amplitude[k]
            if not a > 0:
                extra[k] = 0.0
                continue
            # the phase's gradient in (sine, cosine coefficient): (−A sin c, A cos c)/A²
            grad = np.array([-math.sin(fit.phase[k]), math.cos(fit.phase[k])]) / a
            block = excess[1 + 2 * i:3 + 2 * i, 1 + 2 * i:3 + 2 * i]
            extra[k] = max(float(grad @ block @ grad), 0.0)
        out.append(extra)
    return out
