"""A take while the technician types in a cell: what is typed is never lost, nor entered
half-typed, nor written over a reading without a word.

Through the real window: the readout simulator over a pty into the polygon's encoder
column, the panel's take as auto-take makes it (no click moves the focus), the cell typed
into as a technician does (clicked, typed, Return)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.app.capture.test_capture_dms_cells import _typed_rows
from tests.app.capture.test_takes_undone import FAST
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and an instrument for seconds

TYPED = ["0.000", "30.000", "60.000"]  # the encoder typed; row 4 waits for its reading
READING = 90.00012


def _start_typing(qtbot, bench, row: int, key: str, text: str):
    table, model = bench.view.table, bench.table_model
    index = model.index(row, [c.key for c in model.sheet.columns].index(key))
    table.scrollTo(index)
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton,
                     pos=table.visualRect(index).center())
    qtbot.keyClick(table, text[0])  # any key opens the cell's editor with it
    qtbot.waitUntil(lambda: table._typing_delegate.editor is not None, timeout=3000)
    editor = table._typing_delegate.editor
    qtbot.keyClicks(editor, text[1:])
    assert editor.text() == text
    return editor, index


def _connected(window, qtbot, sim):
    panel = window.capture_panel
    panel.connect_to("readout", sim.port, **FAST)
    link = panel.links[0]
    link.column.setCurrentIndex(link.column.findData("encoder_deg"))
    qtbot.waitUntil(lambda: link.latest is not None and link.usable
                    and abs(link.latest.values[0] - READING) < 1e-6, timeout=5000)
    return panel


def test_a_take_into_another_row_leaves_the_typing_alone(window, qtbot):
    window.show()
    bench = _show(window, "polygon")
    _typed_rows(bench, "encoder_deg", TYPED)
    sheet, table = bench.sheet, bench.view.table
    encoder = [c.key for c in sheet.columns].index("encoder_deg")
    with ReadoutSimulator("pty", positions=[(READING,)]) as ro:
        panel = _connected(window, qtbot, ro)
        editor, index = _start_typing(qtbot, bench, 1, "ac_x_arcsec", "12.3")
        assert panel.take_reading() == "row 4"
        panel.disconnect_instrument()
    assert sheet.text(3, encoder) == "90.00012"
    # was: the take's move to the next row entered "12.3" and closed the editor (the rest
    # typed went to another cell)
    assert table._typing_delegate.editor is editor and table.currentIndex() == index
    with qtbot.waitSignal(bench.analysed, timeout=10000):
        pass  # the take's analysis finished, its shading repainted over the editor
    assert editor.text() == "12.3"
    qtbot.keyClicks(editor, "4")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: sheet.text(1, index.column()) == "12.34", timeout=3000)
    assert sheet.text(3, encoder) == "90.00012"
    window.capture_panel.close()


def test_a_take_into_the_cell_being_typed_in_stands_and_says_what_was_typed(window, qtbot):
    window.show()
    bench = _show(window, "polygon")
    _typed_rows(bench, "encoder_deg", TYPED)
    sheet, table = bench.sheet, bench.view.table
    with ReadoutSimulator("pty", positions=[(READING,)]) as ro:
        panel = _connected(window, qtbot, ro)
        _, index = _start_typing(qtbot, bench, 3, "encoder_deg", "90.5")
        assert panel.take_reading() == "row 4"
        panel.disconnect_instrument()
    # the reading in, the editor closed without entering what was typed, and said (was:
    # the editor silently showed the reading instead, "90.5" gone without a word)
    assert sheet.text(3, index.column()) == "90.00012"
    assert table.state() != table.State.EditingState
    said = window.statusBar().currentMessage()
    assert "Row 4" in said and "“90.00012”" in said and "“90.5”" in said, said
    window.capture_panel.close()
