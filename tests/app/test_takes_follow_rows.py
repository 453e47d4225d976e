"""Rows inserted, deleted or replaced above or over captured readings move their takes, undo
and redo included, so the edit check (what the certificate prints) and the project file name
the row each captured reading is in now; a deleted captured reading is said as deleted
(review 61 F5: every captured reading below a deleted row was printed "edited after capture"
with another row's value)."""

from __future__ import annotations

import hashlib
import json
import subprocess

import pytest

from app.certificate_issue import issue_certificate, readings_edited_after_capture
from app.main_window import _SheetRows
from models.capture.raw_record import session_json
from models.certificate.metadata import CertificateMetadata
from models.project.file import load_project
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.store import Register
from models.registry import KINDS

pytestmark = pytest.mark.slow  # a window

START = "2026-12-02T01:02:03+00:00"


@pytest.fixture
def bench(window):
    """The polygon's row 0 typed by hand, rows 1-3 captured (one frame each)."""
    bench = window.presenter("polygon")
    bench.table_model.set_cells([
        (0, 0, "1"), (0, 1, "0"), (0, 2, "0"), (0, 3, "99"), (0, 4, "9"),
        (1, 0, "1"), (1, 1, "0"), (1, 2, "0"), (1, 3, "12.5"), (1, 4, "-3.25"),
        (2, 0, "2"), (2, 1, "45"), (2, 2, "0"), (2, 3, "21.56"), (2, 4, "1"),
        (3, 0, "3"), (3, 1, "90"), (3, 2, "0"), (3, 3, "7.25"), (3, 4, "0.5")])
    frames = [(0.0, b"3 003 12.500 -3.250", True), (0.1, b"3 003 21.560 1.000", True),
              (0.2, b"3 003 7.250 0.500", True)]
    window.projects.load_raw_capture({"polygon": [session_json(
        "autocollimator", "/dev/ttyUSB0", 9600, START, frames, [[1, 0, 0], [2, 1, 1], [3, 2, 2]],
        workbench="polygon")]})
    yield bench
    window.capture_panel.close()


def _said(window, bench):
    return [str(e.text()) for e in readings_edited_after_capture(
        bench.kind, bench.settings, _SheetRows(bench.sheet),
        window.capture_panel.raw_sessions("polygon"))]


def _rows(window):
    return [t[0] for t in window.capture_panel.raw_sessions("polygon")[0]["takes"]]


def test_deleting_or_inserting_a_row_above_captured_readings_moves_their_takes(window, bench):
    model = bench.table_model
    model.remove_rows([0])  # the typed row: nothing captured was edited
    assert _rows(window) == [0, 1, 2] and _said(window, bench) == [] and model.edited_cells == {}
    bench.undo_stack.undo()
    assert _rows(window) == [1, 2, 3] and _said(window, bench) == []
    bench.undo_stack.redo()
    assert _rows(window) == [0, 1, 2] and _said(window, bench) == []
    bench.undo_stack.undo()
    model.insert_rows(0, 2)  # two rows at the top
    assert _rows(window) == [3, 4, 5] and _said(window, bench) == [] and model.edited_cells == {}
    # a real edit after the shift is said with the reading captured for that row
    model.set_cells([(4, 3, "26.56")])
    assert _said(window, bench) == ["reading of row 5 edited after capture: 21.56 → 26.56"]
    assert set(model.edited_cells) == {(4, 3)}
    bench.undo_stack.undo()  # the edit
    bench.undo_stack.undo()  # the insertion
    assert _rows(window) == [1, 2, 3] and _said(window, bench) == []


def test_a_deleted_captured_reading_is_said_and_comes_back_with_the_undo(window, bench):
    model = bench.table_model
    model.remove_rows([0, 2])  # the typed row and the second captured one
    assert _rows(window) == [0, -4, 1]  # -2 - 2: deleted from row 2 (0-based)
    assert _said(window, bench) == ["reading of row 3 deleted after capture: 21.56, 1"]
    assert model.edited_cells == {}  # in no cell: its row is gone
    bench.undo_stack.undo()
    assert _rows(window) == [1, 2, 3] and _said(window, bench) == []
    bench.undo_stack.redo()
    assert _rows(window) == [0, -4, 1]


def test_readings_replaced_detach_every_take_until_undone(window, bench):
    bench.table_model.replace_all([["1", "0", "0", "1", "2"]], "Import")
    assert _rows(window) == [-3, -4, -5]
    assert _said(window, bench) == ["reading of row 2 deleted after capture: 12.5, -3.25",
                                    "reading of row 3 deleted after capture: 21.56, 1",
                                    "reading of row 4 deleted after capture: 7.25, 0.5"]
    bench.undo_stack.undo()
    assert _rows(window) == [1, 2, 3] and _said(window, bench) == []
    bench.undo_stack.redo()
    assert _rows(window) == [-3, -4, -5]


def test_the_project_saves_the_rows_as_they_are_now_and_its_digest_checks(window, bench,
                                                                          tmp_path):
    bench.table_model.remove_rows([0])
    path = tmp_path / "shifted.anglebench.json"
    assert window.projects.save_to(str(path))
    entry = json.loads(path.read_text(encoding="utf-8"))["raw_capture"]["polygon"]
    assert [t[0] for t in entry["sessions"][0]["takes"]] == [0, 1, 2]
    assert entry["sessions"][0]["workbench"] == "polygon"
    assert entry["sha256"] == hashlib.sha256(json.dumps(
        entry["sessions"], ensure_ascii=False, separators=(",", ":")).encode()).hexdigest()
    project = load_project(path, {"polygon": KINDS["polygon"]})
    assert readings_edited_after_capture(
        KINDS["polygon"], {}, project.workbenches["polygon"].rows,
        project.raw_capture["polygon"]) == []


@pytest.mark.parametrize("register_url", ["sqlite"], indirect=True)
def test_the_certificate_prints_the_deletion_and_the_digest_the_register_records(
        register_url, tmp_path, samples_dir):
    kind = KINDS["polygon"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    keys = [c.key for c in kind.columns]
    x, y = keys.index("ac_x_arcsec"), keys.index("ac_y_arcsec")

    def frame(row):
        return f"3 003 {float(rows[row][x]):.3f} {float(rows[row][y]):.3f}".encode()

    # rows 2 and 3 captured; row 2 deleted afterwards and typed again
    session = session_json("autocollimator", "/dev/ttyUSB0", 9600, START,
                           [(0.0, frame(2), True), (0.1, frame(3), True)],
                           [[2, 0, 0], [3, 1, 1]], workbench="polygon")
    from models.capture.take_rows import TakeRows, session_takes

    takes = TakeRows(lambda: session_takes([session]))
    takes.removed(2, 1)
    takes.inserted(2, 1)  # and the reading typed again by hand: not the one captured
    deleted = [f"{float(rows[2][x]):.3f}", f"{float(rows[2][y]):.3f}"]
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": ""})
    with Register(register_url) as register:
        record = issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                   kind.checked_settings({}), rows, "captured.anglebench.json",
                                   str(tmp_path / "captured.pdf"), raw_capture=[session])
    kept = json.loads(record.project_json)["raw_capture"]["polygon"]
    assert kept["sessions"][0]["takes"] == [[-4, 0, 0], [3, 1, 1]]
    digest = hashlib.sha256(json.dumps(kept["sessions"], ensure_ascii=False,
                                       separators=(",", ":")).encode()).hexdigest()
    assert record.raw_sha256 == kept["sha256"] == digest
    text = " ".join(subprocess.run(["pdftotext", str(tmp_path / "captured.pdf"), "-"],
                                   capture_output=True, text=True, check=True).stdout.split())
    shown = ", ".join(f"{float(v):.12g}" for v in deleted)
    assert f"reading of row 3 deleted after capture: {shown}" in text
    assert "edited after capture" not in text
    assert digest in text.replace(" ", "")


def test_the_takes_of_a_connection_still_open_move_too(window, qtbot):
    from tests.instrument_simulators import AutocollimatorSimulator

    window.tabs.setCurrentIndex(window.presenters.index(window.presenter("polygon")))
    bench = window.presenter("polygon")
    bench.view.table.setCurrentIndex(bench.table_model.index(0, 3))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(2.5, 1.0)]) as sim:
        panel.connect_to("autocollimator", sim.port, silence_s=0.2, retries=1)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        panel.take_button.click()
        assert panel.session is not None and panel.session.takes[0][0] == 0
        bench.table_model.insert_rows(0, 1)  # while connected: the open session's take moves
        assert panel.session.takes[0][0] == 1
        assert _said(window, bench) == [] and bench.table_model.edited_cells == {}
        bench.table_model.remove_rows([1])
        assert _said(window, bench) == ["reading of row 2 deleted after capture: 2.5, 1"]
        panel.disconnect_instrument()
    assert [t[0] for t in panel.raw_capture()["polygon"][0]["takes"]] == [-3]
    panel.close()
