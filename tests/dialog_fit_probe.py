"""Opens every dialog of the window on the screen Qt was started with and prints, as JSON,
each one's frame and the screen's available geometry (tests/widgets/test_dialogs_fit.py runs it
in a process of its own per screen: an offscreen screen of a given size and scale), for each
language of its arguments (``python -m tests.dialog_fit_probe en zh_CN``): a window of its own
in each, one after another, ``{language: {"dialogs": {dialog: ...}, "window and certificate
dialog": ...}}``, the second tests/small_screen_probe.py's records of the same window, made
before its dialogs are opened (tests/widgets/test_small_screens.py reads them).

Each dialog is opened the way the user opens it (its menu action, its button), answered
from a timer that records the modal window in front and closes it."""

from __future__ import annotations

import json
import sys

from PySide6.QtCore import QCoreApplication, QEvent, QPoint, QRect, QTimer
from PySide6.QtWidgets import QApplication, QDialogButtonBox, QMessageBox, QWidget

from tests import small_screen_probe
from tests.screen_process import close_window, open_window

found: dict[str, dict] = {}


def record(name: str, widget: QWidget) -> None:
    QApplication.processEvents()
    frame = widget.frameGeometry()
    screen = (widget.screen() or QApplication.primaryScreen()).availableGeometry()
    found[name] = {"frame": [frame.x(), frame.y(), frame.width(), frame.height()],
                   "available": [screen.x(), screen.y(), screen.width(), screen.height()],
                   "minimum": [widget.minimumSizeHint().width(), widget.minimumSizeHint().height()],
                   "buttons": buttons_in_sight(widget)}


def buttons_in_sight(widget: QWidget) -> list[list]:
    """Each button of ``widget``'s button boxes (OK, Cancel, Open…: the answers, which do not
    scroll) with whether all of it is inside the window and on the screen."""
    window = widget.frameGeometry()
    screen = (widget.screen() or QApplication.primaryScreen()).availableGeometry()
    seen = []
    for box in widget.findChildren(QDialogButtonBox):
        for button in box.buttons():
            if not button.isVisibleTo(widget):
                continue
            corner = button.mapToGlobal(QPoint(0, 0))
            rect = QRect(corner, button.size())
            seen.append([button.text(), window.contains(rect) and screen.contains(rect)])
    return seen


def answer_modal(name: str, then=None) -> None:
    """Record the modal window that the next call opens, then close it."""

    def look() -> None:
        modal = QApplication.activeModalWidget()
        if modal is None:
            QTimer.singleShot(20, look)
            return
        record(name, modal)
        if then is not None:
            then(modal)
        modal.reject() if hasattr(modal, "reject") else modal.close()

    QTimer.singleShot(0, look)


def main() -> None:
    QApplication.instance() or QApplication(["anglebench"])
    by_language = {}
    for language in sys.argv[1:] or ["en"]:
        found.clear()
        window = open_window("anglebench-fit-", language)
        QApplication.processEvents()
        record("main window", window)
        # the window on each workbench and the certificate dialog as a small screen shows them
        # (tests/small_screen_probe.py), in this window before its dialogs are opened: the
        # records the same as that probe's own process gave (compared 2026-12-07)
        small = small_screen_probe.measure(window)
        probe(window)
        by_language[language] = {"dialogs": dict(found), "window and certificate dialog": small}
    sys.stdout.write(json.dumps(by_language) + "\n")


def probe(window) -> None:
    """Every dialog of ``window`` (its "main window" recorded) recorded in ``found``; the
    window closed."""
    from widgets.certificate_dialog import CertificateDialog
    from widgets.column_mapping_dialog import ColumnMappingDialog

    # the certificate dialog as File › Export certificate opens it, with three standards
    meta = window.certificates.details("polygon")
    dialog = CertificateDialog(meta, window)
    for _ in range(3):
        dialog.add_standard({"description": "Autocollimator", "uncertainty": 0.3})
    dialog.show()
    record("certificate details", dialog)
    dialog.close()
    window.tabs.setCurrentIndex(1)
    answer_modal("certificate details (Export certificate…)")
    window.export_certificate()

    kind = max((p.kind for p in window.presenters), key=lambda k: len(k.columns))
    header = [f"column {i}" for i in range(len(kind.columns) + 2)]
    mapping = ColumnMappingDialog(kind.columns, header, [[str(i) for i in range(len(header))]] * 5,
                                  "The headers of readings.csv were not recognised. " * 3, window)
    mapping.show()
    record("which column is which", mapping)
    mapping.close()

    window.show_register()
    record("certificate register", window.register_window)
    for name, button in (("acknowledge a loss", "loss"), ("clock correction", "clock")):
        window.register_window.recovery_buttons[button].click()  # the register's recoveries
        record(name, window.register_window.recovery_dialog)
        window.register_window.recovery_dialog.reject()
    answer_modal("verify a certificate PDF")
    window.register_window.buttons["verify"].click()
    window.register_window.close()
    window.show_manual()
    record("manual", window.manual)
    window.manual.close()

    answer_modal("quick guide")
    window.show_guide()
    answer_modal("about")
    window.show_about()
    long_reason = "row 12, column 'A': '12°34' is not an angle. " * 6
    answer_modal("a message (tell)")
    QMessageBox.warning(window, "Cannot import", long_reason)
    answer_modal("a question (ask)")
    QMessageBox.question(window, "Unsaved readings", long_reason)
    answer_modal("paste question")
    window.current.view.table.ask_paste(5, 20)
    answer_modal("draft question")
    window.certificates.view.confirm_draft(["reference standards", "approver", "customer"])
    from app.certificate_presenter import PendingRevision

    answer_modal("what changed")
    window.certificates.view.ask_change_note(PendingRevision("polygon", "AB-2026-0042"))
    answer_modal("print")
    window.print_dialog()
    answer_modal("open project")
    window.projects.open_project_dialog()
    answer_modal("import readings")
    window.import_dialog()
    answer_modal("save project")
    window.menus.save_as_action.trigger()
    answer_modal("export results")
    window.menus.export_results_action.trigger()
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    answer_modal("polygon certificate")
    polygon.view.certificate_button.click()
    close_window(window, None)
    window.deleteLater()  # gone before the next language's window is made
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


if __name__ == "__main__":
    main()
