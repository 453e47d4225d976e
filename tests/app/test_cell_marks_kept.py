"""A readings table's cell marks are saved with the project and come back when it is
opened (gui77 item 4: save, reopen, and the marks were gone): a take's reading at another
target than its row's, marked (orange, what was said in its tooltip) while its cell holds
that text. The file keeps them under the workbench's optional ``cell_marks``; a file
written before (without the key) opens as it did, with no marks."""

from __future__ import annotations

import json

import pytest
from PySide6.QtCore import Qt

from models.project.file import project_from_json
from tests.app.capture.test_capture_positioning_targets import FAST, _plan, _take
from tests.conftest import answered_window, delete_window
from tests.instrument_simulators import ReadoutSimulator
from widgets.readings_table_model import WARNED_BRUSH

pytestmark = pytest.mark.slow  # two windows and an instrument

WARNED = ("Row 2: measured 45.5000° is +15.5000° from target 30°, the plan's for this row "
          "(more than half the 30° to the neighbouring target 60°): check the axis's "
          "position. The reading is kept; undo the take if it is wrong")


def _marked(window, qtbot, tmp_path):
    """Positioning with row 2 taken at 45.5° where the plan says 30° (marked), saved."""
    presenter = _plan(window, "0:30:3")
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(0.0,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        for value in (0.0003, 45.5):
            _take(panel, readout, value, qtbot)
        panel.disconnect_instrument()
    column = [c.key for c in presenter.sheet.columns].index("measured")
    model = presenter.table_model
    assert model.index(1, column).data(Qt.ItemDataRole.ToolTipRole) == WARNED
    path = tmp_path / "marked.anglebench.json"
    assert window.projects.save_to(path)
    return path, column


def _reopened(qtbot, folder, path):
    folder.mkdir()
    other = answered_window(folder)
    assert other.projects.open_project(path)
    return other


def _closed(other) -> None:
    other.projects.autosave_timer.stop()
    other.capture_panel.close()
    other.close()
    delete_window(other)


def _cell(window, row, column, role):
    model = window.presenter("positioning").table_model
    return model.index(row, column).data(role)


def test_a_takes_mark_comes_back_with_the_project(window, qtbot, tmp_path):
    path, column = _marked(window, qtbot, tmp_path)
    kept = json.loads(path.read_text(encoding="utf-8"))["workbenches"]["positioning"]
    (mark,) = kept["cell_marks"]
    assert (mark["row"], mark["column"], mark["text"]) == (2, "measured", "45.5")
    assert mark["note"]["template"].startswith("Row {row}: {column} {value}{unit} is {off}")
    other = _reopened(qtbot, tmp_path / "other", path)
    try:
        assert _cell(other, 1, column, Qt.ItemDataRole.ToolTipRole) == WARNED
        assert _cell(other, 1, column, Qt.ItemDataRole.BackgroundRole) == WARNED_BRUSH
        assert _cell(other, 0, column, Qt.ItemDataRole.BackgroundRole) is None
        # said in the language of the window that shows it
        action = next(a for a in other.menus.language_actions.actions()
                      if a.data() == "zh_CN")
        action.trigger()
        chinese = _cell(other, 1, column, Qt.ItemDataRole.ToolTipRole)
        assert chinese != WARNED and "45.5000" in chinese and "check" not in chinese, chinese
        next(a for a in other.menus.language_actions.actions() if a.data() == "en").trigger()
        # the cell retyped: the mark goes, and is not saved again
        other.presenter("positioning").table_model.setData(
            other.presenter("positioning").table_model.index(1, column), "30.0002")
        assert _cell(other, 1, column, Qt.ItemDataRole.BackgroundRole) != WARNED_BRUSH
        assert _cell(other, 1, column, Qt.ItemDataRole.ToolTipRole) != WARNED
        assert other.presenter("positioning").state().marks == []
    finally:
        _closed(other)


def test_a_file_written_before_the_marks_were_kept_opens_without_them(window, qtbot,
                                                                      tmp_path):
    path, column = _marked(window, qtbot, tmp_path)
    document = json.loads(path.read_text(encoding="utf-8"))
    del document["workbenches"]["positioning"]["cell_marks"]
    old = tmp_path / "old.anglebench.json"
    old.write_text(json.dumps(document), encoding="utf-8")
    other = _reopened(qtbot, tmp_path / "other", old)
    try:
        presenter = other.presenter("positioning")
        assert presenter.sheet.row_count == 3  # the plan's next row pre-filled, as saved
        assert presenter.sheet.text(1, column) == "45.5"
        assert _cell(other, 1, column, Qt.ItemDataRole.BackgroundRole) is None
        assert presenter.table_model.take_warnings == {}
    finally:
        _closed(other)


def test_marks_that_cannot_be_read_are_left_out_never_the_project():
    document = {"format": "anglebench-project", "schema_version": 2, "workbenches": {
        "positioning": {"rows": [["0", "1", "+", "", "0.0003"]], "settings": {},
                        "cell_marks": [{"row": 1, "column": "measured", "text": "0.0003",
                                        "note": {"template": "far {x}", "figures": {"x": "1"}}},
                                       {"row": 0, "column": "measured", "text": "", "note": ""},
                                       {"row": 1, "column": "measured", "text": "0.0003",
                                        "note": {"template": "{missing}", "figures": {"x": "1"}}},
                                       "junk"]}}}
    from models.project.cell_marks import marks_from_json

    project = project_from_json(json.dumps(document))
    (mark,) = marks_from_json(project.workbenches["positioning"].marks)
    assert mark[:3] == (0, "measured", "0.0003") and mark[3] == "far 1"
    document["workbenches"]["positioning"]["cell_marks"] = "not a list"
    assert project_from_json(json.dumps(document)).workbenches["positioning"].marks == []
