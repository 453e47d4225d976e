"""The readings' identity stored with each record (schema version 8): every issue compared
its readings with every record's of the workbench, the identity made again from each
record's project state on every command-line issue (~2 ms a record: 20 s an issue in a
register of 10,000). Stored at issue, filled in once by the migration for the records
before it, looked up by its index; 'register verify' makes it again and reports one that
was set otherwise in the database."""

from __future__ import annotations

import sqlite3
from pathlib import Path

import pytest

from models.certificate.metadata import CertificateMetadata
from models.register import schema, store
from models.register.readings_identity import readings_key
from models.register.store import IssueRequest, ReadingsOfAnotherItem, Register, RegisterTampered
from tests.own_readings import theodolite_project, theodolite_sample_rows
from tests.read_only_file import deny_writing


def _rows(n: int) -> list[list[str]]:
    """The theodolite sample's readings with row 8's reading n tenths of a second of arc
    away: the readings of a calibration of their own."""
    rows = [list(r) for r in theodolite_sample_rows()]
    assert rows[7][1] == "-12°55'35.8\""
    rows[7][1] = f"-12°55'{35.8 + n / 10:.1f}\""
    return rows


def _issue(register: Register, serial: str, rows, **options):
    meta = CertificateMetadata(approver="Dr. Li", item_serial=serial,
                               calibration_date="2026-11-20",
                               item_description="Limited-rotation axis",
                               item_manufacturer="Example Instruments")
    return register.issue(IssueRequest("theodolite", meta, theodolite_project(rows)),
                          lambda m: f"%PDF {m.certificate_number}".encode(),
                          separate_calibration="", **options)[0]


def _keys(path: Path) -> dict[str, str | None]:
    with sqlite3.connect(path) as conn:
        return dict(conn.execute("SELECT number, readings_key FROM certificates"))


def _as_chain_format_6(path: Path, without_key: bool = False) -> None:
    """Every record as an AngleBench of schema 7 issued it: chain format 6 (its identity
    not in its chain; with ``without_key`` none stored), the chain and head made again."""
    from models.register.chain import GENESIS, link, link_entry

    with sqlite3.connect(path) as conn:
        conn.row_factory = sqlite3.Row
        conn.execute("UPDATE certificates SET chain_format = 6")
        if without_key:
            conn.execute("UPDATE certificates SET readings_key = NULL")
        items = sorted([(r["seq"], 0, dict(r)) for r in conn.execute("SELECT * FROM certificates")]
                       + [(r["seq"], 1, dict(r)) for r in conn.execute("SELECT * FROM entries")],
                       key=lambda t: (t[0], t[1]))
        head = GENESIS
        for _seq, is_entry, item in items:
            head = link_entry(head, item) if is_entry else link(head, item)
            conn.execute(f"UPDATE {'entries' if is_entry else 'certificates'} "
                         "SET chain_sha256 = ? WHERE seq = ?", (head, item["seq"]))
        conn.execute("UPDATE register_state SET value = ? WHERE name = 'head'", (head,))


def _without_version_9(path: Path) -> None:
    """The columns and indexes of schema version 9 dropped (the readings by their physical
    values, tests/models/register/test_readings_identity_stored.py)."""
    with sqlite3.connect(path) as conn:
        for index in ("certificates_readings_anchor", "certificates_readings_reach"):
            conn.execute(f"DROP INDEX {index}")
        for column in ("readings_layout", "readings_anchor", "readings_reach"):
            conn.execute(f"ALTER TABLE certificates DROP COLUMN {column}")


def _as_version_7(path: Path) -> None:
    """The register as schema version 7 left it: its records of chain format 6, no stored
    identity, no index."""
    _as_chain_format_6(path)
    _without_version_9(path)
    with sqlite3.connect(path) as conn:
        conn.execute("DROP INDEX certificates_readings_key")
        conn.execute("ALTER TABLE certificates DROP COLUMN readings_key")
        conn.execute("UPDATE schema_version SET version = 7")
        conn.execute("UPDATE register_state SET value = '7' WHERE name = 'schema_version'")


def test_each_record_stores_its_readings_identity_and_an_issue_makes_none_again(
        tmp_path, monkeypatch):
    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        records = [_issue(register, f"LRA-08{i:02d}", _rows(i)) for i in range(4)]
    assert _keys(path) == {r.number: readings_key(theodolite_project(_rows(i)), "theodolite")
                           for i, r in enumerate(records)}
    assert all(len(k) == 64 for k in _keys(path).values())
    made = []

    def counted(project_json: str, workbench: str) -> str:
        made.append(project_json)
        return readings_key(project_json, workbench)

    monkeypatch.setattr(store, "readings_key", counted)
    with Register(f"sqlite:///{path}") as register:  # a new command line: nothing cached
        # another item's readings (those of the second record) are still found …
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "LRA-0900", _rows(1))
        assert refused.value.numbers == (records[1].number,)
        # … by the request's identity alone: no record's made again from its readings
        assert made and set(made) == {theodolite_project(_rows(1))}
        made.clear()
        new = _issue(register, "LRA-0901", _rows(9))
        project = theodolite_project(_rows(9))
        assert set(made) == {project} and new.readings_key == readings_key(project, "theodolite")
        assert register.get(new.number).readings_key == new.readings_key


def test_a_register_of_version_7_gets_every_records_identity_once_its_chain_kept(tmp_path):
    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        records = [_issue(register, f"LRA-08{i:02d}", _rows(i)) for i in range(3)]
    keys = _keys(path)
    _as_version_7(path)
    with sqlite3.connect(path) as conn:
        chains = [row[0] for row in conn.execute(
            "SELECT chain_sha256 FROM certificates ORDER BY id")]
        head = conn.execute("SELECT value FROM register_state WHERE name = 'head'").fetchone()[0]
    with Register(f"sqlite:///{path}") as register:
        assert register.version == schema.LATEST == 9
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert register.chain_head() == head
        assert [register.get(r.number).chain_sha256 for r in records] == chains
        assert {register.get(r.number).chain_format for r in records} == {6}
    assert _keys(path) == keys
    with sqlite3.connect(path) as conn:
        assert "certificates_readings_key" in {row[0] for row in conn.execute(
            "SELECT name FROM sqlite_master WHERE type = 'index'")}
    # set back to 7 with the column there: refused, never migrated again
    with sqlite3.connect(path) as conn:
        conn.execute("UPDATE schema_version SET version = 7")
        conn.execute("UPDATE register_state SET value = '7' WHERE name = 'schema_version'")
    with pytest.raises(RegisterTampered, match=r"schema version 7 was set back \(the column "
                                               r"of version 8 \(readings_key\) exists\)"):
        Register(f"sqlite:///{path}")


def test_a_read_only_register_of_version_7_is_read_as_it_is(tmp_path, monkeypatch):
    """An archive at version 7 cannot be migrated: read as it is, its readings' identities
    made when compared, verified; nothing written."""
    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        first = _issue(register, "LRA-0800", _rows(0))
    _as_version_7(path)
    before = path.read_bytes()
    deny_writing(monkeypatch, path)
    with Register(f"sqlite:///{path}") as register:
        assert register.read_only and register.version == 7
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert register.get(first.number).readings_key is None
        assert [r.number for r in register.list()] == [first.number]
        meta = CertificateMetadata(approver="Dr. Li", item_serial="LRA-0900",
                                   calibration_date="2026-11-21",
                                   item_description="Limited-rotation axis")
        asked = register.readings_of_another_item("theodolite", meta, _rows(0))
        assert asked is not None and asked.numbers == (first.number,)
    assert path.read_bytes() == before


def test_a_record_issued_without_its_identity_is_compared_by_its_readings(tmp_path):
    """A record an AngleBench of schema 7 issued after the migration (still running) has no
    stored identity: its readings are still compared."""
    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        first = _issue(register, "LRA-0800", _rows(0))
    _as_chain_format_6(path, without_key=True)
    with Register(f"sqlite:///{path}") as register:
        assert register.audit(pdfs=True) == []
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "LRA-0900", _rows(0))
        assert refused.value.numbers == (first.number,)


@pytest.mark.parametrize("stored", ["other", "blank"])
def test_an_identity_set_otherwise_in_the_database_is_found_by_verify(tmp_path, stored):
    """Tampering as tests/models/register/test_register_tampering.py does it: the second
    record's identity set to another's (its readings then hidden from the check) or to
    "" (no readings): 'register verify' (audit with the stored files) names the record."""
    from app.main import main

    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        records = [_issue(register, f"LRA-08{i:02d}", _rows(i)) for i in range(3)]
        assert register.audit(pdfs=True) == []
    value = "0" * 64 if stored == "other" else ""
    with sqlite3.connect(path) as conn:
        conn.execute("UPDATE certificates SET readings_key = ? WHERE number = ?",
                     (value, records[1].number))
    with Register(f"sqlite:///{path}") as register:
        problems = [str(p) for p in register.audit(pdfs=True)]
    # in its chain (chain format 7: hostile79 #2), and made again from its readings
    assert problems == [f"record {records[1].number}: the hash chain is broken here (this "
                        "record, or one before it, was changed, inserted or deleted after "
                        "issue)",
                        f"record {records[1].number}: the identity of its readings stored "
                        "with it is not that of its readings (set otherwise after issue): "
                        "the check of readings issued again would not find them"]
    assert main(["register", "--register", f"sqlite:///{path}", "verify"]) == 3


@pytest.mark.parametrize("stored", ["other", "blank"])
def test_an_identity_set_otherwise_is_found_at_opening_and_launders_nothing(tmp_path, stored):
    """hostile79 #2: the identity of a record's readings set otherwise with sqlite3 hid them
    from the check of one item's readings issued as another's: a copy of them issued as
    LRA-0900's certificate, unsaid, the opening's check clean, until 'register verify'. In
    the chain of every record issued since (chain format 7): the opening finds it, nothing
    is issued."""
    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        first = _issue(register, "LRA-0800", _rows(0))
        assert register.audit(pdfs=True) == []
    with sqlite3.connect(path) as conn:
        conn.execute("UPDATE certificates SET readings_key = ? WHERE number = ?",
                     ("0" * 64 if stored == "other" else "", first.number))
    with Register(f"sqlite:///{path}") as register:
        assert [str(p) for p in register.problems] == [
            f"record {first.number}: the hash chain is broken here (this record, or one "
            "before it, was changed, inserted or deleted after issue)"]
        assert register.issue_refusal() is not None
        with pytest.raises(store.RegisterError, match="changed after issue"):
            _issue(register, "LRA-0900", _rows(0))
        assert [r.number for r in register.list()] == [first.number]
        assert register.get(first.number).chain_format == 8


def test_a_migrated_records_identity_set_otherwise_is_found_by_verify(tmp_path):
    """A record of a register of version 7 keeps its chain (format 6) when migration 8 fills
    in its identity: set otherwise afterwards, 'register verify' still finds it."""
    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        first = _issue(register, "LRA-0800", _rows(0))
    _as_version_7(path)
    with Register(f"sqlite:///{path}") as register:
        assert register.get(first.number).chain_format == 6
        assert register.audit(pdfs=True) == []
    with sqlite3.connect(path) as conn:
        conn.execute("UPDATE certificates SET readings_key = ?", ("0" * 64,))
    with Register(f"sqlite:///{path}") as register:
        assert register.problems == []
        assert [str(p) for p in register.audit(pdfs=True)] == [
            f"record {first.number}: the identity of its readings stored with it is not that "
            "of its readings (set otherwise after issue): the check of readings issued again "
            "would not find them"]


def test_a_full_disk_during_migration_8_says_so_and_leaves_version_7(tmp_path, monkeypatch):
    """hostile79 #1: a full disk during migration 8 (its journal holds every record's row
    rewritten, up to the register's size) was said as a register that cannot be opened for
    want of room for its journal's index; the migration is rolled back whole: version 7,
    no column, verified clean, and migrated once there is room."""
    path = tmp_path / "r.sqlite"
    with Register(f"sqlite:///{path}") as register:
        records = [_issue(register, f"LRA-08{i:02d}", _rows(i)) for i in range(3)]
    _as_version_7(path)
    with sqlite3.connect(path) as conn:  # no free page left by the column dropped
        conn.execute("VACUUM")
    real = store._sqlite_connect

    def no_room(dbapi_connection, record) -> None:  # the file may grow no more
        real(dbapi_connection, record)
        pages = dbapi_connection.execute("PRAGMA page_count").fetchone()[0]
        dbapi_connection.execute(f"PRAGMA max_page_count = {pages}")

    monkeypatch.setattr(store, "_sqlite_connect", no_room)
    with pytest.raises(store.RegisterError) as refused:
        Register(f"sqlite:///{path}")
    size = f"{path.stat().st_size / 1e6:.1f} MB"
    assert str(refused.value) == (
        f"the disk is full at {path}: migrating the register from schema version 7 to 9 "
        f"needs room for its journal (up to the register's own size, {size}); nothing was "
        "changed, the register is still at version 7 (free some space and try again)")
    with sqlite3.connect(path) as conn:
        assert conn.execute("SELECT version FROM schema_version").fetchall() == [(7,)]
        assert "readings_key" not in {r[1] for r in conn.execute(
            "PRAGMA table_info(certificates)")}
    monkeypatch.setattr(store, "_sqlite_connect", real)
    with Register(f"sqlite:///{path}") as register:
        assert register.version == 9 and register.audit(pdfs=True) == []
        assert [register.get(r.number).readings_key for r in records] == [
            readings_key(theodolite_project(_rows(i)), "theodolite") for i in range(3)]
