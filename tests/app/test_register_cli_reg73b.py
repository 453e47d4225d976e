"""reg73 #5, #6 on the command line: a backup restored as the docs advise, the loss
recorded with ``anglebench register acknowledge-loss``, the certificates lost with it
verified later; a record dated by a clock set ahead, then ``register clock-correction``.
The register of each test is its own (conftest.py); the accident is made as the tester made
it (the database file copied and put back)."""

from __future__ import annotations

import datetime as dt
import json
import shutil

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register
from tests.register_forgery import stand_in_pdf

META = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01", item_serial="RX-1",
                           number_scheme="AB-{year}-{seq:04d}")
PROJECT = json.dumps({"workbenches": {"polygon": {"rows": [["0", "0.41"], ["30", "-0.22"]]}}})


def _issue(at: dt.datetime | None = None, **kwargs) -> tuple[str, bytes]:
    with Register(register_url()) as register:
        if at is not None:
            register.clock = lambda: at  # type: ignore[method-assign]
        record, pdf = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf,
                                     **kwargs)
    return record.number, pdf


def test_a_restore_is_acknowledged_and_lost_certificates_are_said_lost(tmp_path, capsys):
    """reg73 #5: after a restore the first lost certificate verified locked the register
    for good and the later ones were "NOT in the register"."""
    database = register_url().split("///", 1)[1]
    _issue()
    shutil.copy(database, tmp_path / "backup.sqlite")
    lost = [_issue() for _ in range(2)]
    shutil.copy(tmp_path / "backup.sqlite", database)  # the disk died: backup restored
    for number, pdf in lost:
        (tmp_path / f"{number}.pdf").write_bytes(pdf)
    # the first lost certificate comes back before the loss is recorded: without the key it
    # carries no proof of issue, so nothing that stops issuing is recorded (reg73 #3)
    assert main(["register", "verify", str(tmp_path / f"{lost[0][0]}.pdf")]) == 1
    assert "cannot tell whether this was issued here" in capsys.readouterr().out
    assert main(["register", "acknowledge-loss", "--by", "I. Chen", "--reason",
                 "disk died, backup restored", "--last-number", lost[-1][0]]) == 0
    said = capsys.readouterr().out
    year = lost[-1][0].split("-")[1]
    assert "loss recorded by I. Chen" in said and f"AB-{year}-# 1 → 3" in said
    assert _issue()[0] == f"AB-{year}-0004"  # no number issued twice
    for number, _pdf in lost:
        assert main(["register", "verify", str(tmp_path / f"{number}.pdf")]) == 3
        out = capsys.readouterr().out
        assert f"LOST, ACKNOWLEDGED: {tmp_path / number}.pdf names {number}" in out
        assert "I. Chen" in out and "NOT in the register" not in out
    assert main(["register", "verify"]) == 0


def test_a_clock_set_ahead_is_corrected_on_the_command_line(capsys):
    """reg73 #6: every right clock was refused for a year after one record dated ahead."""
    now = dt.datetime.now(dt.timezone.utc).replace(microsecond=0)
    _issue(now - dt.timedelta(minutes=5))
    ahead = now + dt.timedelta(days=365)
    _issue(ahead, confirmed_date=ahead.astimezone().date())
    capsys.readouterr()
    assert main(["register", "clock-correction", "--by", "I. Chen", "--reason", "PC-3 a year "
                 "ahead", "--confirm-date", "1999-01-01"]) == 2
    assert "today's date confirmed" in capsys.readouterr().err
    today = dt.datetime.now().astimezone().date().isoformat()
    assert main(["register", "clock-correction", "--by", "I. Chen", "--reason", "PC-3 a year "
                 "ahead", "--confirm-date", today]) == 0
    said = capsys.readouterr().out
    assert "clock correction recorded by I. Chen" in said
    # the record dated ahead in words (day 74: "entry date_confirmed AB-…", the stored form)
    assert "entry " not in said and "certificate AB-" in said, said
    number, _pdf = _issue(dt.datetime.now(dt.timezone.utc) + dt.timedelta(seconds=1))
    assert number.startswith(f"AB-{now.year}-")
    assert main(["register", "verify"]) == 0
