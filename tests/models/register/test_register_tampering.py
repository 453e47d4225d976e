"""#40: tampering done as someone with the database's password would do it (raw SQL behind
AngleBench's back), on SQLite and PostgreSQL, and what the register finds: on opening
(``Register.problems``), in ``audit`` (what ``anglebench register verify`` prints), and by
refusing to issue into a broken chain. What no check inside the database can find — a chain
recomputed wholesale with its state — is found by a head noted outside it (the lab's log,
every certificate's foot)."""

from __future__ import annotations

import dataclasses
import datetime as dt
import json

import pytest
import sqlalchemy as sa

from models.certificate.metadata import CertificateMetadata
from models.register.chain import link
from models.register.schema import LATEST
from models.register.store import IssueRequest, Register, RegisterError, RegisterTampered

META = CertificateMetadata(item_serial="RX-1", item_description="Rotary encoder",
                           customer_name="Acme Optics", calibration_date="2026-11-20",
                           number_scheme="AB-{year}-{seq:04d}", approver="Dr. Li")
PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2026, 11, 24, 10, 0, tzinfo=dt.timezone.utc)


def render(meta: CertificateMetadata, head: str = "") -> bytes:
    return f"%PDF {meta.certificate_number} head {head}".encode()


def _open(url: str) -> Register:
    register = Register(url, timezone="UTC")
    register.clock = lambda: ISSUED
    return register


@pytest.fixture
def issued(register_url):
    """A register with three certificates and an interval; its URL and numbers."""
    with _open(register_url) as register:
        numbers = [register.issue(IssueRequest("polygon", META, PROJECT), render)[0].number
                   for _ in range(3)]
        register.set_interval("RX-1", 365)
        assert register.problems == [] and register.audit(pdfs=True) == []
        head = register.chain_head()
    return register_url, numbers, head


def sql(url: str, *statements: str, **params) -> None:
    """Raw SQL on the register, as an intruder would run it."""
    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))
    with engine.begin() as conn:
        for statement in statements:
            conn.execute(sa.text(statement), params)
    engine.dispose()


def found(url: str) -> list[str]:
    """What opening finds; the same must be what audit finds, and issuing is refused."""
    with _open(url) as register:
        on_opening = [str(p) for p in register.problems]
        assert on_opening == [str(p) for p in register.audit()]
        if on_opening:
            with pytest.raises(RegisterError, match="nothing is recorded into a broken chain"):
                register.issue(IssueRequest("polygon", META, PROJECT), render)
            with pytest.raises(RegisterError, match="broken chain"):
                register.set_interval("ZZ-1", 10)
        return on_opening


@pytest.mark.parametrize("version", [1, 2, 3, 4, 5, 6, 7])
def test_a_schema_version_set_back_is_refused_never_migrated(issued, version):
    url, numbers, head = issued
    sql(url, "UPDATE certificates SET customer = 'Someone Else' WHERE number = :n",
        f"UPDATE schema_version SET version = {version}", n=numbers[1])
    with pytest.raises(RegisterTampered, match=f"schema version {version} was set back"):
        Register(url)
    sql(url, f"UPDATE schema_version SET version = {LATEST}")  # nothing migrated meanwhile
    problems = found(url)
    assert any(f"record {numbers[1]}: the hash chain is broken" in p for p in problems)


@pytest.mark.parametrize("version", [0, -1, LATEST + 1])
def test_an_unknown_schema_version_is_refused(issued, version):
    url, _, _ = issued
    sql(url, f"UPDATE schema_version SET version = {version}")
    with pytest.raises(RegisterError, match=f"schema version {version}"):
        Register(url)


def test_a_state_copy_of_the_version_set_back_with_the_version_is_refused(issued):
    url, _, _ = issued
    sql(url, "UPDATE schema_version SET version = 3",
        "UPDATE register_state SET value = '3' WHERE name = 'schema_version'")
    with pytest.raises(RegisterTampered, match="set back"):
        Register(url)


@pytest.mark.parametrize("deleted", [1, 2])
def test_a_truncated_tail_is_found(issued, deleted):
    url, numbers, _ = issued
    for number in numbers[-deleted:]:
        sql(url, "DELETE FROM certificates WHERE number = :n", n=number)
    problems = found(url)
    assert any("records were deleted" in p for p in problems)
    assert any("counter AB-2026-#: it stands at 3, but no record was numbered 3" in p
               for p in problems)


def test_the_last_record_edited_and_rehashed_is_found(issued):
    url, _, _ = issued
    with _open(url) as register:  # the last record a certificate (not the interval)
        record, _ = register.issue(IssueRequest("polygon", META, PROJECT), render)
        before = register.chain_before(record.number)
    edited = {**record.__dict__, "customer": "Someone Else"}
    sql(url, "UPDATE certificates SET customer = 'Someone Else', chain_sha256 = :c "
        "WHERE number = :n", c=link(before, edited), n=record.number)
    problems = found(url)
    assert any("records were deleted (the tail truncated) or added" in p for p in problems)


def test_a_deleted_record_whose_number_is_issued_again_is_found(issued):
    url, numbers, head = issued
    sql(url, "DELETE FROM certificates WHERE number = :n", n=numbers[-1])
    with _open(url) as register:  # the same number typed again: refused, the chain broken
        typed = CertificateMetadata(**{**META.to_dict(), "standards": (),
                                       "certificate_number": numbers[-1]})
        with pytest.raises(RegisterError, match="broken chain"):
            register.issue(IssueRequest("polygon", typed, PROJECT), render)
    # the intruder also sets the counter and the state back: nothing inside the database
    # contradicts any more, and the number is issued again to other content …
    with _open(url) as register:
        entry_head = register.find_head(head)
    assert entry_head is not None
    sql(url, "DELETE FROM entries", "DELETE FROM calibration_intervals",
        "UPDATE counters SET last_value = 2",
        "UPDATE register_state SET value = '2' WHERE name = 'records'",
        "UPDATE register_state SET value = (SELECT chain_sha256 FROM certificates WHERE "
        "number = :n) WHERE name = 'head'", n=numbers[1])
    with _open(url) as register:
        assert register.problems == []
        again, _ = register.issue(IssueRequest("polygon", META, PROJECT), render)
        assert again.number == numbers[-1]
        # … but the head noted in the lab's log (or printed on a later certificate) is gone
        assert register.find_head(head) is None


def test_a_record_inserted_without_its_place_is_found(issued):
    url, numbers, _ = issued
    columns = ("number", "issued_at", "issue_date", "calibration_date", "workbench",
               "item_description", "item_manufacturer", "item_serial", "customer", "operator",
               "workstation", "status", "revision", "change_note", "project_json",
               "software_json", "headline_json", "pdf_sha256", "pdf")
    values = {c: "" for c in columns}
    values.update(number="AB-2026-0099", status="issued", revision="original",
                  project_json=PROJECT, software_json="{}", headline_json="{}",
                  pdf=b"%PDF forged")
    sql(url, f"INSERT INTO certificates ({', '.join(columns)}) VALUES "
        f"({', '.join(':' + c for c in columns)})", **values)
    problems = found(url)
    assert any("AB-2026-0099: it has no place in the hash chain" in p for p in problems)


def test_a_counter_set_back_is_found(issued):
    url, _, _ = issued
    sql(url, "UPDATE counters SET last_value = 1")
    assert any("set back after issue (a number would be issued twice)" in p
               for p in found(url))


def test_a_calibration_interval_changed_is_found(issued):
    url, _, _ = issued
    sql(url, "UPDATE calibration_intervals SET interval_days = 730")
    assert any("instrument RX-1: calibration interval 730 day(s), but the register's records "
               "set 365" in p for p in found(url))


def test_an_interval_entry_changed_is_found(issued):
    url, _, _ = issued
    sql(url, "UPDATE calibration_intervals SET interval_days = 730",
        "UPDATE entries SET body_json = '{\"days\": 730}' WHERE kind = 'interval'")
    assert any("the calibration interval of serial RX-1: the hash chain is broken" in p
               for p in found(url))


def test_a_withdrawn_certificate_is_a_chained_record_and_set_back_is_found(issued):
    url, numbers, _ = issued
    with _open(url) as register:
        register.withdraw(numbers[0], "wrong serial number printed")
        record = register.get(numbers[0])
        assert record.status == "withdrawn"
        assert record.withdrawn_reason == "wrong serial number printed"
        assert register.audit(pdfs=True) == []
        with pytest.raises(RegisterError, match="was withdrawn"):
            register.issue(IssueRequest("polygon", META, PROJECT), render,
                           supersedes=numbers[0])
        with pytest.raises(RegisterError, match="with a reason"):
            register.withdraw(numbers[1], "  ")
    sql(url, "UPDATE certificates SET status = 'issued' WHERE number = :n", n=numbers[0])
    assert any(f"record {numbers[0]}: marked \"issued\"" in p and "withdrawn" in p
               for p in found(url))


def test_a_withdrawal_reason_rewritten_or_added_by_hand_is_found(issued):
    """rev64 F9: the record's withdrawn_reason is a copy of the chained withdrawal entry's
    reason; rewritten with SQL it passed verify and issuing went on."""
    url, numbers, _ = issued
    with _open(url) as register:
        register.withdraw(numbers[0], "wrong standard used")
    sql(url, "UPDATE certificates SET withdrawn_reason = 'at the customer''s request' "
        "WHERE number = :n", n=numbers[0])
    problems = found(url)  # found on opening and by audit, and issuing is refused
    assert any(f"record {numbers[0]}: its reason for withdrawal reads \"at the customer's "
               f"request\", but the register's withdrawal record says \"wrong standard used\""
               in p for p in problems), problems
    sql(url, "UPDATE certificates SET withdrawn_reason = 'wrong standard used' "
        "WHERE number = :n", n=numbers[0])
    assert found(url) == []  # put back: nothing else was changed
    # a reason given to a certificate that was never withdrawn
    sql(url, "UPDATE certificates SET withdrawn_reason = 'void' WHERE number = :n",
        n=numbers[1])
    assert any(f"record {numbers[1]}: its reason for withdrawal reads \"void\"" in p
               and "it was never withdrawn" in p for p in found(url))


def test_a_stored_pdf_replaced_by_hand_stops_issuing(issued):
    """rev64 F12: verify found a stored PDF replaced in the database, but issuing went on
    (opening does not re-hash the PDFs); every other hand edit stops the next issue."""
    url, numbers, _ = issued
    sql(url, "UPDATE certificates SET pdf = (SELECT pdf FROM certificates WHERE number = :o) "
        "WHERE number = :n", o=numbers[1], n=numbers[0])
    with _open(url) as register:
        assert any(f"record {numbers[0]}: the stored PDF does not match" in str(p)
                   for p in register.audit(pdfs=True))
        before = register.chain_records()
        with pytest.raises(RegisterError, match=f"record {numbers[0]}: the stored PDF does not "
                                                "match the SHA-256 recorded at issue.*nothing "
                                                "is recorded into a broken chain"):
            register.issue(IssueRequest("polygon", META, PROJECT), render)
        assert register.chain_records() == before  # nothing recorded, no number used
    with _open(url) as register:  # the PDF put back: issuing goes on
        genuine = render(dataclasses.replace(META, certificate_number=numbers[0]),
                         head=register.chain_before(numbers[0]))
    sql(url, "UPDATE certificates SET pdf = :p WHERE number = :n", p=genuine, n=numbers[0])
    with _open(url) as register:
        assert register.issue(IssueRequest("polygon", META, PROJECT), render)[0].number


def test_a_whole_chain_recomputed_is_found_only_by_a_head_noted_outside(issued):
    """Honest limit: with the algorithm public, an intruder can recompute every chain value
    and the state; the database then agrees with itself. A head noted before (the lab's log,
    the foot of any certificate issued after the edited record) is no longer in it."""
    url, numbers, head = issued
    with _open(url) as register:
        printed = register.chain_before(numbers[2])  # what certificate 3 prints
        rows = {n: register.get(n) for n in numbers}
    previous = "0" * 64
    for number in numbers:
        fields = rows[number].__dict__
        if number == numbers[0]:
            fields = {**fields, "customer": "Someone Else"}
        previous = link(previous, fields)
        sql(url, "UPDATE certificates SET customer = :c, chain_sha256 = :h WHERE number = :n",
            c=fields["customer"], h=previous, n=number)
    from models.register.chain import link_entry

    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))
    with engine.connect() as conn:
        entry = conn.execute(sa.text("SELECT * FROM entries")).one()._asdict()
    engine.dispose()
    previous = link_entry(previous, entry)
    sql(url, "UPDATE entries SET chain_sha256 = :h",
        "UPDATE register_state SET value = :h WHERE name = 'head'", h=previous)
    assert found(url) == []  # inside the database, nothing contradicts
    with _open(url) as register:
        assert register.find_head(head) is None
        assert register.find_head(printed[:16]) is None


def test_verify_of_a_pdf_copied_into_a_second_record_names_both(issued):
    url, numbers, _ = issued
    with _open(url) as register:
        genuine = register.pdf(numbers[0])
        digest = register.get(numbers[0]).pdf_sha256
    sql(url, "UPDATE certificates SET pdf = :p, pdf_sha256 = :d WHERE number = :n",
        p=genuine, d=digest, n=numbers[1])
    with _open(url) as register:
        assert [r.number for r in register.verify_all(genuine)] == numbers[:2]
        assert any(f"record {numbers[1]}: the hash chain is broken" in str(p)
                   for p in register.problems)


def test_look_alike_numbers_and_serials_are_one(register_url):
    with _open(register_url) as register:
        typed = CertificateMetadata(**{**META.to_dict(), "standards": (),
                                       "certificate_number": "AB-2026-0001"})
        register.issue(IssueRequest("polygon", typed, PROJECT), render)
        for alike in ("AB\u20102026\u20100001", "AB\u20132026\u22120001", "ＡＢ-2026-0001",
                      " AB-2026-0001 "):
            with pytest.raises(RegisterError, match="AB-2026-0001 was issued on"):
                register.issue(IssueRequest("polygon", typed.__class__(**{
                    **typed.to_dict(), "standards": (), "certificate_number": alike}),
                    PROJECT), render)
        for hidden in ("AB-2026-0001\u200b", "AB-2026\u00ad-0001", "\u202eAB-2026-0001"):
            with pytest.raises(RegisterError, match="prints as nothing"):
                register.issue(IssueRequest("polygon", typed.__class__(**{
                    **typed.to_dict(), "standards": (), "certificate_number": hidden}),
                    PROJECT), render)
        with pytest.raises(RegisterError, match="kept for specimen"):
            register.issue(IssueRequest("polygon", typed.__class__(**{
                **typed.to_dict(), "standards": (), "certificate_number": "SPECIMEN-1"}),
                PROJECT), render)
        dashed = CertificateMetadata(**{**META.to_dict(), "standards": (),
                                        "item_serial": "RX\u20111"})
        record, _ = register.issue(IssueRequest("polygon", dashed, PROJECT), render)
        assert record.item_serial == "RX-1"
        assert [r.number for r in register.history("RX\u22121")] == ["AB-2026-0001",
                                                                     record.number]
        assert len(register.list()) == 2 and register.audit(pdfs=True) == []


def test_the_date_of_issue_is_the_labs_local_date(register_url):
    """At 07:30 in Beijing the UTC date is still the day before: the lab's date counts."""
    with Register(register_url, timezone="Asia/Shanghai") as register:
        register.clock = lambda: dt.datetime(2026, 12, 1, 23, 30, tzinfo=dt.timezone.utc)
        morning = CertificateMetadata(**{**META.to_dict(), "standards": (),
                                         "calibration_date": "2026-12-02"})
        record, _ = register.issue(IssueRequest("polygon", morning, PROJECT), render)
        assert record.issue_date == "2026-12-02"
        assert record.issued_at == "2026-12-01T23:30:00+00:00"  # UTC, with its offset
    with pytest.raises(RegisterError, match="time zone 'Mars/Olympus' is not known"):
        Register(register_url, timezone="Mars/Olympus")


def test_the_issuing_user_and_approver_are_chained(issued):
    url, numbers, _ = issued
    with _open(url) as register:
        record = register.get(numbers[0])
        assert record.approver == "Dr. Li" and record.os_user is not None
        assert record.chain_format == 8 and record.seq == 1  # every record since schema 9
    sql(url, "UPDATE certificates SET approver = 'Someone' WHERE number = :n", n=numbers[0])
    assert any(f"record {numbers[0]}: the hash chain is broken" in p for p in found(url))


def test_a_certificate_carries_the_head_before_it(issued):
    url, numbers, head = issued
    with _open(url) as register:
        pdfs = [register.pdf(n) for n in numbers]
        befores = [register.chain_before(n) for n in numbers]
        assert befores[0] == "0" * 64
        assert befores[1:] == [register.get(n).chain_sha256 for n in numbers[:2]]
        assert [f"head {b}".encode() in p for p, b in zip(pdfs, befores, strict=True)] == [
            True] * 3
        record, _ = register.issue(IssueRequest("polygon", META, PROJECT), render)
        assert register.chain_before(record.number) == head  # after the interval's entry
        assert json.loads(record.project_json)["metadata"]["certificates"]["polygon"][
            "certificate_number"] == record.number


def test_the_number_a_certificate_pdf_names_in_its_title():
    """What verify --head-from names a certificate by when its record is gone: its title's
    last word, a title fpdf2 writes as a literal string or, beyond Latin-1, as UTF-16."""
    from fpdf import FPDF

    from models.register.chain import number_in_pdf

    for title, number in (("Calibration certificate AB-2026-0001-A1", "AB-2026-0001-A1"),
                          ("校准证书 AB-2026-0002", "AB-2026-0002"),
                          ("Test report (draft) T\\1", "T\\1")):
        pdf = FPDF()
        pdf.set_title(title)
        pdf.add_page()
        assert number_in_pdf(bytes(pdf.output())) == number
    assert number_in_pdf(b"%PDF no title") == ""
    assert number_in_pdf(b"%PDF /Title (AB-1)") == ""  # one word: no number told from a label


def test_authorised_signatories_and_a_distinct_approver(register_url):
    with _open(register_url) as register:
        assert register.signatories() == ([], False)
        register.issue(IssueRequest("polygon", META, PROJECT), render)  # none listed: any
        register.set_signatories(["Dr. Li", "Ms. Wang"], distinct=True)
        assert register.signatories() == (["Dr. Li", "Ms. Wang"], True)
        stranger = CertificateMetadata(**{**META.to_dict(), "standards": (),
                                          "approver": "Mr. Nobody"})
        with pytest.raises(RegisterError, match="not one of the lab's authorised"):
            register.issue(IssueRequest("polygon", stranger, PROJECT), render)
        own = CertificateMetadata(**{**META.to_dict(), "standards": (), "operator": "dr.  li"})
        with pytest.raises(RegisterError, match="cannot approve a calibration they made"):
            register.issue(IssueRequest("polygon", own, PROJECT), render)
        other = CertificateMetadata(**{**META.to_dict(), "standards": (), "operator": "Tech"})
        record, _ = register.issue(IssueRequest("polygon", other, PROJECT), render)
        assert (record.approver, record.operator) == ("Dr. Li", "Tech")
        assert register.audit() == []
    sql(register_url, "UPDATE entries SET body_json = '{\"names\": [\"Mr. Nobody\"]}'")
    assert any("the list of authorised signatories: the hash chain is broken" in p
               for p in found(register_url))


def test_a_stalled_issuer_on_postgresql_is_named_not_waited_for_forever(postgres_server,
                                                                        monkeypatch):
    """#40: one stalled issuer blocked every other indefinitely; now a statement waits
    LOCK_TIMEOUT_S and the refusal names the session holding the lock."""
    from models.register import store

    url = postgres_server.new_database()
    with _open(url) as register:
        register.issue(IssueRequest("polygon", META, PROJECT), render)
    monkeypatch.setattr(store, "LOCK_TIMEOUT_S", 1)
    engine = sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"),
                              connect_args={"application_name": "stalled issuer"})
    with engine.connect() as stalled:
        stalled.execute(sa.text("SELECT pg_advisory_xact_lock(:k)"), {"k": store._CHAIN_LOCK})
        with _open(url) as register:  # opening and listing take no lock: not blocked
            assert len(register.list()) == 1
            with pytest.raises(RegisterError, match="waited 1 s for the register's lock, held "
                                                    "by pid .*stalled issuer"):
                register.set_interval("RX-1", 100)
        stalled.rollback()
    engine.dispose()
    with _open(url) as register:
        register.set_interval("RX-1", 100)
        assert register.interval("RX-1") == 100 and register.problems == []


def test_a_record_forged_after_the_last_genuine_one_is_found_with_the_labs_key(register_url,
                                                                                tmp_path):
    """#40 (optional part): chain and state can be recomputed by anyone; a signature with
    the lab's key, kept outside the database, cannot."""
    import os

    key = tmp_path / "lab.key"
    key.write_bytes(os.urandom(32))
    with Register(register_url, timezone="UTC", key_file=str(key)) as register:
        register.clock = lambda: ISSUED
        genuine = [register.issue(IssueRequest("polygon", META, PROJECT), render)[0]
                   for _ in range(2)]
        register.set_interval("RX-1", 365)
        assert all(r.signature and len(r.signature) == 64 for r in genuine)
        assert register.audit(pdfs=True) == []
    with _open(register_url) as intruder, pytest.raises(  # without the key: refused (reg72)
            RegisterError, match="ANGLEBENCH_REGISTER_KEY is not set"):
        intruder.issue(IssueRequest("polygon", META, PROJECT), render)
    with _open(register_url) as intruder, pytest.MonkeyPatch.context() as patch:
        # an AngleBench that does not refuse (0.8.20, or one changed): chain and state fine
        patch.setattr(Register, "_refuse_without_key", lambda self, conn: None)
        forged, _ = intruder.issue(IssueRequest("polygon", META, PROJECT), render)
        assert intruder.problems == [] and intruder.audit() == []
    with Register(register_url, timezone="UTC", key_file=str(key)) as register:
        said = [str(p) for p in register.problems]
        assert said[0] == (
            f"record {forged.number}: not signed with the laboratory's key (the last record "
            "and every one since the first signed are): added outside AngleBench, or issued "
            "without the key")
        # and the state it left is not the key's (reg72 #1)
        assert len(said) == 2 and "does not carry the laboratory key's signature" in said[1]
    sql(register_url, "UPDATE certificates SET signature = :s WHERE number = :n",
        s=genuine[1].signature, n=forged.number)  # a genuine signature copied
    with Register(register_url, timezone="UTC", key_file=str(key)) as register:
        assert any(f"record {forged.number}: its signature is not the laboratory key's" in
                   str(p) for p in register.problems)
    short = tmp_path / "short.key"
    short.write_bytes(b"secret")
    with pytest.raises(RegisterError, match="holds 6 bytes"):
        Register(register_url, key_file=str(short))
