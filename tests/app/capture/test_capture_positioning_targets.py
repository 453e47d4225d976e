"""A take on the positioning workbench checked against the plan's target of its row: a
reading nearer another target of the plan (more than half the distance to the
neighbouring target) is warned of, naming the row, the target and the reading, and kept;
a readout's reading of a rotary axis — sent as −0.5 by a ±180° display or as 359.5 by a
0…360° one — is written in the turn of its row's target (the raw record keeps it as
sent), so measured − target is the deviation the axis had, and the cell is "as captured".
The readout is the protocol simulator on TCP."""

from __future__ import annotations

import pytest

from app.certificate_issue import readings_edited_after_capture
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and an instrument: more than 0.4 s

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}


def _plan(window, targets: str, runs: int = 1, directions: str = "both"):
    presenter = _show(window, "positioning")
    presenter.table_model.replace_all([], "empty")
    presenter.set_settings({**presenter.settings, "plan_runs": runs, "plan_targets": targets,
                            "plan_directions": directions, "plan_order": "linear",
                            "target_unit": "deg", "deviation_unit": "arcsec"})
    return presenter


def _text(model, row, key):
    return model.sheet.text(row, [c.key for c in model.sheet.columns].index(key))


def _take(panel, readout, value, qtbot):
    link = panel.links[0]
    readout.positions[0] = (value,)
    qtbot.waitUntil(lambda: link.latest is not None and link.usable
                    and abs(link.latest.values[0] - value) < 6e-6
                    and not panel.used_again(), timeout=3000)
    return panel.take_reading()


def test_a_take_nearer_another_target_than_its_rows_is_warned_of_and_kept(window, qtbot):
    """"next: target 30°, run 1 ↑" and the axis at 45.5°: taken without a word (the
    polygon warned of a take half a pitch from its face; positioning said nothing). More
    than half the 30° to the neighbouring target from the row's target is warned of, the
    reading kept; at the end target read beyond the end, half the gap to its one
    neighbour."""
    presenter = _plan(window, "0:30:3")
    model = presenter.table_model
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(0.0,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        # the cycle 0, 30, 60 ↑, 60, 30, 0 ↓: what the axis read at each
        for row, (target, value, warned) in enumerate((
                ("0", 0.0003, None),
                ("30", 45.5, "Row 2: measured 45.5000° is +15.5000° from target 30°, the "
                             "plan's for this row (more than half the 30° to the "
                             "neighbouring target 60°)"),
                ("60", 60.0002, None),
                ("60", 75.2, "Row 4: measured 75.2000° is +15.2000° from target 60°, the "
                             "plan's for this row (more than half the 30° to the "
                             "neighbouring target 30°)"),
                ("30", 15.1, None),  # 14.9° below 30°: still nearer 30° than 0°
                ("0", -16.0, "Row 6: measured -16.0000° is -16.0000° from target 0°, the "
                             "plan's for this row (more than half the 30° to the "
                             "neighbouring target 30°)"))):
            assert _take(panel, readout, value, qtbot) == f"row {row + 1}"
            assert _text(model, row, "target") == target
            assert float(_text(model, row, "measured")) == pytest.approx(value, abs=1e-9)
            note = panel.take_note.text()
            if warned is None:
                assert note == "", (row, note)
            else:
                assert note == warned + (": check the axis's position. The reading is "
                                         "kept; undo the take if it is wrong"), note
                assert panel.take_note.isVisibleTo(panel)
        panel.disconnect_instrument()
    assert model.sheet.row_count == 6  # every reading kept


def test_a_readouts_reading_is_written_in_its_targets_turn_either_form(window, qtbot):
    """A rotary axis over a full turn (targets 0, 90, …, 360°): run 1 read by a ±180°
    display (−0.0005 at 0°, −89.9997 at 270°, 0.0004 at 360°), run 2 by a 0…360° one
    (359.9996 at 0°). Written as sent, 359.9996 − 0 (and 0.0004 − 360) was a deviation of
    ~360° the analysis refused, and a cell typed in the target's turn was "edited after
    capture". Each is written in its target's turn; the raw record keeps the lines as
    sent; the deviations are the axis's; no cell is said edited."""
    presenter = _plan(window, "0:90:5", runs=2, directions="up")
    model = presenter.table_model
    panel = window.capture_panel
    sent = [-0.0005, 90.0003, -179.9998, -89.9997, 0.0004,        # run 1: ±180° display
            359.9996, 90.0001, 180.0002, 270.0003, 0.0001]        # run 2: 0…360° display
    written = ["-0.0005", "90.0003", "180.0002", "270.0003", "360.0004",
               "-0.0004", "90.0001", "180.0002", "270.0003", "360.0001"]
    with ReadoutSimulator("tcp", positions=[(0.0,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        for row, value in enumerate(sent):
            assert _take(panel, readout, value, qtbot) == f"row {row + 1}"
            assert panel.take_note.text() == "", (row, panel.take_note.text())
        panel.disconnect_instrument()
    assert [_text(model, r, "measured") for r in range(10)] == written
    (session,) = panel.raw_sessions("positioning")
    lines = [session["frames"][t[1]][1] for t in session["takes"]]
    assert [float(line.split()[0]) for line in lines] == pytest.approx(sent, abs=1e-9)
    assert lines[5].startswith("+359.99960")  # the form the readout sent, kept
    assert readings_edited_after_capture(presenter.kind, presenter.settings,
                                         model.sheet.rows, [session]) == []
    assert model.edited_cells == {}
    presenter.refresh()
    assert presenter.problem == "", presenter.problem
    deviations = dict(zip((int(r) for r in presenter.result.rows),
                          presenter.result.deviations, strict=True))
    assert [deviations[r] for r in range(10)] == pytest.approx(
        [-1.8, 1.08, 0.72, 1.08, 1.44, -1.44, 0.36, 0.72, 1.08, 0.36], abs=1e-6)


def test_the_deviation_column_shows_measured_minus_target_as_each_reading_arrives(window,
                                                                                    qtbot):
    """gui77 (live76 F11): in a live run the *measured* cells filled and the *deviation*
    column stayed empty. Each take's row shows measured − target in its deviation cell
    (greyed, said in its tooltip), the figure the analysis takes; the sheet keeps the
    cell blank (nothing is written that an edit of the measured position would contradict),
    and a copy of the row is the sheet's text."""
    from PySide6.QtCore import Qt

    presenter = _plan(window, "0:15:2")
    model = presenter.table_model
    panel = window.capture_panel
    column = [c.key for c in model.sheet.columns].index("deviation")
    with ReadoutSimulator("tcp", positions=[(0.0,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        for row, (value, shown) in enumerate(((0.0003, "1.08"), (15.0, "0"),
                                              (14.9995, "-1.80"))):
            assert _take(panel, readout, value, qtbot) == f"row {row + 1}"
            index = model.index(row, column)
            assert index.data() == shown, (row, index.data())
            assert index.data(Qt.ItemDataRole.EditRole) == ""
            assert _text(model, row, "deviation") == ""
            assert index.data(Qt.ItemDataRole.ForegroundRole) is not None
            assert index.data(Qt.ItemDataRole.ToolTipRole).startswith("measured − target")
        panel.disconnect_instrument()
    # the row waiting for the next reading shows nothing
    assert model.index(3, column).data() == ""
    # an edit of the measured position: the figure shown follows it
    model.setData(model.index(0, column + 1), "0.0006")
    assert model.index(0, column).data() == "2.16"
    # the deviation unit changed: shown in it
    presenter.set_settings({**presenter.settings, "deviation_unit": "urad"})
    assert model.index(0, column).data() == "10.5"
    view = presenter.view.table
    view.selectRow(0)
    assert view.selected_text().split("\t")[column] == ""
