"""Read tables of readings from CSV (any usual encoding and delimiter) and XLSX files.

CSV: UTF-8 with or without BOM, GBK (Chinese Windows), comma, semicolon or tab
delimited; with semicolons, a decimal comma (``12,5``) is turned into a point.
XLSX: the first worksheet, read with openpyxl. Every cell comes back as text
so the readings sheet keeps exactly what the file holds.
"""

from __future__ import annotations

import csv
import io
import itertools
import re
from collections import Counter
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from models.messages import QT_TR_NOOP, message, reason_of
from models.readings.angles import AngleParseError, parse_angle_deg
from models.readings.headers import match_header, normalise_header
from models.readings.sheet import Column

__all__ = ["TableImportError", "RawTable", "map_columns", "read_table", "split_pasted_text"]


class TableImportError(ValueError):
    """A file could not be read as a table; the message names the file and what is wrong."""


class MissingColumnError(TableImportError):
    """The file's header does not name a required column; ``table`` is the file as read, for
    a mapping chosen by the user (``map_columns(table, columns, mapping)``)."""

    def __init__(self, message: str, table: RawTable) -> None:
        super().__init__(message)
        self.table = table


def header_signature(header: Sequence[str]) -> str:
    """A file layout's identity: its header cells, as a mapping is remembered for it."""
    return "\x1f".join(h.strip().lower() for h in header)


#: Limits of a readings file: no readings file comes near them, a hostile one does.
MAX_ROWS = 5_000_000
MAX_COLUMNS = 64
MAX_CELL_CHARS = 1_000
#: A run of empty sheet rows longer than this ends the reading with an error.
MAX_EMPTY_XLSX_ROWS = 10_000
#: An XLSX workbook whose parts expand beyond this (a "zip bomb") is refused unread.
MAX_XLSX_EXPANDED_BYTES = 768 * 1024 * 1024


@dataclass
class RawTable:
    """Text cells of a file. ``line_numbers[i]`` is the 1-based file row of ``rows[i]``."""

    source: str
    header: list[str] | None
    rows: list[list[str]]
    line_numbers: list[int]


_DECIMAL_COMMA = re.compile(r"^[+\-\u2212]?\d+,\d+$")


def _decode(data: bytes, source: str) -> str:
    if data.startswith(b"\xef\xbb\xbf"):
        return data[3:].decode("utf-8")
    if data.startswith((b"\xff\xfe", b"\xfe\xff")):
        return data.decode("utf-16")
    first = None
    for encoding in ("utf-8", "gb18030"):
        try:
            return data.decode(encoding)
        except UnicodeDecodeError as exc:
            first = first or exc
            continue
    where = first.start if first is not None else 0
    raise TableImportError(message(
        QT_TR_NOOP("{source}: row {row}: not UTF-8 or GBK text (byte {byte} hex at position {column}); "
                   "save it as CSV UTF-8 and try again"),
        source=source, row=data.count(b"\n", 0, where) + 1, byte=f"{data[where]:02X}",
        column=where - data.rfind(b"\n", 0, where)))


def _sniff_delimiter(text: str) -> str:
    lines = [ln for ln in text[:65536].splitlines() if ln.strip()][:20]  # not all 1M lines
    best, best_score = ",", -1
    for delim in ("\t", ";", ","):
        counts = [c for c in (ln.count(delim) for ln in lines) if c]
        if not counts:
            continue
        # the delimiter appears the same number of times on most lines (a title line above
        # the table may have none: it does not count against the table's delimiter)
        # (the first counted of the most frequent, as Counter.most_common(1) gives, without
        # the heapq it imports: a plain analyze starts without it)
        tally = Counter(counts)
        usual = max(tally, key=tally.__getitem__)
        score = sum(1 for c in counts if c == usual) * 10 + usual
        if score > best_score:
            best, best_score = delim, score
    return best


def split_pasted_text(text: str) -> list[list[str]]:
    """Cells of a block pasted from a spreadsheet (tab-separated) or typed as CSV."""
    text = text.replace("\r\n", "\n").replace("\r", "\n").rstrip("\n")
    if not text:
        return []
    delim = "\t" if "\t" in text else _sniff_delimiter(text)
    if delim not in text or (delim == "," and _dms_with_decimal_comma(text.split("\n"))):
        return [[line] for line in text.split("\n")]
    rows = [list(r) for r in csv.reader(io.StringIO(text), delimiter=delim)]
    if delim == ";":
        rows = [[_fix_decimal_comma(c) for c in r] for r in rows]
    return rows


_DMS_MARK = re.compile("[°'\"′″度分秒]")


def _dms_with_decimal_comma(lines: list[str]) -> bool:
    """Tell whether pasted lines are one column of D°M'S" angles with decimal commas, such
    as 138°24'05,15". The commas of such lines are decimal commas, not cell separators."""
    filled = [ln.strip() for ln in lines if ln.strip()]
    if not filled or not all(_DMS_MARK.search(ln) for ln in filled):
        return False
    try:
        for ln in filled:
            parse_angle_deg(ln)
    except AngleParseError:
        return False
    return True


def _fix_decimal_comma(cell: str) -> str:
    stripped = cell.strip()
    return stripped.replace(",", ".") if _DECIMAL_COMMA.match(stripped) else cell


def _looks_like_header(cells: Sequence[str]) -> bool:
    for cell in cells:
        if not cell.strip():
            continue
        try:
            parse_angle_deg(cell)
        except AngleParseError:
            return True
    return False


def read_table(path: str | Path) -> RawTable:
    """Read a CSV or XLSX file into text cells, detecting a header row."""
    path = Path(path)
    source = str(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise TableImportError(message(
            QT_TR_NOOP("{source}: cannot read ({value})"),
            source=source, value=exc.strerror or exc)) from None
    if path.suffix.lower() in (".xlsx", ".xlsm"):
        grid = _read_xlsx(data, source)
    else:
        text = _decode(data, source)
        # universal newlines: CR-only files (old Mac, some instruments) read like the others
        text = text.replace("\r\n", "\n").replace("\r", "\n")
        delim = _sniff_delimiter(text)
        grid = _read_csv(text, delim, source)
        if delim == ";":
            grid = [[_fix_decimal_comma(c) for c in r] for r in grid]
    return table_from_grid(grid, source)


def table_from_grid(grid: list[list[str]], source: str) -> RawTable:
    """The cells of a file with its header row found (if it has one) and each row's line."""
    filled = [i for i, row in enumerate(grid) if any(c.strip() for c in row)]
    if not filled:
        raise TableImportError(message(
            QT_TR_NOOP("{source}: the file holds no rows"),
            source=source))
    # blank rows inside the data stay (a gap keeps its place: a sample's phase can depend
    # on its row); the sheet leaves them out of every analysis that does not need them
    numbered = [(i + 1, grid[i]) for i in range(filled[0], filled[-1] + 1)]
    header = None
    if _looks_like_header(numbered[0][1]):
        header = [c.strip() for c in numbered[0][1]]
        numbered = numbered[1:]
        while numbered and not any(c.strip() for c in numbered[0][1]):
            numbered = numbered[1:]
    return RawTable(source, header, [r for _, r in numbered], [n for n, _ in numbered])


def _check_row(row: list[str], line: int, source: str) -> None:
    if len(row) > MAX_COLUMNS and any(c.strip() for c in row[MAX_COLUMNS:]):
        raise TableImportError(message(
            QT_TR_NOOP("{source}: row {line}: {len} columns; a readings file has at most {max_columns}"),
            source=source, line=line, len=len(row), max_columns=MAX_COLUMNS))
    for col, cell in enumerate(row, 1):
        if len(cell) > MAX_CELL_CHARS:
            raise TableImportError(message(
                QT_TR_NOOP("{source}: row {line}, column {col}: a cell of {len} characters is not a "
                           "reading (at most {max_cell_chars})"),
                source=source, line=line, col=col, len=len(cell), max_cell_chars=MAX_CELL_CHARS))


def _read_csv(text: str, delim: str, source: str) -> list[list[str]]:
    reader = csv.reader(io.StringIO(text), delimiter=delim, strict=True)
    grid: list[list[str]] = []
    try:
        for row in reader:
            _check_row(row, reader.line_num, source)
            grid.append(row[:MAX_COLUMNS])
            if len(grid) > MAX_ROWS:
                raise TableImportError(message(
                    QT_TR_NOOP("{source}: more than {max_rows} rows"),
                    source=source, max_rows=MAX_ROWS))
    except csv.Error as exc:
        what = ("a quote is not closed" if any(w in str(exc) for w in ("field larger", "EOF",
                                                                        "end of data"))
                else str(exc))
        raise TableImportError(message(
            QT_TR_NOOP("{source}: row {line_num}: cannot read the CSV ({what})"),
            source=source, line_num=reader.line_num, what=what)) \
            from None
    return grid


def _xlsx_expanded_size(data: bytes, source: str) -> int:
    import zipfile

    try:
        with zipfile.ZipFile(io.BytesIO(data)) as archive:
            return sum(info.file_size for info in archive.infolist())
    except (zipfile.BadZipFile, OSError, ValueError) as exc:
        raise TableImportError(message(
            QT_TR_NOOP("{source}: not a readable XLSX workbook ({exc})"),
            source=source, exc=reason_of(exc))) from None


def _xlsx_text(value) -> str:
    """A cell's value as the text a CSV saved from the sheet would hold. An angle typed as
    138:24:05 is stored as a time of day (below 24 h) or a duration ([h]:mm:ss): written
    back as D:M:S with its seconds, so both paths read the same angle."""
    import datetime

    if value is None:
        return ""
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, datetime.time):
        seconds = value.second + value.microsecond / 1e6
        return f"{value.hour}:{value.minute:02d}:{seconds:09.6f}"
    if isinstance(value, datetime.timedelta):
        sign = "-" if value < datetime.timedelta(0) else ""
        micro = abs(value) // datetime.timedelta(microseconds=1)
        whole, micro = divmod(micro, 1_000_000)
        hours, rest = divmod(whole, 3600)
        minutes, seconds = divmod(rest, 60)
        return f"{sign}{hours}:{minutes:02d}:{seconds + micro / 1e6:09.6f}"
    return str(value)


def _read_xlsx(data: bytes, source: str) -> list[list[str]]:
    try:
        import openpyxl
    except ImportError:  # pragma: no cover - openpyxl is a dependency
        raise TableImportError(message(
            QT_TR_NOOP("{source}: reading XLSX needs openpyxl"),
            source=source)) from None
    expanded = _xlsx_expanded_size(data, source)
    if expanded > MAX_XLSX_EXPANDED_BYTES:
        raise TableImportError(message(
            QT_TR_NOOP("{source}: the workbook expands to {value} MB, more than the {value2} MB a "
                       "readings file needs: save the sheet as CSV"),
            source=source, value=f"{expanded / 2**20:.0f}",
            value2=f"{MAX_XLSX_EXPANDED_BYTES / 2**20:.0f}"))
    try:
        book = openpyxl.load_workbook(io.BytesIO(data), read_only=True, data_only=True)
        # the formulas: a formula cell with no stored value (a sheet written by a program,
        # never recalculated) reads as its formula, as a CSV of it does, not as a blank cell
        formulas = openpyxl.load_workbook(io.BytesIO(data), read_only=True, data_only=False)
    except Exception as exc:  # noqa: BLE001 - openpyxl raises many types for damaged files
        raise TableImportError(message(
            QT_TR_NOOP("{source}: not a readable XLSX workbook ({exc})"),
            source=source, exc=reason_of(exc))) from None
    try:
        sheet, formula_sheet = book.worksheets[0], formulas.worksheets[0]
        # the stored dimension can claim a million rows by 16384 columns: read what is there
        sheet.reset_dimensions()
        formula_sheet.reset_dimensions()
        grid: list[list[str]] = []
        empty_run = 0
        rows = itertools.zip_longest(
            sheet.iter_rows(max_col=MAX_COLUMNS + 1, values_only=True),
            formula_sheet.iter_rows(max_col=MAX_COLUMNS + 1, values_only=True), fillvalue=())
        for line, (stored, written) in enumerate(rows, 1):
            row = [w if v is None and isinstance(w, str) and w.startswith("=") else v
                   for v, w in itertools.zip_longest(stored, written)]
            if all(v is None for v in row):
                empty_run += 1
                if empty_run > MAX_EMPTY_XLSX_ROWS:
                    raise TableImportError(
                        message(
                        QT_TR_NOOP("{source}: more than {max_empty_xlsx_rows} empty rows after row "
                                   "{value}: keep the readings in one block (a stray far cell?)"),
                        source=source, max_empty_xlsx_rows=MAX_EMPTY_XLSX_ROWS, value=line - empty_run))
                grid.append([])
                continue
            empty_run = 0
            cells = [_xlsx_text(v) for v in row]
            _check_row(cells, line, source)
            grid.append(cells[:MAX_COLUMNS])
            if line > MAX_ROWS:
                raise TableImportError(message(
                    QT_TR_NOOP("{source}: more than {max_rows} rows"),
                    source=source, max_rows=MAX_ROWS))
        return grid
    except TableImportError:
        raise
    except Exception as exc:  # noqa: BLE001 - a damaged sheet fails in many ways while read
        raise TableImportError(message(
            QT_TR_NOOP("{source}: the workbook's sheet cannot be read ({exc})"),
            source=source, exc=reason_of(exc))) from None
    finally:
        book.close()
        formulas.close()


def _apply_mapping(table: RawTable, columns: Sequence[Column], positions: list[int | None],
                   mapping: dict[str, str]) -> list[int | None]:
    names = [h.strip().lower() for h in table.header or []]
    out = list(positions)
    mapped: dict[str, str] = {}  # a header named in the mapping -> the key it was given to
    for wanted, header in mapping.items():
        index = next((k for k, c in enumerate(columns)
                      if wanted.strip().lower() in (c.key.lower(), c.title.lower())), None)
        if index is None:
            raise TableImportError(message(
                QT_TR_NOOP("{source}: column mapping names '{wanted}', which is not a column here "
                           "({join})"),
                source=table.source, wanted=wanted, join=', '.join(c.key for c in columns)))
        if not header.strip():
            out[index] = None
            continue
        other = mapped.setdefault(header.strip().lower(), columns[index].key)
        if other != columns[index].key:
            raise TableImportError(message(
                QT_TR_NOOP("{source}: column mapping gives the header '{header}' to both "
                           "{first} and {second}: one column holds one quantity; map each "
                           "to its own header"),
                source=table.source, header=header.strip(), first=other,
                second=columns[index].key))
        found = next((i for i, n in enumerate(names) if n == header.strip().lower()), None)
        if found is None:
            raise TableImportError(message(
                QT_TR_NOOP("{source}: column mapping {wanted}={header}: the file has no header "
                           "'{header}' (its headers: {join})"),
                source=table.source, wanted=wanted, header=header,
                join=', '.join(table.header or [])[:200]))
        out[index] = found
    return out


#: How far below the top a header is looked for (title, lab and date rows above it).
HEADER_SEARCH_ROWS = 12


def _complete(positions: list[int | None], columns: Sequence[Column]) -> bool:
    return all(p is not None for p, c in zip(positions, columns, strict=True) if c.required)


def map_columns(table: RawTable, columns: Sequence[Column],
                mapping: dict[str, str] | None = None) -> list[list[str]]:
    """Reorder a table's cells into ``columns`` order, by header name or by position.

    Header names are matched as labs write them (models/readings/headers.py: keys,
    titles, units in the header, Chinese names). When the first row does not name every
    required column, the header is looked for in the rows below it (a title block above
    the table); when found, ``table`` is updated in place (its header, rows and line
    numbers), so that messages keep naming the file's rows. A missing required column is
    an error naming the file, the header row and the column.
    """
    if table.header is None:
        width = len(columns)
        return [(list(r) + [""] * width)[:width] for r in table.rows]
    positions = column_positions(table, columns, mapping)
    out = []
    for row in table.rows:
        out.append([row[p].strip() if p is not None and p < len(row) else "" for p in positions])
    return out


def _refuse_ambiguous(table: RawTable, columns: Sequence[Column],
                      positions: list[int | None]) -> None:
    """Refuse a header that leaves open which cells a column's are (contract review 75 F6:
    the first of two 'ac_x_arcsec' columns was analysed, the other ignored, no word): two
    header cells that name the column alike (the same text, as normalised), or one file
    column given to two keys (a mapping). Names the header and both column positions."""
    header = table.header or []
    names = [normalise_header(h) for h in header]
    for column, found in zip(columns, positions, strict=True):
        if found is None or found >= len(header) or not names[found]:
            continue
        twin = next((i for i, n in enumerate(names) if i != found and n == names[found]), None)
        if twin is not None:
            first, second = sorted((found, twin))
            raise TableImportError(message(
                QT_TR_NOOP("{source}: the header names columns {first} and {second} alike "
                           "('{header}', {key}): which holds the readings is not clear; rename "
                           "or delete one"),
                source=table.source, first=first + 1, second=second + 1,
                header=header[found].strip(), key=column.key))
    for k, found in enumerate(positions):
        other = next((j for j in range(k) if positions[j] == found), None)
        if found is not None and other is not None:
            raise TableImportError(message(
                QT_TR_NOOP("{source}: column {position} ('{header}') is taken for both "
                           "{first} and {second}: one column holds one quantity; map each "
                           "to its own header"),
                source=table.source, position=int(found) + 1,
                header=header[found].strip() if found < len(header) else "",
                first=columns[other].key, second=columns[k].key))


def column_positions(table: RawTable, columns: Sequence[Column],
                     mapping: dict[str, str] | None = None) -> list[int | None]:
    """Where each of ``columns`` is in ``table`` (which has a header), found as
    :func:`map_columns` finds it; raises MissingColumnError naming a missing column (a
    table without a header is searched for one in its first rows like any other)."""
    positions = match_header(table.header or [], columns)
    if mapping:  # the user's choice: column key (or title) -> the file's header text
        positions = _apply_mapping(table, columns, positions, mapping)
    if not _complete(positions, columns):
        for k, row in enumerate(table.rows[:HEADER_SEARCH_ROWS]):
            below = match_header(row, columns)
            if _complete(below, columns):
                table.header, positions = [c.strip() for c in row], below
                table.rows, table.line_numbers = table.rows[k + 1:], table.line_numbers[k + 1:]
                break
    _refuse_ambiguous(table, columns, positions)
    for column, found in zip(columns, positions, strict=True):
        if found is None and column.required:
            raise MissingColumnError(
                message(
                QT_TR_NOOP("{source}: row 1 (header): no column '{key}'; expected headers {join} (or "
                           "their names, e.g. {title}{value}); the file's header is {join2}"),
                source=table.source, key=column.key, join=','.join(c.key for c in columns),
                title=f"{column.title!r}", value=', ' + repr(column.aliases[0]) if column.aliases else '',
                join2=','.join(table.header or [])[:200]), table)
    return positions
