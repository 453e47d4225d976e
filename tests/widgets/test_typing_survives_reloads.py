"""What is typed in a cell's editor, not yet entered, is never dropped without a word when the
table's rows change (stop 65; stop 63 kept it through repaints)."""

from __future__ import annotations

import pytest

from tests.widgets.test_typing_survives_repaints import KEY, ROW, _bench, _column, _start_typing


@pytest.mark.parametrize("removed", [ROW + 3, ROW - 1])
def test_rows_removed_elsewhere_leave_what_is_typed_looked_after(qtbot, removed):
    """A row deleted below or above the one being typed in: the editor stays open with what
    was typed, which is still the window's to autosave and to look after (before: Qt left
    the view's state at NoState, and ``pending_edit``, which asked it, said nothing was being
    typed: the autosave left it out)."""
    bench = _bench(qtbot)
    column = _column(bench, KEY)
    editor = _start_typing(qtbot, bench, ROW, column, "21.7")
    bench.table_model.remove_rows([removed])
    row = ROW if removed > ROW else ROW - 1
    assert editor.isVisible() and editor.text() == "21.7"
    assert bench.view.table.pending_edit() == (row, column, "21.7")
