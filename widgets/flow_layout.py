"""A layout that places its widgets in a row and wraps them onto the next row where the row
is too narrow for them (Qt's flow layout example): a row of buttons that fits a small
screen (200 % on a 1280×720 laptop: 640 px logical) as well as a wide one, each button
whole, none off the window's edge (day74 #11: the register window's seven buttons made it
652 px wide)."""

from __future__ import annotations

from PySide6.QtCore import QMargins, QPoint, QRect, QSize, Qt
from PySide6.QtWidgets import QLayout, QLayoutItem, QSizePolicy, QWidget

__all__ = ["FlowLayout"]


class FlowLayout(QLayout):
    """Widgets left to right, wrapping; its minimum width is its widest widget's."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._items: list[QLayoutItem] = []
        #: the height the rows took when last laid out (0: not yet)
        self._height = 0
        self.setContentsMargins(QMargins(0, 0, 0, 0))

    # -- QLayout's interface ---------------------------------------------------------------
    def addItem(self, item: QLayoutItem) -> None:  # noqa: N802 - Qt's name
        self._items.append(item)

    def count(self) -> int:
        return len(self._items)

    def itemAt(self, index: int) -> QLayoutItem | None:  # noqa: N802 - Qt's name
        return self._items[index] if 0 <= index < len(self._items) else None

    def takeAt(self, index: int) -> QLayoutItem | None:  # noqa: N802 - Qt's name
        return self._items.pop(index) if 0 <= index < len(self._items) else None

    def expandingDirections(self) -> Qt.Orientation:  # noqa: N802 - Qt's name
        return Qt.Orientation(0)

    def hasHeightForWidth(self) -> bool:  # noqa: N802 - Qt's name
        return True

    def heightForWidth(self, width: int) -> int:  # noqa: N802 - Qt's name
        return self._place(QRect(0, 0, width, 0), move=False)

    def setGeometry(self, rect: QRect) -> None:  # noqa: N802 - Qt's name
        super().setGeometry(rect)
        self._place(rect, move=True)

    def sizeHint(self) -> QSize:  # noqa: N802 - Qt's name
        """All on one row."""
        width = sum(item.sizeHint().width() for item in self._visible())
        width += self._spacing() * max(0, len(self._visible()) - 1)
        height = max((item.sizeHint().height() for item in self._visible()), default=0)
        margins = self.contentsMargins()
        return QSize(width + margins.left() + margins.right(),
                     height + margins.top() + margins.bottom())

    def minimumSize(self) -> QSize:  # noqa: N802 - Qt's name
        """The widest widget (every other one wraps), as tall as the rows were when last
        laid out."""
        size = QSize()
        for item in self._visible():
            size = size.expandedTo(item.minimumSize())
        margins = self.contentsMargins()
        size += QSize(margins.left() + margins.right(), margins.top() + margins.bottom())
        return QSize(size.width(), max(size.height(), self._height))

    # -- placing ---------------------------------------------------------------------------
    def _visible(self) -> list[QLayoutItem]:
        shown = []
        for item in self._items:
            widget = item.widget()
            if widget is None or not widget.isHidden():
                shown.append(item)
        return shown

    def _spacing(self) -> int:
        """Between two widgets of a row: the layout's, else the style's between buttons."""
        spacing = self.spacing()
        return spacing if spacing >= 0 else self._style_spacing(Qt.Orientation.Horizontal)

    def _place(self, rect: QRect, move: bool) -> int:
        """Lay the widgets out in ``rect`` (only measured unless ``move``), each centred on
        its row's height: the height used. The rows' height is then the layout's minimum
        (a splitter asks the minimum, not the height for its width: a second row of buttons
        was cut off)."""
        margins = self.contentsMargins()
        area = rect.adjusted(margins.left(), margins.top(), -margins.right(), -margins.bottom())
        spacing = self._spacing()
        vertical = self._style_spacing(Qt.Orientation.Vertical)
        rows: list[list[QLayoutItem]] = [[]]
        x = area.x()
        for item in self._visible():
            width = item.sizeHint().width()
            if rows[-1] and x + width > area.right() + 1:
                rows.append([])
                x = area.x()
            rows[-1].append(item)
            x += width + spacing
        y = area.y()
        for row in rows:
            height = max((item.sizeHint().height() for item in row), default=0)
            x = area.x()
            for item in row:
                hint = item.sizeHint()
                if move:
                    item.setGeometry(QRect(QPoint(x, y + (height - hint.height()) // 2), hint))
                x += hint.width() + spacing
            y += height + vertical
        used = max(0, y - vertical - area.y()) + margins.top() + margins.bottom()
        if move and used != self._height:
            self._height = used
            self.invalidate()  # the minimum height changed: asked again
        return used

    def _style_spacing(self, orientation: Qt.Orientation) -> int:
        """The style's spacing between two buttons (6 px without a widget to ask)."""
        parent = self.parentWidget()
        if parent is None:
            return 6
        spacing = parent.style().layoutSpacing(QSizePolicy.ControlType.PushButton,
                                               QSizePolicy.ControlType.PushButton, orientation)
        return spacing if spacing >= 0 else 6
