"""Auto-take's window means what its field says for every instrument (day review 74 F1):
a readout sending degrees is gated in arcseconds, as a theodolite is. A readout drifting
0.01°/s (36″/s) was taken as stable at a window of 0.5 ″ — applied as 0.5° — and the
drift entered the sheet as deviations; now it is never taken, and a steady readout is. A
readout in another unit is gated in that unit, and the window's field says so. The
readout is the protocol simulator on TCP, its drift in its own unit (degrees) a second."""

from __future__ import annotations

import time

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and an instrument: more than 0.4 s

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}

#: 36″ a second, in the readout's degrees
DRIFT_DEG_PER_S = 36.0 / 3600.0


def _positioning(window):
    presenter = _show(window, "positioning")
    presenter.table_model.replace_all([], "empty")
    presenter.set_settings({**presenter.settings, "plan_runs": 1, "plan_targets": "0:15:4",
                            "plan_directions": "up", "plan_order": "linear",
                            "target_unit": "deg", "deviation_unit": "arcsec"})
    return presenter


def _auto(panel, readout, qtbot, window_value=0.5, dwell_s=0.3):
    panel.connect_to("readout", readout.port, **FAST)
    link = panel.links[0]
    link.column.setCurrentIndex(link.column.findData("measured"))
    qtbot.waitUntil(lambda: link.latest is not None and link.usable, timeout=3000)
    panel.window_box.setValue(window_value)
    panel.dwell_box.setValue(dwell_s)
    panel.auto.setChecked(True)
    return link


def test_a_readout_drifting_36_arcsec_a_second_is_never_taken_at_half_an_arcsecond(window,
                                                                                   qtbot):
    _positioning(window)
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(15.0,)], drift_per_s=DRIFT_DEG_PER_S) as readout:
        _auto(panel, readout, qtbot)
        end = time.monotonic() + 3.0  # ten dwells of 0.3 s: 10.8″ moved in each
        while time.monotonic() < end:
            qtbot.wait(50)
        assert panel.taken == []
        assert panel.window_box.suffix() == ' "'
        # the spread shown is in the window's unit and says why it waits: 36″ over a second
        assert panel.stability.text().endswith('"')
        shown = float(panel.stability.text().split(":")[1].strip().rstrip('"'))
        assert 30.0 < shown < 42.0
        # and why it waits: the output moving at 36″ a second, not a window to widen (a
        # wider window would take the drift as stable)
        said = panel.auto_state.text()
        assert "the output is moving (+36\" a second)" in said, said
        assert "widen" not in said
        panel.disconnect_instrument()


def test_a_steady_readout_is_taken_at_half_an_arcsecond(window, qtbot):
    presenter = _positioning(window)
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(0.00004,)], sigma=0.02 / 3600.0) as readout:
        _auto(panel, readout, qtbot)
        qtbot.waitUntil(lambda: len(panel.taken) >= 1, timeout=5000)
        panel.disconnect_instrument()
    keys = [c.key for c in presenter.table_model.sheet.columns]
    measured = float(presenter.table_model.sheet.text(0, keys.index("measured")))
    assert measured == pytest.approx(0.00004, abs=0.5 / 3600.0)


def test_a_readout_in_millimetres_is_gated_in_millimetres_and_the_window_says_so(window,
                                                                               qtbot):
    """A 0.5 window on a readout in mm is 0.5 mm: a drift of 0.01 mm/s settles within it
    (3 mm/s would not), and the field shows "mm", not ″."""
    _positioning(window)
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(15.0,)], drift_per_s=0.01, unit="mm") as readout:
        _auto(panel, readout, qtbot)
        qtbot.waitUntil(lambda: len(panel.taken) >= 1, timeout=5000)
        assert panel.window_box.suffix() == " mm"
        assert "readout's own unit (mm)" in panel.window_box.toolTip()
        assert panel.stability.text().endswith(" mm")
        panel.disconnect_instrument()


def test_each_axis_s_spread_has_its_unit(window, qtbot):
    """live78: an autocollimator's spread read "Spread over the last second: 0.097   0.097\\""
    — the first figure, x's, without a unit; each is followed by its own."""
    import re

    from tests.instrument_simulators import AutocollimatorSimulator

    _show(window, "polygon")
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)], sigma=0.05) as ac:
        panel.connect_to("autocollimator", ac.port, **FAST)
        qtbot.waitUntil(lambda: bool(panel.stability.text()), timeout=5000)
        said = panel.stability.text()
        assert re.fullmatch(r'Spread over the last second: \d+\.\d{3}"   \d+\.\d{3}"', said), said
        panel.disconnect_instrument()
