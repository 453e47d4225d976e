"""Amend… in the real window (rev62 day review): it says before it replaces the window's
readings that it will (F3), shows the pending amendment until it is issued or ended (F3),
names the readings' source as the original did (F4), and the register window open beside
shows the amendment once issued (F11), its Workbench column as the tabs name them (F14).
A second original of the same calibration is asked about before the file name (F10); a
certificate that will be a test report says so, and why, before the file name, which is a
report's (F7)."""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import pytest
from pypdf import PdfReader
from PySide6.QtWidgets import QMessageBox

from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import Register

pytestmark = pytest.mark.slow  # certificates are issued from the window

#: a folder to keep the screenshots in (unset: the test's tmp_path)
SHOTS = Path(os.environ["ANGLEBENCH_TEST_SHOTS"]) if os.environ.get("ANGLEBENCH_TEST_SHOTS") \
    else None


def _pdf_text(path) -> str:
    return re.sub(r"\s+", " ", "".join(p.extract_text() for p in PdfReader(path).pages))


def _details(samples_dir, key: str, **changes) -> CertificateMetadata:
    data = json.loads((samples_dir / f"certificate_{key}.json").read_text(encoding="utf-8"))
    data.update({"example": False, "certificate_number": "", **changes})  # the lab's own
    return CertificateMetadata.from_dict(data)


def _answer_dialogs(window, tmp_path, samples_dir, key: str, calls: list, name: str) -> None:
    """The certificate's dialogs answered, each call recorded in order."""
    view = window.certificates.view
    view.edit_certificate_details = lambda meta, problems, raw: calls.append("details") or \
        _details(samples_dir, key)
    view.confirm_draft = view.confirm_implausible = view.confirm_standards = lambda *a: True
    view.ask_change_note = lambda revision: calls.append(("note", revision.number)) or \
        "row 5 AC x typed from the notebook"
    view.ask_separate_calibration = lambda numbers, reason: calls.append(
        ("separate", numbers, reason)) or ""
    view.confirm_test_report = lambda reasons: calls.append(("test report", reasons)) or True
    view.choose_save_path = lambda title, suggested, file_filter: calls.append(
        ("file", suggested)) or str(tmp_path / name)
    view.wait_cursor = lambda on: None
    view.show_status = lambda text, *_: calls.append(("status", text))
    view.tell = lambda title, text: calls.append(("tell", text))


def _grab(widget, tmp_path, name: str):
    path = (SHOTS or tmp_path) / name
    widget.grab().save(str(path))
    return path


def test_amend_says_what_it_replaces_shows_it_pending_and_keeps_the_readings_source(
        window, qtbot, samples_dir, tmp_path):
    window.resize(1254, 662)
    window.show()
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.load_sample()
    assert window.projects.save_to(tmp_path / "morning_polygon.anglebench.json")
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    calls: list = []
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "cert1.pdf")
    assert window.export_certificate()
    assert "Readings morning_polygon.anglebench.json" in _pdf_text(tmp_path / "cert1.pdf")
    number = calls[-1][1].split()[1]

    # a reading changed in the window, then Amend… in the register window
    model = polygon.table_model
    model.setData(model.index(0, 2), "0.75")
    assert window.projects.is_modified
    window.show_register()
    register_window = window.register_window
    register_window.tell = lambda title, text: calls.append(("register", text))
    asked: list = []
    window.ask = lambda title, text, *a: asked.append(text) or QMessageBox.StandardButton.Save
    register_window.table.selectRow(0)
    register_window.buttons["amend"].click()
    # the question names the consequence, and the window's change was saved to its file
    window.ask = lambda *a: QMessageBox.StandardButton.Discard
    assert asked == [f"Amend… opens the readings and details {number} was issued from in place "
                     "of the readings now in the window. Save the window's changes to their "
                     "project first? (Discard: they are lost)"]
    saved = json.loads((tmp_path / "morning_polygon.anglebench.json").read_text("utf-8"))
    assert saved["workbenches"]["polygon"]["rows"][0][2] == "0.75"
    assert calls[-1][1].startswith(f"The readings and details of {number} are open in place "
                                   "of the window's.")
    # pending: in the status bar and the title, until issued
    label = window.revision_label
    assert label.isVisible() and label.text() == f"Amending {number}"
    assert f"Amending {number}" in window.windowTitle()
    shot = _grab(window, tmp_path, "amend_pending.png")
    assert shot.stat().st_size > 0
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)

    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "cert1_amend.pdf")
    register_window.tell = lambda title, text: calls.append(("register", text))
    assert window.export_certificate()
    assert not label.isVisible() and "Amending" not in window.windowTitle()
    # the amendment names the readings' source as the original did (not "typed in AngleBench")
    text = _pdf_text(tmp_path / "cert1_amend.pdf")
    assert "Readings morning_polygon.anglebench.json" in text
    assert "readings typed in AngleBench" not in text
    # the register window, still open, lists the amendment and the original superseded
    table = register_window.table
    rows = {table.item(r, 0).text(): [table.item(r, c).text() for c in range(table.columnCount())]
            for r in range(table.rowCount())}
    assert set(rows) == {number, f"{number}-A1"}
    assert rows[number][1] == "superseded" and rows[f"{number}-A1"][2] == "amendment 1"
    assert rows[number][6] == "Polygon encoder test"  # the tab's title, not the key "polygon"
    _grab(register_window, tmp_path, "register_after_amend.png")
    with Register(register_url()) as register:
        assert register.get(f"{number}-A1").supersedes == number


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF read: of the questions asked
def test_a_second_original_is_asked_about_before_the_file_name(window, qtbot, samples_dir,
                                                              tmp_path):
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.load_sample()
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    calls: list = []
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "first.pdf")
    assert window.export_certificate()
    number = calls[-1][1].split()[1]
    polygon.table_model.setData(polygon.table_model.index(0, 2), "0.75")
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    calls.clear()
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "again.pdf")
    assert not window.export_certificate()
    assert [c if isinstance(c, str) else c[0] for c in calls] == ["details", "separate", "tell"]
    reason = calls[1][2]
    assert reason.startswith(f"{number} already reports this calibration (serial ")
    assert "Readings or details changed since are a correction" in reason
    assert "--separate-calibration" not in reason  # the command line's, not the window's
    assert calls[2][1] == (f"No certificate was written or recorded: {number} already reports "
                           "this calibration. To correct it, select it in File › Certificate "
                           "register and press Amend… or Replace….")
    assert not (tmp_path / "again.pdf").exists()
    # a calibration of its own: said why before the name, then issued
    calls.clear()
    window.certificates.view.ask_separate_calibration = lambda numbers, reason: calls.append(
        "separate") or "as left after the adjustment"
    assert window.export_certificate()
    assert calls[:3] == ["details", "separate", ("file", "polygon-certificate.pdf")]


@pytest.mark.usefixtures("pdf_stand_in")  # no PDF read: of the questions asked
def test_a_test_report_is_said_before_the_file_name_which_is_a_reports(window, qtbot,
                                                                      samples_dir, tmp_path):
    positioning = window.presenter("positioning")
    window.tabs.setCurrentIndex(window.presenters.index(positioning))
    positioning.load_sample()
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    calls: list = []
    _answer_dialogs(window, tmp_path, samples_dir, "positioning", calls, "positioning.pdf")
    assert _details(samples_dir, "positioning").document_type == "calibration"
    assert window.export_certificate()
    assert [c if isinstance(c, str) else c[0] for c in calls] == [
        "details", "test report", "file", "status"]
    reasons = calls[1][1]
    assert reasons and any("not stated" in r for r in reasons), reasons
    assert calls[2] == ("file", "positioning-report.pdf")
    assert calls[3][1].startswith("Test report ")
    # No: nothing written, no file name asked
    calls.clear()
    window.certificates.view.confirm_test_report = lambda reasons: calls.append("asked") or False
    assert not window.export_certificate()
    assert calls == ["details", "asked"]


def test_an_amendment_is_offered_its_own_name_and_never_written_over_the_original(
        window, qtbot, samples_dir, tmp_path):
    """Day review 65 F6: Amend… suggested the original's file name (its number, pre-filled in
    the details) and issued the amendment into it. The amendment's own number is suggested;
    the original's issued PDF is refused as the amendment's file, and stays as issued."""
    window.show()
    polygon = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(polygon))
    polygon.load_sample()
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    calls: list = []
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "cert1.pdf")
    assert window.export_certificate()
    number = calls[-1][1].split()[1]
    original = (tmp_path / "cert1.pdf").read_bytes()

    window.show_register()
    register_window = window.register_window
    register_window.tell = lambda title, text: calls.append(("register", text))
    register_window.table.selectRow(0)
    register_window.buttons["amend"].click()
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)
    polygon = window.presenter("polygon")
    polygon.table_model.setData(polygon.table_model.index(0, 2), "0.75")
    qtbot.waitUntil(lambda: window._current_result() is not None, timeout=20000)

    # the original's PDF chosen for the amendment: refused, the original as issued; the
    # details accepted as shown: the original's, its number pre-filled
    calls.clear()
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, "cert1.pdf")
    shown: list = []
    window.certificates.view.edit_certificate_details = \
        lambda meta, problems, raw: shown.append(meta) or meta
    assert not window.export_certificate()
    assert shown[0].certificate_number == number
    assert ("file", f"{number}-A1.pdf") in calls
    assert any(c[0] == "tell" and "never replaced" in c[1]
               for c in calls if isinstance(c, tuple)), calls
    assert (tmp_path / "cert1.pdf").read_bytes() == original
    # the name suggested taken: the amendment is issued into its own file
    _answer_dialogs(window, tmp_path, samples_dir, "polygon", calls, f"{number}-A1.pdf")
    window.certificates.view.edit_certificate_details = lambda meta, problems, raw: meta
    assert window.export_certificate()
    assert f"Certificate {number}-A1 " in _pdf_text(tmp_path / f"{number}-A1.pdf")
    assert (tmp_path / "cert1.pdf").read_bytes() == original
