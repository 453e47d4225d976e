"""Opens the window (every workbench in turn) and the certificate dialog on the screen Qt was
started with and prints, as JSON, what a technician on that screen would meet: each one's
frame and least size against the screen's free area, and every text in the dialog shown
narrower than it needs. tests/widgets/test_small_screens.py reads :func:`measure`'s records
from tests/dialog_fit_probe.py's process of each screen (an offscreen screen of a given size
and scale), made in its window of each language before its dialogs are opened."""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QAbstractButton,
    QApplication,
    QComboBox,
    QGroupBox,
    QLabel,
    QLineEdit,
    QStyle,
    QStyleOptionFrame,
    QWidget,
)

from tests.screen_process import close_window, open_window


def cut_texts(dialog: QWidget) -> list[str]:
    """Every caption, switch, choice, group title and hint in ``dialog`` shown narrower than
    its text (a label that wraps takes the lines it needs: not counted)."""
    cut = []
    for widget in dialog.findChildren(QWidget):
        if not widget.isVisibleTo(dialog):
            continue
        if isinstance(widget, QLabel) and not widget.wordWrap() or isinstance(
                widget, (QAbstractButton, QComboBox)):
            text = widget.currentText() if isinstance(widget, QComboBox) else widget.text()
            if text and widget.width() < widget.sizeHint().width():
                cut.append(f"{text!r}: {widget.width()} of {widget.sizeHint().width()} px")
        elif isinstance(widget, QGroupBox):
            need = widget.fontMetrics().horizontalAdvance(widget.title()) + 16
            if widget.width() < need:
                cut.append(f"{widget.title()!r}: {widget.width()} of {need} px")
        elif isinstance(widget, QLineEdit) and widget.placeholderText() and not widget.text():
            hint, room = widget.placeholderText(), hint_room(widget)
            if widget.fontMetrics().elidedText(hint, Qt.TextElideMode.ElideRight, room) != hint:
                need = widget.fontMetrics().horizontalAdvance(hint)
                cut.append(f"{hint!r}: {room} of {need} px")
    return cut


def hint_room(edit: QLineEdit) -> int:
    """The width (px) ``edit`` has for its hint, as QLineEdit paints it: its style's text
    rectangle (inside the frame, SE_LineEditContents) less its text margins and its own 2 px
    each side; the hint is elided (fontMetrics().elidedText, on the text's real width) when
    it needs more. (It was taken as the widget's width less 4 px, the frame counted as room:
    a hint cut by up to 2 px went unseen; the zh trusted-certificate hint of the certificate
    dialog, 430 px, had 431 at 1280×720, not the 433 counted.)"""
    option = QStyleOptionFrame()
    edit.initStyleOption(option)
    rect = edit.style().subElementRect(QStyle.SubElement.SE_LineEditContents, option, edit)
    return rect.marginsRemoved(edit.textMargins()).width() - 4


def record(widget: QWidget) -> dict:
    QApplication.processEvents()
    frame = widget.frameGeometry()
    free = (widget.screen() or QApplication.primaryScreen()).availableGeometry()
    least = widget.minimumSizeHint().expandedTo(widget.minimumSize())
    return {"frame": [frame.x(), frame.y(), frame.width(), frame.height()],
            "available": [free.x(), free.y(), free.width(), free.height()],
            "minimum": [least.width(), least.height()]}


def measure(window) -> dict:
    """What a technician meets on this screen in ``window`` (tests.screen_process.open_window's,
    just opened): the window on each workbench, alone and with the instrument panel, and the
    certificate dialog; the dialog closed, the panel hidden, the window left open."""
    app = QApplication.instance()
    from app.screenshot import _example_metadata
    from widgets.certificate_dialog import CertificateDialog

    found: dict[str, dict] = {}
    for index, presenter in enumerate(window.presenters):
        window.tabs.setCurrentIndex(index)
        for _ in range(3):
            app.processEvents()
        found[f"window: {presenter.kind.key}"] = record(window)
    # the instrument panel open beside the workbench, as at the bench (day review 66: the
    # window was 760 px wide at the least with it, at 200 % on 1280×720)
    for index, presenter in enumerate(window.presenters):
        window.tabs.setCurrentIndex(index)
        window.capture_panel.show()
        for _ in range(3):
            app.processEvents()
        found[f"window and instrument panel: {presenter.kind.key}"] = record(window)
    window.capture_panel.hide()
    dialog = CertificateDialog(_example_metadata(), window)
    for _ in range(2):
        dialog.add_standard({"description": "Autocollimator", "uncertainty": 0.3})
    dialog.show()
    found["certificate details"] = record(dialog)
    found["certificate details"].update(
        cut=cut_texts(dialog), sideways=dialog.details_area.horizontalScrollBar().maximum())
    dialog.close()
    return found


def main() -> None:
    """The probe on its own: a window in the language of the first argument (en without one)."""
    QApplication.instance() or QApplication(["anglebench"])
    window = open_window("anglebench-small-")
    close_window(window, measure(window))


if __name__ == "__main__":
    main()
