"""The lock a project save holds over "changed on disk?" and the write (rev62 F5): another
process waits for it; a lock whose holder was killed, or that another workstation left
untouched for long, does not stop saving."""

from __future__ import annotations

import os
import signal
import socket
import subprocess
import sys
import time
from pathlib import Path

import pytest

from models.project import save_lock
from models.project.save_lock import ProjectFileBusy, SaveLock, lock_path_of

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
