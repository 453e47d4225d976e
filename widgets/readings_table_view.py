"""Table view of readings: type, paste blocks from a spreadsheet, copy out, add/delete rows."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QGuiApplication, QKeySequence
from PySide6.QtWidgets import QAbstractItemView, QHeaderView, QMenu, QTableView

from models.readings.tabular_import import split_pasted_text
from widgets.readings_table_model import ReadingsTableModel


class ReadingsTableView(QTableView):
    """A QTableView with the clipboard and row commands a technician expects.

    Paste starts at the current cell and fills right and down, adding rows as
    needed; one undo step undoes the whole paste. Delete clears the selected
    cells; the row commands insert above the current row or delete the
    selected rows.
    """

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self._setup_ui()

    def _setup_ui(self) -> None:
        self.setSelectionMode(QAbstractItemView.SelectionMode.ExtendedSelection)
        self.setAlternatingRowColors(True)
        self.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
        self.verticalHeader().setDefaultSectionSize(22)
        self.setContextMenuPolicy(Qt.ContextMenuPolicy.ActionsContextMenu)
        self.copy_action = self._action("Copy", QKeySequence.StandardKey.Copy, self.copy_selection)
        self.paste_action = self._action("Paste", QKeySequence.StandardKey.Paste, self.paste)
        self.clear_action = self._action("Clear cells", QKeySequence.StandardKey.Delete,
                                         self.clear_selection)
        self.insert_action = self._action("Insert row above", QKeySequence("Ctrl+I"),
                                          self.insert_row)
        self.delete_rows_action = self._action("Delete rows", QKeySequence("Ctrl+-"),
                                               self.delete_rows)

    def _action(self, text: str, shortcut, slot) -> QAction:
        action = QAction(text, self)
        action.setShortcut(shortcut)
        action.setShortcutContext(Qt.ShortcutContext.WidgetWithChildrenShortcut)
        action.triggered.connect(slot)
        self.addAction(action)
        return action

    def readings_model(self) -> ReadingsTableModel:
        model = self.model()
        assert isinstance(model, ReadingsTableModel)
        return model

    # -- clipboard ------------------------------------------------------
    def selected_text(self) -> str:
        indexes = self.selectedIndexes()
        if not indexes:
            return ""
        rows = sorted({i.row() for i in indexes})
        cols = sorted({i.column() for i in indexes})
        chosen = {(i.row(), i.column()) for i in indexes}
        model = self.readings_model()
        lines = []
        for r in rows:
            cells = [model.data(model.index(r, c)) or "" if (r, c) in chosen else "" for c in cols]
            lines.append("\t".join(cells))
        return "\n".join(lines)

    def copy_selection(self) -> None:
        QGuiApplication.clipboard().setText(self.selected_text())

    def paste(self) -> None:
        self.paste_text(QGuiApplication.clipboard().text())

    def paste_text(self, text: str) -> None:
        grid = split_pasted_text(text)
        if not grid:
            return
        current = self.currentIndex()
        top = current.row() if current.isValid() else 0
        left = current.column() if current.isValid() else 0
        changes = [
            (top + i, left + j, cell.strip())
            for i, row in enumerate(grid)
            for j, cell in enumerate(row)
            if left + j < self.readings_model().columnCount()
        ]
        self.readings_model().set_cells(changes, f"Paste {len(grid)} row(s)")

    def clear_selection(self) -> None:
        model = self.readings_model()
        changes = [(i.row(), i.column(), "") for i in self.selectedIndexes()
                   if i.row() < model.sheet.row_count and model.sheet.text(i.row(), i.column())]
        model.set_cells(changes, "Clear cells")

    # -- rows -----------------------------------------------------------
    def insert_row(self) -> None:
        current = self.currentIndex()
        self.readings_model().insert_rows(current.row() if current.isValid() else 0)

    def delete_rows(self) -> None:
        self.readings_model().remove_rows([i.row() for i in self.selectedIndexes()])

    def contextMenuEvent(self, event) -> None:  # noqa: N802
        menu = QMenu(self)
        for action in self.actions():
            menu.addAction(action)
        menu.exec(event.globalPos())
