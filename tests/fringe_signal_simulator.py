"""A read head's two channels from first principles, for the signal tolerance and the
interpolator table tests (#45): imports nothing from models/.

u_a = A·sin θ + Σ_k h_k·A·sin(kθ + φ_k) + o_a
u_b = B·cos(θ + φ) + Σ_k h_k·B·cos(k(θ + φ) + φ_k) + o_b

θ the true electrical phase, A and B peak amplitudes (half the peak-to-peak of the
fundamental), φ the quadrature error (B leads A by 90° + φ), o_a, o_b the offsets, h_k the
relative amplitude of harmonic k (the same distortion of the grating seen by both channels),
and white noise of standard deviation ``noise`` on each channel.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np


@dataclass(frozen=True)
class Head:
    peak_a: float = 0.5  # V (peak; 1 Vpp is 0.5)
    peak_b: float = 0.5
    quadrature_deg: float = 0.0
    offset_a: float = 0.0
    offset_b: float = 0.0
    harmonics: dict[int, tuple[float, float]] = field(default_factory=dict)  # k: (h_k, φ_k rad)
    noise: float = 0.0

    def signals(self, theta: np.ndarray, rng: np.random.Generator | None = None
                ) -> tuple[np.ndarray, np.ndarray]:
        theta = np.asarray(theta, dtype=float)
        phi = math.radians(self.quadrature_deg)
        u_a = self.peak_a * np.sin(theta) + self.offset_a
        u_b = self.peak_b * np.cos(theta + phi) + self.offset_b
        for k, (h, c) in self.harmonics.items():
            u_a = u_a + h * self.peak_a * np.sin(k * theta + c)
            u_b = u_b + h * self.peak_b * np.cos(k * (theta + phi) + c)
        if self.noise:
            rng = rng or np.random.default_rng(0)
            u_a = u_a + rng.normal(0.0, self.noise, theta.size)
            u_b = u_b + rng.normal(0.0, self.noise, theta.size)
        return u_a, u_b


    def peak_to_peak(self, grid: int = 1 << 20) -> tuple[float, float]:
        """Each channel's true peak-to-peak (noise-free), from a dense grid (the peaks read low
        by at most (π/grid)²/2 of the amplitude: 5e-12 at the default)."""
        theta = np.arange(grid) * (2.0 * math.pi / grid)
        clean = Head(self.peak_a, self.peak_b, self.quadrature_deg, 0.0, 0.0, self.harmonics)
        u_a, u_b = clean.signals(theta)
        return float(np.ptp(u_a)), float(np.ptp(u_b))


def equal_phase(periods: int, per_period: int) -> np.ndarray:
    """N equal steps a period, starting at 0 (rad)."""
    return np.arange(periods * per_period) * (2.0 * math.pi / per_period)


def true_interpolation_error(measured_rad: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """Measured phase minus the true one, wrapped, its circular mean removed (rad)."""
    d = np.angle(np.exp(1j * (np.asarray(measured_rad) - theta)))
    return np.angle(np.exp(1j * (d - np.angle(np.mean(np.exp(1j * d))))))


def ideal_terms(head: Head, u_a: np.ndarray, u_b: np.ndarray, terms: tuple[str, ...]
                ) -> tuple[np.ndarray, np.ndarray]:
    """What a chip that corrects ``terms`` ("offset", "gain", "phase") of the head's
    fundamentals exactly makes of its signals: offsets subtracted, B scaled to A, and B's
    quadrature error q removed (B' = (B + A sin q) / cos q)."""
    a, b = u_a, u_b
    if "offset" in terms:
        a, b = a - head.offset_a, b - head.offset_b
    if "gain" in terms:
        b = b * (head.peak_a / head.peak_b)
    if "phase" in terms:
        q = math.radians(head.quadrature_deg)
        b = (b + a * math.sin(q)) / math.cos(q)
    return a, b


def chip_phase(u_a: np.ndarray, u_b: np.ndarray, codes: np.ndarray, lsb_period: float,
               interpolation: str, sign: str) -> np.ndarray:
    """A chip's corrected phase (rad): φ = atan2(u_a, u_b), the table of ``codes`` over one
    period of φ looked up (``step``: the entry below φ; ``linear``: between the two about it),
    code·LSB·2π added (``sign`` "add") or subtracted."""
    phi = np.arctan2(u_a, u_b)
    n = len(codes)
    pos = (phi % (2.0 * math.pi)) / (2.0 * math.pi) * n
    j = np.floor(pos).astype(int) % n
    value = np.asarray(codes, dtype=float)[j]
    if interpolation == "linear":
        nxt = np.asarray(codes, dtype=float)[(j + 1) % n]
        value = value + (nxt - value) * (pos - np.floor(pos))
    value = value * lsb_period * 2.0 * math.pi
    return phi + value if sign == "add" else phi - value
