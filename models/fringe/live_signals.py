"""The live view of a read head's signals while it is mounted: a sliding window of the last
periods of a sin/cos stream, its signal figures judged against a tolerance preset, the
interpolation error the window shows, and the lowest and highest of each figure since the
last reset.

No phase reference comes with a stream: the phase is estimated from the signals
(Heydemann's ellipse, then refined against the channels' own harmonics, as the workbench
does for a record without one), so the figures are those of the signals themselves:
amplitudes, ratio, phase between the channels, offsets and harmonic content
(models/fringe/signal_tolerance.py). The interpolation error is what an arctangent
interpolator makes of the raw signals: ``atan2(u_sin, u_cos) − θ`` with θ the estimated
phase, its mean removed, in electrical degrees.

A window that covers less than :data:`MIN_PERIODS` periods (the scale stands still) gives
no figures: it says so (:attr:`LiveFigures.problem`) rather than fitting a piece of an
ellipse.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from models.fringe.model import ChannelFit, model_signal, refine_phase
from models.fringe.phase import fit_ellipse, unwrapped
from models.fringe.signal_tolerance import Judgement, TolerancePreset, judge, signal_figures
from models.messages import QT_TR_NOOP, message

__all__ = ["MIN_PERIODS", "Extremes", "LiveFigures", "SampleWindow", "live_figures"]

#: the fewest periods a window must cover to give figures
MIN_PERIODS = 1.0
#: the harmonics fitted to each channel of the window (the content's 2nd and 3rd)
LIVE_ORDERS = (1, 2, 3)
#: a window is thinned to at most this many samples for its fit (evenly, every k-th sample)
FIT_SAMPLES = 2048
#: a channel whose fundamental's amplitude is below this many times the rms of what its fit
#: leaves is not above its noise: only the amplitudes are judged (a head that lost its signal)
MIN_SIGNAL_TO_NOISE = 3.0


class SampleWindow:
    """The newest samples of a stream (at most ``capacity``), each with the index of the
    line it came from; :meth:`last_periods` gives the samples of the last periods."""

    def __init__(self, capacity: int = 200_000) -> None:
        self.capacity = int(capacity)
        self._data = np.empty((3, 2 * self.capacity))  # u_sin, u_cos, line index
        self._start = 0
        self._stop = 0
        #: samples added since the start (or the last clear)
        self.total = 0

    def __len__(self) -> int:
        return self._stop - self._start

    def clear(self) -> None:
        self._start = self._stop = 0
        self.total = 0

    def add(self, u_sin, u_cos, line_index) -> None:
        u_sin = np.asarray(u_sin, dtype=float)
        n = u_sin.size
        if n == 0:
            return
        self.total += n
        if n >= self.capacity:
            self._data[0, :self.capacity] = u_sin[-self.capacity:]
            self._data[1, :self.capacity] = np.asarray(u_cos, dtype=float)[-self.capacity:]
            self._data[2, :self.capacity] = np.asarray(line_index, dtype=float)[-self.capacity:]
            self._start, self._stop = 0, self.capacity
            return
        if self._stop + n > self._data.shape[1]:  # move the newest to the front
            keep = min(len(self), self.capacity - n)
            self._data[:, :keep] = self._data[:, self._stop - keep:self._stop]
            self._start, self._stop = 0, keep
        self._data[0, self._stop:self._stop + n] = u_sin
        self._data[1, self._stop:self._stop + n] = u_cos
        self._data[2, self._stop:self._stop + n] = line_index
        self._stop += n
        if len(self) > self.capacity:
            self._start = self._stop - self.capacity

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(u_sin, u_cos, line index) of every sample held, oldest first (views)."""
        d = self._data[:, self._start:self._stop]
        return d[0], d[1], d[2].astype(np.int64)

    def last_periods(self, periods: float, since_index: int | None = None
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray, float]:
        """The samples of the last ``periods`` signal periods (or all held, when they cover
        fewer) and the periods they cover, counted on the samples' angle about their centre.
        ``since_index``: no sample of an older line (the window's age limit: a head that lost
        its signal would otherwise be judged on the periods it gave before)."""
        u_sin, u_cos, index = self.arrays()
        if since_index is not None and index.size and index[0] < since_index:
            start = int(np.searchsorted(index, since_index))
            u_sin, u_cos, index = u_sin[start:], u_cos[start:], index[start:]
        if u_sin.size < 3:
            return u_sin, u_cos, index, 0.0
        angle = unwrapped(np.arctan2(u_sin - u_sin.mean(), u_cos - u_cos.mean()))
        travel = np.abs(angle - angle[-1]) / (2.0 * math.pi)
        inside = np.nonzero(travel >= periods)[0]
        first = int(inside[-1]) + 1 if inside.size else 0
        covered = float(travel[first:].max()) if first < u_sin.size else 0.0
        return u_sin[first:], u_cos[first:], index[first:], covered


@dataclass
class LiveFigures:
    """What one refresh of the live view shows."""

    #: the samples of the window, and the periods they cover
    samples: int
    periods: float
    #: the signal figures (signal_tolerance.QUANTITIES; the preset's units)
    figures: dict[str, float] = field(default_factory=dict)
    judgements: list[Judgement] = field(default_factory=list)
    #: the channels' fits at the estimated phase (sin, cos), and the ellipse's centre and
    #: semi-axes in V (u_sin, u_cos) for the Lissajous figure
    fits: tuple[ChannelFit, ChannelFit] | None = None
    #: the estimated phase (rad) and the interpolation error (electrical degrees), per
    #: sample of the window (thinned as fitted)
    phase_rad: np.ndarray = field(default_factory=lambda: np.empty(0))
    error_deg: np.ndarray = field(default_factory=lambda: np.empty(0))
    #: why there are no figures ("" when there are)
    problem: str = ""

    @property
    def error_peak_to_peak_deg(self) -> float:
        return float(np.ptp(self.error_deg)) if self.error_deg.size else math.nan


def _wrapped(angle):
    return (angle + math.pi) % (2.0 * math.pi) - math.pi


def live_figures(u_sin, u_cos, preset: TolerancePreset | None, periods: float,
                 scale: float = 1.0) -> LiveFigures:
    """The figures of a window of samples covering ``periods`` periods."""
    u_sin = np.asarray(u_sin, dtype=float)
    u_cos = np.asarray(u_cos, dtype=float)
    out = LiveFigures(int(u_sin.size), float(periods))
    if periods < MIN_PERIODS or u_sin.size < 4 * (1 + 2 * len(LIVE_ORDERS)):
        out.problem = message(QT_TR_NOOP(
            "the window covers {periods} periods: move the scale (at least {least} a window)"),
            periods=f"{periods:.2f}", least=f"{MIN_PERIODS:g}")
        return out
    step = max(1, math.ceil(u_sin.size / FIT_SAMPLES))
    s, c = u_sin[::step], u_cos[::step]
    try:
        ellipse = fit_ellipse(s, c)
        phase, *phasor = ellipse.phase_and_phasor(s, c)
        theta, fits, _ = refine_phase(phase, s, c, LIVE_ORDERS, iterations=2,
                                      phasor=(phasor[0], phasor[1]))
    except (ValueError, np.linalg.LinAlgError) as exc:
        out.problem = str(exc)
        return out
    out.fits = (fits[0], fits[1])
    out.figures = signal_figures(out.fits, preset, scale)
    noise = [float(np.sqrt(np.mean((u - model_signal(theta, fit)) ** 2)))
             for u, fit in ((s, fits[0]), (c, fits[1]))]
    weak = [name for name, fit, rms in (("A", fits[0], noise[0]), ("B", fits[1], noise[1]))
            if not fit.amplitude[1] >= MIN_SIGNAL_TO_NOISE * rms]
    if weak:
        # the ratio, phase, offsets and harmonics of noise mean nothing: not judged
        out.figures = {k: v for k, v in out.figures.items() if k.startswith("amplitude_")
                       and k != "amplitude_ratio"}
        out.judgements = judge(out.figures, preset) if preset is not None else []
        out.problem = message(QT_TR_NOOP(
            "no signal above the noise on channel {channels} (amplitude {amplitude} V against "
            "{noise} V rms left by the fit): only the amplitudes are judged"),
            channels=", ".join(weak), amplitude=f"{min(f.amplitude[1] for f in fits[:2]):.2g}",
            noise=f"{max(noise):.2g}")
        return out
    out.judgements = judge(out.figures, preset) if preset is not None else []
    error = _wrapped(np.arctan2(s, c) - theta)
    mean = math.atan2(float(np.mean(np.sin(error))), float(np.mean(np.cos(error))))
    out.error_deg = np.degrees(_wrapped(error - mean))
    out.phase_rad = _wrapped(theta)
    return out


class Extremes:
    """The lowest and highest value of each figure since the last :meth:`reset`."""

    def __init__(self) -> None:
        self.low: dict[str, float] = {}
        self.high: dict[str, float] = {}

    def reset(self) -> None:
        self.low.clear()
        self.high.clear()

    def add(self, figures: Mapping[str, float]) -> None:
        for key, value in figures.items():
            if value is None or not math.isfinite(value):
                continue
            self.low[key] = min(self.low.get(key, value), value)
            self.high[key] = max(self.high.get(key, value), value)
