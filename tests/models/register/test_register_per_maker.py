"""A serial number is unique only within its maker: the calibration interval is set per
maker's item (schema version 7, migrated from a register written by 0.8.13, the hash chain
verifying before and after, atomically: a migration killed half-way leaves version 6; stop
63's note: two makers' serial "001" shared one interval)."""

from __future__ import annotations

import datetime as dt
import os
import shutil
import sqlite3
import subprocess
import sys
from pathlib import Path

import pytest
import sqlalchemy as sa

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register import schema
from models.register.store import (
    IssueRequest,
    Register,
    RegisterError,
    RegisterTampered,
    SameCalibrationIssued,
)
from tests.read_only_file import deny_writing

PROJECT = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
ISSUED = dt.datetime(2026, 11, 25, 10, 0, tzinfo=dt.timezone.utc)
#: a register as AngleBench 0.8.13 (schema version 6) left it, made by that version's own
#: Register (PYTHONPATH at d5495a3, stand-in PDFs "%PDF <number> <revision> head <head>"):
#: AB-2026-0001 of Acme Optics' "001" calibrated 2025-06-01, AB-2026-0002 of Zeta
#: Instruments' "001" calibrated 2026-11-20 and its amendment AB-2026-0002-A1; the
#: intervals 365 days for "001" and 180 for "PG-12" (per serial, chained entries 3 and 4);
#: audit clean, head below
SCHEMA_6 = Path(__file__).parents[2] / "fixtures" / "register_schema6.sqlite"
SCHEMA_6_HEAD = "9b3724068adfc238a9565806f18e75f2cdef0d51331a5df8399a471dedb78885"
ROOT = Path(__file__).parents[3]


def render(meta: CertificateMetadata, head: str = "") -> bytes:
    return f"%PDF {meta.certificate_number} {meta.revision} head {head}".encode()


def meta(maker: str, day: str = "2026-11-20", serial: str = "001") -> CertificateMetadata:
    return CertificateMetadata(item_serial=serial, item_manufacturer=maker,
                               item_description="24-face polygon", customer_name="Acme Optics",
                               calibration_date=day, number_scheme="AB-{year}-{seq:04d}",
                               approver="Dr. Li")


def _open(url: str) -> Register:
    register = Register(url, timezone="UTC")
    register.clock = lambda: ISSUED
    return register


@pytest.fixture
def register(register_url):
    with _open(register_url) as reg:
        yield reg


def issue(register: Register, maker: str, day: str = "2026-11-20", **options):
    return register.issue(IssueRequest("polygon", meta(maker, day), PROJECT), render,
                          **{"separate_calibration": "", **options})[0]


# -- the interval per maker's item ------------------------------------------------------------
def test_two_makers_serial_001_have_an_interval_each(register):
    issue(register, "Acme Optics", "2025-06-01")
    issue(register, "Zeta Instruments", "2026-11-20")
    register.set_interval("001", 365, "Acme Optics")
    assert register.interval("001", "Zeta Instruments") is None  # not Acme's
    assert register.due_date("001", "Zeta Instruments") is None
    register.set_interval("001", 730, "Zeta Instruments")
    assert register.interval("001", "Acme Optics") == 365
    assert register.due_date("001", "Acme Optics") == dt.date(2026, 6, 1)
    assert register.due_date("001", "Zeta Instruments") == dt.date(2028, 11, 19)
    # one item, one interval: the maker typed with a Cyrillic "А", in other case, or the
    # serial with a letter O, is Acme's item, and its interval replaces Acme's
    register.set_interval("OO1", 180, "\u0410CME optics")
    assert register.interval("001", "Acme Optics") == 180
    assert register.interval("001", "Zeta Instruments") == 730
    with register._read() as conn:
        rows = conn.execute(sa.select(schema.INSTRUMENTS)).all()
    assert sorted((r.serial, r.manufacturer, r.interval_days) for r in rows) == [
        ("001", "Zeta Instruments", 730), ("OO1", "\u0410CME optics", 180)]
    # one set without a maker is every maker's item's that has none of its own
    register.set_interval("001", 90)
    assert register.interval("001", "Other Corp") == 90
    assert register.interval("001", "Acme Optics") == 180
    register.set_interval("001", 0, "Zeta Instruments")  # cleared: every maker's again
    assert register.interval("001", "Zeta Instruments") == 90
    assert register.audit() == []


def test_the_command_line_sets_one_makers_interval(register_url, capsys):
    with _open(register_url) as register:
        acme = issue(register, "Acme Optics", "2025-06-01")
        zeta = issue(register, "Zeta Instruments", "2026-11-20")
    assert main(["register", "--register", register_url, "interval", "001", "365",
                 "--manufacturer", "Acme Optics"]) == 0
    capsys.readouterr()
    assert main(["register", "--register", register_url, "show", acme.number]) == 0
    assert "next calibration of 001 due: 2026-06-01" in capsys.readouterr().out
    assert main(["register", "--register", register_url, "show", zeta.number]) == 0
    assert "due:" not in capsys.readouterr().out  # Zeta's item has no interval
    assert main(["register", "--register", register_url, "verify"]) == 0


def test_an_interval_moved_to_another_maker_behind_the_registers_back_is_found(register):
    register.set_interval("001", 365, "Acme Optics")
    with register.engine.begin() as conn:
        conn.execute(sa.text("UPDATE calibration_intervals SET manufacturer = "
                             "'Zeta Instruments'"))
    problems = [str(p) for p in register.audit()]
    assert any("instrument 001 (Acme Optics): calibration interval — day(s), but the "
               "register's records set 365" in p for p in problems)
    assert any("instrument 001 (Zeta Instruments): calibration interval 365" in p
               for p in problems)


# -- the migration of a register written by 0.8.13 ---------------------------------------------
def _schema_6(tmp_path: Path) -> tuple[str, dict]:
    path = tmp_path / "register.sqlite"
    shutil.copy(SCHEMA_6, path)
    with sqlite3.connect(path) as conn:
        chains = dict(conn.execute("SELECT number, chain_sha256 FROM certificates"))
        chains |= {f"entry {seq}": c for seq, c in conn.execute(
            "SELECT seq, chain_sha256 FROM entries")}
        assert conn.execute("SELECT version FROM schema_version").fetchone() == (6,)
    return f"sqlite:///{path}", chains


def _chains(url: str) -> dict:
    with sqlite3.connect(url.split("///", 1)[1]) as conn:
        return dict(conn.execute("SELECT number, chain_sha256 FROM certificates")) | {
            f"entry {seq}": c for seq, c in conn.execute("SELECT seq, chain_sha256 FROM entries")}


def _instruments(url: str, table: str = "instruments") -> tuple[list, list]:
    with sqlite3.connect(url.split("///", 1)[1]) as conn:
        columns = [row[1] for row in conn.execute(f"PRAGMA table_info({table})")]
        return columns, sorted(conn.execute(f"SELECT * FROM {table}"))


def test_a_register_of_0_8_13_migrates_keeping_its_chain_and_intervals(tmp_path, capsys):
    url, chains = _schema_6(tmp_path)
    with _open(url) as register:
        assert register.version == schema.LATEST == 9
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert register.chain_head() == SCHEMA_6_HEAD and _chains(url) == chains
        # the intervals set per serial are every maker's item's, as they were
        assert register.interval("001", "Acme Optics") == register.interval(
            "001", "Zeta Instruments") == 365 and register.interval("PG-12") == 180
        assert register.due_date("001", "Acme Optics") == dt.date(2026, 6, 1)
        register.set_interval("001", 730, "Zeta Instruments")
        assert register.interval("001", "Acme Optics") == 365
        assert register.due_date("001", "Zeta Instruments") == dt.date(2028, 11, 19)
        assert register.audit(pdfs=True) == []
    assert _instruments(url, "calibration_intervals") == (
        ["serial", "manufacturer", "interval_days"],
        [("001", "", 365), ("001", "Zeta Instruments", 730), ("PG-12", "", 180)])
    with sqlite3.connect(url.split("///", 1)[1]) as conn:  # version 6's is gone (rev65 F3)
        assert "instruments" not in {row[0] for row in conn.execute(
            "SELECT name FROM sqlite_master")}
    assert main(["register", "--register", url, "verify"]) == 0
    # set back to 6 (its state's copy too) it is refused, never migrated again
    engine = sa.create_engine(url)
    with engine.begin() as conn:
        conn.execute(sa.text("UPDATE schema_version SET version = 6"))
        conn.execute(sa.text("UPDATE register_state SET value = '6' WHERE name = "
                             "'schema_version'"))
    engine.dispose()
    with pytest.raises(RegisterTampered, match=r"schema version 6 was set back \(the table "
                                               r"of version 7 \(calibration_intervals\) "
                                               r"exists\)"):
        Register(url)


def test_a_read_only_register_of_0_8_13_is_read_and_verified_as_it_is(tmp_path, monkeypatch,
                                                                     capsys):
    """A register that cannot be written (an archive) cannot be migrated: at version 6 it is
    read as it is, its intervals every maker's item's, and verified; nothing is written."""
    import hashlib

    url, _ = _schema_6(tmp_path)
    path = url.split("///", 1)[1]
    digest = hashlib.sha256(Path(path).read_bytes()).hexdigest()
    deny_writing(monkeypatch, path)
    with _open(url) as register:
        assert register.read_only and register.version == 6
        assert register.problems == [] and register.audit(pdfs=True) == []
        assert register.interval("001", "Zeta Instruments") == 365
        assert register.due_date("001", "Acme Optics") == dt.date(2026, 6, 1)
        with pytest.raises(RegisterError, match="read-only"):
            register.set_interval("001", 30, "Acme Optics")
    assert main(["register", "--register", url, "verify"]) == 0
    assert main(["register", "--register", url, "show", "AB-2026-0001"]) == 0
    assert "next calibration of 001 due: 2026-06-01" in capsys.readouterr().out
    assert hashlib.sha256(Path(path).read_bytes()).hexdigest() == digest


def test_a_migration_that_fails_half_way_leaves_version_6(tmp_path, monkeypatch):
    """The new table made, the rows copied, the old one dropped, and then an error: the
    migration's one transaction is rolled back, the register is as 0.8.13 left it."""
    url, chains = _schema_6(tmp_path)
    before = _instruments(url)
    migrate = schema.MIGRATIONS[7]

    def failing(conn):
        migrate(conn)
        raise OSError("disk full")

    monkeypatch.setitem(schema.MIGRATIONS, 7, failing)
    with pytest.raises(RegisterError, match="disk full"):
        Register(url)
    assert _instruments(url) == before == (["serial", "interval_days"],
                                           [("001", 365), ("PG-12", 180)])
    with sqlite3.connect(url.split("///", 1)[1]) as conn:
        assert conn.execute("SELECT version FROM schema_version").fetchone() == (6,)
        assert "calibration_intervals" not in {row[0] for row in conn.execute(
            "SELECT name FROM sqlite_master")}
    monkeypatch.setitem(schema.MIGRATIONS, 7, migrate)
    with _open(url) as register:
        assert register.version == schema.LATEST and register.audit(pdfs=True) == []
        assert register.interval("001", "Acme Optics") == 365
    assert _chains(url) == chains


def test_a_migration_killed_half_way_leaves_version_6(tmp_path):
    """The process killed (os._exit: no rollback, no clean-up) after the old table was
    dropped and before the commit: the next opening finds version 6 whole and migrates it."""
    url, chains = _schema_6(tmp_path)
    before = _instruments(url)
    program = (
        "import os, sys\n"
        "from models.register import schema\n"
        "from models.register.store import Register\n"
        "migrate = schema.MIGRATIONS[7]\n"
        "def killed(conn):\n"
        "    migrate(conn)\n"
        "    os._exit(9)\n"
        "schema.MIGRATIONS[7] = killed\n"
        "Register(sys.argv[1])\n")
    done = subprocess.run([sys.executable, "-c", program, url], cwd=ROOT, timeout=120,
                          env={**os.environ, "PYTHONPATH": str(ROOT)}, capture_output=True)
    assert done.returncode == 9, done.stderr
    assert _instruments(url) == before
    with sqlite3.connect(url.split("///", 1)[1]) as conn:
        assert conn.execute("SELECT version FROM schema_version").fetchone() == (6,)
    with _open(url) as register:
        assert register.version == schema.LATEST and register.audit(pdfs=True) == []
        assert register.chain_head() == SCHEMA_6_HEAD
        assert register.interval("001", "Zeta Instruments") == 365
    assert _chains(url) == chains


def test_capital_rn_and_m_are_two_items_of_one_maker(tmp_path):
    """rev65 F8: "rn" read as "m" after case folding made Kern's "RN-05" and "M-05" one item:
    M-05's calibration the same day refused as a second original, the histories merged, and
    setting M-05's interval replaced RN-05's. Small "rn-05" typed is still M-05's look-alike."""
    def meta(serial: str, day: str) -> CertificateMetadata:
        return CertificateMetadata(item_serial=serial, item_manufacturer="Kern",
                                   item_description="autocollimator", customer_name="X",
                                   calibration_date=day, number_scheme="AB-{year}-{seq:04d}",
                                   approver="Dr. Li")

    with Register(f"sqlite:///{tmp_path / 'r.sqlite'}", timezone="UTC") as register:
        register.clock = lambda: ISSUED
        for serial, day in (("RN-05", "2026-11-20"), ("M-05", "2025-01-10")):
            register.issue(IssueRequest("polygon", meta(serial, day), PROJECT), render,
                           separate_calibration="")
        register.set_interval("RN-05", 365, "Kern")
        register.set_interval("M-05", 730, "Kern")
        assert (register.interval("RN-05", "Kern"), register.interval("M-05", "Kern")) \
            == (365, 730)
        assert [(r.item_serial, r.calibration_date) for r in register.history("M-05", "Kern")] \
            == [("M-05", "2025-01-10")]
        assert str(register.due_date("M-05", "Kern")) == "2027-01-10"
        issued = register.issue(IssueRequest("polygon", meta("M-05", "2026-11-20"), PROJECT),
                                render, separate_calibration="")[0]  # not RN-05's: no reason
        assert (issued.number, issued.revision) == ("AB-2026-0003", "original")
        with pytest.raises(SameCalibrationIssued, match="AB-2026-0002"):  # typed small: M-05
            register.issue(IssueRequest("polygon", meta("rn-05", "2025-01-10"), PROJECT), render,
                           separate_calibration="")


def test_schema_6_codes_interval_statements_fail_on_a_migrated_register(tmp_path):
    """rev65 F3: a 0.8.13 window open across the migration ran its set_interval's
    "DELETE FROM instruments WHERE serial = ?" (every maker's row of the serial) and its
    INSERT, unrecorded; the register then read CHANGED AFTER ISSUE lab-wide. Its statements
    on the intervals, as 0.8.13's Register issues them, now fail and change nothing."""
    url, _ = _schema_6(tmp_path)
    path = url.split("///", 1)[1]
    with Register(url, timezone="UTC") as register:
        register.set_interval("001", 730, "Zeta Instruments")
    with sqlite3.connect(path) as conn:
        with pytest.raises(sqlite3.OperationalError, match="no such table: instruments"):
            conn.execute("DELETE FROM instruments WHERE serial = ?", ("001",))
        with pytest.raises(sqlite3.OperationalError, match="no such table: instruments"):
            conn.execute("INSERT INTO instruments (serial, interval_days) VALUES (?, ?)",
                         ("001", 200))
        with pytest.raises(sqlite3.OperationalError, match="no such table: instruments"):
            conn.execute("SELECT serial, interval_days FROM instruments")
    with Register(url, timezone="UTC") as register:
        assert register.audit(pdfs=True) == []
        assert register.interval("001", "Zeta Instruments") == 730
        assert register.interval("001", "Acme Optics") == 365
    assert main(["register", "--register", url, "verify"]) == 0
