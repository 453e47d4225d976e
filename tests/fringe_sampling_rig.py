"""A read head's two channels sampled at N equal steps a period by a clock with timing jitter,
then digitised by an ADC, from first principles: imports nothing from models/.

The read head (what a certificate states the parameters of), at its true electrical phase φ:

    u_sin(φ) = o_s + A_s·sin(φ) + Σ_k a_k·sin(kφ + α_k)
    u_cos(φ) = o_c + A_c·sin(φ + 90° + q) + Σ_k b_k·sin(kφ + β_k)

The sampling, N equal steps a period: sample i is meant at φ₀ + 2π·i/N, and the clock takes
it at φᵢ = φ₀ + 2π·i/N + εᵢ, εᵢ drawn N(0, jitter²) for each sample (the same instant for
both channels: one clock). The analysis is told N, so its phase is θᵢ = 2π·i/N: its frame
has θ = 0 at the first sample's nominal phase, φ = θ + φ₀, and a term sin(kφ + α) of the
head is sin(kθ + kφ₀ + α) there (:meth:`SampledHead.parameters`). Or (N = 0) a motion of
uneven steps (0.2 … 1.8 × 2π/32) from φ₀ with a θ column: a reference reads each sample's
phase as φᵢ − φ₀ + εᵢ, εᵢ its reading noise (``jitter_deg`` again), the same frame.

The ADC, ONCE PER RUN (a calibration's error, not noise): an offset on each channel drawn
N(0, u_offset²) and a gain ratio 1 + δ, δ from N(0, u_gain²), put on one channel or the other
at random (the ratio's error does not say which); then white noise on each reading and
rounding to the ADC's step.

The cells :data:`AUDIT_CELLS` are those of an audit's fringe rig (audit 69, cells FA, FD, FG:
the same head, sampling and ADC figures), written afresh here.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

TWO_PI = 2.0 * math.pi


def wrapped(angle: float) -> float:
    """An angle into [−π, π] (rad)."""
    return math.remainder(angle, TWO_PI)


@dataclass(frozen=True)
class SampledHead:
    """One design: the head, its sampling and its ADC (V, rad unless named)."""

    per_period: int
    samples: int
    noise_v: float
    offsets_v: tuple[float, float] = (0.010, -0.006)
    amplitudes_v: tuple[float, float] = (0.50, 0.49)
    quadrature_deg: float = 1.0
    #: {k: (amplitude V, phase rad)} of each channel's harmonics, as sin(kφ + phase)
    sin_harmonics: dict[int, tuple[float, float]] = field(default_factory=dict)
    cos_harmonics: dict[int, tuple[float, float]] = field(default_factory=dict)
    start_rad: float = 0.3  # φ₀: the true phase of the first sample's nominal instant
    jitter_deg: float = 0.02  # the clock's timing jitter, degrees of a signal period
    adc_offset_u_v: float = 0.001
    adc_gain_u: float = 0.001  # of the ratio of the channels' gains (0.001: 0.1 %)
    lsb_v: float = 0.00025

    def clean(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """The read head's own signals (V) at the true phases ``phi``."""
        q = math.radians(self.quadrature_deg)
        u_sin = self.offsets_v[0] + self.amplitudes_v[0] * np.sin(phi)
        u_cos = self.offsets_v[1] + self.amplitudes_v[1] * np.sin(phi + math.pi / 2 + q)
        for k, (a, c) in self.sin_harmonics.items():
            u_sin = u_sin + a * np.sin(k * phi + c)
        for k, (a, c) in self.cos_harmonics.items():
            u_cos = u_cos + a * np.sin(k * phi + c)
        return u_sin, u_cos

    def phases(self, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray]:
        """(where each sample really was, rad of the true phase φ; the θ column, degrees,
        NaN with N equal steps)."""
        noise = np.radians(rng.normal(0.0, self.jitter_deg, self.samples))
        if self.per_period:  # the clock's jitter moves the samples
            nominal = self.start_rad + np.arange(self.samples) * (TWO_PI / self.per_period)
            return nominal + noise, np.full(self.samples, np.nan)
        steps = rng.uniform(0.2, 1.8, self.samples - 1) * (TWO_PI / 32)
        moved = np.concatenate([[0.0], np.cumsum(steps)])  # the reference's noise its reading
        return self.start_rad + moved, np.degrees(moved + noise)

    def readings(self, rng: np.random.Generator) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """One run: the digitised channels (V), sampled, the ADC's offsets and gain ratio
        drawn once, noise and rounding per reading; and the θ column (degrees; NaN with N
        equal steps)."""
        phi, theta_deg = self.phases(rng)
        u_sin, u_cos = self.clean(phi)
        offsets = rng.normal(0.0, self.adc_offset_u_v, 2)
        ratio = 1.0 + rng.normal(0.0, self.adc_gain_u)
        gains = (1.0, ratio) if rng.random() < 0.5 else (1.0 / ratio, 1.0)
        out = []
        for u, gain, offset in ((u_sin, gains[0], offsets[0]), (u_cos, gains[1], offsets[1])):
            v = gain * u + offset + rng.normal(0.0, self.noise_v, u.size)
            out.append(np.round(v / self.lsb_v) * self.lsb_v)
        return out[0], out[1], theta_deg

    def parameters(self) -> dict[str, dict[str, float]]:
        """The read head's parameters in the analysis's frame (θ = 0 at the first sample's
        nominal phase; a channel as A0 + Σ A_k·sin(kθ + c_k)): {"sin": {"A0", "A1", "c1",
        "A3", "c3", …}, "cos": …} (V, rad)."""
        q = math.radians(self.quadrature_deg)
        start = self.start_rad
        out = {}
        for label, offset, amplitude, phase, harmonics in (
                ("sin", self.offsets_v[0], self.amplitudes_v[0], 0.0, self.sin_harmonics),
                ("cos", self.offsets_v[1], self.amplitudes_v[1], math.pi / 2 + q,
                 self.cos_harmonics)):
            p = {"A0": offset, "A1": amplitude, "c1": wrapped(start + phase)}
            for k, (a, c) in harmonics.items():
                p[f"A{k}"], p[f"c{k}"] = a, wrapped(k * start + c)
            out[label] = p
        return out

    def settings(self, lines_per_rev: int = 16384) -> dict[str, float]:
        """The analysis's settings that state this design: N, and the ADC's and the
        sampling's figures as the laboratory knows them."""
        return {"lines_per_rev": lines_per_rev, "samples_per_period": self.per_period,
                "adc_lsb_mv": self.lsb_v * 1e3, "adc_offset_u_mv": self.adc_offset_u_v * 1e3,
                "adc_gain_u_pct": self.adc_gain_u * 100, "phase_reference_u": self.jitter_deg}


# The audit's harmonics (its signals: h3 sin(3φ + .7), h5 sin(5φ + 2.1) on the sine channel
# and .8 h3 cos(3φ + 1.9), 1.1 h5 cos(5φ − .6) on the cosine one, all × the amplitude),
# here as sines: cos x = sin(x + 90°).
def _audit_harmonics(amplitudes: tuple[float, float], h3: float, h5: float
                     ) -> tuple[dict[int, tuple[float, float]], dict[int, tuple[float, float]]]:
    a_s, a_c = amplitudes
    return ({3: (a_s * h3, 0.7), 5: (a_s * h5, 2.1)},
            {3: (0.8 * h3 * a_c, 1.9 + math.pi / 2), 5: (1.1 * h5 * a_c, -0.6 + math.pi / 2)})


def _audit_cell(per_period: int, samples: int, noise_v: float, h3: float = 0.005,
                h5: float = 0.002, **rest) -> SampledHead:
    amplitudes = rest.pop("amplitudes_v", (0.50, 0.49))
    sin_h, cos_h = _audit_harmonics(amplitudes, h3, h5)
    return SampledHead(per_period, samples, noise_v, amplitudes_v=amplitudes,
                       sin_harmonics=sin_h, cos_harmonics=cos_h, **rest)


#: the audit's cells: FA (16 a period, 4 periods, 1 mV), FD (64 a period, 20 periods, 0.2 mV,
#: a coarse ADC); controls where the audit found cos c1 wide: FG (24 a period, 2.5 periods,
#: 2 mV), FE (uneven steps with a θ column, 5 periods, 2 mV)
AUDIT_CELLS: dict[str, SampledHead] = {
    "FA": _audit_cell(16, 64, 0.001),
    "FD": _audit_cell(64, 1280, 0.0002, h3=0.01, quadrature_deg=-2.0, lsb_v=0.00061,
                      adc_offset_u_v=0.002, adc_gain_u=0.003),
    "FG": _audit_cell(24, 60, 0.002, offsets_v=(0.03, -0.006), amplitudes_v=(0.50, 0.45),
                      quadrature_deg=3.0),
    "FE": _audit_cell(0, 160, 0.002),
}
