"""``anglebench analyze … --certificate --capture-record RAW.csv`` (stop 63: a certificate
issued from the command line named only the readings file as the readings' origin, where
the window's names the rows captured from the instruments and the instrument output's
SHA-256). The record is what ``anglebench capture --raw`` wrote; a captured row that is not
what the instrument sent is refused, naming the file and the row, unless the edit is
declared — then the certificate lists it, as the window's does."""

from __future__ import annotations

import csv
import hashlib
import json
import shutil
import subprocess

import pytest

from app.main import main
from models.capture.raw_record import raw_digest
from models.register.location import register_url
from models.register.store import Register
from tests.instrument_simulators import AutocollimatorSimulator
from tests.own_readings import own_readings

FAST = ["--silence", "0.2", "--retries", "1"]


def _pdf_text(path) -> str:
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext is missing")
    out = subprocess.run(["pdftotext", "-raw", "-enc", "UTF-8", str(path), "-"],
                         capture_output=True, text=True, check=True).stdout
    return " ".join(out.split())


@pytest.fixture(scope="module")
def captured(tmp_path_factory):
    """Three stable readings of the autocollimator at the polygon sample's first three
    faces (its ac_x, ac_y), as 'anglebench capture --out/--raw' wrote them."""
    folder = tmp_path_factory.mktemp("capture")
    positions = [(15.10, -242.01), (9.53, -126.22), (21.56, -2.04)]
    out, raw = folder / "ac.csv", folder / "raw.csv"
    with AutocollimatorSimulator("pty", positions=positions, hold_s=0.4, sigma=0.0) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "3", "--stable",
                     "0.5", "--dwell", "0.1", "--out", str(out), "--raw", str(raw),
                     *FAST]) == 0
    with open(out, newline="", encoding="utf-8") as handle:
        taken = list(csv.reader(handle))[1:]
    assert len(taken) == 3
    return taken, raw


def _readings(samples_dir, tmp_path, taken, edit=None):
    """The polygon sample with the capture's time_s column, its first three rows the
    readings taken (``edit``: (row, ac_x text) changed afterwards)."""
    with open(samples_dir / "polygon_sample.csv", newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    rows[0].append("time_s")
    for i, row in enumerate(rows[1:]):
        row.append(taken[i][0] if i < len(taken) else "")
        if i < len(taken):
            row[3], row[4] = taken[i][1], taken[i][2]
    if edit is not None:
        rows[edit[0]][3] = edit[1]
    path = tmp_path / "readings.csv"
    with open(path, "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows(rows)
    return path


def _details(samples_dir, tmp_path):
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": "", "language": "en"})
    path = tmp_path / "details.json"
    path.write_text(json.dumps(meta), encoding="utf-8")
    return path


def _analyze(readings, details, pdf, *more):
    return main(["analyze", "polygon", str(readings), "--metadata", str(details),
                 "--certificate", str(pdf), *more])


@pytest.mark.slow
def test_a_certificate_from_captured_readings_says_so_and_names_the_output(
        captured, samples_dir, tmp_path, capsys):
    taken, raw = captured
    readings = _readings(samples_dir, tmp_path, taken)
    pdf = tmp_path / "cert.pdf"
    assert _analyze(readings, _details(samples_dir, tmp_path), pdf,
                    "--capture-record", str(raw)) == 0, capsys.readouterr().err
    text = _pdf_text(pdf)
    # the readings named as the window names them (imported, with their SHA-256: 0.8.15);
    # where the cell wraps depends on the digest's letters (a proportional font): inside the
    # digest, or between its ")" and the ";" (a space there once failed CI), so the sentence
    # is compared with every space taken out
    digest = hashlib.sha256(readings.read_bytes()).hexdigest()
    assert (f"importedfromreadings.csv(SHA-256{digest});rows1–3(3of50)capturedfromtheinstruments"
            in text.replace(" ", "")), text
    with Register(register_url()) as register:
        (record,) = register.list()
        project = json.loads(record.project_json)
    stored = project["raw_capture"]["polygon"]  # recorded with the readings, in the chain
    sessions = stored["sessions"]
    assert [take[0] for take in sessions[0]["takes"]] == [0, 1, 2]
    assert stored["sha256"] == raw_digest(sessions)
    assert raw_digest(sessions) in text.replace(" ", "")  # the instrument output's SHA-256
    # without the record: a readings file alone, as before (readings of their own: the same
    # readings and details are the first calibration issued again, refused: register79)
    plain = own_readings(readings, "plain", tmp_path / "plain")
    assert _analyze(plain, _details(samples_dir, tmp_path), tmp_path / "plain.pdf",
                    "--separate-calibration", "issued again without the record") == 0
    assert "captured from the instruments" not in _pdf_text(tmp_path / "plain.pdf")


@pytest.mark.slow
def test_a_capture_record_that_is_not_the_readings_is_refused_unless_edits_are_declared(
        captured, samples_dir, tmp_path, capsys):
    taken, raw = captured
    readings = _readings(samples_dir, tmp_path, taken, edit=(2, "9.63"))  # face 2 retyped
    details, pdf = _details(samples_dir, tmp_path), tmp_path / "cert.pdf"
    capsys.readouterr()
    assert _analyze(readings, details, pdf, "--capture-record", str(raw)) == 2
    err = capsys.readouterr().err
    assert (f"{readings}: row 3, column 'ac_x_arcsec': 9.63 here, 9.53 in the capture record "
            f"{raw}: nothing was issued") in err, err
    assert not pdf.exists()
    with Register(register_url()) as register:
        assert register.list() == []
    assert _analyze(readings, details, pdf, "--capture-record", str(raw),
                    "--edited-after-capture") == 0
    text = _pdf_text(pdf)
    assert "reading of row 2 edited after capture: 9.53 → 9.63" in text, text
    assert "rows 1–3 (3 of 50) captured from the instruments" in text


def test_a_record_read_without_time_s_and_records_that_are_not_one():
    """Without the readings' time_s column the record's readings are the filled rows in
    order (one flagged line each, or a dwell's run); a count that differs, a file that is
    not a capture record, or a workbench with no column for the instrument is refused."""
    from app.capture_record import CaptureRecordError, capture_session

    keys = ["position", "encoder_deg", "polygon_dev_arcsec", "ac_x_arcsec", "ac_y_arcsec"]
    rows = [["1", "0", "0", "15.1", "-242.01"], ["2", "0", "0", "9.53", "-126.22"]]
    data = (b"time_s,reading,line\n0.1,0,boot\n0.2,1,3 003 15.100 -242.010\n"
            b"0.3,1,3 003 9.530 -126.220\n")
    session = capture_session("raw.csv", data, "r.csv", "polygon", keys, rows, None)
    assert session["instrument"] == "autocollimator" and session["takes"] == [[0, 1, 1],
                                                                              [1, 2, 2]]
    with pytest.raises(CaptureRecordError, match="readings in the capture record, 3 rows in r.csv"):
        capture_session("raw.csv", data, "r.csv", "polygon", keys, [*rows, rows[0]], None)
    with pytest.raises(CaptureRecordError, match="raw.csv: not a capture record"):
        capture_session("raw.csv", b"time_s,ac_x_arcsec\n", "r.csv", "polygon", keys, rows,
                        None)
    with pytest.raises(CaptureRecordError, match="raw.csv: line 3 is not"):
        capture_session("raw.csv", b"time_s,reading,line\n0.1,1,x\n0.2,yes,y\n", "r.csv",
                        "polygon", keys, rows, None)
    with pytest.raises(CaptureRecordError, match="no column for an autocollimator"):
        capture_session("raw.csv", data, "r.csv", "fringe", ["value"], rows, None)
    with pytest.raises(CaptureRecordError, match="no row of r.csv is a reading of this"):
        capture_session("raw.csv", data, "r.csv", "polygon", keys, rows, ["9.0", "9.5"])
