"""The "open" file dialog of the window (widgets/open_file.py): what it returns, and its size
from the screen it opens on (fit74: Qt's own dialog was 634×410 at 200 % on a 1280×720
laptop, 640×360 logical; tests/widgets/test_dialogs_fit.py opens it from the window)."""

from __future__ import annotations

from PySide6.QtCore import QEvent
from PySide6.QtWidgets import QApplication, QDialog, QFileDialog, QWidget

from widgets.open_file import ask_open_file, open_file_dialog
from widgets.screen_fit import available_size


def test_the_file_chosen_is_returned_and_nothing_when_cancelled(qtbot, tmp_path, monkeypatch):
    chosen = tmp_path / "bench run.csv"
    chosen.write_text("pos,dev\n1,0.5\n")
    asked = []

    def choose(dialog):
        asked.append((dialog.windowTitle(), dialog.directory().absolutePath(),
                      dialog.nameFilters(), dialog.fileMode()))
        dialog.selectFile(str(chosen))
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(QFileDialog, "exec", choose)
    assert ask_open_file(None, "Import readings", str(tmp_path),
                         "Readings (*.csv);;All files (*)") == str(chosen)
    assert asked == [("Import readings", str(tmp_path), ["Readings (*.csv)", "All files (*)"],
                      QFileDialog.FileMode.ExistingFile)]
    monkeypatch.setattr(QFileDialog, "exec", lambda dialog: QDialog.DialogCode.Rejected)
    assert ask_open_file(None, "Import readings", str(tmp_path), "Readings (*.csv)") == ""


def test_the_dialog_is_no_larger_than_the_screen_has_free(qtbot, tmp_path):
    dialog = open_file_dialog(None, "Open project", str(tmp_path), "Project (*.json)")
    qtbot.addWidget(dialog)
    free_width, free_height = available_size(dialog)
    assert dialog.width() == min(dialog.sizeHint().width(), free_width)
    assert dialog.height() == min(dialog.sizeHint().height(), free_height)


def test_no_dialog_is_left_behind_in_the_window(qtbot, tmp_path, monkeypatch):
    """Each file opened made a dialog, a child of the window kept until the window closed
    (with its folder model watching the folder); the static function's went when it
    returned."""
    window = QWidget()
    qtbot.addWidget(window)
    monkeypatch.setattr(QFileDialog, "exec", lambda dialog: QDialog.DialogCode.Rejected)
    for _ in range(3):
        ask_open_file(window, "Import readings", str(tmp_path), "Readings (*.csv)")
    QApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    assert window.findChildren(QFileDialog) == []
