"""The readings' identity by their physical values stored with each record (schema version 9,
ident80): migration 9 fills it in once for the records before it, in its one transaction
(killed half-way, version 8 is left whole), keeping every chain value (readings_key stays in
the chains of format 7); records issued since chain it (format 8), so one set otherwise in
the database is found at opening; 'register verify' makes every record's again. SQLite and
PostgreSQL."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest
import sqlalchemy as sa

from models.certificate.metadata import CertificateMetadata
from models.readings.angles import parse_angle_deg
from models.register import schema, store
from models.register.readings_identity import readings_identity
from models.register.store import ReadingsOfAnotherItem, Register, RegisterTampered
from tests.models.register.test_readings_key_stored import _issue
from tests.own_readings import theodolite_project, theodolite_sample_rows
from tests.read_only_file import deny_writing

ROOT = Path(__file__).parents[3]
IDENTITY = ("readings_layout", "readings_anchor", "readings_reach")


def _rows(n: int) -> list[list[str]]:
    """The sample's readings with row 8's azimuth n tenths of a second of arc away."""
    rows = [list(r) for r in theodolite_sample_rows()]
    rows[7][1] = f"-12°55'{35.8 + n / 10:.1f}\""
    return rows


def _decimal(rows, places: int = 8):
    return [[r[0], f"{parse_angle_deg(r[1]):.{places}f}", f"{parse_angle_deg(r[2]):.{places}f}"]
            for r in rows]


def _engine(url: str) -> sa.Engine:
    return sa.create_engine(url.replace("postgresql://", "postgresql+psycopg://"))


def _select(url: str, query: str) -> list[tuple]:
    engine = _engine(url)
    with engine.begin() as conn:
        rows = [tuple(r) for r in conn.execute(sa.text(query))]
    engine.dispose()
    return rows


def _as_version_8(url: str) -> None:
    """The register as schema version 8 left it: its records of chain format 7 (their
    readings_key chained, no identity by physical values), the chain and head made again,
    the columns and indexes of version 9 dropped."""
    from models.register.chain import GENESIS, link, link_entry

    engine = _engine(url)
    with engine.begin() as conn:
        conn.execute(sa.text("UPDATE certificates SET chain_format = 7"))
        certificates = [(r["seq"], 0, dict(r)) for r in conn.execute(
            sa.text("SELECT * FROM certificates")).mappings()]
        entries = [(r["seq"], 1, dict(r)) for r in conn.execute(
            sa.text("SELECT * FROM entries")).mappings()]
        head = GENESIS
        for _seq, is_entry, item in sorted(certificates + entries, key=lambda t: t[:2]):
            head = link_entry(head, item) if is_entry else link(head, item)
            conn.execute(sa.text(f"UPDATE {'entries' if is_entry else 'certificates'} "
                                 "SET chain_sha256 = :h WHERE seq = :s"),
                         {"h": head, "s": item["seq"]})
        for statement in ("DROP INDEX certificates_readings_anchor",
                          "DROP INDEX certificates_readings_reach",
                          *(f"ALTER TABLE certificates DROP COLUMN {c}" for c in IDENTITY),
                          "UPDATE schema_version SET version = 8",
                          "UPDATE register_state SET value = '8' WHERE name = 'schema_version'"):
            conn.execute(sa.text(statement))
        conn.execute(sa.text("UPDATE register_state SET value = :h WHERE name = 'head'"),
                     {"h": head})
    engine.dispose()


def _version_8_register(url: str) -> tuple[list, list[tuple]]:
    """Three records issued, the register set back as version 8 left it: the records and
    their (number, chain value) in order."""
    with Register(url) as register:
        records = [_issue(register, f"LRA-08{i:02d}", _rows(i)) for i in range(3)]
    _as_version_8(url)
    return records, _select(url, "SELECT number, chain_sha256 FROM certificates ORDER BY seq")


def test_each_record_issued_stores_and_chains_its_readings_by_their_values(register_url):
    with Register(register_url) as register:
        first = _issue(register, "LRA-0800", _rows(0))
        assert first.chain_format == 8
        identity = readings_identity(theodolite_project(_rows(0)), "theodolite")
        assert (first.readings_layout, first.readings_anchor, first.readings_reach) == \
            identity.stored
        assert register.get(first.number).readings_layout == identity.layout
        assert len(identity.layout) == 64 and identity.reach > 0
        assert register.audit(pdfs=True) == []


def test_a_register_of_version_8_gets_every_records_identity_once_its_chain_kept(
        register_url):
    records, chains = _version_8_register(register_url)
    with Register(register_url) as register:
        assert register.version == schema.LATEST == 9
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert {register.get(r.number).chain_format for r in records} == {7}
        # the readings_key of format 7 kept as it was, in its chain
        assert [register.get(r.number).readings_key for r in records] == \
            [r.readings_key for r in records]
        # the identity filled in from each record's readings: a re-typed copy is found
        assert [(register.get(r.number).readings_layout, register.get(r.number).readings_anchor,
                 register.get(r.number).readings_reach) for r in records] == [
            readings_identity(theodolite_project(_rows(i)), "theodolite").stored
            for i in range(3)]
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "LRA-0900", _decimal(_rows(1)))
        assert refused.value.numbers == (records[1].number,)
        new = _issue(register, "LRA-0901", _rows(9))
        assert new.chain_format == 8 and register.audit(pdfs=True) == []
    assert _select(register_url, "SELECT number, chain_sha256 FROM certificates ORDER BY seq"
                   )[:3] == chains
    # set back to 8 with the columns there: refused, never migrated again
    engine = _engine(register_url)
    with engine.begin() as conn:
        conn.execute(sa.text("UPDATE schema_version SET version = 8"))
        conn.execute(sa.text("UPDATE register_state SET value = '8' WHERE name = "
                             "'schema_version'"))
    engine.dispose()
    with pytest.raises(RegisterTampered, match=r"schema version 8 was set back \(the columns "
                                               r"of version 9 \(readings_layout …\) exist\)"):
        Register(register_url)


def test_migration_9_killed_half_way_leaves_version_8(register_url):
    """The process killed (os._exit: no rollback, no clean-up) after every record's identity
    was written and before the commit: the next opening finds version 8 whole and migrates
    it."""
    records, chains = _version_8_register(register_url)
    program = (
        "import os, sys\n"
        "from models.register import schema\n"
        "from models.register.store import Register\n"
        "migrate = schema.MIGRATIONS[9]\n"
        "def killed(conn):\n"
        "    migrate(conn)\n"
        "    os._exit(9)\n"
        "schema.MIGRATIONS[9] = killed\n"
        "Register(sys.argv[1])\n")
    done = subprocess.run([sys.executable, "-c", program, register_url], cwd=ROOT, timeout=120,
                          env={**os.environ, "PYTHONPATH": str(ROOT)}, capture_output=True)
    assert done.returncode == 9, done.stderr
    assert _select(register_url, "SELECT version FROM schema_version") == [(8,)]
    engine = _engine(register_url)
    with engine.begin() as conn:
        columns = {c["name"] for c in sa.inspect(conn).get_columns("certificates")}
    engine.dispose()
    assert not set(IDENTITY) & columns
    with Register(register_url) as register:
        assert register.version == 9 and register.audit(pdfs=True) == []
        assert register.get(records[2].number).readings_layout == readings_identity(
            theodolite_project(_rows(2)), "theodolite").layout
    assert _select(register_url, "SELECT number, chain_sha256 FROM certificates ORDER BY seq"
                   ) == chains


@pytest.mark.parametrize("column,value", [("readings_layout", "0" * 64),
                                          ("readings_anchor", 0), ("readings_reach", 0)])
def test_an_identity_set_otherwise_is_found_at_opening_and_by_verify(register_url, column,
                                                                     value):
    """Set otherwise with SQL (hostile79 #2's route, on the new identity): the record's
    readings would be hidden from the look-up; in its chain (format 8), the opening finds it
    and nothing is issued; verify names it."""
    with Register(register_url) as register:
        first = _issue(register, "LRA-0800", _rows(0))
    engine = _engine(register_url)
    with engine.begin() as conn:
        conn.execute(sa.text(f"UPDATE certificates SET {column} = :v"), {"v": value})
    engine.dispose()
    with Register(register_url) as register:
        assert [str(p) for p in register.problems] == [
            f"record {first.number}: the hash chain is broken here (this record, or one "
            "before it, was changed, inserted or deleted after issue)"]
        with pytest.raises(store.RegisterError, match="changed after issue"):
            _issue(register, "LRA-0900", _decimal(_rows(0)))
        assert f"record {first.number}: the identity of its readings stored with it is not " \
               "that of its readings" in " ".join(str(p) for p in register.audit(pdfs=True))
        assert [r.number for r in register.list()] == [first.number]


@pytest.mark.parametrize("column", IDENTITY)
def test_a_column_of_version_9_dropped_is_said_at_opening(register_url, column):
    """A column of version 9 dropped with SQL (ident80b: ALTER TABLE … DROP COLUMN
    readings_anchor gave a raw "no such column" at opening): the register's own refusal,
    as for a table gone, naming the table and the column; nothing opened."""
    with Register(register_url) as register:
        _issue(register, "LRA-0800", _rows(0))
    engine = _engine(register_url)
    with engine.begin() as conn:
        for statement in ("DROP INDEX certificates_readings_anchor",
                          "DROP INDEX certificates_readings_reach",
                          f"ALTER TABLE certificates DROP COLUMN {column}"):
            conn.execute(sa.text(statement))
    engine.dispose()
    with pytest.raises(RegisterTampered) as refused:
        Register(register_url)
    said = str(refused.value)
    assert said.startswith("register ") and "no such column" not in said
    assert said.endswith(f": its table certificates lacks the column(s) {column} of schema "
                         "version 9: it has been altered outside AngleBench; the register "
                         "is not opened; restore it from a backup")


def test_a_migrated_records_identity_set_otherwise_is_found_by_verify(register_url):
    """A record of chain format 7 keeps its chain when migration 9 fills in its identity:
    set otherwise afterwards, the opening cannot see it (its chain does not cover it), but
    'register verify' makes it again from the readings and names it."""
    records, _ = _version_8_register(register_url)
    with Register(register_url) as register:
        assert register.audit(pdfs=True) == []
    engine = _engine(register_url)
    with engine.begin() as conn:
        conn.execute(sa.text("UPDATE certificates SET readings_anchor = readings_anchor + "
                             "1000000000 WHERE number = :n"), {"n": records[1].number})
    engine.dispose()
    with Register(register_url) as register:
        assert register.problems == []
        assert [str(p) for p in register.audit(pdfs=True)] == [
            f"record {records[1].number}: the identity of its readings stored with it is not "
            "that of its readings (set otherwise after issue): the check of readings issued "
            "again would not find them"]


def test_a_record_issued_without_the_identity_is_compared_by_its_readings(tmp_path):
    """A record an AngleBench of schema 8 issued after the migration (still running) has no
    identity by physical values: its readings are made from its project state and compared."""
    url = f"sqlite:///{tmp_path / 'r.sqlite'}"
    records, _ = _version_8_register(url)
    with Register(url) as register:
        assert register.audit(pdfs=True) == []
    engine = _engine(url)
    with engine.begin() as conn:
        conn.execute(sa.text("UPDATE certificates SET readings_layout = NULL, "
                             "readings_anchor = NULL, readings_reach = NULL"))
    engine.dispose()
    with Register(url) as register:
        assert register.audit(pdfs=True) == []
        with pytest.raises(ReadingsOfAnotherItem) as refused:
            _issue(register, "LRA-0900", _decimal(_rows(2), 6))
        assert refused.value.numbers == (records[2].number,)


def test_a_read_only_register_of_version_8_is_read_as_it_is(tmp_path, monkeypatch):
    """An archive at version 8 cannot be migrated: read as it is, its readings compared by
    their physical values made when compared, verified; nothing written."""
    path = tmp_path / "r.sqlite"
    records, _ = _version_8_register(f"sqlite:///{path}")
    before = path.read_bytes()
    deny_writing(monkeypatch, path)
    with Register(f"sqlite:///{path}") as register:
        assert register.read_only and register.version == 8
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert register.get(records[0].number).readings_layout is None
        meta = CertificateMetadata(approver="Dr. Li", item_serial="LRA-0900",
                                   calibration_date="2026-11-21",
                                   item_description="Limited-rotation axis")
        asked = register.readings_of_another_item("theodolite", meta, _decimal(_rows(0), 10))
        assert asked is not None and asked.numbers == (records[0].number,)
    assert path.read_bytes() == before
