"""The stability gate: a reading is taken when the instrument's output has stayed
inside a window for a dwell time (the way Keysight's laser software triggers).

``window`` is the spread allowed (largest minus smallest, per axis) of every frame of
the last ``dwell`` seconds; the frames must cover the whole dwell (the oldest one of
them at least ``dwell`` seconds old), so a single quiet frame after a gap is not
"stable". The reading taken is the mean of those frames, with their standard
deviation.

After a take the gate waits for the output to leave the window around the value it
took (the operator turns to the next position) before it can take again: a set of n
positions gives n readings, not n copies of the first. ``retake=True`` takes again at
once (n readings of one position, each from fresh frames).

Where the move to the next position is seen elsewhere (``moves_seen_elsewhere``: the
table's encoder read by another instrument, the mirror leaving an autocollimator's view),
the position just taken is left only by :meth:`moved`: an autocollimator nulled at each
face reads the same within the window at every face, and its reading moving at one face
(re-nulled, drifting) is no other face.

Where another instrument is read beside (the table's encoder), a reading is taken only
when each other instrument's newest reading came while the output was steady
(``others_since`` of :meth:`StabilityGate.feed`): one read before the dwell may be of the
move to this position, and its cell would hold the table half-way there.

When the link is lost and comes back (:meth:`restart`) the dwell starts again from the
frames after it: a reading is never the mean of frames from both sides of a gap in
which the instrument was not heard.
"""

from __future__ import annotations

from collections import deque
from dataclasses import dataclass

import numpy as np
from scipy.special import stdtrit

__all__ = ["ANGLE_UNITS", "OUT_OF_VIEW_GAP_S", "StabilityGate", "StableReading",
           "UnwrappedAngles", "gate_scale", "steady_motion"]

#: the units of a reading the auto-take window is applied to in arcseconds (a reading in
#: another unit, a readout's mm or none, is gated in that unit, and the window says so)
ANGLE_UNITS = ("deg", "arcsec")


def gate_scale(unit: str) -> float:
    """The factor from a reading's ``unit`` to the auto-take window's: degrees to
    arcseconds (a theodolite's, a readout's), else 1 (the window, in the window and in
    ``anglebench capture --stable``, is in arcseconds for every angle)."""
    return 3600.0 if unit == "deg" else 1.0


#: a spread is the output moving when the straight line through the frames moves at least
#: this many times the frames' own scatter about it …
MOTION_OVER_SCATTER = 2.0
#: … and its slope is not noise's: Student's t of the slope beyond its two-sided quantile at
#: this probability (noise alone is called moving once in a million looks, whatever the
#: number of frames; twice the scatter alone did so 0.27 % of the time with 8 frames)
MOTION_FALSE_RATE = 1e-6
#: the fewest frames a motion is told from
MOTION_FRAMES = 5


def steady_motion(times_s, values) -> float | None:
    """The rate (per second, in the values' unit) at which the frames move when their spread
    is a motion — the axis turning to the next point, a drift — and not noise: the least-
    squares line through them moves over their time span at least
    :data:`MOTION_OVER_SCATTER` times the peak-to-peak of the frames about it, and its slope
    is significant (:data:`MOTION_FALSE_RATE`). None for noise, or fewer than
    :data:`MOTION_FRAMES` frames. ``values``: one axis (1-D) or several (2-D, frames × axes:
    the axis that moves most). Why it matters: a window too tight for the noise is widened;
    a window that a moving output exceeds is right, and widening it would take a moving
    axis's reading as stable."""
    t = np.asarray(times_s, dtype=float)
    y = np.asarray(values, dtype=float)
    if y.ndim == 1:
        y = y[:, None]
    if t.size < MOTION_FRAMES or y.shape[0] != t.size or np.ptp(t) <= 0.0:
        return None
    dt = t - t.mean()
    sxx = float(dt @ dt)
    slopes = dt @ (y - y.mean(axis=0)) / sxx
    residuals = y - y.mean(axis=0) - np.outer(dt, slopes)
    moved = np.abs(slopes) * float(np.ptp(t))
    scatter = np.ptp(residuals, axis=0)
    se = np.sqrt(np.sum(residuals**2, axis=0) / (t.size - 2) / sxx)
    critical = float(stdtrit(t.size - 2, 1.0 - 0.5 * MOTION_FALSE_RATE))
    with np.errstate(divide="ignore", invalid="ignore"):
        significant = np.where(se > 0.0, np.abs(slopes) > critical * se, moved > 0.0)
    moving = (moved > MOTION_OVER_SCATTER * scatter) & significant & (moved > 0.0)
    if not np.any(moving):
        return None
    return float(slopes[int(np.argmax(np.where(moving, moved, -np.inf)))])

#: frames with no measurement (an autocollimator's mirror out of view) for this long between
#: two readings are a gap: the dwell starts again after it, and — the move to the next face
#: seen by the autocollimator alone — the position just taken is left. A turn to the next
#: face takes longer, by hand or by a motor; one frame marked not valid among good ones (a
#: speck, a vibration: 4 ms at 250 Hz) is neither
OUT_OF_VIEW_GAP_S = 0.5

#: times are sums of floats: a dwell of 0.3 s from 2.0 s ends at 2.3 s, not 2.2999999…
_EPS = 1e-9


@dataclass(frozen=True)
class StableReading:
    time_s: float
    mean: tuple[float, ...]
    std: tuple[float, ...]
    frames: int
    #: the ``tag`` fed with the first frame of the reading (the raw frame's index), or None
    first_tag: object = None


class StabilityGate:
    """The gate (see the module's docstring). Each frame costs the same however many the
    dwell holds: the spread is kept by monotonic queues of the largest and smallest values
    per axis (a sliding-window extreme), and the frames are averaged only when a reading is
    taken (the spread worked out again over every frame kept, at every frame, cost a 25 s
    dwell of a 1 kHz stream quadratic time in the window's thread)."""

    def __init__(self, window: float, dwell_s: float, retake: bool = False) -> None:
        if not (window > 0 and dwell_s > 0):
            raise ValueError("the window and the dwell time must be greater than 0")
        self.window, self.dwell_s, self.retake = window, dwell_s, retake
        #: the position just taken is left only when :meth:`moved` says so, not when the
        #: output leaves the window around it
        self.moves_seen_elsewhere = False
        #: (time, values, tag, sequence number) of the frames kept
        self._frames: deque[tuple[float, np.ndarray, object, int]] = deque()
        self._taken: np.ndarray | None = None
        self._count = 0  # frames fed: the sequence number of the next
        # per axis: (sequence number, value) of the frames that may yet be the largest
        # (values falling from front to back) and the smallest (rising)
        self._highs: list[deque[tuple[int, float]]] = []
        self._lows: list[deque[tuple[int, float]]] = []

    def _clear(self) -> None:
        self._frames.clear()
        for q in self._highs + self._lows:
            q.clear()

    def _spread_now(self) -> np.ndarray:
        return np.array([h[0][1] - lo[0][1] for h, lo in zip(self._highs, self._lows,
                                                              strict=True)])

    def _drop_oldest(self) -> None:
        seq = self._frames.popleft()[3]
        for q in self._highs + self._lows:
            if q and q[0][0] == seq:
                q.popleft()

    def spread(self) -> np.ndarray | None:
        """Largest minus smallest per axis over the frames kept (None before any)."""
        if not self._frames:
            return None
        return self._spread_now()

    def progress(self, time_s: float) -> tuple[str, float]:
        """Where the gate stands at ``time_s`` (the last frame's time): ``("taken", 0)``
        while it waits for the output to leave the position just taken, else
        ``("settling", f)`` with f the part of the dwell the frames kept have covered
        (0 to 1)."""
        if self._taken is not None:
            return "taken", 0.0
        if not self._frames:
            return "settling", 0.0
        return "settling", min(1.0, max(0.0, (time_s - self._frames[0][0]) / self.dwell_s))

    def restart(self) -> None:
        """Forget the frames of the dwell in progress (the link was lost: the next reading
        comes from frames after it). A position just taken stays taken: the same position
        after a reconnection is not taken twice."""
        self._clear()

    @property
    def waiting_for_move(self) -> bool:
        """A position was taken and the gate waits for the move to the next."""
        return self._taken is not None

    def moved(self) -> None:
        """The move to the next position was seen (elsewhere than in the frames fed: another
        instrument, the target leaving the view): the next stable dwell is taken, however
        near the position just taken it reads. The frames kept before it are forgotten."""
        self._taken = None
        self._clear()

    @property
    def dwell_since(self) -> float | None:
        """The time of the first frame of the dwell in progress (None before any)."""
        return self._frames[0][0] if self._frames and self._taken is None else None

    def feed(self, time_s: float, values, tag: object = None,
             others_since: float | None = None) -> StableReading | None:
        """One frame (``tag``: what names it, e.g. its index in the raw record; the reading
        carries its first frame's); the reading when this frame completes a stable dwell.
        ``others_since``: when the oldest of the other instruments' newest readings came (in
        this gate's time): while that is before the dwell's first frame the dwell goes on
        and nothing is taken (that reading may be of the move: a fresh-clone run paired face
        4's null with the encoder half-way from face 3)."""
        value = np.atleast_1d(np.asarray(values, dtype=float))
        if self._taken is not None:
            if self.moves_seen_elsewhere or np.all(np.abs(value - self._taken) <= self.window):
                return None  # still at the position just taken
            self._taken = None
            self._clear()
        if len(self._highs) != value.size:  # the first frame, or another instrument's
            self._clear()
            self._highs = [deque() for _ in range(value.size)]
            self._lows = [deque() for _ in range(value.size)]
        seq, self._count = self._count, self._count + 1
        self._frames.append((time_s, value, tag, seq))
        for axis, v in enumerate(value.tolist()):
            high, low = self._highs[axis], self._lows[axis]
            while high and high[-1][1] <= v:
                high.pop()
            high.append((seq, v))
            while low and low[-1][1] >= v:
                low.pop()
            low.append((seq, v))
        # keep the newest frames within the window of one another; older ones reset the dwell
        while len(self._frames) > 1 and np.any(self._spread_now() > self.window):
            self._drop_oldest()
        # frames older than the dwell are not needed beyond the oldest one covering it
        while len(self._frames) > 1 and self._frames[1][0] <= time_s - self.dwell_s + _EPS:
            self._drop_oldest()
        if time_s - self._frames[0][0] < self.dwell_s - _EPS:
            return None
        if others_since is not None and others_since < self._frames[0][0] - _EPS:
            return None
        values = np.array([v for _, v, _, _ in self._frames])
        reading = StableReading(time_s, tuple(values.mean(axis=0)),
                                tuple(values.std(axis=0, ddof=1) if len(values) > 1
                                      else np.zeros(values.shape[1])), len(values),
                                self._frames[0][2])
        self._clear()
        if not self.retake:
            self._taken = values.mean(axis=0)
        return reading


class UnwrappedAngles:
    """Angles in degrees as continuous offsets from the first frame's, each frame's
    difference from the frame before it taken to ±180°: a position at 0°/360° settles and
    averages where it is, and so does one 180° from the first frame (a theodolite's face II
    of its first target, whose offsets from a fixed origin jumped between +180° and −180°
    and never settled)."""

    def __init__(self) -> None:
        self.origin: np.ndarray | None = None
        self._last = np.zeros(0)
        self._offsets = np.zeros(0)

    def offsets(self, degrees) -> np.ndarray:
        """The frame's offsets (degrees) from the first frame, continuous from frame to frame."""
        value = np.atleast_1d(np.asarray(degrees, dtype=float))
        if self.origin is None or self.origin.shape != value.shape:
            self.origin, self._last, self._offsets = value, value, np.zeros_like(value)
        else:
            self._offsets = self._offsets + (value - self._last + 180.0) % 360.0 - 180.0
            self._last = value
        return self._offsets.copy()

    def angles(self, offsets) -> tuple[float, ...]:
        """Offsets (e.g. a reading's mean) back to angles in [0°, 360°)."""
        assert self.origin is not None
        return tuple(float(a) % 360.0 for a in self.origin + np.asarray(offsets, dtype=float))
