"""A full disk during a register write (stop 63: it was reported as "[Errno 28] No space
left on device", or SQLite's "database or disk is full"): said in words — where, that
nothing was recorded, that the register is unchanged — and the register is unchanged."""

from __future__ import annotations

import errno

import pytest
import sqlalchemy as sa

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register, RegisterError

META = CertificateMetadata(approver="Dr. Li", calibration_date="2026-01-01",
                           item_serial="RX-1")


def _issued(register: Register, n: int = 1) -> list[str]:
    return [register.issue(IssueRequest("polygon", META, '{"workbenches": {}}'),
                           lambda m, head="": f"%PDF {m.certificate_number}".encode()
                           )[0].number for _ in range(n)]


def _state(register: Register) -> tuple:
    """What the register holds: its head, its record count, each record's status."""
    return (register.chain_head(), register.chain_records(),
            [(r.number, r.status) for r in register.list()])


def test_enospc_on_a_register_write_is_said_in_words_and_records_nothing(monkeypatch,
                                                                         capsys):
    with Register(register_url()) as register:
        number = _issued(register)[0]
        before = _state(register)
    path = register_url().split("///", 1)[1]
    kept = Register._set_state

    def full(self, conn, records, head):  # the entry is written; the state's write fails
        kept(self, conn, records, head)
        raise OSError(errno.ENOSPC, "No space left on device", path)

    monkeypatch.setattr(Register, "_set_state", full)
    assert main(["register", "withdraw", number, "--reason", "wrong item"]) == 2
    err = capsys.readouterr().err
    assert (f"the disk is full at {path}: nothing was recorded; the register is "
            "unchanged") in err
    assert "Errno" not in err and "28" not in err.replace(path, "")
    monkeypatch.setattr(Register, "_set_state", kept)
    with Register(register_url()) as register:
        assert _state(register) == before and register.problems == []
    assert main(["register", "verify"]) == 0


def test_sqlites_disk_full_on_an_issue_is_said_in_words(capsys):
    """SQLite reports ENOSPC as SQLITE_FULL: the same words, the issue not recorded."""
    with Register(register_url()) as register:
        _issued(register)
        before = _state(register)
        path = register_url().split("///", 1)[1]

        @sa.event.listens_for(register.engine, "connect")
        def no_room(dbapi_connection, _record) -> None:  # the file may grow no more
            pages = dbapi_connection.execute("PRAGMA page_count").fetchone()[0]
            dbapi_connection.execute(f"PRAGMA max_page_count = {pages}")

        register.engine.dispose()  # new connections: with the limit
        big = CertificateMetadata(approver="Dr. Li", calibration_date="2026-01-02",
                                  item_serial="RX-2")
        with pytest.raises(RegisterError) as refused:
            register.issue(IssueRequest("polygon", big, '{"workbenches": {}}'),
                           lambda m, head="": b"%PDF " + bytes(200_000))
        assert str(refused.value) == (f"the disk is full at {path}: nothing was recorded; "
                                      "the register is unchanged (free some space and try "
                                      "again)")
        sa.event.remove(register.engine, "connect", no_room)
        register.engine.dispose()
        assert _state(register) == before


@pytest.mark.parametrize(("free", "said"), [
    (0, "the disk is full at {path}: nothing was recorded; the register is unchanged"),
    (10 << 30, "disk I/O error")])
def test_sqlites_io_error_on_a_full_disk_is_said_as_a_full_disk(monkeypatch, free, said):
    """reg72 #7: on a full tmpfs SQLite says "disk I/O error" (SQLITE_IOERR), not
    SQLITE_FULL: with no room left in the register's folder it is the full disk's words;
    with room, the I/O error is said as it is."""
    import shutil
    import sqlite3
    from collections import namedtuple

    with Register(register_url()) as register:
        number = _issued(register)[0]
        before = _state(register)
    path = register_url().split("///", 1)[1]
    kept = Register._set_state

    def failing(self, conn, records, head):
        kept(self, conn, records, head)
        error = sqlite3.OperationalError("disk I/O error")
        error.sqlite_errorname = "SQLITE_IOERR_WRITE"
        raise sa.exc.OperationalError("UPDATE register_state …", {}, error)

    usage = namedtuple("usage", "total used free")
    monkeypatch.setattr(Register, "_set_state", failing)
    monkeypatch.setattr(shutil, "disk_usage", lambda _path: usage(1 << 30, 1 << 30, free))
    with Register(register_url()) as register:
        with pytest.raises(RegisterError) as refused:
            register.withdraw(number, "wrong item")
        assert said.format(path=path) in str(refused.value)
        monkeypatch.setattr(Register, "_set_state", kept)
        assert _state(register) == before


def _register_on_a_full_tmpfs(monkeypatch, free: int) -> tuple[str, str, str]:
    """A register with one certificate issued, then SQLite failing as on a full tmpfs when a
    connection is made (its "PRAGMA journal_mode=WAL" unable to map the WAL index,
    SQLITE_IOERR_SHMSIZE) with ``free`` bytes left in its folder: (url, path, number)."""
    import shutil
    import sqlite3
    from collections import namedtuple

    import models.register.store as store

    url = register_url()
    with Register(url) as register:
        number = _issued(register)[0]
    path = url.split("///", 1)[1]

    def no_wal_index(dbapi_connection, _record) -> None:
        error = sqlite3.OperationalError("disk I/O error")
        error.sqlite_errorname = "SQLITE_IOERR_SHMSIZE"
        raise error

    usage = namedtuple("usage", "total used free")
    monkeypatch.setattr(store, "_sqlite_connect", no_wal_index)
    monkeypatch.setattr(shutil, "disk_usage", lambda _path: usage(1 << 30, 1 << 30, free))
    return url, path, number


@pytest.mark.parametrize(("free", "said"), [
    (0, "the disk is full at {path}: the register cannot be opened there (SQLite needs room "
        "beside it for its journal's index); it was not changed"),
    (10 << 30, "disk I/O error")])
def test_sqlites_io_error_on_connecting_to_a_full_disk_is_said_as_a_full_disk(
        monkeypatch, capsys, free, said):
    """reg72 #7 as it happens: on a full tmpfs SQLite fails already when a connection is
    made, its "PRAGMA journal_mode=WAL" unable to map the WAL index (SQLITE_IOERR_SHMSIZE),
    before any write: the register's opening said "disk I/O error". With no room left in
    the register's folder it is the full disk's words; with room, the I/O error as it is."""
    url, path, number = _register_on_a_full_tmpfs(monkeypatch, free)
    with pytest.raises(RegisterError) as refused:
        Register(url)
    assert said.format(path=path) in str(refused.value)
    capsys.readouterr()
    assert main(["register", "--register", path, "withdraw", number, "--reason",
                 "wrong item"]) == 2
    assert said.format(path=path) in capsys.readouterr().err
    monkeypatch.undo()
    with Register(url) as register:
        assert [(r.number, r.status) for r in register.list()] == [(number, "issued")]


@pytest.mark.parametrize("command", [["list"], ["verify"], ["show", "{number}"]])
def test_a_command_that_only_reads_a_register_on_a_full_disk_records_nothing_unsaid(
        monkeypatch, capsys, command):
    """hostile77 L1: `register list` and `verify` with the register's disk full said
    "nothing was recorded; the register is unchanged", of a command that records nothing:
    the register cannot be opened there, and it was not changed."""
    url, path, number = _register_on_a_full_tmpfs(monkeypatch, 0)
    capsys.readouterr()
    assert main(["register", "--register", path,
                 *(c.format(number=number) for c in command)]) == 2
    err = capsys.readouterr().err
    assert f"the disk is full at {path}: the register cannot be opened there" in err
    assert "nothing was recorded" not in err
