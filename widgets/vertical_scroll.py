"""A dialog's content that scrolls up and down only, the dialog's buttons kept below it in
sight (the column mapping dialog's, the register's recovery dialogs'): on a small screen
(a 1280×720 laptop at 200 %) the fields scroll, what answers them does not."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import QFrame, QScrollArea, QWidget

__all__ = ["vertical_scroll_area"]


def vertical_scroll_area(content: QWidget) -> QScrollArea:
    """``content`` in a frameless area that scrolls vertically and is as wide as it is
    given (no horizontal scroll bar: the content wraps to it)."""
    area = QScrollArea()
    area.setWidgetResizable(True)
    area.setFrameShape(QFrame.Shape.NoFrame)
    area.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
    area.setWidget(content)
    return area
