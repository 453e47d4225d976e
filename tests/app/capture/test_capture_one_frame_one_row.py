"""#60 review: F9 pressed twice between two replies of a slow theodolite (a reply every
0.5 s) filled two rows from the same frame (takes [[0, 0, 0], [1, 0, 0]]): with n
readings per point, a reading repeated as if independent. The second take is refused,
saying why; the next frame is taken."""

from __future__ import annotations

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import TheodoliteSimulator

pytestmark = pytest.mark.slow  # a window and an instrument: more than 0.4 s


def test_one_frame_never_fills_two_rows(window, qtbot):
    presenter = _show(window, "theodolite")
    model = presenter.table_model
    model.replace_all([], "empty")
    keys = [c.key for c in model.sheet.columns]
    presenter.view.table.setCurrentIndex(model.index(0, keys.index("azimuth_deg")))
    panel = window.capture_panel
    with TheodoliteSimulator("pty", positions=[(33.5, 90.25)], reply_delay_s=0.5,
                             sigma=0.5) as sim:
        panel.connect_to("theodolite", sim.port, silence_s=2.0)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=5000)
        frame = panel.latest.frame
        # twice with no event between: the panel has no newer frame for the second
        assert panel.take_reading() == "row 1"
        assert panel.take_reading() == ""
        note = panel.take_note.text()
        qtbot.waitUntil(lambda: panel.latest.frame > frame, timeout=5000)
        assert panel.take_reading() == "row 2"
        assert panel.take_note.text() == ""
        panel.disconnect_instrument()
    assert note == f"Not taken: no new reading from Theodolite (Leica GeoCOM) on {sim.port} " \
        "since the last take"
    takes = panel.raw_sessions("theodolite")[-1]["takes"]
    assert [t[0] for t in takes] == [0, 1]
    assert takes[0][1] == takes[0][2] == frame < takes[1][1] == takes[1][2]
