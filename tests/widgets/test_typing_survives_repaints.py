"""What is typed in a cell's editor, not yet entered, survives any repaint of the table.

Qt gives an open editor its cell's text again at every ``dataChanged`` that covers the cell,
whatever roles it names: a change of the highlighted rows (the polygon's closure rows after an
analysis), a cell's mark, the rows waiting for their reading, a take into another cell put the
cell's old text back into the editor. What was typed was lost, and typing on wrote a wrong
number (21.7 typed, the editor reset to 21.56, "7" more and Return: 21.567 in the cell). A
take that moved the cursor on entered the half-typed value. A real change of the very cell
being typed in (a take into it) stands; the editor is closed, what was typed not entered, and
the status line says both.

Driven as a technician does: the cell clicked, typed into (the table's own edit trigger),
Return pressed."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from widgets.crosscal.presenter import CrossCalPresenter
from widgets.fringe.presenter import FringePresenter
from widgets.polygon.presenter import PolygonPresenter
from widgets.positioning.presenter import PositioningPresenter
from widgets.readings_table_model import ReadingsTableModel
from widgets.readings_table_view import ReadingsTableView
from widgets.theodolite.presenter import TheodolitePresenter

ROW, KEY = 2, "ac_x_arcsec"  # the polygon sample's row 3: AC x 21.56


def _bench(qtbot, presenter_class=PolygonPresenter):
    bench = presenter_class()
    qtbot.addWidget(bench.view)
    bench.view.show()
    bench.load_sample()
    with qtbot.waitSignal(bench.analysed, timeout=10000):
        bench.refresh()
    return bench


def _column(bench, key: str) -> int:
    return [c.key for c in bench.sheet.columns].index(key)


def _start_typing(qtbot, bench, row: int, column: int, text: str):
    """The cell clicked and ``text`` typed over it (its first key opens the editor); the
    editor, open, nothing entered."""
    table = bench.view.table
    index = bench.table_model.index(row, column)
    table.scrollTo(index)
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton,
                     pos=table.visualRect(index).center())
    assert table.currentIndex() == index
    qtbot.keyClick(table, text[0])  # any key opens the cell's editor with it
    qtbot.waitUntil(lambda: table._typing_delegate.editor is not None, timeout=3000)
    editor = table._typing_delegate.editor
    qtbot.keyClicks(editor, text[1:])
    assert editor.text() == text
    return editor


def _enter(qtbot, bench, editor, row: int, column: int, expected: str) -> None:
    """More typed is ``expected`` in the editor, Return: the cell holds it."""
    assert editor.text() == expected
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    # the delegate commits on Return through a queued call: let the event loop run
    qtbot.waitUntil(lambda: bench.sheet.text(row, column) == expected, timeout=3000)


def _highlight(bench, qtbot, row, column):
    bench.table_model.set_highlight_rows({0, 1, row})


def _analysis_shading(bench, qtbot, row, column):
    """The analysis finishing: the presenter draws the closure rows apart again."""
    with qtbot.waitSignal(bench.analysed, timeout=10000):
        bench.refresh()
    assert bench.table_model.highlight_rows == bench.result.closure_rows != set()


def _cell_mark(bench, qtbot, row, column):
    """The cell itself marked (a captured reading edited since): its one cell repainted."""
    bench.table_model.set_edited_cells({(row, column): "captured 21.56"})


def _waiting(bench, qtbot, row, column):
    model = bench.table_model
    model.planned_row = lambda: row
    model.forget_waiting()


def _cell_of_the_row(bench, qtbot, row, column):
    """Another cell of the row written (a take's AC y beside it), and the analysis after."""
    with qtbot.waitSignal(bench.analysed, timeout=10000):
        bench.table_model.set_cells([(row, _column(bench, "ac_y_arcsec"), "-2.50")], "take")


@pytest.mark.parametrize("repaint", [_highlight, _analysis_shading, _cell_mark, _waiting,
                                     _cell_of_the_row])
def test_typed_text_survives_a_repaint(qtbot, repaint):
    bench = _bench(qtbot)
    column = _column(bench, KEY)
    assert bench.sheet.text(ROW, column) == "21.56"
    if repaint is _analysis_shading:
        bench.clear_result()  # no result drawn (as while readings cannot be read)
        assert bench.table_model.highlight_rows == set()
    editor = _start_typing(qtbot, bench, ROW, column, "21.7")
    repaint(bench, qtbot, ROW, column)
    # was: "21.56" again in the editor
    assert editor.text() == "21.7"
    qtbot.keyClicks(editor, "7")
    # was: 21.567 entered
    _enter(qtbot, bench, editor, ROW, column, "21.77")


@pytest.mark.parametrize("presenter_class", [
    PolygonPresenter, TheodolitePresenter, FringePresenter, PositioningPresenter,
    CrossCalPresenter])
def test_every_workbench_keeps_typed_text_through_its_repaints(qtbot, presenter_class):
    """Every workbench's table is the same view, delegate and model."""
    bench = _bench(qtbot, presenter_class)
    table = bench.view.table
    assert type(table) is ReadingsTableView and type(bench.table_model) is ReadingsTableModel
    assert table.itemDelegate() is table._typing_delegate
    column = _column(bench, bench.kind.entry_column)
    editor = _start_typing(qtbot, bench, 1, column, "12.3")
    bench.table_model.set_highlight_rows({0, 1, 2} ^ bench.table_model.highlight_rows)
    bench.table_model.set_edited_cells({(1, column): "captured"})
    assert editor.text() == "12.3"
    qtbot.keyClicks(editor, "4")
    _enter(qtbot, bench, editor, 1, column, "12.34")


def test_a_change_of_the_cell_being_typed_in_stands_and_is_said(qtbot):
    """A take into the very cell being typed in: the reading goes in, the editor is closed
    with what was typed not entered, and the status line says both (before: the editor
    took the take's text without a word, what was typed gone)."""
    bench = _bench(qtbot)
    table = bench.view.table
    column = _column(bench, KEY)
    editor = _start_typing(qtbot, bench, ROW, column, "21.7")
    bench.table_model.set_cells([(ROW, column, "19.25")], "Take reading (row 3)")
    assert bench.sheet.text(ROW, column) == "19.25"
    assert table.state() != table.State.EditingState
    assert table._typing_delegate.editor is None or not editor.isVisible()
    assert "“19.25”" in bench.view.last_status and "“21.7”" in bench.view.last_status
    assert "Row 3" in bench.view.last_status
    # undone: the reading back as it was, no editor to write over
    bench.undo_stack.undo()
    assert bench.sheet.text(ROW, column) == "21.56"


def test_a_take_moves_no_cursor_away_from_a_cell_being_typed_in(qtbot):
    """After a take the cursor goes on to the next row (ReadingsTableView.next_row); with a
    value being typed elsewhere that move entered what was typed so far ("21.7") and closed
    the editor, the rest typed going to the next row. Now the cursor stays."""
    bench = _bench(qtbot)
    table = bench.view.table
    column = _column(bench, KEY)
    editor = _start_typing(qtbot, bench, ROW, column, "21.7")
    bench.table_model.set_cells([(ROW + 5, column, "30.00")], "Take reading (row 8)")
    table.next_row(ROW + 5)  # as the capture panel's take does
    assert table.state() == table.State.EditingState
    assert table.currentIndex() == bench.table_model.index(ROW, column)
    assert bench.sheet.text(ROW, column) == "21.56"  # nothing entered yet
    qtbot.keyClicks(editor, "7")
    _enter(qtbot, bench, editor, ROW, column, "21.77")
