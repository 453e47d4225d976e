"""day74 #7 in the register window: a register restored from a backup (its high-water mark
says records were issued since) is told once per window, on opening — not again before each
verify and each refresh — and kept in the window's state line while it holds, which no
longer says only "Every stored PDF matches its record." of a register that issues nothing;
the box points to the button above the list (the user is in that window). An issue on such
a register is refused before any question about the document. After the loss is
acknowledged the list shows the loss (and a clock correction) as rows of their own, with
the numbers issued and lost, so the gap is seen explained.

The accidents are made as a user makes them (tests/app/test_register_recoveries_in_window.py):
the database file copied and put back; an issue on a clock a year ahead."""

from __future__ import annotations

import datetime as dt

import pytest
from PySide6.QtCore import Qt

from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import Register
from tests.app.test_certificate_presenter import COMPLETE, _theodolite, parts  # noqa: F401
from tests.register_accidents import issue, restored

pytestmark = pytest.mark.slow  # a main window each

CHANGED = "Register changed after issue"


def _settled(qtbot, dialog) -> None:
    """The stored PDFs' check on its worker thread done."""
    for thread in dialog.background:
        thread.join(10)
    qtbot.waitUntil(lambda: "Checking" not in dialog.pdf_check.text(), timeout=20000)


def test_a_restore_is_told_once_per_window_and_kept_in_its_state_line(
        window, qtbot, tmp_path, lab_key, told, monkeypatch):
    import widgets.register_window as register_window

    kept, _lost = restored(tmp_path)
    with Register(register_url()) as register:
        (tmp_path / "kept.pdf").write_bytes(register.pdf(kept[0]))
    window.show_register()
    dialog = window.register_window
    _settled(qtbot, dialog)
    assert [title for title, _text in told] == [CHANGED]  # told on opening
    # a verify, a refresh, the window opened again: no second box of the same findings
    monkeypatch.setattr(register_window, "ask_open_file", lambda *a, **k: str(tmp_path / "kept.pdf"))
    qtbot.mouseClick(dialog.buttons["verify"], Qt.MouseButton.LeftButton)
    assert told[-1][0] == "Verified"
    window.show_register()
    _settled(qtbot, dialog)
    qtbot.mouseClick(dialog.buttons["verify"], Qt.MouseButton.LeftButton)
    boxes = [text for title, text in told if title == CHANGED]
    assert len(boxes) == 1
    # in the register window the button above the list is named, not the menu leading to it
    assert "the button Acknowledge a loss… above the list" in boxes[0]
    assert "File › Certificate register" not in boxes[0]
    # the state line keeps it while it holds
    assert dialog.pdf_check_warning
    assert dialog.pdf_check.text().startswith("⚠ The register issues nothing")
    assert "Every stored PDF matches its record." not in dialog.pdf_check.text()
    # once the loss is recorded the state line says the files again
    with Register(register_url()) as register:
        register.acknowledge_loss("I. Chen", "disk died, backup restored")
    window.show_register()
    _settled(qtbot, dialog)
    assert not dialog.pdf_check_warning
    assert dialog.pdf_check.text() == "Every stored PDF matches its record."


def _listed(dialog) -> list[list[str]]:
    table = dialog.table
    return [[table.item(row, column).text() if table.item(row, column) else ""
             for column in range(table.columnCount())] for row in range(table.rowCount())]


def test_the_list_shows_the_loss_and_the_numbers_lost(window, qtbot, tmp_path, told):
    kept, lost = restored(tmp_path, issued=2, lost=2)
    with Register(register_url()) as register:
        register.acknowledge_loss("I. Chen", "disk died", last_number=lost[-1])
    after = issue()
    window.show_register()
    dialog = window.register_window
    _settled(qtbot, dialog)
    rows = _listed(dialog)
    assert [row[0] for row in rows] == [after, ", ".join(lost), kept[1], kept[0]]
    loss = rows[1]
    assert loss[3] == "Loss acknowledged" and loss[1] == "issued and lost"
    # who recorded it and why in the customer's column; no links (register79: the last)
    assert loss[9] == "recorded by I. Chen: disk died" and loss[-1] == ""
    assert loss[4]  # the day it was recorded
    # the loss's row is no certificate: the certificate's actions say so
    dialog.table.selectRow(1)
    told.clear()
    qtbot.mouseClick(dialog.buttons["history"], Qt.MouseButton.LeftButton)
    assert told and "records a loss or a clock correction, not a certificate" in told[-1][1]
    # found by the search for a number lost
    dialog.search.setText(lost[0])
    assert [row[0] for row in _listed(dialog)] == [", ".join(lost)]
    dialog.search.setText(kept[0])
    assert [row[0] for row in _listed(dialog)] == [kept[0]]


def test_the_list_shows_a_clock_correction(window, qtbot, told):
    now = dt.datetime.now(dt.timezone.utc).replace(microsecond=0)
    first = issue(now - dt.timedelta(minutes=5))
    ahead = now + dt.timedelta(days=365)
    dated_ahead = issue(ahead, confirmed_date=ahead.astimezone().date())
    with Register(register_url()) as register:
        register.correct_clock("I. Chen", "PC-3 a year ahead", dt.datetime.now().astimezone()
                               .date())
    window.show_register()
    dialog = window.register_window
    _settled(qtbot, dialog)
    rows = _listed(dialog)
    # the record dated ahead stays first (newest by its date); the correction below it
    assert [row[3] for row in rows].count("Clock correction") == 1
    row = next(r for r in rows if r[3] == "Clock correction")
    assert dated_ahead in row[0] and row[1] == "dated by a clock set ahead"
    assert not row[0].startswith("entry ")  # the record named in words
    assert row[9].startswith("recorded by I. Chen: PC-3 a year ahead;") and row[-1] == ""
    assert {r[0] for r in rows if r[3] != "Clock correction"} == {first, dated_ahead}


def test_an_issue_on_a_register_that_issues_nothing_is_refused_before_any_question(
        parts, samples_dir, tmp_path, lab_key):  # noqa: F811 - the fixture imported
    """day74 #7 b: "Issue it as a test report?" (and the file dialog) came first, the
    register's refusal after Yes."""
    presenter, view, _, _ = parts
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = COMPLETE
    restored(tmp_path)
    view.choose_save_path.return_value = str(tmp_path / "a.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    title, text = view.tell.call_args.args
    assert title == "Not issued" and "records were removed since" in text
    assert "Acknowledge a loss…" in text
    view.choose_save_path.assert_not_called()
    view.confirm_test_report.assert_not_called()
    view.ask_separate_calibration.assert_not_called()
    assert not (tmp_path / "a.pdf").exists()
    # a draft, never recorded, is still written
    view.edit_certificate_details.return_value = CertificateMetadata(lab_name="Lab")
    view.confirm_draft.return_value = True
    view.choose_save_path.return_value = str(tmp_path / "draft.pdf")
    assert presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert (tmp_path / "draft.pdf").exists()


@pytest.mark.parametrize("keyed", [True, False])
def test_an_altered_copy_is_called_altered_not_absent_from_the_register(
        window, qtbot, tmp_path, told, monkeypatch, request, keyed):
    """A copy of a certificate edited after issue (a comment saved into the PDF) was told in
    a box titled "Not in the register", whose text said it may be a draft or another
    register's, beside the finding that it is this register's record altered. The title now
    says what ``register verify`` says: "Altered after issue" where the register proves the
    copy altered (with the lab's key, its record signed and intact), "Changed after issue"
    where it cannot rule out the record replaced (no key); the finding alone, no "draft"."""
    import widgets.register_window as register_window

    if keyed:
        request.getfixturevalue("lab_key")
    number = issue()
    issue()
    with Register(register_url()) as register:
        pdf = register.pdf(number)
    at = pdf.rfind(b"%%EOF")
    at = len(pdf) if at < 0 else at
    (tmp_path / "edited.pdf").write_bytes(pdf[:at] + b"\n% edited after issue\n" + pdf[at:])
    monkeypatch.setattr(register_window, "ask_open_file",
                        lambda *a, **k: str(tmp_path / "edited.pdf"))
    window.show_register()
    dialog = window.register_window
    _settled(qtbot, dialog)
    told.clear()
    qtbot.mouseClick(dialog.buttons["verify"], Qt.MouseButton.LeftButton)
    title, text = told[-1]
    if keyed:
        assert title == "Altered after issue"
        assert text.startswith(f"ALTERED: {tmp_path / 'edited.pdf'} ({number})")
        assert "the copy was altered after issue" in text
    else:
        assert title in ("Altered after issue", "Changed after issue")
        assert "replaced" in text or "issued again" in text
    assert "draft" not in text and "Not in the register" not in title
