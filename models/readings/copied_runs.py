"""A run copied under another run number: two runs of one direction that read alike at
every point are one run entered twice, not two repeats.

A hostile tester entered run 2 again as run 3 (and as runs 3 to 5) of a positioning test,
and pass 1 again as pass 2 of a theodolite run: each was analysed as independent repeats,
the scatter understated and its degrees of freedom overstated, with nothing said. Where the
readings are entered coarser than about three times their scatter, two real runs may read
alike by the rounding's chance (:data:`ALIKE_BY_CHANCE` steps), and no copy is told.
"""

from __future__ import annotations

import math

import numpy as np

from models.messages import QT_TR_NOOP

__all__ = ["ALIKE_BY_CHANCE", "COPIED_RUN", "COPIED_PASS", "MIN_POINTS", "copied_run"]

#: the refusals: a positioning run, a theodolite pass
COPIED_RUN = QT_TR_NOOP("run {later} ({direction}) repeats run {earlier} at every target, "
                        "reading for reading: a copied run is no repeat; delete it or enter "
                        "the run as it was read")
COPIED_PASS = QT_TR_NOOP("run {later} ({direction}) repeats run {earlier} at every θ, reading "
                         "for reading: a copied pass is no repeat; delete it or enter the pass "
                         "as it was read")

#: the scatter, in steps of the readings as entered, up to which two runs may read alike at
#: every point by the rounding's chance
ALIKE_BY_CHANCE = 3.0
#: the fewest points two runs must share to be told a copy (two or three may agree by chance)
MIN_POINTS = 4


def copied_run(run: np.ndarray, direction: np.ndarray, point: np.ndarray, value: np.ndarray,
               step: float | None, scatter: float) -> tuple[int, int, float] | None:
    """(earlier run, later run, direction) of the first run that repeats an earlier one of
    its direction at every point (``point``: the target or θ, rounded to 1e-9; ``value``:
    the reading or its error, alike to 1e-9), or None. None also where ``step`` (the
    readings' step as entered) is not small against ``scatter`` (their pooled standard
    deviation): the rounding may then make two runs alike; and where nothing scatters (every
    run alike, or every run of the direction: the workbench says so and withholds what the
    scatter would determine)."""
    if not (math.isfinite(scatter) and scatter > 0.0):
        return None  # every run alike: no scatter to tell a copy by (said elsewhere)
    if step is not None and not scatter > ALIKE_BY_CHANCE * step:
        return None
    run = np.asarray(run, dtype=float)
    direction = np.asarray(direction, dtype=float)
    key = np.round(np.asarray(point, dtype=float), 9)
    value = np.asarray(value, dtype=float)
    seen: dict[float, list[tuple[int, np.ndarray, np.ndarray]]] = {}
    for r in dict.fromkeys(run[np.isfinite(run)].tolist()):
        for d in dict.fromkeys(direction[run == r].tolist()):
            here = (run == r) & (direction == d)
            order = np.argsort(key[here], kind="stable")
            points, readings = key[here][order], value[here][order]
            if points.size < MIN_POINTS or np.unique(points).size != points.size:
                continue
            seen.setdefault(d, []).append((int(r), points, readings))
    for d, runs in seen.items():
        alike = [[np.array_equal(p, q) and bool(np.allclose(v, w, rtol=1e-12, atol=1e-9))
                  for _, q, w in runs] for _, p, v in runs]
        if all(all(row) for row in alike):
            continue  # every run of the direction alike: no scatter to tell a copy by
        for later in range(len(runs)):
            for earlier in range(later):
                if alike[later][earlier]:
                    return runs[earlier][0], runs[later][0], float(d)
    return None
