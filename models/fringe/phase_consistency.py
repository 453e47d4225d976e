"""Whether the phase given to a fringe record (N equal steps, or a θ column) is the phase its
signals show: the checks that refuse a wrong N, or a θ cell out of place, before any figure.

A wrong samples per period N makes the phase it assigns run ahead of, or behind, the signals'
by the same amount every period: fitted period by period against one model of each channel,
both channels' phases drift alike along a straight line, ``2π (N_true − N) / N_true`` a period (63 on a
record of 64 samples a period: −5.6° a period, 45° over 8 periods). A right N leaves the
periods' phases where the noise puts them. (Its fit's R² against the wrong phase was 0.946:
the gate of R² ≥ 0.9 let it through, and the error printed was 10.7" for 0.99".)

A θ cell typed wrong (another row's value, a DMS angle in the middle of a record in degrees,
1e308) puts one sample at a phase its signals contradict: the sample lies off the fitted
signals by far more than the other samples scatter about them.
"""

from __future__ import annotations

import math

import numpy as np

from models.fringe.model import TWO_PI, ChannelFit, fit_design, model_signal
from models.fringe.order_statistics import median
from models.messages import QT_TR_NOOP, message

__all__ = ["DRIFT_FLOOR_PERIOD", "DRIFT_SIGMAS", "ROW_FLOOR_DEG", "ROW_SIGMAS", "THETA_LIMIT_DEG",
           "check_samples_follow_n", "check_theta_rows", "check_theta_sequence", "period_drift"]

#: A θ beyond this (degrees of electrical phase) is no sample's phase: 2.8 million periods,
#: and a float64 still resolves 1e-9 of a period there.
THETA_LIMIT_DEG = 1e9
#: The drift of the phase over the record is refused beyond this many of its standard
#: uncertainties ...
DRIFT_SIGMAS = 6.0
#: ... and beyond this share of a period (a smaller drift over the whole record moves no
#: printed figure: the error is stated to 0.001" of a 79" period, 1.3e-5 of it).
DRIFT_FLOOR_PERIOD = 1e-3
#: A period fitted for the drift holds at least this share of its N samples.
PERIOD_SHARE = 0.5
#: A sample lies off the fitted signals by more than this many times their scatter
#: (a chance of 1e-15 a sample for normal noise along the path) ...
ROW_SIGMAS = 8.0
#: ... and by more than this phase (degrees of a period): its θ is not its phase.
ROW_FLOOR_DEG = 0.5


def _model(theta: np.ndarray, fits: tuple[ChannelFit, ChannelFit]
           ) -> tuple[np.ndarray, np.ndarray]:
    return model_signal(theta, fits[0]), model_signal(theta, fits[1])


#: Periods with gaps fitted one by one at most (the others are left out of the drift).
_GAP_PERIODS = 2000


def period_drift(place: np.ndarray, per_period: int, u: np.ndarray, fit: ChannelFit
                 ) -> tuple[float, float, float] | None:
    """(drift, its standard uncertainty, periods spanned): how far (rad of phase) one
    channel's phase moves from its first period to its last against N = ``per_period`` equal
    steps.

    ``place`` is each sample's place in the record (0, 1, 2 …; a gap keeps its place). Each
    period is fitted on its own (offset and the orders of ``fit``, at the phases
    ``2π place / N``): its fundamental's phase φ_p. A straight line through φ_p (unwrapped)
    against the period, each weighted by its samples, gives the drift a period. Its
    uncertainty is the larger of the channel's scatter about the periods' fits (white
    noise: u(φ_p)² = 2σ² / (A1² n_p)) and, with five periods or more, the periods' scatter
    about the line (a phase that wanders). None when fewer than two periods hold at least
    :data:`PERIOD_SHARE` of their N samples: the drift is not determined."""
    place = np.asarray(place, dtype=np.int64)
    u = np.asarray(u, dtype=float)
    amplitude = fit.amplitude.get(1, 0.0)
    if 1 not in fit.orders or not amplitude > 0:
        return None
    x = fit_design(np.arange(per_period) * (TWO_PI / per_period), fit.orders)
    params = x.shape[1]
    if per_period < params or place.size < 2:
        return None
    if int(place[-1]) == place.size - 1:  # no gap (the places rise): whole periods in a row
        full = np.arange(place.size // per_period)
        counts = np.full(full.size + 1, per_period)
        counts[-1] = place.size - full.size * per_period  # the last period's part
        block = u[: full.size * per_period].reshape(full.size, per_period)
        grid = np.full((1, per_period), np.nan)  # its one row: period full.size
        grid[0, : counts[-1]] = u[full.size * per_period:]
        first = full.size
    else:
        period, slot = np.divmod(place, per_period)
        counts = np.bincount(period)
        full = np.flatnonzero(counts == per_period)
        grid = np.full((counts.size, per_period), np.nan)
        grid[period, slot] = u
        block = grid[full]
        first = 0
    phases, weights, where = [], [], []
    squares, freedom = 0.0, 0
    if full.size:
        coef = np.linalg.pinv(x) @ block.T  # (params, periods)
        # the residual sum of squares of least squares: |u|² − |X c|²
        squares += float(np.sum(block * block)) - float(np.einsum("ip,ij,jp->", coef,
                                                                  x.T @ x, coef))
        freedom += full.size * (per_period - params)
        phases.append(np.arctan2(coef[2], coef[1]))
        weights.append(np.full(full.size, float(per_period)))
        where.append(full.astype(float))
    gaps = np.flatnonzero((counts < per_period) & (counts >= max(params + 1,
                                                                  PERIOD_SHARE * per_period)))
    for p in gaps[:_GAP_PERIODS]:
        row = grid[p - first]
        have = np.isfinite(row)
        coef, *_ = np.linalg.lstsq(x[have], row[have], rcond=None)
        residual = row[have] - x[have] @ coef
        squares += float(residual @ residual)
        freedom += int(have.sum()) - params
        phases.append(np.array([math.atan2(coef[2], coef[1])]))
        weights.append(np.array([float(have.sum())]))
        where.append(np.array([float(p)]))
    if not phases:
        return None
    at = np.concatenate(where)
    order = np.argsort(at)
    at, w = at[order], np.concatenate(weights)[order]
    phase = np.unwrap(np.concatenate(phases)[order])
    if at.size < 2:
        return None
    noise = math.sqrt(max(squares, 0.0) / freedom) if freedom > 0 else 0.0  # V
    total = float(np.sum(w))
    centre = float(np.sum(w * at)) / total
    spread = float(np.sum(w * (at - centre) ** 2))
    mean_phase = float(np.sum(w * phase)) / total
    slope = float(np.sum(w * (at - centre) * (phase - mean_phase))) / spread
    u_slope = math.sqrt(2.0) * noise / amplitude / math.sqrt(spread)
    if at.size >= 5:
        line = mean_phase + slope * (at - centre)
        scatter = float(np.sum(w * (phase - line) ** 2)) / (at.size - 2)
        u_slope = max(u_slope, math.sqrt(scatter / spread))
    periods = float(at[-1] - at[0])
    return slope * periods, u_slope * periods, periods


def check_samples_follow_n(place: np.ndarray, per_period: int, u_sin: np.ndarray,
                           u_cos: np.ndarray, fits: tuple[ChannelFit, ChannelFit]) -> None:
    """Refuse N samples per period that the signals do not follow: both channels' phases
    drift, the same way, from the first period to the last by more than
    :data:`DRIFT_SIGMAS` standard uncertainties and more than :data:`DRIFT_FLOOR_PERIOD` of
    a period (:func:`period_drift`). A wrong N moves both alike; a quadrature error that
    changes along the record moves one channel against the other, and is the signals' own
    (models.fringe.signal_quality shows it). The refusal says how many samples a period the
    signals show."""
    sine = period_drift(place, per_period, u_sin, fits[0])
    cosine = period_drift(place, per_period, u_cos, fits[1])
    if sine is None or cosine is None:
        return
    (drift_s, u_s, periods), (drift_c, u_c, _) = sine, cosine
    floor = DRIFT_FLOOR_PERIOD * TWO_PI
    if not all(abs(d) > max(DRIFT_SIGMAS * u_d, floor) for d, u_d in ((drift_s, u_s),
                                                                     (drift_c, u_c))):
        return
    if (drift_s > 0) != (drift_c > 0):
        return
    drift = 0.5 * (drift_s + drift_c)
    u_drift = 0.5 * math.hypot(u_s, u_c)
    per = drift / periods  # rad a period of N samples
    shown = per_period * TWO_PI / (TWO_PI + per)
    raise ValueError(message(QT_TR_NOOP(
        "the signals do not follow N = {n} samples per period: against it their phase "
        "drifts by {per}° a period, {drift}° from the first period to the last ({sigmas} "
        "times its uncertainty); they show {shown} samples a period. Give the N the record "
        "was taken with, or leave it out to estimate the phase from the signals"),
        n=per_period, per=f"{math.degrees(per):+.3g}", drift=f"{math.degrees(drift):+.3g}",
        sigmas=f"{abs(drift) / u_drift:.0f}" if u_drift > 0 else "∞",
        shown=f"{shown:.4g}"))


def _signals_phase(u_s: float, u_c: float, fits: tuple[ChannelFit, ChannelFit],
                   near_rad: float) -> float:
    """The phase (rad) at which the fitted signals come nearest the sample (u_s, u_c), the
    whole periods taken nearest ``near_rad``."""
    dense = np.linspace(0.0, TWO_PI, 3600, endpoint=False)
    m_s, m_c = _model(dense, fits)
    phase = float(dense[int(np.argmin((m_s - u_s) ** 2 + (m_c - u_c) ** 2))])
    return phase + TWO_PI * round((near_rad - phase) / TWO_PI)


def check_theta_rows(theta_rad: np.ndarray, u_sin: np.ndarray, u_cos: np.ndarray,
                     fits: tuple[ChannelFit, ChannelFit], row_of) -> None:
    """Refuse a θ cell that contradicts its sample's signals: the sample lies off the
    signals fitted against θ by more than :data:`ROW_SIGMAS` times the samples' scatter
    about them (from their median distance) and by more than :data:`ROW_FLOOR_DEG`
    of phase. The refusal names the (first) row, its θ and the phase its signals show.
    ``row_of(i)`` is the sheet row of sample i."""
    m_s, m_c = _model(theta_rad, fits)
    off = np.hypot(u_sin - m_s, u_cos - m_c)  # V
    sin_fit, cos_fit = fits
    amplitude = 0.5 * (sin_fit.amplitude.get(1, 0.0) + cos_fit.amplitude.get(1, 0.0))
    # σ of the samples' distance: as if all of it were along the path (a θ column's own
    # noise; its median is 0.674 σ), the larger of the two readings of the median (the
    # channels' noise alone, in two directions, has 1.18 σ; taken so, a θ jittered by
    # 0.5° was refused as 2.4° off, 4.9 σ)
    scatter = median(np.asarray(off, dtype=float).ravel()) / 0.6745
    floor = 2.0 * amplitude * math.sin(0.5 * math.radians(ROW_FLOOR_DEG))
    bad = np.flatnonzero(off > max(ROW_SIGMAS * scatter, floor))
    if not bad.size:
        return
    i = int(bad[0])
    theta = float(theta_rad[i])
    shown = _signals_phase(float(u_sin[i]), float(u_cos[i]), fits, theta)
    others = (message(QT_TR_NOOP(" (and {count} other rows)"), count=bad.size - 1)
              if bad.size > 1 else "")
    raise ValueError(message(QT_TR_NOOP(
        "row {row}, column 'theta_deg': θ = {theta}° is not the phase of its signals (u_sin "
        "{u_sin} V, u_cos {u_cos} V lie at {shown}° on the signals the other samples draw, "
        "{off}° away, where the samples scatter by {scatter}°){others}: a mistyped θ or a row "
        "out of place; check that row"),
        row=row_of(i), theta=f"{math.degrees(theta):.6g}", u_sin=f"{u_sin[i]:g}",
        u_cos=f"{u_cos[i]:g}", shown=f"{math.degrees(shown):.1f}",
        off=f"{math.degrees(abs(shown - theta)):.3g}",
        scatter=f"{math.degrees(scatter / amplitude) if amplitude > 0 else 0.0:.2g}",
        others=others))


#: A θ column steps by less than this (degrees, the median step) where it is read along a
#: motion (sequential), not in another order (shuffled rows).
SEQUENCE_STEP_DEG = 45.0
#: A θ column this share of whose θ lie within one period is wrapped into it.
WRAPPED_SHARE = 0.99


def check_theta_sequence(theta_deg: np.ndarray, row_of) -> None:
    """Refuse a θ that leaves the record's sequence and comes back: in a record read along a
    motion (median step below :data:`SEQUENCE_STEP_DEG`), a θ half a period or more away
    from both its neighbours while they lie within half a period of each other (an end row:
    half a period or more from the next, which steps on as the record does). Such a θ is a
    whole number of periods off (else its signals contradict it: :func:`check_theta_rows`),
    which the fit does not see, but the span of the record does: a record of 300° with one
    θ typed 360° too high passed as a whole period, and its error was extrapolated over the
    60° never sampled. Where the θ lie in [0°, 360°) or [−180°, 180°) (wrapped into one
    period, jumping a period at each wrap; :data:`WRAPPED_SHARE` of them, a few typed wrong
    may not) only a θ outside that period is judged
    (a θ typed a period off lies outside); a record with other jumps of half a period (two
    runs one after the other) is not judged. ``row_of(i)`` is the sheet row of sample i."""
    theta = np.asarray(theta_deg, dtype=float)
    if theta.size < 4:
        return
    step = np.diff(theta)
    jumps = np.abs(step) >= 180.0
    if not (np.any(jumps) and median(np.abs(np.asarray(step, dtype=float)).ravel()) < SEQUENCE_STEP_DEG):
        return
    # inner rows: a jump out and one back, the neighbours together
    out_and_back = (jumps[:-1] & jumps[1:] & (np.sign(step[:-1]) != np.sign(step[1:]))
                    & (np.abs(theta[2:] - theta[:-2]) < 180.0))
    candidates = [int(i) + 1 for i in np.flatnonzero(out_and_back)]
    explained = 2 * len(candidates)
    if jumps[0] and not jumps[1]:  # the ends: a jump to rows that step as the record does
        candidates.insert(0, 0)
        explained += 1
    if jumps[-1] and not jumps[-2]:
        candidates.append(theta.size - 1)
        explained += 1
    if not candidates:
        return
    wrapped = next(((low, low + 360.0) for low in (0.0, -180.0)
                    if np.count_nonzero((theta >= low) & (theta < low + 360.0))
                    >= WRAPPED_SHARE * theta.size), None)
    if wrapped is not None:
        # θ wrapped into one period: a wrap jumps a period (and noise at a wrap out and
        # back), but a θ typed a period off lies outside the period
        candidates = [i for i in candidates if not wrapped[0] <= theta[i] < wrapped[1]]
    elif explained != int(np.count_nonzero(jumps)):
        return  # other jumps (two runs one after the other): not judged
    if not candidates:
        return
    i = candidates[0]
    if i == 0:
        neighbours = message(QT_TR_NOOP("the next two rows are at {a}° and {b}°"),
                             a=f"{theta[1]:.6g}", b=f"{theta[2]:.6g}")
    elif i == theta.size - 1:
        neighbours = message(QT_TR_NOOP("the two rows before it are at {a}° and {b}°"),
                             a=f"{theta[-3]:.6g}", b=f"{theta[-2]:.6g}")
    else:
        neighbours = message(QT_TR_NOOP("the rows before and after it are at {a}° and {b}°"),
                             a=f"{theta[i - 1]:.6g}", b=f"{theta[i + 1]:.6g}")
    raise ValueError(message(QT_TR_NOOP(
        "row {row}, column 'theta_deg': θ = {theta}° leaves the record's sequence "
        "({neighbours}): a mistyped θ; check that row"),
        row=row_of(i), theta=f"{theta[i]:.6g}", neighbours=neighbours))
