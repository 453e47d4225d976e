"""The register window's two recoveries, each a dialog asking what its command asks: a loss
acknowledged (``anglebench register acknowledge-loss``: who, why, the last number known
issued — required where no high-water mark tells it — and its number scheme) and a clock
correction (``anglebench register clock-correction``: who, why, today's date typed as a
confirmation). Widgets only: the dialog hands what was typed to ``record`` (the
presenter's), which records it through the register and returns "" or the register's
refusal; a refusal is shown in the dialog, which stays open with everything typed kept."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QFormLayout,
    QLabel,
    QLineEdit,
    QVBoxLayout,
    QWidget,
)

from widgets.i18n import tr
from widgets.screen_fit import fit_to_screen
from widgets.vertical_scroll import vertical_scroll_area

__all__ = ["ClockCorrectionDialog", "CorrectionTyped", "LossDialog", "LossTyped"]


@dataclass(frozen=True)
class LossTyped:
    """What the loss dialog asks (``--by``, ``--reason``, ``--last-number``, ``--scheme``)."""

    by: str
    reason: str
    last_number: str
    scheme: str


@dataclass(frozen=True)
class CorrectionTyped:
    """What the clock-correction dialog asks (``--by``, ``--reason``, ``--confirm-date``)."""

    by: str
    reason: str
    confirmed_date: str


def _note(text: str) -> QLabel:
    label = QLabel(text)
    label.setWordWrap(True)
    return label


class _RecoveryDialog(QDialog):
    """A form, the register's refusal under it (hidden until there is one) and the two
    buttons; OK hands the typed values to ``record``."""

    def __init__(self, parent: QWidget | None, title: str, intro: str, ok_text: str,
                 record: Callable[[object], str]) -> None:
        super().__init__(parent)
        self.setWindowTitle(title)
        self._record = record
        self.form = QFormLayout()
        self.form.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.ExpandingFieldsGrow)
        self.refusal = QLabel()
        self.refusal.setObjectName("refusal")
        self.refusal.setWordWrap(True)
        self.refusal.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.refusal.setStyleSheet("color: #b00020;")
        self.refusal.hide()
        self.buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Ok
                                        | QDialogButtonBox.StandardButton.Cancel)
        self.ok = self.buttons.button(QDialogButtonBox.StandardButton.Ok)
        self.ok.setText(ok_text)
        self.ok.setDefault(False)  # Enter in a field is not a recorded entry
        self.ok.setAutoDefault(False)
        self.buttons.accepted.connect(self._submit)
        self.buttons.rejected.connect(self.reject)
        # the explanation and the fields scroll on a small screen (200 % on 1280×720: 360
        # logical pixels), the refusal and the buttons stay in sight
        self.content = QWidget()
        self.inner = inner = QVBoxLayout(self.content)
        inner.setContentsMargins(0, 0, 0, 0)
        inner.addWidget(_note(intro))
        inner.addLayout(self.form)
        inner.addStretch(1)
        self.area = vertical_scroll_area(self.content)
        self.outer = layout = QVBoxLayout(self)
        layout.addWidget(self.area, 1)
        layout.addWidget(self.refusal)
        layout.addWidget(self.buttons)

    def _field(self, caption: str, placeholder: str, note: str = "") -> QLineEdit:
        edit = QLineEdit()
        edit.setPlaceholderText(placeholder)
        self.form.addRow(caption, edit)
        if note:
            self.form.addRow(_note(note))
        return edit

    def _fit(self) -> None:
        """As wide as a line of its explanation wants (or as the user made it), as tall as
        its fields and the refusal shown, at most the screen (the content scrolls below)."""
        width = max(self.width(), 600 * self.logicalDpiX() // 96) if self.isVisible() \
            else 600 * self.logicalDpiX() // 96
        margins = self.outer.contentsMargins()
        inside = width - margins.left() - margins.right()
        tall = (self.inner.heightForWidth(inside)
                if self.inner.hasHeightForWidth() else self.content.sizeHint().height())
        if self.refusal.isVisibleTo(self):  # the register's refusal, under the fields
            tall += self.refusal.heightForWidth(inside) + self.outer.spacing()
        fit_to_screen(self, width, tall + self.buttons.sizeHint().height()
                      + margins.top() + margins.bottom() + 2 * self.outer.spacing())

    def typed(self) -> object:
        raise NotImplementedError

    def _submit(self) -> None:
        refused = self._record(self.typed())
        if refused:
            self.refusal.setText(refused)
            self.refusal.show()
            self._fit()  # taller by the refusal, as far as the screen allows
            return  # kept open, everything typed kept
        self.accept()


class LossDialog(_RecoveryDialog):
    """``last_number_needed``: no high-water mark tells how far the numbers went (no
    laboratory key, or no mark beside it), so the last number known issued is required."""

    def __init__(self, parent: QWidget | None, last_number_needed: bool,
                 record: Callable[[LossTyped], str]) -> None:
        super().__init__(parent, tr("Acknowledge a loss"), tr(
            "Records in the register that records were lost — an older copy restored or put "
            "back — with who records it and why. Every counter moves past the last number "
            "known issued, so no number is issued twice, and issuing resumes. The same as "
            "the command 'anglebench register acknowledge-loss'."),
            tr("Record the loss"), record)  # type: ignore[arg-type]
        self.by = self._field(tr("Recorded by"), tr("your name"))
        self.reason = self._field(tr("Reason"), tr("what was lost and restored"))
        self.last_number = self._field(
            tr("Last number known issued"), tr("e.g. AB-2026-0042"),
            tr("Required: without the laboratory's key and its high-water mark the register "
               "cannot tell how far its numbers went. From the lab's log or the customers' "
               "copies.") if last_number_needed else
            tr("Optional: the high-water mark beside the laboratory's key tells how far the "
               "numbers went; give it when the lab's log or a customer's copy names a later "
               "one."))
        self.scheme = self._field(
            tr("Number scheme"), tr("e.g. AB-{year}-{seq:04d}"),
            tr("Only when the register restored has no counter of that number's scheme yet."))
        self._fit()

    def typed(self) -> LossTyped:
        return LossTyped(self.by.text(), self.reason.text(), self.last_number.text(),
                         self.scheme.text())


class ClockCorrectionDialog(_RecoveryDialog):
    def __init__(self, parent: QWidget | None, record: Callable[[CorrectionTyped], str]) -> None:
        super().__init__(parent, tr("Clock correction"), tr(
            "Records that the register's last record was dated by a clock set ahead (the "
            "year typed wrong, say), so that issues on this computer's clock, now right, are "
            "accepted again. The record dated ahead stays as issued; the correction is "
            "chained after it. The same as the command 'anglebench register "
            "clock-correction'."), tr("Record the correction"), record)  # type: ignore[arg-type]
        self.by = self._field(tr("Recorded by"), tr("your name"))
        self.reason = self._field(tr("Reason"), tr("which clock was wrong"))
        self.confirmed_date = self._field(
            tr("Today's date"), "YYYY-MM-DD",
            tr("Type today's date as you know it, not as this computer shows it: it must be "
               "the computer's date, or nothing is recorded (correct the clock first)."))
        self._fit()

    def typed(self) -> CorrectionTyped:
        return CorrectionTyped(self.by.text(), self.reason.text(), self.confirmed_date.text())
