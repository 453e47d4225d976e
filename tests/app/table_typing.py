"""Typing into a readings table as a user does: the cell's editor opened, the text typed or
deleted, Return pressed (shared by the entry-plan, live-day and reading-in-progress tests)."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLineEdit


def _editor(table, row: int, column: int) -> QLineEdit:
    """The editor of cell (row, column), opened with its text selected."""
    index = table.model().index(row, column)
    table.scrollTo(index)
    table.setCurrentIndex(index)
    table.edit(index)
    editors = [w for w in table.viewport().findChildren(QLineEdit) if w.isVisible()]
    assert len(editors) == 1
    editors[0].selectAll()
    return editors[0]


def type_and_return(qtbot, table, row: int, column: int, text: str) -> None:
    """``text`` typed into cell (row, column) through the table's editor, then Return."""
    editor = _editor(table, row, column)
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.model().data(table.model().index(row, column)) == text)


def clear_and_return(qtbot, table, row: int, column: int) -> None:
    """Cell (row, column) emptied in the table's editor (Delete), then Return."""
    editor = _editor(table, row, column)
    qtbot.keyClick(editor, Qt.Key.Key_Delete)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.model().data(table.model().index(row, column)) == "")
