"""Interpolator look-up tables as a chip takes them (#45), with the residual they leave.

An interpolator chip computes the measured phase φ = atan2(u_sin, u_cos) of its (offset-,
gain- and phase-corrected, where it has those terms) signals and corrects it with a table of
``entries`` = 2^k values over one period of φ: b-bit signed codes, one code step (``LSB``) a
stated fraction of a period, looked up at φ (the entry below φ, or linearly between the two
entries about it) and subtracted from φ (or added: the chip's own sign convention).

The table is made from the fitted signals of a fringe record (models/fringe/analysis.py): the
interpolation error e(θ) = φ(θ) − θ of the fitted waveforms, re-sampled over φ at the table's
entries, its mean removed (a constant only moves the phase origin), divided by the LSB and
rounded. The **residual predicted after quantisation** is a simulation of the chip: the
quantised codes applied to the fitted signals over a dense phase grid (other phases than the
table's), the corrected phase minus the true one, mean removed; its largest magnitude and
RMS are stated beside those of the table unquantised (what the entries alone leave) and of no
table. When a residual is asked for and the table cannot reach it, it is refused, naming
the entries or bits that would.

Profiles: ``generic`` (entries, bits, LSB and the separate terms as given; the LSB, when not
given, the smallest power of two of a period whose code range holds the table), and
``ic-tw8`` modelled after iC-Haus iC-TW8 as its public data sheet describes it (see
:data:`IC_TW8`'s ``source``).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from models.fringe.model import ChannelFit, model_signal, phase_error_about_its_mean
from models.messages import QT_TR_NOOP, joined, message

__all__ = [
    "GENERIC",
    "IC_TW8",
    "PROFILES",
    "TERMS",
    "ChipProfile",
    "InterpolatorTable",
    "Residual",
    "SeparateTerms",
    "TableRefused",
    "chip_profile",
    "design_table",
    "simulate_residual",
]

TWO_PI = 2.0 * math.pi
TERMS = ("offset", "gain", "phase")
#: the phase grid the table is built on and the residual simulated over (points a period)
BUILD_GRID = 1 << 16
SIMULATION_GRID = (1 << 16) + 1  # (coprime with the build grid: other phases)
MAX_ENTRIES_LOG2 = 16
MAX_BITS = 16


class TableRefused(ValueError):
    """The table cannot be made, or cannot reach the residual asked for (its message says
    which entries or bits would)."""


@dataclass(frozen=True)
class ChipProfile:
    key: str
    name: str
    entries: int  # 2^k entries over one period of the measured phase
    bits: int  # signed codes
    lsb_period: float | None  # one code step as a fraction of a period (None: chosen)
    max_code: int  # the largest |code| the chip takes
    interpolation: str  # "linear" between entries, or "step" (the entry below φ)
    sign: str  # "subtract": corrected = φ − value; "add": corrected = φ + value
    separate_terms: tuple[str, ...] = ()  # corrected apart from the table (TERMS)
    terms_written: bool = True  # the separate terms written beside the table (else the chip
    # calibrates them itself)
    source: str = ""

    @property
    def entries_log2(self) -> int:
        return int(round(math.log2(self.entries)))


GENERIC = ChipProfile(
    "generic", "generic interpolator", 64, 8, None, 127, "step", "subtract", (), True,
    "A generic chip: the parameters as given (entries, bits, LSB, lookup, separate terms); the "
    "table's value at the measured phase is subtracted from it.")

IC_TW8 = ChipProfile(
    "ic-tw8", "modelled after iC-Haus iC-TW8", 64, 8, 1.0 / 4096.0, 127, "linear", "add",
    ("offset", "gain", "phase"), False,
    "iC-Haus, iC-TW8 16-bit sin/cos interpolator with auto-calibration, data sheet, Serial "
    "Configuration Mode, \"Using the LUT\" (p. SC34/36 of the Jan 9, 2013 preliminary edition; "
    "p. SC35/36 of the Aug 16, 2016 edition): a 64-byte sensor distortion LUT over one input "
    "cycle, 64 segments of 5.625°, values shown −127…127, linearly interpolated between the two "
    "entries about the angle, the correction added to the sensor angle; the LSB from its worked "
    "example (a shift of −3.8° is −3.8·16384/(360·4) = −43): 4/16384 = 1/4096 of a cycle. "
    "Offset, amplitude match and phase are calibrated by the chip itself (auto-calibration, "
    "front page), apart from the LUT: modelled here as an exact correction of the fundamental's "
    "offsets, gain ratio and quadrature; the table corrects what remains (the harmonics). Not "
    "modelled: the chip's 14-bit angle ahead of the LUT, and its register or EEPROM layout "
    "(the table is written as 64 signed codes).")

PROFILES = {p.key: p for p in (GENERIC, IC_TW8)}


def chip_profile(key: str = "generic", entries: int | None = None, bits: int | None = None,
                 lsb_period: float | None = None,
                 separate_terms: Sequence[str] | None = None) -> ChipProfile:
    """The profile ``key`` with what is given changed; a chip's fixed figures are not."""
    if key not in PROFILES:
        raise TableRefused(message(QT_TR_NOOP("no interpolator profile '{key}' (there are: "
                                              "{keys})"), key=key, keys=", ".join(PROFILES)))
    base = PROFILES[key]
    if key != "generic":
        asked = {"entries": entries, "bits": bits, "LSB": lsb_period,
                 "separate terms": None if separate_terms is None else tuple(separate_terms)}
        fixed = {"entries": base.entries, "bits": base.bits, "LSB": base.lsb_period,
                 "separate terms": base.separate_terms}
        for name, value in asked.items():
            if value is not None and value != fixed[name]:
                raise TableRefused(message(QT_TR_NOOP(
                    "the {chip} takes {name} {fixed}, not {value}: choose the generic profile "
                    "for another table"), chip=base.name, name=name, fixed=str(fixed[name]),
                    value=str(value)))
        return base
    entries = base.entries if entries is None else int(entries)
    if entries < 2 or entries & (entries - 1) or entries > 1 << MAX_ENTRIES_LOG2:
        raise TableRefused(message(QT_TR_NOOP("{entries} entries: a table takes 2^k entries, 2 … "
                                              "{largest}"), entries=entries,
                                   largest=1 << MAX_ENTRIES_LOG2))
    bits = base.bits if bits is None else int(bits)
    if not 2 <= bits <= MAX_BITS:
        raise TableRefused(message(QT_TR_NOOP("{bits} bits: a table's codes take 2 … {most} "
                                              "bits"), bits=bits, most=MAX_BITS))
    if lsb_period is not None and not (math.isfinite(lsb_period) and 0 < lsb_period < 1):
        raise TableRefused(message(QT_TR_NOOP("LSB {lsb}: one code step must be a fraction of "
                                              "a period between 0 and 1"),
                                   lsb=f"{lsb_period:g}"))
    terms = tuple(separate_terms or ())
    unknown = [t for t in terms if t not in TERMS]
    if unknown:
        raise TableRefused(message(QT_TR_NOOP("separate term '{term}' is not one of {terms}"),
                                   term=unknown[0], terms=", ".join(TERMS)))
    return replace(base, entries=entries, bits=bits, lsb_period=lsb_period,
                   max_code=(1 << (bits - 1)) - 1, separate_terms=terms)


@dataclass(frozen=True)
class SeparateTerms:
    """What the chip corrects apart from the table, from the fit (record units): offsets
    subtracted, B multiplied by ``gain_b`` (A1/B1), and the quadrature error ``phase_deg``
    removed by B' = (B + A·sin q)/cos q."""

    offset_a: float = 0.0
    offset_b: float = 0.0
    gain_b: float = 1.0
    phase_deg: float = 0.0
    applied: tuple[str, ...] = ()

    def apply(self, u_a: np.ndarray, u_b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        a, b = u_a, u_b
        if "offset" in self.applied:
            a, b = a - self.offset_a, b - self.offset_b
        if "gain" in self.applied:
            b = b * self.gain_b
        if "phase" in self.applied:
            q = math.radians(self.phase_deg)
            b = (b + a * math.sin(q)) / math.cos(q)
        return a, b


@dataclass(frozen=True)
class Residual:
    """An interpolation error over one period of true phase, mean removed (fractions of a
    period)."""

    max_abs: float
    rms: float
    peak_to_peak: float

    def as_dict(self, period_length: float = 1.0, unit: str = "period") -> dict[str, float]:
        return {f"max_abs_{unit}": self.max_abs * period_length,
                f"rms_{unit}": self.rms * period_length,
                f"peak_to_peak_{unit}": self.peak_to_peak * period_length}


@dataclass
class InterpolatorTable:
    profile: ChipProfile
    codes: np.ndarray  # int, one per entry
    lsb_period: float
    ideal_period: np.ndarray  # the value each entry should hold, unquantised (fraction)
    terms: SeparateTerms
    residual: Residual  # the quantised table applied (the prediction)
    residual_unquantised: Residual  # the table unquantised (what the entries alone leave)
    residual_without: Residual  # no table
    lsb_chosen: bool = False  # the LSB was chosen (the smallest power of two that holds it)
    notes: list[str] = field(default_factory=list)

    @property
    def entries(self) -> int:
        return int(self.codes.size)

    @property
    def phase_at_entry_deg(self) -> np.ndarray:
        """The measured phase each entry stands at (deg of a period): the entry's start
        (linear: the value at it; step: the value over [it, next))."""
        return np.arange(self.entries) * (360.0 / self.entries)


# -- the signals and the simulation ----------------------------------------------------------

def _fits(result: Any) -> tuple[ChannelFit, ChannelFit]:
    if isinstance(result, Sequence) and len(result) == 2:
        return result[0], result[1]
    return result.sin_fit, result.cos_fit


def separate_terms_of(sin_fit: ChannelFit, cos_fit: ChannelFit,
                      applied: tuple[str, ...]) -> SeparateTerms:
    d = cos_fit.phase[1] - sin_fit.phase[1]
    quadrature = math.degrees((d - math.pi / 2 + math.pi) % TWO_PI - math.pi)
    return SeparateTerms(sin_fit.offset, cos_fit.offset,
                         sin_fit.amplitude[1] / cos_fit.amplitude[1], quadrature, applied)


def _wrap(x: np.ndarray) -> np.ndarray:
    return (x + math.pi) % TWO_PI - math.pi


def _measured(theta: np.ndarray, sin_fit: ChannelFit, cos_fit: ChannelFit,
              terms: SeparateTerms) -> np.ndarray:
    a, b = terms.apply(model_signal(theta, sin_fit), model_signal(theta, cos_fit))
    return np.arctan2(a, b)


def _lookup(values: np.ndarray, phase: np.ndarray, interpolation: str) -> np.ndarray:
    """The table ``values`` (one per entry over a period) at measured ``phase`` (rad)."""
    n = values.size
    pos = np.mod(phase, TWO_PI) * (n / TWO_PI)
    j = np.minimum(pos.astype(np.intp), n - 1)
    if interpolation == "step":
        return values[j]
    frac = pos - j
    nxt = values[(j + 1) % n]
    return values[j] + (nxt - values[j]) * frac


def _residual(error_rad: np.ndarray) -> Residual:
    e = phase_error_about_its_mean(error_rad)[0]
    return Residual(float(np.max(np.abs(e))) / TWO_PI, float(np.sqrt(np.mean(e * e))) / TWO_PI,
                    float(np.ptp(e)) / TWO_PI)


@dataclass
class _Phases:
    """The true phases of a grid over one period and the measured phase of the fitted
    signals (after the separate terms) at each (rad)."""

    theta: np.ndarray
    measured: np.ndarray

    @classmethod
    def of(cls, sin_fit: ChannelFit, cos_fit: ChannelFit, terms: SeparateTerms,
           grid: int) -> _Phases:
        theta = np.arange(grid) * (TWO_PI / grid)
        return cls(theta, _measured(theta, sin_fit, cos_fit, terms))

    @functools.cached_property
    def error_over_measured(self) -> tuple[np.ndarray, np.ndarray]:
        """(measured phase in [0, 2π) ascending, the error φ − θ there, mean removed)."""
        error = phase_error_about_its_mean(self.measured - self.theta)[0]
        phi = np.mod(self.measured, TWO_PI)
        order = np.argsort(phi)
        return phi[order], error[order]

    def residual(self, values_period: np.ndarray, profile: ChipProfile) -> Residual:
        value = _lookup(np.asarray(values_period, dtype=float), self.measured,
                        profile.interpolation) * TWO_PI
        corrected = self.measured + value if profile.sign == "add" else self.measured - value
        return _residual(corrected - self.theta)


def simulate_residual(result: Any, values_period: np.ndarray, profile: ChipProfile,
                      terms: SeparateTerms | None = None,
                      grid: int = SIMULATION_GRID) -> Residual:
    """The interpolation error left when the table ``values_period`` (fractions of a period,
    as the chip holds them: added or subtracted per ``profile.sign``) corrects the fitted
    signals of ``result`` over ``grid`` true phases of one period."""
    sin_fit, cos_fit = _fits(result)
    terms = terms or separate_terms_of(sin_fit, cos_fit, profile.separate_terms)
    return _Phases.of(sin_fit, cos_fit, terms, grid).residual(values_period, profile)


def _check_turns_once(phases: _Phases) -> None:
    phi = phases.measured
    steps = _wrap(np.diff(np.concatenate([phi, phi[:1]])))
    if round(float(np.sum(steps)) / TWO_PI) != 1 or not np.all(steps > 0):
        raise TableRefused(message(QT_TR_NOOP(
            "no table: the measured phase of the fitted signals does not turn once, forward, a "
            "period (the Lissajous figure does not circle 0 V, or loops back): no table over it "
            "can correct them")))


def _ideal_table(build: _Phases, profile: ChipProfile) -> np.ndarray:
    """The error over the measured phase at the entries (fractions of a period, mean
    removed, in the chip's sign)."""
    phi, error = build.error_over_measured
    n = profile.entries
    at = np.arange(n) * (TWO_PI / n)
    if profile.interpolation == "step":
        at = at + math.pi / n  # the entry holds over [j, j + 1): its middle
    table = np.interp(at, phi, error, period=TWO_PI)
    table = (table - float(np.mean(table))) / TWO_PI
    return -table if profile.sign == "add" else table


def _chosen_lsb(ideal: np.ndarray, max_code: int) -> float:
    """The smallest power of two of a period whose code range holds the table."""
    largest = float(np.max(np.abs(ideal)))
    if largest == 0.0:
        return 2.0 ** -24
    return 2.0 ** math.ceil(math.log2(largest / (max_code + 0.499)))


def _build(build: _Phases, simulation: _Phases, terms: SeparateTerms,
           profile: ChipProfile, quick: bool = False) -> InterpolatorTable:
    """The table; ``quick``: its quantised residual only (the others left as it)."""
    ideal = _ideal_table(build, profile)
    chosen = profile.lsb_period is None
    lsb = _chosen_lsb(ideal, profile.max_code) if profile.lsb_period is None else profile.lsb_period
    codes = np.rint(ideal / lsb).astype(np.int64)
    over = int(np.max(np.abs(codes)))
    if over > profile.max_code:
        largest = float(np.max(np.abs(ideal)))
        need_bits = math.ceil(math.log2(largest / lsb + 0.5)) + 1
        raise TableRefused(message(QT_TR_NOOP(
            "no table: the correction reaches {largest} of a period, {codes} codes of LSB {lsb}, "
            "beyond the ±{most} of {bits}-bit codes: an LSB of at least {need_lsb} of a period, "
            "or {need_bits} bits, would hold it"),
            largest=f"{largest:.4g}", codes=over, lsb=f"{lsb:.4g}", most=profile.max_code,
            bits=profile.bits, need_lsb=f"{largest / profile.max_code:.4g}",
            need_bits=need_bits))
    residual = simulation.residual(codes * lsb, profile)
    return InterpolatorTable(
        profile, codes, lsb, ideal, terms, residual=residual,
        residual_unquantised=residual if quick else simulation.residual(ideal, profile),
        residual_without=residual if quick else simulation.residual(np.zeros(1), profile),
        lsb_chosen=chosen)


def design_table(result: Any, profile: ChipProfile = GENERIC,
                 max_residual_period: float | None = None,
                 residual_unit: tuple[float, str] = (1.0, "of a period")) -> InterpolatorTable:
    """The table for the fitted signals of ``result`` (a FringeResult or (sin_fit, cos_fit)),
    quantised as ``profile`` takes it, with its predicted residual.

    ``max_residual_period``: the largest |residual| asked for (a fraction of a period); a
    table that leaves more is refused (:class:`TableRefused`), naming the entries (at these
    bits) and the bits (at these entries) of a generic table that would reach it.
    ``residual_unit``: (one period in the unit, the unit's name) for the refusal's text.
    """
    sin_fit, cos_fit = _fits(result)
    terms = separate_terms_of(sin_fit, cos_fit, profile.separate_terms)
    build = _Phases.of(sin_fit, cos_fit, terms, BUILD_GRID)
    _check_turns_once(build)
    simulation = _Phases.of(sin_fit, cos_fit, terms, SIMULATION_GRID)
    table = _build(build, simulation, terms, profile)
    if max_residual_period is None or table.residual.max_abs <= max_residual_period:
        return table
    period, unit = residual_unit

    def reaches(entries: int, bits: int) -> bool:
        # a generic table of these entries and bits, its LSB the finest that holds it
        trial = replace(profile, entries=entries, bits=bits, max_code=(1 << (bits - 1)) - 1,
                        lsb_period=None)
        try:
            return _build(build, simulation, terms, trial, quick=True
                          ).residual.max_abs <= max_residual_period
        except TableRefused:
            return False

    options = []
    more_entries = next((1 << k for k in range(profile.entries_log2 + 1, MAX_ENTRIES_LOG2 + 1)
                         if reaches(1 << k, profile.bits)), None)
    if more_entries:
        options.append(message(QT_TR_NOOP("{entries} entries of {bits} bits"),
                               entries=more_entries, bits=profile.bits))
    more_bits = next((b for b in range(profile.bits + 1, MAX_BITS + 1)
                      if reaches(profile.entries, b)), None)
    if more_bits:
        options.append(message(QT_TR_NOOP("{entries} entries of {bits} bits"),
                               entries=profile.entries, bits=more_bits))
    if not options:
        both = next(((1 << k, b) for k in range(profile.entries_log2, MAX_ENTRIES_LOG2 + 1)
                     for b in range(profile.bits, MAX_BITS + 1) if reaches(1 << k, b)), None)
        if both:
            options.append(message(QT_TR_NOOP("{entries} entries of {bits} bits"),
                                   entries=both[0], bits=both[1]))
    limited_by = (QT_TR_NOOP("the entries (unquantised, they leave {ideal})")
                  if table.residual_unquantised.max_abs > max_residual_period else
                  QT_TR_NOOP("the quantisation (unquantised, the entries leave {ideal})"))
    would = (message(QT_TR_NOOP("a generic table of {options} would reach it"),
                     options=joined(part for i, option in enumerate(options)
                                    for part in ((message(QT_TR_NOOP(" or ")) if i else ""),
                                                 option))) if options else
             message(QT_TR_NOOP("no table up to {entries} entries of {bits} bits reaches it: "
                                "the fitted signals' error is not smooth enough for a table"),
                     entries=1 << MAX_ENTRIES_LOG2, bits=MAX_BITS))
    raise TableRefused(message(QT_TR_NOOP(
        "no table: {entries} entries of {bits} bits leave a residual of {residual} {unit} (largest "
        "magnitude), more than the {asked} {unit} asked for; limited by {limited}; {would}"),
        entries=profile.entries, bits=profile.bits,
        residual=f"{table.residual.max_abs * period:.4g}", unit=unit,
        asked=f"{max_residual_period * period:.4g}",
        limited=message(limited_by, ideal=f"{table.residual_unquantised.max_abs * period:.4g} "
                                          f"{unit}"),
        would=would))
