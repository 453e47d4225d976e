"""Qt table model over a :class:`models.readings.sheet.ReadingsSheet`, with undo."""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QAbstractTableModel, QModelIndex, QPersistentModelIndex, Qt, Signal
from PySide6.QtGui import QBrush, QColor, QUndoCommand, QUndoStack

from models.capture.take_cells import waiting_row
from models.certificate.readings_origin import PastedIn, SheetOrigin
from models.project.cell_marks import mark_to_json, marks_from_json
from models.readings.sheet import NumericRows, ReadingsSheet
from widgets.i18n import declared, on_language_change, tr, translated
from widgets.table_commands import (
    InsertRowsCommand,
    RemoveRowsCommand,
    ReplaceAllCommand,
    SetCellsCommand,
    SettingsCommand,
)

INVALID_BRUSH = QBrush(QColor(255, 205, 205))
MUTED_BRUSH = QBrush(QColor(235, 240, 250))
#: a row the analysis left out (positioning's reading of another position): a shade that
#: stands apart from the alternate rows' and the closures' at any scale, black text on it
#: still readable (gui77: the muted shade of a closure row was barely seen at 1280 × 720)
LEFT_OUT_BRUSH = QBrush(QColor(196, 204, 220))
EDITED_BRUSH = QBrush(QColor(255, 226, 160))  # a captured reading edited since
#: the text of a figure shown in a blank cell and worked out from its row (positioning's
#: measured − target): greyed, as no one typed it; still readable on every background
SHOWN_FOREGROUND = QBrush(QColor(96, 96, 96))
#: a take's reading that does not match its row's point (another face, another target)
WARNED_BRUSH = QBrush(QColor(255, 190, 120))

_Index = QModelIndex | QPersistentModelIndex
#: the roles :meth:`ReadingsTableModel.data` answers; the view asks about ten per cell at each
#: paint and column fit, and the others are turned away before any work (a capture's take
#: re-measures the columns, and this is most of its cost)
_ROLES = frozenset((Qt.ItemDataRole.DisplayRole, Qt.ItemDataRole.EditRole,
                    Qt.ItemDataRole.BackgroundRole, Qt.ItemDataRole.ToolTipRole,
                    Qt.ItemDataRole.ForegroundRole))


class ReadingsTableModel(QAbstractTableModel):
    """Shows the sheet's raw text; unreadable cells are red with the reason as tooltip.

    One extra blank row at the end takes new readings. Every edit goes through
    the undo stack. ``sheet_changed`` fires after any change of the cells.
    """

    sheet_changed = Signal()
    #: the sheet is about to be replaced as one undo step (:meth:`replace_all`: a paste over
    #: the sheet, an import, the fringe's live take), with the step's label: the view enters
    #: what is being typed in a cell first (widgets/readings_table_view.py)
    replacing = Signal(object)

    def __init__(self, sheet: ReadingsSheet, undo_stack: QUndoStack, parent=None) -> None:
        super().__init__(parent)
        self.sheet = sheet
        self.undo_stack = undo_stack
        self.highlight_rows: set[int] = set()  # rows drawn apart (e.g. the closure row)
        #: rows the analysis left out (its warnings say why): shaded clearly, and said so
        #: in their cells' tooltip
        self.left_out_rows: set[int] = set()
        #: {column: what its blank cells wait for} — a column the analysis needs that no row
        #: has filled yet (the polygon's face deviations before its certificate is loaded:
        #: plan80), said once by the presenter: its blank cells are not bad cells (not red),
        #: drawn as left out with that sentence as their tooltip. A cell typed wrong in it
        #: is still red
        self.awaited_columns: dict[int, str] = {}
        #: cells whose captured reading was edited since, with what to say of each
        #: (models/capture/edits.py): drawn apart, the text in their tooltip
        self.edited_cells: dict[tuple[int, int], str] = {}
        #: cells a take filled with a reading that does not match its row's point (the table
        #: at another face, the axis at another target: live76 F1), with the text the take
        #: wrote and what to say of it: drawn apart, the words in their tooltip, while the
        #: cell holds that text (undone, retyped or taken again, the mark goes). Rows
        #: inserted or removed above move them
        self.take_warnings: dict[tuple[int, int], tuple[str, str]] = {}
        #: the capture's takes of this workbench (models/capture/take_rows.TakeRows, set by
        #: the window): every command that moves rows moves them, before the sheet is said
        #: changed (review 61 F5: a row deleted above captured readings made them all look
        #: edited, with other rows' values, on the certificate)
        self.take_rows = None
        #: where the rows came from when one step replaced them all (models/certificate/
        #: readings_origin.SheetOrigin: a file imported, a paste, another workbench's; None:
        #: typed, or a project's), set and put back by that undo step (:attr:`origin_step`,
        #: None: at the bottom of the undo history)
        self.origin: SheetOrigin | None = None
        self.origin_step: QUndoCommand | None = None
        #: with no :attr:`origin_step` (the origin is the sheet's as it was opened: a
        #: project's record of it, models/certificate/stored_origin.py), whether the rows
        #: were edited before, and the rows pasted before (0-based, as opened)
        self.opened_edited = False
        self.opened_pasted: tuple[int, ...] = ()
        #: why a cell's text cannot be read, by (column, text): a column's parse depends on
        #: the text alone, and every paint asks it of every visible cell
        self._reasons: dict[tuple[int, str], str | None] = {}
        #: the columns of a reading (the workbench's plan_reading_keys): the rows at the end
        #: with their point's cells filled and these blank wait for their reading (the
        #: plan's next point, pre-filled), and their blank cells are not red (#62 review F8:
        #: every capture showed its next row as cells that cannot be read)
        self.reading_columns: tuple[int, ...] = ()
        #: the row the entry plan sends the next reading to (the presenter's), wherever it
        #: is: one in the middle whose reading was cleared waits for it too, its blank cells
        #: not red (None: a new row, or no plan)
        self.planned_row: Callable[[], int | None] = lambda: None
        #: the row a reading is being typed into by hand, some of its reading cells typed and
        #: the others blank (the presenter's: the last row with a reading, or the row the
        #: entry plan is filling): its blank reading cells wait, not red (row81: between the
        #: autocollimator's x and the encoder, every reading typed showed a bad cell). None:
        #: none
        self.typing_row: Callable[[], int | None] = lambda: None
        #: the figure a blank cell (row, column) shows, worked out from its row, with what
        #: to say of it (the presenter's: Workbench.shown_in_blank), or None: shown, greyed,
        #: never written into the sheet (the editor opens on the sheet's blank text)
        self.shown_in_blank: Callable[[int, int], tuple[str, str] | None] = lambda r, c: None
        #: the columns whose blank cells may show such a figure (repainted with every change)
        self.shown_columns: tuple[int, ...] = ()
        #: {column index: unit} the settings give a column (its header shows it)
        self.header_units: dict[int, str] = {}
        #: the cells an edit's own cells bring with them, in the same undo step (the
        #: presenter's; [] by default): a polygon face typed after its certificate was
        #: loaded gets its deviation (gui78)
        self.cells_brought: Callable[[list[tuple[int, int, str]]],
                                     list[tuple[int, int, str]]] = lambda changes: []
        #: the same for pasted rows that replace the whole sheet (Ctrl+A, Ctrl+V), each
        #: (row, column, text) of them: a full set of a polygon's readings pasted after its
        #: certificate was loaded gets the deviations kept by face, as rows pasted over
        #: part of the sheet do (leftovers 79)
        self.rows_brought: Callable[[list[list[str]]],
                                    list[tuple[int, int, str]]] = lambda rows: []
        self._waiting_from: int | None = None  # the first of them (None: none)
        self._planned: int | None = None
        self._typing: int | None = None
        self._waiting_known = False
        self.sheet_changed.connect(self.forget_waiting)
        self.sheet_changed.connect(self.shown_changed)
        on_language_change(self, self._on_language_changed)

    def forget_waiting(self) -> None:
        """The cells made or no longer waiting by a change (of the cells, or of the plan)
        repainted (their red)."""
        known = self._waiting_known
        before, planned_before = (self._waiting_from, self._planned) if known else (None, None)
        typing_before = self._typing if known else None
        self._waiting_known = False
        after = self.waiting_from()
        last = self.sheet.row_count - 1
        if before != after and last >= 0:
            first = min(r for r in (before, after) if r is not None)
            if first <= last:
                self.dataChanged.emit(self.index(first, 0),
                                      self.index(last, self.sheet.column_count - 1),
                                      [Qt.ItemDataRole.BackgroundRole,
                                       Qt.ItemDataRole.ToolTipRole])
        for row in ({planned_before, self._planned, typing_before, self._typing}
                    if (planned_before, typing_before) != (self._planned, self._typing) else ()):
            if row is not None and row <= last:
                self.dataChanged.emit(self.index(row, 0),
                                      self.index(row, self.sheet.column_count - 1),
                                      [Qt.ItemDataRole.BackgroundRole,
                                       Qt.ItemDataRole.ToolTipRole])

    def waiting_from(self) -> int | None:
        """The first of the rows at the end that wait for their reading (None: none)."""
        if not self._waiting_known:
            sheet = self.sheet
            numeric = isinstance(sheet.rows, NumericRows)
            self._waiting_from = None if numeric else waiting_row(
                sheet.row_count, sheet.column_count, self.reading_columns, sheet.text)
            self._planned = None if numeric else self.planned_row()
            self._typing = None if numeric else self.typing_row()
            self._waiting_known = True
        return self._waiting_from

    def is_waiting(self, r: int) -> bool:
        """Row ``r`` waits for its reading: one of the rows at the end that do
        (:meth:`waiting_from`), or the row the entry plan sends the next reading to."""
        waiting = self.waiting_from()
        return (waiting is not None and r >= waiting) or r == self._planned

    def is_typing(self, r: int) -> bool:
        """Row ``r`` is the row a reading is being typed into (:attr:`typing_row`)."""
        self.waiting_from()
        return r == self._typing

    def _on_language_changed(self) -> None:
        self.headerDataChanged.emit(Qt.Orientation.Horizontal, 0, self.sheet.column_count - 1)

    # -- read -----------------------------------------------------------
    def rowCount(self, parent: _Index = QModelIndex()) -> int:  # noqa: B008, N802
        return 0 if parent.isValid() else self.sheet.row_count + 1

    def columnCount(self, parent: _Index = QModelIndex()) -> int:  # noqa: B008, N802
        return 0 if parent.isValid() else self.sheet.column_count

    def data(self, index: _Index, role: int = Qt.ItemDataRole.DisplayRole):
        if role not in _ROLES or not index.isValid():
            return None
        r, c = index.row(), index.column()
        inside = r < self.sheet.row_count
        if role == Qt.ItemDataRole.EditRole:
            return self.sheet.text(r, c) if inside else ""
        if role == Qt.ItemDataRole.DisplayRole:
            text = self.sheet.text(r, c) if inside else ""
            if inside and c in self.shown_columns and not text.strip():
                shown = self.shown_in_blank(r, c)
                if shown is not None:
                    return shown[0]
            return text
        if not inside:
            return None
        if role == Qt.ItemDataRole.ForegroundRole:
            if c in self.shown_columns and not self.sheet.text(r, c).strip() \
                    and self.shown_in_blank(r, c) is not None:
                return SHOWN_FOREGROUND
            return None
        if role == Qt.ItemDataRole.BackgroundRole:
            if self.cleared_after_capture(r, c):
                return EDITED_BRUSH
            if self.cell_error(r, c) is not None:
                return INVALID_BRUSH
            if self.awaits(r, c):
                return LEFT_OUT_BRUSH
            if (r, c) in self.edited_cells:
                return EDITED_BRUSH
            if self.take_warning(r, c) is not None:
                return WARNED_BRUSH
            if r in self.left_out_rows:
                return LEFT_OUT_BRUSH
            if r in self.highlight_rows:
                return MUTED_BRUSH
            return None
        if role == Qt.ItemDataRole.ToolTipRole:
            if self.awaits(r, c):
                return translated(self.awaited_columns[c])
            reason = self.cell_error(r, c)
            edited = self.edited_cells.get((r, c))
            if reason is None and edited is not None:
                return translated(edited)
            warned = self.take_warning(r, c)
            if reason is None and warned is not None:
                return translated(warned)
            column = self.sheet.columns[c]  # the header the user sees, the file's key beside it
            why = (tr("Row {row}, {header} ({key}): {reason}").format(
                row=r + 1, header=declared(column.header), key=column.key,
                reason=translated(reason))
                if reason else None)
            if edited is not None and self.cleared_after_capture(r, c):
                # a cleared reading: what was captured, and why its row is left out
                return f"{translated(edited)}\n{why}"
            if why is None and c in self.shown_columns and not self.sheet.text(r, c).strip():
                shown = self.shown_in_blank(r, c)
                if shown is not None:
                    return declared(shown[1])
            if why is None and r in self.left_out_rows:
                return tr("Row {row} is left out of the analysis; the warnings above the "
                          "result say why").format(row=r + 1)
            return why
        return None

    def take_warning(self, r: int, c: int) -> str | None:
        """What a take said of the reading it wrote in cell (r, c), while the cell holds it."""
        warned = self.take_warnings.get((r, c))
        if warned is None or r >= self.sheet.row_count or self.sheet.text(r, c) != warned[0]:
            return None
        return warned[1]

    def warn_take(self, r: int, c: int, message: str) -> None:
        """Mark cell (r, c), as a take just wrote it, with ``message`` (a Message or text)."""
        self.take_warnings[(r, c)] = (self.sheet.text(r, c), message)
        index = self.index(r, c)
        self.dataChanged.emit(index, index, [Qt.ItemDataRole.BackgroundRole,
                                             Qt.ItemDataRole.ToolTipRole])

    def mark_records(self) -> list[dict]:
        """The cells' marks that hold (a take's reading at another face or target, its
        cell still holding that text), as a project file keeps them
        (models/project/cell_marks.py)."""
        keys = [c.key for c in self.sheet.columns]
        return [mark_to_json(r, keys[c], text, note)
                for (r, c), (text, note) in sorted(self.take_warnings.items())
                if r < self.sheet.row_count and c < len(keys) and self.sheet.text(r, c) == text]

    def set_mark_records(self, records: list[dict]) -> None:
        """The marks a project file kept (a project opened), on the cells they name
        (gui77: save, reopen, and the marks were gone)."""
        keys = [c.key for c in self.sheet.columns]
        self.take_warnings = {(r, keys.index(column)): (text, note)
                              for r, column, text, note in marks_from_json(records)
                              if column in keys}
        if self.sheet.row_count:
            self.dataChanged.emit(self.index(0, 0), self.index(self.sheet.row_count - 1,
                                                               self.sheet.column_count - 1),
                                  [Qt.ItemDataRole.BackgroundRole, Qt.ItemDataRole.ToolTipRole])

    def _move_warnings(self, at: int, count: int) -> None:
        """Rows inserted (``count`` > 0) or removed (< 0) at ``at``: the marks below move."""
        moved = {}
        for (r, c), warned in self.take_warnings.items():
            if r < at:
                moved[(r, c)] = warned
            elif count > 0 or r >= at - count:
                moved[(r + count, c)] = warned
        self.take_warnings = moved

    def cleared_after_capture(self, r: int, c: int) -> bool:
        """The cell of a captured reading the user emptied: an edit (marked so, its tooltip
        says what was captured), never a cell that cannot be read (it was red)."""
        return (r, c) in self.edited_cells and not self.sheet.text(r, c).strip()

    def awaits(self, r: int, c: int) -> bool:
        """Cell (r, c) is a blank cell of a column the analysis waits for
        (:attr:`awaited_columns`) in a row that is not blank."""
        return (c in self.awaited_columns and r < self.sheet.row_count
                and not self.sheet.text(r, c).strip() and not self.sheet.is_blank_row(r))

    def set_awaited_columns(self, columns: dict[int, str]) -> None:
        """The columns whose blank cells wait for what the presenter says once
        (:attr:`awaited_columns`); those columns repainted on a change."""
        if columns == self.awaited_columns:
            return
        changed = set(columns) | set(self.awaited_columns)
        self.awaited_columns = dict(columns)
        if self.sheet.row_count:
            for c in changed:
                self.dataChanged.emit(self.index(0, c), self.index(self.sheet.row_count - 1, c),
                                      [Qt.ItemDataRole.BackgroundRole,
                                       Qt.ItemDataRole.ToolTipRole])

    def cell_error(self, r: int, c: int) -> str | None:
        """The sheet's :meth:`~models.readings.sheet.ReadingsSheet.cell_error`, the parse
        remembered by column and text (a blank row is fine, asked each time, and so is a
        blank cell of a row waiting for its reading: :meth:`is_waiting`, one of a column
        the analysis waits for: :attr:`awaited_columns`, and a blank reading cell of the
        row a reading is being typed into: :meth:`is_typing`)."""
        if self.sheet.is_blank_row(r):
            return None
        key = (c, self.sheet.text(r, c))
        if not key[1].strip() and (self.is_waiting(r) or c in self.awaited_columns
                                   or (c in self.reading_columns and self.is_typing(r))):
            return None  # a row waiting for its reading, or a column: a cell not filled yet
        try:
            return self._reasons[key]
        except KeyError:
            pass
        if len(self._reasons) > 50_000:
            self._reasons.clear()
        reason = self._reasons[key] = self.sheet.cell_error(r, c)
        return reason

    def headerData(self, section: int, orientation: Qt.Orientation,  # noqa: N802
                   role: int = Qt.ItemDataRole.DisplayRole):
        if orientation == Qt.Orientation.Horizontal:
            column = self.sheet.columns[section]
            if role == Qt.ItemDataRole.DisplayRole:
                unit = self.header_units.get(section)
                if unit:  # a unit the settings give (Workbench.column_units)
                    # degrees as the headers' own "[deg]" are in each language ("θ [°]")
                    shown = tr("deg") if unit == "deg" else unit
                    return f"{declared(column.title)} [{shown}]"
                return declared(column.header)
            if role == Qt.ItemDataRole.ToolTipRole:
                return f"{column.key}: {declared(column.help)}" if column.help else column.key
            return None
        if role == Qt.ItemDataRole.DisplayRole:
            return str(section + 1) if section < self.sheet.row_count else "*"
        return None

    def flags(self, index: _Index) -> Qt.ItemFlag:
        if not index.isValid():
            return Qt.ItemFlag.NoItemFlags
        return Qt.ItemFlag.ItemIsSelectable | Qt.ItemFlag.ItemIsEnabled | Qt.ItemFlag.ItemIsEditable

    def set_highlight_rows(self, rows: set[int]) -> None:
        """Draw these rows apart (e.g. closure readings); repaints only on a change."""
        if rows != self.highlight_rows:
            self.highlight_rows = set(rows)
            if self.sheet.row_count:
                self.dataChanged.emit(self.index(0, 0), self.index(self.sheet.row_count - 1,
                                                                   self.sheet.column_count - 1),
                                      [Qt.ItemDataRole.BackgroundRole])

    def set_header_units(self, units: dict[int, str]) -> None:
        """The units the settings give some columns ({column index: unit}), in their
        headers; the header repainted on a change."""
        if units != self.header_units:
            self.header_units = dict(units)
            if self.sheet.column_count:
                self.headerDataChanged.emit(Qt.Orientation.Horizontal, 0,
                                            self.sheet.column_count - 1)

    def shown_changed(self) -> None:
        """The figures shown in blank cells repainted (the cells, or the settings they are
        worked out with, changed)."""
        if self.shown_columns and self.sheet.row_count:
            last = self.sheet.row_count - 1
            self.dataChanged.emit(self.index(0, min(self.shown_columns)),
                                  self.index(last, max(self.shown_columns)),
                                  [Qt.ItemDataRole.DisplayRole, Qt.ItemDataRole.ForegroundRole,
                                   Qt.ItemDataRole.ToolTipRole])

    def set_left_out_rows(self, rows: set[int]) -> None:
        """Shade the rows the analysis left out; repaints only on a change."""
        if rows != self.left_out_rows:
            changed = rows ^ self.left_out_rows
            self.left_out_rows = set(rows)
            last = self.sheet.row_count - 1
            for r in sorted(changed):
                if r <= last:
                    self.dataChanged.emit(self.index(r, 0),
                                          self.index(r, self.sheet.column_count - 1),
                                          [Qt.ItemDataRole.BackgroundRole,
                                           Qt.ItemDataRole.ToolTipRole])

    def set_edited_cells(self, cells: dict[tuple[int, int], str]) -> None:
        """Mark the cells of captured readings edited since (repaints only on a change)."""
        if cells != self.edited_cells:
            changed = set(cells) | set(self.edited_cells)
            self.edited_cells = dict(cells)
            for r, c in changed:
                index = self.index(r, c)
                self.dataChanged.emit(index, index, [Qt.ItemDataRole.BackgroundRole,
                                                     Qt.ItemDataRole.ToolTipRole])

    # -- undoable edits ---------------------------------------------------
    def setData(self, index: _Index, value, role: int = Qt.ItemDataRole.EditRole) -> bool:  # noqa: N802
        if role != Qt.ItemDataRole.EditRole or not index.isValid():
            return False
        text = "" if value is None else str(value)
        r, c = index.row(), index.column()
        if r < self.sheet.row_count and self.sheet.text(r, c) == text:
            return False
        if r >= self.sheet.row_count and not text:
            return False
        self.set_cells([(r, c, text)], tr("Edit row {row}").format(row=r + 1))
        return True

    def set_cells(self, changes: list[tuple[int, int, str]], label: str = "",
                  takes: list | None = None, columns: dict | None = None,
                  pasted: bool = False) -> None:
        """``takes``: ``(key, row)`` of a capture's takes whose reading these cells are: undone
        and redone with them (widgets/table_commands.SetCellsCommand); ``columns``: the
        keys of the columns each wrote, by its key; ``pasted``: the cells were pasted from
        the clipboard (:meth:`readings_origin`)."""
        changes = [(r, c, t) for r, c, t in changes if 0 <= c < self.sheet.column_count]
        if changes:
            changes += [(r, c, t) for r, c, t in self.cells_brought(changes)
                        if 0 <= c < self.sheet.column_count]
            self.undo_stack.push(SetCellsCommand(self, changes, label or tr("Edit cells"),
                                                 takes, columns, pasted))

    def insert_rows(self, at: int, count: int = 1) -> None:
        at = max(0, min(at, self.sheet.row_count))
        rows = [[""] * self.sheet.column_count for _ in range(count)]
        self.undo_stack.push(InsertRowsCommand(self, at, rows))

    def remove_rows(self, rows: list[int]) -> None:
        rows = sorted({r for r in rows if 0 <= r < self.sheet.row_count})
        if not rows:
            return
        blocks: list[tuple[int, int]] = []
        for r in rows:
            if blocks and blocks[-1][0] + blocks[-1][1] == r:
                blocks[-1] = (blocks[-1][0], blocks[-1][1] + 1)
            else:
                blocks.append((r, 1))
        self.undo_stack.push(RemoveRowsCommand(self, blocks, tr("Delete {rows} row(s)").format(
            rows=len(rows))))

    def readings_origin(self) -> tuple[SheetOrigin | None, bool, list[int], int]:
        """Where the rows came from (models/certificate/readings_origin.sheet_source's
        arguments): the step that replaced them all (None: none, or with no source), whether
        they were edited since other than by a paste (a step done above it in the undo
        history that changed rows: a change of settings is none, a step undone is none;
        with no source, only a change of a pasted row), the filled rows pasted since (as
        they are numbered now), and the filled rows' count. Day review 66: pasted rows were
        "readings typed in AngleBench"."""
        origin, edited, pasted = self.origin_since()
        filled = [r for r in range(self.sheet.row_count) if not self.sheet.is_blank_row(r)]
        return origin, edited, sorted(set(filled) & pasted), len(filled)

    def origin_since(self) -> tuple[SheetOrigin | None, bool, set[int]]:
        """:meth:`readings_origin` less the count of filled rows: the origin, whether the
        rows were edited since, and the rows pasted since (filled or not): what a project
        file keeps of it (models/certificate/stored_origin.py), cheap for a long sheet."""
        stack = self.undo_stack
        done = [stack.command(i) for i in range(stack.index())]
        start = next((i + 1 for i, step in enumerate(done) if step is self.origin_step), 0)
        edited = False
        pasted: set[int] = set()
        if self.origin_step is None:  # the sheet's origin as it was opened, and since
            edited, pasted = self.opened_edited, set(self.opened_pasted)
        for step in done[start:]:
            commands = [step.child(i) for i in range(step.childCount())] or [step]
            paste = any(getattr(command, "pasted", False) for command in commands)
            for command in commands:
                if isinstance(command, SettingsCommand):
                    continue
                if isinstance(command, SetCellsCommand):
                    rows = command.rows()
                    if paste:  # the plan's cells of the pasted rows are in the paste's step
                        pasted |= rows
                        continue
                    changed = self.origin is not None or bool(rows & pasted)
                elif isinstance(command, InsertRowsCommand):
                    pasted = {r + command.count if r >= command.at else r for r in pasted}
                    changed = self.origin is not None
                elif isinstance(command, RemoveRowsCommand):
                    gone = sorted(command.removed_rows)
                    pasted = {r - sum(1 for g in gone if g < r) for r in pasted
                              if r not in command.removed_rows}
                    changed = self.origin is not None or bool(pasted & set(gone))
                else:
                    changed = self.origin is not None
                edited = edited or changed
        return self.origin, edited, pasted

    def forget_origin(self) -> None:
        """The rows are another's now (a project was opened): no import's."""
        self.origin = self.origin_step = None
        self.opened_edited, self.opened_pasted = False, ()

    def set_opened_origin(self, origin: SheetOrigin | None, edited: bool,
                          pasted: tuple[int, ...]) -> None:
        """The rows' origin as a project opened says it (at the bottom of the undo
        history): ``origin`` (None: typed), ``edited`` and the rows ``pasted`` since."""
        self.origin, self.origin_step = origin, None
        self.opened_edited, self.opened_pasted = bool(edited), tuple(pasted)

    def replace_all(self, rows: list[list[str]], label: str = "",
                    checked: bool = False, replaces: str = "",
                    origin: SheetOrigin | None = None) -> None:
        """Replace every row (one undo step); ``checked``: rows already fit the columns;
        ``replaces``: the instrument whose earlier takes the rows replace, in the same step
        (the fringe's live take: widgets/table_commands.py ReplaceAllCommand). What is being
        typed in a cell is entered before, as its own step (:attr:`replacing`). ``origin``:
        where the rows come from (a file, a paste, another workbench; None: typed or taken
        in the window; :meth:`readings_origin`)."""
        label = label or tr("Replace readings")
        if isinstance(origin, PastedIn):  # the cells they bring, in the same step
            brought = [(r, c, t) for r, c, t in self.rows_brought(rows)
                       if 0 <= r < len(rows) and 0 <= c < len(rows[r])]
            if brought:
                rows = [list(row) for row in rows]
                for r, c, t in brought:
                    rows[r][c] = t
        self.replacing.emit(label)
        self.undo_stack.push(ReplaceAllCommand(self, rows, label, checked, replaces, origin))

    # -- raw operations used by the commands ------------------------------
    def apply_cells(self, changes: list[tuple[int, int, str]]) -> None:
        if not changes:
            return
        max_row = max(r for r, _, _ in changes)
        first_blank = self.sheet.row_count
        if max_row >= self.sheet.row_count:
            first = self.sheet.row_count + 1  # the trailing blank row already exists
            self.beginInsertRows(QModelIndex(), first, max_row + 1)
            for r, c, t in changes:
                self.sheet.set_text(r, c, t)
            self.endInsertRows()
        else:
            for r, c, t in changes:
                self.sheet.set_text(r, c, t)
        rows = [r for r, _, _ in changes]
        self.dataChanged.emit(self.index(min(rows), 0),
                              self.index(max(rows), self.sheet.column_count - 1))
        if max_row >= first_blank:  # rows were added: their numbers (and the "*") move
            self.headerDataChanged.emit(Qt.Orientation.Vertical, min(rows), self.sheet.row_count)
        self.sheet_changed.emit()

    def truncate_rows(self, count: int) -> None:
        if self.sheet.row_count > count:
            self.apply_remove(count, self.sheet.row_count - count)

    def move_takes(self, takes) -> None:
        """``takes(take_rows)``: what a command does to the captured readings' rows."""
        if takes is not None and self.take_rows is not None:
            takes(self.take_rows)

    def apply_insert(self, at: int, rows: list[list[str]], takes=None) -> None:
        """``takes``: given the model's :attr:`take_rows`, moves them (the commands'; a
        project opened, or an undone take's row cut off at the end, moves none)."""
        self.beginInsertRows(QModelIndex(), at, at + len(rows) - 1)
        self.sheet.insert_rows(at, rows)
        self.endInsertRows()
        self._move_warnings(at, len(rows))
        self.move_takes(takes)
        self.headerDataChanged.emit(Qt.Orientation.Vertical, at, self.sheet.row_count)
        self.sheet_changed.emit()

    def apply_remove(self, at: int, count: int, takes=None) -> list[list[str]]:
        self.beginRemoveRows(QModelIndex(), at, at + count - 1)
        removed = self.sheet.remove_rows(at, count)
        self.endRemoveRows()
        self._move_warnings(at, -count)
        self.move_takes(takes)
        self.headerDataChanged.emit(Qt.Orientation.Vertical, at, self.sheet.row_count)
        self.sheet_changed.emit()
        return removed

    def apply_replace(self, rows: list[list[str]], checked: bool = False, takes=None) -> None:
        self.beginResetModel()
        try:
            self.sheet.adopt_rows(rows, checked)
        except ValueError:
            self.sheet.replace_all(rows)
        self.take_warnings = {}  # of rows that are gone
        self.endResetModel()
        self.move_takes(takes)
        self.sheet_changed.emit()
