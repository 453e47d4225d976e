"""Tolerances of an encoder's sin/cos signals at the mounting (#45): presets, the figures of
a fit in a preset's units, and the judgement of each figure against its band.

These are **mounting indications**, not statements of conformity: a figure is judged against
the band as it is, with no guard band and no uncertainty (a certificate that states
conformity of a signal uses the decision rules of models/certificate, not this).

Quantities (the names the window and the command line share)::

    amplitude_a, amplitude_b  peak-to-peak of each channel (max − min of its fitted waveform),
                              in the interface's unit (Vpp, µApp)
    amplitude_ratio           B / A (the cos channel's peak-to-peak over the sin channel's)
    phase_deviation           phase of B's fundamental − A's − 90° (degrees)
    offset_a, offset_b        either the offset in the interface's unit (V, µA), or — when the
                              preset's band is in "%" — the asymmetry (P − N) / 2M of the
                              channel in %, P and N its positive and negative peak about 0, M
                              its peak-to-peak (HEIDENHAIN's definition; signed here)
    harmonic_content          √(Σ_{k≥2} A_k²) / A_1 of the fitted waveform in %, the larger of
                              the two channels

A preset's bands: ``inside`` (the band a mounted head should reach), ``outer`` (a wider band
the source calls still acceptable, or None when the source gives one band only). A value on
an edge counts as inside (within the arithmetic's rounding, :data:`EDGE_RTOL`).

Presets are saved with the lab defaults under :data:`LAB_DEFAULTS_KEY` (a list of
:func:`preset_to_dict`); :func:`load_presets` gives the built-in ones and the lab's own (a
lab preset with a built-in's key replaces it).
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from models.fringe.model import ChannelFit, model_signal
from models.messages import QT_TR_NOOP, message

__all__ = [
    "BUILTIN_PRESETS",
    "EDGE_RTOL",
    "INTERFACES",
    "LAB_DEFAULTS_KEY",
    "NOT_CONFORMITY",
    "QUANTITIES",
    "STATES",
    "Band",
    "Judgement",
    "PresetError",
    "TolerancePreset",
    "judge",
    "lab_defaults_with_presets",
    "load_presets",
    "preset_by_key",
    "preset_from_dict",
    "preset_to_dict",
    "signal_figures",
]

#: the key of the lab's own presets in the lab defaults (a list of preset_to_dict)
LAB_DEFAULTS_KEY = "signal_tolerance_presets"
INTERFACES = ("1Vpp", "11uApp", "TTL")
QUANTITIES = ("amplitude_a", "amplitude_b", "amplitude_ratio", "phase_deviation",
              "offset_a", "offset_b", "harmonic_content")
STATES = ("inside", "outer", "outside")
#: a value this close to an edge (relative to the band's width or the edge) is on it
EDGE_RTOL = 1e-9
#: the dense phase grid the fitted waveforms' peaks are read from
_GRID = 4096

NOT_CONFORMITY = message(QT_TR_NOOP(
    "Mounting indication, not a statement of conformity: each signal figure is compared with "
    "its band as measured, with no guard band and no uncertainty."))


class PresetError(ValueError):
    """A preset (typed or read from the lab defaults) that does not hold: the message names
    the preset and the field."""


@dataclass(frozen=True)
class Band:
    """The band of one quantity: ``inside`` (low, high), and the wider ``outer`` band the
    source calls still acceptable (None when it gives one band only)."""

    quantity: str
    unit: str
    inside: tuple[float, float]
    outer: tuple[float, float] | None = None


@dataclass(frozen=True)
class TolerancePreset:
    key: str
    name: str
    interface: str  # "1Vpp", "11uApp" or "TTL"
    bands: tuple[Band, ...]
    source: str  # the document the bands come from (maker, title, edition, page)

    def band(self, quantity: str) -> Band | None:
        return next((b for b in self.bands if b.quantity == quantity), None)


@dataclass(frozen=True)
class Judgement:
    quantity: str
    value: float
    unit: str
    state: str  # "inside" | "outer" | "outside"
    band: Band


# -- the built-in presets: only what was read in the documents named -------------------------

_PWM20 = ("HEIDENHAIN, PWM 20 / ATS Software User's Manual, November 2014, p. 159 \"Standard "
          "signal amplitudes and tolerance ranges\" (HEIDENHAIN standard values; the manual "
          "says to observe the encoder's own mounting instructions, which may be tighter, e.g. "
          "for angle encoders). ")
_TV = ("The offset band is the manual's on-off ratio TV A/TV B −15°…+15° expressed as the "
       "asymmetry (P − N)/2M: a comparator at 0 V makes the high time 180° + 2·asin(2·SYM), so "
       "TV = ±15° is SYM = ±sin(7.5°)/2 = ±6.53 % (p. 160 defines TV, SYM = |P − N|/2M and "
       "their relation; p. 215 pairs an asymmetry of 0.05 with TV 11.5°, as this relation gives). ")
_ONE_BAND = ("The manual gives one band a quantity (no narrower mounting band; none is "
             "invented here) and no harmonic content.")


def _symmetric_asymmetry(tv_deg: float) -> float:
    """The asymmetry (P − N)/2M in % whose on-off ratio error is ``tv_deg``."""
    return 100.0 * math.sin(math.radians(tv_deg) / 2.0) / 2.0


_SYM15 = _symmetric_asymmetry(15.0)

BUILTIN_PRESETS: tuple[TolerancePreset, ...] = (
    TolerancePreset(
        "heidenhain_1vpp", "HEIDENHAIN 1 Vpp (standard values)", "1Vpp",
        (Band("amplitude_a", "Vpp", (0.6, 1.2)),
         Band("amplitude_b", "Vpp", (0.6, 1.2)),
         Band("amplitude_ratio", "", (0.8, 1.25)),
         Band("phase_deviation", "°", (-10.0, 10.0)),
         Band("offset_a", "%", (-_SYM15, _SYM15)),
         Band("offset_b", "%", (-_SYM15, _SYM15))),
        _PWM20 + "1 Vpp: Sig A and Sig B 0.6…1.2 Vpp (typical 1 Vpp), A/B 0.8…1.25, Pha 80°…100° "
        "(phase deviation ±10°), TV A and TV B −15°…+15°. The ratio band is symmetric in A/B "
        "and B/A (0.8 = 1/1.25). " + _TV + _ONE_BAND),
    TolerancePreset(
        "heidenhain_11uapp", "HEIDENHAIN 11 µApp (standard values)", "11uApp",
        (Band("amplitude_a", "µApp", (7.0, 16.0)),
         Band("amplitude_b", "µApp", (7.0, 16.0)),
         Band("amplitude_ratio", "", (0.8, 1.25)),
         Band("phase_deviation", "°", (-10.0, 10.0)),
         Band("offset_a", "%", (-_SYM15, _SYM15)),
         Band("offset_b", "%", (-_SYM15, _SYM15))),
        _PWM20 + "11 µApp: Sig A and Sig B 7…16 µApp (typical 11 µApp), A/B 0.8…1.25, Pha "
        "80°…100°, TV A and TV B −15°…+15° (HEIDENHAIN's 11 µApp interface page states the "
        "asymmetry |P − N|/2M ≤ 0.065, which agrees). A record in volts needs the scale µA per "
        "V of its transimpedance. " + _TV + _ONE_BAND),
    TolerancePreset(
        "heidenhain_1vpp_commutating", "HEIDENHAIN 1 Vpp with commutating signals "
        "(ERN 1085, ERN 1185, ERN 1387)", "1Vpp",
        (Band("amplitude_a", "Vpp", (0.75, 1.2)),
         Band("amplitude_b", "Vpp", (0.75, 1.2)),
         Band("amplitude_ratio", "", (0.9, 1.1)),
         Band("phase_deviation", "°", (-5.0, 5.0)),
         Band("offset_a", "%", (-5.0, 5.0)),
         Band("offset_b", "%", (-5.0, 5.0))),
        "HEIDENHAIN, PWM 20 / ATS Software User's Manual, November 2014, p. 215, 7.2.3 "
        "\"Incremental signals 1 Vpp with commutating signals\": incremental signals A, B: "
        "signal amplitude M 0.75…1.2 Vpp (typical 1 Vpp), asymmetry |P − N|/2M ≤ 0.05 (TV ≤ "
        "11.5°), signal ratio MA/MB 0.9…1.1, phase angle |φ1 + φ2|/2 90° ± 5° el. One band a "
        "quantity; no harmonic content given."),
)
# No built-in TTL preset: a TTL interface's figures (edge separation, on-off ratio of the
# square waves) are not figures of the sin/cos fit; a lab may add one for the sin/cos signals
# ahead of its interpolator.


# -- the figures ----------------------------------------------------------------------------

def _peaks(fit: ChannelFit) -> tuple[float, float]:
    """(highest, lowest) value of the fitted waveform over one period: the best of a dense
    grid, refined to the arithmetic's precision by Newton's steps on the slope about it (a
    peak between grid points would otherwise read low by up to 1 − cos(π/grid))."""
    step = 2.0 * math.pi / _GRID
    grid = np.arange(_GRID) * step
    u = model_signal(grid, fit)

    def refined(at: int) -> float:
        t = float(grid[at])
        for _ in range(8):
            slope = sum(k * fit.amplitude[k] * math.cos(k * t + fit.phase[k])
                        for k in fit.orders)
            curve = -sum(k * k * fit.amplitude[k] * math.sin(k * t + fit.phase[k])
                         for k in fit.orders)
            if curve == 0.0:
                break
            t_next = min(max(t - slope / curve, grid[at] - step), grid[at] + step)
            if t_next == t:
                break
            t = t_next
        return float(model_signal(np.array([t]), fit)[0])

    high, low = int(np.argmax(u)), int(np.argmin(u))
    return max(float(u[high]), refined(high)), min(float(u[low]), refined(low))


def _fits(result: Any) -> tuple[ChannelFit, ChannelFit]:
    if isinstance(result, Sequence) and len(result) == 2:
        return result[0], result[1]
    return result.sin_fit, result.cos_fit


def signal_figures(result: Any, preset: TolerancePreset | None = None,
                   scale: float = 1.0) -> dict[str, float]:
    """The quantities of :data:`QUANTITIES` from a fringe fit, in ``preset``'s units.

    ``result``: a :class:`~models.fringe.result.FringeResult` or a pair (sin_fit, cos_fit) of
    :class:`~models.fringe.model.ChannelFit`. ``scale``: the preset's unit per unit of the
    record (V per ADC count for a record in counts, µA per V for a current interface read
    through a transimpedance; 1 when the record is in the preset's unit). The offsets are the
    asymmetry in % where the preset's offset band is in "%" (or no preset is given: then in
    the record's unit × scale); ``harmonic_content`` only when harmonics were fitted.
    """
    if not (math.isfinite(scale) and scale > 0):
        raise ValueError(message(QT_TR_NOOP("the scale must be a positive number, not {scale}"),
                                 scale=f"{scale:g}"))
    sin_fit, cos_fit = _fits(result)
    out: dict[str, float] = {}
    relative = {"offset_a": False, "offset_b": False}
    if preset is not None:
        for key in relative:
            band = preset.band(key)
            relative[key] = band is not None and band.unit == "%"
    for name, fit in (("a", sin_fit), ("b", cos_fit)):
        high, low = _peaks(fit)
        ptp = high - low
        out[f"amplitude_{name}"] = ptp * scale
        if relative[f"offset_{name}"]:
            # (P − N) / 2M, P = high, N = −low about 0 V: (high + low) / 2(high − low)
            out[f"offset_{name}"] = 100.0 * (high + low) / (2.0 * ptp) if ptp > 0 else math.nan
        else:
            out[f"offset_{name}"] = fit.offset * scale
    out["amplitude_ratio"] = (out["amplitude_b"] / out["amplitude_a"]
                              if out["amplitude_a"] > 0 else math.nan)
    d = cos_fit.phase[1] - sin_fit.phase[1]
    out["phase_deviation"] = math.degrees((d - math.pi / 2 + math.pi) % (2 * math.pi) - math.pi)
    if any(k > 1 for k in sin_fit.orders) and any(k > 1 for k in cos_fit.orders):
        out["harmonic_content"] = max(_harmonic_content(sin_fit), _harmonic_content(cos_fit))
    return out


def _harmonic_content(fit: ChannelFit) -> float:
    rest = math.sqrt(sum(fit.amplitude[k] ** 2 for k in fit.orders if k > 1))
    return 100.0 * rest / fit.amplitude[1] if fit.amplitude[1] > 0 else math.nan


# -- the judgement --------------------------------------------------------------------------

def _within(value: float, band: tuple[float, float]) -> bool:
    low, high = band
    slack = EDGE_RTOL * max(high - low, abs(low), abs(high))
    return low - slack <= value <= high + slack


def judge(figures: Mapping[str, float], preset: TolerancePreset) -> list[Judgement]:
    """Each band of ``preset`` whose quantity is among ``figures`` (and finite), in the
    preset's order: inside its inside band (an edge counts as inside), else inside its outer
    band ("outer"), else "outside". A quantity the figures lack (or give as NaN) is not
    judged: the caller says it was not determined."""
    out = []
    for band in preset.bands:
        value = figures.get(band.quantity)
        if value is None or not math.isfinite(value):
            continue
        if _within(value, band.inside):
            state = "inside"
        elif band.outer is not None and _within(value, band.outer):
            state = "outer"
        else:
            state = "outside"
        out.append(Judgement(band.quantity, float(value), band.unit, state, band))
    return out


# -- presets as dicts (the lab defaults) ----------------------------------------------------

def _pair(value: Any, where: str) -> tuple[float, float]:
    try:
        low, high = (float(v) for v in value)
    except (TypeError, ValueError):
        raise PresetError(message(QT_TR_NOOP("{where}: not a pair of numbers (low, high)"),
                                  where=where)) from None
    if not (math.isfinite(low) and math.isfinite(high)) or low > high:
        raise PresetError(message(QT_TR_NOOP("{where}: {low} … {high} is not a band (low ≤ "
                                             "high, both finite)"),
                                  where=where, low=f"{low:g}", high=f"{high:g}"))
    return low, high


def preset_to_dict(preset: TolerancePreset) -> dict[str, Any]:
    return {"key": preset.key, "name": preset.name, "interface": preset.interface,
            "source": preset.source,
            "bands": [{"quantity": b.quantity, "unit": b.unit, "inside": list(b.inside),
                       "outer": None if b.outer is None else list(b.outer)}
                      for b in preset.bands]}


def preset_from_dict(data: Any) -> TolerancePreset:
    """A preset from :func:`preset_to_dict`'s form, checked: a message names the preset and
    the field that does not hold (:class:`PresetError`)."""
    if not isinstance(data, Mapping):
        raise PresetError(message(QT_TR_NOOP("a signal tolerance preset must be a mapping")))
    key = data.get("key")
    if not isinstance(key, str) or not key.strip():
        raise PresetError(message(QT_TR_NOOP("a signal tolerance preset needs a key")))
    key = key.strip()
    name = data.get("name", key)
    source = data.get("source", "")
    if not isinstance(name, str) or not isinstance(source, str):
        raise PresetError(message(QT_TR_NOOP("preset {key}: name and source must be texts"),
                                  key=key))
    interface = data.get("interface")
    if interface not in INTERFACES:
        raise PresetError(message(QT_TR_NOOP("preset {key}: interface '{interface}' is not one "
                                             "of {interfaces}"),
                                  key=key, interface=str(interface),
                                  interfaces=", ".join(INTERFACES)))
    raw = data.get("bands")
    if not isinstance(raw, Sequence) or isinstance(raw, str | bytes):
        raise PresetError(message(QT_TR_NOOP("preset {key}: bands must be a list"), key=key))
    bands, seen = [], set()
    for i, b in enumerate(raw, start=1):
        if not isinstance(b, Mapping):
            raise PresetError(message(QT_TR_NOOP("preset {key}, band {i}: not a mapping"),
                                      key=key, i=i))
        quantity = b.get("quantity")
        if quantity not in QUANTITIES:
            raise PresetError(message(QT_TR_NOOP("preset {key}, band {i}: quantity '{quantity}' "
                                                 "is not one of {quantities}"),
                                      key=key, i=i, quantity=str(quantity),
                                      quantities=", ".join(QUANTITIES)))
        if quantity in seen:
            raise PresetError(message(QT_TR_NOOP("preset {key}: {quantity} has two bands"),
                                      key=key, quantity=quantity))
        seen.add(quantity)
        unit = b.get("unit", "")
        if not isinstance(unit, str):
            raise PresetError(message(QT_TR_NOOP("preset {key}, band {i}: the unit must be a "
                                                 "text"), key=key, i=i))
        where = f"{key}, {quantity}"
        inside = _pair(b.get("inside"), where + " inside")
        outer = None if b.get("outer") is None else _pair(b.get("outer"), where + " outer")
        if outer is not None and not (outer[0] <= inside[0] and inside[1] <= outer[1]):
            raise PresetError(message(QT_TR_NOOP("preset {key}, {quantity}: the outer band "
                                                 "{outer} does not contain the inside band "
                                                 "{inside}"),
                                      key=key, quantity=quantity,
                                      outer=f"{outer[0]:g} … {outer[1]:g}",
                                      inside=f"{inside[0]:g} … {inside[1]:g}"))
        bands.append(Band(quantity, unit, inside, outer))
    if not bands:
        raise PresetError(message(QT_TR_NOOP("preset {key}: no band"), key=key))
    return TolerancePreset(key, name, interface, tuple(bands), source)


def load_presets(lab_defaults: Mapping[str, Any] | None) -> tuple[list[TolerancePreset],
                                                                    list[str]]:
    """The built-in presets and the lab's own from its defaults (a lab preset with a
    built-in's key replaces it), and a message for each stored preset that does not read
    (kept out, the others kept)."""
    presets = {p.key: p for p in BUILTIN_PRESETS}
    problems: list[str] = []
    stored = (lab_defaults or {}).get(LAB_DEFAULTS_KEY) or []
    if not isinstance(stored, list):
        problems.append(message(QT_TR_NOOP("the lab's signal tolerance presets are not a list; "
                                           "they were not read")))
        stored = []
    for i, data in enumerate(stored, start=1):
        try:
            preset = preset_from_dict(data)
        except PresetError as exc:
            problems.append(message(QT_TR_NOOP("lab preset {i} not read: {exc}"), i=i,
                                    exc=str(exc)))
            continue
        presets[preset.key] = preset
    return list(presets.values()), problems


def lab_defaults_with_presets(lab_defaults: Mapping[str, Any],
                              presets: Iterable[TolerancePreset]) -> dict[str, Any]:
    """``lab_defaults`` with the lab's presets stored: those of ``presets`` that are not a
    built-in as it is (a built-in edited is stored, and then replaces it)."""
    builtin = {p.key: p for p in BUILTIN_PRESETS}
    own = [preset_to_dict(p) for p in presets if builtin.get(p.key) != p]
    out = {k: v for k, v in lab_defaults.items() if k != LAB_DEFAULTS_KEY}
    if own:
        out[LAB_DEFAULTS_KEY] = own
    return out


def preset_by_key(key: str, presets: Iterable[TolerancePreset] = BUILTIN_PRESETS
                  ) -> TolerancePreset:
    presets = tuple(presets)
    for p in presets:
        if p.key == key:
            return p
    keys = ", ".join(p.key for p in presets)
    raise PresetError(message(QT_TR_NOOP("no signal tolerance preset '{key}' (there are: "
                                         "{keys})"), key=key, keys=keys))
