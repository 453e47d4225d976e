"""A run in progress: the last set, mounting, run (or target) not yet complete.

A workbench whose readings come in units (the polygon's sets, the cross-calibration's
mountings, the positioning's runs, the theodolite's passes) finds the *last* unit when it
is short of readings (:meth:`models.workbench.Workbench.split_incomplete`). The complete
units are analysed as they are; the incomplete one's readings enter no figure and are
shown as progress ("set 2: 3 of 24 faces"). Only the last unit may be incomplete: a
gap in the middle is refused by the analysis as before.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Hashable, Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, Message, listed, message, separated
from models.readings.sheet import Column, ParsedReadings

__all__ = ["UNIT_WORDS", "IncompleteUnit", "RowInProgress", "point_groups", "row_in_progress",
           "short_last_unit", "subset", "typing_row", "with_row_in_progress",
           "without_waiting_rows"]

#: each unit's words: (what the unit is, what its readings are)
UNIT_WORDS: dict[str, tuple[str, str]] = {
    "set": (QT_TR_NOOP("set {number}: {readings} of {expected} faces"), "faces"),
    "mounting": (QT_TR_NOOP("mounting {number}: {readings} of {expected} faces"), "faces"),
    "run": (QT_TR_NOOP("run {number}: {readings} of {expected} readings"), "readings"),
    "target": (QT_TR_NOOP("target {number}: {readings} of {expected} readings"), "readings"),
    "pass": (QT_TR_NOOP("pass {number}: {readings} of {expected} steps"), "steps"),
    # a workbench without units, or whose last unit is complete but for its last point:
    # that point, short of its n readings, is the unit in progress on its own
    "point": (QT_TR_NOOP("point {number}: {readings} of {expected} readings"), "readings"),
}


@dataclass(frozen=True)
class IncompleteUnit:
    """The last unit, short of readings: which (``unit`` "set", "mounting", "run",
    "target" or "pass", and its ``number``; "row": no unit but the row being typed, its
    :attr:`typing`), how many readings of how many, and the sheet
    rows (1-based) its readings are in. ``rows`` index the parsed readings (0-based)."""

    unit: str
    number: float
    readings: int
    expected: int
    first_row: int
    last_row: int
    rows: tuple[int, ...] = ()
    #: with n readings per point, the unit's last point when it is short of them (it is not
    #: counted in ``readings``): what it is ("face 3"), its readings taken, and n; a unit
    #: "point" (that point in progress on its own) named so when its workbench names it
    point: str = ""
    point_readings: int = 0
    per_point: int = 1
    #: the row a reading is being typed into, some of its reading cells typed and the
    #: others blank (:class:`RowInProgress`; None: none), after the unit's readings
    typing: RowInProgress | None = None

    def text(self) -> Any:
        """"set 2: 3 of 24 faces"; with its last point short of its n readings "set 2: 2 of
        24 faces, face 3: reading 1 of 2"; that point in progress on its own, named (a
        polygon set's closure): "set 1: closure on face 1: reading 1 of 2"; with a row
        being typed, that row after it ("set 2: 3 of 24 faces, row 29: encoder a not typed
        yet"), or the row alone (unit "row")."""
        if self.typing is None:
            return self._unit_text()
        if self.unit == "row":
            return self.typing.text()
        return separated((self._unit_text(), self.typing.text()), ", ")

    def _unit_text(self) -> Message:
        if self.unit == "point" and self.point:  # the point on its own, named with its unit
            return message(QT_TR_NOOP("{point}: reading {readings} of {n}"), point=self.point,
                           readings=self.point_readings, n=self.per_point)
        number = int(self.number) if float(self.number).is_integer() else self.number
        unit = message(UNIT_WORDS[self.unit][0], number=f"{number:g}"
                       if isinstance(number, float) else number, readings=self.readings,
                       expected=self.expected)
        if not self.point:
            return unit
        return message(QT_TR_NOOP("{unit}, {point}: reading {readings} of {n}"), unit=unit,
                       point=self.point, readings=self.point_readings, n=self.per_point)

    def progress(self) -> Message:
        """The line the summary and the command line print."""
        return message(QT_TR_NOOP("In progress: {unit} (rows {first}–{last}); its readings "
                                  "enter no figure until it is complete, and a certificate "
                                  "waits for it."),
                       unit=self.text(), first=self.first_row, last=self.last_row)

    def as_dict(self) -> dict[str, object]:
        """The JSON key ``incomplete``."""
        number = int(self.number) if float(self.number).is_integer() else float(self.number)
        out: dict[str, object] = {
            "unit": self.unit, "number": number, "readings": self.readings,
            "expected": self.expected, "first_row": self.first_row, "last_row": self.last_row,
            "text": str(self.text())}
        if self.point:
            out["point"] = {"name": str(self.point), "readings": self.point_readings,
                            "expected": self.per_point}
        if self.typing is not None:
            out["typing"] = {"row": self.typing.row + 1, "blank": list(self.typing.keys)}
        return out


@dataclass(frozen=True)
class RowInProgress:
    """The row a reading is being typed into by hand: some of its reading cells typed, the
    others (``keys``, headed ``headers`` as the table heads them) still blank. Between the
    two cells of a reading (the autocollimator's x, then the encoder; the theodolite's A,
    then E) it is a reading in progress, not a bad row: its blank cells wait, the complete
    rows keep their result, and a certificate waits for it (row81). ``row``: 0-based, as
    ``parsed.row_index``."""

    row: int
    keys: tuple[str, ...]
    headers: tuple[str, ...]
    #: the row's cells as typed, (column key, text) each: which point it is (its face, set)
    cells: tuple[tuple[str, str], ...] = ()

    def cell(self, key: str) -> str:
        """The text of the row's cell ``key`` ("" when blank or not known)."""
        return next((text for k, text in self.cells if k == key), "").strip()

    def text(self) -> Message:
        """"row 4: encoder a [deg] not typed yet"."""
        return message(QT_TR_NOOP("row {row}: {columns} not typed yet"), row=self.row + 1,
                       columns=listed(message(h) for h in self.headers))


def typing_row(row_count: int, reading_columns: Sequence[int], required: Sequence[bool],
               text: Callable[[int, int], str]) -> int | None:
    """The row a reading is being typed into at the end of the sheet: the last row with a
    reading cell typed (the rows after it have none: the plan's next points, waiting), when
    a reading cell that needs a value is blank in it (``required``: each of
    ``reading_columns``'s). None otherwise. A row in the middle is never it: a reading left
    half-typed there is a bad row, as before."""
    if not reading_columns:
        return None
    for r in range(row_count - 1, -1, -1):
        typed = [bool(text(r, c).strip()) for c in reading_columns]
        if any(typed):
            blank = any(need and not t for need, t in zip(required, typed, strict=True))
            return r if blank else None
    return None


def row_in_progress(parsed: ParsedReadings, row: int | None, reading_keys: Sequence[str],
                    columns: Sequence[Column], blank_too: Sequence[str] = (),
                    text: Callable[[int, int], str] | None = None
                    ) -> tuple[ParsedReadings, RowInProgress | None]:
    """``parsed`` less the cells that cannot be read of ``row`` (:func:`typing_row`, or the
    row the entry plan is filling) when each is a blank cell of ``reading_keys`` (or of
    ``blank_too``: a column the analysis waits for, never named), and that row in progress;
    ``parsed`` as it is and None when ``row`` is None or has a cell typed wrong or another
    cell wanting (a bad row, as before). The row is not among the readings (its blank
    cells left it out of them). ``text(row, column)``: the sheet's cells, kept with it."""
    if row is None:
        return parsed, None
    errors = [e for e in parsed.errors if e.row == row]
    allowed = set(reading_keys) | set(blank_too)
    if not errors or any(e.text.strip() or e.column_key not in allowed for e in errors):
        return parsed, None
    keys = {e.column_key for e in errors} & set(reading_keys)
    if not keys:
        return parsed, None
    ordered = tuple(c.key for c in columns if c.key in keys)
    headers = {c.key: c.header for c in columns}
    return (ParsedReadings(parsed.values, parsed.row_index,
                           [e for e in parsed.errors if e.row != row], parsed.first_line),
            RowInProgress(row, ordered, tuple(headers[k] for k in ordered),
                          () if text is None else tuple((c.key, text(row, i))
                                                        for i, c in enumerate(columns))))


def with_row_in_progress(unit: IncompleteUnit | None, typing: RowInProgress) -> IncompleteUnit:
    """The run in progress with the row being typed after it: ``unit``'s (its rows reaching
    the row), or the row alone (unit "row") when no unit is in progress."""
    sheet_row = typing.row + 1
    if unit is None:
        return IncompleteUnit("row", float(sheet_row), 0, 0, sheet_row, sheet_row, (),
                              typing=typing)
    return dataclasses.replace(unit, first_row=min(unit.first_row, sheet_row),
                               last_row=max(unit.last_row, sheet_row), typing=typing)


def point_groups(parsed: ParsedReadings, n: int) -> tuple[list[np.ndarray], int]:
    """The readings' indices taken ``n`` at a time, in order (each group one point, as
    models.readings.repeats.average_repeats takes them), the last group short when the
    readings are not a multiple of ``n``; and how many readings that short group has (0:
    none is short)."""
    total = parsed.n
    groups = [np.arange(i, min(i + n, total)) for i in range(0, total, n)]
    return groups, total % n


def subset(parsed: ParsedReadings, keep: np.ndarray) -> ParsedReadings:
    """The readings of the rows where ``keep`` is true (bad cells of the rows kept)."""
    keep = np.asarray(keep, dtype=bool)
    removed = set(parsed.row_index[~keep].tolist())
    return ParsedReadings({k: v[keep] for k, v in parsed.values.items()},
                          parsed.row_index[keep],
                          [e for e in parsed.errors if e.row not in removed])


def short_last_unit(unit_of_row: Sequence[Hashable], member_of_row: Sequence[Hashable],
                    expected: set) -> np.ndarray | None:
    """The indices of the last unit's readings when that unit is in progress: its rows are
    the last ones (one block), each of its members (face, target and direction) read once,
    and they are fewer than ``expected``, all among them. None otherwise."""
    n = len(unit_of_row)
    if n == 0 or not expected:
        return None
    last = unit_of_row[-1]
    rows = [i for i in range(n) if unit_of_row[i] == last]
    if rows != list(range(rows[0], n)):
        return None  # the last unit's readings are not the last rows: no run in progress
    members = [member_of_row[i] for i in rows]
    if len(set(members)) != len(members) or not set(members) < set(expected):
        return None
    return np.asarray(rows, dtype=int)


def _blank(value: object) -> bool:
    if isinstance(value, float):
        return not np.isfinite(value)
    return not str(value).strip()


def without_waiting_rows(parsed: ParsedReadings, reading_keys: tuple[str, ...],
                         blank_reading: Callable[[int], bool] | None = None,
                         planned: int | None = None) -> tuple[ParsedReadings, int]:
    """The readings less the rows at the end that wait for their reading: their plan's or
    nominal step's cells filled (target, face, set), every cell of ``reading_keys`` blank.
    Such a row is a point not yet taken, not a bad row. (readings, rows left out).

    ``blank_reading(row)``: whether the row's cells of ``reading_keys`` are all blank (its
    text); with it, a blank cell of a waiting row that is no reading's (the polygon's
    deviation, filled at the take) does not make it a bad row either (#62 review F8). A
    cell typed that cannot be read always does.

    ``planned``: the row the entry plan sends the next reading to, wherever it is — a row in
    the middle whose reading was cleared (a take thrown away) waits for it as the rows at
    the end do, and is left out on the same terms (it was counted a bad row)."""
    if not reading_keys or (parsed.n == 0 and not parsed.errors):
        return parsed, 0
    in_parsed = {int(r): i for i, r in enumerate(parsed.row_index.tolist())}
    errors_of: dict[int, list] = {}
    for e in parsed.errors:
        errors_of.setdefault(e.row, []).append(e)

    def waits(row: int) -> bool:
        errors = errors_of.get(row, [])
        if any(e.text.strip() for e in errors):
            return False  # a cell of its own is wrong: told as before
        if blank_reading is not None:
            if not blank_reading(row):
                return False  # it has a reading
        elif any(e.column_key not in reading_keys for e in errors):
            return False  # a cell of its own is wrong: told as before
        i = in_parsed.get(row)
        return i is None or all(_blank(parsed.values[k][i]) for k in reading_keys
                                if k in parsed.values)  # else it has a reading

    waiting: set[int] = set()
    for row in sorted(set(in_parsed) | set(errors_of), reverse=True):
        if not waits(row):
            break
        waiting.add(row)
    if planned is not None and (planned in in_parsed or planned in errors_of) and waits(planned):
        waiting.add(planned)
    if not waiting:
        return parsed, 0
    keep = np.array([int(r) not in waiting for r in parsed.row_index], dtype=bool)
    out = subset(parsed, keep)
    out.errors[:] = [e for e in out.errors if e.row not in waiting]
    return out, len(waiting)
