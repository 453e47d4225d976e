"""A run in progress: the last set, mounting, run (or target) not yet complete.

A workbench whose readings come in units (the polygon's sets, the cross-calibration's
mountings, the positioning's runs, the theodolite's passes) finds the *last* unit when it
is short of readings (:meth:`models.workbench.Workbench.split_incomplete`). The complete
units are analysed as they are; the incomplete one's readings enter no figure and are
shown as progress ("set 2: 3 of 24 faces"). Only the last unit may be incomplete: a
gap in the middle is refused by the analysis as before.
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Sequence
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, Message, message
from models.readings.sheet import ParsedReadings

__all__ = ["UNIT_WORDS", "IncompleteUnit", "point_groups", "short_last_unit", "subset",
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
    "target" or "pass", and its ``number``), how many readings of how many, and the sheet
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

    def text(self) -> Message:
        """"set 2: 3 of 24 faces"; with its last point short of its n readings "set 2: 2 of
        24 faces, face 3: reading 1 of 2"; that point in progress on its own, named (a
        polygon set's closure): "set 1: closure on face 1: reading 1 of 2"."""
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
        return out


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
