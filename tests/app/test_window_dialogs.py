"""The window's side of the project and certificate presenters (app/project_dialogs.py,
app/certificate_dialogs.py): each offers every call of its presenter's view protocol with
the protocol's signature, and turns the window's answers into the presenter's, on a mock
window (no dialog is shown)."""

from __future__ import annotations

import inspect
from unittest import mock

import pytest
from PySide6.QtWidgets import QMessageBox

from app.certificate_dialogs import CertificateDialogs
from app.certificate_presenter import CertificateView, PendingRevision
from app.project_dialogs import ProjectDialogs
from app.project_presenter import ProjectView
from widgets import save_file

Button = QMessageBox.StandardButton


def protocol_calls(protocol) -> dict[str, inspect.Signature]:
    return {name: inspect.signature(member) for name, member in vars(protocol).items()
            if inspect.isfunction(member) and not name.startswith("_")}


@pytest.mark.parametrize("dialogs, protocol", [(ProjectDialogs, ProjectView),
                                               (CertificateDialogs, CertificateView)])
def test_the_window_side_offers_every_call_of_the_view(dialogs, protocol):
    calls = protocol_calls(protocol)
    assert len(calls) >= 8
    for name, signature in calls.items():
        assert hasattr(dialogs, name), f"{dialogs.__name__} lacks {name} of {protocol.__name__}"
        mine = inspect.signature(getattr(dialogs, name))
        assert list(mine.parameters) == list(signature.parameters), (
            f"{dialogs.__name__}.{name}{mine} differs from {protocol.__name__}.{name}{signature}")


def test_project_questions_are_asked_through_the_window_and_answered():
    window = mock.Mock()
    dialogs = ProjectDialogs(window)
    for answer, meaning in ((Button.Save, True), (Button.Discard, False), (Button.Cancel, None),
                            (None, None)):
        window.ask.return_value = answer
        assert dialogs.ask_save_changes() is meaning
    title, text, buttons, default = window.ask.call_args.args
    # the readings, or only the certificate details entered (day review live76 F11: "Unsaved
    # readings" asked after only a certificate was issued)
    assert title == "Unsaved changes" and default == Button.Save
    window.ask.return_value = Button.Yes
    assert dialogs.ask_recover("run.anglebench.json", "2026-12-02 01:00:00")
    assert "run.anglebench.json, autosaved 2026-12-02 01:00:00" in window.ask.call_args.args[1]
    window.ask.return_value = Button.No
    assert not dialogs.ask_recover("an untitled project", "an unknown time")
    dialogs.tell("Cannot save", "why")
    window.tell.assert_called_once_with("Cannot save", "why")
    dialogs.show_title("AngleBench — run *")
    window.setWindowTitle.assert_called_once_with("AngleBench — run *")


def test_certificate_questions_and_the_suffix_of_the_file_type_chosen(tmp_path):
    window = mock.Mock()
    window.projects.last_dir.return_value = str(tmp_path)
    dialogs = CertificateDialogs(window)
    window.ask.return_value = Button.Yes
    assert dialogs.confirm_draft(["approver"]) and dialogs.confirm_implausible("2°")
    assert "These details are missing: approver." in window.ask.call_args_list[0].args[1]
    window.ask.return_value = Button.Discard  # anything but Yes: no
    assert not dialogs.confirm_draft(["approver"]) and not dialogs.confirm_implausible("2°")
    with mock.patch.object(save_file, "choose_save_file",
                           return_value=(str(tmp_path / "out"), "Excel workbook (*.xlsx)")) as ask:
        assert dialogs.choose_save_path("Export results", "r.csv", "CSV (*.csv);;Excel "
                                        "workbook (*.xlsx)") == str(tmp_path / "out.xlsx")
    assert ask.call_args.args[2] == str(tmp_path / "r.csv")  # offered in the last folder used
    with mock.patch.object(CertificateDialogs, "_multiline_answer", return_value="") as note:
        assert dialogs.ask_change_note(PendingRevision("polygon", "AB-1", replacement=True)) == ""
    assert "This certificate replaces AB-1." in note.call_args.args[1]


def test_the_separate_calibration_question_wraps_and_fits_the_screen(qtbot):
    """The register's refusal is a long sentence: QInputDialog's own label does not wrap, and
    the question was 2096 px wide on a 1280 px screen (#61, looked at under Xvfb)."""
    from PySide6.QtCore import QTimer
    from PySide6.QtWidgets import QApplication, QInputDialog

    from widgets.screen_fit import available_size

    dialogs = CertificateDialogs(None)  # no window: the dialog's own screen
    seen = {}

    def answer():
        dialog = QApplication.activeModalWidget()
        assert isinstance(dialog, QInputDialog)
        seen["width"], seen["free"] = dialog.width(), available_size(dialog)[0]
        dialog.setTextValue("as left after the adjustment")
        dialog.accept()

    QTimer.singleShot(200, answer)
    reason = "AB-2026-0001 already reports this calibration " + "(a long reason) " * 40
    assert dialogs.ask_separate_calibration(("AB-2026-0001",), reason) == \
        "as left after the adjustment"
    assert seen["width"] <= seen["free"]
