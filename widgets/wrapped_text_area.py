"""A column of word-wrapped labels that is as tall as their whole text where the window has
room, and scrolls up and down where it has not, every line whole (day review 69 F5: at 200 %
on a 1280×720 screen the Result pane's bold line and warning were cut through mid-line, the
qualifier "…the error it leaves there is not determined" out of sight)."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, QSize, Qt
from PySide6.QtWidgets import QFrame, QLabel, QScrollArea, QSizePolicy, QVBoxLayout, QWidget

__all__ = ["WrappedTextArea"]


class WrappedTextArea(QScrollArea):
    """``labels`` one under the other, each given the height its text needs at the area's
    width; the area asks for that height and, given less, keeps at least
    :attr:`LEAST_LINES` lines and scrolls."""

    #: the lines of text the area keeps in sight at the least (the rest scrolls)
    LEAST_LINES = 3

    def __init__(self, labels: list[QLabel], parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setWidgetResizable(True)
        self.setFrameShape(QFrame.Shape.NoFrame)
        self.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        self.setVerticalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAsNeeded)
        self.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Maximum)
        inside = QWidget()
        layout = QVBoxLayout(inside)
        layout.setContentsMargins(0, 0, 0, 0)
        for label in labels:
            label.setWordWrap(True)
            layout.addWidget(label)
            label.installEventFilter(self)  # shown, hidden or its text changed: ask again
        self.setWidget(inside)
        inside.installEventFilter(self)  # a label's new text asks its layout again
        self._labels = labels
        self._inside, self._layout = inside, layout

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:  # noqa: N802 - Qt's name
        if event.type() in (QEvent.Type.Show, QEvent.Type.Hide, QEvent.Type.LayoutRequest,
                            QEvent.Type.Resize):
            self.updateGeometry()
        return super().eventFilter(watched, event)

    def _text_height(self) -> int:
        """The height of every shown label's whole text at the viewport's width."""
        inside = self._inside
        layout = self._layout
        width = max(self.viewport().width(), 1)
        if layout.hasHeightForWidth():
            return layout.totalHeightForWidth(width)
        return inside.sizeHint().height()

    def sizeHint(self) -> QSize:  # noqa: N802 - Qt's name
        frame = 2 * self.frameWidth()
        return QSize(super().sizeHint().width(), self._text_height() + frame)

    def minimumSizeHint(self) -> QSize:  # noqa: N802 - Qt's name
        least = self.LEAST_LINES * self.fontMetrics().lineSpacing() + 8
        return QSize(super().minimumSizeHint().width(),
                     min(self._text_height(), least) + 2 * self.frameWidth())

    def resizeEvent(self, event) -> None:  # noqa: N802 - Qt's name
        """A new width: the text's height changes with it."""
        super().resizeEvent(event)
        if event.oldSize().width() != event.size().width():
            self.updateGeometry()
