"""A take on the positioning workbench checked against the plan's target of its row: a
reading nearer another target of the plan (more than half the distance to the
neighbouring target) is warned of, naming the row, the target and the reading, and kept.
The readout is the protocol simulator on TCP."""

from __future__ import annotations

import pytest

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

