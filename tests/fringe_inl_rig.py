"""A read head's two channels through an ADC with an integral nonlinearity (INL), from first
principles: imports nothing from models/.

At the true electrical phase φ:

    u_sin(φ) = o_s + A_s·sin(φ) + Σ_k a_k·sin(kφ + α_k)
    u_cos(φ) = o_c + A_c·sin(φ + 90° + q) + Σ_k b_k·sin(kφ + β_k)

Sample i is at φᵢ = φ₀ + 2π·i/N (φ₀ drawn each record), over whole periods. Each reading
gets white noise N(0, σ²), then the ADC's transfer error e(v), then its rounding to the step
δ: round((v + n + e(v + n))/δ)·δ. The INL e is one shape over the ADC's input range ±R,
drawn once per record and channel and scaled so that max|e| over the range is s·b, s drawn
in 0.5 … 1 and b the bound stated: a bow (x² about its mean), an S curve (x³ − x), a sine of
the code (a few cycles over the range, random phase), or a step (±1 on either side of a
random code); x = v/R.

The analysis is told N, so its phase is θᵢ = 2π·i/N (θ = 0 at the first sample); a term
sin(kφ + α) is sin(kθ + kφ₀ + α) there (:meth:`InlHead.parameters`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from tests.fringe_rounding_rig import head_signals

TWO_PI = 2.0 * math.pi
SHAPES = ("bow", "s_curve", "sine", "step")


def wrapped(angle: float) -> float:
    """An angle into [−π, π] (rad)."""
    return math.remainder(angle, TWO_PI)


def inl_shape(kind: str, rng: np.random.Generator):
    """One INL shape over x in [−1, 1], max |e| = 1 there (a function of x)."""
    grid = np.linspace(-1.0, 1.0, 20001)
    if kind == "bow":
        def raw(x):
            return x * x - 1.0 / 3.0
    elif kind == "s_curve":
        def raw(x):
            return x ** 3 - x
    elif kind == "sine":
        cycles, start = rng.uniform(1.5, 6.0), rng.uniform(0.0, TWO_PI)

        def raw(x):
            return np.sin(math.pi * cycles * x + start)
    elif kind == "step":
        where = rng.uniform(-0.6, 0.6)

        def raw(x):
            return np.where(x < where, -1.0, 1.0)
    else:
        raise ValueError(kind)
    scale = float(np.max(np.abs(raw(grid))))
    sign = rng.choice((-1.0, 1.0))
    return lambda x: sign * raw(np.clip(x, -1.0, 1.0)) / scale


@dataclass(frozen=True)
class InlHead:
    """One design (V, rad): N a period, whole periods, noise σ, ADC step δ, INL bound b
    over the ADC's range ±R, and the head's amplitude."""

    per_period: int
    periods: int
    amplitude_v: float
    inl_v: float
    shape: str
    noise_v: float = 0.0002
    lsb_v: float = 0.00025
    range_v: float = 0.0  # 0: 1.2 × the amplitude
    highest: int = 5
    quadrature_deg: float = -1.2

    def offsets(self) -> tuple[float, float]:
        return (0.021 * self.amplitude_v, -0.013 * self.amplitude_v)

    def amplitudes(self) -> tuple[float, float]:
        return (self.amplitude_v, 0.97 * self.amplitude_v)

    def harmonics(self):
        # a 3rd of 0.8 % and a 5th of 0.3 % of the amplitude
        a_s, a_c = self.amplitudes()
        return ({3: (0.008 * a_s, 0.4), 5: (0.003 * a_s, -2.2)},
                {3: (0.008 * a_c, 2.6), 5: (0.003 * a_c, 1.1)})

    def clean(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return head_signals(phi, self.offsets(), self.amplitudes(), self.quadrature_deg,
                            self.harmonics())

    def readings(self, rng: np.random.Generator) -> tuple[float, np.ndarray, np.ndarray]:
        """One record: (φ₀, sin readings, cos readings), V; each channel its own INL."""
        start = float(rng.uniform(0.0, TWO_PI))
        phi = start + np.arange(self.per_period * self.periods) * (TWO_PI / self.per_period)
        span = self.range_v or 1.2 * self.amplitude_v
        out = []
        for u in self.clean(phi):
            shape = inl_shape(self.shape, rng)
            scale = rng.uniform(0.5, 1.0) * self.inl_v
            v = u + rng.normal(0.0, self.noise_v, u.size)
            v = v + scale * shape(v / span)
            out.append(np.round(v / self.lsb_v) * self.lsb_v)
        return start, out[0], out[1]

    def parameters(self, start: float) -> dict[str, dict[str, float]]:
        """The head's parameters in the analysis's frame for φ₀ = ``start``, with the
        amplitude ratio and the quadrature error (deg)."""
        q = math.radians(self.quadrature_deg)
        sin_h, cos_h = self.harmonics()
        out: dict[str, dict[str, float]] = {}
        for label, offset, amplitude, phase, harmonics in (
                ("sin", self.offsets()[0], self.amplitudes()[0], 0.0, sin_h),
                ("cos", self.offsets()[1], self.amplitudes()[1], math.pi / 2 + q, cos_h)):
            p = {"A0": offset, "A1": amplitude, "c1": wrapped(start + phase)}
            for k, (a, c) in harmonics.items():
                p[f"A{k}"], p[f"c{k}"] = a, wrapped(k * start + c)
            out[label] = p
        out["pair"] = {"ratio": self.amplitudes()[1] / self.amplitudes()[0],
                       "quadrature_deg": self.quadrature_deg}
        return out

    def settings(self, inl_stated: bool = True) -> dict[str, float]:
        return {"lines_per_rev": 16384, "samples_per_period": self.per_period,
                "max_order": self.highest, "adc_lsb_mv": self.lsb_v * 1e3,
                "adc_linearity_mv": self.inl_v * 1e3 if inl_stated else 0.0}
