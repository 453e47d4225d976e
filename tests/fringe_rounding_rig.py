"""A read head's two channels sampled at N exactly equal steps over whole periods, with a
little noise and an ADC that rounds each reading to its step, from first principles: imports
nothing from models/.

At the true electrical phase φ:

    u_sin(φ) = o_s + A_s·sin(φ) + Σ_k a_k·sin(kφ + α_k)
    u_cos(φ) = o_c + A_c·sin(φ + 90° + q) + Σ_k b_k·sin(kφ + β_k)

Sample i is at φᵢ = φ₀ + 2π·i/N exactly (a clock without jitter), i = 0 … N·periods − 1, so
every period repeats the same N phases; φ₀ is drawn uniformly for each record (where the
rounding falls on the signal changes from record to record, not within one). Each reading
gets white noise N(0, σ²) and is then rounded to the ADC's step δ: round(v/δ)·δ. With σ well
below δ the rounding of a phase comes out alike in every period.

The analysis is told N, so its phase is θᵢ = 2π·i/N (θ = 0 at the first sample, φ = θ + φ₀);
a term sin(kφ + α) is sin(kθ + kφ₀ + α) there (:meth:`RoundedHead.parameters`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

TWO_PI = 2.0 * math.pi


def wrapped(angle: float) -> float:
    """An angle into [−π, π] (rad)."""
    return math.remainder(angle, TWO_PI)


def _harmonics(highest: int, amplitude_v: float, phases: tuple[float, float]
               ) -> dict[int, tuple[float, float]]:
    # a 3rd of 0.5 % and (where the sampling resolves it) a 5th of 0.2 % of the amplitude
    out = {3: (0.005 * amplitude_v, phases[0])}
    if highest >= 5:
        out[5] = (0.002 * amplitude_v, phases[1])
    return out


def head_signals(phi: np.ndarray, offsets: tuple[float, float], amplitudes: tuple[float, float],
                 quadrature_deg: float, harmonics) -> tuple[np.ndarray, np.ndarray]:
    """A read head's sin and cos signals (V) at the true phases ``phi``: each channel its
    offset, its fundamental (cos a quarter period ahead, less the quadrature error) and its
    harmonics ``harmonics`` = (sin's, cos's) {order: (amplitude, phase)}."""
    q = math.radians(quadrature_deg)
    u_sin = offsets[0] + amplitudes[0] * np.sin(phi)
    u_cos = offsets[1] + amplitudes[1] * np.sin(phi + math.pi / 2 + q)
    sin_h, cos_h = harmonics
    for k, (a, c) in sin_h.items():
        u_sin = u_sin + a * np.sin(k * phi + c)
    for k, (a, c) in cos_h.items():
        u_cos = u_cos + a * np.sin(k * phi + c)
    return u_sin, u_cos


@dataclass(frozen=True)
class RoundedHead:
    """One design (V, rad): N a period, whole periods, the noise σ and the ADC's step δ."""

    per_period: int
    periods: int
    noise_v: float
    lsb_v: float
    offsets_v: tuple[float, float] = (0.01037, -0.00623)  # not on the ADC's grid
    amplitudes_v: tuple[float, float] = (0.50, 0.49)
    quadrature_deg: float = 1.0
    #: the highest harmonic the head has (and the analysis fits): 3 at N = 8 (a 5th would
    #: fold into the 3rd there), else 5
    highest: int = 5
    sin_phases: tuple[float, float] = (0.7, 2.1)
    cos_phases: tuple[float, float] = (1.9 + math.pi / 2, -0.6 + math.pi / 2)

    def harmonics(self) -> tuple[dict[int, tuple[float, float]], dict[int, tuple[float, float]]]:
        return (_harmonics(self.highest, self.amplitudes_v[0], self.sin_phases),
                _harmonics(self.highest, self.amplitudes_v[1], self.cos_phases))

    def clean(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The head's own signals (V) at the true phases ``phi``."""
        return head_signals(phi, self.offsets_v, self.amplitudes_v, self.quadrature_deg,
                            self.harmonics())

    def readings(self, rng: np.random.Generator) -> tuple[float, np.ndarray, np.ndarray]:
        """One record: (φ₀, the rounded sin readings, the rounded cos readings), V."""
        start = float(rng.uniform(0.0, TWO_PI))
        phi = start + np.arange(self.per_period * self.periods) * (TWO_PI / self.per_period)
        out = []
        for u in self.clean(phi):
            v = u + rng.normal(0.0, self.noise_v, u.size)
            out.append(np.round(v / self.lsb_v) * self.lsb_v)
        return start, out[0], out[1]

    def parameters(self, start: float) -> dict[str, dict[str, float]]:
        """The head's parameters in the analysis's frame (θ = 0 at the first sample; a
        channel as A0 + Σ A_k·sin(kθ + c_k)) for the record drawn at φ₀ = ``start``."""
        q = math.radians(self.quadrature_deg)
        sin_h, cos_h = self.harmonics()
        out = {}
        for label, offset, amplitude, phase, harmonics in (
                ("sin", self.offsets_v[0], self.amplitudes_v[0], 0.0, sin_h),
                ("cos", self.offsets_v[1], self.amplitudes_v[1], math.pi / 2 + q, cos_h)):
            p = {"A0": offset, "A1": amplitude, "c1": wrapped(start + phase)}
            for k, (a, c) in harmonics.items():
                p[f"A{k}"], p[f"c{k}"] = a, wrapped(k * start + c)
            out[label] = p
        return out

    def settings(self, lsb_stated: bool = True) -> dict[str, float]:
        """The analysis's settings for this design: N, the highest harmonic, and the ADC's
        step as stated (or not)."""
        return {"lines_per_rev": 16384, "samples_per_period": self.per_period,
                "max_order": self.highest,
                "adc_lsb_mv": self.lsb_v * 1e3 if lsb_stated else 0.0}


def head(per_period: int, periods: int, noise_over_lsb: float, lsb_v: float = 0.001
         ) -> RoundedHead:
    """A design of N = ``per_period`` over ``periods`` periods, the noise a share of δ."""
    return RoundedHead(per_period, periods, noise_over_lsb * lsb_v, lsb_v,
                       highest=3 if per_period < 11 else 5)
