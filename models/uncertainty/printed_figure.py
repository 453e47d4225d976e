"""A figure as it is printed that can print itself in another angle unit from its
unrounded value (assessment 70 H3).

A certificate's text states its figures rounded (GUM 7.2.6: an expanded uncertainty U to
at most two significant digits, a value to the same decimal). Read in another unit
(``--unit urad``, the window's unit menu), a figure converted from its printed digits
carries the first rounding into the second: 1.4″ becomes 6.79 µrad where U is 6.964 µrad,
an understatement of 2.5 %. A :class:`PrintedFigure` is the printed text (a ``str``, so it
goes wherever a formatted figure went) that keeps its value, its unit and its rounding
rule; :func:`models.display_units.in_unit` converts the value and rounds it again in the
target unit by the same rule:

* ``u``: the U whose decimal the figure is printed to (two significant digits of U at
  most, in the unit it is printed in); a U itself is printed to its own (``u=None`` and
  ``decimals=None``);
* ``decimals``: a figure printed to a fixed decimal, not set by a U (its resolution is
  carried over on conversion, and never fewer than three significant digits, as any
  converted figure);
* ``rounding``: "nearest", or "up"/"down" for an end or a U rounded outward (ceil/floor
  on the printed grid);
* ``rounding`` "g": a limit stated exactly (a tolerance), to six significant digits;
* ``less``: a figure printed as the difference of two printed figures (``value`` as
  printed less ``less`` as printed), so that a sum in the text adds up as printed;
* ``sign``: "+" to sign the figure always, as a range's ends are;
* ``resolution_only``: a fixed decimal carried into another unit at its resolution alone,
  no significant digits added (a range's ends and its peak-to-peak keep one decimal);
* ``interval``: (value, U₋, U₊) of a value stated with its coverage interval, and ``part``
  which of its printed figures this is ("value", "lower", "upper", "low", "high"), printed
  by :func:`models.uncertainty.rounding.stated_interval` (the value ± its U the interval's
  ends, as printed) to the decimal of the larger U; ``clip``: a half range's, its lower end
  held at 0.
"""

from __future__ import annotations

import math
from typing import cast

from models.quantity import UnitError, unit
from models.uncertainty.rounding import fixed_places, stated_interval, uncertainty_decimals

__all__ = ["CONVERTED_LIMIT_DIGITS", "PrintedFigure", "PrintedRange", "converted_limit",
           "converted_text", "interval_range", "printed", "printed_interval_figures",
           "printed_range_figures", "rounded_to", "StatedLimit", "StatedTolerance",
           "tolerance_figure", "ZoneLimit"]


def rounded_to(value: float, decimals: int, rounding: str = "nearest") -> float:
    """``value`` on the grid of ``decimals`` decimals: to the nearest, or "up" (toward +∞)
    or "down" (toward −∞); a value already on the grid (to 1e-9 of a digit) is kept, so that
    a figure's binary noise never moves it a whole digit."""
    if not math.isfinite(value) or rounding == "nearest":
        return round(value, decimals) + 0.0 if math.isfinite(value) else value
    units = value * 10.0 ** decimals
    near = round(units)
    whole = near if abs(units - near) < 1e-9 else (math.ceil(units) if rounding == "up"
                                                     else math.floor(units))
    return round(whole / 10.0 ** decimals, decimals) + 0.0


def _carried_decimals(decimals: int, value: float, factor: float) -> int:
    """A fixed decimal carried into another unit: the resolution kept (0.01″ is 0.01 µrad,
    0.001 mdeg) and never fewer than three significant digits."""
    places = decimals + max(0, math.ceil(-math.log10(factor)))
    if value != 0.0 and math.isfinite(value):
        places = max(places, 2 - math.floor(math.log10(abs(value))))
    return max(0, places)


class PrintedFigure(str):
    """``value`` in the unit spelt ``symbol`` ('"', " µrad", " nm", "°"; a leading space
    where the unit is written apart from the number, "" for a figure printed without its
    unit, ``unit_key`` then naming it), printed by its rule (see the module)."""

    value: float
    u: float | None
    decimals: int | None
    rounding: str
    sign: str
    symbol: str
    unit_key: str
    interval: tuple[float, float, float] | None
    part: str
    clip: bool
    less: float | None
    stated_exactly: bool
    resolution_only: bool
    shown: float  # the number as printed (on its grid; nan where "—" is printed)

    def __new__(cls, value: float, symbol: str, *, u: float | None = None,
                decimals: int | None = None, rounding: str = "nearest", sign: str = "",
                unit_key: str = "", interval: tuple[float, float, float] | None = None,
                part: str = "value", clip: bool = False,
                less: float | None = None, stated_exactly: bool = False,
                resolution_only: bool = False) -> PrintedFigure:
        value = float(value)
        if interval is not None:
            interval = tuple(float(x) for x in interval)  # type: ignore[assignment]
        places = cls._places(value, u, decimals, interval)
        if interval is not None:
            shown = stated_interval(*interval, places, clip)[part]
        else:
            shown = rounded_to(value, places, rounding)
        if less is not None:  # a difference of two printed figures, as printed
            shown = round(shown - rounded_to(float(less), places, rounding), places) + 0.0
        text = ("—" if not math.isfinite(shown) else
                f"{value:{sign}g}{symbol}" if rounding == "g" else
                f"{fixed_places(shown, places, sign)}{symbol}")
        figure = super().__new__(cls, text)
        figure.value, figure.u, figure.decimals = value, u, decimals
        figure.rounding, figure.sign, figure.symbol = rounding, sign, symbol
        figure.unit_key = unit_key or _unit_key(symbol)
        figure.interval, figure.part, figure.clip = interval, part, clip
        figure.less, figure.stated_exactly = less, stated_exactly
        figure.resolution_only = resolution_only
        figure.shown = float(shown)
        return figure

    @staticmethod
    def _places(value: float, u: float | None, decimals: int | None,
                interval: tuple[float, float, float] | None = None) -> int:
        if decimals is not None:
            return decimals
        if interval is not None:
            return uncertainty_decimals(max(interval[1], interval[2]))
        return uncertainty_decimals(value if u is None else u)

    def __getnewargs_ex__(self):  # copied, pickled
        return ((self.value, self.symbol), {"u": self.u, "decimals": self.decimals,
                                            "rounding": self.rounding, "sign": self.sign,
                                            "unit_key": self.unit_key,
                                            "interval": self.interval, "part": self.part,
                                            "clip": self.clip, "less": self.less,
                                            "stated_exactly": self.stated_exactly,
                                            "resolution_only": self.resolution_only})

    @property
    def exact(self) -> float | None:
        """The unrounded value where the machine-readable outputs state it so
        (``stated_exactly``: the DCC then states it, not the digits printed), else None."""
        return self.value if self.stated_exactly else None

    @property
    def places(self) -> int:
        """The decimals printed."""
        return self._places(self.value, self.u, self.decimals, self.interval)

    def to(self, key: str) -> PrintedFigure:
        """The figure in the unit ``key`` (arcsec, urad, mdeg, …), its value and its U
        converted unrounded and rounded there by the same rule; a figure in a unit of
        another dimension (nm) or in no known unit comes back as it is."""
        if not self.unit_key:
            return self
        try:
            source, target = unit(self.unit_key), unit(key)
        except UnitError:
            return self
        if source.dimension != target.dimension or source == target:
            return self
        factor = source.size / target.size
        value = self.value * factor
        decimals = (None if self.decimals is None else
                    _carried_decimals(self.decimals, 0.0 if self.resolution_only else value,
                                      factor))
        symbol = (target.written() if self.symbol.strip() else "")
        interval = (None if self.interval is None else
                    tuple(x * factor for x in self.interval))
        return PrintedFigure(value, symbol, u=None if self.u is None else self.u * factor,
                             decimals=decimals, rounding=self.rounding, sign=self.sign,
                             unit_key=target.key, interval=interval,  # type: ignore[arg-type]
                             part=self.part, clip=self.clip,
                             less=None if self.less is None else self.less * factor,
                             stated_exactly=self.stated_exactly,
                             resolution_only=self.resolution_only)


class ZoneLimit(PrintedFigure):
    """A decision zone's limit, T less the printed U₊ (``side`` −1) or plus the printed U₋
    (+1), ``band`` that printed U, rounded down to ``decimals`` (so that a printed value lies
    at or below it exactly when it lies at or below T ∓ U). Read in another unit it is made
    there from T converted and the U as printed there, to the decimal of that U: the zones
    beside U = 2.4 µrad read 4.6 µrad, not 4.58 µrad (0.94″ converted with the decimal of
    U = 0.50″: assessment 72 L4)."""

    limit: float
    band: PrintedFigure
    side: int

    def __new__(cls, limit: float, band: PrintedFigure, side: int, symbol: str,
                decimals: int) -> ZoneLimit:
        made = cast(ZoneLimit, PrintedFigure.__new__(cls, float(limit) + side * band.shown,
                                                     symbol, decimals=decimals,
                                                     rounding="down"))
        made.limit, made.band, made.side = float(limit), band, side
        return made

    def __getnewargs_ex__(self):  # copied, pickled
        return (self.limit, self.band, self.side, self.symbol, self.decimals), {}

    def to(self, key: str) -> PrintedFigure:
        band = self.band.to(key)
        if band is self.band or self.decimals is None:
            return self
        factor = unit(self.band.unit_key).size / unit(band.unit_key).size
        symbol = unit(key).written() if self.symbol.strip() else ""
        # the zones' decimal beside U's as it was, in the unit read (U's own there)
        decimals = self.decimals + band.places - self.band.places
        return ZoneLimit(self.limit * factor, band, self.side, symbol, decimals)


class PrintedRange(str):
    """Two printed figures joined by " … " (a coverage interval's ends), which converts as
    its ends do; ``exact``: both ends unrounded (the DCC states them)."""

    low: PrintedFigure
    high: PrintedFigure

    def __new__(cls, low: PrintedFigure, high: PrintedFigure) -> PrintedRange:
        made = super().__new__(cls, f"{low} … {high}")
        made.low, made.high = low, high
        return made

    def __getnewargs__(self):  # copied, pickled
        return self.low, self.high

    @property
    def exact(self) -> tuple[float, float]:
        return self.low.value, self.high.value

    @property
    def unit_key(self) -> str:
        return self.low.unit_key

    def to(self, key: str) -> PrintedRange:
        return PrintedRange(self.low.to(key), self.high.to(key))


def interval_range(low: float, high: float, symbol: str) -> PrintedRange:
    """A coverage interval [``low``, ``high``] as printed, alone (no U beside it): each end
    to the decimal of its half-width (two significant digits, GUM 7.2.6) rounded outward, in
    any unit it is read in."""
    half = (high - low) / 2.0
    return PrintedRange(PrintedFigure(low, symbol, u=half, rounding="down", stated_exactly=True),
                        PrintedFigure(high, symbol, u=half, rounding="up", stated_exactly=True))


def _unit_key(symbol: str) -> str:
    try:
        return unit(symbol.strip()).key if symbol.strip() else ""
    except UnitError:
        return ""


def printed(value: float, symbol: str, *, u: float | None = None, decimals: int | None = None,
            rounding: str = "nearest", sign: str = "", unit_key: str = "",
            stated_exactly: bool = False) -> PrintedFigure:
    """:class:`PrintedFigure` (the name the formatting helpers use)."""
    return PrintedFigure(value, symbol, u=u, decimals=decimals, rounding=rounding, sign=sign,
                         unit_key=unit_key, stated_exactly=stated_exactly)


def printed_range_figures(low: float, high: float, decimals: int,
                          symbol: str = "\"") -> dict[str, PrintedFigure]:
    """A curve's range as a summary prints it, {"low", "high", "ptp"}: its ends signed, to
    ``decimals``, and the peak-to-peak the difference of the ends as printed (as
    :func:`models.uncertainty.rounding.printed_range`), each a figure that converts itself
    from its unrounded value: read in µrad it is rounded there, not converted from the
    digits printed in arcseconds (assessment 72 L5: "−7.66 µrad" for −7.644 µrad, −1.58″
    converted)."""
    # one decimal for the three, carried into another unit at its resolution
    return {"low": PrintedFigure(low, symbol, decimals=decimals, sign="+", resolution_only=True),
            "high": PrintedFigure(high, symbol, decimals=decimals, sign="+",
                                  resolution_only=True),
            "ptp": PrintedFigure(high, symbol, decimals=decimals, less=low,
                                 resolution_only=True)}


def printed_interval_figures(value: float, lower: float, upper: float, symbol: str,
                             clip: bool = False, unit_key: str = "",
                             decimals: int | None = None) -> dict[str, PrintedFigure]:
    """A value with its coverage interval [value − ``lower``, value + ``upper``] as printed
    figures ("value", "lower", "upper", "low", "high"): value ± U is the printed interval
    (:func:`models.uncertainty.rounding.stated_interval`), in any unit it is read in."""
    interval = (float(value), float(lower), float(upper))
    exact = {"value": value, "lower": lower, "upper": upper, "low": value - lower,
             "high": value + upper}
    return {part: PrintedFigure(exact[part], symbol, interval=interval, part=part, clip=clip,
                                unit_key=unit_key, decimals=decimals)
            for part in exact}


class StatedLimit(float):
    """A tolerance in the unit of the errors it is judged against that remembers how the
    customer stated it (``stated``: its number and unit key), so that the texts quote the
    specification as stated (assessment 70 M4)."""

    stated: tuple[float, str]

    def __new__(cls, value: float, stated: tuple[float, str]) -> StatedLimit:
        made = super().__new__(cls, value)
        made.stated = stated
        return made

    def __getnewargs__(self):  # copied, pickled
        return float(self), self.stated


def _as_stated(number: float) -> str:
    """A number as it was typed: its shortest digits, in positional notation, or to the
    decimals it was typed with where it keeps them (a limit of "1.50" is ±1.50, its last
    place the one ASTM E29 rounds a value compared with it to:
    :class:`models.uncertainty.rounding.StatedNumber`)."""
    import numpy as np

    decimals = getattr(number, "decimals", None)
    if isinstance(decimals, int) and decimals >= 0:
        return f"{float(number):.{decimals}f}"
    return np.format_float_positional(number, unique=True, trim="-")


#: the significant digits a tolerance stated in another unit is converted to, printed beside
#: it and decided with (assessment 72 M2: three digits printed 7.0297 µrad as 1.45″, against
#: which the printed 0.95″ + 0.50″ passes, beside the conditional pass decided on 1.44998″)
CONVERTED_LIMIT_DIGITS = 6


def converted_limit(number: float, key: str, unit_key: str) -> float:
    """A tolerance stated as ``number`` in the unit ``key`` in the unit ``unit_key`` as it is
    printed beside it and decided with: to :data:`CONVERTED_LIMIT_DIGITS` significant
    digits (0.0001 % of it at most), so that a reader who redoes the decision from the
    printed figures and this T gets the printed verdict; exactly where the units agree."""
    if not unit_key or unit_key == key:
        return float(number)
    return float(f"{float(number) * unit(key).size / unit(unit_key).size:.{CONVERTED_LIMIT_DIGITS}g}")


def converted_text(value: float) -> str:
    """A tolerance converted to another unit (:func:`converted_limit`) as printed beside the
    one stated: its :data:`CONVERTED_LIMIT_DIGITS` significant digits, trailing zeros kept,
    so that a reader sees it is the converted figure to six digits (1.45000″ for 7.02979 µrad,
    1.4499983″; until 0.8.21 "1.45″", which read as exact or as a three-digit figure:
    assessment 73 L1)."""
    value = float(value)
    if value == 0.0 or not math.isfinite(value):
        return _as_stated(value)
    decimals = max(0, CONVERTED_LIMIT_DIGITS - 1 - math.floor(math.log10(abs(value))))
    return f"{value:.{decimals}f}"


class StatedTolerance(str):
    """A specification quoted as the customer stated it ("14.5 µrad"), followed, where it
    is read in another unit, by its value there as the decision uses it
    (:func:`converted_limit`: "14.5 µrad (2.99084″)"), so that the customer's specification
    is never replaced by a conversion, and the decision can be redone from the figures
    printed beside it."""

    stated: tuple[float, str]
    unit_key: str

    def __new__(cls, stated: tuple[float, str], unit_key: str) -> StatedTolerance:
        number, key = stated
        said = f"{_as_stated(number)}{unit(key).written()}"
        if unit_key and unit_key != key:
            value = converted_limit(number, key, unit_key)
            said += f" ({converted_text(value)}{unit(unit_key).written()})"
        made = super().__new__(cls, said)
        made.stated, made.unit_key = stated, unit_key
        return made

    def __getnewargs__(self):  # copied, pickled
        return self.stated, self.unit_key

    def to(self, key: str) -> StatedTolerance:
        return StatedTolerance(self.stated, key)


def tolerance_figure(tolerance: float, symbol: str) -> str:
    """A tolerance T as the decision texts print it: as the customer stated it where it is
    a :class:`StatedLimit` in another unit (:class:`StatedTolerance`), else exactly, to six
    significant digits (3″ is 14.5444 µrad read in µrad, never 14.5 µrad from a rounded
    figure)."""
    stated = getattr(tolerance, "stated", None)
    key = _unit_key(symbol)
    if stated is not None and key:
        return StatedTolerance(stated, key)
    if stated is not None and isinstance(getattr(stated[0], "decimals", None), int):
        # typed with trailing zeros: printed so (±1.50″), the place E29 rounds to
        return PrintedFigure(tolerance, symbol, decimals=stated[0].decimals)
    return PrintedFigure(tolerance, symbol, rounding="g", decimals=0)
