"""The cross-calibration's readings: their columns, the checks that name the row (and
the cell) of readings that cannot be a cross-calibration, and the n × n matrix labs
write (rows mountings, columns positions) turned into rows of readings.

A mounting is one block of rows: every face once, starting at the face the mounting
brings to the encoder's first step (face j + 1 for mounting j) with the encoder at the
same reading as every other mounting, optionally ending with a closure reading that
repeats its first face. A blank encoder column (all rows) means the encoder was set to
its nominal steps, 360°/n apart from 0, and the autocollimator read what was left.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.number_text import fixed
from models.readings.sheet import Column, ColumnKind, ParsedReadings
from models.readings.tabular_import import RawTable

__all__ = ["COLUMNS", "CrossCalReadings", "matrix_rows", "read_crosscal"]

COLUMNS = (
    Column("mounting", "mounting", "", ColumnKind.INTEGER,
           help="How many faces the polygon was turned on the shaft, in the encoder's counting "
                "sense, from mounting 0",
           aliases=("mount", "安装", "安装位置", "转位", "转位号")),
    Column("position", "pos", "", ColumnKind.INTEGER,
           help="Polygon face 1…n at the autocollimator; the row that repeats the mounting's "
                "first face at its end is the closure reading",
           aliases=("face", "面号", "面", "位置", "受检位置")),
    Column("encoder_deg", "encoder a", "deg", ColumnKind.ANGLE_DEG, required=False,
           help="Encoder reading (decimal or D°M'S\"); blank in every row: the encoder was set "
                "to its nominal steps from 0",
           aliases=("encoder", "编码器读数", "编码器", "a")),
    Column("ac_x_arcsec", "AC x", "\"", ColumnKind.NUMBER,
           help="Autocollimator horizontal reading",
           aliases=("ac x", "x", "自准直仪水平", "自准直仪x", "水平读数")),
    Column("ac_y_arcsec", "AC y", "\"", ColumnKind.NUMBER, required=False,
           help="Autocollimator vertical reading (gives each mounting's tilt)",
           aliases=("ac y", "y", "自准直仪垂直", "自准直仪y", "垂直读数")),
)

#: autocollimator readings beyond this are no readings of a polygon's faces
READING_LIMIT_ARCSEC = 3600.0
#: a matrix's last column named so holds each mounting's closure reading (its first face)
CLOSURE_HEADERS = ("closure", "闭合", "回零", "c")


@dataclass(frozen=True)
class CrossCalReadings:
    """The checked readings, in the order measured (used rows only)."""

    faces: int
    mounting: np.ndarray
    position: np.ndarray
    encoder_deg: np.ndarray
    ac_x_arcsec: np.ndarray
    ac_y_arcsec: np.ndarray | None
    sheet_rows: np.ndarray  # 1-based sheet row of each reading
    closure: np.ndarray  # bool: the row is its mounting's closure reading
    nominal_encoder: bool  # the encoder column was blank: nominal steps taken
    mountings: tuple[int, ...]  # in the order measured

    def row(self, index: int) -> int:
        return int(self.sheet_rows[index])

    def closure_arcsec(self) -> np.ndarray:
        """Each mounting's closure (x′ − x) − (a′ − a) in ″ (NaN without a closure reading)."""
        out = np.full(len(self.mountings), np.nan)
        for q, j in enumerate(self.mountings):
            rows = np.flatnonzero(self.mounting == j)
            if self.closure[rows[-1]]:
                first, last = rows[0], rows[-1]
                da = (self.encoder_deg[last] - self.encoder_deg[first] + 180.0) % 360.0 - 180.0
                out[q] = (self.ac_x_arcsec[last] - self.ac_x_arcsec[first]) - da * 3600.0
        return out


def _refuse(text: str, **figures) -> ValueError:
    return ValueError(message(text, **figures))


def read_crosscal(parsed: ParsedReadings, faces_setting: int = 0) -> CrossCalReadings:
    """The readings checked as a cross-calibration; ValueError naming the sheet row."""
    if parsed.n == 0:
        raise _refuse(QT_TR_NOOP("no readings"))
    sheet_rows = parsed.row_index.astype(int) + 1
    mounting = parsed["mounting"].astype(int)
    position = parsed["position"].astype(int)
    a = np.asarray(parsed["encoder_deg"], dtype=float)
    x = np.asarray(parsed["ac_x_arcsec"], dtype=float)
    y = np.asarray(parsed["ac_y_arcsec"], dtype=float)
    for key, values in (("ac_x_arcsec", x), ("ac_y_arcsec", y)):
        bad = np.flatnonzero(np.isfinite(values) & (np.abs(values) > READING_LIMIT_ARCSEC))
        if bad.size:
            i = int(bad[0])
            raise _refuse(QT_TR_NOOP("row {row}, column '{key}': {value}\" is beyond ±{limit}\" and "
                                     "cannot be an autocollimator reading of a face"),
                          row=sheet_rows[i], key=key, value=f"{values[i]:g}",
                          limit=f"{READING_LIMIT_ARCSEC:g}")
    blank_a = ~np.isfinite(a)
    if blank_a.any() and not blank_a.all():
        i = int(np.flatnonzero(blank_a if blank_a.sum() < blank_a.size / 2 else ~blank_a)[0])
        raise _refuse(QT_TR_NOOP("row {row}, column 'encoder_deg': the encoder reading is given "
                                 "in some rows and blank in others; give it in every row, or "
                                 "leave the column blank when the encoder was set to its "
                                 "nominal steps"), row=sheet_rows[i])
    blank_y = ~np.isfinite(y)
    if blank_y.any() and not blank_y.all():
        i = int(np.flatnonzero(blank_y)[0])
        raise _refuse(QT_TR_NOOP("row {row}, column 'ac_y_arcsec': a vertical reading is missing "
                                 "(give one in every row, or none)"), row=sheet_rows[i])
    # mountings: one block of rows each, in the order measured
    order: list[int] = []
    for i, j in enumerate(mounting):
        if order and j == order[-1]:
            continue
        if j in order:
            raise _refuse(QT_TR_NOOP("row {row}: mounting {mounting} again, after mounting "
                                     "{other}: keep each mounting's readings in one block"),
                          row=sheet_rows[i], mounting=int(j), other=order[-1])
        order.append(int(j))
    first_rows = np.flatnonzero(mounting == order[0])
    n = int(faces_setting) or max(int(np.unique(position[first_rows]).size), int(position.max()))
    if n < 3:
        raise _refuse(QT_TR_NOOP("{faces} faces: a polygon has at least 3"), faces=n)
    for i, (j, p) in enumerate(zip(mounting, position, strict=True)):
        if not 0 <= j < n:
            raise _refuse(QT_TR_NOOP("row {row}, column 'mounting': mounting {mounting} is outside "
                                     "0…{last} (a mounting is how many faces the polygon was "
                                     "turned, for {faces} faces)"),
                          row=sheet_rows[i], mounting=int(j), last=n - 1, faces=n)
        if not 1 <= p <= n:
            raise _refuse(QT_TR_NOOP("row {row}, column 'position': face {face} is outside 1…{faces} "
                                     "(the face count is {faces})"),
                          row=sheet_rows[i], face=int(p), faces=n)
    closure = np.zeros(mounting.size, dtype=bool)
    for j in order:
        rows = np.flatnonzero(mounting == j)
        seen: dict[int, int] = {}
        for q, r in enumerate(map(int, rows)):
            p = int(position[r])
            if p in seen:
                if q == rows.size - 1 and p == int(position[rows[0]]):
                    closure[r] = True
                    continue
                raise _refuse(QT_TR_NOOP("row {row}: mounting {mounting}, face {face} is read "
                                         "again (row {first}); only the closure reading, last in "
                                         "its mounting, may repeat the first face"),
                              row=sheet_rows[r], mounting=j, face=p, first=sheet_rows[seen[p]])
            seen[p] = r
        read = len(seen)
        if read != n:
            missing = sorted(set(range(1, n + 1)) - set(seen))
            raise _refuse(QT_TR_NOOP("rows {row}–{last}: mounting {mounting} reads {read} "
                                         "faces, the face count is {faces}: face(s) {missing} "
                                         "missing"),
                          row=sheet_rows[rows[0]], last=sheet_rows[rows[-1]], mounting=j,
                          read=read, faces=n, missing=", ".join(map(str, missing)))
        start_face = j + 1  # mounting j brings face j + 1 to the encoder's first step
        if int(position[rows[0]]) != start_face:
            raise _refuse(QT_TR_NOOP("row {row}: mounting {mounting} starts at face {face}; turned "
                                     "{mounting} face(s), the polygon has face {start} at the "
                                     "encoder's first step, where every mounting starts"),
                          row=sheet_rows[rows[0]], mounting=j, face=int(position[rows[0]]),
                          start=start_face)
    if len(order) < 2:
        raise _refuse(QT_TR_NOOP("only mounting {mounting}: one mounting does not connect the "
                                 "faces with the encoder's steps; turn the polygon on the shaft "
                                 "and read at least one more mounting"), mounting=order[0])
    nominal = bool(blank_a.all())
    step = 360.0 / n
    k = (position - 1 - mounting) % n
    if nominal:
        a = k * step
    else:
        start = a[first_rows[0]]
        tolerance = min(3.0, step / 4.0)
        for j in order[1:]:
            r = int(np.flatnonzero(mounting == j)[0])
            off = (a[r] - start + 180.0) % 360.0 - 180.0
            if abs(off) > tolerance:
                raise _refuse(QT_TR_NOOP("row {row}: mounting {mounting} starts with the encoder at "
                                         "{reading}°, {off}° from where mounting {first} started "
                                         "({start}°): every mounting starts from the same "
                                         "encoder position"),
                              row=sheet_rows[r], mounting=j, reading=fixed(a[r], 4),
                              off=f"{off:+.3f}", first=order[0], start=fixed(start, 4))
        off = (a - start - k * step + 180.0) % 360.0 - 180.0
        far = np.flatnonzero(np.abs(off) > tolerance)
        if far.size:
            i = int(far[0])
            raise _refuse(QT_TR_NOOP("row {row}, column 'encoder_deg': {reading}° is {off}° from "
                                     "step {step} ({nominal}°) where mounting {mounting} reads "
                                     "face {face}: a wrong mounting or face number, or a "
                                     "mis-typed reading"),
                          row=sheet_rows[i], reading=fixed(a[i], 4), off=f"{off[i]:+.3f}",
                          step=int(k[i]), nominal=f"{(start + k[i] * step) % 360.0:.4f}",
                          mounting=int(mounting[i]), face=int(position[i]))
    return CrossCalReadings(n, mounting, position, a, x, None if blank_y.all() else y,
                            sheet_rows, closure, nominal, tuple(order))


def _whole(text: str) -> int | None:
    try:
        value = float(text.strip())
    except ValueError:
        return None
    return int(value) if math.isfinite(value) and value.is_integer() else None


def matrix_rows(table: RawTable) -> list[list[str]] | None:
    """The n × n matrix (a header ``mounting, 1, 2, …, n[, closure]``, one row per mounting:
    its number, then the autocollimator's reading at each position) as rows of
    :data:`COLUMNS`, each mounting's faces in the order the encoder steps through them
    (face j + 1 first), the closure reading last. None when the table is no such matrix.
    The encoder column stays blank: the encoder was set to its nominal steps."""
    header = [h.strip() for h in table.header or []]
    while header and not header[-1]:  # a workbook's row is as wide as its widest
        header.pop()
    if len(header) < 4:
        return None
    closure = header[-1].lower() in CLOSURE_HEADERS
    faces = [_whole(h) for h in header[1:len(header) - closure]]
    n = len(faces)
    if n < 3 or faces != list(range(1, n + 1)):
        return None
    out: list[list[str]] = []
    for row in table.rows:
        cells = [c.strip() for c in row] + [""] * (len(header) - len(row))
        if not any(cells):
            continue
        j = _whole(cells[0])
        mounting = cells[0] if j is None else str(j)
        shift = j if j is not None and 0 <= j < n else 0
        for k in range(n):
            face = (k + shift) % n + 1
            out.append([mounting, str(face), "", cells[face], ""])
        if closure and cells[n + 1]:
            out.append([mounting, str(shift + 1), "", cells[n + 1], ""])
    return out
