"""A read head's two channels sampled at N steps a period, the steps equal or jittered, from
first principles: imports nothing from models/.

The head at its true electrical phase φ (an audit's, cov76): offsets 20 / −30 mV, an
amplitude ratio 0.985, a quadrature error of 0.6°, 3rd and 5th harmonics on each channel:

    u_sin(φ) = o_s + A·sin φ + A·Σ a_k·sin(kφ + α_k)
    u_cos(φ) = o_c + r·A·cos(φ + q) + r·A·Σ b_k·cos(kφ + β_k)

Sample i is meant at φ₀ + 2π i / N and taken at φᵢ = φ₀ + 2π i / N + εᵢ, εᵢ drawn
N(0, jitter²) for each sample (0: equal steps); white noise of σ on each channel.

The truth of the interpolation error is the noise-free channels' atan2 phase less the true
phase (indicated − reference) over a dense whole period; the decided quantity is half its
peak-to-peak (:func:`true_half_range_arcsec`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

TWO_PI = 2.0 * math.pi
LINES = 16384
PERIOD_ARCSEC = 1296000.0 / LINES


@dataclass(frozen=True)
class JitteredHead:
    """The head (V, rad unless named) and its sampling."""

    per_period: int
    periods: float
    noise_v: float
    jitter_deg: float = 0.0
    amplitude_v: float = 1.0
    offsets_v: tuple[float, float] = (0.02, -0.03)
    ratio: float = 0.985
    quadrature_deg: float = 0.6
    #: (order, share of the amplitude, phase rad) of each channel's harmonics
    sin_harmonics: tuple[tuple[int, float, float], ...] = ((3, 0.02, 0.3), (5, 0.006, 1.1))
    cos_harmonics: tuple[tuple[int, float, float], ...] = ((3, 0.018, 1.9), (5, 0.005, -0.7))
    start_rad: float = 0.0

    @property
    def samples(self) -> int:
        return int(round(self.per_period * self.periods))

    def clean(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The head's noise-free channels (V) at the true phases ``phi``."""
        a, q = self.amplitude_v, math.radians(self.quadrature_deg)
        u_sin = self.offsets_v[0] + a * np.sin(phi)
        u_cos = self.offsets_v[1] + a * self.ratio * np.cos(phi + q)
        for k, share, phase in self.sin_harmonics:
            u_sin = u_sin + a * share * np.sin(k * phi + phase)
        for k, share, phase in self.cos_harmonics:
            u_cos = u_cos + a * self.ratio * share * np.cos(k * phi + phase)
        return u_sin, u_cos

    def record(self, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(u_sin, u_cos, the true phases φᵢ − φ₀ in degrees: a θ column of the reference)."""
        nominal = np.arange(self.samples) * (TWO_PI / self.per_period)
        phi = self.start_rad + nominal + np.radians(self.jitter_deg) * rng.standard_normal(
            self.samples)
        u_sin, u_cos = self.clean(phi)
        u_sin = u_sin + self.noise_v * rng.standard_normal(self.samples)
        u_cos = u_cos + self.noise_v * rng.standard_normal(self.samples)
        return u_sin, u_cos, np.degrees(phi - self.start_rad)

    def error_arcsec(self, phi: np.ndarray) -> np.ndarray:
        """The true interpolation error at ``phi`` (arcsec of shaft angle, L = 16384)."""
        u_sin, u_cos = self.clean(phi)
        delta = np.angle(np.exp(1j * (np.arctan2(u_sin, u_cos) - phi)))
        return delta * PERIOD_ARCSEC / TWO_PI

    def true_half_range_arcsec(self) -> float:
        error = self.error_arcsec(np.linspace(0.0, TWO_PI, 20000, endpoint=False))
        return 0.5 * float(np.ptp(error))
