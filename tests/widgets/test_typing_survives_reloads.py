"""What is typed in a cell's editor, not yet entered, is never dropped without a word when the
table is reloaded (stop 65; stop 63 kept it through repaints).

A replacement of every row (``beginResetModel``/``endResetModel``: a paste over the sheet,
the fringe's live take, an import, File › New or Open, Edit › Undo of one of those) and a
deletion of the row being typed in closed the editor through Qt's reset and what was typed
was gone, silently. Now a replacement pushed as an undo step enters the typed text first when
it reads as the column's value (as Return would: its own step, Edit › Undo of the
replacement shows it) and says so; otherwise the editor closes, nothing entered, and the
status line says what was typed.

Driven as a technician does: the cell clicked and typed into, then the other path taken (the
Edit menu's Paste, the live window's Take, Edit › Undo)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication

from tests.instrument_simulators import SIMULATORS
from tests.widgets.test_typing_survives_repaints import KEY, ROW, _bench, _column, _start_typing
from widgets.fringe.presenter import FringePresenter
from widgets.workbench_presenter import WorkbenchState


def _said(qtbot, bench, *parts: str) -> str:
    """The status line's message about the sheet, once it holds every one of ``parts``."""
    qtbot.waitUntil(lambda: all(p in (getattr(bench.view, "last_status", "") or "")
                                for p in parts), timeout=3000)
    return bench.view.last_status


def _closed(table) -> bool:
    return table.state() != table.State.EditingState and table._typing_delegate.editor is None


def _paste_over_the_sheet(qtbot, bench) -> list[list[str]]:
    """Every row selected (the cursor's cell typed into after), a block of readings on the
    clipboard, Edit › Paste: the block replaces the sheet."""
    sheet = bench.sheet
    rows = [list(sheet.rows[r]) for r in range(sheet.row_count)]
    rows[0][_column(bench, KEY)] = "11.11"  # the block: the readings, one of them other
    header = [c.key for c in sheet.columns]  # its header row names the columns
    QGuiApplication.clipboard().setText("\n".join("\t".join(r) for r in [header, *rows]))
    bench.view.table.paste_action.trigger()
    return rows


def _typing_over_a_whole_selection(qtbot, bench, text: str):
    table = bench.view.table
    editor = _start_typing(qtbot, bench, ROW, _column(bench, KEY), text)
    table.selectAll()  # every row selected, the editor still open
    assert table.state() == table.State.EditingState
    return editor


def test_a_paste_over_the_sheet_enters_what_was_typed_first_and_says_so(qtbot):
    bench = _bench(qtbot)
    table, column = bench.view.table, _column(bench, KEY)
    _typing_over_a_whole_selection(qtbot, bench, "21.7")
    _paste_over_the_sheet(qtbot, bench)
    assert bench.sheet.text(0, column) == "11.11"  # the paste stands
    assert bench.sheet.text(ROW, column) == "21.56"  # the block's own reading
    assert _closed(table)
    said = _said(qtbot, bench, "Row 3", "“21.7”", "was entered", "replacing the sheet")
    assert "not entered" not in said
    # before: the paste was the only step, what was typed gone; now it was entered first
    bench.undo_stack.undo()
    assert bench.sheet.text(ROW, column) == "21.7"
    assert bench.sheet.text(0, column) != "11.11"
    bench.undo_stack.undo()
    assert bench.sheet.text(ROW, column) == "21.56"


def test_a_paste_over_the_sheet_keeps_what_does_not_read_in_the_status_line(qtbot):
    bench = _bench(qtbot)
    table, column = bench.view.table, _column(bench, KEY)
    _typing_over_a_whole_selection(qtbot, bench, "21.7q")
    steps = bench.undo_stack.count()
    _paste_over_the_sheet(qtbot, bench)
    assert bench.sheet.text(0, column) == "11.11"
    assert bench.undo_stack.count() == steps + 1  # the paste alone: nothing entered
    assert _closed(table)
    _said(qtbot, bench, "Row 3", "“21.7q”", "was not entered", "replaced")


@pytest.mark.parametrize("how", ["new", "undo"])
def test_a_replacement_that_cannot_enter_first_says_what_was_typed(qtbot, how):
    """File › New (load_state, as the window does per workbench) and Edit › Undo of an
    import: nothing can be entered before them (the history is cleared; an entry would
    become what Undo undoes), so the editor closes and the status line keeps the text."""
    bench = _bench(qtbot)
    table, column = bench.view.table, _column(bench, KEY)
    if how == "undo":
        bench.table_model.replace_all([list(r) for r in bench.sheet.rows], "Import again",
                                      checked=True)
    _start_typing(qtbot, bench, ROW, column, "21.7")
    if how == "new":
        bench.load_state(WorkbenchState())
        assert bench.sheet.row_count == 0
    else:
        bench.undo_stack.undo()
        assert bench.sheet.text(ROW, column) == "21.56"
    assert _closed(table)
    _said(qtbot, bench, "Row 3", "“21.7”", "was not entered", "replaced")


def test_the_row_being_typed_in_removed_says_what_was_typed(qtbot):
    """A row inserted, typed into, and the insert undone (Edit › Undo from the menu, the
    editor open): the row goes, and with it the editor — said, not silently."""
    bench = _bench(qtbot)
    table, column = bench.view.table, _column(bench, KEY)
    table.setCurrentIndex(bench.table_model.index(ROW, column))
    table.insert_action.trigger()  # Ctrl+I: a blank row above row 3
    assert bench.sheet.text(ROW, column) == ""
    _start_typing(qtbot, bench, ROW, column, "22.5")
    bench.undo_stack.undo()
    assert bench.sheet.text(ROW, column) == "21.56"
    assert _closed(table)
    _said(qtbot, bench, "Row 3", "“22.5”", "was not entered", "removed")


@pytest.mark.parametrize("removed", [ROW + 3, ROW - 1])
def test_rows_removed_elsewhere_leave_what_is_typed_looked_after(qtbot, removed):
    """A row deleted below or above the one being typed in: the editor stays open with what
    was typed, which is still the window's to autosave and to look after (before: Qt left
    the view's state at NoState, and ``pending_edit``, which asked it, said nothing was being
    typed: the autosave left it out, and a replacement after dropped it without a word)."""
    bench = _bench(qtbot)
    table, column = bench.view.table, _column(bench, KEY)
    editor = _start_typing(qtbot, bench, ROW, column, "21.7")
    bench.table_model.remove_rows([removed])
    row = ROW if removed > ROW else ROW - 1
    assert editor.isVisible() and editor.text() == "21.7"
    assert table.pending_edit() == (row, column, "21.7")
    bench.load_state(WorkbenchState())  # File › New
    _said(qtbot, bench, f"Row {row + 1}", "“21.7”", "was not entered")


@pytest.fixture
def fringe(qtbot):
    bench = _bench(qtbot, FringePresenter)
    yield bench
    bench.view.live_signals.disconnect_stream()


def _live_take(qtbot, fringe) -> None:
    """The read head simulator streaming over TCP, its window taken (the live window's Take
    button, as clicked)."""
    from app.capture.signal_live import open_signal_stream

    head = SIMULATORS["signals"]("tcp", sample_hz=10_000.0, signal_hz=40.0, noise_mv=1.0,
                                 gap_mm=0.9, yaw_mrad=2.0, roll_mrad=10.0, seed=11)
    with head:
        panel = fringe.view.live_signals
        panel.attach(open_signal_stream)
        assert panel.connect_stream(head.port, "")
        qtbot.waitUntil(lambda: panel.figures is not None and panel.figures.periods >= 4,
                        timeout=10_000)
        panel.take_button.click()
        panel.disconnect_stream()


@pytest.mark.parametrize("typed, entered", [("0.4321", True), ("0.43x", False)])
def test_a_live_take_while_typing_enters_what_reads_and_says_what_does_not(qtbot, fringe,
                                                                         typed, entered):
    table = fringe.view.table
    column = _column(fringe, "u_sin")
    row = 1
    before = [list(r) for r in fringe.sheet.rows]
    _start_typing(qtbot, fringe, row, column, typed)
    _live_take(qtbot, fringe)
    assert fringe.undo_stack.undoText().startswith("Take live signals")
    assert fringe.sheet.row_count > 100 and fringe.sheet.text(row, column) != typed
    assert _closed(table)
    fringe.undo_stack.undo()  # the take undone: the record it replaced
    if entered:
        _said(qtbot, fringe, "Row 2", f"“{typed}”", "was entered", "Take live signals")
        assert fringe.sheet.text(row, column) == typed  # before: gone, nowhere
        fringe.undo_stack.undo()
    else:
        _said(qtbot, fringe, "Row 2", f"“{typed}”", "was not entered", "replaced")
    assert [list(r) for r in fringe.sheet.rows] == before


# -- in the window: its menus, its status line ------------------------------------------

def _in_window(window, qtbot, text: str):
    from tests.app.capture.window_steps import show_workbench

    bench = show_workbench(window, "polygon")
    window.show()
    bench.load_sample()
    column = _column(bench, KEY)
    editor = _start_typing(qtbot, bench, ROW, column, text)
    return bench, column, editor


@pytest.mark.slow
def test_in_the_window_file_new_says_what_was_typed_and_not_entered(window, qtbot):
    """File › New with a value being typed: the window takes away the messages about the
    old sheet's rows (day review 64 P7); the one about what was typed comes after it."""
    bench, _, _ = _in_window(window, qtbot, "21.7")
    window.menus.new_action.trigger()
    assert bench.sheet.row_count == 0
    bar = window.statusBar()
    qtbot.waitUntil(lambda: "“21.7”" in bar.currentMessage(), timeout=3000)
    assert bar.currentMessage().startswith("Row 3, AC x")
    assert "was not entered" in bar.currentMessage()


@pytest.mark.slow
def test_in_the_window_a_language_switch_leaves_what_is_typed(window, qtbot):
    """View › Language re-labels the headers and every text: the editor stays open with
    what was typed, and Return enters it."""
    bench, column, editor = _in_window(window, qtbot, "21.7")
    try:
        window.set_language("zh_CN")
        assert editor.isVisible() and editor.text() == "21.7"
        assert bench.view.table.pending_edit() == (ROW, column, "21.7")
    finally:
        window.set_language("en")
    qtbot.keyClicks(editor, "7")
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: bench.sheet.text(ROW, column) == "21.77", timeout=3000)
