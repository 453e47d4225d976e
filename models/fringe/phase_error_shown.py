"""The per-sample phase error the readings show against a θ column: their scatter about the
fitted signals along the Lissajous figure beyond their scatter across it (covf77 F1).

A θ column's error δᵢ at sample i (the reference's own, independent from sample to sample)
moves the reading along the figure only: u(θᵢ + δᵢ) ≈ U(θᵢ) + U′(θᵢ)·δᵢ, by the figure's
speed |dU/dθ| times δᵢ. The signals' own noise moves it along and across alike (the same
noise on both channels, or any noise averaged over the phases of whole periods:
:mod:`models.fringe.equal_steps`). So, of the residuals of the fitted model, the mean
square along the figure T and across it R differ by the reference's share:

    σ_δ² ≈ (T − R) / mean(|dU/dθ|²)   (its positive part),

with ν(T − R)² / (T² + R²) degrees of freedom (Welch–Satterthwaite for a difference of two
mean squares of ν each; ν the residuals' n − p, taken down to what the samples share out).

A channel's residual scatter holds only about half of that variance (the share along each
channel's own slope), and a sample's phase all of it: left in the "Signal noise" row, a θ
column worse than its stated u was counted half (the audit's rig: σθ 0.02″ stated as 0.002″,
a sample's U covered 90.4 % where 95.45 % is printed, U/(2·scatter) 0.83). The phase
reference's u per sample is so taken as the larger of the stated u and this estimate
(models.fringe.report), and the readings' scatter beyond it is what "Signal noise" keeps
(models.fringe.reference_through_fit.reading_scatter_beyond: about the radial share).

Taken where it stands out: where the ratio T / (R + u²·mean(|dU/dθ|²)) of the scatter along
to what the noise and the stated u (0: none stated) put there passes the F test at
:data:`SIGNIFICANCE` (the degrees of freedom the samples share out, as the equal steps'
test takes them). Else the stated u is kept (an envelope, what the readings show being
within chance of it), and none enters where none is stated: a chance excess entered every
record of a θ column with a row of a few degrees of freedom (the bundled sample: 0.002″ on
2 degrees of freedom, its U 0.01347″ → 0.01383″ with nothing there to find), and a reference
stated at its true u was replaced by the estimate in half of the records.

Only a θ column's: N equal steps a period have their timing tested for the same excess and
refused where it stands out (:func:`models.fringe.equal_steps.step_scatter`); an estimated
phase follows the readings and shows none.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.fringe.equal_steps import along_and_across, f_survival
from models.fringe.model import model_signal

__all__ = ["SIGNIFICANCE", "PhaseErrorShown", "phase_error_shown"]

#: the chance, with no phase error beyond the stated u, that the scatter along the figure
#: passes the test by the noise alone (the level the lack-of-fit test of the phase means
#: takes, models.fringe.reference_through_fit.LACK_OF_FIT_LEVEL)
SIGNIFICANCE = 0.05


@dataclass(frozen=True)
class PhaseErrorShown:
    """The readings' per-sample phase error against their θ column (rad of a signal period,
    standard uncertainty), its degrees of freedom, the scatter along (tangential) and
    across (radial) the figure it is from (V rms), and the chance of so large a scatter
    along with no phase error beyond the stated u."""

    u_rad: float
    dof: float
    tangential_v: float
    radial_v: float
    p_value: float

    @property
    def beyond_stated(self) -> bool:
        """Whether the readings show more than the stated u beyond chance (the F test at
        :data:`SIGNIFICANCE`): the estimate then enters in its place."""
        return self.p_value < SIGNIFICANCE


def phase_error_shown(result, stated_u_rad: float = 0.0) -> PhaseErrorShown | None:
    """What ``result``'s readings show of their θ column's per-sample error (see the
    module's note), tested against the stated u ``stated_u_rad`` (rad of a signal period; 0:
    none stated); None for phases not from a θ column, or no degree of freedom."""
    if result.phase_source != "theta_column":
        return None
    theta = np.asarray(result.theta_rad, dtype=float)
    fits = (result.sin_fit, result.cos_fit)
    dof = theta.size - (1 + 2 * len(fits[0].orders))
    if dof < 1:
        return None
    r_s = np.asarray(result.u_sin, dtype=float) - model_signal(theta, fits[0])
    r_c = np.asarray(result.u_cos, dtype=float) - model_signal(theta, fits[1])
    split = along_and_across(theta, r_s, r_c, fits, dof)
    if split is None:
        return None
    tangential, radial, effective, speed2 = split
    excess = max(tangential - radial, 0.0)
    nu = max(effective * excess ** 2 / (tangential ** 2 + radial ** 2), 1.0)
    expected = radial + stated_u_rad ** 2 * speed2
    return PhaseErrorShown(math.sqrt(excess / speed2), nu, math.sqrt(tangential),
                           math.sqrt(radial), f_survival(tangential / expected, max(effective, 1.0)))
