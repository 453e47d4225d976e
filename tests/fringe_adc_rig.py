"""A read head's two channels digitised by an ADC with an offset and a gain error of its own
per run, from first principles: imports nothing from models/.

The read head (what a certificate states the parameters of):

    u_sin = o_s + A_s·sin(θ) + Σ_k a_k·sin(kθ + α_k)
    u_cos = o_c + A_c·sin(θ + 90° + q) + Σ_k b_k·sin(kθ + β_k)

θ the true electrical phase of each sample (N equal steps a period from 0, or random steps),
o the offsets, A the amplitudes, q the quadrature error, a_k, b_k and α_k, β_k each
channel's harmonics. The ADC then adds, ONCE PER RUN (a calibration's error, not noise):
an offset to each channel drawn from N(0, u_offset²), and a gain ratio 1 + ε, ε from
N(0, u_gain²), of the cos channel's gain to the sin channel's (put on one channel or the
other at random, each run: the ratio's error does not say which); then white noise on
each reading and rounding to the ADC's step.

The truth of each parameter in the frame the analysis states it in (sine phases: sin(kθ +
c_k), θ = 0 at the first sample): :meth:`Head.parameters`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

TWO_PI = 2.0 * math.pi


@dataclass(frozen=True)
class Head:
    offsets_v: tuple[float, float] = (0.010, -0.006)
    amplitudes_v: tuple[float, float] = (0.5, 0.49)
    quadrature_deg: float = 1.0
    sin_harmonics: dict[int, tuple[float, float]] = field(
        default_factory=lambda: {3: (0.0025, 0.7), 5: (0.001, 2.1)})
    cos_harmonics: dict[int, tuple[float, float]] = field(
        default_factory=lambda: {3: (0.002, 1.9), 5: (0.0011, -0.6)})

    def clean(self, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The read head's own signals (V) at the true phases ``theta``."""
        q = math.radians(self.quadrature_deg)
        u_sin = self.offsets_v[0] + self.amplitudes_v[0] * np.sin(theta)
        u_cos = self.offsets_v[1] + self.amplitudes_v[1] * np.sin(theta + math.pi / 2 + q)
        for k, (a, c) in self.sin_harmonics.items():
            u_sin = u_sin + a * np.sin(k * theta + c)
        for k, (a, c) in self.cos_harmonics.items():
            u_cos = u_cos + a * np.sin(k * theta + c)
        return u_sin, u_cos

    def parameters(self) -> dict[str, dict[str, float]]:
        """The read head's parameters: {"sin": {"A0", "A1", "c1", "A3", "c3", …}, "cos": …}
        (V, rad), a harmonic not in the head with amplitude 0."""
        q = math.radians(self.quadrature_deg)
        out = {}
        for label, offset, amplitude, phase, harmonics in (
                ("sin", self.offsets_v[0], self.amplitudes_v[0], 0.0, self.sin_harmonics),
                ("cos", self.offsets_v[1], self.amplitudes_v[1], math.pi / 2 + q,
                 self.cos_harmonics)):
            p = {"A0": offset, "A1": amplitude, "c1": phase}
            for k, (a, c) in harmonics.items():
                p[f"A{k}"], p[f"c{k}"] = a, c
            out[label] = p
        return out

    @property
    def amplitude_ratio(self) -> float:
        return self.amplitudes_v[1] / self.amplitudes_v[0]


@dataclass(frozen=True)
class Adc:
    offset_u_v: float = 0.001  # standard uncertainty of each channel's offset
    gain_u: float = 0.002  # standard uncertainty of the ratio of the channels' gains
    noise_v: float = 0.0003
    lsb_v: float = 0.00025

    def digitise(self, u_sin: np.ndarray, u_cos: np.ndarray, rng: np.random.Generator
                 ) -> tuple[np.ndarray, np.ndarray]:
        """One run's readings: the ADC's offsets and gain ratio drawn once, then noise and
        rounding per reading."""
        offsets = rng.normal(0.0, self.offset_u_v, 2)
        ratio = 1.0 + rng.normal(0.0, self.gain_u)
        gains = (1.0, ratio) if rng.random() < 0.5 else (1.0 / ratio, 1.0)
        out = []
        for u, gain, offset in ((u_sin, gains[0], offsets[0]), (u_cos, gains[1], offsets[1])):
            v = gain * u + offset + rng.normal(0.0, self.noise_v, u.size)
            out.append(np.round(v / self.lsb_v) * self.lsb_v)
        return out[0], out[1]


def equal_steps(count: int, per_period: int) -> np.ndarray:
    return np.arange(count) * (TWO_PI / per_period)


def random_steps(count: int, rng: np.random.Generator, mean_step: float = TWO_PI / 32
                 ) -> np.ndarray:
    """A motion of uneven steps (0.2 … 1.8 × the mean step) from 0."""
    steps = rng.uniform(0.2, 1.8, count - 1) * mean_step
    return np.concatenate([[0.0], np.cumsum(steps)])


def wrapped(angle: float) -> float:
    return math.remainder(angle, TWO_PI)
