"""reg72 #8: a write that finds the SQLite register's write lock held by another process
waited up to a minute in silence, then said "database is locked", the holder not named. It
now says at once (within two seconds) that it waits, for whom — the holder's note beside
the database: user, computer, process, since when — and for how long at most; it still
waits as before, and succeeds when the lock is released in time."""

from __future__ import annotations

import getpass
import json
import os
import socket
import sqlite3
import subprocess
import sys
import threading
import time
from unittest import mock

import pytest

import models.register.store as store
from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.register.location import register_url
from models.register.store import IssueRequest, Register, RegisterError

META = CertificateMetadata(approver="Dr. Li", calibration_date="2026-01-01",
                           item_serial="RX-1")


def _issued(url: str) -> str:
    with Register(url) as register:
        return register.issue(IssueRequest("polygon", META, '{"workbenches": {}}'),
                              lambda m, head="": f"%PDF {m.certificate_number}".encode()
                              )[0].number


def _path(url: str) -> str:
    return url.split("///", 1)[1]


class _Holder(threading.Thread):
    """Another connection holding the database's write lock (as ``sqlite3`` with ``BEGIN
    IMMEDIATE`` does) until ``release`` is set, or ``longest`` seconds."""

    def __init__(self, path: str, longest: float = 20.0) -> None:
        super().__init__(daemon=True)
        self.path, self.longest = path, longest
        self.held, self.release = threading.Event(), threading.Event()

    def run(self) -> None:
        conn = sqlite3.connect(self.path, isolation_level=None)
        conn.execute("BEGIN IMMEDIATE")
        self.held.set()
        self.release.wait(self.longest)
        conn.execute("COMMIT")
        conn.close()

    def __enter__(self) -> _Holder:
        self.start()
        assert self.held.wait(10)
        return self

    def __exit__(self, *_exc) -> None:
        self.release.set()
        self.join(10)


class _AngleBenchHolder(_Holder):
    """An AngleBench write holding the lock (it leaves its note beside the database)."""

    def run(self) -> None:
        with Register(f"sqlite:///{self.path}") as register, register._write():
            self.held.set()
            self.release.wait(self.longest)


def test_a_write_says_at_once_that_it_waits_for_an_anglebench_holder_and_goes_on():
    url = register_url()
    number = _issued(url)
    told: list[tuple[float, bool, str]] = []
    with _AngleBenchHolder(_path(url)) as holder, Register(url) as register:
        start = time.monotonic()

        def on_wait(said) -> None:
            told.append((time.monotonic() - start, holder.release.is_set(), str(said)))
            holder.release.set()  # released after being told: the write goes on

        register.on_wait = on_wait
        register.withdraw(number, "wrong item")
        assert register.get(number).status == "withdrawn"
    assert len(told) == 1
    after, released, said = told[0]
    assert 1.0 <= after < 3.0 and not released
    assert said.startswith(f"waiting for the register at {_path(url)}: its write lock is "
                           f"held by {getpass.getuser()}@{socket.gethostname()}, process "
                           f"{os.getpid()} since 20")
    assert said.endswith("; giving up after 60 s unless it is released")
    assert not os.path.exists(_path(url) + ".writer")  # the note goes with the lock


def test_a_holder_that_left_no_note_or_a_stale_one_is_not_named_and_the_wait_gives_up(
        monkeypatch):
    url = register_url()
    number = _issued(url)
    gone = subprocess.Popen([sys.executable, "-c", "pass"])
    gone.wait()  # a process of this computer that no longer runs: its note is stale
    with open(_path(url) + ".writer", "w", encoding="utf-8") as note:
        json.dump({"host": socket.gethostname(), "pid": gone.pid, "user": "lab",
                   "since": "2026-12-06T10:00:00+00:00"}, note)
    monkeypatch.setattr(store, "BUSY_TIMEOUT_S", 3)
    told: list[str] = []
    with _Holder(_path(url)), Register(url) as register:
        register.on_wait = lambda said: told.append(str(said))
        start = time.monotonic()
        with pytest.raises(RegisterError) as refused:
            register.withdraw(number, "wrong item")
        waited = time.monotonic() - start
    assert told == [f"waiting for the register at {_path(url)}: its write lock is held by "
                    "another program, which left no note of who it is; giving up after 3 s "
                    "unless it is released"]
    assert 2.5 <= waited < 6
    assert str(refused.value).endswith("waited 3 s for the register's lock, held by another "
                                       "program, which left no note of who it is")
    with Register(url) as register:
        assert register.get(number).status == "issued"


def test_the_command_line_says_on_stderr_that_it_waits(capsys):
    number = _issued(register_url())
    path = _path(register_url())
    with _Holder(path, longest=3.5):
        assert main(["register", "withdraw", number, "--reason", "wrong item"]) == 0
    err = capsys.readouterr().err
    assert err.count("waiting for the register") == 1
    assert (f"anglebench register: waiting for the register at {path}: its write lock is "
            "held by another program") in err


def test_the_window_says_in_its_status_line_that_it_waits(monkeypatch):
    from app.certificate_presenter import CertificatePresenter, CertificateView
    from tests.app.test_certificate_presenter import Store

    url = register_url()
    number = _issued(url)
    monkeypatch.delenv("ANGLEBENCH_REGISTER")  # the window's setting is the register
    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, Store(), dict, mock.Mock())
    presenter.set_register_url(_path(url))
    with _Holder(_path(url)) as holder, presenter.open_register() as register:
        view.show_status.side_effect = lambda *_args: holder.release.set()
        register.withdraw(number, "wrong item")
    (text, milliseconds), _ = view.show_status.call_args
    assert text.startswith(f"waiting for the register at {_path(url)}: its write lock is "
                           "held by another program") and milliseconds >= 60_000
