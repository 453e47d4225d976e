"""Where the readings came from survives the project file and the autosave (day review 67):
a project saved and opened again, or recovered after a crash, said its imported, pasted or
edited readings were the project's, or typed. A project file written before the origin was
kept says its readings are "from project NAME", never typed."""

from __future__ import annotations

import hashlib
import json
import os

import pytest

pytestmark = pytest.mark.slow  # windows, each analysing the polygon's readings

TYPED = "readings typed in AngleBench"


def _session(rows: list[int]) -> dict:
    """An autocollimator's session (as models/capture/raw_record.py stores it) whose takes
    went into ``rows`` (0-based): written here, as a project file holds it."""
    from models.capture.raw_record import session_json

    frames = [(0.1 * i, b"1.00 2.00\r\n", 1) for i in range(len(rows))]
    return session_json("autocollimator", "pty", 9600, "2026-12-06T07:00:00Z", frames,
                        [(r, i, i) for i, r in enumerate(rows)], workbench="polygon")


def _polygon(window, qtbot):
    presenter = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    qtbot.waitUntil(lambda: not presenter.analysis_pending, timeout=20000)
    return presenter


def _line(window, presenter) -> str:
    """The "Readings:" line a certificate of ``presenter``'s readings prints."""
    return str(window._readings_line(presenter))


def _imported_edited_pasted_captured(window, qtbot, tmp_path, samples_dir):
    """The polygon's readings imported from a file, one reading typed over, two rows
    pasted, and two taken from an instrument: (the presenter, the file's SHA-256)."""
    polygon = _polygon(window, qtbot)
    csv = tmp_path / "bench_run_0512.csv"
    csv.write_bytes((samples_dir / polygon.kind.sample_file).read_bytes())
    polygon.import_file(csv)
    column = polygon.sheet.column_index("polygon_dev_arcsec")
    polygon.table_model.set_cells([(2, column, "0.25")])
    table = polygon.view.table
    copied = "\n".join("\t".join(polygon.sheet.text(r, c) for c in range(polygon.sheet.column_count))
                       for r in (5, 6))
    table.setCurrentIndex(table.model().index(5, 0))
    assert table.paste_text(copied) == "cells"
    window._load_raw_capture({"polygon": [_session([8, 9])]})
    qtbot.waitUntil(lambda: not polygon.analysis_pending, timeout=20000)
    return polygon, hashlib.sha256(csv.read_bytes()).hexdigest()


def _said(digest: str, rows: int) -> str:
    return (f"imported from bench_run_0512.csv (SHA-256 {digest}), edited in AngleBench; rows "
            f"6–7 (2 of {rows}) pasted into AngleBench; rows 9–10 (2 of {rows}) captured from "
            "the instruments")


def test_a_saved_and_reopened_project_names_the_file_imported_and_the_rows_pasted(
        recovering_window, qtbot, tmp_path, samples_dir):
    window = recovering_window()
    polygon, digest = _imported_edited_pasted_captured(window, qtbot, tmp_path, samples_dir)
    rows = polygon.sheet.row_count
    assert _line(window, polygon) == _said(digest, rows)
    path = tmp_path / "job.anglebench.json"
    assert window.projects.save_to(path), window.told
    # the project's name, and where its readings came from
    assert _line(window, polygon) == f"job.anglebench.json: {_said(digest, rows)}"
    stored = json.loads(path.read_text(encoding="utf-8"))["workbenches"]["polygon"]
    assert stored["readings_origin"] == {"source": "imported", "name": "bench_run_0512.csv",
                                         "sha256": digest, "edited": True,
                                         "pasted_rows": [5, 6]}
    reopened = recovering_window()
    assert reopened.projects.open_project(path), reopened.told
    again = _polygon(reopened, qtbot)
    assert _line(reopened, again) == f"job.anglebench.json: {_said(digest, rows)}"
    assert TYPED not in _line(reopened, again)
    # a row inserted above the pasted ones moves them (the opened origin is a start)
    again.table_model.insert_rows(0)
    assert "rows 7–8 (2 of" in _line(reopened, again)


def test_a_recovered_autosave_names_the_file_imported_and_the_rows_pasted(
        recovering_window, qtbot, tmp_path, samples_dir):
    window = recovering_window()
    polygon, digest = _imported_edited_pasted_captured(window, qtbot, tmp_path, samples_dir)
    rows = polygon.sheet.row_count
    window.projects.autosave()
    # the window dies (kill -9): its lock goes with the process, the autosave stays
    os.close(window.projects.recovery._lock_fd)
    window.projects.recovery._lock_fd = None
    window.projects.autosave_timer.stop()
    survivor = recovering_window()
    assert survivor.projects.offer_recovery()
    recovered = _polygon(survivor, qtbot)
    assert survivor.projects.path is None
    assert _line(survivor, recovered) == _said(digest, rows)  # not typed


def test_a_project_file_that_does_not_say_names_itself_never_typed(
        recovering_window, qtbot, tmp_path, samples_dir):
    """A file written before the origin was kept: "from project NAME", also once saved
    under another name or as an untitled project's autosave; typed rows saved are typed."""
    window = recovering_window()
    polygon = _polygon(window, qtbot)
    lines = (samples_dir / polygon.kind.sample_file).read_text(encoding="utf-8").splitlines()
    old = tmp_path / "old.anglebench.json"
    old.write_text(json.dumps({
        "format": "anglebench-project", "schema_version": 2, "app_version": "0.8.14",
        "metadata": {}, "workbenches": {"polygon": {
            "rows": [line.split(",") for line in lines[1:]], "settings": {}}}}),
        encoding="utf-8")
    assert window.projects.open_project(old), window.told
    polygon = _polygon(window, qtbot)
    assert _line(window, polygon) == "old.anglebench.json"  # the project's, as it says
    new = tmp_path / "new.anglebench.json"
    assert window.projects.save_to(new), window.told
    assert _line(window, polygon) == "new.anglebench.json: from project old.anglebench.json"
    reopened = recovering_window()
    assert reopened.projects.open_project(new), reopened.told
    assert _line(reopened, _polygon(reopened, qtbot)) == (
        "new.anglebench.json: from project old.anglebench.json")
    # rows typed into a new project, saved and opened again: the project's (as before)
    reopened.projects.new_project()
    typed = _polygon(reopened, qtbot)
    typed.table_model.set_cells([(r, c, polygon.sheet.text(r, c)) for r in range(12)
                                 for c in range(polygon.sheet.column_count)])
    assert _line(reopened, typed) == TYPED
    assert reopened.projects.save_to(tmp_path / "typed.anglebench.json"), reopened.told
    third = recovering_window()
    assert third.projects.open_project(tmp_path / "typed.anglebench.json"), third.told
    assert _line(third, _polygon(third, qtbot)) == "typed.anglebench.json"


def test_the_stored_origin_read_back():
    from models.certificate.readings_origin import FromProject, sheet_source
    from models.certificate.stored_origin import stored_origin

    unknown = stored_origin(None, "")
    assert sheet_source(unknown.origin, False, [], 3) == (
        "from an autosave that does not record their origin")
    # damaged records are an origin not known: the file's, never typed, never a crash
    for record in ("typed", {"source": "typed", "pasted_rows": [-1]},
                   {"source": "imported"}, {"source": "typed", "edited": "yes"},
                   {"source": "comet"}):
        assert stored_origin(record, "p.anglebench.json").origin == FromProject(
            "p.anglebench.json")
    opened = stored_origin({"source": "sent", "workbench": "Polygon encoder test",
                            "origin": "", "edited": False, "pasted_rows": [2, 0]}, "p.json")
    assert sheet_source(opened.origin, opened.edited, [0, 2], 4) == (
        "sent from the Polygon encoder test workbench; rows 1, 3 (2 of 4) pasted into "
        "AngleBench")


def _typing(window, qtbot, presenter, row: int, column: int, text: str):
    """``text`` typed over a cell of ``presenter``'s sheet and not entered (no Return)."""
    window.show()
    table = presenter.view.table
    index = table.model().index(row, column)
    table.setCurrentIndex(index)
    table.edit(index)
    qtbot.waitUntil(lambda: table._typing_delegate.editor is not None, timeout=3000)
    editor = table._typing_delegate.editor
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    assert table.pending_edit() == (row, column, text)
    return table


def test_a_value_being_typed_when_the_window_died_makes_the_recovered_readings_edited(
        recovering_window, qtbot, tmp_path, samples_dir):
    """Day review (stop 65) F1: a file imported, a reading typed over it and not entered,
    kill -9: the recovered sheet holds the typed value, so its certificate must not state
    the file's name and SHA-256 as if the readings were the file's."""
    window = recovering_window()
    polygon = _polygon(window, qtbot)
    csv = tmp_path / "bench_run_0512.csv"
    csv.write_bytes((samples_dir / polygon.kind.sample_file).read_bytes())
    polygon.import_file(csv)
    qtbot.waitUntil(lambda: not polygon.analysis_pending, timeout=20000)
    digest = hashlib.sha256(csv.read_bytes()).hexdigest()
    assert _line(window, polygon) == f"imported from bench_run_0512.csv (SHA-256 {digest})"
    column = polygon.sheet.column_index("ac_x_arcsec")
    typed = "11.50" if polygon.sheet.text(9, column) != "11.50" else "11.60"
    _typing(window, qtbot, polygon, 9, column, typed)
    window.projects.autosave()
    os.close(window.projects.recovery._lock_fd)  # the window dies (kill -9)
    window.projects.recovery._lock_fd = None
    window.projects.autosave_timer.stop()
    survivor = recovering_window()
    assert survivor.projects.offer_recovery()
    recovered = _polygon(survivor, qtbot)
    assert recovered.sheet.text(9, column) == typed
    assert _line(survivor, recovered) == (
        f"imported from bench_run_0512.csv (SHA-256 {digest}), edited in AngleBench")


def test_closing_the_window_enters_what_is_being_typed_and_asks_to_save_it(
        recovering_window, qtbot, tmp_path, samples_dir):
    """Day review (stop 65) F2: a saved project, a reading typed over and not entered, then
    Ctrl+Q: the window closed without asking, its autosave deleted, the file without the
    value typed. It is entered (as Return enters it) and the question about unsaved work is
    asked; answered Cancel, the window stays with the value."""
    window = recovering_window()
    polygon = _polygon(window, qtbot)
    polygon.import_file(samples_dir / polygon.kind.sample_file)
    qtbot.waitUntil(lambda: not polygon.analysis_pending, timeout=20000)
    path = tmp_path / "job.anglebench.json"
    assert window.projects.save_to(path), window.told
    column = polygon.sheet.column_index("ac_x_arcsec")
    before = polygon.sheet.text(9, column)
    typed = "11.50" if before != "11.50" else "11.60"
    _typing(window, qtbot, polygon, 9, column, typed)
    asked = []
    window.projects.view.ask_save_changes = lambda *question: asked.append(question)  # Cancel
    window.close()
    assert asked, "the window closed without asking about the value typed"
    assert window.isVisible()
    assert polygon.sheet.text(9, column) == typed
    assert polygon.view.table.pending_edit() is None
    window.projects.view.ask_save_changes = lambda *question: True  # Save
    window.close()
    assert not window.isVisible()
    from models.project.file import load_project

    assert load_project(path).workbenches["polygon"].rows[9][column] == typed
