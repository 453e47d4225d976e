"""regwin74: the register window records the two recoveries the command line has
(``anglebench register acknowledge-loss``, ``anglebench register clock-correction``): a
technician at the bench types who, why, the last number or today's date and clicks; the
register's state afterwards is what the command leaves, and a refusal is the command's own
words. The issue's "Not issued" points to the window's action and still names the command.

The register of each test is its own file (tests/conftest.py); the accidents are made as a
user makes them: the database file copied and put back (a restore), an issue on a clock a
year ahead and then the clock set right."""

from __future__ import annotations

import datetime as dt
import json

import pytest
from PySide6.QtCore import Qt

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import Register, RegisterError
from tests.app.test_certificate_presenter import COMPLETE, _theodolite, parts  # noqa: F401
from tests.register_accidents import issue, restored

pytestmark = pytest.mark.slow  # a main window each



def _type(qtbot, field, text: str) -> None:
    field.clear()
    qtbot.keyClicks(field, text)


def _opening(said: str) -> str:
    """The command's refusal as the dialog's line opens it: its first letter a capital."""
    return said[:1].upper() + said[1:]


def _entries(kind: str) -> list[dict]:
    import sqlalchemy as sa

    engine = sa.create_engine(register_url())
    with engine.connect() as conn:
        rows = [dict(r._mapping) for r in conn.execute(sa.text(
            "SELECT subject, body_json FROM entries WHERE kind = :k ORDER BY seq"), {"k": kind})]
    engine.dispose()
    return [{**r, "body": json.loads(r["body_json"])} for r in rows]


def test_a_restore_found_by_the_high_water_mark_is_acknowledged_in_the_window(
        window, qtbot, tmp_path, lab_key, told):
    _, lost = restored(tmp_path)
    year = lost[0].split("-")[1]
    with pytest.raises(RegisterError, match="records were removed since"):
        issue()  # the restore is found: nothing is issued
    window.show_register()
    dialog = window.register_window
    # on opening: the finding, and where the window records the loss
    assert told[0][0] == "Register changed after issue"
    assert "records were removed since" in told[0][1]
    assert "the button Acknowledge a loss… above the list" in told[0][1]  # day74
    qtbot.mouseClick(dialog.recovery_buttons["loss"], Qt.MouseButton.LeftButton)
    asked = dialog.recovery_dialog
    assert asked is not None and asked.isVisible()
    # with the key the mark tells how far the numbers went: the last number is optional
    notes = " ".join(label.text() for label in asked.findChildren(type(asked.refusal)))
    assert "Optional: the high-water mark" in notes
    _type(qtbot, asked.by, "I. Chen")
    _type(qtbot, asked.reason, "disk died, backup of last night restored")
    qtbot.mouseClick(asked.ok, Qt.MouseButton.LeftButton)
    assert dialog.recovery_dialog is None  # recorded: closed
    assert told[-1][0] == "Loss recorded"
    assert told[-1][1].startswith("Loss recorded by I. Chen")
    assert f"AB-{year}-# 1 → 3" in told[-1][1]
    # the register's state: the loss chained, the counter past the numbers lost, issuing on
    [entry] = _entries("loss_acknowledged")
    assert entry["body"]["by"] == "I. Chen"
    assert entry["body"]["counters"] == {f"AB-{year}-#": [1, 3]}
    with Register(register_url()) as register:
        assert register.problems == []
    assert issue() == f"AB-{year}-0004"  # no number issued twice


def test_without_a_key_the_window_asks_the_last_number_and_refuses_as_the_command(
        window, qtbot, tmp_path, told, capsys):
    """No key, so no high-water mark: the last number known issued is required, and the
    refusal without it is the command's sentence."""
    _, lost = restored(tmp_path)
    year = lost[0].split("-")[1]
    assert main(["register", "acknowledge-loss", "--by", "I. Chen", "--reason", "disk died"]) == 2
    command_said = capsys.readouterr().err.strip().removeprefix("anglebench register: ")
    assert "give the last certificate number known issued" in command_said
    window.show_register()
    dialog = window.register_window
    qtbot.mouseClick(dialog.recovery_buttons["loss"], Qt.MouseButton.LeftButton)
    asked = dialog.recovery_dialog
    notes = " ".join(label.text() for label in asked.findChildren(type(asked.refusal)))
    assert "Required: without the laboratory's key" in notes
    _type(qtbot, asked.by, "I. Chen")
    _type(qtbot, asked.reason, "disk died")
    qtbot.mouseClick(asked.ok, Qt.MouseButton.LeftButton)
    assert dialog.recovery_dialog is asked and asked.refusal.isVisible()  # kept open
    assert asked.refusal.text() == _opening(command_said)
    assert asked.by.text() == "I. Chen" and asked.reason.text() == "disk died"  # kept
    assert _entries("loss_acknowledged") == []
    _type(qtbot, asked.last_number, "XY-0003")  # a number of no counter: refused, kept
    qtbot.mouseClick(asked.ok, Qt.MouseButton.LeftButton)
    assert "is a number of none of the register's counters" in asked.refusal.text()
    assert asked.refusal.text().startswith("XY-0003 is a number")
    _type(qtbot, asked.last_number, lost[-1])
    qtbot.mouseClick(asked.ok, Qt.MouseButton.LeftButton)
    assert dialog.recovery_dialog is None
    [entry] = _entries("loss_acknowledged")
    assert entry["subject"] == lost[-1] and entry["body"]["reason"] == "disk died"
    assert issue() == f"AB-{year}-0004"


def test_a_clock_set_ahead_is_corrected_in_the_window(window, qtbot, told, capsys):
    now = dt.datetime.now(dt.timezone.utc).replace(microsecond=0)
    issue(now - dt.timedelta(minutes=5))
    ahead = now + dt.timedelta(days=365)
    dated_ahead = issue(ahead, confirmed_date=ahead.astimezone().date())
    with pytest.raises(RegisterError, match="before the register's last record"):
        issue()  # every right clock refused
    assert main(["register", "clock-correction", "--by", "I. Chen", "--reason", "PC-3",
                 "--confirm-date", "1999-01-01"]) == 2
    command_said = capsys.readouterr().err.strip().removeprefix("anglebench register: ")
    window.show_register()
    dialog = window.register_window
    qtbot.mouseClick(dialog.recovery_buttons["clock"], Qt.MouseButton.LeftButton)
    asked = dialog.recovery_dialog
    _type(qtbot, asked.by, "I. Chen")
    _type(qtbot, asked.reason, "PC-3")
    _type(qtbot, asked.confirmed_date, "1999-01-01")  # not today: refused as the command
    qtbot.mouseClick(asked.ok, Qt.MouseButton.LeftButton)
    assert asked.refusal.text() == _opening(command_said)
    assert "today's date confirmed" in command_said
    _type(qtbot, asked.confirmed_date, "today")
    qtbot.mouseClick(asked.ok, Qt.MouseButton.LeftButton)
    assert asked.refusal.text() == "--confirm-date today: not a date YYYY-MM-DD"
    assert _entries("clock_correction") == []
    _type(qtbot, asked.reason, "PC-3's year was typed a year ahead")
    _type(qtbot, asked.confirmed_date, dt.datetime.now().astimezone().date().isoformat())
    qtbot.mouseClick(asked.ok, Qt.MouseButton.LeftButton)
    assert dialog.recovery_dialog is None
    assert told[-1][0] == "Clock correction recorded"
    assert f"{dated_ahead}, dated {ahead.isoformat()}" in told[-1][1]
    [entry] = _entries("clock_correction")
    # the last chained record: the date confirmed (wrongly) with the certificate dated ahead
    assert entry["subject"] == f"entry date_confirmed {dated_ahead}"
    assert entry["body"]["by"] == "I. Chen"
    assert issue().startswith(f"AB-{now.year}-")  # a right clock issues again
    # nothing left to correct: refused with the command's words
    qtbot.mouseClick(dialog.recovery_buttons["clock"], Qt.MouseButton.LeftButton)
    again = dialog.recovery_dialog
    _type(qtbot, again.by, "I. Chen")
    _type(qtbot, again.reason, "again")
    _type(qtbot, again.confirmed_date, dt.datetime.now().astimezone().date().isoformat())
    qtbot.mouseClick(again.ok, Qt.MouseButton.LeftButton)
    assert again.refusal.text().startswith("Nothing to correct: the register's last record")
    qtbot.mouseClick(again.buttons.button(again.buttons.StandardButton.Cancel),
                     Qt.MouseButton.LeftButton)
    assert dialog.recovery_dialog is None and len(_entries("clock_correction")) == 1


def test_not_issued_points_to_the_windows_recoveries_and_names_the_commands(
        parts, samples_dir, tmp_path, lab_key):  # noqa: F811 - the fixture imported
    """The issue's refusal said only "'anglebench register acknowledge-loss …'" (or
    clock-correction): the technician at the bench had to find a terminal."""
    presenter, view, _, _ = parts
    kind, result = _theodolite(samples_dir)
    view.edit_certificate_details.return_value = COMPLETE
    restored(tmp_path)
    view.choose_save_path.return_value = str(tmp_path / "a.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    title, text = view.tell.call_args.args
    assert title == "Not issued" and "records were removed since" in text
    assert "File › Certificate register, Acknowledge a loss…" in text
    assert "anglebench register acknowledge-loss" in text
    assert not (tmp_path / "a.pdf").exists()
    with Register(register_url()) as register:
        register.acknowledge_loss("I. Chen", "restored")
    # another refusal (a number typed that was issued) points to no recovery
    view.edit_certificate_details.return_value = CertificateMetadata.from_dict(
        {**COMPLETE.to_dict(), "certificate_number": f"AB-{dt.date.today().year}-0001"})
    view.choose_save_path.return_value = str(tmp_path / "c.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    assert "was issued on" in view.tell.call_args.args[1]
    assert "Certificate register, " not in view.tell.call_args.args[1]
    view.edit_certificate_details.return_value = COMPLETE
    now = dt.datetime.now(dt.timezone.utc).replace(microsecond=0)
    ahead = now + dt.timedelta(days=365)
    issue(ahead, confirmed_date=ahead.astimezone().date())
    view.choose_save_path.return_value = str(tmp_path / "b.pdf")
    assert not presenter.export_certificate(kind, result, {}, "run.csv", [])
    title, text = view.tell.call_args.args
    assert title == "Not issued" and "before the register's last record" in text
    assert "File › Certificate register, Clock correction…" in text
    assert "anglebench register clock-correction" in text
