"""Undoable edits of a readings table (QUndoCommand subclasses).

The commands that move rows move the capture's takes with them, undo and redo included
(models/capture/take_rows.py, through the model's ``take_rows``): an undo puts back exactly
the takes its command detached."""

from __future__ import annotations

from PySide6.QtGui import QUndoCommand

from widgets.i18n import tr


class SetCellsCommand(QUndoCommand):
    """Set many cells at once (typing one cell, pasting a block, clearing a selection).

    ``takes``: a capture's take, ``(key, row)`` of each take whose reading these cells are
    (models/capture/take_rows.py), ``columns`` the keys of the columns each wrote. The take
    and its cells are one step: its undo undoes the takes too (no cell claims them: a
    reading typed there later is not "edited after capture", review 62 F4), its redo puts
    them back. A take supersedes an older take of its instrument in its row (cleared and
    taken again, review 62 F1), and its undo gives the row back to that one. The takes are
    in their sessions before the push, undone (-1), so that the first redo is every redo:
    the sheet is said changed with the takes in their rows (the window marked the older
    take's reading edited until the next change)."""

    def __init__(self, model, changes: list[tuple[int, int, str]], label: str,
                 takes: list | None = None, columns: dict | None = None,
                 pasted: bool = False) -> None:
        super().__init__(label)
        self._model = model
        self._changes = changes
        #: the cells were pasted from the clipboard (not typed): what the certificate's
        #: "Readings:" says of their rows (models/certificate/readings_origin.sheet_source)
        self.pasted = pasted
        self._takes = list(takes or [])
        #: the keys of the columns each take wrote, by its key (what it supersedes)
        self._columns = dict(columns or {})
        self._old_rows = model.sheet.row_count
        self._old: list[tuple[int, int, str]] = []

    def rows(self) -> set[int]:
        """The rows whose cells this step sets (their numbers when it was done)."""
        return {r for r, _, _ in self._changes}

    def redo(self) -> None:
        self._old = [(r, c, self._model.sheet.text(r, c) if r < self._model.sheet.row_count else "")
                     for r, c, _ in self._changes]
        if self._takes:  # before the cells: the sheet is said changed with its takes in place
            self._model.move_takes(lambda takes: takes.taken(self._takes, self._columns))
        self._model.apply_cells(self._changes)

    def undo(self) -> None:
        if self._takes:
            self._model.move_takes(lambda takes: takes.untaken(self._takes))
        self._model.apply_cells(self._old)
        self._model.truncate_rows(self._old_rows)


class InsertRowsCommand(QUndoCommand):
    def __init__(self, model, at: int, rows: list[list[str]], label: str = "") -> None:
        super().__init__(label or tr("Insert rows"))
        self._model, self._at, self._rows = model, at, rows
        #: where the rows go and how many: what moves the rows below (read by the model's
        #: readings_origin)
        self.at, self.count = at, len(rows)
        self._detached: list = []  # takes made into the rows, detached by the undo

    def redo(self) -> None:
        def move(takes) -> None:
            takes.inserted(self._at, len(self._rows))
            takes.reattach(self._detached)

        self._model.apply_insert(self._at, self._rows, move)

    def undo(self) -> None:
        def move(takes) -> None:
            self._detached = takes.removed(self._at, len(self._rows))

        self._model.apply_remove(self._at, len(self._rows), move)


class RemoveRowsCommand(QUndoCommand):
    """Remove rows given as sorted, non-overlapping (start, count) blocks."""

    def __init__(self, model, blocks: list[tuple[int, int]], label: str = "") -> None:
        super().__init__(label or tr("Delete rows"))
        self._model, self._blocks = model, blocks
        #: the rows removed (0-based, before the removal): what moves the rows below
        self.removed_rows = frozenset(r for start, count in blocks
                                      for r in range(start, start + count))
        #: per block, bottom first: its start, its rows and the takes detached with them
        self._removed: list[tuple[int, list[list[str]], list]] = []

    def redo(self) -> None:
        self._removed = []
        for start, count in reversed(self._blocks):
            detached: list = []
            rows = self._model.apply_remove(
                start, count, lambda takes, s=start, n=count, d=detached:
                d.extend(takes.removed(s, n)))
            self._removed.append((start, rows, detached))

    def undo(self) -> None:
        for start, rows, detached in reversed(self._removed):
            def move(takes, s=start, r=rows, d=detached) -> None:
                takes.inserted(s, len(r))
                takes.reattach(d)

            self._model.apply_insert(start, rows, move)


class ReplaceAllCommand(QUndoCommand):
    """Replace every row (import of a file, loading a sample, the fringe's live take).

    ``replaces``: the instrument whose earlier takes the new rows replace (the fringe's live
    signals, ``"signals"``): they are marked replaced (row -1) by this command, so its undo
    gives them back their rows and its redo replaces them again (a retake marked them
    outside any command: its undo left the earlier take's readings unclaimed)."""

    def __init__(self, model, rows: list[list[str]], label: str, checked: bool = False,
                 replaces: str = "", origin=None) -> None:
        super().__init__(label)
        self._model, self._new, self._checked = model, rows, checked
        self._replaces = replaces
        #: where the new rows came from (models/certificate/readings_origin.SheetOrigin:
        #: a file, a paste, another workbench; None: typed or taken in the window), the
        #: model's while this step is
        #: done; the undo puts back the earlier rows' origin with them (day review 65 F4)
        self._origin = origin
        self._old_origin: tuple = (None, None)
        #: the earlier takes of ``replaces`` this replacement replaced, at their rows then
        self._replaced: list = []
        self._old: list[list[str]] = []
        #: the takes whose rows the replacement took away (None: not yet replaced); a redo
        #: detaches these again, not the takes made since (the fringe's live take adds its
        #: own right after replacing the readings)
        self._detached: list | None = None
        #: the takes made into the replacement (the fringe's live take), undone by the undo
        #: and put back by the redo (review 62 F4: they claimed the rows of the sheet put
        #: back, typed by hand, as "edited after capture")
        self._made: list = []

    def redo(self) -> None:
        def move(takes) -> None:
            if self._detached is None:
                if self._replaces:
                    self._replaced = takes.replaced_by_later_take(self._replaces)
                self._detached = takes.replaced()
            else:
                takes.undone(self._replaced)
                takes.detach(self._detached)
                takes.redone(self._made)

        # the row lists themselves change hands: edits after the import mutate them, and
        # their own commands undo those edits first
        self._old = self._model.sheet.rows
        self._old_origin = (self._model.origin, self._model.origin_step)
        self._model.origin, self._model.origin_step = self._origin, self
        self._model.apply_replace(self._new, self._checked, move)
        self._checked = True  # from now on the rows are the sheet's own

    def undo(self) -> None:
        self._new = self._model.sheet.rows
        def move(takes) -> None:
            self._made = takes.undo_replacement()
            takes.reattach(self._detached or [])
            takes.unreplaced(self._replaced)

        self._model.origin, self._model.origin_step = self._old_origin
        self._model.apply_replace(self._old, checked=True, takes=move)


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


class KeptValueCommand(QUndoCommand):
    """A value a workbench keeps beside its rows set (a polygon certificate's deviations by
    face, loaded before the faces have rows: gui78); ``apply`` takes the value to keep. An
    undo step, so that the project counts as changed and its undo puts the old one back."""

    def __init__(self, apply, old, new, label: str) -> None:
        super().__init__(label)
        self._apply, self._old, self._new = apply, old, new

    def redo(self) -> None:
        self._apply(self._new)

    def undo(self) -> None:
        self._apply(self._old)
