"""Grating signals sampled at a known true phase, from first principles (numpy only).

An encoder's read head gives two channels in quadrature. Here the true
electrical phase of each sample is set first (any motion: equal steps, a
speed that wanders, stops, reversals); the channels are then the sine and
cosine of that phase with the imperfections a real head has — offsets,
unequal amplitudes, a quadrature error, odd harmonics — plus noise and an
ADC's quantisation. Nothing here comes from the code under test.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class FringeHead:
    offsets_v: tuple[float, float] = (0.0, 0.0)  # sin, cos
    amplitudes_v: tuple[float, float] = (1.0, 1.0)
    quadrature_deg: float = 0.0  # the cos channel leads the sin by 90° + this
    phase_rad: float = 0.0  # the sin channel's fundamental is sin(θ + this)
    sin_harmonics: dict[int, tuple[float, float]] = field(default_factory=dict)  # k: (V, rad)
    cos_harmonics: dict[int, tuple[float, float]] = field(default_factory=dict)
    noise_v: float = 0.0
    adc_bits: int | None = None
    full_scale_v: float = 2.5  # the ADC reads −full scale … +full scale

    def channels(self, phase_rad, rng: np.random.Generator | None = None
                 ) -> tuple[np.ndarray, np.ndarray]:
        """(u_sin, u_cos) in volts at the true phases ``phase_rad``."""
        theta = np.asarray(phase_rad, dtype=float)
        rng = rng or np.random.default_rng(0)
        q = np.radians(self.quadrature_deg)
        p = self.phase_rad
        u_sin = self.offsets_v[0] + self.amplitudes_v[0] * np.sin(theta + p)
        u_cos = self.offsets_v[1] + self.amplitudes_v[1] * np.sin(theta + p + np.pi / 2 + q)
        for k, (a, c) in self.sin_harmonics.items():
            u_sin = u_sin + a * np.sin(k * theta + c)
        for k, (a, c) in self.cos_harmonics.items():
            u_cos = u_cos + a * np.sin(k * theta + c)
        if self.noise_v:
            u_sin = u_sin + rng.normal(0.0, self.noise_v, theta.size)
            u_cos = u_cos + rng.normal(0.0, self.noise_v, theta.size)
        if self.adc_bits:
            lsb = 2.0 * self.full_scale_v / 2**self.adc_bits
            u_sin = np.clip(np.round(u_sin / lsb) * lsb, -self.full_scale_v, self.full_scale_v)
            u_cos = np.clip(np.round(u_cos / lsb) * lsb, -self.full_scale_v, self.full_scale_v)
        return u_sin, u_cos


def equal_steps(count: int, samples_per_period: int) -> np.ndarray:
    """True phase of ``count`` samples taken at equal steps, N per period (rad)."""
    return np.arange(count) * (2.0 * np.pi / samples_per_period)


def wandering_motion(count: int, rng: np.random.Generator, min_samples: float = 2.0,
                     max_samples: float = 200.0, stops: int = 2, reversal: bool = True
                     ) -> np.ndarray:
    """True phase (rad) of a motion turned by hand: the speed wanders between
    ``max_samples`` and ``min_samples`` samples per period (a random walk in log
    speed), stands still ``stops`` times and, with ``reversal``, turns back once."""
    log_lo, log_hi = np.log(2 * np.pi / max_samples), np.log(2 * np.pi / min_samples)
    walk = np.cumsum(rng.normal(0.0, 0.05, count))
    walk = log_lo + (log_hi - log_lo) * (0.5 + 0.5 * np.sin(walk + rng.uniform(0, 2 * np.pi)))
    step = np.exp(walk)
    for _ in range(stops):
        start = int(rng.integers(count // 10, count - count // 10))
        step[start:start + count // 50] = 0.0
    if reversal:
        turn = int(rng.integers(count // 3, 2 * count // 3))
        step[turn:] *= -1.0
    return np.concatenate([[0.0], np.cumsum(step[1:])])
