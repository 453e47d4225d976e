"""A sheet of readings: typed columns over the raw text the technician typed.

The sheet keeps every cell as the text that was entered, so nothing is lost
when a cell is wrong; parsing happens on demand and reports each bad cell by
row and column. Rows that are entirely blank are ignored.
"""

from __future__ import annotations

import enum
import functools
import math
import re
import unicodedata
from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from models.messages import QT_TR_NOOP, message, reason_of
from models.readings.angles import AngleParseError, parse_angle_deg

__all__ = ["CellError", "Column", "ColumnKind", "ParsedReadings", "ReadingsSheet", "one_line"]


def _escaped(ch: str) -> str:
    code = ord(ch)
    if ch == "\t":
        return "\\t"
    return f"\\x{code:02x}" if code < 0x100 else (f"\\u{code:04x}" if code < 0x10000
                                                  else f"\\U{code:08x}")


def one_line(text: str, limit: int = 400) -> str:
    """A message fit for one line: line breaks shown as ⏎, every other character a terminal
    would not print as itself (control characters, the line and paragraph separators that
    split a line, bidirectional overrides, lone surrogates of undecodable bytes) escaped as
    ``\\xNN`` / ``\\uNNNN``; cut at ``limit`` characters."""
    flat = str(text).replace("\r\n", "⏎").replace("\n", "⏎").replace("\r", "⏎")
    if not flat.isprintable():
        flat = "".join(ch if ch.isprintable() or unicodedata.category(ch) == "Zs" else _escaped(ch)
                       for ch in flat)
    return flat if len(flat) <= limit else flat[: limit - 1] + "…"


class ColumnKind(enum.Enum):
    ANGLE_DEG = "angle"  # decimal degrees or D°M'S"
    NUMBER = "number"  # a float in the column's unit
    INTEGER = "integer"
    TEXT = "text"


@dataclass(frozen=True)
class CellError:
    """A cell that could not be read. ``row`` and ``column`` are 0-based indices."""

    row: int
    column: int
    column_key: str
    text: str
    reason: str

    def describe(self, source: str = "", row_offset: int = 1) -> str:
        """One line: ``file: row N, column 'key': reason`` (rows counted from ``row_offset``)."""
        where = message(QT_TR_NOOP("{source}: row {row}, column '{column}': {reason}")
                        if source else
                        QT_TR_NOOP("row {row}, column '{column}': {reason}"),
                        source=source, row=self.row + row_offset, column=self.column_key,
                        reason=self.reason)
        return where if where.isprintable() and len(where) <= 400 else one_line(where)


@dataclass(frozen=True)
class Column:
    """One typed column of a readings sheet.

    ``key`` is the CSV header; ``unit`` is shown in the table header.
    ``choices`` restricts a TEXT column to the listed values (case-insensitive).
    """

    key: str
    title: str
    unit: str
    kind: ColumnKind
    required: bool = True
    help: str = ""
    choices: tuple[str, ...] = ()
    aliases: tuple[str, ...] = ()  # other headers labs use for it (see readings/headers.py)

    @property
    def header(self) -> str:
        return f"{self.title} [{self.unit}]" if self.unit else self.title

    def parse(self, text: str) -> float | int | str | None:
        """Value of one cell; ``None`` for a blank optional cell.

        Raises ``ValueError`` with a readable reason.
        """
        stripped = text.strip()
        if not stripped:
            if self.required:
                raise ValueError(message(QT_TR_NOOP("empty; a value is needed here")))
            return None
        if self.kind is ColumnKind.ANGLE_DEG:
            try:
                return _angle_deg(stripped)
            except AngleParseError as exc:
                raise ValueError(reason_of(exc)) from None
        if self.kind is ColumnKind.NUMBER:
            return _parse_number(stripped)
        if self.kind is ColumnKind.INTEGER:
            value = _parse_number(stripped)
            if not float(value).is_integer():
                raise ValueError(message(QT_TR_NOOP("'{text}' is not a whole number"),
                                         text=stripped))
            if abs(value) > MAX_INTEGER:
                raise ValueError(message(QT_TR_NOOP("'{text}' is out of range for a whole number "
                                                    "here"), text=stripped))
            return int(value)
        if self.choices:
            lowered = {c.lower(): c for c in self.choices}
            if stripped.lower() not in lowered:
                raise ValueError(message(QT_TR_NOOP("'{text}' is not one of {choices}"),
                                         text=stripped, choices=", ".join(self.choices)))
            return lowered[stripped.lower()]
        return stripped


#: an angle cell's value by its text, remembered (a float: the same for every reader): the
#: register reads every record's readings at migration 9 and at each look-up (10,000
#: records of 41 rows, 1.2 million angle cells, most of them a target's, a nominal step's
#: or a display's usual reading seen before; ident80b); an unreadable text is not kept
_angle_deg = functools.lru_cache(maxsize=1 << 16)(parse_angle_deg)

#: The largest whole number an INTEGER column takes (positions, set numbers …).
MAX_INTEGER = 1_000_000_000

_PLAIN_NUMBER = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?", re.ASCII)


def _parse_number(text: str) -> float:
    """A plain decimal number: digits, one point (or one decimal comma), an exponent.

    Python's ``float`` also takes "1_0", "nan" and other scripts' digits; a
    reading is none of these, so they are refused here as in the fast path.
    """
    candidate = text.replace("\u2212", "-").replace(" ", "")
    if candidate.count(",") == 1 and "." not in candidate:
        candidate = candidate.replace(",", ".")
    if not _PLAIN_NUMBER.fullmatch(candidate):
        raise ValueError(message(QT_TR_NOOP("'{text}' is not a number"), text=one_line(text, 40)))
    value = float(candidate)
    if not math.isfinite(value):
        raise ValueError(message(QT_TR_NOOP("'{text}' is not a finite number"), text=text))
    return value


@dataclass
class ParsedReadings:
    """The readable rows of a sheet.

    ``values[key]`` is a float array over the *used* rows (NaN for a blank
    optional cell, text columns as object arrays); ``row_index`` maps each used
    row back to its sheet row; ``errors`` lists every unreadable cell.
    """

    values: dict[str, np.ndarray]
    row_index: np.ndarray
    errors: list[CellError] = field(default_factory=list)
    # the file's line of the sheet's first row, when read from a file by
    # models.readings.numeric_csv (1: the sheet's own numbering)
    first_line: int = 1

    @property
    def n(self) -> int:
        return int(self.row_index.size)

    def __getitem__(self, key: str) -> np.ndarray:
        return self.values[key]


_FLOAT_CHUNK = 4_096


def _floats(texts: list[str]) -> np.ndarray:
    """``np.array(texts, dtype=float)`` in chunks: one call on a million strings holds the
    GIL for ~0.3 s, which freezes the window while a worker thread parses."""
    if len(texts) <= _FLOAT_CHUNK:
        return np.array(texts, dtype=float)
    out = np.empty(len(texts))
    for start in range(0, len(texts), _FLOAT_CHUNK):
        out[start:start + _FLOAT_CHUNK] = np.array(texts[start:start + _FLOAT_CHUNK], dtype=float)
    return out


class NumericRows:
    """The rows of a sheet read from a file of plain numbers, held as one float array per
    column: a row becomes text only when it is edited, a cell only when it is shown. A
    million readings are then 16 MB of numbers instead of half a gigabyte of strings, and
    the analysis reads the arrays as they are.

    A cell reads as the shortest text that gives its number back (``3.70`` in the file
    shows as ``3.7``); an edited row is kept as typed. Inserting or removing rows turns
    the whole sheet into text rows first (rare on a recorded signal, and then undoable
    as every edit is).
    """

    def __init__(self, columns: Sequence[Column], values: Mapping[str, np.ndarray],
                 count: int) -> None:
        self.columns = tuple(columns)
        self.values = [None if values[c.key].dtype == object or not np.any(
            np.isfinite(values[c.key])) else np.asarray(values[c.key], dtype=float)
            for c in self.columns]  # None: the column is blank throughout
        self.count = count
        self.edited: dict[int, list[str]] = {}
        # JSON text of blocks of rows no edit touched: the numbers never change, so a
        # block is encoded once for every later save (shared with the snapshots)
        self._json_blocks: dict[tuple[int, int], str] = {}

    def __len__(self) -> int:
        return self.count

    def _texts(self, c: int, start: int, stop: int) -> list[str]:
        """Return the text that cells ``start:stop`` of column ``c`` show. A blank column
        shows empty cells, a whole number its digits, and any other number the shortest text
        that reads back as the same number. One C loop does a whole column, so a million
        cells take a fraction of a second."""
        data = self.values[c]
        if data is None:
            return [""] * (stop - start)
        if self.columns[c].kind is ColumnKind.INTEGER:
            return list(map(str, map(int, data[start:stop].tolist())))
        return list(map(repr, data[start:stop].tolist()))

    def _text(self, r: int, c: int) -> str:
        return self._texts(c, r, r + 1)[0]

    def cell(self, r: int, c: int) -> str:
        row = self.edited.get(r)
        return row[c] if row is not None else self._text(r, c)

    def row(self, r: int) -> list[str]:
        """Row ``r`` as text the sheet may change in place (it is kept as edited)."""
        if r not in self.edited:
            self.edited[r] = [self._text(r, c) for c in range(len(self.columns))]
        return self.edited[r]

    def __getitem__(self, index):
        """Row ``index`` (or a slice of rows) as new text lists; edits go through ``row``."""
        if isinstance(index, slice):
            return [self[r] for r in range(*index.indices(self.count))]
        r = index + self.count if index < 0 else index
        if not 0 <= r < self.count:
            raise IndexError(index)
        row = self.edited.get(r)
        return list(row) if row is not None else [self._text(r, c)
                                                  for c in range(len(self.columns))]

    def snapshot(self) -> NumericRows:
        """A copy that later edits do not reach (the numbers are shared: they never change)."""
        copy = NumericRows.__new__(NumericRows)
        copy.columns, copy.values, copy.count = self.columns, self.values, self.count
        copy.edited = {r: list(row) for r, row in self.edited.items()}
        copy._json_blocks = self._json_blocks
        return copy

    def json_blocks(self, size: int, dumps: Callable[[Any], str]) -> Iterator[str]:
        """The rows as the elements of a JSON array (``dumps`` of lists of text), ``size``
        rows a block: a block that holds no edited row is encoded once and kept, so an
        autosave after an edit encodes the edited blocks only."""
        touched = {r // size for r in self.edited}
        for start in range(0, self.count, size):
            if start // size in touched:
                yield dumps(self[start:start + size])[1:-1]
                continue
            text = self._json_blocks.get((size, start))
            if text is None:
                text = self._json_blocks[(size, start)] = self._block_json(
                    start, min(start + size, self.count))
            yield text

    def _block_json(self, start: int, stop: int) -> str:
        """Rows ``start:stop`` as the elements of a JSON array of text lists, each cell the
        text it shows, made a column at a time: a million rows in about a third of the time
        of building the text rows and encoding them."""
        columns = [self._texts(c, start, stop) for c in range(len(self.columns))]
        row = "[" + ",".join(['"{}"'] * len(self.columns)) + "]"
        return ",".join(map(row.format, *columns))

    def __iter__(self):
        for r in range(self.count):
            yield self[r]

    def parse(self) -> ParsedReadings:
        """The readings, as the text rows would parse: edited rows read cell by cell."""
        out: dict[str, np.ndarray] = {}
        for column, data in zip(self.columns, self.values, strict=True):
            if data is not None:
                out[column.key] = data.copy()
            else:
                out[column.key] = (np.full(self.count, None, dtype=object)
                                   if column.kind is ColumnKind.TEXT
                                   else np.full(self.count, np.nan))
        keep = np.ones(self.count, dtype=bool)
        errors: list[CellError] = []
        for r in sorted(self.edited):
            row = self.edited[r]
            if all(not t.strip() for t in row):
                keep[r] = False
                continue
            parsed: list[float | int | str | None] = []
            bad = False  # a cell that cannot be read
            for c, column in enumerate(self.columns):
                try:
                    parsed.append(column.parse(row[c]))
                except ValueError as exc:
                    errors.append(CellError(r, c, column.key, row[c], reason_of(exc)))
                    parsed.append(None)
                    bad = True
            if bad:
                keep[r] = False
                continue
            for column, value in zip(self.columns, parsed, strict=True):
                if column.kind is ColumnKind.TEXT:
                    if out[column.key].dtype != object:
                        out[column.key] = out[column.key].astype(object)
                    out[column.key][r] = value
                else:
                    out[column.key][r] = np.nan if value is None else float(value)
        if keep.all():
            return ParsedReadings(out, np.arange(self.count), errors)
        return ParsedReadings({k: v[keep] for k, v in out.items()}, np.nonzero(keep)[0], errors)


class ReadingsSheet:
    """Rows of raw cell text under a fixed list of typed columns (or, for a file of plain
    numbers, :class:`NumericRows`, which reads as the same rows)."""

    def __init__(self, columns: Sequence[Column], rows: Iterable[Sequence[str]] = ()) -> None:
        self.columns: tuple[Column, ...] = tuple(columns)
        self.rows: list[list[str]] | NumericRows = []
        for row in rows:
            self.rows.append(self._fit_row(row))

    def _fit_row(self, row: Sequence[str]) -> list[str]:
        cells = ["" if c is None else str(c) for c in row][: len(self.columns)]
        return cells + [""] * (len(self.columns) - len(cells))

    # -- access ---------------------------------------------------------
    @property
    def row_count(self) -> int:
        return len(self.rows)

    @property
    def column_count(self) -> int:
        return len(self.columns)

    def column_index(self, key: str) -> int:
        for i, column in enumerate(self.columns):
            if column.key == key:
                return i
        raise KeyError(key)

    def text(self, row: int, column: int) -> str:
        rows = self.rows
        return rows.cell(row, column) if isinstance(rows, NumericRows) else rows[row][column]

    def is_blank_row(self, row: int) -> bool:
        rows = self.rows
        if isinstance(rows, NumericRows) and row not in rows.edited:
            return False  # a row of numbers
        return all(not c.strip() for c in rows[row])

    def cell_error(self, row: int, column: int) -> str | None:
        """Why a cell cannot be read, or ``None`` if it is fine (blank rows are fine)."""
        if self.is_blank_row(row):
            return None
        try:
            self.columns[column].parse(self.text(row, column))
        except ValueError as exc:
            return reason_of(exc)
        return None

    # -- edits ----------------------------------------------------------
    def _as_text_rows(self) -> list[list[str]]:
        """The rows as text lists (a numeric block is turned into text: rows move)."""
        if isinstance(self.rows, NumericRows):
            self.rows = list(self.rows)
        return self.rows

    def set_text(self, row: int, column: int, text: str) -> None:
        if isinstance(self.rows, NumericRows) and row < len(self.rows):
            self.rows.row(row)[column] = text
            return
        rows = self._as_text_rows()
        while row >= len(rows):
            rows.append([""] * len(self.columns))
        # the row is replaced, never changed in place: a snapshot (which shares the row
        # lists) keeps the text it was taken with
        cells = list(rows[row])
        cells[column] = text
        rows[row] = cells

    def insert_rows(self, at: int, rows: Sequence[Sequence[str]]) -> None:
        self._as_text_rows()[at:at] = [self._fit_row(r) for r in rows]

    def remove_rows(self, at: int, count: int) -> list[list[str]]:
        rows = self._as_text_rows()
        removed = rows[at : at + count]
        del rows[at : at + count]
        return removed

    def replace_all(self, rows: Iterable[Sequence[str]]) -> None:
        self.rows = [self._fit_row(r) for r in rows]

    def adopt_rows(self, rows: list[list[str]] | NumericRows, checked: bool = False) -> None:
        """Use ``rows`` as the sheet's rows without copying them. Each row must already hold
        one string per column; with ``checked`` the caller guarantees this (rows from
        :func:`map_columns`) and the rows are not scanned. A :class:`NumericRows` with the
        sheet's columns is used as it is."""
        if isinstance(rows, NumericRows):
            if rows.columns != self.columns:
                raise ValueError("rows do not match the columns")
            self.rows = rows
            return
        width = len(self.columns)
        if not checked and rows and not all(type(r) is list and len(r) == width for r in rows):
            raise ValueError("rows do not match the columns")
        self.rows = rows

    def copy_rows(self) -> list[list[str]]:
        return [list(r) for r in self.rows]

    def snapshot(self) -> ReadingsSheet:
        """The sheet as it is now, which later edits do not reach: the rows an analysis
        parses and a certificate records with its figures. Cheap: the list of rows is
        copied, the rows themselves are shared (an edit replaces a row, never changes
        it in place: :meth:`set_text`); a record of numbers shares its columns and copies
        only its edited rows."""
        copy = ReadingsSheet.__new__(ReadingsSheet)
        copy.columns = self.columns
        copy.rows = (self.rows.snapshot() if isinstance(self.rows, NumericRows)
                     else list(self.rows))
        return copy

    # -- parsing --------------------------------------------------------
    def _parse_fast(self) -> ParsedReadings | None:
        """Vectorised parse when every filled column is plain numbers (large signal files,
        long runs); anything else — a unit, DMS, a blank cell, text — takes the cell-by-cell
        path, which gives the same values and says what is wrong where."""
        if not self.rows:
            return None
        out: dict[str, np.ndarray] = {}
        for c, column in enumerate(self.columns):
            texts = [row[c] for row in self.rows]
            if not column.required and not any(t.strip() for t in texts):
                out[column.key] = (np.full(len(texts), None, dtype=object)
                                   if column.kind is ColumnKind.TEXT else np.full(len(texts), np.nan))
                continue
            if column.kind is ColumnKind.TEXT:
                return None
            joined = "\x1f".join(texts)
            if "_" in joined or not joined.isascii():  # numpy reads "1_0" as 10: not a reading
                return None
            try:
                values = _floats(texts)
            except ValueError:
                return None
            if not np.all(np.isfinite(values)):
                return None
            if column.kind is ColumnKind.INTEGER and not (
                    np.all(values == np.round(values)) and np.all(np.abs(values) <= MAX_INTEGER)):
                return None
            out[column.key] = values
        if not any(c.required for c in self.columns):
            return None
        return ParsedReadings(out, np.arange(len(self.rows)), [])

    def parse(self) -> ParsedReadings:
        """Parse every non-blank row; rows with an unreadable cell are left out."""
        if isinstance(self.rows, NumericRows):
            return self.rows.parse()
        fast = self._parse_fast()
        if fast is not None:
            return fast
        errors: list[CellError] = []
        kept_rows: list[int] = []
        kept: list[list[float | int | str | None]] = []
        for r, row in enumerate(self.rows):
            if all(not c.strip() for c in row):
                continue
            values: list[float | int | str | None] = []
            ok = True
            for c, column in enumerate(self.columns):
                try:
                    values.append(column.parse(row[c]))
                except ValueError as exc:
                    errors.append(CellError(r, c, column.key, row[c], reason_of(exc)))
                    ok = False
            if ok:
                kept_rows.append(r)
                kept.append(values)
        out: dict[str, np.ndarray] = {}
        for c, column in enumerate(self.columns):
            cells = [v[c] for v in kept]
            if column.kind is ColumnKind.TEXT:
                out[column.key] = np.array(cells, dtype=object)
            else:
                out[column.key] = np.array(
                    [np.nan if v is None else float(v) for v in cells], dtype=float
                )
        return ParsedReadings(out, np.array(kept_rows, dtype=int), errors)
