"""Without an entry plan, a captured row in the middle whose reading the user cleared (a take
thrown away) is the row the next take goes to, and waits for it (day review 64 P4):

* it is no bad row: no "cannot be read" in the result strip, no "bad cell" in the caption,
  and the rest of the readings still give a result;
* the guidance names that row's face, and the take goes there — also after a click on
  another (filled) row — with no warning of a wrong face.

Through the real window: the autocollimator and readout simulators, the polygon workbench
with no entry plan, the table's Clear cells (Delete), a click in the table, F9."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.app.capture.test_capture_marks import _connect, _take_at
from tests.app.capture.test_takes_superseded import _clear
from tests.app.capture.test_takes_undone import X, Y
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds

#: a 4-face polygon: set 1 (its closure at face 1 again) and set 2 in progress (faces 1 to
#: 3); per take the encoder (readout) and the autocollimator's x and y
TAKES = [(0.00004, 0.5, 0.25), (90.00001, 0.75, 0.5), (180.00002, 1.25, 0.75),
         (270.00001, -0.5, 1.0), (0.00005, 0.55, 0.3),
         (0.00003, 0.45, 0.2), (90.00002, 0.7, 0.55), (180.00001, 1.2, 0.7)]
CLEARED = 6  # set 2's face 2 (row 7)


@pytest.fixture
def unplanned(window):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": 4, "plan_sets": 0})
    bench.undo_stack.clear()
    assert bench.entry_plan() is None  # "next pos +" off: no entry plan
    yield bench
    window.capture_panel.close()


def test_a_cleared_middle_row_without_a_plan_waits_for_its_take(window, qtbot, unplanned):
    from widgets.readings_table_model import INVALID_BRUSH

    bench, model = unplanned, unplanned.table_model
    panel, view, table = window.capture_panel, unplanned.view, unplanned.view.table
    columns = [c.key for c in model.sheet.columns]

    def analysed():
        with qtbot.waitSignal(bench.analysed, timeout=5000):
            bench.refresh()
        return view.warnings.text(), view.readings_label.text()

    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(0.00004,)]) as ro:
        _connect(panel, ac, ro)
        for row, values in enumerate(TAKES):
            assert _take_at(qtbot, panel, ac, ro, *values) == f"row {row + 1}"
        # the polygon's certificate typed for faces 1 to 4
        dev = columns.index("polygon_dev_arcsec")
        position = columns.index("position")
        model.set_cells([(r, dev, f"0.{model.sheet.text(r, position)}")
                         for r in range(len(TAKES))], "typed")
        warnings, caption = analysed()
        assert bench.result is not None and "cannot be read" not in warnings, warnings
        # set 2's face 2 thrown away: its encoder and autocollimator cells cleared
        _clear(bench, CLEARED, ["encoder_deg", X, Y])
        warnings, caption = analysed()  # while capturing: on a worker
        # was: "3 cell(s) cannot be read (row 2); those rows are left out", no result
        assert "cannot be read" not in warnings, warnings
        assert "bad cell" not in caption, caption
        assert "row 7 waits for its reading" in warnings, warnings
        assert bench.result is not None, warnings  # the other faces still give one
        for key in ("encoder_deg", X, Y):  # its blank cells are not red
            index = model.index(CLEARED, columns.index(key))
            assert model.data(index, Qt.ItemDataRole.BackgroundRole) is not INVALID_BRUSH, key
        # a click on another, filled row: the guidance and the take stay with row 7
        click = table.visualRect(model.index(7, columns.index(X))).center()
        qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=click)
        assert table.currentIndex().row() == 7
        assert "face 2" in panel.guide.text(), panel.guide.text()
        assert panel.target_row() == CLEARED
        assert "cannot be read" not in analysed()[0]
        # the take at face 2, as the guidance says: into row 7, no warning of a wrong face
        assert _take_at(qtbot, panel, ac, ro, 90.00003, 0.7, 0.45) == "row 7"
        assert panel.take_note.text() == "", panel.take_note.text()
        assert model.sheet.text(CLEARED, columns.index("encoder_deg")).startswith("90.0000")
        assert model.sheet.row_count == len(TAKES)
        warnings, caption = analysed()
        assert "cannot be read" not in warnings and "waits for its reading" not in warnings, warnings
        assert bench.result is not None
        panel.disconnect_instrument()
