"""#41: a take fills the encoder's nominal from the plan into a blank encoder cell (the
polygon's and the cross-calibration's encoder reading expected at the face: the set's or
mounting's first reading plus the steps of 360°/N), only when no instrument fills that
column; a typed encoder cell is never written over."""

from __future__ import annotations

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and an instrument: more than 0.4 s

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}


def _text(model, row, key):
    keys = [c.key for c in model.sheet.columns]
    return model.sheet.text(row, keys.index(key))


def test_the_crosscal_take_writes_the_encoder_nominal_where_no_readout_does(window, qtbot):
    presenter = _show(window, "crosscal")
    presenter.set_settings({**presenter.settings, "faces": 8})
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    # mounting 0's first two faces typed: 8 faces from 10.0003°, the encoder counting up
    model.replace_all([["0", "1", "10.0003", "1.5", ""], ["0", "2", "55.0001", "2.0", ""]],
                      "two faces")
    presenter.view.table.setCurrentIndex(model.index(2, keys.index("ac_x_arcsec")))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(1.25, -0.5)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        panel.take_button.click()
        # a typed encoder cell in the next row stays as typed
        model.set_cells([(3, keys.index("encoder_deg"), "100.0100")], "typed")
        qtbot.waitUntil(lambda: not panel.used_again(), timeout=3000)  # a new frame (#60)
        panel.take_button.click()
        panel.disconnect_instrument()
    assert [_text(model, 2, k) for k in ("mounting", "position", "ac_x_arcsec")] == \
        ["0", "3", "1.25"]
    assert float(_text(model, 2, "encoder_deg")) == pytest.approx(10.0003 + 2 * 45.0, abs=1e-6)
    assert _text(model, 3, "position") == "4"
    assert _text(model, 3, "encoder_deg") == "100.0100"
    # with the encoder's readout connected, its reading goes there, never the nominal
    with AutocollimatorSimulator("pty", positions=[(0.75, -0.5)]) as ac, \
            ReadoutSimulator("tcp", positions=[(145.00052,)]) as readout:
        panel.connect_to("autocollimator", ac.port, **FAST)
        panel.connect_to("readout", readout.port, slot=1, **FAST)
        second = panel.links[1]
        second.column.setCurrentIndex(second.column.findData("encoder_deg"))
        qtbot.waitUntil(lambda: all(link.usable for link in panel.links), timeout=3000)
        panel.take_button.click()
        panel.disconnect_instrument()
    assert _text(model, 4, "position") == "5"
    assert float(_text(model, 4, "encoder_deg")) == pytest.approx(145.00052, abs=1e-9)


def test_the_polygon_take_writes_the_encoder_nominal_into_a_blank_cell(window, qtbot):
    presenter = _show(window, "polygon")
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    rows = [[str(f), f"{15 * f + 90.0002}", "0", "", "", "1", "+"] for f in range(1, 7)]
    model.replace_all(rows + [["", "", "", "", "", "", ""]], "six faces")
    presenter.view.table.setCurrentIndex(model.index(6, keys.index("ac_x_arcsec")))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(1.25, -0.5)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        panel.take_button.click()
        panel.disconnect_instrument()
    assert [_text(model, 6, k) for k in ("position", "ac_x_arcsec")] == ["7", "1.25"]
    # set 1's first reading (105.0002°) plus six steps of 15° (24 faces from the step)
    assert float(_text(model, 6, "encoder_deg")) == pytest.approx(195.0002, abs=1e-6)
