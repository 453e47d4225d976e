"""A figure's coverage interval said in the note beside it, in a table with no interval
columns: the theodolite's ISO 230-2 figures ("3.1″" — "coverage interval 1.0″ … 5.0″ (92 %)").

The note is a message whose ends keep their figures at full precision (:class:`Exact`), so
that the machine-readable outputs state the interval as numbers, as they state positioning's
(whose table has the columns "Coverage interval" and "Probability"): the results export as
number cells (from, to, probability), the DCC as a figure with its interval (value,
intervalMin, intervalMax, p). Audit 69 finding 5: the interval was in the note's text only.
"""

from __future__ import annotations

from typing import Any

from models.certificate.document import Exact
from models.messages import QT_TR_NOOP, Message, message

__all__ = ["INTERVAL_NOTE", "interval_cells", "interval_note"]

#: the note: the interval's ends as printed (rounded outwards) and its probability in %
INTERVAL_NOTE = QT_TR_NOOP("coverage interval {low} … {high} ({p} %)")


def interval_note(low: float, high: float, printed_low: str, printed_high: str,
                  percent: str) -> Message:
    """The note of an interval from ``low`` to ``high`` printed as ``printed_low`` …
    ``printed_high`` (each with its unit) at ``percent`` ("92", "95.45")."""
    # an end that converts itself from its value (a PrintedFigure) kept as it is
    return message(INTERVAL_NOTE,
                   low=printed_low if hasattr(printed_low, "to") else Exact(printed_low, float(low)),
                   high=printed_high if hasattr(printed_high, "to") else Exact(printed_high,
                                                                               float(high)),
                   p=percent)


def interval_cells(note: Any) -> tuple[str, str] | None:
    """The interval a note of :func:`interval_note` states, as the cells of a table with
    interval columns would hold it: ("1.0″ … 5.0″", an :class:`Exact` with both ends when
    the note's are exact; "92 %"); None for any other cell. Its ends as the note holds them:
    in the unit it was converted to, if it was (models.display_units.in_unit)."""
    if not isinstance(note, Message) or note.template != INTERVAL_NOTE or note.parts:
        return None
    low, high, p = (note.figures.get(key) for key in ("low", "high", "p"))
    if not all(isinstance(x, str) for x in (low, high, p)):
        return None
    span = f"{low} … {high}"
    first, last = getattr(low, "exact", None), getattr(high, "exact", None)
    if isinstance(first, float) and isinstance(last, float):
        return Exact(span, (first, last)), f"{p} %"
    return span, f"{p} %"
