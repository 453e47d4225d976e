"""A message of several paragraphs (the quick guide) in a dialog no larger than the screen:
its text wraps to the dialog's width and scrolls where the screen is too low for all of it,
OK always in sight. QMessageBox neither scrolls nor shrinks: at 200 % on a 1280×720 laptop
(640×360 logical) the quick guide was 380 px tall, its OK button below the screen's edge."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QHBoxLayout,
    QLabel,
    QStyle,
    QVBoxLayout,
    QWidget,
)

from widgets.screen_fit import fit_to_screen
from widgets.wrapped_text_area import WrappedTextArea

__all__ = ["TextDialog"]


class TextDialog(QDialog):
    """``text`` (plain, paragraphs split by blank lines) under ``title``, an information icon
    beside it and OK under it; as wide as :attr:`WIDTH` (logical pixels at 96 dpi) and as
    tall as its text at that width, each at most the screen's free size."""

    WIDTH = 520

    def __init__(self, title: str, text: str, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setWindowTitle(title)
        self.text = QLabel(text)
        self.text.setTextFormat(Qt.TextFormat.PlainText)
        self.text.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.area = WrappedTextArea([self.text])
        icon = QLabel()
        size = self.style().pixelMetric(QStyle.PixelMetric.PM_MessageBoxIconSize, None, self)
        icon.setPixmap(self.style().standardIcon(
            QStyle.StandardPixmap.SP_MessageBoxInformation, None, self).pixmap(size, size))
        icon.setAlignment(Qt.AlignmentFlag.AlignTop)
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok)
        self.buttons.accepted.connect(self.accept)
        row = QHBoxLayout()
        row.addWidget(icon)
        row.addWidget(self.area, 1)
        self.outer = QVBoxLayout(self)
        self.outer.addLayout(row, 1)
        self.outer.addWidget(self.buttons)
        self._fit(icon.sizeHint().width() + row.spacing())

    def _fit(self, beside: int) -> None:
        """:attr:`WIDTH` wide and as tall as the whole text, or less where the screen is."""
        width = self.WIDTH * self.logicalDpiX() // 96
        margins = self.outer.contentsMargins()
        scroll_bar = self.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent, None, self)
        inside = width - margins.left() - margins.right() - beside - scroll_bar
        tall = self.text.heightForWidth(max(inside, 1))
        fit_to_screen(self, width, tall + self.buttons.sizeHint().height() + margins.top()
                      + margins.bottom() + self.outer.spacing())
