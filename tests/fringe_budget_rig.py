"""A read head sampled against a phase reference with errors of its own, digitised by an ADC
with an offset, a gain ratio and a step of its own, from first principles: imports nothing
from models/ (the budget's inputs, each made as what it physically is, so that the per-sample
U and the decided half range's interval can be checked against the truth).

The read head, at its TRUE phase θ:

    S(θ) = o_s + A_s·sin(θ) + Σ_k a_k·sin(kθ + α_k)
    C(θ) = o_c + A_c·sin(θ + 90° + q) + Σ_k b_k·sin(kθ + β_k)

Its interpolation error is e(θ) = atan2(S, C) − θ (wrapped), stated with its mean over the
period removed; the decided quantity is half its peak-to-peak over the whole (continuous)
period, as shaft angle (one period 1296000″/L).

One record: the phase reference states the phases θᵢ (the θ column: equal steps, N a
period); the head is really at θᵢ + δᵢ, δᵢ ~ N(0, u_ref²) independent from sample to sample
(``repeated``: one δ a sample phase, the same in every period). The ADC adds to each channel
an offset drawn ONCE PER RUN from N(0, u_offset²), multiplies the cos channel by 1 + ε, ε ~
N(0, u_gain²) once per run (the ratio of the gains), adds white noise σ to each reading and
rounds to its step (LSB; 0: none). The truth at sample i is e(θᵢ), the error the certificate
states at the phase θᵢ it prints.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

TWO_PI = 2.0 * math.pi


def wrapped(x: np.ndarray) -> np.ndarray:
    return (np.asarray(x) + math.pi) % TWO_PI - math.pi


@dataclass(frozen=True)
class Head:
    offsets_v: tuple[float, float] = (-0.018, -0.064)
    amplitudes_v: tuple[float, float] = (3.776, 3.735)
    quadrature_deg: float = 0.6
    sin_harmonics: dict[int, tuple[float, float]] = field(
        default_factory=lambda: {3: (0.030, 0.9), 5: (0.011, 0.47)})
    cos_harmonics: dict[int, tuple[float, float]] = field(
        default_factory=lambda: {3: (0.028, 2.1), 5: (0.010, 2.07)})
    lines_per_rev: int = 16384

    @property
    def period_arcsec(self) -> float:
        return 1296000.0 / self.lines_per_rev

    def signals(self, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(S, C) in V at the true phases ``theta`` (rad)."""
        q = math.radians(self.quadrature_deg)
        s = self.offsets_v[0] + self.amplitudes_v[0] * np.sin(theta)
        c = self.offsets_v[1] + self.amplitudes_v[1] * np.sin(theta + math.pi / 2 + q)
        for k, (a, phase) in self.sin_harmonics.items():
            s = s + a * np.sin(k * theta + phase)
        for k, (a, phase) in self.cos_harmonics.items():
            c = c + a * np.sin(k * theta + phase)
        return s, c

    def error_rad(self, theta: np.ndarray) -> np.ndarray:
        """e(θ) = atan2(S, C) − θ (rad), not yet with its mean removed."""
        s, c = self.signals(theta)
        return wrapped(np.arctan2(s, c) - theta)

    def mean_error_rad(self) -> float:
        dense = np.arange(8192) * (TWO_PI / 8192)
        return float(np.mean(self.error_rad(dense)))

    def error_arcsec(self, theta: np.ndarray) -> np.ndarray:
        """The true interpolation error at ``theta``, its mean over the period removed (″)."""
        return (self.error_rad(theta) - self.mean_error_rad()) * self.period_arcsec / TWO_PI

    def half_range_arcsec(self) -> float:
        """Half the true error's peak-to-peak over the whole period (″)."""
        dense = np.arange(65536) * (TWO_PI / 65536)
        return 0.5 * float(np.ptp(self.error_rad(dense))) * self.period_arcsec / TWO_PI


@dataclass(frozen=True)
class Bench:
    """The reference and the ADC of a run (their true figures; what a lab states may differ)."""

    reference_u_arcsec: float = 0.0  # standard deviation of δᵢ, shaft angle
    repeated: bool = False  # δ the same at a sample phase in every period
    offset_u_v: float = 0.0
    gain_u: float = 0.0  # of the ratio, relative
    noise_v: float = 0.002
    lsb_v: float = 0.0  # 0: no rounding beyond the typed digits
    typed_decimals: int = 5  # the readings as a CSV holds them (0.01 mV)
    periods: int = 8
    per_period: int = 64


@dataclass
class Record:
    theta_rad: np.ndarray  # the phases the reference states
    u_sin: np.ndarray
    u_cos: np.ndarray
    truth_arcsec: np.ndarray  # the true error at each stated phase, its mean removed
    delta_rad: np.ndarray  # the reference's errors (true − stated)


def record(head: Head, bench: Bench, rng: np.random.Generator) -> Record:
    """One run of the bench: the stated phases from a random start, the channels read."""
    n = bench.periods * bench.per_period
    stated = (np.arange(n) * (TWO_PI / bench.per_period) + rng.uniform(0.0, TWO_PI)) % TWO_PI
    scale = bench.reference_u_arcsec * TWO_PI / head.period_arcsec
    if bench.repeated:
        delta = np.tile(rng.normal(0.0, scale, bench.per_period), bench.periods)
    else:
        delta = rng.normal(0.0, scale, n)
    s, c = head.signals(stated + delta)
    offsets = rng.normal(0.0, bench.offset_u_v, 2)
    gain = 1.0 + rng.normal(0.0, bench.gain_u)
    readings = []
    for v, offset, g in ((s, offsets[0], 1.0), (c, offsets[1], gain)):
        v = (v + offset) * g + rng.normal(0.0, bench.noise_v, n)
        if bench.lsb_v > 0.0:
            v = np.round(v / bench.lsb_v) * bench.lsb_v
        readings.append(np.round(v, bench.typed_decimals))
    return Record(stated, readings[0], readings[1], head.error_arcsec(stated), delta)
