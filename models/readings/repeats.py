"""Repeated readings per point: n readings of one face, target or θ point, averaged.

The ELCOWIN habit: at each point the technician takes n readings in a row and the
evaluation uses their mean, with the standard deviation of that mean,
``s(x̄) = s / √n`` with ν = n − 1 degrees of freedom, as a Type A input of the
uncertainty budget.

The data shape: a workbench's setting *readings per point* n (default 1, every row
its own point, as before). With n > 1 the sheet's used rows are taken n at a time,
in order: each group is one point, and must agree on the columns that say which
point it is (face / target / θ, set or run, direction); the measured columns are
averaged. A group whose rows disagree, or a last group with fewer than n rows, is
refused naming the rows — a deleted or mistyped reading never shifts every later
point silently.

Angles (an encoder's or a theodolite's reading) are averaged as their deviations
from the group's first reading, wrapped to ±180°, so readings either side of 0° or
360° average to where they are.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.parameters import Parameter
from models.readings.sheet import ParsedReadings

__all__ = ["REPEATS_PARAMETER", "RepeatedReadings", "average_repeats"]

#: the setting every workbench with repeated readings declares
REPEATS_PARAMETER = Parameter(
    "readings_per_point", "readings per point n", "int", 1, minimum=1, maximum=100,
    help="n readings taken one after another at each point (face, target or θ): every n rows "
         "are one point, averaged; their s/√n (ν = n − 1) enters the uncertainty budget as "
         "the Type A input 'Repeated readings'. 1: every row is a point")


@dataclass(frozen=True)
class RepeatedReadings:
    """What is left of the repeated readings after averaging them. ``s_mean`` holds, for
    each measured column, one standard deviation of the mean (s/√n, in the column's unit)
    per point, in the order of the averaged rows."""

    n: int
    s_mean: dict[str, np.ndarray]
    rows: np.ndarray  # (points, n): the sheet rows (0-based) of each point's readings

    @property
    def dof(self) -> int:
        return self.n - 1


def _same(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Cells that say the same (numbers to 1e-9, NaN = NaN, text as text)."""
    if a.dtype == object or b.dtype == object:
        return np.array([(x or "") == (y or "") for x, y in zip(a, b, strict=True)], dtype=bool)
    a, b = a.astype(float), b.astype(float)
    return (np.isnan(a) & np.isnan(b)) | (np.abs(a - b) <= 1e-9)


def average_repeats(parsed: ParsedReadings, n: int, keys: Sequence[str],
                    measured: Sequence[str], angles: Sequence[str] = ()
                    ) -> tuple[ParsedReadings, RepeatedReadings | None]:
    """Average every ``n`` consecutive used rows of ``parsed`` into one row.

    In each group of ``n`` rows the ``keys`` columns must hold the same values, and the
    ``measured`` columns are averaged. The ``angles`` among them are in degrees and are
    averaged as deviations from the group's first reading, wrapped to ±180°. Return the
    averaged readings and what the averaging left; when ``n`` is 1 nothing changes and the
    second value is None."""
    n = int(n)
    if n <= 1:
        return parsed, None
    rows = parsed.row_index
    total = rows.size
    if total % n:
        first = total - total % n
        raise ValueError(message(
            QT_TR_NOOP("{n} readings per point, but the last point has {count} (row {row} on): "
                       "add its missing readings or remove the extra ones"),
            n=n, count=total % n, row=int(rows[first]) + 1))
    points = total // n
    groups = rows.reshape(points, n)
    out: dict[str, np.ndarray] = {}
    s_mean: dict[str, np.ndarray] = {}
    for key in keys:
        column = parsed[key].reshape(points, n)
        for j in range(1, n):
            differ = np.nonzero(~_same(column[:, 0], column[:, j]))[0]
            if differ.size:
                p = int(differ[0])
                raise ValueError(message(
                    QT_TR_NOOP("rows {row} and {row2} are readings {j} and 1 of one point "
                               "({n} readings per point), but their '{column}' differs: check "
                               "for a missing or extra reading"),
                    row=int(groups[p, j]) + 1, row2=int(groups[p, 0]) + 1, j=j + 1, n=n,
                    column=key))
        out[key] = column[:, 0].copy()
    for key in measured:
        column = parsed[key].astype(float).reshape(points, n)
        blank = np.isnan(column)
        mixed = np.nonzero(blank.any(axis=1) & ~blank.all(axis=1))[0]
        if mixed.size:
            p = int(mixed[0])
            j = int(np.nonzero(blank[p])[0][0])
            raise ValueError(message(
                QT_TR_NOOP("row {row}: '{column}' is blank, but the other readings of its point "
                           "have it: give every reading of a point the same columns"),
                row=int(groups[p, j]) + 1, column=key))
        base = column[:, :1]  # averaged as deviations from it: n equal readings give it back
        offsets = column - base
        if key in angles:
            offsets = (offsets + 180.0) % 360.0 - 180.0
        with np.errstate(invalid="ignore"):
            out[key] = base[:, 0] + np.mean(offsets, axis=1)
            s_mean[key] = np.std(offsets, axis=1, ddof=1) / np.sqrt(n)
    for key, values in parsed.values.items():
        if key not in out:
            out[key] = values.reshape(points, n)[:, 0].copy()
    averaged = ParsedReadings(out, groups[:, 0].copy(), list(parsed.errors))
    return averaged, RepeatedReadings(n, s_mean, groups)
