"""The Allan deviation of an instrument's output: how its noise averages down.

For frames y_1 … y_N taken every τ0 seconds, at τ = m·τ0 the overlapping Allan variance
(IEEE Std 1139; Riley, NIST SP 1065, eq. 12, with the frames as the "fractional
frequency" samples) is

    σ²(τ) = 1 / (2 (N − 2m + 1)) · Σ_j (ȳ_{j+m} − ȳ_j)²,   j = 1 … N − 2m + 1

where ȳ_j is the mean of the m frames starting at j. White noise of standard
deviation σ gives σ(τ) = σ/√m; a steady drift D per second gives σ(τ) = D·τ/√2, so
the minimum shows how long averaging still helps.

The formula holds for frames evenly spaced in time. A stream is not, across a link lost
and found again or an instrument that paused: :func:`last_even_run` gives where the frames
after the last such gap begin, and only those are used (frames on both sides of a gap
taken as neighbours would mix two stretches of drift and report a τ that was not there).
"""

from __future__ import annotations

import numpy as np

__all__ = ["GAP_FACTOR", "allan_deviation", "last_even_run", "octave_factors"]

#: an interval longer than this many times the stream's typical interval is a gap: a polled
#: instrument's replies jitter (on a loaded PC by more than their interval), a pause or a
#: reconnection takes many
GAP_FACTOR = 3.0


def octave_factors(n: int) -> np.ndarray:
    """m = 1, 2, 4, … while at least two averages of m frames fit (N ≥ 2m)."""
    if n < 2:
        return np.array([], dtype=int)
    return 2 ** np.arange(int(np.floor(np.log2(n // 2))) + 1)


def allan_deviation(values, tau0_s: float, factors=None) -> tuple[np.ndarray, np.ndarray]:
    """τ (s) and the overlapping Allan deviation at each averaging factor m (default:
    octaves). Factors with fewer than 2m frames are left out."""
    y = np.asarray(values, dtype=float)
    if y.ndim != 1 or not np.all(np.isfinite(y)):
        raise ValueError("the Allan deviation needs one finite series")
    if not tau0_s > 0:
        raise ValueError("the frame interval must be greater than 0")
    m = octave_factors(len(y)) if factors is None else np.asarray(factors, dtype=int)
    m = m[(m >= 1) & (2 * m <= len(y))]
    cumulative = np.concatenate(([0.0], np.cumsum(y - y.mean())))
    deviations = []
    for k in m:
        means = (cumulative[k:] - cumulative[:-k]) / k  # mean of frames j … j+k-1
        steps = means[k:] - means[:-k]
        deviations.append(np.sqrt(0.5 * np.mean(steps ** 2)))
    return m * tau0_s, np.array(deviations)


def last_even_run(times_s, gap_factor: float = GAP_FACTOR) -> int:
    """The index of the first frame of the stream's last evenly spaced run (``times_s`` in
    seconds, ascending): after the last interval longer than ``gap_factor`` times the
    typical one (a gap: a pause, a link lost, frames at a slower rate before the rate was
    raised) or not positive (a clock that went back, a time repeated). The typical interval
    is the median of the newest 64. A rate lowered is not a gap: its faster frames stay in
    the series until they leave the panel's window of frames. 0 when the whole stream is
    one run."""
    t = np.asarray(times_s, dtype=float)
    if t.ndim != 1:
        raise ValueError("the frames' times must be one series")
    if len(t) < 2:
        return 0
    steps = np.diff(t)
    typical = float(np.median(steps[-64:]))
    if not typical > 0:  # the newest frames share a time: no spacing to go by
        return len(t)
    breaks = np.flatnonzero(~((steps > 0) & (steps <= gap_factor * typical)))
    return int(breaks[-1]) + 1 if len(breaks) else 0
