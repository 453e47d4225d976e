"""The signal tolerance presets, edited (#45): the built-in ones shown read-only ("Copy to
edit"), the lab's own added, copied, renamed, deleted, each band (quantity, unit, inside
low/high, outer low/high or empty) and the source text edited.

The dialog works on a copy: nothing is stored until *Save*, and *Cancel* leaves the presets
as they were. A cell that does not hold (not a number, low above high, an outer band that
does not contain the inside band, a quantity twice) is marked red with the reason in its
tooltip and in the dialog's message, as the user types; *Save* refuses while any lab preset
has one (the preset is shown, the cell marked), and never drops the other presets.

:meth:`PresetEditorDialog.presets` gives every preset after *Save* (the built-in ones as they
are and the lab's own, as :class:`~models.fringe.signal_tolerance.TolerancePreset`);
:meth:`PresetEditorDialog.stored` the list the lab defaults keep.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

from PySide6.QtCore import Qt
from PySide6.QtGui import QBrush, QColor
from PySide6.QtWidgets import (
    QAbstractItemView,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QHBoxLayout,
    QHeaderView,
    QLabel,
    QLineEdit,
    QListWidget,
    QPlainTextEdit,
    QPushButton,
    QStyledItemDelegate,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from models.fringe.signal_tolerance import (
    BUILTIN_PRESETS,
    INTERFACES,
    LAB_DEFAULTS_KEY,
    QUANTITIES,
    PresetError,
    TolerancePreset,
    lab_defaults_with_presets,
    preset_from_dict,
    preset_to_dict,
)
from widgets.i18n import declared, live, tr, translated

__all__ = ["COLUMNS", "PresetEditorDialog"]

#: the band table's columns
COLUMNS = ("quantity", "unit", "inside_low", "inside_high", "outer_low", "outer_high")
BAD = QColor("#ffcdd2")
#: the column of a problem with the preset's name
NAME = -2


def quantity_titles() -> dict[str, str]:
    return {"amplitude_a": tr("Amplitude A (sin)"), "amplitude_b": tr("Amplitude B (cos)"),
            "amplitude_ratio": tr("Ratio B/A"), "phase_deviation": tr("Phase B − A − 90°"),
            "offset_a": tr("Offset A"), "offset_b": tr("Offset B"),
            "harmonic_content": tr("Harmonic content")}


def _number_text(value: float) -> str:
    return f"{value:.10g}"


def _number(text: str) -> float | None:
    """The number typed (a Unicode minus and a decimal comma taken), None when it is not one."""
    text = text.strip().replace("−", "-").replace(",", ".")
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def _is_builtin(preset: TolerancePreset) -> bool:
    return any(p == preset for p in BUILTIN_PRESETS)


class _QuantityDelegate(QStyledItemDelegate):
    """The quantity column: its key stored, its title shown, chosen from a list."""

    def displayText(self, value, locale) -> str:  # noqa: N802 - Qt's name
        return quantity_titles().get(str(value), str(value))

    def createEditor(self, parent, option, index):  # noqa: N802 - Qt's name
        box = QComboBox(parent)
        for key, title in quantity_titles().items():
            box.addItem(title, key)
        return box

    def setEditorData(self, editor, index) -> None:  # noqa: N802 - Qt's name
        editor.setCurrentIndex(max(0, editor.findData(index.data(Qt.ItemDataRole.EditRole))))

    def setModelData(self, editor, model, index) -> None:  # noqa: N802 - Qt's name
        model.setData(index, editor.currentData(), Qt.ItemDataRole.EditRole)


class PresetEditorDialog(QDialog):
    def __init__(self, presets: Sequence[TolerancePreset], parent=None) -> None:
        super().__init__(parent)
        #: the presets being edited: dicts of preset_to_dict's form with the band cells as
        #: typed (texts), "builtin" True for a built-in one as it is
        self.entries: list[dict] = [self._entry(p) for p in presets]
        self._current = -1
        self._showing = False
        self._result: list[TolerancePreset] | None = None
        self._setup_ui()
        self._layout()
        live(self.setWindowTitle, tr("Signal tolerance presets"))
        self.resize(1000, 580)
        self._fill_list()
        self.list.setCurrentRow(0 if self.entries else -1)

    @staticmethod
    def _entry(preset: TolerancePreset) -> dict:
        data = preset_to_dict(preset)
        data["builtin"] = _is_builtin(preset)
        data["cells"] = [[b.quantity, b.unit, _number_text(b.inside[0]),
                          _number_text(b.inside[1]),
                          "" if b.outer is None else _number_text(b.outer[0]),
                          "" if b.outer is None else _number_text(b.outer[1])]
                         for b in preset.bands]
        return data

    # ------------------------------------------------------------------ the widgets
    def _setup_ui(self) -> None:
        self.list = QListWidget()
        self.list.setWordWrap(True)  # a built-in preset's name is long
        self.list.setTextElideMode(Qt.TextElideMode.ElideNone)
        self.list.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.list.setSpacing(2)
        self.add_button, self.copy_button = QPushButton(), QPushButton()
        self.delete_button = QPushButton()
        live(self.add_button.setText, tr("Add"))
        live(self.copy_button.setText, tr("Copy"))
        live(self.delete_button.setText, tr("Delete"))
        self.readonly_note = QLabel()
        self.readonly_note.setWordWrap(True)
        self.readonly_note.setStyleSheet("QLabel { color: #5d4037; background: #fff8e1; "
                                         "padding: 3px; }")
        live(self.readonly_note.setText, tr("A built-in preset cannot be changed: Copy it "
                                            "to edit the copy."))
        self.name = QLineEdit()
        self.key_label = QLabel()
        self.key_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.interface = QComboBox()
        for interface in INTERFACES:
            self.interface.addItem(interface, interface)
        self.source = QPlainTextEdit()
        self.source.setMaximumHeight(90)
        self.table = QTableWidget(0, len(COLUMNS))
        self.table.setItemDelegateForColumn(0, _QuantityDelegate(self.table))
        self.table.setSelectionBehavior(QAbstractItemView.SelectionBehavior.SelectItems)
        header = self.table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.Stretch)
        header.setSectionResizeMode(0, QHeaderView.ResizeMode.ResizeToContents)
        self.add_band_button, self.remove_band_button = QPushButton(), QPushButton()
        live(self.add_band_button.setText, tr("Add band"))
        live(self.remove_band_button.setText, tr("Remove band"))
        self.message = QLabel()
        self.message.setWordWrap(True)
        self.message.setStyleSheet("QLabel { color: #c62828; }")
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Save
                                        | QDialogButtonBox.StandardButton.Cancel)

    def _layout(self) -> None:
        left = QVBoxLayout()
        left.addWidget(self.list, 1)
        row = QHBoxLayout()
        for button in (self.add_button, self.copy_button, self.delete_button):
            row.addWidget(button)
        left.addLayout(row)
        form = QFormLayout()
        self.name_label, self.key_title = QLabel(), QLabel()
        self.interface_label, self.source_label = QLabel(), QLabel()
        form.addRow(self.name_label, self.name)
        form.addRow(self.key_title, self.key_label)
        form.addRow(self.interface_label, self.interface)
        form.addRow(self.source_label, self.source)
        right = QVBoxLayout()
        right.addWidget(self.readonly_note)
        right.addLayout(form)
        right.addWidget(self.table, 1)
        band_row = QHBoxLayout()
        band_row.addWidget(self.add_band_button)
        band_row.addWidget(self.remove_band_button)
        band_row.addStretch(1)
        right.addLayout(band_row)
        right.addWidget(self.message)
        body = QHBoxLayout()
        left_widget = QWidget()
        left_widget.setLayout(left)
        left_widget.setFixedWidth(280)
        body.addWidget(left_widget)
        body.addLayout(right, 1)
        outer = QVBoxLayout(self)
        outer.addLayout(body, 1)
        outer.addWidget(self.buttons)
        live(self.name_label.setText, tr("Name"))
        live(self.key_title.setText, tr("Key"))
        live(self.interface_label.setText, tr("Interface"))
        live(self.source_label.setText, tr("Source (the document the bands come from)"))
        self.table.setHorizontalHeaderLabels([
            tr("Quantity"), tr("Unit"), tr("Inside low"), tr("Inside high"), tr("Outer low"),
            tr("Outer high")])
        tips = {1: tr("For the offsets, % is the asymmetry (P − N)/2M of the channel; any other "
                      "unit is the offset in the stream's unit × scale"),
                4: tr("Optional: the wider band still acceptable (empty: none)"),
                5: tr("Optional: the wider band still acceptable (empty: none)")}
        for column, tip in tips.items():
            self.table.horizontalHeaderItem(column).setToolTip(tip)
        self.list.currentRowChanged.connect(self._select)
        self.add_button.clicked.connect(self.add_preset)
        self.copy_button.clicked.connect(self.copy_preset)
        self.delete_button.clicked.connect(self.delete_preset)
        self.add_band_button.clicked.connect(self.add_band)
        self.remove_band_button.clicked.connect(self.remove_band)
        self.name.textEdited.connect(self._renamed)
        self.table.itemChanged.connect(lambda _item: self._edited())
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)

    # ------------------------------------------------------------------ the list
    def _title(self, entry: dict) -> str:
        if entry["builtin"]:
            return tr("{name} (built-in)").format(name=declared(entry["name"]))
        return entry["name"] or entry["key"]

    def _fill_list(self) -> None:
        self.list.blockSignals(True)
        self.list.clear()
        for entry in self.entries:
            self.list.addItem(self._title(entry))
        self.list.blockSignals(False)

    def _select(self, row: int) -> None:
        if self._showing:
            return
        self._store_current()
        self._current = row
        self._show(row)

    @property
    def current(self) -> dict | None:
        return self.entries[self._current] if 0 <= self._current < len(self.entries) else None

    def _unique_key(self) -> str:
        keys = {e["key"] for e in self.entries}
        n = 1
        while f"lab_{n}" in keys:
            n += 1
        return f"lab_{n}"

    def _append(self, entry: dict) -> None:
        self._store_current()
        self.entries.append(entry)
        self._fill_list()
        self._current = -1
        self.list.setCurrentRow(len(self.entries) - 1)
        self.name.setFocus()
        self.name.selectAll()

    def add_preset(self) -> None:
        """A new lab preset: one band to start from."""
        self._append({"key": self._unique_key(), "name": tr("New preset"), "interface": "1Vpp",
                      "source": "", "builtin": False,
                      "cells": [["amplitude_a", "Vpp", "", "", "", ""]]})

    def copy_preset(self) -> None:
        """A lab preset copied from the one shown (a built-in one's name in the window's
        language)."""
        self._store_current()
        entry = self.current
        if entry is None:
            return
        name = declared(entry["name"]) if entry["builtin"] else entry["name"]
        self._append({**entry, "key": self._unique_key(), "builtin": False,
                      "name": tr("{name} (copy)").format(name=name),
                      "cells": [list(cells) for cells in entry["cells"]]})

    def delete_preset(self) -> None:
        entry = self.current
        if entry is None or entry["builtin"]:
            return
        row = self._current
        del self.entries[row]
        self._current = -1
        self._fill_list()
        self.list.setCurrentRow(min(row, len(self.entries) - 1))

    def _renamed(self, text: str) -> None:
        entry = self.current
        if entry is not None and not entry["builtin"]:
            entry["name"] = text
            self.list.item(self._current).setText(self._title(entry))
            self._edited()

    # ------------------------------------------------------------------ one preset
    def _show(self, row: int) -> None:
        entry = self.current
        self._showing = True
        self.table.blockSignals(True)
        try:
            readonly = entry is None or entry["builtin"]
            self.readonly_note.setVisible(entry is not None and entry["builtin"])
            self.name.setText("" if entry is None else
                              declared(entry["name"]) if entry["builtin"] else entry["name"])
            self.key_label.setText("" if entry is None else entry["key"])
            self.interface.setCurrentIndex(max(0, self.interface.findData(
                entry["interface"] if entry else "1Vpp")))
            self.source.setPlainText("" if entry is None else entry["source"])
            self.table.setRowCount(0)
            for cells in (entry["cells"] if entry else []):
                self._add_row(cells)
            for widget in (self.name, self.source):
                widget.setReadOnly(readonly)
            self.interface.setEnabled(not readonly)
            self.table.setEditTriggers(
                QAbstractItemView.EditTrigger.NoEditTriggers if readonly else
                QAbstractItemView.EditTrigger.DoubleClicked
                | QAbstractItemView.EditTrigger.EditKeyPressed
                | QAbstractItemView.EditTrigger.AnyKeyPressed
                | QAbstractItemView.EditTrigger.SelectedClicked)
            for button in (self.add_band_button, self.remove_band_button, self.delete_button):
                button.setEnabled(not readonly)
            self.copy_button.setEnabled(entry is not None)
        finally:
            self.table.blockSignals(False)
            self._showing = False
        self._mark(self.problems(entry) if entry and not entry["builtin"] else [])

    def _add_row(self, cells: Sequence[str]) -> None:
        row = self.table.rowCount()
        self.table.insertRow(row)
        for column, text in enumerate(cells):
            item = QTableWidgetItem()
            item.setData(Qt.ItemDataRole.EditRole, text)
            if column >= 2:
                item.setTextAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            self.table.setItem(row, column, item)

    def add_band(self) -> None:
        entry = self.current
        if entry is None or entry["builtin"]:
            return
        used = {self._cell(r, 0) for r in range(self.table.rowCount())}
        quantity = next((q for q in QUANTITIES if q not in used), QUANTITIES[0])
        self.table.blockSignals(True)
        self._add_row([quantity, "", "", "", "", ""])
        self.table.blockSignals(False)
        self._edited()
        self.table.setCurrentCell(self.table.rowCount() - 1, 2)

    def remove_band(self) -> None:
        entry = self.current
        row = self.table.currentRow()
        if entry is None or entry["builtin"] or row < 0:
            return
        self.table.removeRow(row)
        self._edited()

    def _cell(self, row: int, column: int) -> str:
        item = self.table.item(row, column)
        value = item.data(Qt.ItemDataRole.EditRole) if item is not None else ""
        return "" if value is None else str(value)

    def _store_current(self) -> None:
        """The preset shown, as typed, into its entry (a built-in one is not changed)."""
        entry = self.current
        if entry is None or entry["builtin"]:
            return
        entry["name"] = self.name.text()
        entry["interface"] = self.interface.currentData()
        entry["source"] = self.source.toPlainText()
        entry["cells"] = [[self._cell(r, c) for c in range(len(COLUMNS))]
                          for r in range(self.table.rowCount())]

    def _edited(self) -> None:
        if self._showing:
            return
        self._store_current()
        entry = self.current
        if entry is not None and not entry["builtin"]:
            self._mark(self.problems(entry))

    # ------------------------------------------------------------------ validation
    def problems(self, entry: dict) -> list[tuple[int, int, str]]:
        """What does not hold in a lab preset: (band row, column, why); row −1 for the
        preset's own fields (its name, its bands as a whole)."""
        out: list[tuple[int, int, str]] = []
        if not entry["name"].strip():
            out.append((-1, NAME, tr("The preset needs a name")))
        if not entry["cells"]:
            out.append((-1, -1, tr("The preset needs at least one band")))
        seen: set[str] = set()
        titles = quantity_titles()
        for row, cells in enumerate(entry["cells"]):
            quantity = cells[0]
            title = titles.get(quantity, quantity)
            if quantity not in QUANTITIES:
                out.append((row, 0, tr("Row {row}: choose a quantity").format(row=row + 1)))
            elif quantity in seen:
                out.append((row, 0, tr("Row {row}: {quantity} has a band already").format(
                    row=row + 1, quantity=title)))
            seen.add(quantity)
            numbers = {}
            for column in range(2, 6):
                text = cells[column].strip()
                if column >= 4 and not text:
                    numbers[column] = None
                    continue
                value = _number(text)
                if value is None:
                    out.append((row, column, tr("Row {row}, {column}: '{text}' is not a "
                                                "number").format(
                        row=row + 1, column=self._column_title(column), text=text)))
                numbers[column] = value
            low, high = numbers.get(2), numbers.get(3)
            if low is not None and high is not None and low > high:
                out.append((row, 2, tr("Row {row}: the inside band's low {low} is above its "
                                       "high {high}").format(row=row + 1, low=cells[2].strip(),
                                                             high=cells[3].strip())))
            olow, ohigh = numbers.get(4), numbers.get(5)
            texts = (cells[4].strip(), cells[5].strip())
            if bool(texts[0]) != bool(texts[1]):
                column = 4 if not texts[0] else 5
                out.append((row, column, tr("Row {row}: the outer band needs both its low and "
                                            "its high (or neither)").format(row=row + 1)))
            elif olow is not None and ohigh is not None:
                if olow > ohigh:
                    out.append((row, 4, tr("Row {row}: the outer band's low {low} is above its "
                                           "high {high}").format(row=row + 1, low=texts[0],
                                                                 high=texts[1])))
                elif low is not None and high is not None and low <= high:
                    if olow > low:
                        out.append((row, 4, tr("Row {row}: the outer band must contain the "
                                               "inside band (outer low {outer} is above "
                                               "inside low {inside})").format(
                            row=row + 1, outer=texts[0], inside=cells[2].strip())))
                    if ohigh < high:
                        out.append((row, 5, tr("Row {row}: the outer band must contain the "
                                               "inside band (outer high {outer} is below "
                                               "inside high {inside})").format(
                            row=row + 1, outer=texts[1], inside=cells[3].strip())))
        return out

    def _column_title(self, column: int) -> str:
        return self.table.horizontalHeaderItem(column).text()

    def _mark(self, problems: list[tuple[int, int, str]]) -> None:
        """The cells that do not hold red, with the reason as their tooltip; the message."""
        self.table.blockSignals(True)
        bad = {(r, c): why for r, c, why in problems if r >= 0}
        for row in range(self.table.rowCount()):
            for column in range(len(COLUMNS)):
                item = self.table.item(row, column)
                if item is None:
                    continue
                why = bad.get((row, column))
                item.setBackground(QBrush(BAD) if why else QBrush())
                item.setToolTip(why or "")
        self.table.blockSignals(False)
        self.name.setStyleSheet("QLineEdit { background: #ffcdd2; }"
                                if any(c == NAME for _, c, _ in problems) else "")
        self.message.setText("\n".join(why for _, _, why in problems))

    def marked(self) -> dict[tuple[int, int], str]:
        """The band cells marked now: (row, column) → why."""
        out = {}
        for row in range(self.table.rowCount()):
            for column in range(len(COLUMNS)):
                item = self.table.item(row, column)
                if item is not None and item.toolTip():
                    out[(row, column)] = item.toolTip()
        return out

    # ------------------------------------------------------------------ the result
    def _preset(self, entry: dict) -> TolerancePreset:
        if entry["builtin"]:
            return next(p for p in BUILTIN_PRESETS if p.key == entry["key"])
        bands = []
        for cells in entry["cells"]:
            outer = ([_number(cells[4]), _number(cells[5])]
                     if cells[4].strip() or cells[5].strip() else None)
            bands.append({"quantity": cells[0], "unit": cells[1].strip(),
                          "inside": [_number(cells[2]), _number(cells[3])], "outer": outer})
        return preset_from_dict({"key": entry["key"], "name": entry["name"].strip(),
                                 "interface": entry["interface"],
                                 "source": entry["source"].strip(), "bands": bands})

    def accept(self) -> None:
        """Save: refused (the first preset that does not hold shown, its cells marked) until
        every lab preset holds."""
        self._store_current()
        presets = []
        for row, entry in enumerate(self.entries):
            problems = [] if entry["builtin"] else self.problems(entry)
            preset = None
            if not problems:
                try:
                    preset = self._preset(entry)
                except PresetError as exc:  # what the table's own checks missed
                    problems = [(-1, -1, translated(str(exc)))]
            if problems:
                self.list.setCurrentRow(row)
                self._mark(problems)
                return
            presets.append(preset)
        self._result = presets
        super().accept()

    def presets(self) -> list[TolerancePreset] | None:
        """Every preset as saved (None before Save)."""
        return self._result

    def stored(self) -> list[dict]:
        """The lab's own presets as the lab defaults keep them (after Save)."""
        defaults = lab_defaults_with_presets({}, self._result or [])
        return list(defaults.get(LAB_DEFAULTS_KEY, []))
