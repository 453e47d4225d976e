"""What the readings table and the certificate say of a captured reading thrown away: its
cells cleared, or its take undone, and the position taken again.

* A captured cell cleared by the user is marked "edited after capture" (orange, the edit
  in its tooltip), not red as a cell that cannot be read.
* A row cleared in the middle of the table, to which the entry plan sends the next take,
  waits for its reading: it is not a bad row in the result strip or the readings caption.
* A take undone (Edit › Undo) and the position taken again into the same row is said as a
  row whose cells were cleared and taken again: "captured again", once (it was silent,
  though the raw record holds both takes for that row).

Through the real window: the autocollimator and readout simulators, the polygon's entry
plan, the table's Clear cells, Edit › Undo and Redo."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.app.capture.test_takes_superseded import AGAIN, _clear, _wait_for
from tests.app.capture.test_takes_undone import FAST, X, Y, _said
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds

#: per face of set 1: the encoder (readout) and the autocollimator's x and y
FACES = [(0.00004, 0.5, 0.25), (30.00001, 0.75, 0.5), (60.00002, 1.25, 0.75),
         (90.00001, -0.5, 1.0)]


@pytest.fixture
def planned(window):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": 12, "plan_sets": 2})
    bench.undo_stack.clear()
    yield bench
    window.capture_panel.close()


def _connect(panel, ac, ro):
    panel.connect_to("autocollimator", ac.port, **FAST)
    panel.connect_to("readout", ro.port, slot=1, **FAST)
    readout = panel.links[1]
    readout.column.setCurrentIndex(readout.column.findData("encoder_deg"))
    return readout


def _take_at(qtbot, panel, ac, ro, encoder, x, y) -> str:
    """The table at ``encoder`` with the autocollimator at ``x``, ``y``: F9."""
    ac.positions[0], ro.positions[0] = (x, y), (encoder,)
    _wait_for(qtbot, panel.links[0], (x, y))
    _wait_for(qtbot, panel.links[1], (encoder,))
    qtbot.waitUntil(lambda: not panel.used_again(), timeout=5000)
    return panel.take_reading()


def _stored(panel) -> list[list]:
    """Per instrument, its takes' rows as stored ('s' beside a superseded one's -1)."""
    return [[f"{t[0]}s" if len(t) > 3 else t[0] for t in s["takes"]]
            for s in panel.raw_sessions("polygon")]


def test_a_cleared_captured_cell_is_marked_edited_not_red(window, qtbot, planned):
    from widgets.readings_table_model import EDITED_BRUSH, INVALID_BRUSH

    bench, model = planned, planned.table_model
    panel = window.capture_panel
    columns = [c.key for c in model.sheet.columns]
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(0.00004,)]) as ro:
        _connect(panel, ac, ro)
        for face, values in enumerate(FACES):
            assert _take_at(qtbot, panel, ac, ro, *values) == f"row {face + 1}"
        panel.disconnect_instrument()
    # row 2's autocollimator reading cleared (its encoder kept): an edit of row 2
    _clear(bench, 1, [X, Y])
    assert _said(window, bench) == ["reading of row 2 cleared after capture: 0.75",
                                    "reading of row 2 cleared after capture: 0.5"]
    for key in (X, Y):
        index = model.index(1, columns.index(key))
        brush = model.data(index, Qt.ItemDataRole.BackgroundRole)
        assert brush is EDITED_BRUSH, key  # was INVALID_BRUSH: "cannot be read"
        assert "cleared after capture" in model.data(index, Qt.ItemDataRole.ToolTipRole)
    # a cell typed that cannot be read stays red, a captured one included
    model.setData(model.index(2, columns.index(X)), "1.2x")
    index = model.index(2, columns.index(X))
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is INVALID_BRUSH
    # a blank cell of a typed row, never captured, is still one that cannot be read
    model.set_cells([(4, columns.index("position"), "5"), (4, columns.index("set"), "1"),
                     (4, columns.index("encoder_deg"), "120"),
                     (5, columns.index("position"), "6"), (5, columns.index("set"), "1"),
                     (5, columns.index("encoder_deg"), "150"), (5, columns.index(X), "0.1"),
                     (5, columns.index(Y), "0.1")], "typed")
    index = model.index(4, columns.index(X))
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is INVALID_BRUSH


def test_a_cleared_row_the_plan_fills_next_is_not_a_bad_row(window, qtbot, planned):
    bench, model = planned, planned.table_model
    panel = window.capture_panel
    view = bench.view
    columns = [c.key for c in model.sheet.columns]

    def analysed():
        with qtbot.waitSignal(bench.analysed, timeout=5000):
            bench.refresh()
        return view.warnings.text(), view.readings_label.text()

    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(0.00004,)]) as ro:
        _connect(panel, ac, ro)
        for face, values in enumerate(FACES):
            assert _take_at(qtbot, panel, ac, ro, *values) == f"row {face + 1}"
        # the polygon's certificate typed for faces 1 to 4
        dev = columns.index("polygon_dev_arcsec")
        model.set_cells([(r, dev, f"0.{r + 1}") for r in range(4)], "typed")
        assert "cannot be read" not in analysed()[0]
        # face 2 thrown away: its reading cleared, the plan's cells kept
        _clear(bench, 1, ["encoder_deg", X, Y])
        assert bench.plan_placement().row == 1  # the plan sends the next take there
        warnings, caption = analysed()  # while capturing: on a worker
        # was: "2 cell(s) cannot be read (row 2)" and ", 2 bad cell(s)"
        assert "cannot be read" not in warnings, warnings
        assert "bad cell" not in caption, caption
        assert "— 3 used" in caption, caption
        panel.disconnect_instrument()
    warnings, caption = analysed()  # on the GUI thread
    assert "cannot be read" not in warnings and "bad cell" not in caption, (warnings, caption)
    # the row's blank cells wait: none red (the captured ones are marked cleared)
    from widgets.readings_table_model import INVALID_BRUSH
    for key in ("encoder_deg", X, Y, "polygon_dev_arcsec"):
        index = model.index(1, columns.index(key))
        assert model.data(index, Qt.ItemDataRole.BackgroundRole) is not INVALID_BRUSH, key
    # a cell typed in it that cannot be read is still said
    model.setData(model.index(1, columns.index(X)), "0.7x")
    warnings, caption = analysed()
    assert "cannot be read (row 2)" in warnings, warnings
    model.setData(model.index(1, columns.index(X)), "")
    # a row cleared that the plan does not fill next (face 2 is still waiting) is bad
    _clear(bench, 2, ["encoder_deg", X, Y])
    assert bench.plan_placement().row == 1
    warnings, caption = analysed()
    assert "cannot be read (row 3)" in warnings, warnings  # row 3 alone, not "row 2, 3"
    assert "row 2 waits for its reading" in warnings, warnings



def test_an_undone_take_taken_again_is_said_as_a_cleared_one(window, qtbot, planned):
    bench, model = planned, planned.table_model
    panel = window.capture_panel
    undo, redo = window.menus.undo_action, window.menus.redo_action
    columns = [c.key for c in model.sheet.columns]
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(0.00004,)]) as ro:
        _connect(panel, ac, ro)
        for face, values in enumerate(FACES[:2]):
            assert _take_at(qtbot, panel, ac, ro, *values) == f"row {face + 1}"
        # face 3 taken with the table at face 4, and thrown away by clearing its cells
        assert _take_at(qtbot, panel, ac, ro, *FACES[3]) == "row 3"
        _clear(bench, 2, ["encoder_deg", X, Y])
        assert _take_at(qtbot, panel, ac, ro, *FACES[2]) == "row 3"
        cleared_then_taken = _said(window, bench)
        assert cleared_then_taken == [AGAIN.format(row=3)]
        assert _stored(panel) == [[0, 1, "-1s", 2]] * 2

        # the same throw-away by Edit › Undo of the take, on face 4
        assert _take_at(qtbot, panel, ac, ro, 120.00002, -1.5, 0.5) == "row 4"
        undo.trigger()
        assert model.sheet.text(3, columns.index(X)) == ""
        assert _said(window, bench) == cleared_then_taken  # the undone take claims no row
        assert _stored(panel) == [[0, 1, "-1s", 2, -1]] * 2
        assert _take_at(qtbot, panel, ac, ro, *FACES[3]) == "row 4"
        assert model.sheet.text(3, columns.index(X)) == "-0.50"
        # was: silent, the undone take's frames in the raw record claimed by no word
        assert _said(window, bench) == [AGAIN.format(row=3), AGAIN.format(row=4)]
        assert _stored(panel) == [[0, 1, "-1s", 2, "-1s", 3]] * 2
        sessions = {s["instrument"]: s for s in panel.raw_sessions("polygon")}
        for instrument, session in sessions.items():
            newer = [instrument, session["port"], session["started_utc"],
                     *session["takes"][5][1:]]
            assert session["takes"][4][3] == newer, instrument
        assert model.edited_cells == {}

        # Edit › Undo of the new take: the older one is undone again (no row, nothing said);
        # Redo: captured again
        undo.trigger()
        assert _said(window, bench) == [AGAIN.format(row=3)]
        assert _stored(panel) == [[0, 1, "-1s", 2, -1, -1]] * 2
        redo.trigger()
        assert _said(window, bench) == [AGAIN.format(row=3), AGAIN.format(row=4)]
        assert _stored(panel) == [[0, 1, "-1s", 2, "-1s", 3]] * 2
        panel.disconnect_instrument()


def test_an_undone_take_follows_its_row_and_supersedes_only_a_take_into_it(window, qtbot,
                                                                           planned):
    """The row an undone take was in moves with the rows inserted above it; a take into it
    there is said captured again. Its row deleted, a take into the row that has its number
    now is a first take."""
    bench, model = planned, planned.table_model
    panel = window.capture_panel
    undo = window.menus.undo_action
    columns = [c.key for c in model.sheet.columns]
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(0.00004,)]) as ro:
        _connect(panel, ac, ro)
        for face, values in enumerate(FACES[:2]):
            assert _take_at(qtbot, panel, ac, ro, *values) == f"row {face + 1}"
        undo.trigger()  # the take of row 2 (face 2)
        # a row typed above: face 2's row is row 3 now, and the take goes there
        model.insert_rows(0, 1)
        model.set_cells([(0, columns.index(X), "0.1"), (0, columns.index(Y), "0.1")], "typed")
        assert _take_at(qtbot, panel, ac, ro, *FACES[1]) == "row 3"
        assert _said(window, bench) == [AGAIN.format(row=3)]
        undo.trigger()  # the take again: both takes undone, of row 3
        assert _said(window, bench) == []
        model.remove_rows([2])  # face 2's row deleted: the plan appends it as row 3
        assert bench.plan_placement().row == 2
        assert _take_at(qtbot, panel, ac, ro, *FACES[1]) == "row 3"
        assert _said(window, bench) == []
        assert _stored(panel) == [[1, -1, -1, 2]] * 2
        panel.disconnect_instrument()
