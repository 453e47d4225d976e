"""Closing right after a certificate is issued (gui78, live78 F9): the window asked the
generic "Unsaved changes — Save the changes to the project first?", though after the last
save the user had only issued a certificate. What the issue changed in the project: the
details typed in its dialog (the number left out) are stored in the project, for the next
certificate of it; the register keeps them with the certificate as issued. They are not in
the project's file: the window still asks (nothing is lost unasked), and says precisely
what is unsaved. Anything else changed too: the generic question, as before. An issue that
stored nothing new (the details as saved): no question at all."""

from __future__ import annotations

import json

import pytest
from PySide6.QtWidgets import QMessageBox

from tests.app.test_amend_flow import _answer_dialogs

pytestmark = pytest.mark.slow  # certificates are issued from the window


def _reopened_and_issued(window, qtbot, samples_dir, tmp_path):
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.load_sample()
    path = tmp_path / "morning.anglebench.json"
    assert window.projects.save_to(path)
    assert window.projects.open_project(path)  # a freshly reopened project, as the day's
    assert not window.projects.is_modified
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    calls: list = []
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "cert1.pdf")
    assert window.export_certificate()
    number = calls[-1][1].split()[1]
    return polygon, path, number


def _close_asked(window, answer) -> list:
    asked: list = []
    window.ask = lambda title, text, *a: asked.append((title, text)) or answer
    window.close()
    return asked


def test_closing_after_an_issue_says_the_details_it_stored_are_unsaved(window, qtbot,
                                                                        samples_dir,
                                                                        tmp_path):
    polygon, path, number = _reopened_and_issued(window, qtbot, samples_dir, tmp_path)
    assert window.projects.is_modified  # the details typed are in the project, not its file
    asked = _close_asked(window, QMessageBox.StandardButton.Cancel)
    assert asked == [("Unsaved changes", (
        f"Issuing {number} stored the certificate details entered for it in this project; "
        "they are not yet saved in morning.anglebench.json. The register keeps them with "
        "the certificate as issued; nothing else was changed since the project was saved. "
        "Save the details in the project (the next certificate of this project starts from "
        "them)?"))]
    assert window.projects.is_modified  # Cancel: the work stays, unsaved
    # Save: the details are in the file; then nothing is asked
    assert _close_asked(window, QMessageBox.StandardButton.Save)
    saved = json.loads(path.read_text(encoding="utf-8"))
    assert saved["metadata"]["certificates"]["polygon"]["customer_name"]
    assert saved["metadata"]["certificates"]["polygon"]["certificate_number"] == ""
    assert not window.projects.is_modified


def test_a_change_after_the_issue_gets_the_generic_question(window, qtbot, samples_dir,
                                                           tmp_path):
    polygon, _path, _number = _reopened_and_issued(window, qtbot, samples_dir, tmp_path)
    model = polygon.table_model
    model.setData(model.index(0, 2), "0.75")  # a reading changed after the issue
    asked = _close_asked(window, QMessageBox.StandardButton.Cancel)
    assert asked == [("Unsaved changes", "Save the changes to the project first?")]


def test_an_issue_with_the_details_as_saved_leaves_nothing_to_ask(window, qtbot, samples_dir,
                                                                  tmp_path):
    polygon, path, _number = _reopened_and_issued(window, qtbot, samples_dir, tmp_path)
    # the calibration as left: a reading of its own (the same readings and details are the
    # first calibration issued again, refused: register79), saved before its issue
    model = polygon.table_model
    typed = str(model.index(0, 2).data())
    model.setData(model.index(0, 2), typed[:-1] + str((int(typed[-1]) + 1) % 10))
    assert window.projects.save_to(path)
    calls: list = []
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "cert2.pdf")
    window.certificates.view.ask_separate_calibration = lambda numbers, reason: "as left"
    assert window.export_certificate()
    assert not window.projects.is_modified
    assert _close_asked(window, QMessageBox.StandardButton.Cancel) == []
