"""The window's instrument panel against the simulators over a pty: the live readout
never waits for the instrument, and Take reading fills the current row as one undo
step."""

from __future__ import annotations

import time

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, TheodoliteSimulator

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}


def test_take_reading_fills_the_polygon_row_as_one_undo_step(window, qtbot):
    presenter = _show(window, "polygon")
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    row = model.sheet.row_count  # the empty row after the readings
    presenter.view.table.setCurrentIndex(model.index(row, 0))
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(3.25, -1.5)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.latest is not None, timeout=3000)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        # as the cells will read (0.01" resolution), not 3 decimals of its own (#41 review),
        # each axis named (day review live76 F11: "9.56″ −3.19″")
        assert panel.value.text() == 'x 3.25"\ny -1.50"'
        steps = presenter.undo_stack.count()
        panel.take_button.click()
        panel.disconnect_instrument()
    assert model.sheet.text(row, keys.index("ac_x_arcsec")) == "3.25"
    # rounded to the autocollimator's resolution (0.01" unless set), not 12 digits (#41)
    assert model.sheet.text(row, keys.index("ac_y_arcsec")) == "-1.50"
    assert presenter.undo_stack.count() == steps + 1
    presenter.undo_stack.undo()
    assert row >= model.sheet.row_count or model.sheet.text(row, keys.index("ac_x_arcsec")) == ""

    # a silent instrument: the window is never kept waiting, and it says so naming the port
    with AutocollimatorSimulator("pty", faults=("silence",)) as sim:
        started = time.monotonic()
        panel.connect_to("autocollimator", sim.port, **FAST)
        assert time.monotonic() - started < 0.1
        assert not panel.take_button.isEnabled()
        qtbot.waitUntil(lambda: "no answer" in panel.status.text(), timeout=3000)
        panel.disconnect_instrument()
    assert panel.status.text().startswith(f"{sim.port}: no answer") and not panel.take_button.isEnabled()


def test_theodolite_zenith_fills_the_vertical_column_as_it_reads(window, qtbot):
    """#41: the elevation is filled from the zenith angle (90° − V) where the column reads
    elevation, the zenith angle itself where it reads zenith; both rounded to the
    theodolite's resolution (0.1" unless set), the raw frames keeping every digit."""
    presenter = _show(window, "theodolite")
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    panel = window.capture_panel
    for reads in ("elevation", "zenith"):
        presenter.set_settings({**presenter.settings, "vertical_reading": reads})
        row = model.sheet.row_count
        presenter.view.table.setCurrentIndex(model.index(row, 0))
        with TheodoliteSimulator("pty", positions=[(123.4567, 87.6543)]) as sim:
            panel.connect_to("theodolite", sim.port, **FAST)
            qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
            panel.take_reading()
            panel.disconnect_instrument()
        azimuth = model.sheet.text(row, keys.index("azimuth_deg"))
        vertical = model.sheet.text(row, keys.index("elevation_deg"))
        # 123.4567° = 444444.12" → 444444.1"; written in the column's format (decimal here)
        assert float(azimuth) * 3600 == pytest.approx(444444.1, abs=0.004)
        expected = 87.6543 if reads == "zenith" else 90.0 - 87.6543
        assert float(vertical) == pytest.approx(expected, abs=0.05 / 3600 + 1e-9)
    assert panel.raw_sessions("theodolite")[-1]["frames"]  # the raw frames kept


def test_no_blank_band_at_the_top_of_the_panel_docked_at_a_side(window):
    """#41 review: docked at the right before connecting, the empty guidance took ~60 px of
    blank height above the instrument (the parts stretched one above the other)."""
    from PySide6.QtCore import QPoint, Qt
    from PySide6.QtWidgets import QApplication

    window.resize(1280, 720)
    window.show()
    panel = window.capture_panel
    window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, panel)
    panel.show()
    for _ in range(5):
        QApplication.processEvents()
    top = panel.links[0].box.mapTo(panel.body, QPoint(0, 0)).y()
    # the margin, the (empty) guidance's line and the layout's spacing: no more
    assert top <= panel.guide.sizeHint().height() + 20, top


def test_the_resolution_is_the_instruments_once_one_is_connected(window, qtbot):
    """Day review live76 F11: the first instrument's Resolution read "as sent" before any
    instrument was connected (an autocollimator's is 0.01″); it waits for the instrument."""
    _show(window, "polygon")
    panel = window.capture_panel
    link = panel.links[0]
    assert not link.resolution.isEnabled() and not link.resolution_label.isEnabled()
    with AutocollimatorSimulator("pty", positions=[(3.25, -1.5)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        assert link.resolution.isEnabled() and link.resolution.currentText() == '0.01"'
        panel.disconnect_instrument()


def test_an_encoder_just_below_zero_is_said_as_the_cell_reads_it(window):
    """Day review live76 F11: the cell read "-0.00001" while the off-plan note said
    "360.0000°"."""
    from types import SimpleNamespace

    presenter = _show(window, "polygon")
    panel = window.capture_panel
    link = panel.links[0]
    panel.next_reading = SimpleNamespace(pitch_deg=30.0, nominal={"encoder_deg": 40.0},
                                         near={}, fill={"position": "5"})
    said = panel._off_the_plan(presenter.table_model.sheet, 21, [(link, 0, "encoder_deg")],
                               {link.slot: ((-0.00001,), "deg", (0, 0))})
    assert len(said) == 1 and said[0][1].startswith(
        "Row 22: encoder a [deg] 0.0000° is -40.0° from the ≈ 40° the plan expects at face 5"), said
