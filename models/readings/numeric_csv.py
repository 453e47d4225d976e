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
_BLANK_LINE = re.compile(rb"(?:\A|\n)[ \t]*\n")
_TRAILING_SPACE = b" \t\r\n\x0b\x0c"


def _line_offset(data: bytes, line: int) -> int:
    """Where 1-based ``line`` starts in ``data`` (its end when it has fewer lines)."""
    offset = 0
    for _ in range(line - 1):
        offset = data.find(b"\n", offset) + 1
        if offset == 0:
            return len(data)
    return offset


# ~400 lines a step, so that a reading window keeps its interpreter: BENCHMARKS.md, Notes
CHUNK_BYTES = 8 * 1024


class _NotPlain(Exception):
    """The body is not plain numbers: the tolerant reader reads the file."""


def _parse(data: bytes, start: int, end: int, delimiter: str, used: list[int]) -> np.ndarray:
    """Parse the numbers in ``data[start:end]``, a chunk of lines at a time. Raise
    _NotPlain as soon as a chunk holds anything but plain numbers."""
    blocks = []
    while start < end:
        stop = data.find(b"\n", min(start + CHUNK_BYTES, end), end)
        stop = end if stop < 0 else stop + 1
        chunk = data[start:stop].replace(b"\r\n", b"\n")
        if (not chunk.isascii() or b"_" in chunk or b'"' in chunk or b"#" in chunk
                or b"\r" in chunk or _BLANK_LINE.search(chunk)
                or (delimiter == ";" and b"," in chunk)):
            raise _NotPlain
        blocks.append(np.loadtxt(io.StringIO(chunk.decode("ascii")), delimiter=delimiter,
                                 comments=None, ndmin=2, usecols=used, dtype=float))
        start = stop
    if not blocks:
        raise _NotPlain
    return blocks[0] if len(blocks) == 1 else np.concatenate(blocks)


def read_numeric(path: str | Path, columns: Sequence[Column],
                 mapping: dict[str, str] | None = None) -> ParsedReadings | None:
    """Read a CSV file whose body is plain numbers. Return None for any other file, so that
    the tolerant reader reads it. This function never raises an error of its own: the
    tolerant reader is the one that says what is wrong and where."""
    path = Path(path)
    if path.suffix.lower() in (".xlsx", ".xlsm"):
        return None
    source = str(path)
    try:
        data = path.read_bytes()
    except OSError:
        return None
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):  # UTF-16: not a plain body
        return None
    # the header and any title above it may be Chinese (UTF-8 or GBK): decoded as the
    # tolerant reader decodes; the body below must be ASCII (checked a chunk at a time)
    head_end = _line_offset(data, HEAD_LINES)
    try:
        head = _decode(data[:head_end], source)
    except (TableImportError, UnicodeDecodeError):
        return None
    if "\r" in head:  # lines end in CR LF (a lone CR is left to the tolerant reader)
        head = head.replace("\r\n", "\n")
    delimiter = _sniff_delimiter(head)
    if delimiter not in (",", "\t", ";") or '"' in head or "#" in head or "\r" in head:
        return None
    try:
        table = table_from_grid(_read_csv(head, delimiter, source), source)
        if table.header is None or not table.rows:
            return None
        positions = column_positions(table, columns, mapping)
    except TableImportError:
        return None
    if not table.line_numbers:  # the header found was the last line: no readings under it
        return None
    start, end = _line_offset(data, table.line_numbers[0]), len(data)
    while end > start and data[end - 1] in _TRAILING_SPACE:
        end -= 1
    first = data.find(b"\n", start, end)
    width = data[start:end if first < 0 else first].count(delimiter.encode()) + 1
    used = sorted({p for p in positions if p is not None})
    if width > MAX_COLUMNS or any(p >= width for p in used):
        return None
    try:
        block = _parse(data, start, end, delimiter, used)
    except (ValueError, _NotPlain):
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
        numbers = np.ascontiguousarray(block[:, used.index(position)])
        if column.kind is ColumnKind.INTEGER and not (
                np.all(numbers == np.round(numbers)) and np.all(np.abs(numbers) <= MAX_INTEGER)):
            return None
        values[column.key] = numbers
    return ParsedReadings(values, np.arange(block.shape[0]), [], table.line_numbers[0])
