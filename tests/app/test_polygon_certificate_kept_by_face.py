"""A polygon certificate loaded before the faces have rows is kept by face (live78 F1,
173bc541: each face taken gets its deviation). gui78: a row TYPED by hand after it (the face
and its reading, or the reading with the entry plan's face) got no deviation — red, "cannot
be read", no result — and the kept deviations were not saved with the project: saved before
the first take, closed and reopened, the certificate had to be loaded again. They are now
filled into typed rows as into taken ones, and kept in the project file
(``certificate_by_face``, optional: a file written before it still opens, keeping none)."""

from __future__ import annotations

import json

import pytest

from models.project.file import Project, WorkbenchState, project_from_json, project_to_json
from tests.app.capture.window_steps import show_workbench as _show
from tests.conftest import answered_window, delete_window

#: the polygon's 6 face deviations (″)
DEVIATIONS = [0.1, 0.2, 0.3, 0.0, -0.2, -0.1]
#: per face: encoder (°) — 60° a face, a little off
ENCODER = [10.0, 70.0004, 130.0002, 189.9999, 250.0001, 310.0003]


def polygon_certificate_file(folder):
    """The polygon's certificate in ``folder``: its 6 faces' deviations (″) by position."""
    path = folder / "polygon6_certificate.csv"
    path.write_text("position,deviation_arcsec\n" + "".join(
        f"{face},{value:g}\n" for face, value in enumerate(DEVIATIONS, start=1)))
    return path


@pytest.fixture
def certificate(tmp_path):
    return polygon_certificate_file(tmp_path)


def _empty_polygon(window):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": 6, "plan_sets": 1})
    bench.mark_saved()
    return bench


def _col(bench, key: str) -> int:
    return bench.sheet.column_index(key)


def _type(bench, row: int, key: str, text: str) -> None:
    """A cell typed and entered, as the table's editor does it (the same text again: no
    edit, as the editor's)."""
    model = bench.table_model
    model.setData(model.index(row, _col(bench, key)), text)
    assert bench.sheet.text(row, _col(bench, key)) == text


def test_rows_typed_after_the_certificate_get_their_face_s_deviation(window, qtbot,
                                                                    certificate):
    bench = _empty_polygon(window)
    assert bench.load_certificate(str(certificate)) == 0  # no row yet
    dev = _col(bench, "polygon_dev_arcsec")
    # face 1: the reading typed, Return: the plan gives the row its face, and the deviation
    _type(bench, 0, "encoder_deg", f"{ENCODER[0]}")
    bench.plan_return(0)
    assert bench.sheet.text(0, _col(bench, "position")) == "1"
    assert bench.sheet.text(0, dev) == "0.1"
    _type(bench, 0, "ac_x_arcsec", "0.5")
    # faces 2…6 typed by hand: the face, then the reading
    for face in range(2, 7):
        row = face - 1
        _type(bench, row, "position", str(face))
        assert bench.sheet.text(row, dev) == ""  # no reading yet: nothing brought
        _type(bench, row, "encoder_deg", f"{ENCODER[row]}")
        assert bench.sheet.text(row, dev) == f"{DEVIATIONS[row]:g}", face
        _type(bench, row, "ac_x_arcsec", "0.5")
    qtbot.waitUntil(lambda: not bench.analysis_pending and bench.parsed is not None
                    and bench.parsed.n == 6, timeout=5000)
    assert not bench.parsed.errors  # no red row
    xs, _ = bench.view.error_plot.raw_curve.getData()
    assert xs is not None and len(xs) == 6
    # one edit, one undo: the reading and the deviation it brought go together
    bench.undo_stack.undo()  # the AC x of row 6
    bench.undo_stack.undo()
    assert bench.sheet.text(5, _col(bench, "encoder_deg")) == ""
    assert bench.sheet.text(5, dev) == ""
    # a deviation cleared by hand stays cleared; another row of the face gives its own
    _type(bench, 5, "encoder_deg", "310.0003")
    _type(bench, 5, "polygon_dev_arcsec", "")
    assert bench.sheet.text(5, dev) == ""
    _type(bench, 2, "polygon_dev_arcsec", "0.35")  # face 3's deviation corrected by hand
    _type(bench, 6, "position", "3")
    _type(bench, 6, "encoder_deg", "130.0001")
    assert bench.sheet.text(6, dev) == "0.35"


def test_the_kept_deviations_are_saved_with_the_project(window, qtbot, tmp_path, certificate):
    bench = _empty_polygon(window)
    assert not bench.is_modified
    bench.load_certificate(str(certificate))
    assert bench.is_modified  # the project changed: closing asks, the autosave keeps it
    path = tmp_path / "before_the_run.anglebench.json"
    assert window.projects.save_to(path)
    kept = json.loads(path.read_text(encoding="utf-8"))["workbenches"]["polygon"]
    assert kept["certificate_by_face"] == {"1": "0.1", "2": "0.2", "3": "0.3", "4": "0",
                                           "5": "-0.2", "6": "-0.1"}
    folder = tmp_path / "reopened"
    folder.mkdir()
    other = answered_window(folder)
    try:
        assert other.projects.open_project(path)
        again = _show(other, "polygon")
        assert again.face_deviations[5] == "-0.2"
        assert not again.is_modified
        _type(again, 0, "position", "5")
        _type(again, 0, "encoder_deg", "250.0001")
        assert again.sheet.text(0, _col(again, "polygon_dev_arcsec")) == "-0.2"
        other.menus.new_action.trigger()  # a new project keeps none
        assert again.face_deviations == {}
    finally:
        other.projects.autosave_timer.stop()
        other.close()
        delete_window(other)
    # the certificate's load undone: none kept, none saved
    bench.undo_stack.undo()
    assert bench.face_deviations == {}
    assert window.projects.save_to(path)
    assert "certificate_by_face" not in json.loads(
        path.read_text(encoding="utf-8"))["workbenches"]["polygon"]


def test_a_project_written_before_the_key_opens_keeping_none(window, tmp_path):
    """An older file (no ``certificate_by_face``) opens as it did; entries that are not a
    face and a deviation are left out, never a refused project."""
    older = tmp_path / "older.anglebench.json"
    text = project_to_json(Project({"polygon": WorkbenchState(
        [["1", "10.0", "0.1"]], {"faces": 6})}))
    assert "certificate_by_face" not in text
    older.write_text(text, encoding="utf-8")
    assert window.projects.open_project(older)
    bench = _show(window, "polygon")
    assert bench.face_deviations == {}
    assert bench.sheet.text(0, _col(bench, "position")) == "1"
    document = json.loads(text)
    document["workbenches"]["polygon"]["certificate_by_face"] = {
        "2": "0.2", "x": "1", "0": "0.5", "3": 0.3, "4": " -0.1 "}
    read = project_from_json(json.dumps(document))
    assert read.workbenches["polygon"].certificate_by_face == {2: "0.2", 4: "-0.1"}
    assert project_from_json(project_to_json(read)).workbenches["polygon"] \
        .certificate_by_face == {2: "0.2", 4: "-0.1"}
