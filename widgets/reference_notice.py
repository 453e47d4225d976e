"""The notice a workbench that holds a sent reference (the polygon's face deviations from a
cross-calibration) shows when that reference is no longer what its source would send: what
changed, and a button that sends it again. Hidden while the reference is current. Widgets
only (app/reference_sender.py decides what it says)."""

from __future__ import annotations

from PySide6.QtCore import Signal
from PySide6.QtWidgets import QHBoxLayout, QLabel, QPushButton, QSizePolicy, QWidget

from widgets.i18n import live, tr


class ReferenceNotice(QWidget):
    """A warning line and *Send again*; ``resend`` when the button is clicked."""

    resend = Signal()

    def __init__(self, parent=None) -> None:
        super().__init__(parent)
        self.label = QLabel()
        self.label.setWordWrap(True)
        self.label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.label.setStyleSheet("QLabel { color: #8a1f00; background: #ffe4dc; padding: 4px; }")
        self.button = QPushButton()
        live(self.button.setText, tr("Send again"))
        self.button.clicked.connect(self.resend.emit)
        layout = QHBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(self.label, 1)
        layout.addWidget(self.button)
        self.hide()

    @property
    def stale(self) -> bool:
        """Whether the notice is up (the reference held is not what its source sends now)."""
        return not self.isHidden()

    def show_stale(self, text: str, can_resend: bool = True) -> None:
        self.label.setText(text)
        self.button.setEnabled(can_resend)
        self.show()

    def clear(self) -> None:
        self.label.clear()
        self.hide()
