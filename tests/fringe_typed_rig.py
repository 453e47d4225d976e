"""A read head's two channels sampled at N equal steps over whole periods and typed to a few
decimals of a volt (no ADC LSB stated), from first principles: imports nothing from models/.

The head is tests/fringe_rounding_rig.py's (:func:`head_signals`) in a frame of its own: the
true phase at the first sample φ₀ drawn for each record, offsets −9 / +21 mV, amplitudes
0.61 / 0.55 V, quadrature −1.5°, a 3rd of 0.6 % and a 5th of 0.25 % of each amplitude. An
ADC offset (u 0.3 mV a channel) and gain ratio (u 0.03 %, on the sin channel) are drawn
once a record and stated; white noise σ is added to each reading, which is then typed to
``decimals`` decimals ("%.2f": the rounding of the reading's own value, the same at a phase
in every period while σ is well below the step).

The truth is the head's own: the half peak-to-peak of its continuous as-found interpolation
error atan2(u_sin, u_cos) − φ over a whole period (20,000 phases), in arcsec of a shaft with
``LINES`` lines.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from tests.fringe_rounding_rig import head_signals

TWO_PI = 2.0 * math.pi
LINES = 16384
ADC_OFFSET_U_MV, ADC_GAIN_U_PCT, PHASE_REFERENCE_U_DEG = 0.3, 0.03, 0.002


@dataclass(frozen=True)
class TypedHead:
    """One design: N a period, whole periods, the digits typed, the noise as a share of
    the typed step."""

    per_period: int
    periods: int
    decimals: int
    noise_over_step: float
    offsets_v: tuple[float, float] = (-0.009, 0.021)
    amplitudes_v: tuple[float, float] = (0.61, 0.55)
    quadrature_deg: float = -1.5

    @property
    def step_v(self) -> float:
        return 10.0 ** -self.decimals

    def harmonics(self):
        a_s, a_c = self.amplitudes_v
        return ({3: (0.006 * a_s, -1.3), 5: (0.0025 * a_s, 0.4)},
                {3: (0.006 * a_c, 2.6), 5: (0.0025 * a_c, -2.2)})

    def clean(self, phi: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        return head_signals(phi, self.offsets_v, self.amplitudes_v, self.quadrature_deg,
                            self.harmonics())

    def rows(self, rng: np.random.Generator) -> list[str]:
        """One record as a user's file holds it: "u_sin,u_cos" rows of typed readings."""
        start = rng.uniform(0.0, TWO_PI)
        phi = start + np.arange(self.per_period * self.periods) * (TWO_PI / self.per_period)
        u_sin, u_cos = self.clean(phi)
        offsets = rng.normal(0.0, ADC_OFFSET_U_MV * 1e-3, 2)
        gain = 1.0 + rng.normal(0.0, ADC_GAIN_U_PCT / 100.0)
        sigma = self.noise_over_step * self.step_v
        u_sin = u_sin * gain + offsets[0] + rng.normal(0.0, sigma, phi.size)
        u_cos = u_cos + offsets[1] + rng.normal(0.0, sigma, phi.size)
        typed = f"%.{self.decimals}f"
        return ["u_sin,u_cos"] + [f"{typed % s},{typed % c}" for s, c in zip(u_sin, u_cos, strict=True)]

    def write(self, path: Path, rng: np.random.Generator) -> Path:
        path.write_text("\n".join(self.rows(rng)) + "\n", encoding="utf-8")
        return path

    def true_half_range_arcsec(self) -> float:
        """The head's own half peak-to-peak as-found error over a whole period (arcsec)."""
        phi = np.linspace(0.0, TWO_PI, 20000, endpoint=False)
        u_sin, u_cos = self.clean(phi)
        error = np.remainder(np.arctan2(u_sin, u_cos) - phi + math.pi, TWO_PI) - math.pi
        return float(np.ptp(error)) / 2.0 * 1296000.0 / (TWO_PI * LINES)

    def options(self, lsb_mv: float = 0.0) -> list[str]:
        """The command line's options: N, the ADC's figures stated (an LSB only if
        ``lsb_mv``), a linear ADC (its linearity stated, negligible)."""
        out = ["--samples-per-period", str(self.per_period), "--lines-per-rev", str(LINES),
               "--adc-offset-u-mv", str(ADC_OFFSET_U_MV), "--adc-gain-u-pct",
               str(ADC_GAIN_U_PCT), "--phase-reference-u", str(PHASE_REFERENCE_U_DEG),
               "--adc-linearity-mv", "0.001"]
        return out + (["--adc-lsb-mv", f"{lsb_mv:g}"] if lsb_mv else [])


#: the certificate's details: the decided quantity the half range, tolerance 3″
METADATA = {"tolerance": 3.0, "tolerance_unit": "arcsec", "decision_rule": "simple",
            "decision_quantity": "half_range",
            "standards": [{"description": "ADC (data acquisition)", "serial": "DAQ-3",
                           "certificate_no": "C-ADC-3", "uncertainty": None,
                           "uncertainty_unit": "arcsec", "basis": "U95"}]}
