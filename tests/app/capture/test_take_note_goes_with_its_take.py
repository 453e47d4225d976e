"""The red take note goes with its take (live78): after Edit › Undo of a take at another
face's place — "Row 2: encoder a [deg] 60.0000° is +30.0° from the ≈ 30° the plan expects
at face 2 … The reading is kept; undo the take if it is wrong" — the note stayed in red
over the emptied row, telling of a reading no longer there, until the next take.
Through the window: the autocollimator and readout simulators, the polygon's entry plan,
Edit › Undo."""

from __future__ import annotations

import pytest

from tests.app.capture.test_capture_marks import _connect, _take_at
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds


def test_the_take_note_goes_when_its_take_is_undone(window, qtbot):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": 12, "plan_sets": 2})
    bench.undo_stack.clear()
    panel, model = window.capture_panel, bench.table_model
    encoder = [c.key for c in model.sheet.columns].index("encoder_deg")
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(0.0,)]) as ro:
        _connect(panel, ac, ro)
        assert _take_at(qtbot, panel, ac, ro, 0.0001, 0.5, 0.25) == "row 1"
        assert panel.take_note.text() == ""
        # face 2 taken with the table at face 3's place
        assert _take_at(qtbot, panel, ac, ro, 60.0, 0.75, 0.5) == "row 2"
        note = panel.take_note.text()
        assert note.startswith("Row 2: encoder a [deg] 60.0000° is +30.0° from the ≈ 30°"), note
        assert panel.take_note.isVisibleTo(panel)
        window.menus.undo_action.trigger()  # Edit › Undo: the take goes
        assert model.sheet.row_count < 2 or model.sheet.text(1, encoder) == ""
        assert panel.take_note.text() == ""
        assert not panel.take_note.isVisibleTo(panel)
        # taken again at its place: nothing to say
        assert _take_at(qtbot, panel, ac, ro, 30.0002, 0.75, 0.5) == "row 2"
        assert panel.take_note.text() == ""
        panel.disconnect_instrument()
