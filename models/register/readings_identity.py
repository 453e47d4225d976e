"""When two certificates hold the same readings: the readings as they decide the result,
compared by their values, not by the bytes they were typed or saved in.

No two calibrations repeat every reading to the last digit: one item's readings issued as
another item's certificate (hostile78 F7: 41 readings to 0.1″ issued for LRA-0815, LRA-0900,
… each an original, nothing said) is refused unless the user says why
(:meth:`models.register.store.Register.issue`, ``readings_of_another_item``), and an
original of a withdrawn certificate's readings, of its item, names it even with the date of
calibration moved (hostile78 F3's route left open by a day).

Two identities are made. :func:`readings_key` (schema 8, chain format 7) is a SHA-256 of
the cells to 10 significant digits: the same readings re-typed to other digits or in another
unit escaped it (ident80: an angle typed in decimal degrees to 6–10 places instead of D°M'S",
the deviations in µrad instead of arcseconds, the vertical column as zenith angles). It is
kept as it is, in the chains of the records issued with it. :func:`readings_identity`
(schema 9, chain format 8) is what the register compares readings by since:

- each angle or length cell (a column whose unit, as the workbench's settings make it,
  :meth:`models.workbench.Workbench.column_units`, is an angle or a length of
  :data:`models.quantity.UNITS`) is its physical value, in rad or m, read as the analysis
  reads it: through the unit the settings give the column and the origin they give it
  (:meth:`models.workbench.Workbench.column_origins`: the theodolite's zenith angle V is
  E = V − 90°);
- each cell keeps the resolution it was typed to: the step of its last digit
  (``12°30'00.1"``: 0.1″; ``12.500028``: 1e-6° = 0.0036″; ``-7.0298`` µrad: 1e-4 µrad),
  found by reading the text with that digit moved by one, through the column's own parser;
- every other cell (fringe signals in V, run, set and face numbers, directions) is
  compared as the analysis reads it (:meth:`models.workbench.Workbench.read_cells`, through
  the analysis's own functions: a choice by its meaning — the positioning's "up", "↑" are
  "+"; a run or direction left blank as the analysis derives it — the positioning's k-th
  approach, the order of its targets, the polygon's set 1 and its encoder's steps, the
  theodolite's forward pass; ident80b), else as before: to 10 significant digits, a text as
  it parses;
- the rows are a set: each row of one set has a row of the other with the same other
  cells and every angle or length within the tolerance below, and the other way round
  (their order, and a row given twice, aside; a row left out or added is other readings).

The tolerance: two values a and b of one cell are the same reading when
``|a − b| <= max(δa, δb) / 2`` (δ: the step of each one's last digit), plus float noise
(8 ulp of the values, 1e-6 of the tolerance). That is, each is the other rounded to the
coarser of the two resolutions: a copy re-typed to any digits, finer or coarser, lands
within half its own last digit or the original's, and is found; digits made up beyond the
original's resolution (0.1″ re-typed as ``…00.13"``) do not hide it, since the coarser
step decides. One reading changed by one step of its resolution (0.1″ typed to 0.1″, or to
more digits) is a step away, twice the tolerance: other readings. Re-typed coarser than the
instrument's step (readings to 0.001″ re-typed in decimal degrees to 6 places, 0.0036″) the
copy cannot show a one-step change, and one below its own step is the same readings. A
cell typed with fewer digits than its neighbours (``30.5`` of a file of numbers, whose
trailing zeros are not kept) compares at its own coarser step.

No grid is cut through the values, so no copy can fall on the other side of a boundary
from its original: the register finds the candidates by an anchor (:class:`ReadingsIdentity`:
the smallest value of the first reading column with the largest half step of that column, in
whole units of 2⁻⁴⁰ rad or m — a row given twice changes neither — found within the larger of
the two half steps, :func:`near`), and compares the candidates' cells and values as above
(:func:`same_readings_values`). The layout stored beside it (the other cells' set as typed,
in the chains of format 8) keeps its meaning and is checked by ``register verify``; it no
longer narrows the look-up, since the cells are compared as the analysis reads them
(``shape``, made again from the record's project state): so the records issued before keep
their stored values, and a copy with its directions re-spelt still finds them."""

from __future__ import annotations

import hashlib
import json
import math
import re
import unicodedata
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = ["INDEX_BOUND", "NO_READINGS", "ReadingsIdentity", "near", "readings_identity", "readings_key",
           "same_readings_values"]

#: significant digits a value is compared to: far below any reading's last digit (20° to
#: 10 digits is 4e-5″; a reading of 0.1″ resolution has 7), far above the float noise of
#: one value written two ways ("12.5" and "12°30'00.0\"" parse within 1e-15 of each other)
#: or an angle re-typed in decimal degrees to 12 places
_DIGITS = 10


def _value(value: Any) -> str:
    """One cell's value as compared: a number to :data:`_DIGITS` significant digits (-0 as
    0), a blank optional cell as "", a text as it parses (a choice in its listed case)."""
    if value is None:
        return ""
    if isinstance(value, str):
        return value.strip()
    number = float(value)
    if math.isnan(number):
        return ""
    text = f"{number:.{_DIGITS}g}"
    return "0" if float(text) == 0 else text


def readings_key(project_json: str, workbench: str) -> str:
    """The identity of the readings that ``project_json`` (a certificate's project state, as
    the register records it) holds for ``workbench``: "" when it holds none that parse (no
    project, no rows, a workbench unknown to this version), else a SHA-256 of exactly this:

    - the rows the analysis reads: each row of the workbench's sheet parsed by the
      workbench's columns (:class:`models.readings.sheet.ReadingsSheet`), blank rows and
      rows of an unreadable cell left out, as the analysis leaves them out;
    - each cell by its value, under its column's key: an angle typed 12°30'00.0" is the
      angle typed 12.5, 12.50 is 12.5, "+1" is 1 (numbers to 10 significant digits, a blank
      optional cell as empty, a text as it parses);
    - the rows as a set with their repeats, their order aside.

    So a re-typed, re-saved or re-ordered file (columns, or rows) of the same values is the
    same readings, and one reading changed in its last digit is not. What is not compared:
    the settings (a unit chosen, a run's layout), the certificate's details, the file's
    name or bytes, the instrument's raw capture."""
    from models.readings.sheet import ReadingsSheet
    from models.registry import KINDS

    try:
        data = json.loads(project_json or "{}")
        bench = (data.get("workbenches") or {}).get(workbench) or {}
        rows = bench.get("rows") if isinstance(bench, dict) else None
        if not isinstance(rows, list) or not rows or workbench not in KINDS:
            return ""
        columns = KINDS[workbench].columns
        parsed = ReadingsSheet(columns, [r if isinstance(r, list) else [r] for r in rows]
                               ).parse()
    except (ValueError, TypeError, AttributeError, LookupError):
        return ""  # no project state this version reads: nothing to compare
    if parsed.n == 0:
        return ""
    keys = [c.key for c in columns]
    table = sorted(tuple(_value(parsed.values[k][i]) for k in keys) for i in range(parsed.n))
    return hashlib.sha256(json.dumps([keys, table], ensure_ascii=False).encode()).hexdigest()


#: the unit of the index's interval (:attr:`ReadingsIdentity.low`, ``high``): 2⁻⁴⁰ rad or m
#: (9.1e-13; 1.9e-7″), far below any reading's step; a sum of 10⁵ rad is 1.1e17 of them
_QUANTUM = 2.0 ** -40
#: an interval beyond ±this (values of 10⁶ rad and more) is every value's: always compared
_BOUND = 2 ** 62
#: the reach of such an interval: a record of it is a candidate of every look-up
INDEX_BOUND = _BOUND
#: the float noise allowed beside a tolerance: of the values (a value parsed from two
#: spellings and converted to rad differs by a few ulp) and of the tolerance itself
_ULPS = 8 * float(np.finfo(float).eps)
_RELATIVE = 1e-6
#: an exponent at a number's end: the step is that of the mantissa's last digit
_EXPONENT = re.compile(r"[eE][+-]?\d+\s*$")


@dataclass(frozen=True)
class ReadingsIdentity:
    """The readings of a project state, as the register compares them
    (:func:`readings_identity`). ``layout``, ``anchor`` and ``reach`` are stored with the
    record (schema version 9; in the chain from chain format 8); the anchors within the
    larger reach (:func:`near`) find the candidates, whose ``shape`` and ``groups`` are
    compared (:func:`same_readings_values`)."""

    #: SHA-256 of the columns (each one's key and dimension) and of the set of the rows'
    #: other cells as typed (every cell but the angles and lengths, and which of those are
    #: blank): stored and chained, checked by verify, no longer compared (``shape`` is)
    layout: str
    #: the smallest value of the first reading column, and the largest half step of that
    #: column, in whole units of :data:`_QUANTUM` (:func:`_anchor`): the anchors of the same
    #: readings are within the larger of their two reaches
    anchor: int
    reach: int
    #: SHA-256 of the columns and of the set of the rows' other cells as the analysis reads
    #: them (:meth:`models.workbench.Workbench.read_cells`: a choice by its meaning, a blank
    #: run or direction as it derives it): what is compared (not stored, made again from the
    #: record's project state; ident80b)
    shape: str = field(compare=False, repr=False)
    #: each set of other cells as the analysis reads them → (the rows' angles and lengths in
    #: rad or m, NaN blank; the half step of each one's last digit), as arrays of one row a
    #: reading
    groups: Mapping[tuple, tuple[np.ndarray, np.ndarray]] = field(compare=False, repr=False)

    @property
    def stored(self) -> tuple[str, int, int]:
        """(layout, anchor, reach): what the record stores."""
        return self.layout, self.anchor, self.reach


def near(anchor: int, reach: int, other_anchor: int, other_reach: int) -> bool:
    """Whether two anchors (:attr:`ReadingsIdentity.anchor`) may be of the same readings:
    within the larger of the two reaches."""
    return abs(anchor - other_anchor) <= max(reach, other_reach)


#: what a record of no readings that parse stores
NO_READINGS = ("", 0, 0)


#: the steps found (:func:`_step`) by the column's kind and the cell's text, which alone
#: decide them (an angle or a number parses by its text alone): a register's records repeat
#: many cells (the targets, the nominal steps, a display's usual readings), and migration 9
#: made every one's again (34.6 s for 10,000 records, ident80b); cleared past its size
_STEPS: dict[tuple[Any, str], float] = {}
_STEPS_KEPT = 200_000


def _step_of(text: str, column: Any, value: float) -> float:
    """:func:`_step`, remembered by the column's kind and the text."""
    key = (column.kind, text)
    found = _STEPS.get(key)
    if found is None:
        if len(_STEPS) >= _STEPS_KEPT:
            _STEPS.clear()
        found = _STEPS[key] = _step(text, column, value)
    return found


def _step(text: str, column: Any, value: float) -> float:
    """The step of the last digit of ``text`` (a cell ``column`` reads as ``value``), in
    the unit the column reads it in: the text read again with that digit moved by one,
    through the column's own parser — so for every spelling it takes (``12°30'00.1"``:
    0.1″ in degrees; ``12 30 00.1``; ``12.5``: 0.1; ``1.25e1``: 0.1; full-width digits).
    0 when no digit can be moved (compared exactly)."""
    s = text.strip()
    found = _EXPONENT.search(s)
    end = found.start() if found else len(s)
    for i in range(end - 1, -1, -1):
        digit = unicodedata.digit(s[i], None)
        if digit is not None:
            break
    else:
        return 0.0
    for other in ((digit + 1, digit - 1) if digit < 9 else (digit - 1,)):
        if other < 0:
            continue
        moved = f"{s[:i]}{chr(ord(s[i]) - digit + other)}{s[i + 1:]}"
        try:
            step = abs(float(column.parse(moved)) - value)
        except (ValueError, TypeError, OverflowError):
            continue
        if math.isfinite(step):
            return step
    return 0.0


def readings_identity(project_json: str, workbench: str) -> ReadingsIdentity | None:
    """The identity of the readings ``project_json`` holds for ``workbench`` by their physical
    values (the module's docstring says how they are compared); None when it holds none that
    parse (no project, no rows, a workbench unknown to this version)."""
    from models.quantity import UnitError, unit
    from models.readings.sheet import ColumnKind, ReadingsSheet
    from models.registry import KINDS

    try:
        data = json.loads(project_json or "{}")
        bench = (data.get("workbenches") or {}).get(workbench) or {}
        rows = bench.get("rows") if isinstance(bench, dict) else None
        if not isinstance(rows, list) or not rows or workbench not in KINDS:
            return None
        kind = KINDS[workbench]
        stated = bench.get("settings")
        settings = kind.settings_with_defaults(stated if isinstance(stated, dict) else {})
        units, origins = kind.column_units(settings), kind.column_origins(settings)
        columns = kind.columns
        sheet = ReadingsSheet(columns, [r if isinstance(r, list) else [r] for r in rows])
        parsed = sheet.parse()
    except (ValueError, TypeError, AttributeError, LookupError):
        return None  # no project state this version reads: nothing to compare
    if parsed.n == 0:
        return None
    physical: list[tuple[int, Any, float, float, str]] = []  # (index, column, size, origin,
    #                                                     dimension)
    dimensions = []
    for index, column in enumerate(columns):
        size, dimension = 0.0, ""
        if column.kind in (ColumnKind.ANGLE_DEG, ColumnKind.NUMBER):
            try:
                found = unit(str(units.get(column.key, column.unit)))
            except UnitError:
                found = None
            if found is not None and found.dimension in ("angle", "length"):
                size, dimension = found.size, found.dimension
        dimensions.append([column.key, dimension])
        if dimension:
            physical.append((index, column, size, float(origins.get(column.key, 0.0)), dimension))
    others = [c.key for c in columns if not any(c is p[1] for p in physical)]
    n = parsed.n
    values = np.full((n, len(physical)), np.nan)
    halves = np.zeros((n, len(physical)))
    for j, (index, column, size, origin, _) in enumerate(physical):
        raw = np.asarray(parsed.values[column.key], dtype=float)
        values[:, j] = (raw + origin) * size
        for r in np.nonzero(np.isfinite(raw))[0].tolist():
            text = sheet.text(int(parsed.row_index[r]), index)
            halves[r, j] = 0.5 * _step_of(text, column, float(raw[r])) * size
    _derive(kind.derived_columns(settings), physical, values, halves)
    try:
        read = {k: v for k, v in kind.read_cells(parsed, settings).items()
                if k in others and len(v) == n}
    except (ValueError, TypeError, ArithmeticError, LookupError):
        read = {}  # refused by the analysis: the cells as typed
    blank = ~np.isfinite(values)
    typed: dict[tuple, list[int]] = {}
    members: dict[tuple, list[int]] = {}
    for i in range(n):
        blanks = tuple(bool(b) for b in blank[i])
        typed.setdefault((tuple(_value(parsed.values[k][i]) for k in others), blanks),
                         []).append(i)
        if read:
            members.setdefault((tuple(_value(read[k][i] if k in read else parsed.values[k][i])
                                      for k in others), blanks), []).append(i)
    if not read:
        members = typed  # every cell read as typed
    groups = {key: (values[rows_], halves[rows_]) for key, rows_ in members.items()}
    layout, shape = (hashlib.sha256(json.dumps(
        [dimensions, sorted([list(k[0]), list(k[1])] for k in keys)],
        ensure_ascii=False).encode()).hexdigest() for keys in (typed, members))
    anchor, reach = _anchor(kind, physical, values, halves)
    return ReadingsIdentity(layout, anchor, reach, shape, groups)


def _derive(derived: Mapping[str, tuple[str, str]], physical: list, values: np.ndarray,
            halves: np.ndarray) -> None:
    """The readings as the analysis takes them where a column's value may be given through
    others (:meth:`models.workbench.Workbench.derived_columns`: the positioning's deviation
    as measured − target): a blank cell of the column gets source − other (in rad or m, so
    in any of their units), with the source's half step; the source column is then blank
    throughout (where both are given, the analysis takes the column's), in place."""
    at = {p[1].key: j for j, p in enumerate(physical)}
    for key, (source, other) in derived.items():
        if key not in at or source not in at or other not in at:
            continue
        j, js, jo = at[key], at[source], at[other]
        if len({physical[i][4] for i in (j, js, jo)}) != 1:
            continue
        fill = ~np.isfinite(values[:, j]) & np.isfinite(values[:, js]) & np.isfinite(values[:, jo])
        values[fill, j] = values[fill, js] - values[fill, jo]
        halves[fill, j] = halves[fill, js]
        values[:, js], halves[:, js] = np.nan, 0.0


def _anchor(kind: Any, physical: list, values: np.ndarray, halves: np.ndarray
            ) -> tuple[int, int]:
    """The index's anchor: the smallest value of the first reading column that holds one
    (the workbench's ``plan_reading_keys`` among the angles and lengths, or the first of
    them: a column that sets a point, such as the theodolite's θ typed "30", is typed
    coarsely), and the largest half step of that column, both in whole units of
    :data:`_QUANTUM` (the step rounded up, with the float noise). Readings the same as
    another's by :func:`same_readings_values` have anchors within the larger of their two
    half steps: the smallest value of either is within it of a value of the other, and no
    value of the other is smaller by more. A row given twice moves neither."""
    reading = [j for j, p in enumerate(physical) if p[1].key in kind.plan_reading_keys] \
        + list(range(len(physical)))
    for j in reading:
        finite = np.isfinite(values[:, j])
        if finite.any():
            small = float(values[finite, j].min())
            half = float(halves[finite, j].max()) * (1 + 2 * _RELATIVE) + 2 * _ULPS * abs(small)
            anchor = small / _QUANTUM
            if not math.isfinite(anchor + half / _QUANTUM) or abs(anchor) + half / _QUANTUM >= _BOUND:
                return 0, _BOUND  # beyond the index: compared with every record of its layout
            return round(anchor), math.ceil(half / _QUANTUM) + 1
    return 0, 0


def _covered(values: np.ndarray, halves: np.ndarray, others: np.ndarray,
             other_halves: np.ndarray) -> bool:
    """Whether every row of ``values`` has a row of ``others`` whose every value is within
    the larger of the two half steps of its own (blank where it is blank)."""
    if values.shape[1] == 0 or others.shape[0] == 0:
        return others.shape[0] > 0 or values.shape[0] == 0
    finite = np.nonzero(np.isfinite(values[0]))[0]
    if finite.size == 0:
        return True  # every angle and length blank: the rows are their other cells
    j = int(finite[0])
    order = np.argsort(others[:, j], kind="stable")
    others, other_halves = others[order], other_halves[order]
    column = others[:, j]
    reach = float(other_halves[:, j].max())
    for row, half in zip(values, halves, strict=True):
        span = (half[j] + reach) * (1 + 2 * _RELATIVE) + 2 * _ULPS * (abs(row[j]) + 1.0)
        start = int(np.searchsorted(column, row[j] - span, "left"))
        stop = int(np.searchsorted(column, row[j] + span, "right"))
        if start >= stop:
            return False
        near = others[start:stop]
        tolerance = (np.maximum(half, other_halves[start:stop]) * (1 + _RELATIVE)
                     + _ULPS * np.maximum(np.abs(near), np.abs(row)))
        with np.errstate(invalid="ignore"):
            alike = (np.abs(near - row) <= tolerance) | (np.isnan(near) & np.isnan(row))
        if not alike.all(axis=1).any():
            return False
    return True


def same_readings_values(one: ReadingsIdentity | None, other: ReadingsIdentity | None) -> bool:
    """Whether two identities are of the same readings (the module's docstring): the same
    columns and set of other cells, and each row of either within the tolerance of a row of
    the other with those cells. None (no readings) is no one's."""
    if one is None or other is None or one.shape != other.shape:
        return False
    for key, (values, halves) in one.groups.items():
        found = other.groups.get(key)
        if found is None:
            return False
        if not (_covered(values, halves, *found) and _covered(*found, values, halves)):
            return False
    return len(one.groups) == len(other.groups)
