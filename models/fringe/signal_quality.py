"""Signal quality along the record — over a revolution (#45): the amplitudes, their ratio, the
phase between the channels and the offsets per period (or per window of periods), from the
per-period fits the workbench already makes (FringeResult.sin_periods / cos_periods:
models/fringe/model.py fit_periods, fit_periods_along), each judged against a preset's bands
when one is chosen, so that a read head in tolerance at one place and out at another is found.

Mounting indications, not conformity statements (models/fringe/signal_tolerance.py): no guard
band, no uncertainty.

A window's figures are those of its periods' mean fit: the mean of their fitted coefficients
(A_k cos c_k, A_k sin c_k) — with N equal steps a period exactly the least-squares fit of the
window's samples. Windows are in record order; with N
equal steps a period, window i starts at period i·n of the record (its place on the
revolution from the record's start, ``revolution_deg``); with a θ column or an estimated
phase, the per-period fits are segments of one period of travel each (a segment covering
less than three quarters of a period is left out by the fit), so a window is n such
segments, in record order.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from models.fringe.signal_tolerance import (
    NOT_CONFORMITY,
    QUANTITIES,
    TolerancePreset,
    judge,
)
from models.messages import QT_TR_NOOP, message

__all__ = ["SignalQuality", "default_window", "period_figures", "signal_quality", "tolerance_json"]

#: grid of the per-period waveforms' peaks (refined by a parabola through the best three)
_GRID = 512


def _peaks(rows: np.ndarray, orders: tuple[int, ...]) -> tuple[np.ndarray, np.ndarray]:
    """(highest, lowest) of each row's waveform A0 + Σ A_k sin(kt + c_k) over a period."""
    t = np.arange(_GRID) * (2.0 * math.pi / _GRID)
    u = np.repeat(rows[:, :1], _GRID, axis=1)
    for i, k in enumerate(orders):
        u += rows[:, 1 + 2 * i, None] * np.sin(k * t[None, :] + rows[:, 2 + 2 * i, None])

    def vertex(j: np.ndarray) -> np.ndarray:
        r = np.arange(u.shape[0])
        y0, y1, y2 = u[r, (j - 1) % _GRID], u[r, j], u[r, (j + 1) % _GRID]
        den = y0 - 2.0 * y1 + y2
        with np.errstate(divide="ignore", invalid="ignore"):
            shift = np.where(den != 0, 0.5 * (y0 - y2) / den, 0.0)
        return y1 - 0.25 * (y0 - y2) * shift

    return vertex(np.argmax(u, axis=1)), vertex(np.argmin(u, axis=1))


def period_figures(sin_rows: np.ndarray, cos_rows: np.ndarray, orders: tuple[int, ...],
                   preset: TolerancePreset | None = None, scale: float = 1.0
                   ) -> dict[str, np.ndarray]:
    """Each period's figures (the quantities of signal_tolerance.signal_figures, in the
    preset's units) from the per-period fit rows ``[A0, A_k, c_k …]`` of the two channels."""
    n = min(len(sin_rows), len(cos_rows))
    sin_rows, cos_rows = np.asarray(sin_rows[:n], float), np.asarray(cos_rows[:n], float)
    out: dict[str, np.ndarray] = {}
    for name, rows in (("a", sin_rows), ("b", cos_rows)):
        high, low = _peaks(rows, orders) if n else (np.empty(0), np.empty(0))
        ptp = high - low
        out[f"amplitude_{name}"] = ptp * scale
        band = preset.band(f"offset_{name}") if preset is not None else None
        if band is not None and band.unit == "%":
            with np.errstate(divide="ignore", invalid="ignore"):
                out[f"offset_{name}"] = np.where(ptp > 0, 100.0 * (high + low) / (2.0 * ptp),
                                                 np.nan)
        else:
            out[f"offset_{name}"] = rows[:, 0] * scale
    with np.errstate(divide="ignore", invalid="ignore"):
        out["amplitude_ratio"] = out["amplitude_b"] / out["amplitude_a"]
    first = orders.index(1)
    d = cos_rows[:, 2 + 2 * first] - sin_rows[:, 2 + 2 * first]
    out["phase_deviation"] = np.degrees((d - math.pi / 2 + math.pi) % (2 * math.pi) - math.pi)
    higher = [i for i, k in enumerate(orders) if k > 1]
    if higher:
        def content(rows: np.ndarray) -> np.ndarray:
            rest = np.sqrt(np.sum(rows[:, [1 + 2 * i for i in higher]] ** 2, axis=1))
            with np.errstate(divide="ignore", invalid="ignore"):
                return 100.0 * rest / rows[:, 1 + 2 * first]
        out["harmonic_content"] = np.maximum(content(sin_rows), content(cos_rows))
    return out


@dataclass
class SignalQuality:
    windows: list[dict[str, Any]]  # per window: window, first_period, periods, figures…
    units: dict[str, str]
    periods_per_window: int
    preset: TolerancePreset | None = None
    scale: float = 1.0
    #: per quantity: the windows judged outer / outside (with a preset)
    out_of_band: dict[str, dict[str, int]] = field(default_factory=dict)

    def extremes(self, quantity: str) -> tuple[float, float] | None:
        values = [w[quantity] for w in self.windows
                  if quantity in w and w[quantity] is not None and math.isfinite(w[quantity])]
        return (min(values), max(values)) if values else None

    def summary(self) -> list[str]:
        """One line a quantity judged with a window out of its band (with a preset)."""
        out: list[str] = []
        for quantity, counts in self.out_of_band.items():
            if counts.get("outer") or counts.get("outside"):
                low, high = self.extremes(quantity) or (math.nan, math.nan)
                out.append(message(QT_TR_NOOP(
                    "{quantity}: {outside} of {windows} windows outside the band, {outer} in "
                    "the outer band (along the record {low} … {high} {unit})"),
                    quantity=quantity, outside=counts.get("outside", 0),
                    outer=counts.get("outer", 0), windows=len(self.windows),
                    low=f"{low:.4g}", high=f"{high:.4g}", unit=self.units.get(quantity, "")))
        return out


def signal_quality(result: Any, preset: TolerancePreset | None = None, scale: float = 1.0,
                   periods_per_window: int = 1) -> SignalQuality:
    """The figures per window of ``periods_per_window`` periods along the record of a
    FringeResult, in ``preset``'s units (``scale``: the preset's unit per record unit), each
    window judged when a preset is given."""
    if periods_per_window < 1:
        raise ValueError(message(QT_TR_NOOP("a window holds at least one period, not {n}"),
                                 n=periods_per_window))
    if not (math.isfinite(scale) and scale > 0):
        raise ValueError(message(QT_TR_NOOP("the scale must be a positive number, not {scale}"),
                                 scale=f"{scale:g}"))
    orders = tuple(result.sin_fit.orders)
    sin_rows, cos_rows = (_windowed(np.asarray(rows, float), periods_per_window)
                          for rows in (result.sin_periods, result.cos_periods))
    count = min(len(result.sin_periods), len(result.cos_periods))
    figures = period_figures(sin_rows, cos_rows, orders, preset, scale)
    units = _units(preset, figures)
    equal_steps = getattr(result, "phase_source", "") == "samples_per_period"
    lines = getattr(result, "lines_per_rev", 0) if getattr(result, "unit", "") == "arcsec" else 0
    windows: list[dict[str, Any]] = []
    out_of_band: dict[str, dict[str, int]] = {}
    for i, start in enumerate(range(0, count, periods_per_window)):
        stop = min(count, start + periods_per_window)
        entry: dict[str, Any] = {"window": i, "first_period": start, "periods": stop - start}
        if equal_steps and lines:
            entry["revolution_deg"] = (start + 0.5 * (stop - start)) * 360.0 / lines
        values = {q: float(v[i]) for q, v in figures.items()}
        entry.update(values)
        if preset is not None:
            states = {j.quantity: j.state for j in judge(values, preset)}
            entry["states"] = states
            for q, state in states.items():
                counts = out_of_band.setdefault(q, {"inside": 0, "outer": 0, "outside": 0})
                counts[state] += 1
        windows.append(entry)
    return SignalQuality(windows, units, periods_per_window, preset, scale, out_of_band)


def _windowed(rows: np.ndarray, n: int) -> np.ndarray:
    """The rows ``[A0, A_k, c_k …]`` of each window of ``n`` periods: their coefficients'
    mean, in canonical form again."""
    if n == 1 or not len(rows):
        return rows
    count = len(rows)
    starts = np.arange(0, count, n)
    sizes = np.minimum(starts + n, count) - starts

    def mean(values: np.ndarray) -> np.ndarray:
        return np.add.reduceat(values, starts, axis=0) / sizes[:, None]

    amp, phase = rows[:, 1::2], rows[:, 2::2]
    s, c = mean(amp * np.cos(phase)), mean(amp * np.sin(phase))
    out = np.empty((len(starts), rows.shape[1]))
    out[:, 0] = mean(rows[:, :1])[:, 0]
    out[:, 1::2], out[:, 2::2] = np.hypot(s, c), np.arctan2(c, s)
    return out


def default_window(result: Any, most: int = 1000) -> int:
    """Periods a window so that a record gives at most ``most`` windows."""
    count = min(len(result.sin_periods), len(result.cos_periods))
    return max(1, -(-count // most))


def _units(preset: TolerancePreset | None, figures: dict[str, np.ndarray]) -> dict[str, str]:
    base = {"amplitude_a": "V (peak-to-peak)", "amplitude_b": "V (peak-to-peak)",
            "amplitude_ratio": "", "phase_deviation": "°", "offset_a": "V", "offset_b": "V",
            "harmonic_content": "%"}
    if preset is not None:
        for band in preset.bands:
            base[band.quantity] = band.unit
        if preset.band("amplitude_a") and not preset.band("amplitude_b"):
            base["amplitude_b"] = base["amplitude_a"]
    return {q: base[q] for q in QUANTITIES if q in figures}


def tolerance_json(figures: dict[str, float], preset: TolerancePreset, scale: float,
                   quality: SignalQuality | None = None) -> dict[str, Any]:
    """The ``signal_tolerance`` key of the fringe JSON: the preset, each quantity's value and
    state against its band (the whole record's fit), and with ``quality`` the windows out of
    band per quantity."""
    judged = {j.quantity: j for j in judge(figures, preset)}
    out: dict[str, Any] = {
        "preset": preset.key, "name": preset.name, "interface": preset.interface,
        "source": preset.source, "scale": scale, "note": str(NOT_CONFORMITY),
        "guard_band": None,
        "quantities": {},
    }
    for band in preset.bands:
        j = judged.get(band.quantity)
        out["quantities"][band.quantity] = {
            "value": None if j is None else j.value, "unit": band.unit,
            "state": None if j is None else j.state,
            "inside": list(band.inside), "outer": None if band.outer is None else list(band.outer)}
    if quality is not None:
        out["windows"] = len(quality.windows)
        out["periods_per_window"] = quality.periods_per_window
        out["windows_by_state"] = quality.out_of_band
    return out
