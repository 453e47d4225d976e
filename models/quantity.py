"""A value with its unit, as data: arcseconds, microradians, nanometres ….

A figure that leaves a model (an uncertainty budget's input, a tolerance, a figure
in a result's text) carries its unit with it, from a closed set: angles (arcsec,
µrad, mdeg, deg, rad) and lengths (nm, µm, mm, m). Converting between units of one
dimension is a multiplication; converting an angle to a length is refused, so an
interferometer's nm can never be printed as arcseconds.

Why not pint: pint 0.25 takes 0.21–0.28 s to import and about 0.2 s more to build
its unit registry on this machine (``python -X importtime``), while the command
line's whole start-up target is 0.2 s (BENCHMARKS.md: ``anglebench analyze`` on a
sample, 0.17–0.18 s). We need nine units and a multiplication, not a units
language, so this module does it in a few lines and loads nothing.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["UNITS", "Quantity", "Unit", "UnitError", "unit", "unit_of_title"]


class UnitError(ValueError):
    """A unit this program does not know, or a conversion between dimensions."""


@dataclass(frozen=True)
class Unit:
    key: str  # the name stored in files: "arcsec", "urad", "nm"
    symbol: str  # as it is written after a number: '"', "µrad", "nm"
    dimension: str  # "angle" or "length"
    size: float  # this unit in the dimension's SI unit (rad or m)

    @property
    def spaced(self) -> bool:
        """A number and this unit are written with a space between them (1.5 µrad; 1.5")."""
        return self.symbol not in ("\"", "°", "'")

    def written(self) -> str:
        """The unit as it follows a number: '"' or " µrad"."""
        return f" {self.symbol}" if self.spaced else self.symbol


_ARCSEC = math.pi / (180.0 * 3600.0)
UNITS: dict[str, Unit] = {u.key: u for u in (
    Unit("arcsec", "\"", "angle", _ARCSEC),
    Unit("urad", "µrad", "angle", 1e-6),
    Unit("mdeg", "mdeg", "angle", math.pi / 180.0 / 1000.0),
    Unit("deg", "°", "angle", math.pi / 180.0),
    Unit("rad", "rad", "angle", 1.0),
    Unit("nm", "nm", "length", 1e-9),
    Unit("um", "µm", "length", 1e-6),
    Unit("mm", "mm", "length", 1e-3),
    Unit("m", "m", "length", 1.0),
)}

# other spellings of a unit (a symbol, a second µ, the prime of typography)
_SPELLINGS: dict[str, str] = {
    **{u.symbol: u.key for u in UNITS.values()}, "″": "arcsec", "μrad": "urad",
    "μm": "um", "µm": "um", "deg": "deg",
}


def unit(name: str | Unit) -> Unit:
    """The unit called ``name`` (a key such as "urad" or a symbol such as "µrad")."""
    if isinstance(name, Unit):
        return name
    key = _SPELLINGS.get(name.strip(), name.strip()) if isinstance(name, str) else name
    try:
        return UNITS[key]
    except (KeyError, TypeError):
        raise UnitError(f"unknown unit {name!r}; choose one of {', '.join(UNITS)}") from None


_named_unit = unit  # for Quantity, whose argument ``unit`` hides the function


_TITLE_UNIT = re.compile(r"\(([^()]+)\)\s*$")


def unit_of_title(title: str) -> str:
    """The key of the unit a title or header ends with ("error (µrad)" → "urad"), or ""
    when it ends with none of ours ("signal (V)")."""
    found = _TITLE_UNIT.search(str(title))
    if found is None:
        return ""
    name = found.group(1).strip()
    key = _SPELLINGS.get(name, name)
    return key if key in UNITS else ""


@dataclass(frozen=True, init=False)
class Quantity:
    """``value`` (a number or an array) in ``unit``; ``spec`` is how the number is
    written (a format spec such as ".2f" or "+.3f") when the quantity is shown as text.
    A converted quantity keeps the resolution its text had: :meth:`to` widens ``spec``
    by the decimals the conversion needs (1" at .2f is 4.85 µrad at .2f, 0.278 mdeg at
    .3f). The unit is given as a :class:`Unit` or its name, and held as a :class:`Unit`."""

    value: Any
    unit: Unit
    spec: str = "g"

    def __init__(self, value: Any, unit: Unit | str, spec: str = "g") -> None:
        object.__setattr__(self, "value", value)
        object.__setattr__(self, "unit", _named_unit(unit))
        object.__setattr__(self, "spec", spec)

    def factor_to(self, other: str | Unit) -> float:
        """What a value in this unit is multiplied by to be in ``other``."""
        target = unit(other)
        if target.dimension != self.unit.dimension:
            raise UnitError(f"cannot convert {self.unit.symbol} ({self.unit.dimension}) to "
                            f"{target.symbol} ({target.dimension})")
        return self.unit.size / target.size

    def to(self, other: str | Unit) -> Quantity:
        """The same quantity in ``other``, written at the resolution it had."""
        target = unit(other)
        factor = self.factor_to(target)
        if target == self.unit:
            return self
        value = (np.asarray(self.value, dtype=float) * factor if np.ndim(self.value)
                 else float(self.value) * factor)
        return Quantity(value, target, _converted_spec(self.spec, value, factor))

    def in_unit(self, other: str | Unit) -> Any:
        """The number (or array) in ``other``."""
        return self.to(other).value

    def __format__(self, spec: str) -> str:
        return f"{format(self.value, spec or self.spec)}{self.unit.written()}"

    def __str__(self) -> str:
        return format(self, "")

    def to_dict(self) -> dict[str, Any]:
        """As stored in a file: ``{"value": 0.5, "unit": "nm"}``."""
        value = self.value.tolist() if isinstance(self.value, np.ndarray) else self.value
        return {"value": value, "unit": self.unit.key}

    @classmethod
    def from_dict(cls, data: Any) -> Quantity:
        """From :meth:`to_dict`'s form; UnitError for anything else."""
        if not isinstance(data, dict) or set(data) != {"value", "unit"}:
            raise UnitError('a quantity is stored as {"value": number, "unit": name}')
        value = data["value"]
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise UnitError("a quantity's value must be a number")
        return cls(float(value), unit(str(data["unit"])))


def _converted_spec(spec: str, value: Any, factor: float) -> str:
    """``spec`` (".2f", "+.3f") with the decimals a conversion by ``factor`` needs: the
    resolution carried over, and never fewer than three significant digits."""
    head, dot, tail = spec.rpartition(".")
    if not dot or not tail.endswith("f") or not tail[:-1].isdigit():
        return spec
    decimals = int(tail[:-1]) + max(0, math.ceil(-math.log10(factor)))
    if np.ndim(value) == 0 and value != 0.0 and math.isfinite(value):
        decimals = max(decimals, 2 - math.floor(math.log10(abs(value))))
    return f"{head}.{max(0, decimals)}f"
