"""Where a captured reading goes and how it is written into the readings table.

* **The row a take goes to** (:func:`next_empty_point`): the row the cursor is on when the
  cells the take fills are blank there; else the next row below whose cells are all blank
  (rows pre-filled by a plan with target, face or θ but no reading count as empty points);
  else a new row after the last. A take never writes over a filled reading.
* **The row waiting for its reading** (:func:`waiting_row`): without a plan, the first of the
  rows at the end of the table that have their point (θ, target, face) but no reading yet —
  typing θ and Return with a nominal step leaves two such rows: the first is the next point
  (#41 review: the take filled row 2 while row 1 waited and the guidance named row 1's θ).
* **A row cleared in the middle** (:func:`cleared_row`): without a plan, the first row used
  whose cells the take fills and whose reading cells are all blank (a take thrown away).
  With the cursor on a filled row or below the last, the next take goes there, and the
  guidance names it (day review 64 P4: the guidance named the cleared row while a click on
  another row sent the take to a new row, warned about as at the wrong face).
* **The text of a cell** (:func:`cell_text`): the value rounded to the instrument's
  resolution (arcseconds, e.g. 0.01″, 0.1″, 1 µrad = 0.206265″), written in the column's
  angle format — D°M′S″ where the column's cells are written so, else decimal degrees — or
  in arcseconds for a column in arcseconds. The raw trace and ``capture --out`` keep the
  instrument's full precision; only the cell is rounded.
* **Elevation from a zenith angle** (:func:`elevation_from_zenith_deg`).
* **A reading in its target's turn** (:func:`in_turn_of`): a readout showing one turn sends
  the same position as −0.5 (a ±180° display) or 359.5 (a 0…360° display); into a
  column whose readings are positions in the turn of their row's target (positioning's
  *measured* on a rotary axis: ``Workbench.reading_positions``) the take writes it in the turn
  nearest that target — a reading within 180° of it as sent. The raw trace keeps the line
  as sent (the form the readout used).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from decimal import Decimal

from models.readings.angles import format_dms

__all__ = ["RESOLUTIONS_ARCSEC", "cell_step", "cell_text", "column_is_dms", "decimals_for",
           "cleared_row", "elevation_from_zenith_deg", "fixed_text", "in_turn_of", "next_empty_point",
           "rounded", "waiting_row"]

#: one microradian in arcseconds
MICRORADIAN_ARCSEC = 1e-6 * 180.0 / math.pi * 3600.0
#: the resolutions offered per instrument (arcseconds); 0 keeps what the instrument sent
RESOLUTIONS_ARCSEC = (0.0, 0.001, 0.01, 0.1, 1.0, MICRORADIAN_ARCSEC)

_DMS = re.compile(r"[°'′\"″]|^\s*[-+]?\d+\s+\d+(\s+\d+(\.\d*)?)?\s*$")


def next_empty_point(row_count: int, start: int, columns: Sequence[int],
                     text: Callable[[int, int], str]) -> int:
    """The row a take goes to: ``start`` or the first row after it whose cells in ``columns``
    are all blank (``text(row, column)`` is a cell's text); ``row_count`` (a new row) when
    there is none. ``start`` beyond the rows (the empty row after the last) is kept."""
    start = max(0, start)
    for r in range(start, row_count):
        if all(not text(r, c).strip() for c in columns):
            return r
    return max(start, row_count)


def cleared_row(before: int, column_count: int, take_columns: Sequence[int],
                reading_columns: Sequence[int], text: Callable[[int, int], str]) -> int | None:
    """The first row above ``before`` that is used (some cell filled) but whose cells of
    ``take_columns`` and ``reading_columns`` are all blank: a row whose reading was cleared
    (a take thrown away), waiting for it. None when there is none (or no take column)."""
    if not take_columns:
        return None
    empty = tuple(take_columns) + tuple(reading_columns)
    for r in range(max(0, before)):
        if all(not text(r, c).strip() for c in empty) \
                and any(text(r, c).strip() for c in range(column_count)):
            return r
    return None


def waiting_row(row_count: int, column_count: int, reading_columns: Sequence[int],
                text: Callable[[int, int], str]) -> int | None:
    """The first of the rows at the end of the table (blank rows after them aside) that wait
    for their reading: some cell filled, every cell of ``reading_columns`` blank; None when
    the last row used has a reading (or no row is used, or no column is a reading's)."""
    if not reading_columns:
        return None
    first = None
    for r in range(row_count - 1, -1, -1):
        if not any(text(r, c).strip() for c in range(column_count)):
            if first is None:
                continue  # blank rows after the last used one
            break
        if any(text(r, c).strip() for c in reading_columns):
            break
        first = r
    return first


def in_turn_of(value: float, near: float) -> float:
    """An angle in degrees in the turn nearest ``near`` (its row's target): ``value`` itself
    when within 180° of it — a reading in its target's own turn is never changed — else
    ``value`` + k·360°. At target 0° a ±180° display's −0.5 stays −0.5 and a 0…360°
    display's 359.5 becomes −0.5; at 360° 0.0003 becomes 360.0003; at 270° −90.0003
    becomes 269.9997 (as sent they were 360° from their target, a deviation the analysis
    refuses). The turns are added to the decimal digits the value has (359.9996 − 360 is
    −0.0004, not −0.000400000000013). A number not finite is returned as it is."""
    if not (math.isfinite(value) and math.isfinite(near)) or abs(value - near) <= 180.0:
        return value
    return float(Decimal(repr(value)) + 360 * round((near - value) / 360.0))


def rounded(value: float, resolution: float) -> float:
    """``value`` to the nearest multiple of ``resolution`` (0: unchanged)."""
    if resolution <= 0 or not math.isfinite(value):
        return value
    return round(value / resolution) * resolution


def decimals_for(resolution: float) -> int:
    """Decimals that show a multiple of ``resolution`` to a tenth of it (a power of ten: its
    own decimals)."""
    if resolution <= 0:
        return 12
    exponent = -math.log10(resolution)
    if abs(exponent - round(exponent)) < 1e-9:
        return max(0, round(exponent))
    return max(0, math.ceil(exponent + 1))


def column_is_dms(texts: Sequence[str]) -> bool:
    """Whether a column's cells are written as D°M′S″ (the majority of its filled cells)."""
    filled = [t for t in texts if t.strip()]
    if not filled:
        return False
    return 2 * sum(1 for t in filled if _DMS.search(t)) > len(filled)


def elevation_from_zenith_deg(zenith_deg: float) -> float:
    """The elevation of a sight from its zenith angle: 90° − V in face I (V ≤ 180°), V − 270°
    in face II."""
    return 90.0 - zenith_deg if zenith_deg <= 180.0 else zenith_deg - 270.0


def cell_text(value: float, unit: str, resolution_arcsec: float, dms: bool = False,
              column_unit: str = "") -> str:
    """The text a captured ``value`` (in ``unit``: ``"deg"`` or ``"arcsec"``, else the
    readout's own unit) is written as in a cell.

    ``resolution_arcsec`` is the instrument's resolution (0: as sent, 12 significant
    digits); ``dms`` writes degrees as D°M′S″; ``column_unit`` ``'"'`` writes an angle in
    arcseconds. A value in another unit is rounded to ``resolution_arcsec`` taken in its
    own unit."""
    if unit == "deg" and column_unit not in ('"', "arcsec"):
        if resolution_arcsec <= 0:
            # as sent: D°M′S″ to 0.001″ (a readout's 0.00001° is 0.036″), else every digit
            return format_dms(value, 3) if dms else _as_sent(value)
        arcsec = rounded(value * 3600.0, resolution_arcsec)
        if dms:
            return format_dms(arcsec / 3600.0, decimals_for(resolution_arcsec))
        return fixed_text(arcsec / 3600.0, decimals_for(resolution_arcsec / 3600.0))
    if unit == "deg":
        value, unit = value * 3600.0, "arcsec"
    if resolution_arcsec <= 0:
        return _as_sent(value)
    return fixed_text(rounded(value, resolution_arcsec), decimals_for(resolution_arcsec))


def cell_step(unit: str, resolution_arcsec: float, dms: bool = False,
              column_unit: str = "") -> float:
    """The step :func:`cell_text` rounds a value in ``unit`` to, in that unit (0: none, 12
    significant digits): what a cell may differ from the instrument's reading by, half of
    it, and still hold that reading (models/capture/edits.py)."""
    if unit == "deg":
        if resolution_arcsec <= 0:
            as_sent_dms = dms and column_unit not in ('"', "arcsec")
            return 0.001 / 3600.0 if as_sent_dms else 0.0
        return resolution_arcsec / 3600.0
    return max(0.0, resolution_arcsec)


def fixed_text(value: float, decimals: int) -> str:
    """``value`` to ``decimals`` in fixed notation, never "-0.00" (a value that rounds to
    zero is "0.00")."""
    text = f"{value:.{decimals}f}"
    if text.startswith("-") and float(text) == 0.0:
        text = text[1:]
    return text


def _as_sent(value: float) -> str:
    """A value as sent (12 significant digits) in fixed notation, never scientific nor
    "-0": a readout's 0.00004° is "0.00004", not "4e-05" (review 62, F12)."""
    if not math.isfinite(value):
        return f"{value}"
    text = format(Decimal(f"{value:.12g}"), "f")
    return text[1:] if text.startswith("-") and float(text) == 0.0 else text
