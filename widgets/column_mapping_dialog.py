"""Which of a file's headers holds which column, when they are not recognised: one choice per
column with the file's first rows previewed as they would be read, and a box to remember the
choice for files with the same headers."""

from __future__ import annotations

from PySide6.QtCore import QT_TR_NOOP
from PySide6.QtWidgets import (
    QAbstractItemView,
    QCheckBox,
    QComboBox,
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
)

from models.readings.headers import match_header
from widgets.i18n import declared, tr

NONE = QT_TR_NOOP("(not in the file)")


class ColumnMappingDialog(QDialog):
    def __init__(self, columns, header: list[str], preview: list[list[str]], reason: str,
                 parent=None) -> None:
        super().__init__(parent)
        self.setWindowTitle(tr("Which column is which?"))
        self.columns, self.header, self.preview_rows = list(columns), list(header), preview
        self.choices: dict[str, QComboBox] = {}
        form = QFormLayout()
        guess = match_header(header, columns)
        for column, found in zip(self.columns, guess, strict=True):
            box = QComboBox()
            box.addItem(tr(NONE), "")
            for h in header:
                box.addItem(h, h)
            if found is not None:
                box.setCurrentIndex(found + 1)
            box.currentIndexChanged.connect(self._refresh)
            self.choices[column.key] = box
            form.addRow(declared(column.header) + ("" if column.required else tr(" (optional)")),
                        box)
        self.preview = QTableWidget(0, len(self.columns))
        self.preview.setHorizontalHeaderLabels([declared(c.header) for c in self.columns])
        self.preview.setEditTriggers(QAbstractItemView.EditTrigger.NoEditTriggers)
        self.remember = QCheckBox(tr("Remember for files with these headers"))
        self.remember.setChecked(True)
        self.problem = QLabel()
        self.problem.setStyleSheet("color: #b00020;")
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                        | QDialogButtonBox.StandardButton.Cancel)
        self.buttons.accepted.connect(self.accept)
        self.buttons.rejected.connect(self.reject)
        layout = QVBoxLayout(self)
        note = QLabel(reason)
        note.setWordWrap(True)
        layout.addWidget(note)
        layout.addLayout(form)
        layout.addWidget(QLabel(tr("The first rows as they would be read:")))
        layout.addWidget(self.preview)
        layout.addWidget(self.problem)
        layout.addWidget(self.remember)
        layout.addWidget(self.buttons)
        self._refresh()

    def mapping(self) -> dict[str, str]:
        return {key: box.currentData() or "" for key, box in self.choices.items()}

    def _refresh(self) -> None:
        positions = {key: (self.header.index(h) if h in self.header else None)
                     for key, h in self.mapping().items()}
        self.preview.setRowCount(len(self.preview_rows))
        for r, row in enumerate(self.preview_rows):
            for c, column in enumerate(self.columns):
                p = positions[column.key]
                self.preview.setItem(r, c, QTableWidgetItem(row[p] if p is not None
                                                            and p < len(row) else ""))
        missing = [declared(c.header) for c in self.columns
                   if c.required and positions[c.key] is None]
        self.problem.setText(tr("Still needed: {columns}").format(columns=", ".join(missing))
                             if missing else "")
        self.buttons.button(QDialogButtonBox.StandardButton.Ok).setEnabled(not missing)
