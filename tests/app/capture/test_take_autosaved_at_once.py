"""hostile77 M2: a reading taken in the window waited for the autosave's few seconds (3 s
after the first edit of a burst); a window killed in between lost it, where `anglebench
capture` syncs each reading to its journal before it counts as taken. A take is now
autosaved at once. The reading comes from the readout's protocol simulator; the kill is the
window's autosave left behind with its lock released, as kill -9 leaves it."""

from __future__ import annotations

import os

import pytest

from tests.app.capture.window_steps import planned_positioning
from tests.instrument_simulators import ReadoutSimulator

pytestmark = pytest.mark.slow  # two windows and an instrument

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}
CAPTURED = 15.01401  # where the readout stands at the take (degrees)


def test_a_take_survives_a_kill_right_after_it(recovering_window, qtbot):
    window = recovering_window()
    window.show()
    bench = planned_positioning(window)
    measured = [c.key for c in bench.sheet.columns].index("measured")
    projects = window.projects
    projects.autosave()  # the empty sheet, as an earlier autosave left it
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(CAPTURED,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        qtbot.waitUntil(lambda: link.latest is not None and link.usable
                        and abs(link.latest.values[0] - CAPTURED) < 6e-6, timeout=3000)
        assert panel.take_reading() == "row 1"
        # the window dies (kill -9) at once: no timer fires again, the lock goes with it
        projects.autosave_timer.stop()
        os.close(projects.recovery._lock_fd)
        projects.recovery._lock_fd = None
        panel.disconnect_instrument()
    assert float(bench.sheet.text(0, measured)) == pytest.approx(CAPTURED, abs=1e-9)

    survivor = recovering_window()
    assert survivor.projects.offer_recovery()
    recovered = survivor.presenter("positioning")
    assert float(recovered.sheet.text(0, measured)) == pytest.approx(CAPTURED, abs=1e-9)
