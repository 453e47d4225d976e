"""#43: ``anglebench analyze polygon FILE --reference-dcc POLY.xml``: the polygon's DCC is
the reference — its face deviations replace the readings' column and its U enters the
budget exactly as the same figures typed in would; refused with the reason. The closed loop:
the cross-calibration workbench's polygon DCC read back by the polygon workbench."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from app.main import main
from tests import dcc_documents as t

SCHEMA = str(t.SHARED_DCC)


def _run(capsys, *args) -> tuple[int, str, str]:
    code = main(["analyze", *map(str, args)])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def _with_column(src, dst, deviations: dict[int, float]) -> None:
    """The readings with the deviation column typed by hand (what --reference-dcc does)."""
    with open(src, encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    for row in rows[1:]:
        row[2] = f"{deviations[int(row[0])]:.6f}"
    with open(dst, "w", encoding="utf-8", newline="") as handle:
        csv.writer(handle).writerows(rows)


def _details(samples_dir, tmp_path, name, standard=None, **changes):
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update(changes)
    if standard is not None:
        meta["standards"][0] = {**meta["standards"][0], **standard}
    path = tmp_path / name
    path.write_text(json.dumps(meta), encoding="utf-8")
    return path


@pytest.mark.slow
def test_the_dcc_replaces_the_column_and_its_u_enters_the_budget(samples_dir, tmp_path, capsys):
    errors = t.polygon_errors(24, seed=2, spread_arcsec=0.3)
    dcc = tmp_path / "poly.xml"
    dcc.write_bytes(t.document("PTB-2026-0007", results=t.polygon_results(
        errors, unit=r"\degree", u_arcsec=0.06, k=2.0), statements=t.validity(date="2027-12-31"),
        item="24-face polygon", serial="P24-3"))  # the polygon the details list
    readings = samples_dir / "polygon_sample.csv"
    details = samples_dir / "certificate_polygon.json"
    code, out, err = _run(capsys, "polygon", readings, "--reference-dcc", dcc, "--dcc-schema",
                          SCHEMA, "--metadata", details, "--json")
    assert code == 0, err
    assert "the deviation column held other values" in err and "PTB-2026-0007" in err
    via_dcc = json.loads(out)
    # the same figures typed in by hand: the column, and the polygon's row of the standards
    typed = tmp_path / "typed.csv"
    _with_column(readings, typed, dict(enumerate(errors, 1)))
    by_hand = _details(samples_dir, tmp_path, "hand.json", {
        "certificate_no": "PTB-2026-0007", "uncertainty": 0.06, "basis": "U95",
        "applies_to": "reading", "due_date": "2027-12-31"})
    code, out, err = _run(capsys, "polygon", typed, "--metadata", by_hand, "--json")
    assert code == 0, err
    typed_in = json.loads(out)
    for key in ("corrected_error_arcsec", "expanded_uncertainty_corrected_error_arcsec"):
        np.testing.assert_allclose(via_dcc[key], typed_in[key], rtol=0, atol=1e-9)
    code, out, _ = _run(capsys, "polygon", readings, "--metadata", details, "--json")
    sample = json.loads(out)  # the sample's own polygon certificate: U 0.2" from face 1
    assert (max(via_dcc["expanded_uncertainty_corrected_error_arcsec"])
            < max(sample["expanded_uncertainty_corrected_error_arcsec"]))


def test_a_refused_dcc_says_why_and_writes_nothing(samples_dir, tmp_path, capsys):
    readings = samples_dir / "polygon_sample.csv"
    details = samples_dir / "certificate_polygon.json"  # calibrated 2026-11-20
    pdf = tmp_path / "c.pdf"
    twelve = tmp_path / "twelve.xml"
    twelve.write_bytes(t.document("TWELVE-1"))
    expired = tmp_path / "expired.xml"
    expired.write_bytes(t.document("OLD-1", results=t.polygon_results(
        t.polygon_errors(24)), statements=t.validity(date="2026-11-19")))
    radians = tmp_path / "metre.xml"
    radians.write_bytes(t.document("M-1", results=t.polygon_results(t.polygon_errors(24),
                                                                    unit=r"\metre")))
    for dcc, reason in ((twelve, "measures face 13; certificate TWELVE-1 gives faces 1 to 12"),
                        (expired, "due for recalibration on 2026-11-19, before the measurement "
                                  "on 2026-11-20"),
                        (radians, r"the unit \metre is not an angle")):
        code, _, err = _run(capsys, "polygon", readings, "--reference-dcc", dcc, "--metadata",
                            details, "--certificate", pdf)
        assert code == 2 and reason in err, err
        assert not pdf.exists()
    code, _, err = _run(capsys, "theodolite", samples_dir / "theodolite_sample.csv",
                        "--reference-dcc", twelve)
    assert code == 2 and "--reference-dcc is for the polygon workbench" in err
    code, _, err = _run(capsys, "polygon", readings, "--reference-dcc", tmp_path / "none.xml")
    assert code == 2 and "none.xml: cannot read" in err


@pytest.mark.slow
def test_the_closed_loop_crosscal_polygon_dcc_read_by_the_polygon_workbench(samples_dir,
                                                                            tmp_path, capsys):
    """Cross-calibrate the polygon, issue its DCC, then test an encoder against it: the
    faces and U the polygon workbench reads are the cross-calibration's."""
    from models.validation.polygon_rig import PolygonRig, write_csv

    meta = samples_dir / "certificate_crosscal.json"
    xml = tmp_path / "polygon.xml"
    code, _, err = _run(capsys, "crosscal", samples_dir / "crosscal_sample.csv", "--metadata",
                        meta, "--certificate", tmp_path / "polygon.pdf", "--dcc", xml,
                        "--dcc-schema", SCHEMA)
    assert code == 0, err
    code, out, err = _run(capsys, "crosscal", samples_dir / "crosscal_sample.csv", "--metadata",
                          meta, "--json")
    crosscal = json.loads(out)
    faces = np.array(crosscal["polygon_deviation_from_face1_arcsec"])
    u = np.array(crosscal["expanded_uncertainty_polygon_deviation_from_face1_arcsec"])
    from models.dcc.reader import read_polygon_dcc

    read = read_polygon_dcc(xml, SCHEMA)
    np.testing.assert_allclose([read.deviations[i] for i in range(1, 13)], faces, atol=1e-6)
    np.testing.assert_allclose([read.expanded_uncertainty[i] for i in range(1, 13)], u,
                               rtol=1e-5, atol=1e-9)
    # an encoder tested against that polygon (simulated with its faces as they are)
    rig = PolygonRig(12, 0.3 * np.cos(np.radians(np.arange(12) * 30.0)), psi_arcsec=200.0,
                     omega_deg=30.0, face_dev_arcsec=faces, noise_arcsec=0.02,
                     rng=np.random.default_rng(1))
    rows = rig.set_rows(1) + rig.set_rows(2, reverse=True)
    for row in rows:
        row[2] = ""  # the column left empty: the DCC fills it
    readings = tmp_path / "encoder.csv"
    write_csv(readings, rows)
    # the details list that polygon (P12-7), not the sample's 24-face P24-3: another item's
    # DCC is refused (dccin74 F1)
    details = _details(samples_dir, tmp_path, "p12.json", {
        "description": "12-face polygon (deviations from face 1)", "serial": "P12-7"})
    code, out, err = _run(capsys, "polygon", readings, "--reference-dcc", xml, "--dcc-schema",
                          SCHEMA, "--metadata", details, "--json")
    assert code == 0, err
    assert "held other values" not in err and "states no due date" in err
    result = json.loads(out)
    truth = rig.truth_arcsec()
    corrected = np.reshape(result["corrected_error_arcsec"], (2, 12))
    residual = corrected[0] - truth - (corrected[0] - truth).mean()
    assert np.max(np.abs(residual)) < 0.1  # the polygon's faces taken out: the encoder left


@pytest.mark.slow
def test_an_encoders_dcc_given_as_the_polygons_is_refused_naming_the_polygons(samples_dir,
                                                                              tmp_path, capsys):
    """The polygon sample's own DCC (an encoder tested against polygon NIM-2026-0871) given
    as the polygon's certificate: 0.8.11 took the reference's face deviations from it and
    issued a certificate citing the encoder's number as the polygon's calibration."""
    readings = samples_dir / "polygon_sample.csv"
    details = samples_dir / "certificate_polygon.json"
    encoder = tmp_path / "encoder.xml"
    code, _, err = _run(capsys, "polygon", readings, "--metadata", details, "--certificate",
                        tmp_path / "encoder.pdf", "--dcc", encoder, "--dcc-schema", SCHEMA)
    assert code == 0, err
    number = next(line for line in err.splitlines() if line.startswith("DCC of ")).split()[2]
    pdf = tmp_path / "c.pdf"
    code, out, err = _run(capsys, "polygon", readings, "--reference-dcc", encoder,
                          "--dcc-schema", SCHEMA, "--metadata", details, "--certificate", pdf)
    assert code == 2, err
    assert (f"certificate {number} calibrates an encoder against a reference polygon, not the "
            "polygon" in err), err
    assert "restated from its own certificate NIM-2026-0871 (as this DCC lists the standard)" in err
    assert not pdf.exists()
