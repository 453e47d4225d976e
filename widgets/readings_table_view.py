"""Table view of readings: type, paste blocks from a spreadsheet, copy out, add/delete rows."""

from __future__ import annotations

from PySide6.QtCore import QPersistentModelIndex, Qt, QTimer, Signal
from PySide6.QtGui import QAction, QGuiApplication, QKeySequence
from PySide6.QtWidgets import (
    QAbstractItemDelegate,
    QAbstractItemView,
    QHeaderView,
    QLineEdit,
    QMenu,
    QMessageBox,
    QStyledItemDelegate,
    QTableView,
)

from models.certificate.readings_origin import PastedIn
from models.readings.paste import plan_paste
from models.readings.tabular_import import RawTable, split_pasted_text
from widgets.i18n import live, tr
from widgets.readings_table_model import ReadingsTableModel
from widgets.shortcuts import key_sequences


class _TypingDelegate(QStyledItemDelegate):
    """The default editor, watched: what is typed in it before it is entered can be
    autosaved (a reading being typed is not lost with the window), and no repaint of the
    table puts the cell's text back over it.

    Qt gives an open editor the cell's text again at every ``dataChanged`` that covers its
    cell, whatever the roles (QAbstractItemView::dataChanged → setEditorData): a row
    highlight, the shading after an analysis, a take into another cell of the row put the
    old text back, what was typed but not yet entered lost (and typing on wrote a wrong
    number). An editor typed into since it was filled (``QLineEdit.isModified``) keeps its
    text; a real change of its cell meanwhile is the view's
    (:meth:`ReadingsTableView.dataChanged`)."""

    typing = Signal()

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.editor: QLineEdit | None = None
        self.index = QPersistentModelIndex()
        #: the row the last editor opened in, and whether it was empty then (the entry
        #: plan fills the plan's cells of a row typed into only when it was: plan_return)
        self.opened_in: tuple[int, bool] = (-1, True)
        #: ``opened_in`` of the editor whose text was last entered (setModelData): Tab
        #: opens the next cell's editor before the closed one is told of (closeEditor)
        self.entered_in: tuple[int, bool] = (-1, True)
        #: the cell's text the open editor was last filled with ("" when none is open)
        self.loaded = ""

    def createEditor(self, parent, option, index):  # noqa: N802 - Qt's name
        editor = super().createEditor(parent, option, index)
        model = index.model()
        self.opened_in = (index.row(), all(
            not str(model.index(index.row(), c).data() or "").strip()
            for c in range(model.columnCount())))
        if isinstance(editor, QLineEdit):
            self.editor, self.index = editor, QPersistentModelIndex(index)
            editor.textEdited.connect(self.typing)
            editor.destroyed.connect(self._editor_gone)
        return editor

    def setEditorData(self, editor, index) -> None:  # noqa: N802 - Qt's name
        if isinstance(editor, QLineEdit) and editor.isModified():
            return  # typed into: a repaint never puts the cell's text back over it
        super().setEditorData(editor, index)
        if editor is self.editor:
            self.loaded = editor.text()

    def setModelData(self, editor, model, index) -> None:  # noqa: N802 - Qt's name
        self.entered_in = self.opened_in
        super().setModelData(editor, model, index)

    def typed(self) -> QLineEdit | None:
        """The open editor when it was typed into since it was filled, else None."""
        editor = self.editor
        return editor if editor is not None and editor.isModified() else None

    def destroyEditor(self, editor, index) -> None:  # noqa: N802 - Qt's name
        if editor is self.editor:
            self._editor_gone()
        super().destroyEditor(editor, index)

    def _editor_gone(self, *_args) -> None:
        self.editor, self.index, self.loaded = None, QPersistentModelIndex(), ""


class ReadingsTableView(QTableView):
    """A QTableView with the clipboard and row commands a technician expects.

    Paste starts at the current cell and fills right and down, adding rows as
    needed; one undo step undoes the whole paste. Delete clears the selected
    cells; the row commands insert above the current row or delete the
    selected rows.
    """

    #: a message for the status line (the workbench's view shows it): the cell being typed
    #: in was changed by another path, what was typed not entered (:meth:`dataChanged`).
    #: An object, not a str: a ``Signal(str)`` gave the slot a plain copy of the message,
    #: which the status line could not say again after View › Language (day review 64 P6)
    notice = Signal(object)

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.nominal_column: int | None = None  # filled from the step as rows are added
        self.entry_column = 0  # where a row's readings begin
        self.nominal_step = 0.0  # 0: off
        self.readings_per_point = 1  # n readings of a point: the nominal advances every n rows
        # a pasted block in the workbench's own layout (RawTable -> rows | None; the
        # presenter sets Workbench.rows_from_table): unrolled into readings, the sheet replaced
        self.own_layout = None
        # the entry plan (the presenter's WorkbenchPresenter.plan_return): Return after a
        # reading fills the plan's cells and gives the row the next reading goes to; None
        # (or it returns None): no plan, the nominal step as before
        self.plan_return = None
        # … and a reading left by Tab, a click or another cell (the presenter's
        # WorkbenchPresenter.plan_typed): the row's plan cells, the cursor not moved
        self.plan_typed = None
        # the entry plan's part in a paste (the presenter's WorkbenchPresenter.plan_paste):
        # given the block's first row and its row count before the paste, what fills the
        # plan's cells of the pasted rows after it (in the paste's undo step) and returns what
        # to say of it; None: no plan
        self.plan_paste = None
        self._typing_delegate = _TypingDelegate(self)
        self.setItemDelegate(self._typing_delegate)
        #: a value is being typed in a cell (not yet entered): the window autosaves it
        self.typing = self._typing_delegate.typing
        self._setup_ui()
        # after the view's own handling: the edit is committed and the editor closed
        self.itemDelegate().closeEditor.connect(self._editor_closed)

    def pending_edit(self) -> tuple[int, int, str] | None:
        """(row, column, text) of a cell's editor whose text differs from the cell's, while
        it is open; None otherwise. Open is the delegate's editor, not the view's state: rows
        deleted elsewhere leave the view's state at NoState with the editor open (Qt), and
        what was typed in it was then neither autosaved nor looked after."""
        delegate = self._typing_delegate
        editor, index = delegate.editor, delegate.index
        if editor is None or not index.isValid():
            return None
        shown = index.data(Qt.ItemDataRole.EditRole)
        text = editor.text()
        if text == ("" if shown is None else str(shown)):
            return None
        return index.row(), index.column(), text

    def setModel(self, model) -> None:  # noqa: N802 - Qt's name
        super().setModel(model)
        if isinstance(model, ReadingsTableModel):
            model.replacing.connect(self._enter_before_replacement)
            model.modelAboutToBeReset.connect(self._before_reset)

    def _typed_edit(self) -> tuple[QLineEdit, int, int, str] | None:
        """The open editor typed into, its row, column and text, when the text differs from
        its cell's (what a change of the cells would lose); None otherwise."""
        editor, pending = self._typing_delegate.typed(), self.pending_edit()
        return None if editor is None or pending is None else (editor, *pending)

    def _header(self, column: int):
        return self.model().headerData(column, Qt.Orientation.Horizontal,
                                       Qt.ItemDataRole.DisplayRole)

    def _say_after(self, text) -> None:
        """``text`` to the status line once the change under way is done: after the
        window's own handling of a replaced sheet (which takes away the messages about the
        old sheet's rows) and after the message of what replaced it."""
        QTimer.singleShot(0, self, lambda: self.notice.emit(text))

    def _enter_before_replacement(self, label) -> None:
        """The sheet is about to be replaced as one undo step (``label``: a paste over the
        sheet, the fringe's live take, an import). What is typed in a cell and reads as its
        column's value is entered first, as Return would enter it (its own undo step, before
        the replacement's: Edit › Undo of the replacement shows it), and the status line
        says so; what does not read is left to :meth:`_before_reset` (before: the reset
        closed the editor and what was typed was gone without a word)."""
        typed = self._typed_edit()
        if typed is None:
            return
        editor, row, column, text = typed
        try:
            self.readings_model().sheet.columns[column].parse(text)
        except ValueError:
            return
        header = self._header(column)
        self.commitData(editor)
        self.closeEditor(editor, QAbstractItemDelegate.EndEditHint.NoHint)
        self._say_after(tr("Row {row}, {column}: what you typed (“{typed}”) was entered, then "
                           "the readings were replaced ({what})").format(
            row=row + 1, column=header, typed=text, what=label))

    def enter_typed(self) -> bool:
        """What is typed in a cell and not yet entered, entered as Return enters it (its own
        undo step; a text that does not read is kept and marked, as typed); True when
        something was entered. The window does this before it closes, so that the question
        about unsaved work sees it (before, Ctrl+Q with a value still being typed neither
        saved nor asked, and the autosave holding it was deleted: day review, stop 65)."""
        typed = self._typed_edit()
        if typed is None:
            return False
        editor = typed[0]
        self.commitData(editor)
        self.closeEditor(editor, QAbstractItemDelegate.EndEditHint.NoHint)
        return True

    def _before_reset(self) -> None:
        """Every row is about to be replaced by a path that cannot enter what is typed first
        (File › New or Open, Edit › Undo or Redo of a replacement) or with a text that does
        not read: the editor is closed, nothing entered, and the status line says what was
        typed (Qt's reset closed it without a word)."""
        typed = self._typed_edit()
        if typed is None:
            return
        editor, row, column, text = typed
        header = self._header(column)
        self.closeEditor(editor, QAbstractItemDelegate.EndEditHint.NoHint)
        self._say_after(tr("Row {row}, {column}: what you typed (“{typed}”) was not entered: "
                           "the readings were replaced while you were typing in it").format(
            row=row + 1, column=header, typed=text))

    def rowsAboutToBeRemoved(self, parent, start: int, end: int) -> None:  # noqa: N802
        """Rows deleted (Delete rows, Edit › Undo of an insert): an editor typed into in one
        of them is closed, nothing entered (its row is going), and the status line says what
        was typed (Qt closed it without a word)."""
        typed = self._typed_edit()
        if typed is not None and not parent.isValid() and start <= typed[1] <= end:
            editor, row, column, text = typed
            header = self._header(column)
            self.closeEditor(editor, QAbstractItemDelegate.EndEditHint.NoHint)
            self._say_after(tr("Row {row}, {column}: what you typed (“{typed}”) was not "
                               "entered: the row was removed while you were typing in it")
                            .format(row=row + 1, column=header, typed=text))
        super().rowsAboutToBeRemoved(parent, start, end)

    def dataChanged(self, top_left, bottom_right, roles=()) -> None:  # noqa: N802 - Qt's name
        """Cells changed or repainted. An editor typed into keeps its text through any
        repaint (the delegate's setEditorData); but when its own cell's text was changed
        by another path meanwhile (a take into the cell being typed in, an undo), the
        change stands: the editor is closed without entering what was typed, and the
        status line says both (never a typed number silently written over a reading, nor a
        reading silently replaced by one)."""
        delegate = self._typing_delegate
        editor, index = delegate.typed(), delegate.index
        if editor is not None and index.isValid() and \
                top_left.row() <= index.row() <= bottom_right.row() and \
                top_left.column() <= index.column() <= bottom_right.column():
            shown = index.data(Qt.ItemDataRole.EditRole)
            now = "" if shown is None else str(shown)
            typed = editor.text()
            if now not in (delegate.loaded, typed):  # not a repaint, nor its own commit
                row, column = index.row(), index.column()
                self.closeEditor(editor, QAbstractItemDelegate.EndEditHint.NoHint)
                header = self.model().headerData(column, Qt.Orientation.Horizontal,
                                                 Qt.ItemDataRole.DisplayRole)
                self.notice.emit(tr("Row {row}, {column} was changed to “{value}” while you "
                                    "were typing in it; what you typed (“{typed}”) was not "
                                    "entered").format(row=row + 1, column=header, value=now,
                                                      typed=typed))
        super().dataChanged(top_left, bottom_right, list(roles))

    def _setup_ui(self) -> None:
        self.setSelectionMode(QAbstractItemView.SelectionMode.ExtendedSelection)
        self.setAlternatingRowColors(True)
        self.horizontalHeader().setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
        self.verticalHeader().setDefaultSectionSize(22)
        self.setContextMenuPolicy(Qt.ContextMenuPolicy.ActionsContextMenu)
        self.copy_action = self._action(tr("Copy"), QKeySequence.StandardKey.Copy,
                                        self.copy_selection)
        self.paste_action = self._action(tr("Paste"), QKeySequence.StandardKey.Paste, self.paste)
        self.clear_action = self._action(tr("Clear cells"), QKeySequence.StandardKey.Delete,
                                         self.clear_selection)
        self.insert_action = self._action(tr("Insert row above"), QKeySequence("Ctrl+I"),
                                          self.insert_row)
        self.delete_rows_action = self._action(tr("Delete rows"), QKeySequence("Ctrl+-"),
                                               self.delete_rows)

    def _action(self, text: str, shortcut, slot) -> QAction:
        action = QAction(text, self)
        live(action.setText, text)
        action.setShortcuts(key_sequences(shortcut))
        action.setShortcutContext(Qt.ShortcutContext.WidgetWithChildrenShortcut)
        action.triggered.connect(slot)
        self.addAction(action)
        return action

    # -- instrument-style entry ----------------------------------------------
    def _editor_closed(self, _editor, hint) -> None:
        """Return after typing a reading goes to the next row's first cell to type (not the
        same cell): its nominal value when there is no step, else the reading after the
        nominal, filled from the step when it is empty."""
        row = self.currentIndex().row()
        if hint == QAbstractItemDelegate.EndEditHint.SubmitModelCache and row >= 0:
            opened, blank = self._typing_delegate.opened_in
            self.next_row(row, blank_before=blank or opened != row)
        elif hint != QAbstractItemDelegate.EndEditHint.RevertModelCache \
                and self.plan_typed is not None:
            # left otherwise than by Return (Tab, a click): the cursor has moved (Tab has
            # opened the next cell's editor already); the row is the one entered into
            entered, blank = self._typing_delegate.entered_in
            self._typing_delegate.entered_in = (-1, True)  # told once
            if entered >= 0:
                self.plan_typed(entered, blank)

    def next_row(self, row: int, blank_before: bool = True) -> None:
        """After a reading entered in ``row`` (Return, or a take): the cursor to the cell the
        next reading goes to — unless a value is being typed in another cell (a take made
        while the technician types): moving would enter what is typed so far (Qt commits an
        open editor when the current cell changes), so the cursor stays with the editor.
        ``blank_before``: the row was empty before the reading (the entry plan fills only such
        a row's plan cells: the presenter's plan_return)."""
        if self.plan_return is not None:
            target_row = self.plan_return(row, blank_before)
            if target_row is not None:
                self._go_to(self.readings_model().index(target_row, self.entry_column))
                return
        model = self.readings_model()
        sheet = model.sheet
        nominal = self.nominal_column
        if self.nominal_step and nominal is not None and row < sheet.row_count:
            text = sheet.text(row, nominal).strip()
            below = sheet.text(row + 1, nominal).strip() if row + 1 < sheet.row_count else ""
            try:
                value = float(text.replace(",", "."))
            except ValueError:
                value = None
            if value is not None and not below:
                step = self.nominal_step if self._point_complete(row, text) else 0.0
                model.set_cells([(row + 1, nominal, f"{value + step:.10g}")],
                                tr("Next nominal"))
        # with a step the nominal is filled in: its first reading; without one the
        # technician types the nominal too: the row's first column
        stepped = self.nominal_step and nominal is not None
        column = self.entry_column if stepped or nominal is None else nominal
        self._go_to(model.index(row + 1, column))

    def _go_to(self, target) -> None:
        """The cursor to ``target``, unless a value is being typed (asked after the cells
        this entry fills are written: one written into the editor's own cell closed it)."""
        if self.pending_edit() is None:
            self.setCurrentIndex(target)
            self.scrollTo(target)

    def _point_complete(self, row: int, text: str) -> bool:
        """Whether ``row`` is the last of its point's ``readings_per_point`` readings (the rows
        above it with the same nominal text, counted back to the first that differs)."""
        sheet = self.readings_model().sheet
        count = 1
        while count < self.readings_per_point and row - count >= 0 and \
                sheet.text(row - count, self.nominal_column).strip() == text:
            count += 1
        return count >= self.readings_per_point

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
            # the sheet's text: a figure only shown in a blank cell (positioning's measured −
            # target) is not copied, a paste back never gives a row both, disagreeing
            cells = [model.data(model.index(r, c), Qt.ItemDataRole.EditRole) or ""
                     if (r, c) in chosen else "" for c in cols]
            lines.append("\t".join(cells))
        return "\n".join(lines)

    def copy_selection(self) -> None:
        QGuiApplication.clipboard().setText(self.selected_text())

    def paste(self) -> None:
        self.paste_text(QGuiApplication.clipboard().text())

    def paste_text(self, text: str) -> str:
        """Paste a block (see models/readings/paste.py); returns what was done: "replace",
        "overwrite", "cells" or "" (nothing)."""
        grid = split_pasted_text(text)
        if not grid:
            return ""
        model = self.readings_model()
        own = self.own_layout(RawTable("", grid[0], grid[1:], list(range(2, len(grid) + 1)))) \
            if self.own_layout is not None and len(grid) > 1 else None
        if own:
            model.replace_all(own, tr("Paste {rows} row(s), replacing the sheet").format(
                rows=len(own)), checked=True, origin=PastedIn())
            return "replace"
        sheet = model.sheet
        filled = sum(1 for r in range(sheet.row_count) if any(
            sheet.text(r, c).strip() for c in range(sheet.column_count)))
        current = self.currentIndex()
        top = current.row() if current.isValid() else 0
        left = current.column() if current.isValid() else 0
        selected_rows = {i.row() for i in self.selectedIndexes()}
        whole = filled > 1 and set(range(filled)) <= selected_rows
        plan = plan_paste(grid, sheet.columns, filled, top, left, whole)
        width = sheet.column_count
        full = [(([""] * plan.left) + r + [""] * width)[:width] for r in plan.rows]
        label = (tr("Paste {rows} row(s) (header row left out)") if plan.header
                 else tr("Paste {rows} row(s)")).format(rows=len(plan.rows))
        choice = "replace" if plan.replace_sheet else "cells"
        if plan.leaves_rows:
            choice = self.ask_paste(len(plan.rows), plan.leaves_rows)
            if not choice:
                return ""
        if choice == "replace":
            model.replace_all(full, tr("{paste}, replacing the sheet").format(paste=label),
                              checked=True, origin=PastedIn())
            # said of the sheet as replaced: a column the rows brought cells to (a polygon's
            # deviations kept by face) is not "left empty"
            columns_said = self._columns_said(plan, True)
            if columns_said:
                self._say_after(columns_said)
            return "replace"
        columns_said = self._columns_said(plan, False)
        changes = [(top + i, plan.left + j, cell) for i, row in enumerate(plan.rows)
                   for j, cell in enumerate(row) if plan.left + j < width]
        pasted = self.plan_paste(top, len(plan.rows)) if self.plan_paste is not None else None
        planned = ""
        if pasted is None:
            model.set_cells(changes, label, pasted=True)
        else:  # the paste and the plan's cells of its rows: one undo step
            model.undo_stack.beginMacro(label)
            try:
                model.set_cells(changes, label, pasted=True)
                planned = pasted()
            finally:
                model.undo_stack.endMacro()
        said = [t for t in (columns_said, planned) if t]
        if said:
            self.notice.emit(said[0] if len(said) == 1 else
                             tr("{said}; {more}").format(said=said[0], more=said[1]))
        return "overwrite" if plan.leaves_rows else "cells"

    def _columns_said(self, plan, replaces: bool) -> str:
        """What a paste does with the columns, when it is more than the block's columns
        landing on the sheet's: the block's columns beyond the sheet's last one (left out),
        and, when it replaces the sheet, the sheet's columns it leaves empty. "" otherwise."""
        sheet = self.readings_model().sheet
        width = sheet.column_count
        # the sheet's columns the block left empty (``replaces``: asked of the sheet once
        # replaced, where cells the rows brought may fill one)
        empty = [c for c in range(width) if c not in plan.filled and not any(
            sheet.text(r, c).strip() for r in range(sheet.row_count))] if replaces else []
        if not plan.dropped and not empty:
            return ""
        names = ", ".join(str(self._header(c)) for c in plan.filled) or "—"
        text = tr("Pasted into {columns}").format(columns=names)
        if empty:
            text = text + tr("; {columns} left empty").format(
                columns=", ".join(str(self._header(c)) for c in empty))
        if plan.dropped:
            first, last = plan.dropped[0] + 1, plan.dropped[-1] + 1
            numbers = str(first) if first == last else f"{first}–{last}"
            text = text + tr("; the block's column(s) {numbers} left out: the sheet has no "
                             "column for them").format(numbers=numbers)
        return text

    def ask_paste(self, block_rows: int, left_behind: int) -> str:
        """A shorter block over a longer run: "replace", "overwrite" or "" (cancel)."""
        box = QMessageBox(QMessageBox.Icon.Question, tr("Paste readings"),
                          tr("The {pasted} pasted rows land on a run of {run}; {left} row(s) of "
                             "the old run would stay below them and be analysed with them.")
                          .format(pasted=block_rows, run=block_rows + left_behind,
                                  left=left_behind), parent=self)
        replace = box.addButton(tr("Replace the sheet"), QMessageBox.ButtonRole.AcceptRole)
        overwrite = box.addButton(tr("Overwrite rows 1–{rows} only").format(rows=block_rows),
                                  QMessageBox.ButtonRole.DestructiveRole)
        box.addButton(QMessageBox.StandardButton.Cancel)
        box.setDefaultButton(replace)
        box.exec()
        clicked = box.clickedButton()
        return "replace" if clicked is replace else "overwrite" if clicked is overwrite else ""

    def clear_selection(self) -> None:
        model = self.readings_model()
        changes = [(i.row(), i.column(), "") for i in self.selectedIndexes()
                   if i.row() < model.sheet.row_count and model.sheet.text(i.row(), i.column())]
        model.set_cells(changes, tr("Clear cells"))

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
