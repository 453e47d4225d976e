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
    QStyle,
    QTableWidget,
    QTableWidgetItem,
    QVBoxLayout,
    QWidget,
)

from models.readings.headers import match_header
from widgets.i18n import declared, tr
from widgets.screen_fit import fit_to_screen
from widgets.vertical_scroll import vertical_scroll_area

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
        self.problem.setWordWrap(True)
        # the reason, the choices and the preview scroll on a small screen (200 % on a
        # 1280×720 laptop: 360 logical pixels; the dialog was 403 tall, OK and Cancel off
        # it); what is still needed, the box and the buttons stay in sight
        self.content = QWidget()
        self.inner = inner = QVBoxLayout(self.content)
        inner.setContentsMargins(0, 0, 0, 0)
        note = QLabel(reason)
        note.setWordWrap(True)
        inner.addWidget(note)
        inner.addLayout(form)
        inner.addWidget(QLabel(tr("The first rows as they would be read:")))
        inner.addWidget(self.preview)
        self.area = vertical_scroll_area(self.content)
        self.outer = layout = QVBoxLayout(self)
        layout.addWidget(self.area, 1)
        layout.addWidget(self.problem)
        layout.addWidget(self.remember)
        layout.addWidget(self.buttons)
        self._refresh()
        self._fit()

    def _fit(self) -> None:
        """As wide as its choices and every column of the preview want, as tall as all of
        it, at most the screen (the reason, choices and preview scroll below)."""
        scroll_bar = self.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent, None, self)
        margins = self.outer.contentsMargins()
        self.preview.resizeColumnsToContents()
        table = (self.preview.verticalHeader().sizeHint().width()
                 + self.preview.horizontalHeader().length() + 2 * self.preview.frameWidth())
        width = (max(self.content.sizeHint().width(), table) + scroll_bar + margins.left()
                 + margins.right())
        inside = width - margins.left() - margins.right() - scroll_bar
        inner = self.inner
        tall = (inner.heightForWidth(inside) if inner.hasHeightForWidth()
                else self.content.sizeHint().height())
        below = sum(w.sizeHint().height() + self.outer.spacing()
                    for w in (self.problem, self.remember, self.buttons))
        fit_to_screen(self, width, tall + below + margins.top() + margins.bottom())

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
