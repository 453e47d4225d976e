"""A readings file of plain numbers, read by numpy in one pass.

A signal record of a million samples is a million lines of numbers under one header. The
tolerant reader (``tabular_import`` then ``ReadingsSheet``) keeps every cell as text, so
that a unit, an angle in D°M'S", a blank or a typo is read or reported where it is; for a
million lines that costs seconds and half a gigabyte. Here the header is found by the
same code on the first lines, and the body is handed to ``numpy.loadtxt`` (numpy's C
parser: no new dependency; pandas' or pyarrow's readers parse a little faster but take
longer to import than this parse of a million lines takes).

Whenever the body is anything but plain, finite numbers in the columns' kinds — a
blank line (a gap keeps its place in a signal), a text cell, a quote, a comment sign,
``nan``, a decimal comma, a unit — this gives up (``None``) and the tolerant reader
reads the file, with its messages naming the row and cell. So both readers give the same
readings whenever this one answers.
"""

from __future__ import annotations

import io
import re
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from models.readings.sheet import MAX_INTEGER, Column, ColumnKind, ParsedReadings
from models.readings.tabular_import import (
    MAX_COLUMNS,
    MAX_ROWS,
    TableImportError,
    _decode,
    _read_csv,
    _sniff_delimiter,
    column_positions,
    table_from_grid,
)

__all__ = ["read_numeric"]

HEAD_LINES = 40  # the header is looked for in these (a title block above it)
_BLANK_LINE = re.compile(r"\n[ \t]*\n")


def _line_offset(text: str, line: int) -> int:
    """Where 1-based ``line`` starts in ``text`` (its end when it has fewer lines)."""
    offset = 0
    for _ in range(line - 1):
        offset = text.find("\n", offset) + 1
        if offset == 0:
            return len(text)
    return offset


CHUNK_CHARS = 1 << 19  # ~25 000 lines a call: numpy's parser keeps the interpreter meanwhile


def _parse(body: str, delimiter: str, used: list[int]) -> np.ndarray:
    """The body's numbers, parsed a chunk of lines at a time: ``numpy.loadtxt`` holds the
    interpreter while it parses, and a window reading on a worker thread must get it back
    every few milliseconds (a million lines in one call froze it for half a second)."""
    blocks, start = [], 0
    while start < len(body):
        end = body.find("\n", start + CHUNK_CHARS)
        end = len(body) if end < 0 else end + 1
        blocks.append(np.loadtxt(io.StringIO(body[start:end]), delimiter=delimiter,
                                 comments=None, ndmin=2, usecols=used, dtype=float))
        start = end
    if not blocks:
        raise ValueError("no lines of numbers")
    return blocks[0] if len(blocks) == 1 else np.concatenate(blocks)


def read_numeric(path: str | Path, columns: Sequence[Column],
                 mapping: dict[str, str] | None = None) -> ParsedReadings | None:
    """The readings of an all-numeric CSV file, or None to let the tolerant reader read it
    (never an error of its own: the tolerant reader says what is wrong and where)."""
    path = Path(path)
    if path.suffix.lower() in (".xlsx", ".xlsm"):
        return None
    source = str(path)
    try:
        text = _decode(path.read_bytes(), source)
    except (OSError, TableImportError):
        return None
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    delimiter = _sniff_delimiter(text)
    if delimiter not in (",", "\t", ";") or '"' in text or "#" in text:
        return None
    head = text[:_line_offset(text, HEAD_LINES)]
    try:
        table = table_from_grid(_read_csv(head, delimiter, source), source)
        if table.header is None or not table.rows:
            return None
        positions = column_positions(table, columns, mapping)
    except TableImportError:
        return None
    if not table.line_numbers:  # the header found was the last line: no readings under it
        return None
    body = text[_line_offset(text, table.line_numbers[0]):].rstrip()
    del text
    if (not body.isascii() or "_" in body or _BLANK_LINE.search(body)
            or (delimiter == ";" and "," in body)):
        return None
    width = body[:body.find("\n") if "\n" in body else len(body)].count(delimiter) + 1
    used = sorted({p for p in positions if p is not None})
    if width > MAX_COLUMNS or any(p >= width for p in used):
        return None
    try:
        block = _parse(body, delimiter, used)
    except ValueError:
        return None
    if block.shape[0] > MAX_ROWS or not np.all(np.isfinite(block)):
        return None
    values: dict[str, np.ndarray] = {}
    for column, position in zip(columns, positions, strict=True):
        if position is None:
            values[column.key] = (np.full(block.shape[0], None, dtype=object)
                                  if column.kind is ColumnKind.TEXT
                                  else np.full(block.shape[0], np.nan))
            continue
        if column.kind is ColumnKind.TEXT:
            return None
        data = np.ascontiguousarray(block[:, used.index(position)])
        if column.kind is ColumnKind.INTEGER and not (
                np.all(data == np.round(data)) and np.all(np.abs(data) <= MAX_INTEGER)):
            return None
        values[column.key] = data
    return ParsedReadings(values, np.arange(block.shape[0]), [])
