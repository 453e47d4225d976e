"""Old messages go with what they were about (day review 64 P7): the capture panel's red
take note ("Row 50: encoder a … is −75.0° from …", "Not taken: …") stayed after both
instruments were disconnected, the sheet replaced and File › New; the status line's
"Row 4, … was not entered" stayed through File › New. Both read as a warning about the
job now in front."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import TheodoliteSimulator
from tests.widgets.test_typing_survives_repaints import _start_typing

pytestmark = pytest.mark.slow  # a window and an instrument: more than 0.4 s


def _note_said(window, qtbot, sim) -> str:
    """Two takes with no frame between (F9 twice): the second refused, said in the note."""
    panel = window.capture_panel
    panel.connect_to("theodolite", sim.port, silence_s=2.0)
    qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=5000)
    assert panel.take_reading() == "row 1"
    assert panel.take_reading() == ""
    note = panel.take_note.text()
    assert note.startswith("Not taken: no new reading from Theodolite"), note
    assert panel.take_note.isVisibleTo(panel)
    return note


@pytest.fixture
def theodolite(window):
    presenter = _show(window, "theodolite")
    model = presenter.table_model
    model.replace_all([], "empty")
    keys = [c.key for c in model.sheet.columns]
    presenter.view.table.setCurrentIndex(model.index(0, keys.index("azimuth_deg")))
    yield presenter
    window.capture_panel.disconnect_instrument()


def test_the_take_note_goes_when_the_instrument_is_disconnected(window, theodolite, qtbot):
    panel = window.capture_panel
    with TheodoliteSimulator("pty", positions=[(33.5, 90.25)], reply_delay_s=0.5) as sim:
        _note_said(window, qtbot, sim)
        # the link's own Disconnect button, as the technician clicks it
        qtbot.mouseClick(panel.links[0].disconnect_button, Qt.MouseButton.LeftButton)
    assert not panel.links[0].connected
    assert panel.take_note.text() == "" and not panel.take_note.isVisibleTo(panel)


def test_the_take_note_goes_with_its_sheet_replaced_or_a_new_project(window, theodolite,
                                                                     qtbot):
    panel = window.capture_panel
    with TheodoliteSimulator("pty", positions=[(33.5, 90.25)], reply_delay_s=0.5) as sim:
        note = _note_said(window, qtbot, sim)
        # another workbench's sheet replaced: the note is not of its rows, it stays
        window.presenter("polygon").load_sample()
        assert panel.take_note.text() == note
        theodolite.load_sample()  # the theodolite's sheet replaced (its sample)
        assert panel.take_note.text() == ""
        qtbot.waitUntil(lambda: panel.links[0].latest.frame > 0, timeout=5000)
        frame = panel.latest.frame
        qtbot.waitUntil(lambda: panel.latest.frame > frame, timeout=5000)
        theodolite.view.table.setCurrentIndex(theodolite.table_model.index(0, 1))
        assert panel.take_reading()
        assert panel.take_reading() == ""
        assert panel.take_note.text().startswith("Not taken")
        window.menus.new_action.trigger()  # File › New (unsaved work let go)
        assert panel.take_note.text() == ""


def test_what_was_typed_and_not_entered_goes_with_the_sheet(window, qtbot):
    """"Row 3, AC x … was not entered" goes on File › New and when its sheet is replaced;
    another sheet replaced leaves it."""
    bench = _show(window, "polygon")
    bench.load_sample()
    column = [c.key for c in bench.sheet.columns].index("ac_x_arcsec")
    bar = window.statusBar()

    def not_entered() -> str:
        _start_typing(qtbot, bench, 2, column, "21.7")
        bench.table_model.set_cells([(2, column, "19.25")], "Take reading (row 3)")
        said = bar.currentMessage()
        assert said.startswith("Row 3, AC x") and said.endswith("was not entered"), said
        return said

    said = not_entered()
    window.presenter("theodolite").table_model.replace_all([], "empty")
    assert bar.currentMessage() == said
    window.menus.new_action.trigger()  # File › New
    assert "was not entered" not in bar.currentMessage()
    bench.load_sample()
    not_entered()
    bench.load_sample()  # the sheet replaced: its rows are not the ones the message names
    assert "was not entered" not in bar.currentMessage()
