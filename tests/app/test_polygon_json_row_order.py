"""SPEC §4: the polygon JSON's per-point arrays are in input-row order, with each entry's
face and set beside them (contract review 75 F1: a set read in reverse was listed in face
order, so a script pairing values with rows got the wrong error for every face of it)."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from app.main import main
from models.readings.angles import parse_angle_deg

pytestmark = pytest.mark.slow  # runs the command line on the sample (about a second)

PER_POINT = ("error_arcsec", "pyramidal_error_arcsec", "corrected_error_arcsec")


def _rows(path) -> list[dict[str, str]]:
    with open(path, encoding="utf-8-sig", newline="") as handle:
        return list(csv.DictReader(handle))


def _readings_in_row_order(path) -> list[dict[str, str]]:
    """The file's rows less each set's closure row (its last, back on its first face)."""
    rows = _rows(path)
    out = []
    for row in rows:
        first = next(r for r in rows if r["set"] == row["set"])
        last = [r for r in rows if r["set"] == row["set"]][-1]
        if row is last and row["position"] == first["position"] and row is not first:
            continue
        out.append(row)
    return out


def _eq1_errors(path) -> np.ndarray:
    """Eq (1) row by row, against the first reading of set 1 (face 1), 24 faces, the
    encoder counting with the face numbers: e = (a − a_z) − (b − b_z) − (c − c_z)."""
    rows = _readings_in_row_order(path)
    a = np.array([parse_angle_deg(r["encoder_deg"]) for r in rows])
    face = np.array([int(r["position"]) for r in rows])
    dev = np.array([float(r["polygon_dev_arcsec"]) for r in rows])
    c = np.array([float(r["ac_x_arcsec"]) for r in rows])
    da = (a - a[0]) - (face - face[0]) * 15.0
    da = (da + 180.0) % 360.0 - 180.0
    return da * 3600.0 - (dev - dev[0]) - (c - c[0])


def _json(capsys, *args) -> dict:
    code = main(["analyze", "polygon", *map(str, args), "--json"])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    return json.loads(captured.out)


def test_errors_are_listed_in_input_row_order_with_face_and_set(capsys, samples_dir):
    sample = samples_dir / "polygon_sample.csv"
    data = _json(capsys, sample)
    np.testing.assert_allclose(data["error_arcsec"], _eq1_errors(sample), atol=5e-9)
    rows = _readings_in_row_order(sample)
    assert data["face"] == [int(r["position"]) for r in rows]
    assert data["set"] == [int(r["set"]) for r in rows]
    # set 2 is read in reverse: faces 1, 24, 23, … in its rows 27, 28, 29, …
    assert data["face"][24:28] == [1, 24, 23, 22]
    # the corrected error is the error less the pyramidal correction entry by entry
    np.testing.assert_allclose(np.subtract(data["error_arcsec"], data["pyramidal_error_arcsec"]),
                               data["corrected_error_arcsec"], atol=1e-12)


def test_a_set_started_on_another_face_is_listed_as_read(capsys, tmp_path, samples_dir):
    """Set 1 started on face 5 (rows rotated, its closure back on face 5)."""
    rows = _rows(samples_dir / "polygon_sample.csv")
    first = rows[:25]  # set 1: faces 1…24 and the closure on face 1
    rotated = first[4:24] + first[:4] + [dict(first[4])]
    path = tmp_path / "from_face_5.csv"
    with open(path, "w", encoding="utf-8", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rotated + rows[25:])
    data = _json(capsys, path)
    assert data["face"][:6] == [5, 6, 7, 8, 9, 10]
    assert data["set"][:24] == [1] * 24 and data["set"][24:] == [2] * 24
    np.testing.assert_allclose(data["error_arcsec"], _eq1_errors(path), atol=5e-9)


def test_the_u_arrays_follow_their_errors(capsys, samples_dir, tmp_path):
    """U and k of each per-point array pair with the entry beside them: the budget of (set,
    face) as the model gives it (face order) lands where that set's face is in the rows."""
    from models.certificate.metadata import CertificateMetadata
    from models.polygon.analysis import POLYGON
    from models.polygon.report import polygon_json_budgets
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table

    sample = samples_dir / "polygon_sample.csv"
    details = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    data = _json(capsys, sample, "--metadata", meta)
    parsed = ReadingsSheet(POLYGON.columns, map_columns(read_table(sample), POLYGON.columns)).parse()
    result = POLYGON.analyze(parsed, POLYGON.settings_with_defaults({}))
    budgets = polygon_json_budgets(result, CertificateMetadata.from_dict(details), None)
    faces = result.faces
    for name in PER_POINT:
        by_face = np.asarray(budgets[name].expanded)
        expected = [by_face[(s - 1) * faces + f - 1] for f, s in zip(data["face"], data["set"],
                                                                     strict=True)]
        np.testing.assert_allclose(data[f"expanded_uncertainty_{name}"], expected, rtol=1e-12)
        assert len(data[f"expanded_uncertainty_{name}"]) == len(data[name]) == 48
    # the zero reading (set 1, face 1, row 2) has U = 0 by definition, wherever it is listed
    assert data["expanded_uncertainty_error_arcsec"][0] == 0.0
    # set 2's face 1 is its own reading against the zero one: not 0
    assert data["expanded_uncertainty_error_arcsec"][24] > 0.0
