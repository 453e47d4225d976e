"""Polygon: the command line's JSON of a long test grows with its rows, not faster
(contract review 75 F11: 2500 rows, 100 sets, took 30 s and 5000 rows over 300 s, one budget
built anew per set and a least squares over all sets solved whole, m³).

The same 24-face polygon read 25 to 400 times (600 to 9600 rows) from the exact 3-D rig,
forward and reverse in turn; timed: the analysis, its JSON and the U beside every array
(what ``anglebench analyze polygon FILE --json`` computes)."""

from __future__ import annotations

import numpy as np
from bench_util import fmt_time, timings

from models.certificate.metadata import CertificateMetadata
from models.certificate.uncertainty_json import workbench_uncertainty_json
from models.polygon.analysis import POLYGON
from models.readings.sheet import ReadingsSheet
from models.validation.polygon_rig import PolygonRig

FACES = 24
SETS = (25, 50, 100, 200, 400)


def _rows(sets: int) -> list[list[str]]:
    rng = np.random.default_rng(75)
    theta = np.arange(FACES) * 360.0 / FACES
    truth = 0.6 * np.sin(np.radians(theta) + 0.4) + 0.2 * np.sin(np.radians(2 * theta))
    rig = PolygonRig(FACES, truth, 480.0, 30.0, face_dev_arcsec=rng.normal(0, 0.1, FACES),
                     noise_arcsec=0.05, rng=rng)
    rows: list[list[str]] = []
    for s in range(1, sets + 1):
        rows += rig.set_rows(s, reverse=s % 2 == 0, closure_drift_arcsec=0.1)
    return rows


def _json(rows: list[list[str]]) -> dict:
    parsed = ReadingsSheet(POLYGON.columns, rows).parse()
    settings = POLYGON.settings_with_defaults({})
    result = POLYGON.analyze(parsed, settings)
    data = POLYGON.to_json(result)
    data.update(workbench_uncertainty_json(POLYGON, result, CertificateMetadata(), {}))
    return data


def test_polygon_json_time_grows_with_the_rows(report):
    per_row, lines = [], []
    for sets in SETS:
        rows = _rows(sets)
        data = _json(rows)
        assert len(data["error_arcsec"]) == len(data["expanded_uncertainty_error_arcsec"]) \
            == sets * FACES
        seconds = timings(lambda rows=rows: _json(rows), 3 if sets <= 100 else 1, warmup=0)
        per_row.append(float(np.median(seconds)) / len(rows))
        lines.append(f"| {sets} | {len(rows)} | {fmt_time(seconds)} | "
                     f"{per_row[-1] * 1e3:.2f} ms |")
    growth = per_row[-1] / per_row[0]
    report("3-polygon-many-sets", [
        "## Polygon: the JSON of a long test (24 faces, forward and reverse in turn)",
        "",
        "| sets | rows | analysis + JSON + U | per row |",
        "|---|---|---|---|",
        *lines,
        "",
        f"The time per row at {SETS[-1]} sets is {growth:.2f}× that at {SETS[0]} sets "
        "(before contract review 75 F11: 100 sets 30 s, 200 sets over 300 s).",
    ])
    # near-linear: 16 times the rows may not cost more than 3 times as much a row
    assert growth < 3.0
