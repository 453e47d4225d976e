"""Opens the fringe workbench's Live signals window from Instrument › Live signals… on the
screen Qt was started with, runs the demonstration head and clicks Take where the button is
drawn, as a technician would, and prints, as JSON, the window's least size, its frame, the
screen's free area, where Take is on the screen and the rows the take put in the readings
(tests/widgets/fringe/test_live_signals_fit.py runs it on a 1280×720 screen at 150 %)."""

from __future__ import annotations

import json
import os
import sys
import tempfile
import time
from pathlib import Path

from PySide6.QtCore import QPoint, QSettings, Qt
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication


def main() -> None:
    app = QApplication.instance() or QApplication(["anglebench"])
    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    scratch = Path(tempfile.mkdtemp(prefix="anglebench-live-fit-"))
    settings = QSettings(str(scratch / "settings.ini"), QSettings.Format.IniFormat)
    settings.setValue("ui/language", sys.argv[1] if len(sys.argv) > 1 else "en")
    window = MainWindow(settings=settings, recovery=RecoveryStore(scratch / "recovery"))
    window.show()
    fringe = next(p for p in window.presenters if p.kind.key == "fringe")
    window.tabs.setCurrentIndex(window.presenters.index(fringe))
    window.menus.live_signals_action.trigger()
    panel = fringe.view.live_signals
    app.processEvents()
    panel.start_demonstration()
    deadline = time.monotonic() + 30
    while panel.samples < 2000 and time.monotonic() < deadline:
        app.processEvents()
        time.sleep(0.02)
    app.processEvents()
    frame = panel.frameGeometry()
    free = panel.screen().availableGeometry()
    least = panel.minimumSizeHint().expandedTo(panel.minimumSize())
    button = panel.take_button
    corner = button.mapToGlobal(QPoint(0, 0))
    # the button's part not hidden by the window's edges (a scroll area's clip included)
    shown = button.visibleRegion().boundingRect()
    QTest.mouseClick(button, Qt.MouseButton.LeftButton)
    app.processEvents()
    found = {"minimum": [least.width(), least.height()],
             "frame": [frame.x(), frame.y(), frame.width(), frame.height()],
             "available": [free.x(), free.y(), free.width(), free.height()],
             "take": [corner.x(), corner.y(), button.width(), button.height()],
             "take_shown": [shown.width(), shown.height()],
             "rows": fringe.table_model.rowCount()}
    panel.disconnect_stream()
    panel.close()
    window.projects.recovery.discard()
    window.projects.view.ask_save_changes = lambda *_: False  # the take is let go
    window.close()
    sys.stdout.write(json.dumps(found) + "\n")
    sys.stdout.flush()
    # the take's analysis may still run on its worker thread: the interpreter's teardown
    # under it crashed now and then (a probe's exit status is the test's, so leave at once)
    os._exit(0)


if __name__ == "__main__":
    main()
