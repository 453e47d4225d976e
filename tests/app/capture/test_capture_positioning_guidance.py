"""Day review 74 F6: positioning with a test plan gave no guidance in the instrument panel
(its guidance line stayed empty for the whole run while the table's caption said "next:
target 0°, run 2 ↑"). Now it names the plan's next target, run and direction from the
moment the readout is connected, follows the ISO 230-2 cycle take after take, and says
*Entry plan complete* at its end — as the polygon's and the theodolite's do. The readout is
the protocol simulator on TCP, moved to each target before its take."""

from __future__ import annotations

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and an instrument: more than 0.4 s

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}


def _cycle(targets, runs, both):
    """ISO 230-2's linear test cycle: (target, run, arrow) of every approach."""
    out = []
    for run in range(1, runs + 1):
        out += [(t, run, "↑") for t in targets]
        if both:
            out += [(t, run, "↓") for t in reversed(targets)]
    return out


@pytest.mark.parametrize("directions, both", [("both", True), ("up", False)])
def test_the_panel_names_the_plans_next_target_run_and_direction(window, qtbot, directions,
                                                                 both):
    presenter = _show(window, "positioning")
    presenter.table_model.replace_all([], "empty")
    presenter.set_settings({**presenter.settings, "plan_runs": 2, "plan_targets": "0:15:3",
                            "plan_directions": directions, "plan_order": "linear",
                            "target_unit": "deg", "deviation_unit": "arcsec"})
    expected = _cycle([0, 15, 30], 2, both)
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(0.0,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        qtbot.waitUntil(lambda: panel.guide.text() != "", timeout=3000)
        for target, run, arrow in expected:
            assert panel.guide.text() == f"Next: target {target}°, run {run} {arrow}"
            readout.positions[0] = (target + 0.0002,)
            qtbot.waitUntil(lambda t=target: link.latest is not None and link.usable
                            and abs(link.latest.values[0] - t - 0.0002) < 6e-6
                            and not panel.used_again(), timeout=3000)
            panel.take_reading()
            panel.update_guide()
        assert panel.guide.text() == (f"Entry plan complete ({len(expected)} points): a "
                                      "further take is added after it")
        panel.disconnect_instrument()
    sheet = presenter.table_model.sheet
    keys = [c.key for c in sheet.columns]
    assert [float(sheet.text(r, keys.index("target"))) for r in range(len(expected))] == \
        [float(t) for t, _, _ in expected]


def test_without_a_plan_the_panel_asks_for_the_target_then_names_the_one_typed(window,
                                                                               qtbot):
    presenter = _show(window, "positioning")
    model = presenter.table_model
    model.replace_all([], "empty")
    presenter.set_settings({**presenter.settings, "plan_runs": 0})
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(0.0,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        qtbot.waitUntil(lambda: panel.guide.text() != "", timeout=3000)
        assert panel.guide.text() == ("Next: move the axis to the next target and type it in "
                                      "the target column")
        keys = [c.key for c in model.sheet.columns]
        model.set_cells([(0, keys.index("target"), "45")])
        panel.update_guide()
        assert panel.guide.text() == "Next: target 45°"
        panel.disconnect_instrument()
