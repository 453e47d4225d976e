"""Day 74 finding 8: the 30-day date confirmation named the register's last record by its
database kind, "(entry loss_acknowledged —, 2026-12-07)": the kind's identifier and an empty
subject. Each record is named in words: a certificate by its number, an entry by what it
records ("the acknowledgement of a loss of records", "a clock correction", "the withdrawal of
certificate …"), never by the kind's identifier nor with a dash for a subject.

Only the words change: what the chain records of the last record (a clock correction's
subject, a date confirmed's "last") stays in the form it has had since 0.8.22.

The register is used as the window and the command line use it (issue, withdraw, acknowledge
a loss, correct the clock), its clock moved as a computer's would be; nothing else is
imported from the code it checks."""

from __future__ import annotations

import datetime as dt
import json
import os
import re

import pytest
import sqlalchemy as sa

from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register, RegisterError
from models.register.wording import recorded_words
from tests.register_forgery import stand_in_pdf

META = CertificateMetadata(item_serial="RX-1", item_description="Rotary encoder",
                           customer_name="Acme Optics", calibration_date="2026-11-20",
                           number_scheme="AB-{year}-{seq:04d}", approver="Dr. Li")
PROJECT = json.dumps({"format": "anglebench-project", "schema_version": 1, "workbenches": {}})
ISSUED = dt.datetime(2026, 12, 7, 9, 0, tzinfo=dt.timezone.utc)
#: a database kind's identifier (lower case words joined by "_"), as the message said it
IDENTIFIER = re.compile(r"\b[a-z]+_[a-z_]+\b")


def _open(url: str, at: dt.datetime, key: str = "") -> Register:
    register = Register(url, timezone="UTC", key_file=key)
    register.clock = lambda: at  # type: ignore[method-assign]
    return register


def _issue(register: Register, **kwargs):
    return register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf, **kwargs)


def _asked_after(register: Register, days: int) -> str:
    """The question a far-later issue asks (its date to confirm), in English."""
    register.clock = lambda: ISSUED + dt.timedelta(days=days)
    with pytest.raises(RegisterError) as asked:
        _issue(register)
    assert type(asked.value).__name__ == "DateToConfirm", asked.value
    return str(asked.value)


def _last_record_said(text: str) -> str:
    """What the question says the last record was: the words before its date."""
    found = re.search(r"after the register's last record \((.*), \d{4}-\d{2}-\d{2}\)", text)
    assert found, text
    return found.group(1)


@pytest.fixture
def url(tmp_path) -> str:
    return f"sqlite:///{tmp_path / 'register.sqlite'}"


def test_a_loss_acknowledged_is_named_in_words(url):
    with _open(url, ISSUED) as register:
        _issue(register)
        register.clock = lambda: ISSUED + dt.timedelta(minutes=5)
        register.acknowledge_loss("Li", "disk failed; backup restored",
                                  last_number="AB-2026-0001")
        said = _last_record_said(_asked_after(register, 40))
    assert "acknowledgement of a loss" in said and "AB-2026-0001" in said, said
    assert not IDENTIFIER.search(said) and "entry" not in said, said


def test_a_loss_acknowledged_from_the_mark_has_no_empty_subject(url, tmp_path):
    key = tmp_path / "keys" / "lab.key"
    key.parent.mkdir()
    key.write_bytes(os.urandom(32))
    with _open(url, ISSUED, str(key)) as register:
        _issue(register)
        register.clock = lambda: ISSUED + dt.timedelta(minutes=5)
        # the signed high-water mark tells how far the numbers went: no number given
        register.acknowledge_loss("Li", "disk failed; backup restored")
        said = _last_record_said(_asked_after(register, 40))
    assert "acknowledgement of a loss" in said, said
    assert "—" not in said and not said.rstrip().endswith(("(", ":")), said
    assert not IDENTIFIER.search(said) and "entry" not in said, said


def test_a_certificate_and_a_withdrawal_are_named_as_what_they_are(url):
    with _open(url, ISSUED) as register:
        number = _issue(register)[0].number
        said = _last_record_said(_asked_after(register, 31))
        assert said == f"certificate {number}", said
        # confirmed: issued, and its confirmation chained with it
        register.clock = lambda: ISSUED + dt.timedelta(days=31)
        later = _issue(register, confirmed_date=(ISSUED + dt.timedelta(days=31)).date())[0]
        said = _last_record_said(_asked_after(register, 31 + 31))
        assert later.number in said and "date" in said, said
        assert not IDENTIFIER.search(said) and "entry" not in said, said
        register.clock = lambda: ISSUED + dt.timedelta(days=31, minutes=5)
        register.withdraw(later.number, "wrong customer")
        said = _last_record_said(_asked_after(register, 31 + 32))
    assert said == f"the withdrawal of certificate {later.number}", said


def test_a_clock_correction_is_named_in_words(url):
    ahead = ISSUED + dt.timedelta(days=365)
    with _open(url, ISSUED) as register:
        _issue(register)
        register.clock = lambda: ahead
        _issue(register, confirmed_date=ahead.date())
        right = ISSUED + dt.timedelta(minutes=10)
        register.clock = lambda: right
        register.correct_clock("I. Chen", "PC-3's year was typed 2027", right.date())
        said = _last_record_said(_asked_after(register, 40))
    assert said == "a clock correction", said
    # what the chain records is kept as it was recorded since 0.8.22 (only the words change)
    engine = sa.create_engine(url)
    with engine.connect() as conn:
        subject, body = conn.execute(sa.text(
            "SELECT subject, body_json FROM entries WHERE kind = 'clock_correction'")).one()
    engine.dispose()
    assert subject == json.loads(body)["ahead"] == "entry date_confirmed AB-2027-0001"


def test_what_the_chain_recorded_reads_in_the_same_words(url):
    """A clock correction recorded the record dated ahead as the chain names it; read back
    for a person (the window's "Clock correction recorded: …") it is said in words."""
    ahead = ISSUED + dt.timedelta(days=365)
    with _open(url, ISSUED) as register:
        number = _issue(register)[0].number
        register.clock = lambda: ahead
        _issue(register, confirmed_date=ahead.date())
        register.clock = lambda: ISSUED + dt.timedelta(minutes=10)
        body = register.correct_clock("I. Chen", "year typed wrong",
                                      (ISSUED + dt.timedelta(minutes=10)).date())
    assert recorded_words(body["ahead"]) == "the date confirmed for certificate AB-2027-0001"
    assert recorded_words(number) == f"certificate {number}"
    assert recorded_words("entry loss_acknowledged —") == "the acknowledgement of a loss of records"
