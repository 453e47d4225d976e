"""Day review 74 F2: after a kill, recovery entered a value that was being typed (never
entered) over a *captured* reading, with no way back but retyping the reading from the
cell's tooltip. Typed work is still never lost — the text comes back into its cell — but as
an edit of its own: Edit › Undo puts the captured reading back, and the status line names
both values. The reading is captured from the readout's protocol simulator; the kill is the
window's autosave left behind with its lock released, as kill -9 leaves it."""

from __future__ import annotations

import os

import pytest

from tests.app.capture.window_steps import planned_positioning
from tests.instrument_simulators import ReadoutSimulator

pytestmark = pytest.mark.slow  # two windows and an instrument

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}
CAPTURED = 15.01401  # where the readout stands at the take (degrees)
TYPED = "14.9999"  # typed into that cell, Return never pressed


def test_typing_over_a_captured_reading_is_recovered_as_an_edit_that_undo_takes_back(
        recovering_window, qtbot):
    window = recovering_window()
    window.show()
    bench = planned_positioning(window)
    keys = [c.key for c in bench.sheet.columns]
    measured = keys.index("measured")
    panel = window.capture_panel
    with ReadoutSimulator("tcp", positions=[(0.0002,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        for value in (0.0002, CAPTURED):
            readout.positions[0] = (value,)
            qtbot.waitUntil(lambda v=value: link.latest is not None and link.usable
                            and abs(link.latest.values[0] - v) < 6e-6
                            and not panel.used_again(), timeout=3000)
            panel.take_reading()
        panel.disconnect_instrument()
    captured = bench.sheet.text(1, measured)
    assert float(captured) == pytest.approx(CAPTURED, abs=1e-9)
    table = bench.view.table
    index = table.model().index(1, measured)
    table.setCurrentIndex(index)
    table.edit(index)
    qtbot.waitUntil(lambda: table._typing_delegate.editor is not None, timeout=3000)
    editor = table._typing_delegate.editor
    editor.selectAll()
    qtbot.keyClicks(editor, TYPED)
    assert table.pending_edit() == (1, measured, TYPED)
    window.projects.autosave()
    # the window dies (kill -9): its lock goes with the process, the autosave stays
    os.close(window.projects.recovery._lock_fd)
    window.projects.recovery._lock_fd = None
    window.projects.autosave_timer.stop()
    editor.setText(captured)  # (the dead window's editor closed without a word)
    table.closeEditor(editor, table.itemDelegate().EndEditHint.NoHint)

    survivor = recovering_window()
    assert survivor.projects.offer_recovery()
    recovered = survivor.presenter("positioning")
    # the typing kept (never lost), as an edit of its own
    assert recovered.sheet.text(1, measured) == TYPED
    said = survivor.statusBar().currentMessage()
    assert f"row 2, column {measured + 1}: {TYPED} typed over {captured}" in said, said
    assert "Undo" in said
    assert recovered.undo_stack.canUndo()
    recovered.undo_stack.undo()
    assert recovered.sheet.text(1, measured) == captured  # the captured reading back
    assert recovered.sheet.text(0, measured) != ""  # the other take untouched
