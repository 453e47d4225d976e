"""The lock a project save holds over "changed on disk?" and the write (rev62 F5): another
process waits for it; a lock whose holder was killed, or that another workstation left
untouched for long, does not stop saving."""

from __future__ import annotations

import errno
import os
import signal
import socket
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from models.project import save_lock
from models.project.save_lock import LockInTheWay, ProjectFileBusy, SaveLock, lock_path_of

ROOT = Path(__file__).resolve().parents[3]

_HOLDER = """
import os, sys, time
from models.project.save_lock import SaveLock
lock = SaveLock(sys.argv[1]); lock.acquire()
print("held", flush=True)
if sys.argv[2] == "kill":
    os.kill(os.getpid(), 9)  # a save killed half-way: its lock file stays
time.sleep(60)
"""


def _holder(path, how):
    """Another process that takes the lock of ``path``: held (``how`` "hold") or killed
    holding it ("kill")."""
    process = subprocess.Popen([sys.executable, "-c", _HOLDER, str(path), how], cwd=ROOT,
                               env={**os.environ, "PYTHONPATH": str(ROOT)},
                               stdout=subprocess.PIPE, text=True)
    assert process.stdout.readline() == "held\n"
    if how == "kill":
        process.communicate(timeout=30)
        assert process.returncode == -signal.SIGKILL
    return process


def test_the_lock_is_a_file_beside_the_project_gone_after_the_save(tmp_path):
    path = tmp_path / "job.anglebench.json"
    lock = SaveLock(path)
    with lock:
        assert lock.path == tmp_path / ".job.anglebench.json.lock" and lock.held
        pid, host, since = lock.path.read_text().split()
        assert (int(pid), host) == (os.getpid(), socket.gethostname())
        assert abs(float(since) - time.time()) < 60
    assert not lock.path.exists() and not lock.held
    long_name = tmp_path / ("x" * 250 + ".json")  # a legal name: its lock is cut, not refused
    with SaveLock(long_name) as lock:
        assert lock.path.name.startswith(".xxx") and len(lock.path.name) <= 255


def test_a_save_in_another_process_is_waited_for_then_said(tmp_path):
    path = tmp_path / "job.anglebench.json"
    holder = _holder(path, "hold")
    try:
        os.utime(lock_path_of(path), (1, 1))  # a save hung for ages: alive, still waited for
        started = time.monotonic()
        with pytest.raises(ProjectFileBusy) as caught:
            SaveLock(path, wait=0.5).acquire()
        assert time.monotonic() - started >= 0.5
        assert caught.value.holder == f"{socket.gethostname()}, process {holder.pid}"
    finally:
        holder.kill()
        holder.communicate(timeout=30)
    with SaveLock(path, wait=0) as lock:  # its holder is gone: stale at once
        assert lock.held


def test_the_lock_of_a_killed_save_does_not_block_saving(tmp_path):
    path = tmp_path / "job.anglebench.json"
    _holder(path, "kill")
    assert lock_path_of(path).exists()
    started = time.monotonic()
    with SaveLock(path, wait=0) as lock:
        assert lock.held and lock.path.read_text().split()[0] == str(os.getpid())
    assert time.monotonic() - started < 1


def test_another_workstations_lock_is_waited_for_until_it_is_untouched_for_long(tmp_path):
    path = tmp_path / "job.anglebench.json"
    lock_file = lock_path_of(path)
    lock_file.write_text(f"4242 bench-7 {time.time():.3f}\n")  # its process not seen from here
    with pytest.raises(ProjectFileBusy) as caught:
        SaveLock(path, wait=0.2).acquire()
    assert caught.value.holder == "bench-7, process 4242"
    old = time.time() - save_lock.STALE_SECONDS - 5
    os.utime(lock_file, (old, old))  # bench-7 was switched off half-way through a save
    with SaveLock(path, wait=0) as lock:
        assert lock.path.read_text().split()[:2] == [str(os.getpid()), socket.gethostname()]
    lock_file.write_text("")  # made, not written yet (or never): judged by its age
    with pytest.raises(ProjectFileBusy) as caught:
        SaveLock(path, wait=0).acquire()
    assert caught.value.holder == ""
    os.utime(lock_file, (old, old))
    with SaveLock(path, wait=0) as lock:
        assert lock.held


def test_a_long_save_touches_its_lock_so_that_it_is_never_stale(tmp_path, monkeypatch):
    path = tmp_path / "job.anglebench.json"
    monkeypatch.setattr(save_lock, "TOUCH_SECONDS", 0.0)
    with SaveLock(path) as lock:
        os.utime(lock.path, (1, 1))
        lock.touch()  # between blocks of rows
        assert time.time() - lock.path.stat().st_mtime < 60


def _acquire(path, wait, limit=5.0):
    """SaveLock(path, wait).acquire() in a thread: what it raised (None: taken) and how long
    it took; "hung" when it was still waiting after ``limit`` seconds (rev63 F8)."""
    result = {}

    def run():
        started = time.monotonic()
        try:
            lock = SaveLock(path, wait=wait)
            lock.acquire()
            result["r"] = None
            lock.release()
        except Exception as exc:  # noqa: BLE001 - what it raised is the result
            result["r"] = exc
        result["t"] = time.monotonic() - started

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    thread.join(limit)
    return result.get("r", "hung"), result.get("t")


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="links and named pipes: POSIX")
def test_a_lock_that_is_not_a_regular_file_refuses_the_save_at_once_naming_it(tmp_path):
    """rev63 F8: a dangling link spun for ever, a named pipe blocked on open. Neither is a
    lock any AngleBench made: refused at once, naming it, and left as it is."""
    me = __import__("pwd").getpwuid(os.getuid()).pw_name
    old = time.time() - save_lock.STALE_SECONDS - 60
    plants = {
        "dangling link": ("link", lambda d, lock: os.symlink(d / "nowhere", lock)),
        "link to the project": ("link", lambda d, lock: os.symlink(d / "job.anglebench.json",
                                                                   lock)),
        "link loop": ("link", lambda d, lock: (os.symlink(f"{lock}2", lock),
                                               os.symlink(lock, f"{lock}2"))),
        "named pipe": ("pipe", lambda d, lock: os.mkfifo(lock)),
        "folder": ("folder", lambda d, lock: os.mkdir(lock)),
        "old folder": ("folder", lambda d, lock: (os.mkdir(lock), os.utime(lock, (old, old)))),
    }
    for name, (kind, plant) in plants.items():
        folder = tmp_path / name.replace(" ", "-")
        folder.mkdir()
        path = folder / "job.anglebench.json"
        path.write_text('{"mine": 1}')
        lock = lock_path_of(path)
        plant(folder, lock)
        raised, took = _acquire(path, wait=2.0)
        assert isinstance(raised, LockInTheWay), (name, raised)
        assert (raised.kind, raised.owner, raised.path) == (kind, me, lock), name
        assert took < 1.0, (name, took)  # not the 2 s wait: nothing to wait for
        assert os.path.lexists(lock) and path.read_text() == '{"mine": 1}', name


def test_every_wait_has_its_deadline_even_when_the_lock_keeps_coming_and_going(
        tmp_path, monkeypatch):
    """A lock found gone (or stale and removed) on every pass was tried again at once,
    with no deadline (rev63 F8): the deadline holds on every pass."""
    path = tmp_path / "job.anglebench.json"
    lock_path_of(path).write_text("")
    passes = []

    def gone(_self):
        passes.append(1)
        if len(passes) > 2000:
            raise RuntimeError("spinning with no deadline")

    monkeypatch.setattr(SaveLock, "_inspect", gone)
    started = time.monotonic()
    with pytest.raises(ProjectFileBusy) as caught:
        SaveLock(path, wait=0.3).acquire()
    assert 0.3 <= time.monotonic() - started < 2.0
    assert caught.value.holder == "" and 3 <= len(passes) < 100


def _unreadable(monkeypatch, lock, unlink_error=None, readable=False):
    """The lock cannot be opened by this user (another user's, mode 0600): as root that
    cannot be made with a mode, so opening it raises EACCES (unless ``readable``), and
    removing it ``unlink_error`` (a folder with the sticky bit)."""
    real_open, real_unlink = os.open, os.unlink

    def fake_open(name, flags, *args):
        if not readable and os.fspath(name) == str(lock) and not flags & os.O_CREAT:
            raise PermissionError(errno.EACCES, "Permission denied", str(name))
        return real_open(name, flags, *args)

    def fake_unlink(name, *args, **kwargs):
        if unlink_error and os.fspath(name) == str(lock):
            raise PermissionError(unlink_error, os.strerror(unlink_error), str(name))
        return real_unlink(name, *args, **kwargs)

    monkeypatch.setattr(save_lock.os, "open", fake_open)
    monkeypatch.setattr(save_lock.os, "unlink", fake_unlink)


def test_another_users_unreadable_lock_is_judged_by_its_age(tmp_path, monkeypatch):
    """rev63 F9: a colleague's 0600 lock, 10 minutes old, was never stale ("save again in a
    moment" for good). Its age is read with lstat; a fresh one is still waited for."""
    path = tmp_path / "job.anglebench.json"
    lock = lock_path_of(path)
    lock.write_text("4242 otherpc 1\n")
    _unreadable(monkeypatch, lock)
    with pytest.raises(ProjectFileBusy) as caught:  # fresh: a live save of that user
        SaveLock(path, wait=0.1).acquire()
    assert caught.value.holder == ""
    ten_minutes_ago = time.time() - 600
    os.utime(lock, (ten_minutes_ago, ten_minutes_ago))
    monkeypatch.undo()  # our own new lock is readable again
    _unreadable(monkeypatch, lock)
    started = time.monotonic()
    with SaveLock(path, wait=2.0) as taken:
        assert taken.held
        monkeypatch.undo()
        assert lock.read_text().split()[:2] == [str(os.getpid()), socket.gethostname()]
    assert time.monotonic() - started < 1.0


def test_a_stale_lock_that_may_not_be_removed_says_whose_it_is(tmp_path, monkeypatch):
    """The colleague's stale lock in a folder with the sticky bit: it cannot be removed by
    this user. Said plainly, naming its owner and its age, instead of "save again in a
    moment" for ever (or a save without the lock)."""
    me = __import__("pwd").getpwuid(os.getuid()).pw_name
    path = tmp_path / "job.anglebench.json"
    lock = lock_path_of(path)
    lock.write_text("4242 otherpc 1\n")
    ten_minutes_ago = time.time() - 600
    os.utime(lock, (ten_minutes_ago, ten_minutes_ago))
    for readable in (False, True):
        monkeypatch.undo()
        _unreadable(monkeypatch, lock, errno.EPERM, readable)  # readable or not: not ours
        raised, took = _acquire(path, wait=2.0)
        assert isinstance(raised, LockInTheWay), (readable, raised)
        assert (raised.kind, raised.owner, raised.error) == ("stale", me,
                                                             "Operation not permitted")
        assert 590 < raised.age < 700 and took < 1.0
        assert lock.read_text() == "4242 otherpc 1\n"


@pytest.mark.skipif(not hasattr(os, "fchmod"), reason="POSIX modes")
def test_a_lock_made_with_umask_077_is_readable_by_another_users_saver(tmp_path):
    path = tmp_path / "job.anglebench.json"
    old = os.umask(0o077)
    try:
        with SaveLock(path) as lock:
            assert lock.path.stat().st_mode & 0o777 == 0o644
    finally:
        os.umask(old)


def test_a_lock_dated_in_the_future_is_said_then_stale_once_seen_unchanged_for_long(
        tmp_path, monkeypatch):
    """#63 winlock: a lock dated a day ahead (made by a computer whose clock is ahead, or
    this clock was set back) has a negative age, and was never stale: every save was
    refused as "being saved from another window" until that date came. Its age cannot be
    told from its date: the save says so, naming the date; it is stale once this process
    has seen it unchanged for STALE_SECONDS of its own clock (a live save touches it)."""
    monkeypatch.setattr(save_lock, "STALE_SECONDS", 0.6)
    path = tmp_path / "job.anglebench.json"
    lock_file = lock_path_of(path)
    tomorrow = time.time() + 86400
    lock_file.write_text(f"4242 bench-7 {tomorrow:.3f}\n")
    os.utime(lock_file, (tomorrow, tomorrow))
    me = __import__("pwd").getpwuid(os.getuid()).pw_name
    with pytest.raises(LockInTheWay) as caught:
        SaveLock(path, wait=0.2).acquire()
    assert (caught.value.kind, caught.value.owner, caught.value.path) == ("future", me,
                                                                          lock_file)
    assert caught.value.dated == pytest.approx(tomorrow, abs=0.01)
    assert lock_file.read_text() == f"4242 bench-7 {tomorrow:.3f}\n"
    time.sleep(0.3)
    os.utime(lock_file, (tomorrow + 2, tomorrow + 2))  # touched: a live save, its clock ahead
    time.sleep(0.4)  # 0.7 s since first seen, only 0.4 s since it changed: not stale
    with pytest.raises(LockInTheWay):
        SaveLock(path, wait=0).acquire()
    time.sleep(0.7)  # left alone for longer than STALE_SECONDS: the save that made it is gone
    with SaveLock(path, wait=0) as lock:
        assert lock.path.read_text().split()[:2] == [str(os.getpid()), socket.gethostname()]
    assert not lock_file.exists()


def test_a_lock_a_few_seconds_ahead_is_judged_by_its_date(tmp_path):
    """Two workstations' clocks a few seconds apart: a fresh lock is a live save's, waited
    for and said as one (not "dated in the future")."""
    path = tmp_path / "job.anglebench.json"
    lock_file = lock_path_of(path)
    soon = time.time() + save_lock.FUTURE_TOLERANCE_SECONDS / 2
    lock_file.write_text(f"4242 bench-7 {soon:.3f}\n")
    os.utime(lock_file, (soon, soon))
    with pytest.raises(ProjectFileBusy) as caught:
        SaveLock(path, wait=0.1).acquire()
    assert caught.value.holder == "bench-7, process 4242"
