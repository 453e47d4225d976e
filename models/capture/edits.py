"""Readings that no longer say what the instrument said: a captured reading edited in the
sheet afterwards.

Each *take* of a capture session (models/capture/raw_record.py) names the sheet row it
filled and the instrument's frames behind it. The reading those frames give (one frame, or
the mean of a dwell's frames) is compared with what the row's cells hold now; a cell that
differs is an edit after capture. The raw frames and their SHA-256 stay as captured: the
certificate prints the hash, and says which rows were edited and from what to what.

A captured reading whose row was deleted (or replaced: models/capture/take_rows.py) is
said as deleted, with what the frames gave; a take whose frames hold no reading, or a
session recorded on another workbench, cannot be checked and is said so (review 61 F7:
both passed without a word).

A reading whose cell was emptied is said *cleared*, with what the frames gave (it was
"edited …: 300.00002 → —"). A row captured again — its cells cleared and the reading taken
anew, or its take undone and the reading taken anew into it, the older take superseded
(models/capture/take_rows.py) — is checked against the
newer take alone and said once, "captured again", never "edited" (review 62 F1): the
customer is told that the raw record (ISO/IEC 17025 7.5.1, its SHA-256 on the certificate)
holds two takes for that row, and which one the row reports. A file written before the
takes were marked so (two takes of one instrument claiming a row) is read the same way:
the later take is the row's.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import Any

from models.capture.take_cells import cell_text, column_is_dms, in_turn_of
from models.capture.take_rows import deleted_at, superseded_by
from models.messages import QT_TR_NOOP, Message, message
from models.readings.angles import format_dms, parse_angle_deg

__all__ = ["EditedReading", "captured_values", "edited_after_capture"]

#: a cell that holds the captured value within this (relative) is the captured reading: it
#: was written with 12 significant digits
_SAME = 1e-9


@dataclass(frozen=True)
class EditedReading:
    #: the sheet row (0-based) and the column's key
    row: int
    column: str
    #: the reading the frames give, and the cell's text now ("" when emptied)
    captured: str
    now: str
    #: "edited"; "cleared": its cell emptied; "missing": a reading whose cell was chosen at
    #: the time (a readout's) is in no cell of its row now; "again": the row captured again
    #: (an older take superseded; ``column`` ""); "deleted": the row (``row``: where it was
    #: then) was deleted, or the sheet replaced; "unverifiable": no frame behind the take
    #: reads; "elsewhere": a session recorded on the workbench ``now`` (``row`` -1,
    #: ``captured`` the session's start)
    what: str = "edited"

    @property
    def in_sheet(self) -> bool:
        """The reading is in the sheet's row ``row`` now (its cell can be marked there)."""
        return self.what in ("edited", "cleared", "unverifiable") and self.row >= 0

    def text(self) -> Message:
        if self.what == "cleared":
            return message(QT_TR_NOOP("reading of row {row} cleared after capture: {captured}"),
                           row=self.row + 1, captured=self.captured)
        if self.what == "missing":
            return message(QT_TR_NOOP("reading of row {row} edited or cleared after capture: "
                                      "no cell of the row holds {captured} now"),
                           row=self.row + 1, captured=self.captured)
        if self.what == "again":
            return message(QT_TR_NOOP("reading of row {row} captured again, superseding an "
                                      "earlier take (both kept in the instrument output)"),
                           row=self.row + 1)
        if self.what == "deleted":
            return message(QT_TR_NOOP("reading of row {row} deleted after capture: {captured}"),
                           row=self.row + 1, captured=self.captured or "—")
        if self.what == "unverifiable":
            return message(QT_TR_NOOP("reading of row {row} cannot be checked against the "
                                      "capture: its frames give no value of this sheet"),
                           row=self.row + 1)
        if self.what == "elsewhere":
            return message(QT_TR_NOOP("capture session started {started} was recorded on "
                                      "workbench '{workbench}': its readings cannot be checked "
                                      "here"), started=self.captured, workbench=self.now)
        return message(QT_TR_NOOP("reading of row {row} edited after capture: {captured} → "
                                  "{now}"), row=self.row + 1, captured=self.captured,
                       now=self.now or "—")


def captured_values(session: dict[str, Any], first: int, last: int,
                    values_of: Callable[[str, bytes], tuple[float, ...] | None],
                    angles: bool, wrapped: bool = True) -> tuple[float, ...] | None:
    """The reading frames ``first``…``last`` of ``session`` give: the mean of those that
    were readings (angles in degrees averaged about the first, so 359.9° and 0.1° give 0°,
    or 360° not ``wrapped`` into [0°, 360°): the first frame's own turn). None when no frame
    there reads."""
    got = []
    for _, line, used in session["frames"][first:last + 1]:
        if not used:
            continue
        values = values_of(session["instrument"], line.encode("latin-1"))
        if values is not None:
            got.append(tuple(float(v) for v in values))
    if not got or any(len(g) != len(got[0]) for g in got):
        return None
    if not angles:
        return tuple(math.fsum(g[i] for g in got) / len(got) for i in range(len(got[0])))
    origin = got[0]
    means = []
    for i, o in enumerate(origin):
        offsets = [(g[i] - o + 180.0) % 360.0 - 180.0 for g in got]
        mean = o + math.fsum(offsets) / len(offsets)
        means.append(mean % 360.0 if wrapped else mean)
    return tuple(means)


def _number(text: str, angle: bool) -> float | None:
    text = text.strip()
    if not text:
        return None
    try:
        return float(parse_angle_deg(text)) if angle else float(text)
    except (ValueError, TypeError, OverflowError):
        return None


#: angles a take writes as they are, never brought into [0°, 360°): an elevation (90° − V
#: or V − 270°, within ±90°)
_AS_IS = frozenset({"elevation_deg"})


def _forms(value: float, angle: bool, key: str) -> tuple[float, ...]:
    """The numbers a take writes for a captured ``value`` (the frames' reading in the first
    frame's own turn, :func:`captured_values` not wrapped): that one — a take by hand writes
    the instrument's reading as sent — and, for an angle, the same brought into [0°, 360°)
    (an auto-take's mean of its frames).

    Never any other turn (review 62 M3: cells were compared on the circle, so a captured
    12.5° typed as 372.5° — or as −347.5° — was "as captured"). The certificate prints the
    number in the cell, not the angle it stands for: a workbench that reads 372.5 differently
    from 12.5 (a theodolite's analysis does not wrap; a rotary table's turns count), or a
    customer who reads both, must see that the number changed."""
    if not angle or key in _AS_IS:
        return (value,)
    turned = value % 360.0
    forms: tuple[float, ...] = (value,) if turned == value else (value, turned)
    # a mean on 0° itself, a hair below or above it, is written 0° or 360° as the float
    # falls (the window's mean and this one are worked out apart): both are the reading
    if turned < _SAME * 360.0:
        forms += (turned + 360.0,)
    elif 360.0 - turned < _SAME * 360.0:
        forms += (turned - 360.0,)
    return forms


def _same(cell: float | None, value: float, step: float = 0.0) -> bool:
    """The cell holds ``value``: to 12 significant digits, or within half the ``step`` the
    take rounded it to (the instrument's resolution, in the reading's unit)."""
    if cell is None:
        return False
    # 0.51: a D°M′S″ cell rounds the rounded seconds once more to its decimals
    return abs(cell - value) <= max(_SAME * max(1.0, abs(value)), 0.51 * step)


def _as_captured(cell: float | None, forms: tuple[float, ...], step: float) -> bool:
    return any(_same(cell, form, step) for form in forms)


def _seconds_decimals(texts: Sequence[str]) -> int:
    """The most decimals of seconds a column's D°M′S″ cells are written with (1: none
    written so)."""
    decimals = [len(m.group(1)) for t in texts
                if column_is_dms([t]) and (m := _SECONDS.search(t))]
    return max(decimals, default=1)


#: the decimals of a D°M′S″ cell's seconds: 12°34′56.789″, 12 34 56.789
_SECONDS = re.compile(r"\d[.,](\d+)\s*[\"″]?\s*$")


def _shown(cell: float | None, forms: tuple[float, ...], now: str = "",
           step_deg: float = 0.0, column: Sequence[str] = ()) -> str:
    """The captured reading as said beside an edit: in the form nearest the cell's; as
    D°M′S″ to the step the take wrote it to where the cell ``now`` is D°M′S″ (an angle in
    degrees, written to a step), so that it reads beside the cell ("30°00′00.4″ →
    30°00′01.4″", not "30.000123398 → 30°00′01.4″"). A cell emptied (``now`` "") is said
    as its ``column`` (the column's cells now) writes it: D°M′S″ where the column is kept so,
    to the step the take wrote it to, or (a take that recorded none) to the decimals of the
    column's seconds (day review 65: "cleared after capture: 90.00012" of a D°M′S″ cell)."""
    form = forms[0] if cell is None else min(forms, key=lambda f: abs(cell - f))
    written = [now] if now.strip() else list(column)
    if step_deg > 0.0 and column_is_dms(written):
        return cell_text(form, "deg", step_deg * 3600.0, dms=True)
    if not now.strip() and column_is_dms(written):
        return format_dms(form, _seconds_decimals(written))
    return f"{form:.12g}"


def _steps(session: dict[str, Any]) -> list[float]:
    """Per take, the step its cells were written with (``steps``, since #41; a session
    stored before holds none: its cells had every digit)."""
    steps = session.get("steps")
    return [float(s) for s in steps] if isinstance(steps, list) else []


def edited_after_capture(sessions: Sequence[dict[str, Any]], rows: Sequence[Sequence[str]],
                         columns_of: Callable[[str], Sequence[tuple[str, int | None]]],
                         values_of: Callable[[str, bytes], tuple[float, ...] | None],
                         cache: dict | None = None, workbench: str = "",
                         turn_of_row: Callable[[Sequence[str]], float | None] | None = None,
                         number_in: Callable[[int, str], float | None] | None = None,
                         keys: Sequence[str] = ()) -> list[EditedReading]:
    """Every cell of a taken reading that differs now from the reading its frames give;
    then every captured reading whose row was deleted, every take none of whose frames
    reads, and (``workbench`` given) every session recorded on another workbench.

    ``columns_of(instrument)``: per value of the instrument's reading, the column's key and
    index in the sheet (index None: the value went to a cell chosen at the time, e.g. a
    readout's; such a reading is edited when no cell of its row holds it any more; -1: the
    sheet has no column for it).
    ``values_of(instrument, line)``: the values a frame reads (None if none). ``cache``: a
    dict kept between calls, the frames' readings by session and take (they never change).
    ``turn_of_row(cells)``: the angle (degrees) a take wrote a row's reading in the turn of
    (models/capture/take_cells.py in_turn_of: positioning's target on a rotary axis; None:
    as sent): the reading in that turn is the reading as captured too.
    ``number_in(column, text)``: the number a cell of the sheet's column ``column`` holds,
    read as the analysis reads that column (None: none) — an angle column's D°M′S″ by the
    angle parser, whichever instrument wrote it (a readout's reading in a D°M′S″ column was
    "edited or cleared after capture": its value, not an angle by its key, was read with
    ``float``). Not given: a cell is read as a decimal number, or as an angle where the
    instrument's values are angles.
    ``keys``: the sheet's column keys. A session that records, per take, the column a
    readout's value went to (``columns``, raw_record.OPTIONAL_KEYS) has that cell checked
    as any other captured cell ("edited …: 30°00′00.4″ → 30°00′01.4″", "cleared"; marked in
    the table), not searched for in the row (day review 64 P3)."""
    edited: dict[tuple[int, str], EditedReading] = {}
    # the takes superseded by a newer one into their rows: by the newer's key (take_rows.py);
    # in a file from before, a take of an instrument claiming a row a later take of it claims
    # (not a reading written into a cell chosen at the time, a readout's: two of them may be
    # in two columns of the row)
    latest: dict[tuple[int, str], tuple] = {}
    superseding: set[tuple] = set()
    for session in sessions:
        fixed = all(column is not None for _, column in columns_of(session["instrument"]))
        for stored in session["takes"]:
            this = (session["instrument"], session["port"], session["started_utc"],
                    int(stored[1]), int(stored[2]))
            if (by := superseded_by(stored)) is not None:
                superseding.add(by)
            elif stored[0] >= 0 and fixed:
                if latest.get((stored[0], this[0]), this) != this:
                    superseding.add(this)
                latest[(stored[0], this[0])] = this
    # said apart from the edits: a deleted row's number is the one it had then, and
    # another row may hold that number now
    unchecked: list[EditedReading] = []
    for session in sessions:
        instrument = session["instrument"]
        recorded_on = session.get("workbench")
        if workbench and recorded_on is not None and recorded_on != workbench:
            unchecked.append(EditedReading(-1, "", str(session["started_utc"]),
                                           str(recorded_on), "elsewhere"))
            continue
        targets = list(columns_of(instrument))
        # values in degrees (a column key ending in _deg) are angles: averaged on the circle,
        # compared as the numbers a take writes (_forms: never another turn, review 62 M3)
        angles = bool(targets) and all(key.endswith("_deg") for key, _ in targets)
        steps = _steps(session)
        written = session.get("columns")
        written = written if isinstance(written, list) else []

        def number(column: int, text: str, angles: bool = angles) -> float | None:
            if not text.strip():
                return None
            return number_in(column, text) if number_in is not None else _number(text, angles)

        for take, stored in enumerate(session["takes"]):
            row, first, last = (int(v) for v in stored[:3])
            step = steps[take] if take < len(steps) else 0.0
            take_key = (instrument, session["port"], session["started_utc"], first, last)
            if cache is not None and take_key in cache:
                values = cache[take_key]
            else:
                values = captured_values(session, first, last, values_of, angles,
                                         wrapped=False)
                if cache is not None:
                    cache[take_key] = values
            gone = deleted_at(row)
            if gone is not None:  # its row deleted: the captured reading is not in the sheet
                shown = [f"{v:.12g}" for (_, column), v in zip(targets, values or (), strict=False)
                         if column is None or column >= 0]
                unchecked.append(EditedReading(gone, targets[0][0] if targets else "",
                                               ", ".join(shown), "", "deleted"))
                continue
            if row < 0:  # replaced, superseded by a later take, or undone
                continue
            if latest.get((row, instrument), take_key) != take_key:
                continue  # a later take of the instrument claims the row (a file from before)
            if take_key in superseding:  # the row's reading taken again: said once
                edited[(row, "")] = EditedReading(row, "", "", "", "again")
            checked = [column for _, column in targets if column is None or column >= 0]
            if values is None or not checked:
                # no frame behind it reads (a flag set to 0 by hand), or none of its values
                # has a column in this sheet (a session moved from another workbench): the
                # reading cannot be checked, which is said rather than passed
                key = next((k for k, c in targets if c is not None and c >= 0), "")
                edited[(row, key or "?")] = EditedReading(row, key, "", "", "unverifiable")
                continue
            cells = list(rows[row]) if row < len(rows) else []
            near = turn_of_row(cells) if turn_of_row is not None else None
            cell_key = written[take] if take < len(written) else ""
            for (key, column), value in zip(targets, values, strict=False):
                forms = _forms(value, angles, key)
                # a readout's step is in its value's unit: degrees where it wrote D°M′S″
                in_degrees = key.endswith("_deg")
                if column is None and cell_key and cell_key in keys:
                    key, column = cell_key, list(keys).index(cell_key)  # the cell it wrote
                    in_degrees = True  # said as D°M′S″ only where the cell is D°M′S″
                if near is not None and in_turn_of(value, near) != value:
                    forms += (in_turn_of(value, near),)  # written in its target's turn
                if column is not None and column < 0:  # no column for it in this sheet
                    continue
                if column is None:
                    # which cell held it is not known: edited or cleared, never "→ —"
                    if not any(_as_captured(number(i, c), forms, step)
                               for i, c in enumerate(cells)):
                        edited[(row, key)] = EditedReading(row, key, _shown(None, forms), "",
                                                           "missing")
                    continue
                now = cells[column] if column < len(cells) else ""
                held = number(column, now)
                if _as_captured(held, forms, step):
                    edited.pop((row, key), None)  # taken again later: as captured
                else:
                    # a cell emptied is said as its column writes it (D°M′S″ or decimal)
                    # (its rows about this one, as a take reads the column's form)
                    near_rows = range(max(0, row - 50), min(len(rows), row + 50))
                    written = [cells_r[column] for cells_r in (rows[r] for r in near_rows)
                               if column < len(cells_r)] \
                        if in_degrees and not now.strip() else []
                    captured = _shown(held, forms, now, step if in_degrees else 0.0,
                                      written)
                    edited[(row, key)] = EditedReading(row, key, captured,
                                                       now.strip(),
                                                       "edited" if now.strip() else "cleared")
    return sorted(edited.values(), key=lambda e: (e.row, e.column)) + sorted(
        unchecked, key=lambda e: (e.what != "elsewhere", e.row, e.column, e.captured))
