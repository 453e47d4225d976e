"""Whether samples taken as N equal steps a period were at equal steps: their scatter along
the Lissajous figure against their scatter across it (cov76 F4).

With N samples a period and no θ column, each sample's phase is taken as 2π i / N. A
sample taken at 2π i / N + εᵢ instead (sampling jitter) reads the channels there: the
error moves it along the figure only, by the figure's speed |dU/dθ| · εᵢ, and the phase
atan2(u_sin, u_cos) less the assumed step carries εᵢ as if it were interpolation error (an
audit's records with 3° and 5° of jitter printed a half range of 1.7″ and 3.6″ for a true
0.71″, with nothing said). The signals' own noise moves a sample along and across the
figure alike (isotropic: the same noise on both channels, or any noise averaged over the
phases of whole periods). So, of the residuals of the fitted model (a vector (r_sin, r_cos)
a sample), the part along the unit tangent of the fitted figure (tangential) and the part
across it (radial) scatter alike when the steps are equal, and the tangential one exceeds
when they are not.

Where the record holds two whole periods or more, each period's readings less the next
period's at the same phase (periods 1 − 0, 3 − 2, …: independent differences, the fitted
model and whatever is the same at a phase in every period cancel, an ADC's rounding or a
harmonic left out), with each phase's mean difference taken off when there are two pairs or
more (a head whose amplitude and quadrature drift along the record steadily moves along
and across the figure unequally, 3 : 1 for a quadrature error: a fit of the whole record
leaves it in its residuals, a difference of two periods its change a period, the mean of
those its steady part): (pairs − 1) N degrees of freedom each. No fit mixes the phases, so a
jitter stays along the figure. Else (less than two whole periods) the residuals of the fit
of the whole record: n − p each (the fit takes p from each part: the trace of its hat
matrix, the same for both channels, times a unit projection per sample; the fit mixes the
samples, so a jitter's part, about p / n, leaks across and the test is the weaker). The
ratio T / R of the mean squares is about F-distributed with those degrees of freedom,
taken down to what the samples share out: a few samples that scatter unlike the rest (one
typed 0.5 V off in a record without noise; an ADC's rounding flipping a reading by a step
at a few phases, the noise below the step: N = 16, 10 periods, noise 0.1 of a 1 mV step
gave 0.28 mV along against 0.17 mV across, "128" degrees of freedom) decide both sums
however many they are: ν·min(1, 2 (Σs)² / (m Σs²)), s the squares along and across of each
of the m differences or residuals (1 for normal noise). A stated jitter (the phase
reference u, with N equal steps the sampling's timing) is expected along: R +
u²·mean(|dU/dθ|²). The steps are refused as unequal when the ratio to that passes the F test
at :data:`SIGNIFICANCE` and the jitter it shows exceeds :data:`JITTER_FLOOR_PERIOD` of a
period.

:data:`SIGNIFICANCE` is chosen by simulation (tests/fringe_jitter_rig.py, the audit's head):
of 8400 records at equal steps analysed (the signals' noise 1, 2, 5, 10, 20 mV; 1–8
periods, 0.625 refused as short; N 8–256; 40 each) none was refused, and of 3360 with the
cosine channel's noise twice the sine's none; their p values are uniform or above (0.62 %
and 0.54 % below 0.01, 0.04 % and 0 below 0.001, none below 1e-5). The level is 1e-7, not
the 1e-5 those allow: the validation report (``anglebench validate``) analyses thousands of
records at equal steps, and at 1e-5 one of them (64 steps, 4 periods, 4 mV: p 1.2e-6) was
refused. The test's reach (36 records a cell: 16, 64, 256 steps; 1, 2, 8 periods): 3° of
jitter refused in 32 at 1 and 5 mV and 25 at 20 mV, 1° in 32, 28 and 4, 0.3° in 30, 10 and
0; those it missed at 1 mV were one period of 16 steps, whose fit takes 7 of 16 degrees of
freedom from each part.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.fringe.model import ChannelFit, model_signal, model_slope

__all__ = ["JITTER_FLOOR_PERIOD", "SIGNIFICANCE", "StepScatter", "along_and_across",
           "f_survival", "step_scatter", "unequal_steps"]

TWO_PI = 2.0 * math.pi
#: the chance, at equal steps, that the tangential scatter passes the test by the noise alone
#: (see the module's note for why so small)
SIGNIFICANCE = 1e-7
#: a jitter below this share of a period (0.0036°; 0.001″ at 16384 lines, the last digit
#: printed) moves no printed figure, and is not refused however clear it stands out
JITTER_FLOOR_PERIOD = 1e-5


@dataclass(frozen=True)
class StepScatter:
    """The residuals' scatter along (tangential) and across (radial) the fitted Lissajous
    figure (V rms, each with ``dof`` degrees of freedom), the jitter the excess shows (rad
    rms of phase, 0 when none), the chance of so large a ratio at equal steps (with the
    stated jitter) and whether the scatter was within the phases."""

    tangential_v: float
    radial_v: float
    dof: int
    jitter_rad: float
    p_value: float
    within_phases: bool


def f_survival(x: float, dof: float) -> float:
    """P(F > ``x``) for Fisher's F with ``dof`` and ``dof`` degrees of freedom."""
    from scipy.special import fdtrc  # imported late, as start-up pays it

    return float(fdtrc(dof, dof, x))


def _whole_periods(place: np.ndarray, per_period: int, channels: list[np.ndarray]
                   ) -> list[np.ndarray]:
    """Each channel's readings of the record's whole periods (no sample missing), as rows
    of N (periods × N)."""
    period, slot = np.divmod(place, per_period)
    counts = np.bincount(period)
    full = np.flatnonzero(counts == per_period)
    if int(place[-1]) == place.size - 1:  # no gap: the periods in a row
        whole = place.size // per_period
        return [c[: whole * per_period].reshape(whole, per_period) for c in channels]
    keep = np.isin(period, full)
    rows = np.searchsorted(full, period[keep])
    out = []
    for c in channels:
        grid = np.zeros((full.size, per_period))
        grid[rows, slot[keep]] = c[keep]
        out.append(grid)
    return out


def along_and_across(at: np.ndarray, r_s: np.ndarray, r_c: np.ndarray,
                     fits: tuple[ChannelFit, ChannelFit], dof: int
                     ) -> tuple[float, float, float, float] | None:
    """(tangential, radial, effective degrees of freedom, mean squared speed): the mean
    squares (V², over ``dof``) of the residuals (``r_s``, ``r_c``) at the phases ``at``
    along and across the fitted Lissajous figure, the degrees of freedom the samples share
    out, and mean(|dU/dθ|²) (V² a rad² of phase); None where the figure stands still or
    nothing scatters across it."""
    d_s, d_c = model_slope(at, fits[0]), model_slope(at, fits[1])
    speed = np.hypot(d_s, d_c)
    if not np.all(speed > 0.0):
        return None
    along2 = ((r_s * d_s + r_c * d_c) / speed) ** 2
    across2 = ((r_s * d_c - r_c * d_s) / speed) ** 2
    tangential = float(np.sum(along2)) / dof
    radial = float(np.sum(across2)) / dof
    if not radial > 0.0:
        return None
    # the degrees of freedom the samples share out: a few samples that scatter unlike the
    # rest (one typed 0.5 V off in a record without noise; an ADC's rounding flipping by a
    # step at a few phases, the noise below the step) decide both sums, whatever their
    # count; normal noise, along and across together: 2 (Σs)² / (m Σs²) = 1
    share = (along2 + across2).ravel()
    effective = min(float(dof), 2.0 * dof * float(np.sum(share)) ** 2
                    / (share.size * float(share @ share)))
    return tangential, radial, effective, float(np.mean(speed * speed))


def step_scatter(theta_rad: np.ndarray, u_sin: np.ndarray, u_cos: np.ndarray,
                 fits: tuple[ChannelFit, ChannelFit], samples_per_period: int,
                 stated_u_rad: float = 0.0) -> StepScatter | None:
    """The scatter of the samples along and across the fitted figure (see the module's
    note), at the phases ``theta_rad`` (N = ``samples_per_period`` equal steps from 0, a
    gap keeping its step); None when it has no degree of freedom or no scatter."""
    theta = np.asarray(theta_rad, dtype=float)
    n = int(samples_per_period)
    orders = fits[0].orders
    params = 1 + 2 * len(orders)
    place = np.rint(theta / (TWO_PI / n)).astype(np.int64)
    place -= place[0]
    grids = _whole_periods(place, n, [np.asarray(u_sin, dtype=float),
                                      np.asarray(u_cos, dtype=float)])
    pairs = grids[0].shape[0] // 2
    within = pairs >= 1
    if within:  # one period less the next at each phase, the drift's mean change off
        at = np.arange(n) * (TWO_PI / n)
        r_s, r_c = (g[1:2 * pairs:2] - g[0:2 * pairs:2] for g in grids)
        dof = pairs * n
        if pairs >= 2:
            r_s, r_c = r_s - r_s.mean(axis=0), r_c - r_c.mean(axis=0)
            dof = (pairs - 1) * n
    else:  # about the fit of the whole record
        at = theta
        r_s = np.asarray(u_sin, dtype=float) - model_signal(theta, fits[0])
        r_c = np.asarray(u_cos, dtype=float) - model_signal(theta, fits[1])
        dof = theta.size - params
    if dof < 1:
        return None
    split = along_and_across(at, r_s, r_c, fits, dof)
    if split is None:
        return None
    tangential, radial, effective, speed2 = split
    if within:  # differences: twice a reading's variance, along and across alike
        tangential, radial = 0.5 * tangential, 0.5 * radial
    expected = radial + stated_u_rad ** 2 * speed2
    jitter = math.sqrt(max(tangential - radial, 0.0) / speed2)
    return StepScatter(math.sqrt(tangential), math.sqrt(radial), max(int(effective), 1),
                       jitter, f_survival(tangential / expected, max(effective, 1.0)), within)


def unequal_steps(scatter: StepScatter | None) -> bool:
    """Whether ``scatter`` says the steps are not equal: its tangential excess passes the F
    test at :data:`SIGNIFICANCE` and shows a jitter above :data:`JITTER_FLOOR_PERIOD`."""
    return (scatter is not None and scatter.p_value < SIGNIFICANCE
            and scatter.jitter_rad > JITTER_FLOOR_PERIOD * TWO_PI)
