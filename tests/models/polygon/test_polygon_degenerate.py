"""Designs the readings cannot determine (issue 39): the tilt not identified, said with the
real reason, its bound carried in U, and the reading noise never taken as 0.

The readings come from the exact 3-D rig (models/validation/polygon_rig.py, numpy only: it
rotates the face normals of a polygon tilted on the shaft and reads them as an
autocollimator would); the vertical readings are then made degenerate as a technician's
sheet can be: all the same number (copied, not read), or only 3 faces.
"""

from __future__ import annotations

import json

import numpy as np
import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.certificate.withheld import UncertaintyWithheld
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget
from models.readings.sheet import ReadingsSheet
from models.validation.polygon_rig import PolygonRig, write_csv

SIGMA = 0.03  # the autocollimator's noise, arcsec


def _rig(faces: int, psi: float, omega: float, seed: int) -> PolygonRig:
    th = np.radians(np.arange(faces) * 360.0 / faces)
    rng = np.random.default_rng(seed)
    error = rng.uniform(0.1, 0.4) * np.cos(th + rng.uniform(0, 6.3)) + 0.05 * np.sin(2 * th)
    return PolygonRig(faces, error, psi_arcsec=psi, omega_deg=omega, noise_arcsec=SIGMA,
                      rng=rng)


def _flat_vertical(rows, value="12.5"):
    return [[*r[:4], value, *r[5:]] for r in rows]


def _analyze(rows, **settings):
    settings.setdefault("grade", 3)
    return POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), settings)


def test_equal_vertical_readings_do_not_give_a_tilt_of_zero():
    rig = _rig(12, 300.0, 40.0, 1)
    result = _analyze(_flat_vertical(rig.set_rows()))
    assert result.sets[0].tilt is None
    assert "no variation" in result.tilt_verdict and "not identified" in result.tilt_verdict
    assert any("no variation" in w for w in result.warnings)
    assert np.all(result.sets[0].pyramidal_error_arcsec == 0.0)  # nothing removed
    out = POLYGON.to_json(result)
    assert out["pyramidal_tilt_arcsec"] is None and "no variation" in out["tilt_not_identified"]


def test_three_faces_name_the_missing_degrees_of_freedom_not_missing_readings():
    rig = _rig(3, 300.0, 40.0, 2)
    result = _analyze(rig.set_rows())
    assert result.sets[0].tilt is None
    said = " ".join(result.warnings)
    assert "no degrees of freedom" in said and "missing" not in said


@pytest.mark.parametrize("faces", [12, 3])
def test_the_noise_is_never_taken_as_zero_the_budget_is_withheld(faces):
    rig = _rig(faces, 300.0, 40.0, 3)
    rows = rig.set_rows()
    result = _analyze(_flat_vertical(rows) if faces > 3 else rows)
    with pytest.raises(UncertaintyWithheld, match="no degrees of freedom"):
        polygon_budget(result, CertificateMetadata())


def test_the_certificate_is_refused_on_the_command_line_naming_why(tmp_path, capsys):
    path = tmp_path / "flat.csv"
    write_csv(path, _flat_vertical(_rig(12, 300.0, 40.0, 4).set_rows()))
    assert main(["analyze", "polygon", str(path), "--json"]) == 0
    assert "no variation" in json.loads(capsys.readouterr().out)["tilt_not_identified"]
    assert main(["analyze", "polygon", str(path), "--certificate", str(tmp_path / "c.pdf")]) == 2
    err = capsys.readouterr().err
    assert "no uncertainty can be given" in err and "σ of a reading" in err
    assert not (tmp_path / "c.pdf").exists()


@pytest.mark.parametrize("faces, flat", [(12, True), (3, False)])
@pytest.mark.slow
def test_with_the_tilt_bound_and_a_stated_noise_u_covers_the_truth(faces, flat):
    """True tilt 300″ (the default bound) in random directions, σ stated: every position's
    error within its U at about the stated probability (before: 25–27 %)."""
    inside = total = 0
    for seed in range(25):
        rng = np.random.default_rng(100 + seed)
        rig = _rig(faces, 300.0, float(rng.uniform(0, 360)), 100 + seed)
        rows = rig.set_rows()
        result = _analyze(_flat_vertical(rows) if flat else rows, reading_noise_arcsec=SIGMA)
        budget = polygon_budget(result, CertificateMetadata(), {"reading_noise_arcsec": SIGMA})
        names = [c.name for c in budget.components]
        assert "Pyramidal tilt, not identified (bound)" in names
        assert any("Reading noise, stated" in n for n in names)
        miss = np.abs(result.mean_corrected_arcsec - rig.truth_arcsec())
        inside += int(np.sum(miss[1:] <= budget.expanded[1:]))  # face 1 is the zero
        total += faces - 1
    assert inside / total >= 0.95


def test_a_set_copied_under_another_set_number_is_refused_naming_both(tmp_path, capsys):
    """A set that repeats an earlier one reading for reading is a copy, not a second
    measurement (the shaft is stopped anew at each face): counted as a repeat it made the
    sets' scatter 0 and narrowed U (an audit: 0.165″ → 0.148″ at a face). Refused with
    both sets' first rows; the same set read again (new stops, new noise) is analysed."""
    from tests.polygon_sets_simulator import Bench, write_readings

    rows = Bench(faces=12).run_rows((1, 1), np.random.default_rng(4))
    first = [r for r in rows if r.rstrip("\n").split(",")[5] == "1"]
    copied = [",".join(r.rstrip("\n").split(",")[:5] + ["2"] + r.rstrip("\n").split(",")[6:])
              + "\n" for r in first]
    path = tmp_path / "copied.csv"
    write_readings(path, first + copied)
    assert main(["analyze", "polygon", str(path), "--json"]) == 2
    err = capsys.readouterr().err
    # the file's lines, the header line 1 (contract review 75 F7)
    assert "set 2 (from row 15) repeats set 1 (from row 2)" in err, err
    # the same set turned round and entered as the reverse set: it hid the rig's reversal
    reverse = [",".join(r.rstrip("\n").split(",")[:5] + ["2", "-"]) + "\n"
               for r in reversed(first)]
    path = tmp_path / "turned.csv"
    write_readings(path, first + reverse)
    assert main(["analyze", "polygon", str(path), "--json"]) == 2
    assert "repeats set 1" in capsys.readouterr().err
    path = tmp_path / "two_sets.csv"
    write_readings(path, rows)
    assert main(["analyze", "polygon", str(path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["repeatability_arcsec"] > 0.0


def test_sets_read_with_the_autocollimator_nulled_are_not_called_copies(tmp_path, capsys):
    """The autocollimator nulled at each face (x = 0, no vertical reading) and the encoder
    shown to 0.001°: two real sets may read alike at every face (a reviewer: 8 of 8 refused
    as copies). With nothing but the encoder's coarse display to compare, no copy is told."""
    lines = ["position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,direction"]
    for set_id in (1, 2):
        for face in list(range(1, 13)) + [1]:
            lines.append(f"{face},{(face - 1) * 30.0 + 0.001 * (face % 3):.3f},0.0,0.0,,"
                         f"{set_id},+")
    path = tmp_path / "nulled.csv"
    path.write_text("\n".join(lines) + "\n")
    assert main(["analyze", "polygon", str(path), "--json", "--grade", "7"]) == 0, \
        capsys.readouterr().err


def test_sets_alike_at_every_face_give_no_repeatability_of_zero(tmp_path, capsys):
    """Four sets read with the autocollimator nulled on an encoder shown to 0.001° (3.6″)
    (the encoder's error within ±1.5″, its scatter 0.1″): every set reads alike. 0.8.7
    printed "repeatability 0.00″" and took the noise out of U; the repeatability is now not
    evaluated, a warning says why, and with nothing else to evaluate the noise from, U is
    withheld (the summary names the sets alike)."""
    rng = np.random.default_rng(5)
    error = 1.5 * np.sin(np.radians(np.arange(12) * 30.0) + 0.3)  # the encoder's, arcsec
    lines = ["position,encoder_deg,polygon_dev_arcsec,ac_x_arcsec,ac_y_arcsec,set,direction"]
    for set_id in range(1, 5):
        for face in list(range(1, 13)) + [1]:
            shown = (face - 1) * 30.0 + (error[face - 1] + rng.normal(0.0, 0.1)) / 3600.0
            lines.append(f"{face},{round(shown, 3):.3f},0.0,0.0,,{set_id},+")
    path = tmp_path / "alike.csv"
    path.write_text("\n".join(lines) + "\n")
    assert main(["analyze", "polygon", str(path), "--json", "--grade", "7"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["repeatability_arcsec"] is None
    assert any("read alike at every face" in w for w in data["warnings"])
    assert data.get("uncertainty_withheld")
    assert main(["analyze", "polygon", str(path), "--grade", "7"]) == 0
    assert "the sets read alike at every face" in capsys.readouterr().out
