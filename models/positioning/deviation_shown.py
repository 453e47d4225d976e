"""The deviation a positioning row without one has: measured − target in the deviation unit,
as the analysis takes it (models/positioning/analysis.py ``_deviations``), for the readings
table to show in the row's blank *deviation* cell while the reading comes in as a measured
position (a readout's take, or one typed). Shown, never written: the sheet keeps what was
typed or taken, and an edit of the measured position changes the figure shown with it.

It is written to the resolution the two positions were given to: the step of their last
decimal in the deviation unit, one digit finer (a measured 15.0003° is 1.08″ off 15°, not
1.1″); a position in D°M′S″ to 0.01 of the deviation unit. A figure that rounds to zero has
no sign (models/uncertainty/rounding.fixed_places, as the certificate writes it).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

from models.messages import QT_TR_NOOP
from models.positioning.model import DEVIATION_UNITS
from models.readings.angles import AngleParseError, parse_angle_deg
from models.uncertainty.rounding import fixed_places

__all__ = ["DEVIATION_SHOWN_NOTE", "deviation_from_measured"]

#: what the table says of a deviation it shows and no one typed (its tooltip)
DEVIATION_SHOWN_NOTE = QT_TR_NOOP("measured − target in the deviation unit, as the analysis "
                                  "takes it (shown, not typed: typing a deviation replaces it)")


def _decimals(text: str) -> int | None:
    """Decimals of a plain number's text; None for any other form (D°M′S″)."""
    stripped = text.strip().lstrip("+-−")
    head, _, tail = stripped.partition(".")
    if not head.isdigit() and not (not head and tail.isdigit()):
        return None
    return len(tail) if tail.isdigit() else 0


def deviation_from_measured(target: str, measured: str, settings: Mapping[str, Any]
                            ) -> str | None:
    """(measured − target) in the deviation unit of ``settings``, as text; None when either
    position is blank or cannot be read, or the units are not known."""
    if not target.strip() or not measured.strip():
        return None
    unit = DEVIATION_UNITS.get(str(settings.get("deviation_unit", "arcsec")))
    if unit is None:
        return None
    try:
        t = parse_angle_deg(target.strip())
        m = parse_angle_deg(measured.strip())
    except (AngleParseError, ValueError):
        return None
    value = (m - t) * unit[1]
    if not math.isfinite(value):
        return None
    places = [_decimals(target), _decimals(measured)]
    if None in places:
        decimals = 2
    else:
        step = 10.0 ** -max(p for p in places if p is not None) * unit[1]
        decimals = min(9, max(0, 1 - math.floor(math.log10(step))))
    return fixed_places(value, decimals)


def shown_deviation(settings: Mapping[str, Any]
                    ) -> Callable[[Callable[[str], str]], str | None]:
    """The blank deviation cell's figure from the row's cells (``text(key)``)."""
    return lambda text: deviation_from_measured(text("target"), text("measured"), settings)
