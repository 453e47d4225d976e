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

Where the record holds two whole periods or more at :data:`PERIOD_FIT_STEPS` steps or more,
each whole period is fitted on its own (offset and fundamental: a head whose amplitude and
quadrature drift along the record moves along and across the figure unequally, 3 : 1 for a
quadrature error, which a fit of the whole record leaves in its residuals) and each phase's
mean over the periods is taken off (what is the same at a phase in every period, an ADC's
rounding or a harmonic left out, stays out of it): (P − 1)(N − 5) degrees of freedom each.
Else the residuals of the fit of the whole record: n − p each (the fit takes p from each
part: the trace of its hat matrix, the same for both channels, times a unit projection per
sample). The ratio T / R of the mean squares is about F-distributed with those degrees of
freedom. A fit mixes the samples of a period, so a jitter's part leaks across the figure
(about p / N of it): the test is the weaker, never the less calibrated. A stated jitter (the
phase reference u, with N equal steps the sampling's timing) is expected along:
R + u²·mean(|dU/dθ|²). The steps are refused as unequal when the
ratio to that passes the F test at :data:`SIGNIFICANCE` and the jitter it shows exceeds
:data:`JITTER_FLOOR_PERIOD` of a period.

:data:`SIGNIFICANCE` is chosen by simulation (tests/models/fringe/test_fringe_equal_steps.py,
tests/fringe_jitter_rig.py): records at equal steps with the signals' noise 1–20 mV,
0.625–8 periods and N 8–256 are accepted in 99.9 % or more of the records.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.fringe.model import ChannelFit, fit_design, model_signal, model_slope

__all__ = ["JITTER_FLOOR_PERIOD", "PERIOD_FIT_STEPS", "SIGNIFICANCE", "StepScatter", "step_scatter",
           "unequal_steps"]

TWO_PI = 2.0 * math.pi
#: the fewest steps a period whose periods are fitted one by one (offset and fundamental:
#: five unknowns a channel, which take a jitter's share of about 5 / N across the figure)
PERIOD_FIT_STEPS = 20
#: the chance, at equal steps, that the tangential scatter passes the test by the noise alone
SIGNIFICANCE = 1e-5
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


def _f_survival(x: float, dof: int) -> float:
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
    grids = (_whole_periods(place, n, [np.asarray(u_sin, dtype=float),
                                       np.asarray(u_cos, dtype=float)])
             if n >= PERIOD_FIT_STEPS else [])
    within = bool(grids) and grids[0].shape[0] >= 2
    if within:  # whole periods fitted one by one, less each phase's mean over the periods
        at = np.arange(n) * (TWO_PI / n)
        x = fit_design(at, (1,))
        solve = np.linalg.pinv(x)
        r_s, r_c = (g - (x @ (solve @ g.T)).T for g in grids)
        r_s, r_c = r_s - r_s.mean(axis=0), r_c - r_c.mean(axis=0)
        dof = (grids[0].shape[0] - 1) * (n - x.shape[1])
    else:  # about the fit of the whole record
        at = theta
        r_s = np.asarray(u_sin, dtype=float) - model_signal(theta, fits[0])
        r_c = np.asarray(u_cos, dtype=float) - model_signal(theta, fits[1])
        dof = theta.size - params
    if dof < 1:
        return None
    d_s, d_c = model_slope(at, fits[0]), model_slope(at, fits[1])
    speed = np.hypot(d_s, d_c)
    if not np.all(speed > 0.0):
        return None
    tangential = float(np.sum(((r_s * d_s + r_c * d_c) / speed) ** 2)) / dof
    radial = float(np.sum(((r_s * d_c - r_c * d_s) / speed) ** 2)) / dof
    if not radial > 0.0:
        return None
    speed2 = float(np.mean(speed * speed))  # V² a rad² of phase
    expected = radial + stated_u_rad ** 2 * speed2
    jitter = math.sqrt(max(tangential - radial, 0.0) / speed2)
    return StepScatter(math.sqrt(tangential), math.sqrt(radial), dof, jitter,
                       _f_survival(tangential / expected, dof), within)


def unequal_steps(scatter: StepScatter | None) -> bool:
    """Whether ``scatter`` says the steps are not equal: its tangential excess passes the F
    test at :data:`SIGNIFICANCE` and shows a jitter above :data:`JITTER_FLOOR_PERIOD`."""
    return (scatter is not None and scatter.p_value < SIGNIFICANCE
            and scatter.jitter_rad > JITTER_FLOOR_PERIOD * TWO_PI)
