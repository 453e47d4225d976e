"""The ADC's integral nonlinearity (INL) in the fitted signal parameters: a stated bound ±b
on a transfer error e(v) of unknown shape, the same for every reading of a channel.

An INL is a function of the voltage, so a record meets the same e(v) at the same phase in
every period: averaging over periods or records removes none of it, and the fit's scatter
shows none of it (it falls on the harmonics the fit takes up). Its shape is not known, only
|e| ≤ b. A fitted coefficient is a weighted sum of the readings, β = Σₙ wₙ yₙ (the rows of
(XᵀX)⁻¹Xᵀ), so the error e(vₙ) moves it by Σₙ wₙ e(vₙ), at most b·Σₙ |wₙ| whatever the
shape: the offset's weights sum to 1 (bound b), a harmonic's (2/n)Σ|sin kθₙ| ≈ 4/π (bound
≈ 4b/π). A parameter (an amplitude, a phase) is a function of its order's pair of
coefficients; its bound is b·Σₙ |g·wₙ| with g its gradient there (linearised, as the fit's
own u).

The bound enters the u as a rectangular distribution of that half-width (u = B/√3), as the
interpolation error's budget takes the stated INL: a first-principles study
(tests/benchmarks/fringe_inl_study.py) with the INL shape drawn once a record (a bow, an S
curve, a sine of the code, a step; |e| ≤ b, scaled to 0.5 … 1 × b; b 0.3–3 mV at 1 V and
0.1 V, 200 records a cell) found every parameter covered at or above its floor that way,
where before 24 of 24 cells had parameters at 0–183 of 200; the tightest, the amplitude
ratio under a step INL, 192–194 of 200 at a width 1.02–1.05 times what its errors called
for, so the bound is nearly reached and a bound added linearly would only widen the rest.
Each channel's INL is its own: the bounds of the two channels' parameters combine as
independent. The bound is for any shape: one that a gentle shape (a bow, even in the
voltage) leaves far inside, the U then 20–180 times its errors' spread.
"""

from __future__ import annotations

import math

import numpy as np

from models.fringe.model import ChannelFit
from models.fringe.rounding_at_phases import PhaseGroups

__all__ = ["linearity_bounds"]

#: rows of the design taken at a time (a θ column of a million distinct phases)
_CHUNK = 65536


def linearity_bounds(groups: PhaseGroups, fit: ChannelFit, bound_v: float
                     ) -> dict[str, float]:
    """The largest change an INL within ±``bound_v`` (V) makes in each parameter of ``fit``
    ({"A0", "A1", "c1", …}: V, rad) at the readings' phases ``groups``; zeros where no bound
    is stated."""
    keys = ["A0"] + [f"{p}{k}" for k in fit.orders for p in ("A", "c")]
    if not bound_v > 0.0:
        return dict.fromkeys(keys, 0.0)
    x, inv = groups.design(fit.orders)
    p = x.shape[1]
    gradients = np.zeros((len(keys), p))  # each parameter's gradient over the coefficients
    gradients[0, 0] = 1.0
    undefined = []
    for i, k in enumerate(fit.orders):
        amplitude, phase = fit.amplitude[k], fit.phase[k]
        s, c = amplitude * math.cos(phase), amplitude * math.sin(phase)
        row = 1 + 2 * i
        if amplitude > 0:  # (as rounding_at_phases.parameter_variances: amplitude, phase)
            gradients[row, 1 + 2 * i: 3 + 2 * i] = (s / amplitude, c / amplitude)
            gradients[row + 1, 1 + 2 * i: 3 + 2 * i] = (-c / amplitude ** 2,
                                                       s / amplitude ** 2)
        else:
            gradients[row, 1 + 2 * i] = 1.0
            undefined.append(row + 1)  # a phase of no amplitude: no bound
    functionals = gradients @ inv  # each parameter's change per unit of Xᵀe
    total = np.zeros(len(keys))
    for start in range(0, x.shape[0], _CHUNK):
        part = x[start:start + _CHUNK]
        # a phase's readings all meet e(v) there: their weights add before the |…|
        total += np.abs(functionals @ part.T) @ groups.counts[start:start + _CHUNK]
    total[undefined] = math.inf
    return {key: float(bound_v * value) for key, value in zip(keys, total, strict=True)}
