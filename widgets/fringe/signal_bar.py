"""One signal figure as an encoder maker's test set shows it: a horizontal bar with the
quantity's tolerance band (inside band green, the outer band amber, beyond it red), a
needle at the current value, and the lowest and highest value since the last reset as two
small pointers below the bar. The name, the value and its state are written beside it."""

from __future__ import annotations

import math

from PySide6.QtCore import QPointF, QRectF, QSize, Qt
from PySide6.QtGui import QColor, QFont, QPainter, QPen, QPolygonF
from PySide6.QtWidgets import QSizePolicy, QWidget

from models.fringe.signal_tolerance import Band
from models.uncertainty.rounding import fixed_places

__all__ = ["STATE_COLOURS", "SignalBar"]

#: the colour of each state (the needle's and the value's), and of a value with no band
STATE_COLOURS = {"inside": "#2e7d32", "outer": "#ef8f00", "outside": "#c62828", "": "#455a64"}
_ZONE = {"inside": "#c8e6c9", "outer": "#ffe0b2", "outside": "#ffcdd2", "": "#eceff1"}


class SignalBar(QWidget):
    """A bar for one quantity; :meth:`set_value` and :meth:`set_extremes` update it (a
    repaint is asked for, Qt merges repaints into the display's own rate)."""

    def __init__(self, quantity: str, parent=None) -> None:
        super().__init__(parent)
        self.quantity = quantity
        self.title = quantity
        self.band: Band | None = None
        self.value: float = math.nan
        self.state = ""
        self.low: float = math.nan
        self.high: float = math.nan
        self.decimals = 3
        self.unit = ""
        self.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
        self.setMinimumWidth(220)

    def sizeHint(self) -> QSize:  # noqa: N802 - Qt's name
        return QSize(320, self._height())

    def minimumSizeHint(self) -> QSize:  # noqa: N802 - Qt's name
        return QSize(220, self._height())

    def _height(self) -> int:
        return self.fontMetrics().height() + 26

    def set_band(self, title: str, band: Band | None, unit: str, decimals: int) -> None:
        self.title, self.band, self.unit, self.decimals = title, band, unit, decimals
        self.update()

    def set_value(self, value: float, state: str) -> None:
        self.value, self.state = value, state
        self.update()

    def set_extremes(self, low: float, high: float) -> None:
        self.low, self.high = low, high
        self.update()

    def colour(self) -> str:
        """The needle's colour: the state's (no band: grey)."""
        return STATE_COLOURS.get(self.state, STATE_COLOURS[""])

    def value_text(self) -> str:
        if not math.isfinite(self.value):
            return "—"
        unit = f" {self.unit}" if self.unit and self.unit != "°" else self.unit
        # a zero unsigned, as the window prints it elsewhere (live78: "Offset A -0.00 %")
        return f"{fixed_places(self.value, self.decimals)}{unit}"

    def scale_range(self) -> tuple[float, float]:
        """The values the bar's ends stand for: the bands and half their width either side,
        widened to show the value and the pointers."""
        points = [v for v in (self.value, self.low, self.high) if math.isfinite(v)]
        if self.band is not None:
            low, high = self.band.outer or self.band.inside
            low, high = min(low, self.band.inside[0]), max(high, self.band.inside[1])
            margin = 0.5 * (high - low) or 1.0
            low, high = low - margin, high + margin
        elif points:
            low, high = min(points), max(points)
            margin = 0.25 * (high - low) or max(abs(high), 1.0) * 0.25
            low, high = low - margin, high + margin
        else:
            return 0.0, 1.0
        if points:
            span = high - low
            low = min(low, min(points) - 0.05 * span)
            high = max(high, max(points) + 0.05 * span)
        return low, high

    def paintEvent(self, _event) -> None:  # noqa: N802 - Qt's name
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        metrics = self.fontMetrics()
        text_h = metrics.height()
        width = self.width()
        # first line: the name on the left, the value on the right, in the state's colour
        painter.setPen(QColor("#212121"))
        painter.drawText(QRectF(2, 0, width * 0.6, text_h), Qt.AlignmentFlag.AlignLeft
                         | Qt.AlignmentFlag.AlignVCenter, self.title)
        bold = QFont(self.font())
        bold.setBold(True)
        painter.setFont(bold)
        painter.setPen(QColor(self.colour()))
        painter.drawText(QRectF(width * 0.4, 0, width * 0.6 - 2, text_h),
                         Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter,
                         self.value_text())
        painter.setFont(self.font())
        # the bar
        top, bar_h = text_h + 2, 12.0
        left, right = 4.0, width - 4.0
        low, high = self.scale_range()

        def x_of(v: float) -> float:
            return left + (right - left) * (v - low) / (high - low)

        painter.setPen(Qt.PenStyle.NoPen)
        if self.band is None:
            painter.setBrush(QColor(_ZONE[""]))
            painter.drawRect(QRectF(left, top, right - left, bar_h))
        else:
            painter.setBrush(QColor(_ZONE["outside"]))
            painter.drawRect(QRectF(left, top, right - left, bar_h))
            if self.band.outer is not None:
                a, b = (x_of(v) for v in self.band.outer)
                painter.setBrush(QColor(_ZONE["outer"]))
                painter.drawRect(QRectF(a, top, b - a, bar_h))
            a, b = (x_of(v) for v in self.band.inside)
            painter.setBrush(QColor(_ZONE["inside"]))
            painter.drawRect(QRectF(a, top, b - a, bar_h))
        painter.setPen(QPen(QColor("#90a4ae"), 1))
        painter.setBrush(Qt.BrushStyle.NoBrush)
        painter.drawRect(QRectF(left, top, right - left, bar_h))
        # the lowest and highest since the reset: small triangles under the bar
        painter.setPen(Qt.PenStyle.NoPen)
        painter.setBrush(QColor("#37474f"))
        for v in (self.low, self.high):
            if math.isfinite(v):
                x = x_of(v)
                y = top + bar_h + 1
                painter.drawPolygon(QPolygonF([QPointF(x, y), QPointF(x - 4, y + 7),
                                               QPointF(x + 4, y + 7)]))
        # the needle
        if math.isfinite(self.value):
            x = x_of(self.value)
            painter.setPen(QPen(QColor(self.colour()), 3))
            painter.drawLine(QPointF(x, top - 2), QPointF(x, top + bar_h + 2))
        painter.end()
