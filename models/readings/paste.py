"""What a paste into the readings does, decided before anything changes.

* A first row that reads as no value of the columns it lands on, while a later row does,
  and that names a column or holds words only (no digits), is a header: it is taken off,
  and when it names the columns (models/readings/headers.py) the cells go to the columns
  it names, whatever their order. A first row of mistyped readings is pasted as typed.
* A paste over the whole sheet (every row selected) replaces the sheet, from its first
  column (or by the header's names): a block without a header goes to the first column
  whatever cell the cursor was on (day review 65 F1: it went to the cursor's column, the
  target, run and direction left empty and the block's last columns dropped).
* Which of the sheet's columns the block fills (:attr:`PastePlan.filled`) and which of its
  columns fall beyond the sheet's last one (:attr:`PastePlan.dropped`) are known, for the
  window to say: never a column dropped, nor a replaced sheet's column left empty, silently.
* A block of readings (two rows and two columns or more) landing on the first row of a
  longer run would leave that run's later rows behind it — a silent mix of two runs.
  That case is not decided here: the window asks whether to replace the sheet or
  overwrite those rows only.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from models.readings.headers import match_header
from models.readings.sheet import Column

__all__ = ["PastePlan", "plan_paste"]


@dataclass(frozen=True)
class PastePlan:
    rows: list[list[str]]  # the block, header taken off; full rows when ``left`` is 0 and mapped
    left: int  # the sheet column the block's first column goes to
    header: list[str] | None  # the header row taken off, if any
    mapped: bool  # the cells were placed by the header's names
    replace_sheet: bool  # the block replaces every row
    leaves_rows: int  # filled rows of the run after the block: ask before a silent mix
    #: the sheet's columns a column of the block goes to, in the sheet's order
    filled: tuple[int, ...] = ()
    #: the block's columns (0-based, holding text) beyond the sheet's last column: left out
    dropped: tuple[int, ...] = ()


def _parses(column: Column, text: str) -> bool:
    if not text.strip():
        return False
    try:
        return column.parse(text) is not None
    except ValueError:
        return False


def _reads_as_values(row: Sequence[str], columns: Sequence[Column], left: int) -> bool:
    return any(_parses(columns[left + j], cell) for j, cell in enumerate(row)
               if left + j < len(columns))


def plan_paste(grid: Sequence[Sequence[str]], columns: Sequence[Column], filled_rows: int,
               top: int, left: int, whole_sheet: bool) -> PastePlan:
    rows = [[c.strip() for c in r] for r in grid]
    header = None
    mapped = False
    positions = match_header(rows[0], columns) if rows else []
    # a header names a column, or holds words only: a first row of mistyped readings (digits
    # in it) is pasted as it is and shows red, never dropped as if it were a header
    names = any(p is not None for p in positions) or all(
        not any(ch.isdigit() for ch in c) for c in rows[0] if c) if rows else False
    if len(rows) >= 2 and any(c for c in rows[0]) and names \
            and not _reads_as_values(rows[0], columns, left) \
            and any(_reads_as_values(r, columns, left) for r in rows[1:]):
        header, rows = rows[0], rows[1:]
        named = {p for p in positions if p is not None}
        # by name only when every header cell names a column: a header that names some
        # would drop the others' cells; it then lands where the cursor is, as typed
        if named and named == {j for j, c in enumerate(header) if c}:
            mapped, left = True, 0
            rows = [[r[p] if p is not None and p < len(r) else "" for p in positions]
                    for r in rows]
    if whole_sheet and not mapped:
        left = 0  # the sheet replaced: its rows from their first cell, as a spreadsheet does
    used = max((max((j + 1 for j, c in enumerate(r) if c), default=0) for r in rows), default=0)
    if mapped:
        filled = tuple(c for c, p in enumerate(positions) if p is not None)
        dropped: tuple[int, ...] = ()
    else:
        filled = tuple(range(left, min(left + used, len(columns))))
        dropped = tuple(j for j in range(max(0, len(columns) - left), used)
                        if any(j < len(r) and r[j] for r in rows))
    if whole_sheet:
        return PastePlan(rows, left, header, mapped, True, 0, filled, dropped)
    width = max((len(r) for r in rows), default=0)
    block = len(rows) >= 2 and width >= 2
    leaves = filled_rows - (top + len(rows)) if block and top == 0 else 0
    return PastePlan(rows, left, header, mapped, False, max(0, leaves), filled, dropped)
