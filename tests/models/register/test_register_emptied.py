"""hostile77 F3: a SQLite register emptied to 0 bytes (a crash, a disk fault, a command that
wrote over it) was read by SQLite as a new, empty database: ``register verify`` said "hash
chain intact over 0 record(s)", exit 0, and the next certificate was AB-…-0001 again. A
register AngleBench made has its header at once and its tables from its first transaction,
so an empty file is records lost: refused, and ``verify`` exits 3."""

from __future__ import annotations

import sqlite3

import pytest

from app.main import main
from models.register.store import Register, RegisterTampered


@pytest.fixture
def emptied(tmp_path, monkeypatch):
    """A register that held a record, emptied to 0 bytes (no key: nothing outside it tells)."""
    path = tmp_path / "reg" / "register.sqlite"
    path.parent.mkdir()
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(path))
    monkeypatch.delenv("ANGLEBENCH_REGISTER_KEY", raising=False)
    Register(f"sqlite:///{path}").close()
    assert path.stat().st_size > 0
    path.write_bytes(b"")
    return path


def test_an_emptied_register_is_not_opened(emptied):
    with pytest.raises(RegisterTampered, match=r"the file is empty \(0 bytes\)"):
        Register(f"sqlite:///{emptied}")
    assert emptied.stat().st_size == 0  # nothing written into it


def test_verify_says_changed_not_intact(emptied, capsys):
    assert main(["register", "verify"]) == 3
    out = capsys.readouterr().out
    assert "CHANGED AFTER ISSUE" in out and "empty (0 bytes)" in out, out
    assert "intact" not in out


def test_nothing_is_issued_into_it(emptied, tmp_path, samples_dir, capsys):
    meta = tmp_path / "meta.json"
    meta.write_text((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8")
                    .replace('"example": true', '"example": false'), encoding="utf-8")
    pdf = tmp_path / "c.pdf"
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--metadata", str(meta), "--certificate", str(pdf)]) == 2
    assert "empty (0 bytes)" in capsys.readouterr().err
    assert not pdf.exists()
    assert emptied.stat().st_size == 0


def test_a_new_register_and_one_with_its_records_in_the_journal_open(tmp_path):
    new = tmp_path / "new" / "register.sqlite"
    Register(f"sqlite:///{new}").close()  # a missing file is made, as before
    with Register(f"sqlite:///{new}") as register:
        assert register.problems == []
    # the main file still empty but its first transaction in the -wal journal (a writer
    # killed before a checkpoint): SQLite reads it, and so does the register
    held = tmp_path / "held" / "register.sqlite"
    held.parent.mkdir()
    writer = sqlite3.connect(held)
    writer.execute("PRAGMA journal_mode=WAL")
    writer.execute("PRAGMA wal_autocheckpoint=0")
    writer.execute("create table t (x)")
    writer.commit()
    try:
        with open(held, "r+b") as handle:  # as if the header had never reached the file
            handle.truncate(0)
        assert held.stat().st_size == 0
        assert (held.parent / "register.sqlite-wal").stat().st_size > 0
        from models.register.store import _emptied

        assert not _emptied(held)
    finally:
        writer.close()
