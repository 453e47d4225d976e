"""A read head's two channels sampled at a known true phase, from first principles, each
channel with harmonics of its own in volts: imports nothing from models/.

u_sin = o_s + A_s·sin(θ + p) + Σ_k a_k·sin(kθ + c_k)
u_cos = o_c + A_c·sin(θ + p + 90° + q) + Σ_k b_k·sin(kθ + d_k)

θ the true electrical phase of each sample (set first: equal steps, or equal steps with a
jitter of the phase itself), o the offsets, A the amplitudes, q the quadrature error (the cos
channel leads the sin by 90° + q), a_k, b_k (V) and c_k, d_k (rad) the harmonics of each
channel; then white noise on each channel and an ADC's rounding to its step.

The truth a test compares with: the interpolation error of the noise-free channels,
atan2(u_sin, u_cos) − θ wrapped and its circular mean removed, over the whole period on a
dense grid of θ (:meth:`Channels.true_error_rad`), not only at the sampled phases.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

import numpy as np

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Channels:
    offsets_v: tuple[float, float] = (0.0, 0.0)  # sin, cos
    amplitudes_v: tuple[float, float] = (1.0, 1.0)
    quadrature_deg: float = 0.0  # the cos channel leads the sin by 90° + this
    phase_rad: float = 0.0  # the sin channel's fundamental is sin(θ + this)
    sin_harmonics: dict[int, tuple[float, float]] = field(default_factory=dict)  # k: (V, rad)
    cos_harmonics: dict[int, tuple[float, float]] = field(default_factory=dict)
    noise_v: float = 0.0
    adc_bits: int | None = None
    full_scale_v: float = 2.5  # the ADC reads −full scale … +full scale

    def sample(self, theta_rad, rng: np.random.Generator | None = None
               ) -> tuple[np.ndarray, np.ndarray]:
        """(u_sin, u_cos) in volts at the true phases ``theta_rad``."""
        theta = np.asarray(theta_rad, dtype=float)
        q = math.radians(self.quadrature_deg)
        p = self.phase_rad
        u_sin = self.offsets_v[0] + self.amplitudes_v[0] * np.sin(theta + p)
        u_cos = self.offsets_v[1] + self.amplitudes_v[1] * np.sin(theta + p + math.pi / 2 + q)
        for k, (a, c) in self.sin_harmonics.items():
            u_sin = u_sin + a * np.sin(k * theta + c)
        for k, (a, c) in self.cos_harmonics.items():
            u_cos = u_cos + a * np.sin(k * theta + c)
        if self.noise_v:
            rng = rng or np.random.default_rng(0)
            u_sin = u_sin + rng.normal(0.0, self.noise_v, theta.size)
            u_cos = u_cos + rng.normal(0.0, self.noise_v, theta.size)
        if self.adc_bits:
            lsb = 2.0 * self.full_scale_v / 2**self.adc_bits
            u_sin = np.clip(np.round(u_sin / lsb) * lsb, -self.full_scale_v, self.full_scale_v)
            u_cos = np.clip(np.round(u_cos / lsb) * lsb, -self.full_scale_v, self.full_scale_v)
        return u_sin, u_cos

    def true_error_rad(self, points: int = 1 << 16) -> np.ndarray:
        """The interpolation error of the noise-free channels over one whole period (rad):
        atan2(u_sin, u_cos) − θ at ``points`` equal steps of θ, wrapped, its circular mean
        removed."""
        clean = replace(self, noise_v=0.0, adc_bits=None)
        theta = np.arange(points) * (TWO_PI / points)
        u_sin, u_cos = clean.sample(theta)
        d = np.angle(np.exp(1j * (np.arctan2(u_sin, u_cos) - theta)))
        return np.angle(np.exp(1j * (d - np.angle(np.mean(np.exp(1j * d))))))

    def true_half_range_rad(self) -> float:
        """Half the peak-to-peak of :meth:`true_error_rad` (rad)."""
        return 0.5 * float(np.ptp(self.true_error_rad()))


def equal_steps(count: int, per_period: int) -> np.ndarray:
    """True phase of ``count`` samples at equal steps, N a period, from 0 (rad)."""
    return np.arange(count) * (TWO_PI / per_period)


def jittered_steps(count: int, per_period: int, jitter_rad: float,
                   rng: np.random.Generator) -> np.ndarray:
    """Equal steps whose true phase each carries a normal jitter of ``jitter_rad`` (a motion
    read at N steps a period by a reference whose own timing scatters)."""
    return equal_steps(count, per_period) + rng.normal(0.0, jitter_rad, count)
