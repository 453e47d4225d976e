"""The angle unit a user reads results in: arcseconds, microradians or millidegrees.

Every figure is computed and kept in one unit (arcseconds; a positioning log in
the unit it was typed in). What is shown and exported is converted here, at the
last step, and only where it states an angle unit: a header ``error (")`` becomes
``error (µrad)`` and its values are scaled; a result text (a
:class:`~models.messages.Message`) is converted from the figures it was built
with (:func:`in_unit`), a :class:`~models.quantity.Quantity` by its unit, a figure
passed as text (``0.45"``) number by number. A quantity
whose unit is not an angle (nm, mV, V, °C) is left as it is, so an
interferometer's nm stay nm, and so is a reading in degrees, minutes and seconds
(``12°34'56.7"``: its seconds are no figure of their own).

Text that is not a Message (a table cell written as one string) is rewritten with
:func:`text_in_unit`, which converts each number written with its angle unit and
leaves a D°M'S" reading alone.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Any

import numpy as np

from models.messages import QT_TR_NOOP, Message, message
from models.quantity import Quantity
from models.uncertainty.printed_figure import PrintedFigure, PrintedRange, StatedTolerance
from models.uncertainty.rounding import fixed_places

if TYPE_CHECKING:  # a plot's module is loaded by whoever draws one
    from models.plots import PlotFigure

__all__ = [
    "ANGLE_UNITS",
    "AngleUnit",
    "angle_unit",
    "decimals_in_unit",
    "figure_in_unit",
    "figures_in_unit",
    "header_in_unit",
    "in_unit",
    "table_in_unit",
    "text_in_unit",
]


@dataclass(frozen=True)
class AngleUnit:
    key: str
    symbol: str  # as it is written after a number and in a header
    name: str
    per_arcsec: float  # how many of this unit make one arcsecond


ANGLE_UNITS: dict[str, AngleUnit] = {u.key: u for u in (
    AngleUnit("arcsec", "\"", "arcseconds (\")", 1.0),
    AngleUnit("urad", "µrad", "microradians (µrad)", math.pi / (180.0 * 3600.0) * 1e6),
    AngleUnit("mdeg", "mdeg", "millidegrees (mdeg)", 1000.0 / 3600.0),
)}

# how a unit is spelt where it is read: in a header "(…)" and after a number
_SPELLINGS: dict[str, str] = {"\"": "arcsec", "″": "arcsec", "arcsec": "arcsec",
                              "µrad": "urad", "μrad": "urad", "urad": "urad", "mdeg": "mdeg"}
_HEADER_UNIT = re.compile(r"\((\"|″|arcsec|µrad|μrad|urad|mdeg)\)")
_KEY_SUFFIX = re.compile(r"_(arcsec|urad|mdeg)(?![A-Za-z])")  # a column key: error_arcsec
# a number with its unit: not inside a quotation ("1.5" quoted is a cell's text), not
# the tail of a longer word or number, and not the seconds of a D°M'S" reading
_NUMBER_WITH_UNIT = re.compile(
    r"(?<![\"\w.'′°])(?<!' )(?<!′ )(?<!° )"
    r"([+\-−±]?)(\d+(?:\.(\d+))?(?:[eE][+\-]?\d+)?)(\"|″| ?µrad| ?μrad| ?mdeg)(?!\w)")


def angle_unit(key: str) -> AngleUnit:
    """The unit called ``key`` (arcsec, urad, mdeg); ValueError naming the choices."""
    try:
        return ANGLE_UNITS[key]
    except KeyError:
        raise ValueError(message(
            QT_TR_NOOP("unknown angle unit {key}; choose one of {join}"),
            key=f"{key!r}", join=', '.join(ANGLE_UNITS))) from None


def _places(value: float, decimals: int, factor: float, resolution_only: bool = False) -> int:
    """Decimals of a converted figure: the original's resolution carried over, and never
    fewer than three significant digits (1" is 0.278 mdeg, not 0.3); ``resolution_only``:
    the resolution alone (a figure printed to its interval's decimal, and its interval's
    ends, keep one decimal between them: R = 3" in 0" … 30" is 0.8 mdeg in 0.0 … 8.3 mdeg,
    not 0.833 mdeg)."""
    places = decimals + max(0, math.ceil(-math.log10(factor)))
    if value != 0.0 and math.isfinite(value) and not resolution_only:
        places = max(places, 2 - math.floor(math.log10(abs(value))))
    return max(0, places)


def decimals_in_unit(decimals: int, unit: AngleUnit) -> int:
    """The decimals a figure printed to ``decimals`` in arcseconds is shown to in ``unit``:
    its resolution carried over (0.01″ is 0.01 µrad, 0.001 mdeg), as :func:`text_in_unit`
    converts a printed figure."""
    return max(0, decimals + max(0, math.ceil(-math.log10(unit.per_arcsec))))


def _factor(spelt: str, unit: AngleUnit) -> float:
    return unit.per_arcsec / ANGLE_UNITS[_SPELLINGS[spelt.strip()]].per_arcsec


def header_in_unit(header: str, unit: AngleUnit) -> tuple[str, float]:
    """(the header with its angle unit rewritten, the factor its values are multiplied
    by): ``error (")`` or a column key ``error_arcsec``; a header without an angle unit
    comes back as it is, with factor 1."""
    found = _HEADER_UNIT.search(header)
    if found is not None:
        return (header[:found.start()] + f"({unit.symbol})" + header[found.end():],
                _factor(found.group(1), unit))
    found = _KEY_SUFFIX.search(header)
    if found is not None:
        return (header[:found.start()] + f"_{unit.key}" + header[found.end():],
                _factor(found.group(1), unit))
    return header, 1.0


def _rewrite(match: re.Match[str], unit: AngleUnit, resolution_only: bool = False) -> str:
    """A number written with its angle unit, in ``unit`` at the resolution it had."""
    sign, number, decimals, spelt = match.groups()
    factor = _factor(spelt, unit)
    if factor == 1.0:
        return match.group(0)
    value = float(number) * factor
    if "e" in number.lower():
        digits = f"{value:.3g}"
    else:
        digits = f"{value:.{_places(value, len(decimals or ''), factor, resolution_only)}f}"
    gap = "" if unit.symbol == "\"" else " "
    return f"{sign}{digits}{gap}{unit.symbol}"


#: a figure printed that converts itself from its value (models/printed_figure.py)
_PRINTED = PrintedFigure | PrintedRange | StatedTolerance


def _printed_in_unit(figure: PrintedFigure | PrintedRange | StatedTolerance,
                     unit: AngleUnit) -> str:
    """A printed figure in ``unit`` from its unrounded value, rounded there by its own rule
    (:mod:`models.uncertainty.printed_figure`), when it is in one of the units results are read in; a
    figure in degrees (a set-up parameter), nm or V as it is."""
    return figure.to(unit.key) if figure.unit_key in ANGLE_UNITS else figure


def text_in_unit(text: str, unit: AngleUnit, resolution_only: bool = False) -> str:
    """Plain ``text`` (not a Message) with every number written with an angle unit
    converted to ``unit``, keeping the figure's resolution and its sign; a D°M'S"
    reading is left as it is. A Message goes through :func:`in_unit` instead.
    ``resolution_only``: no significant digits added to a small figure (:func:`_places`)."""
    if isinstance(text, Message):
        return in_unit(text, unit, resolution_only)
    if isinstance(text, _PRINTED):  # converted from its value, rounded in ``unit``
        return _printed_in_unit(text, unit)
    return _NUMBER_WITH_UNIT.sub(lambda m: _rewrite(m, unit, resolution_only), text)


def _figure_in_unit(figure: Any, unit: AngleUnit, resolution_only: bool = False) -> Any:
    if isinstance(figure, Quantity):
        return figure.to(unit.key) if figure.unit.dimension == "angle" else figure
    if isinstance(figure, Message):
        return in_unit(figure, unit, resolution_only)
    if isinstance(figure, _PRINTED):
        return _printed_in_unit(figure, unit)
    if isinstance(figure, str):  # a figure passed formatted: "0.45\"", "±3.05\" (u, k = 1)"
        return text_in_unit(figure, unit, resolution_only)
    return figure


def in_unit(text: str, unit: AngleUnit, resolution_only: bool = False) -> str:
    """A result text with its angle figures in ``unit``. A :class:`Message` is rebuilt
    from its own figures (a Quantity converted by its unit, a figure given as text by
    :func:`text_in_unit`), so it can still be translated and its template's own words
    are never touched; its plain-text parts and any other text go through
    :func:`text_in_unit`."""
    if not isinstance(text, Message):
        return text_in_unit(text, unit, resolution_only) if isinstance(text, str) else text
    if text.parts:
        return Message(text.template, None, tuple(in_unit(p, unit, resolution_only)
                                                  for p in text.parts))
    if not text.figures:
        return text
    return Message(text.template, {k: _figure_in_unit(v, unit, resolution_only)
                                   for k, v in text.figures.items()})


def figures_in_unit(figures: Mapping[str, Any], unit: AngleUnit) -> dict[str, Any]:
    """Named figures ``{"name (unit)": value}`` with the angles converted."""
    out: dict[str, Any] = {}
    for name, value in figures.items():
        header, factor = header_in_unit(name, unit)
        out[header] = (value * factor if isinstance(value, int | float) and
                       not isinstance(value, bool) else value)
    return out


def figure_in_unit(figure: PlotFigure, unit: AngleUnit) -> PlotFigure:
    """The plot with its y values (and their bands) in ``unit`` when they are in one of
    the angle units results are read in (its ``y_unit``); other figures (volts, nm,
    degrees of a position) come back unchanged."""
    if figure.y_unit not in ANGLE_UNITS:
        return figure
    factor = unit.per_arcsec / ANGLE_UNITS[figure.y_unit].per_arcsec
    if factor == 1.0:
        return figure
    y_label, _ = header_in_unit(figure.y_label, unit)
    series = tuple(replace(s, y=np.asarray(s.y) * factor,
                           band=None if s.band is None else np.asarray(s.band) * factor)
                   for s in figure.series)
    return replace(figure, y_label=y_label, series=series, y_unit=unit.key)


def _cell_in_unit(cell: Any, factor: float, unit: AngleUnit,
                  resolution_only: bool = False) -> Any:
    if isinstance(cell, bool) or cell is None:
        return cell
    if isinstance(cell, int | float | np.floating | np.integer):
        return float(cell) * factor
    if isinstance(cell, _PRINTED | Message):  # from its own figures, not its digits
        return in_unit(cell, unit)
    text = str(cell)
    try:
        value = float(text.replace("−", "-"))
    except ValueError:
        return text_in_unit(text, unit, resolution_only)
    decimals = len(text.split(".")[1]) if "." in text and "e" not in text.lower() else None
    if decimals is None:
        return f"{value * factor:.6g}"
    sign = "+" if text.startswith("+") else ""
    places = _places(value * factor, decimals, factor, resolution_only)
    return fixed_places(value * factor, places, sign)  # a zero unsigned, as printed


def table_in_unit(header: Sequence[str], rows: Sequence[Sequence[Any]],
                  unit: AngleUnit, resolution_only: bool = False
                  ) -> tuple[tuple[str, ...], list[tuple[Any, ...]]]:
    """A table with each column whose header states an angle unit converted: numbers
    scaled, numeric text rewritten at its resolution, other text converted as text.
    ``resolution_only``: each printed figure at its own resolution carried over, no
    significant digits added (a table of figures printed to their intervals' decimal)."""
    converted = [header_in_unit(h, unit) for h in header]
    new_rows = []
    for row in rows:
        new_rows.append(tuple(
            _cell_in_unit(cell, converted[i][1], unit, resolution_only) if i < len(converted)
            and converted[i][1] != 1.0 else (text_in_unit(cell, unit, resolution_only)
                                             if isinstance(cell, str) else cell)
            for i, cell in enumerate(row)))
    return tuple(h for h, _ in converted), new_rows
