"""Undoable edits of a readings table (QUndoCommand subclasses)."""

from __future__ import annotations

from PySide6.QtGui import QUndoCommand

from widgets.i18n import tr


class SetCellsCommand(QUndoCommand):
    """Set many cells at once (typing one cell, pasting a block, clearing a selection)."""

    def __init__(self, model, changes: list[tuple[int, int, str]], label: str) -> None:
        super().__init__(label)
        self._model = model
        self._changes = changes
        self._old_rows = model.sheet.row_count
        self._old: list[tuple[int, int, str]] = []

    def redo(self) -> None:
        self._old = [(r, c, self._model.sheet.text(r, c) if r < self._model.sheet.row_count else "")
                     for r, c, _ in self._changes]
        self._model.apply_cells(self._changes)

    def undo(self) -> None:
        self._model.apply_cells(self._old)
        self._model.truncate_rows(self._old_rows)


class InsertRowsCommand(QUndoCommand):
    def __init__(self, model, at: int, rows: list[list[str]], label: str = "") -> None:
        super().__init__(label or tr("Insert rows"))
        self._model, self._at, self._rows = model, at, rows

    def redo(self) -> None:
        self._model.apply_insert(self._at, self._rows)

    def undo(self) -> None:
        self._model.apply_remove(self._at, len(self._rows))


class RemoveRowsCommand(QUndoCommand):
    """Remove rows given as sorted, non-overlapping (start, count) blocks."""

    def __init__(self, model, blocks: list[tuple[int, int]], label: str = "") -> None:
        super().__init__(label or tr("Delete rows"))
        self._model, self._blocks = model, blocks
        self._removed: list[tuple[int, list[list[str]]]] = []

    def redo(self) -> None:
        self._removed = []
        for start, count in reversed(self._blocks):
            self._removed.append((start, self._model.apply_remove(start, count)))

    def undo(self) -> None:
        for start, rows in reversed(self._removed):
            self._model.apply_insert(start, rows)


class ReplaceAllCommand(QUndoCommand):
    """Replace every row (import of a file, loading a sample)."""

    def __init__(self, model, rows: list[list[str]], label: str, checked: bool = False) -> None:
        super().__init__(label)
        self._model, self._new, self._checked = model, rows, checked
        self._old: list[list[str]] = []

    def redo(self) -> None:
        # the row lists themselves change hands: edits after the import mutate them, and
        # their own commands undo those edits first
        self._old = self._model.sheet.rows
        self._model.apply_replace(self._new, self._checked)
        self._checked = True  # from now on the rows are the sheet's own

    def undo(self) -> None:
        self._new = self._model.sheet.rows
        self._model.apply_replace(self._old, checked=True)


class SettingsCommand(QUndoCommand):
    """A change of a workbench's set-up (Edit › Undo puts the fields back as they were).

    ``apply`` takes the settings to show and analyse with; the first redo (on push) applies
    what the user already sees."""

    def __init__(self, apply, old: dict, new: dict, label: str) -> None:
        super().__init__(label)
        self._apply, self._old, self._new = apply, dict(old), dict(new)

    def redo(self) -> None:
        self._apply(self._new)

    def undo(self) -> None:
        self._apply(self._old)
