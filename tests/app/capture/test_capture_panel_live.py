"""#41 at the bench: a take never writes over a filled row (the cursor on a filled row: the
reading goes to the next empty point, the table scrolls there); two instruments fill one
row at the same moment, each reading traced to its own raw frames; the value greyed and
marked "link lost" when stale; the statistics and guidance start afresh on a new
connection and another workbench; Disconnect; the port remembered per instrument; a
demonstration instrument. Through the protocol simulators on a pty / TCP."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSettings

from app.capture.panel import ConnectDialog
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import (
    AutocollimatorSimulator,
    ReadoutSimulator,
    TheodoliteSimulator,
)

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, instruments)

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}


def _cells(model, row, keys, names):
    return [model.sheet.text(row, keys.index(k)) for k in names]


def test_auto_take_never_writes_over_a_filled_row(window, qtbot):
    """#41 item 9: with the cursor on row 3 (filled), the next reading replaced row 3's AC
    x/y. Now it goes to the next empty point (row 5 here, row 4 being filled too) and the
    table scrolls there; rows 1–4 keep every digit typed."""
    presenter = _show(window, "polygon")
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    typed = [[str(f), f"{45 * (f - 1)}", "0", f"{f}.11", f"-{f}.22", "1", "+"] for f in range(1, 5)]
    planned = [[str(f), "", "", "", "", "1", "+"] for f in range(5, 9)]
    model.replace_all([list(r) for r in typed + planned], "four faces read, four planned")
    for _ in range(40):  # a long table: the row filled must be scrolled into sight
        model.set_cells([(model.sheet.row_count, 0, "")])
    presenter.view.table.setCurrentIndex(model.index(2, keys.index("ac_x_arcsec")))  # row 3
    panel = window.capture_panel
    panel.auto.setChecked(True)
    panel.window_box.setValue(0.5)
    panel.dwell_box.setValue(0.1)
    with AutocollimatorSimulator("pty", positions=[(7.5, 0.25)], sigma=0.02) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: len(panel.taken) >= 1, timeout=5000)
        panel.disconnect_instrument()
    for f, row in enumerate(typed):
        assert [model.sheet.text(f, c) for c in range(len(keys))] == row  # untouched
    assert panel.taken[0][1] == 4  # row 5, face 5: the next empty point
    x, y = _cells(model, 4, keys, ("ac_x_arcsec", "ac_y_arcsec"))
    assert abs(float(x) - 7.5) < 0.05 and abs(float(y) - 0.25) < 0.05
    assert len(x.split(".")[1]) == 2  # to the autocollimator's 0.01"
    table = presenter.view.table
    assert table.viewport().rect().intersects(table.visualRect(model.index(4, 0)))


def test_two_instruments_fill_one_row_at_the_same_moment(window, qtbot):
    """#41: an autocollimator for AC x/y and the encoder's readout for the encoder column;
    one take (F9) fills the row from both, each reading traced to its own raw frame (with
    its time), each link with its own status."""
    presenter = _show(window, "polygon")
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    model.replace_all([], "empty")
    presenter.view.table.setCurrentIndex(model.index(0, 0))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(2.345, -1.234)]) as ac, \
            ReadoutSimulator("tcp", positions=[(105.00012,)]) as readout:
        panel.connect_to("autocollimator", ac.port, **FAST)
        panel.connect_to("readout", readout.port, slot=1, **FAST)
        second = panel.links[1]
        second.column.setCurrentIndex(second.column.findData("encoder_deg"))
        qtbot.waitUntil(lambda: all(link.usable for link in panel.links), timeout=3000)
        assert panel.links[0].status.text() == f"Connected: {ac.port}"
        assert second.status.text() == f"Connected: {readout.port}"
        assert presenter.capturing  # takes are analysed off the GUI thread
        parsed = presenter.parsed
        panel.take_button.click()
        presenter.refresh()
        assert presenter.parsed is parsed  # not analysed here: on a worker
        qtbot.waitUntil(lambda: presenter.parsed is not parsed, timeout=5000)  # it lands
        panel.disconnect_instrument()
    assert not presenter.capturing
    assert _cells(model, 0, keys, ("ac_x_arcsec", "ac_y_arcsec")) == ["2.35", "-1.23"]
    # the readout's degrees "as sent" (its default resolution), in decimal degrees
    assert float(model.sheet.text(0, keys.index("encoder_deg"))) == pytest.approx(105.00012,
                                                                                 abs=1e-9)
    sessions = {s["instrument"]: s for s in panel.raw_sessions("polygon")}
    assert set(sessions) == {"autocollimator", "readout"}
    for name, session in sessions.items():
        assert len(session["takes"]) == 1, name
        row, first, last = session["takes"][0]
        assert row == 0 and first == last
        frame = session["frames"][first]
        assert frame[2] == 1 and frame[0] > 0  # a reading, with its own time
    assert "105.00012" in sessions["readout"]["frames"][sessions["readout"]["takes"][0][1]][1]


def test_a_stale_value_is_greyed_and_marked_link_lost(window, qtbot):
    _show(window, "polygon")
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(3.0, 1.0)]) as sim:
        panel.connect_to("autocollimator", sim.port, silence_s=30.0, retries=1)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        assert "link lost" not in panel.value.text()
        sim.faults.add("silence")  # the instrument stops sending
        qtbot.waitUntil(lambda: "link lost" in panel.value.text(), timeout=3000)
        assert "#9e9e9e" in panel.value.styleSheet()  # greyed
        assert not panel.take_button.isEnabled()  # a stale value is never taken
        sim.faults.discard("silence")
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        assert "link lost" not in panel.value.text()
        panel.disconnect_instrument()
    assert panel.value.text() == "—" and panel.status.text().startswith("Disconnected from")


def test_statistics_and_guidance_start_afresh(window, qtbot):
    presenter = _show(window, "polygon")
    presenter.table_model.replace_all([], "empty")
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(3.0, 1.0)], sigma=0.1) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.allan.text() != "", timeout=5000)
        qtbot.waitUntil(lambda: panel.guide.text().startswith("Next: go to face"), timeout=3000)
        # another workbench: the polygon's "go to face" is not said on the theodolite tab
        _show(window, "theodolite")
        assert "face" not in panel.guide.text()
        assert panel.allan.text() == "" and panel.stability.text() == ""
        _show(window, "polygon")
        qtbot.waitUntil(lambda: panel.allan.text() != "", timeout=5000)
        with TheodoliteSimulator("pty", positions=[(10.0, 90.0)]) as theodolite:
            panel.connect_to("theodolite", theodolite.port, **FAST)
            # the autocollimator's Allan deviation is not shown for the theodolite
            assert panel.allan.text() == "" and panel.stability.text() == ""
            panel.disconnect_instrument()


def test_the_last_port_of_each_instrument_is_remembered(window, qtbot):
    panel = window.capture_panel
    with AutocollimatorSimulator("pty") as sim:
        panel.connect_to("autocollimator", sim.port, 19200, **FAST)
        panel.disconnect_instrument()
    with ReadoutSimulator("tcp") as readout:
        panel.connect_to("readout", readout.port, slot=1, **FAST)
        panel.disconnect_instrument(1)
    dialog = ConnectDialog(None, window.qsettings, "autocollimator")
    assert dialog.choice() == ("autocollimator", sim.port, 19200)
    dialog.instrument.setCurrentIndex(dialog.instrument.findData("readout"))
    assert dialog.choice()[:2] == ("readout", readout.port)
    dialog.instrument.setCurrentIndex(dialog.instrument.findData("theodolite"))
    assert dialog.choice()[1] == ""  # never connected: nothing guessed
    fresh = QSettings(window.qsettings.fileName(), QSettings.Format.IniFormat)
    assert fresh.value("capture/port/autocollimator") == sim.port


def test_a_demonstration_instrument_from_the_menu(window, qtbot):
    presenter = _show(window, "theodolite")
    panel = window.capture_panel
    port = panel.start_demonstration("theodolite", noise=0.0)
    assert port.startswith("tcp://127.0.0.1:")
    qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
    assert panel.latest.values[0] == pytest.approx(0.0, abs=1e-6)
    simulator = panel.links[0].simulator
    assert simulator is not None
    assert window.qsettings.value("capture/port/theodolite") is None  # its port not remembered
    row = presenter.table_model.sheet.row_count
    presenter.view.table.setCurrentIndex(presenter.table_model.index(row, 0))
    panel.take_reading()
    keys = [c.key for c in presenter.table_model.sheet.columns]
    assert presenter.table_model.sheet.text(row, keys.index("azimuth_deg")) != ""
    window.menus.disconnect_instrument_action.trigger()
    assert panel.links[0].simulator is None and panel.worker is None
    assert simulator.process.poll() is not None  # the demonstration stopped with the link


def test_a_face_deviation_is_filled_from_the_polygon_certificate_rows(window, qtbot):
    """#41: cells the capture cannot fill: a polygon face's deviation (its certificate's,
    typed or sent once per face) goes with the face into the row a take fills; a face
    with two different deviations is left for the technician; D°M′S″ rows get D°M′S″."""
    presenter = _show(window, "polygon")
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    rows = [["1", "0°00'00\"", "0.00", "1.00", "0.50", "1", "+"],
            ["2", "90°00'01\"", "0.13", "2.00", "0.40", "1", "+"],
            ["3", "180°00'02\"", "-0.21", "3.00", "0.30", "1", "+"],
            ["2", "", "", "", "", "2", "+"]]  # set 2, face 2 planned
    model.replace_all([list(r) for r in rows], "set 1 and a planned face")
    presenter.view.table.setCurrentIndex(model.index(3, keys.index("ac_x_arcsec")))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(4.0, 0.2)]) as ac, \
            ReadoutSimulator("pty", positions=[(90.00012,)]) as readout:
        panel.connect_to("autocollimator", ac.port, **FAST)
        panel.connect_to("readout", readout.port, slot=1, **FAST)
        panel.links[1].column.setCurrentIndex(panel.links[1].column.findData("encoder_deg"))
        qtbot.waitUntil(lambda: all(link.usable for link in panel.links), timeout=3000)
        panel.take_reading()
        panel.disconnect_instrument()
    assert _cells(model, 3, keys, ("position", "polygon_dev_arcsec", "ac_x_arcsec", "set")) == \
        ["2", "0.13", "4.00", "2"]
    # 90.00012° = 90°00'00.432" as sent, in the column's D°M′S″
    assert model.sheet.text(3, keys.index("encoder_deg")) == "90°00'00.432\""


def test_a_direction_at_zero_spreads_by_its_noise_not_by_360_degrees(window, qtbot):
    """The theodolite aimed at 0°: readings 359°59'59.8" and 0°00'00.3" are 0.5" apart
    (the panel showed a spread of 1295999.997" and an Allan deviation of 6.4e+05")."""
    _show(window, "theodolite")
    panel = window.capture_panel
    with TheodoliteSimulator("tcp", positions=[(0.0, 90.0)], sigma=0.5) as sim:
        panel.connect_to("theodolite", sim.port, **FAST)
        qtbot.waitUntil(lambda: " s)" in panel.allan.text() and panel.stability.text() != "",
                        timeout=8000)  # figures, not "waiting for frames after the gap"
        spread = [float(v) for v in panel.stability.text().split(":")[1].replace('"', "").split()]
        allan = [float(part.split("(")[0].replace('"', ""))
                 for part in panel.allan.text().split(":")[1].split(",")]
        panel.disconnect_instrument()
    hz = [v[0] for v in sim.sent if v is not None]
    assert min(hz) < 0.001 and max(hz) > 359.999  # it did read on both sides of 0°
    assert 0.0 < spread[0] < 6.0  # σ = 0.5": a few σ, never 360°
    assert all(0.0 < a < 2.0 for a in allan)
