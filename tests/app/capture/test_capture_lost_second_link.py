"""#60 review: two instruments on the cross-calibration workbench (the autocollimator
auto-taking, the encoder's readout into ``encoder_deg``) and the readout's link drops,
then gives up. No take is made while it is lost (auto-take waits and says for which
instrument, a manual take is refused naming it); when it ends for good auto-take is
switched off and the panel says why; and the encoder column never gets a value the
readout did not send — the plan's expected encoder value went into it once the readout
was gone (rows 4–6 of the review: 135.0005194, 180.0005194, 225.0005194)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QTimer

from app.capture.instruments import frame_values
from models.readings.angles import parse_angle_deg
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds

#: the link gives up after 4 tries (~1.5 s) while the readout is silent for 2.5 s
FAST = {"silence_s": 0.3, "retries": 4, "retry_pause_s": 0.05}


def _column(model, key):
    column = [c.key for c in model.sheet.columns].index(key)
    return [model.sheet.text(r, column) for r in range(model.sheet.row_count)]


def test_a_lost_readout_stops_the_takes_and_its_column_gets_only_its_readings(window, qtbot):
    presenter = _show(window, "crosscal")
    presenter.set_settings({**presenter.settings, "faces": 8})
    model = presenter.table_model
    model.replace_all([], "empty")
    keys = [c.key for c in model.sheet.columns]
    model.set_cells([(0, keys.index("mounting"), "0")], "mounting")
    presenter.view.table.setCurrentIndex(model.index(0, keys.index("ac_x_arcsec")))
    panel = window.capture_panel
    panel.auto.setChecked(True)
    panel.window_box.setValue(0.3)
    panel.dwell_box.setValue(0.2)
    seen: set[str] = set()
    refused: list[str] = []
    probe = QTimer(panel)  # goes with the window, whatever the test's outcome
    probe.setInterval(5)
    probe.timeout.connect(lambda: seen.add(panel.auto_state.text()))
    encoder = [45.0 * i + 0.00052 + 0.001 * (i % 3) for i in range(8)]
    with AutocollimatorSimulator("pty", positions=[(float(i), 0.5) for i in range(1, 9)],
                                 hold_s=0.7) as ac, \
            ReadoutSimulator("pty", positions=[(e,) for e in encoder], hold_s=0.7,
                             faults=("disconnect",), disconnect_after=10, gap_s=2.5) as ro:
        panel.connect_to("autocollimator", ac.port, **FAST)
        panel.connect_to("readout", ro.port, slot=1, **FAST)
        second = panel.links[1]
        second.column.setCurrentIndex(second.column.findData("encoder_deg"))
        probe.start()
        qtbot.waitUntil(lambda: second.lost, timeout=10000)
        # the foot switch while the readout reconnects: refused, naming it
        filled = _column(model, "ac_x_arcsec")
        assert panel.take_reading() == ""
        assert _column(model, "ac_x_arcsec") == filled
        refused.append(panel.take_note.text())
        qtbot.waitUntil(lambda: not second.connected, timeout=10000)  # it gave up
        probe.stop()
        assert not panel.auto.isChecked()
        note = panel.take_note.text()
        # a take by hand after it: the autocollimator's cells, the encoder's left blank
        qtbot.waitUntil(lambda: panel.links[0].usable, timeout=3000)
        assert panel.take_reading()
        panel.disconnect_instrument()
    assert refused[0].startswith("Not taken: no reading from Readout") and ro.port in refused[0]
    assert any(s.startswith("Auto-take: waiting for Readout") and ro.port in s for s in seen), seen
    assert note.startswith("Auto-take switched off: the link to Readout") and ro.port in note
    # every row with an autocollimator reading has the encoder's reading of the same take
    # — as the readout sent it — except the last, taken with the readout gone: blank
    sessions = {s["instrument"]: s for s in panel.raw_sessions("crosscal")}
    ac_rows = [t[0] for t in sessions["autocollimator"]["takes"]]
    ro_takes = sessions["readout"]["takes"]
    assert ac_rows[:-1] == [t[0] for t in ro_takes] and ro_takes
    frames = sessions["readout"]["frames"]
    for row, first, last in ro_takes:
        assert first == last
        assert parse_angle_deg(model.sheet.text(row, keys.index("encoder_deg"))) == \
            pytest.approx(frame_values("readout", frames[first][1].encode("latin-1"))[0],
                          abs=1e-9)
    assert model.sheet.text(ac_rows[-1], keys.index("encoder_deg")) == ""
    assert model.sheet.text(ac_rows[-1], keys.index("ac_x_arcsec")) != ""
