"""The "save as" file dialog of the window (widgets/save_file.py, savefit75): built as
QFileDialog.getSaveFileName built it — what it offers, what it returns, its own "replace?"
question — and sized from the screen it opens on (getSaveFileName's was 634×410 at 200 % on
a 1280×720 laptop, 640×360 logical, Save and Cancel off it; tests/widgets/test_dialogs_fit.py
opens Save project and Export results from the window on that screen)."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QTimer
from PySide6.QtWidgets import QApplication, QDialog, QFileDialog, QLineEdit, QMessageBox, QWidget

from widgets import screen_fit
from widgets.save_file import ask_save_file, choose_save_file, save_file_dialog
from widgets.screen_fit import available_size

RESULTS = "CSV (*.csv);;Excel workbook (*.xlsx)"


def test_the_suggested_name_and_the_chosen_type_come_back_and_nothing_when_cancelled(
        qtbot, tmp_path, monkeypatch):
    offered = []

    def choose_excel(dialog):
        offered.append((dialog.windowTitle(), dialog.directory().absolutePath(),
                        dialog.findChild(QLineEdit, "fileNameEdit").text(), dialog.nameFilters(),
                        dialog.selectedNameFilter(), dialog.acceptMode(), dialog.fileMode()))
        dialog.selectNameFilter("Excel workbook (*.xlsx)")
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(QFileDialog, "exec", choose_excel)
    suggested = str(tmp_path / "theodolite-results.csv")
    # the type chosen comes back; the dialog itself renamed the suggested .csv to .xlsx
    assert choose_save_file(None, "Export results", suggested, RESULTS) == (
        str(tmp_path / "theodolite-results.xlsx"), "Excel workbook (*.xlsx)")
    assert offered == [("Export results", str(tmp_path), "theodolite-results.csv",
                        ["CSV (*.csv)", "Excel workbook (*.xlsx)"], "CSV (*.csv)",
                        QFileDialog.AcceptMode.AcceptSave, QFileDialog.FileMode.AnyFile)]
    # a name without its folder is offered in the folder the dialog opens on
    monkeypatch.chdir(tmp_path)
    assert choose_save_file(None, "Save face deviations", "polygon_deviations.csv",
                            "CSV (*.csv)") == (str(tmp_path / "polygon_deviations.csv"),
                                               "CSV (*.csv)")

    # ask_save_file writes the chosen type's extension onto a name typed without one
    def type_run3(dialog):
        dialog.selectFile(str(tmp_path / "run3"))
        dialog.selectNameFilter("Excel workbook (*.xlsx)")
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(QFileDialog, "exec", type_run3)
    assert ask_save_file(None, "Export results", suggested, RESULTS) == str(tmp_path / "run3.xlsx")
    monkeypatch.setattr(QFileDialog, "exec", lambda dialog: QDialog.DialogCode.Rejected)
    assert choose_save_file(None, "Export results", suggested, RESULTS) == ("", "")
    assert ask_save_file(None, "Export results", suggested, RESULTS) == ""


def test_the_dialog_asks_before_replacing_a_file_there(qtbot, tmp_path):
    """The dialog's own question (getSaveFileName's dialog asked it too): No keeps it open."""
    theirs = tmp_path / "run3.csv"
    theirs.write_text("a colleague's readings")
    for answer, accepted in ((QMessageBox.StandardButton.No, False),
                             (QMessageBox.StandardButton.Yes, True)):
        dialog = save_file_dialog(None, "Export results", str(theirs), RESULTS)
        qtbot.addWidget(dialog)
        dialog.show()
        asked = []

        def look(answer=answer, asked=asked):
            box = QApplication.activeModalWidget()
            if not isinstance(box, QMessageBox):
                QTimer.singleShot(10, look)
                return
            asked.append(box.text())
            box.button(answer).click()

        QTimer.singleShot(0, look)
        dialog.accept()
        assert asked == ["run3.csv already exists.\nDo you want to replace it?"]
        assert (dialog.result() == QDialog.DialogCode.Accepted) is accepted
        assert dialog.isVisible() is not accepted
        dialog.close()


def test_the_dialog_is_no_larger_than_the_screen_has_free(qtbot, tmp_path, monkeypatch):
    dialog = save_file_dialog(None, "Save project", str(tmp_path), "Project (*.json)")
    qtbot.addWidget(dialog)
    free_width, free_height = available_size(dialog)
    assert dialog.width() == min(dialog.sizeHint().width(), free_width)
    assert dialog.height() == min(dialog.sizeHint().height(), free_height)
    # 640×360 logical (a 1280×720 laptop at 200 %) leaves 627×331: less than it asks for
    monkeypatch.setattr(screen_fit, "available_size", lambda _widget: (627, 331))
    small = save_file_dialog(None, "Save project", str(tmp_path), "Project (*.json)")
    qtbot.addWidget(small)
    assert small.sizeHint().height() > 331
    assert (small.width(), small.height()) == (min(small.sizeHint().width(), 627), 331)


def test_no_dialog_is_left_behind_in_the_window(qtbot, tmp_path, monkeypatch):
    """Each save made a dialog, a child of the window kept until the window closed (with
    its folder model watching the folder); the static function's went when it returned."""
    window = QWidget()
    qtbot.addWidget(window)
    monkeypatch.setattr(QFileDialog, "exec", lambda dialog: QDialog.DialogCode.Rejected)
    for _ in range(3):
        choose_save_file(window, "Export results", str(tmp_path), RESULTS)
    QApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    assert window.findChildren(QFileDialog) == []
