"""reg73 #2, #5, #6, #8: a number issued twice (an older state copied back, a backup
restored), a loss acknowledged, and the clock rules.

The attacks and accidents are made as the tester made them (/work/reg73/repro): rows copied
and put back with SQL, the database file copied and restored; nothing is imported from the
code they check but its public entry points."""

from __future__ import annotations

import datetime as dt
import json
import os
import shutil

import pytest
import sqlalchemy as sa

from models.certificate.metadata import CertificateMetadata
from models.register.printed_place import say_its_place
from models.register.store import IssueRequest, Register, RegisterError
from tests.register_forgery import stand_in_pdf

META = CertificateMetadata(item_serial="RX-1", item_description="Rotary encoder",
                           customer_name="Acme Optics", calibration_date="2026-11-20",
                           number_scheme="AB-{year}-{seq:04d}", approver="Dr. Li")
PROJECT = json.dumps({"format": "anglebench-project", "schema_version": 1, "workbenches": {}})
ISSUED = dt.datetime(2026, 11, 24, 10, 0, tzinfo=dt.timezone.utc)
UTC = dt.timezone.utc


def _rows(url: str, query: str) -> list[dict]:
    engine = sa.create_engine(url)
    with engine.connect() as conn:
        rows = [dict(r._mapping) for r in conn.execute(sa.text(query))]
    engine.dispose()
    return rows


def _sql(url: str, *statements: str, **params) -> None:
    engine = sa.create_engine(url)
    with engine.begin() as conn:
        for statement in statements:
            conn.execute(sa.text(statement), params)
    engine.dispose()


def _open(url: str, at: dt.datetime, key: str = "") -> Register:
    register = Register(url, timezone="UTC", key_file=key)
    register.clock = lambda: at  # type: ignore[method-assign]
    return register


def _issue(register: Register, **kwargs):
    return register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf, **kwargs)


def _entries(url: str) -> list[dict]:
    return _rows(url, "SELECT seq, kind, subject, body_json, recorded_at FROM entries "
                      "ORDER BY seq")


@pytest.fixture
def url(tmp_path) -> str:
    return f"sqlite:///{tmp_path / 'register.sqlite'}"


@pytest.fixture
def key(tmp_path) -> str:
    path = tmp_path / "keys" / "lab.key"
    path.parent.mkdir()
    path.write_bytes(os.urandom(32))
    return str(path)


# -- the clock (reg73 #6, #8) ------------------------------------------------------------------
def test_a_clock_a_year_ahead_minutes_after_the_last_issue_is_asked_not_trusted(url):
    """reg73 #6: a clock a year ahead a minute after the last issue was accepted, and every
    right clock refused for a year."""
    with _open(url, ISSUED) as register:
        _issue(register)
        register.clock = lambda: ISSUED + dt.timedelta(days=365, minutes=1)
        with pytest.raises(RegisterError, match=r"dated 2027-11-24, 365 days after") as asked:
            _issue(register)
        assert type(asked.value).__name__ == "DateToConfirm"  # the window asks it
        assert getattr(asked.value, "date", None) == dt.date(2027, 11, 24)
        # the technician knows today is 2026-11-24: refused, nothing recorded
        with pytest.raises(RegisterError, match=r"confirmed as 2026-11-24, but the computer's "
                                                r"clock gives 2027-11-24"):
            _issue(register, confirmed_date=dt.date(2026, 11, 24))
        assert [r.number for r in register.list()] == ["AB-2026-0001"]
        # a right clock issues on: nothing dated ahead blocks it
        register.clock = lambda: ISSUED + dt.timedelta(minutes=5)
        assert _issue(register)[0].number == "AB-2026-0002"


def test_a_yearly_lab_confirms_the_date_and_the_confirmation_is_chained(url):
    """reg73 #6: a lab issuing 367 days after its last certificate with a right clock was
    refused until an environment variable was set (the window could not set it)."""
    with _open(url, ISSUED) as register:
        _issue(register)
        register.clock = lambda: ISSUED + dt.timedelta(days=20)  # a month: not asked
        _issue(register)
        later = ISSUED + dt.timedelta(days=20 + 367)
        register.clock = lambda: later
        with pytest.raises(RegisterError, match="367 days after"):
            _issue(register)
        record = _issue(register, confirmed_date=later.date())[0]
        assert record.issue_date == later.date().isoformat()
        assert register.problems == [] and register.audit(pdfs=True) == []
    confirmed = [e for e in _entries(url) if e["kind"] == "date_confirmed"]
    assert [(e["subject"], json.loads(e["body_json"])["date"]) for e in confirmed] == [
        (record.number, later.date().isoformat())]
    assert json.loads(confirmed[0]["body_json"])["days_after_last"] == 367


def test_a_record_dated_ahead_is_corrected_by_a_recorded_clock_correction(url):
    """reg73 #6: a record dated by a clock a year ahead refused every right clock for a
    year, and nothing could end it."""
    ahead = ISSUED + dt.timedelta(days=365)
    with _open(url, ISSUED) as register:
        _issue(register)
        register.clock = lambda: ahead  # the date confirmed wrongly, as it happens
        assert _issue(register, confirmed_date=ahead.date())[0].number == "AB-2027-0001"
        right = ISSUED + dt.timedelta(minutes=10)
        register.clock = lambda: right
        with pytest.raises(RegisterError, match=r"AB-2027-0001.*clock-correction"):
            _issue(register)
        with pytest.raises(RegisterError, match="today's date confirmed"):
            register.correct_clock("I. Chen", "PC-3's year was typed 2027", None)
        with pytest.raises(RegisterError, match="a named person"):
            register.correct_clock("", "why", right.date())
        register.correct_clock("I. Chen", "PC-3's year was typed 2027", right.date())
        register.clock = lambda: right + dt.timedelta(minutes=1)
        assert _issue(register)[0].number == "AB-2026-0002"
        with pytest.raises(RegisterError, match="nothing to correct"):
            register.correct_clock("I. Chen", "again", right.date())
        assert register.audit(pdfs=True) == []
    chain = [(r["seq"], r["number"]) for r in _rows(url, "SELECT seq, number FROM certificates")]
    entries = {e["kind"]: e for e in _entries(url)}
    correction = json.loads(entries["clock_correction"]["body_json"])
    # the record dated ahead: the last chained, the date confirmed with AB-2027-0001
    assert correction["by"] == "I. Chen" and "AB-2027-0001" in correction["ahead"]
    assert correction["ahead_at"].startswith("2027-11-24")
    # the dates stand in the chain as issued, the correction between them
    places = sorted([*chain, *((e["seq"], e["kind"]) for e in _entries(url))])
    assert [p[1] for p in places] == ["AB-2026-0001", "AB-2027-0001", "date_confirmed",
                                      "clock_correction", "AB-2026-0002"]


def test_a_certificate_timed_before_the_last_entry_is_refused(url):
    """reg73 #8: the "clock set back" rule compared only with the last certificate."""
    with _open(url, ISSUED) as register:
        _issue(register)
        register.clock = lambda: ISSUED + dt.timedelta(seconds=52)
        register.withdraw("AB-2026-0001", "wrong customer")
        register.clock = lambda: ISSUED + dt.timedelta(seconds=2)
        with pytest.raises(RegisterError, match=r"before the register's last record \(the "
                                                r"withdrawal of certificate AB-2026-0001"):
            _issue(register)
        assert len(register.list()) == 1


# -- a number issued twice (reg73 #2) -------------------------------------------------------
def _copy_state(url: str) -> tuple[list[dict], list[dict]]:
    return (_rows(url, "SELECT name, value FROM register_state"),
            _rows(url, "SELECT name, last_value FROM counters"))


def _replay(url: str, state: list[dict], counters: list[dict], number: str) -> None:
    """The record ``number`` deleted and the state rows and counters copied earlier put
    back (reg73 repro/replay_state.sh)."""
    statements = ["DELETE FROM certificates WHERE number = :n", "DELETE FROM register_state",
                  "DELETE FROM counters"]
    _sql(url, *statements, n=number)
    for row in state:
        _sql(url, "INSERT INTO register_state (name, value) VALUES (:name, :value)", **row)
    for row in counters:
        _sql(url, "INSERT INTO counters (name, last_value) VALUES (:name, :last_value)", **row)


def test_a_number_found_issued_twice_is_recorded_and_stops_issuing_until_acknowledged(
        url, key, tmp_path):
    """reg73 #2: verify said "number issued again" of the first holder's PDF, recorded
    nothing, and issuing went on. The replay here is by someone who can write every file
    (the high-water mark beside the key deleted too, which nothing local can tell): the
    first holder's PDF, carrying the key's proof of issue (reg73 #3), is what finds it."""
    with _open(url, ISSUED, key) as register:
        _issue(register)
    state, counters = _copy_state(url)
    with _open(url, ISSUED + dt.timedelta(minutes=1), key) as register:
        first, first_pdf = _issue(register)
    _replay(url, state, counters, first.number)
    shutil.rmtree(tmp_path / "keys" / "lab.key.high-water")
    with _open(url, ISSUED + dt.timedelta(minutes=2), key) as register:
        assert register.problems == []  # the mark gone too: nothing local tells the replay
        again = _issue(register)[0]
        assert again.number == first.number == "AB-2026-0002"
        said: list = []
        say_its_place(register, "R-2.pdf", first_pdf, said.append)
        assert "issued again" in str(said[0]) and "recorded in the register" in str(said[-1])
    with _open(url, ISSUED + dt.timedelta(minutes=3), key) as register:
        assert any("issued twice" in str(p) for p in register.problems)
        with pytest.raises(RegisterError, match="issued twice"):
            _issue(register)
        with pytest.raises(RegisterError, match="a named person"):
            register.acknowledge_loss("", "")
        # the issue after the replay wrote a mark again, which tells how far numbers went
        body = register.acknowledge_loss("I. Chen", "state copied back by someone")
        assert register.problems == [] and body["by"] == "I. Chen"
        assert _issue(register)[0].number == "AB-2026-0003"
        loss = register.lost_acknowledged("AB-2026-0002")
        assert loss is not None and loss["by"] == "I. Chen"
        assert register.lost_acknowledged("AB-2026-0001") is None
        assert register.audit(pdfs=True) == []


def test_an_older_signed_state_copied_back_is_found_by_the_high_water_mark(url, key, tmp_path):
    """reg73 #2: with the key, an older signed state (rows, signature, counters) copied back
    after deleting the last record verified intact and the number was issued again."""
    with _open(url, ISSUED, key) as register:
        _issue(register)
    state, counters = _copy_state(url)
    with _open(url, ISSUED + dt.timedelta(minutes=1), key) as register:
        _issue(register)
    marks = list((tmp_path / "keys").glob("lab.key.high-water/*.json"))
    assert len(marks) == 1  # beside the key, outside the database
    _replay(url, state, counters, "AB-2026-0002")
    with _open(url, ISSUED + dt.timedelta(minutes=2), key) as register:
        assert any("held 2 ending at head" in str(p) for p in register.problems)
        assert any("counter AB-2026-#: it stands at 1, but it stood at 2" in str(p)
                   for p in register.problems)
        with pytest.raises(RegisterError, match="records were removed since"):
            _issue(register)
        register.acknowledge_loss("I. Chen", "AB-2026-0002 deleted, state copied back")
        assert register.problems == []
        # the counter moved past the number the mark saw issued: never issued twice
        assert _issue(register)[0].number == "AB-2026-0003"
    # a mark not signed with the key is not trusted
    forged = json.loads(marks[0].read_text())
    forged["records"] += 5
    marks[0].write_text(json.dumps(forged))
    with _open(url, ISSUED + dt.timedelta(minutes=3), key) as register:
        assert any("does not carry the laboratory key's signature" in str(p)
                   and "high-water" in str(p) for p in register.problems)


def test_a_lagging_writer_never_lowers_the_high_water_mark(url, key, tmp_path):
    """The mark only grows: written from a copy of an older state (a second process that
    lagged), it keeps the higher one."""
    with _open(url, ISSUED, key) as register:
        _issue(register)
    older = tmp_path / "older.sqlite"
    shutil.copy(url.split("///")[1], older)
    with _open(url, ISSUED + dt.timedelta(minutes=1), key) as register:
        _issue(register)
    mark = next((tmp_path / "keys").glob("lab.key.high-water/*.json"))
    before = json.loads(mark.read_text())
    shutil.copy(older, url.split("///")[1])  # the older copy back, then written to
    with _open(url, ISSUED + dt.timedelta(minutes=2), key) as register:
        assert register.problems
        with pytest.raises(RegisterError):
            register.withdraw("AB-2026-0001", "x")
    assert json.loads(mark.read_text()) == before


# -- a backup restored (reg73 #5) -----------------------------------------------------------
def test_after_a_restore_the_loss_is_acknowledged_and_no_number_is_issued_twice(url, key,
                                                                               tmp_path):
    """reg73 #5: after a backup was restored the numbers were issued again, the first lost
    certificate verified locked the register for good."""
    path = url.split("///")[1]
    backup = tmp_path / "backup.sqlite"
    with _open(url, ISSUED, key) as register:
        _issue(register)
    shutil.copy(path, backup)
    pdfs = {}
    with _open(url, ISSUED + dt.timedelta(hours=1), key) as register:
        for _ in range(2):
            record, pdf = _issue(register)
            pdfs[record.number] = pdf
    shutil.copy(backup, path)  # the disk died; last night's backup restored
    with _open(url, ISSUED + dt.timedelta(hours=2), key) as register:
        said: list = []
        say_its_place(register, "M-2.pdf", pdfs["AB-2026-0002"], said.append)
    with _open(url, ISSUED + dt.timedelta(hours=2), key) as register:
        assert register.problems  # the lost certificate recorded: issuing stops
        with pytest.raises(RegisterError):
            _issue(register)
        with pytest.raises(RegisterError, match="none of the register's counters"):
            register.acknowledge_loss("I. Chen", "disk died", "XY-0003")
        body = register.acknowledge_loss("I. Chen", "disk died; backup of 2026-11-23 restored",
                                         "AB-2026-0003")
        assert body["counters"] == {"AB-2026-#": [1, 3]}
        assert register.problems == []
        assert _issue(register)[0].number == "AB-2026-0004"
        assert register.audit(pdfs=True) == []
        for number in ("AB-2026-0002", "AB-2026-0003"):
            assert register.lost_acknowledged(number)["last_issued"] == "AB-2026-0003"
        assert register.lost_acknowledged("AB-2026-0004") is None


def test_without_the_key_a_loss_is_acknowledged_only_with_the_last_number(url, tmp_path):
    """reg73 #5 without the key: no high-water mark tells how far the numbers went, so the
    person must give the last number issued, and numbering moves past it; and a lost
    certificate's copy, carrying no proof of issue, records nothing that stops issuing
    (reg73 #3: the head it prints is public)."""
    path = url.split("///")[1]
    backup = tmp_path / "backup.sqlite"
    with _open(url, ISSUED) as register:
        _issue(register)
    shutil.copy(path, backup)
    with _open(url, ISSUED + dt.timedelta(hours=1)) as register:
        lost_pdf = _issue(register)[1]
    shutil.copy(backup, path)
    with _open(url, ISSUED + dt.timedelta(hours=2)) as register:
        said: list = []
        say_its_place(register, "M-2.pdf", lost_pdf, said.append)
        assert "cannot tell whether this was issued here" in str(said[0])
        assert register.problems == []
        with pytest.raises(RegisterError, match="give the last certificate number"):
            register.acknowledge_loss("I. Chen", "disk died")
        register.acknowledge_loss("I. Chen", "disk died", "AB-2026-0002")
        assert _issue(register)[0].number == "AB-2026-0003"
