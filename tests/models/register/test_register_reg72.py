"""reg72: the register attacked by someone with write access to the database file but not
the lab's key (raw SQL, as /work/reg72/repro does). With the key the register's state is
signed too, so the last records deleted with the state row and counter set back are found;
a process without the key writes nothing into a signed register; every PDF issued carries
the digest of its record's content, so the newest record rewritten with its chain
recomputed is found from the customer's copy, key or no key.

The attacks recompute the chain themselves, from its documented definition (SHA-256 of the
previous value, a newline and the record's chained fields as sorted JSON): nothing is
imported from the code they check."""

from __future__ import annotations

import datetime as dt
import json
import os
import re

import pytest
import sqlalchemy as sa

from models.certificate.metadata import CertificateMetadata
from models.register.store import IssueRequest, Register, RegisterError
from tests.register_forgery import relinked, stand_in_pdf

META = CertificateMetadata(item_serial="RX-1", item_description="Rotary encoder",
                           customer_name="Acme Optics", calibration_date="2026-11-20",
                           number_scheme="AB-{year}-{seq:04d}", approver="Dr. Li")
PROJECT = json.dumps({"format": "anglebench-project", "schema_version": 1,
                      "workbenches": {"polygon": {"rows": [["0", "0.41"], ["30", "-0.22"]]}}})
ISSUED = dt.datetime(2026, 11, 24, 10, 0, tzinfo=dt.timezone.utc)
def _engine(url: str) -> sa.Engine:
    return sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))


def _sql(url: str, *statements: str, **params) -> None:
    engine = _engine(url)
    with engine.begin() as conn:
        for statement in statements:
            conn.execute(sa.text(statement), params)
    engine.dispose()


def _rows(url: str, query: str) -> list[dict]:
    engine = _engine(url)
    with engine.connect() as conn:
        rows = [dict(r._mapping) for r in conn.execute(sa.text(query))]
    engine.dispose()
    return rows


@pytest.fixture
def key(tmp_path) -> str:
    path = tmp_path / "lab.key"
    path.write_bytes(os.urandom(32))
    return str(path)


def _keyed(url: str, key: str) -> Register:
    register = Register(url, timezone="UTC", key_file=key)
    register.clock = lambda: ISSUED  # type: ignore[method-assign]
    return register


def _truncate(url: str, number: str) -> None:
    """The last record deleted, the state row and the counter set back to the record
    before it: the register agrees with itself (reg72 truncate_tail.sh)."""
    before = _rows(url, "SELECT chain_sha256, seq FROM certificates WHERE seq = (SELECT "
                        f"seq - 1 FROM certificates WHERE number = '{number}')")[0]
    _sql(url, "DELETE FROM certificates WHERE number = :n",
         "UPDATE register_state SET value = :records WHERE name = 'records'",
         "UPDATE register_state SET value = :head WHERE name = 'head'",
         "UPDATE counters SET last_value = last_value - 1",
         n=number, records=str(before["seq"]), head=before["chain_sha256"])


def test_a_tail_deleted_with_state_and_counter_set_back_is_found_with_the_key(register_url,
                                                                             key):
    with _keyed(register_url, key) as register:
        first, second = (register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)[0]
                         for _ in range(2))
        assert register.audit(pdfs=True) == []
    _truncate(register_url, second.number)
    with _keyed(register_url, key) as register:
        said = " ".join(str(p) for p in register.problems)
        assert "does not carry the laboratory key's signature" in said
        assert "deleted with the state set back" in said
        # the number is not issued again: nothing is issued into the register
        with pytest.raises(RegisterError, match="nothing is recorded into a broken chain"):
            register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)
    assert [r["number"] for r in _rows(register_url, "SELECT number FROM certificates")] == [
        first.number]


def test_a_counter_set_back_alone_is_found_with_the_key(register_url, key):
    with _keyed(register_url, key) as register:
        register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)
        register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)
    _sql(register_url, "UPDATE counters SET last_value = 0")
    with _keyed(register_url, key) as register:
        assert any("does not carry the laboratory key's signature" in str(p)
                   for p in register.problems)


def test_a_genuine_pdf_whose_record_was_deleted_is_lost_not_forged(register_url, key):
    """``register verify X.pdf`` of a certificate whose record is gone: the register LOST
    it (its printed head and number say it was issued there), not "NOT in the register"."""
    from models.register.printed_place import record_lost

    pdfs = {}
    with _keyed(register_url, key) as register:
        for _ in range(2):
            record, pdf = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)
            pdfs[record.number] = pdf
    last = list(pdfs)[-1]
    _truncate(register_url, last)
    with _keyed(register_url, key) as register:
        assert record_lost(register, pdfs[last])
        assert not record_lost(register, pdfs[list(pdfs)[0]])  # still there
        assert not record_lost(register, b"%PDF-1.4 a forgery")


def test_without_the_key_nothing_is_written_into_a_signed_register(register_url, key):
    with _keyed(register_url, key) as register:
        signed = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)[0]
    before = _rows(register_url, "SELECT * FROM register_state ORDER BY name")
    keyless = Register(register_url, timezone="UTC")
    keyless.clock = lambda: ISSUED
    with keyless:
        assert keyless.signed_unchecked() == 1
        for attempt in (lambda: keyless.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf),
                        lambda: keyless.withdraw(signed.number, "wrong item"),
                        lambda: keyless.set_interval("RX-1", 365)):
            with pytest.raises(RegisterError, match="ANGLEBENCH_REGISTER_KEY is not set"):
                attempt()
    assert _rows(register_url, "SELECT * FROM register_state ORDER BY name") == before
    with _keyed(register_url, key) as register:  # the keyed workstations go on issuing
        assert register.problems == []
        register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)


def test_the_newest_record_rewritten_with_its_chain_recomputed_is_found_from_its_pdf(
        register_url):
    """No key: the last record's readings and results rewritten, its chain value and the
    state's head recomputed. The register agrees with itself; the PDF does not agree with
    it (the digest of its record's content it carries)."""
    from models.register.printed_place import content_changed

    with Register(register_url, timezone="UTC") as register:
        register.clock = lambda: ISSUED
        register.issue(IssueRequest("polygon", META, PROJECT, {"peak_to_peak": 2.88}), stand_in_pdf)
        last, pdf = register.issue(IssueRequest("polygon", META, PROJECT,
                                                {"peak_to_peak": 2.88}), stand_in_pdf)
        assert content_changed(register, "last.pdf", pdf, register.get(last.number)) is None
    carried = re.search(rb"anglebench-record-content:([0-9a-f]{64})", pdf)
    assert carried is not None  # the PDF carries its record's digest
    row = _rows(register_url, f"SELECT * FROM certificates WHERE number = '{last.number}'")[0]
    previous = _rows(register_url, "SELECT chain_sha256 FROM certificates WHERE seq = "
                                   f"{row['seq'] - 1}")[0]["chain_sha256"]
    row["project_json"] = row["project_json"].replace("0.41", "0.14")
    row["headline_json"] = json.dumps({"peak_to_peak": 1.44})
    chain = relinked(previous, row)
    _sql(register_url, "UPDATE certificates SET project_json = :p, headline_json = :h, "
                       "chain_sha256 = :c WHERE number = :n",
         "UPDATE register_state SET value = :c WHERE name = 'head'",
         p=row["project_json"], h=row["headline_json"], c=chain, n=last.number)
    with Register(register_url, timezone="UTC") as register:
        assert register.problems == []  # the register agrees with itself
        found = register.verify(pdf)
        assert found is not None and found.number == last.number
        said = content_changed(register, "last.pdf", pdf, found)
        assert said is not None and "the record was rewritten after issue" in str(said)


#: a register as AngleBench 0.8.20 left it, made by that version's own Register (PYTHONPATH
#: at 148c03c1, stand-in PDFs) with the key beside it (32 fixed bytes, a test's): AB-2026-0001
#: and AB-2026-0002 issued signed at 2026-11-24T10:00Z, AB-2026-0001 withdrawn; audit clean
OLD = os.path.join(os.path.dirname(__file__), os.pardir, os.pardir, "fixtures",
                   "register_0_8_20_signed.sqlite")
OLD_HEAD = "1c0a0fd58ad744f1771f8e99d811b8e8d7a436280e49befa436e721fe442ad75"


def test_a_signed_register_of_0_8_20_verifies_and_signs_its_state_from_its_next_record(
        tmp_path):
    import shutil

    path = tmp_path / "register.sqlite"
    shutil.copy(OLD, path)
    key = str(tmp_path / "lab.key")
    shutil.copy(OLD.replace(".sqlite", ".key"), key)
    url = f"sqlite:///{path}"
    with _keyed(url, key) as register:  # no state signature yet: read as it was
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert register.chain_head() == OLD_HEAD
        register.clock = lambda: ISSUED + dt.timedelta(days=3)
        new = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)[0]
        assert new.number == "AB-2026-0003" and new.chain_format == 8
        assert register.chain_before(new.number) == OLD_HEAD
        assert register.audit(pdfs=True) == []
    assert _rows(url, "SELECT value FROM register_state WHERE name = 'state_signature'")
    # the new tail deleted, the state and the counter set back to what 0.8.20 left
    _sql(url, "DELETE FROM certificates WHERE number = :n",
         "UPDATE register_state SET value = '3' WHERE name = 'records'",
         "UPDATE register_state SET value = :h WHERE name = 'head'",
         "UPDATE counters SET last_value = 2", n=new.number, h=OLD_HEAD)
    with _keyed(url, key) as register:
        assert any("does not carry the laboratory key's signature" in str(p)
                   for p in register.problems)


def test_a_certificate_withdrawn_twice_is_refused_in_the_words_of_withdrawal(tmp_path):
    """reg72 #11: the second withdrawal said "it cannot be amended or replaced"."""
    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}", timezone="UTC") as register:
        register.clock = lambda: ISSUED
        number = register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)[0].number
        register.withdraw(number, "wrong item")
        with pytest.raises(RegisterError) as refused:
            register.withdraw(number, "again")
        assert str(refused.value) == (f"{number} was withdrawn already (wrong item): a "
                                      "certificate is withdrawn once")
