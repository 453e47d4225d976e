"""Windows has no flock: whether another window holds its autosave's lock is read from the
process id in the lock file. ``os.kill(pid, 0)`` is no test there — any signal but the two
console events ends the process (TerminateProcess), so asking whether a window runs would
have ended it. The check must ask without touching the process."""

from __future__ import annotations

import os

import pytest

import models.project.recovery as recovery


@pytest.fixture
def windows(monkeypatch):
    """recovery as on Windows (no fcntl, its Windows switch on: os.name itself is left
    alone, the test process runs on it), whose process table says ``alive``; os.kill must
    never be called."""
    alive: dict[int, bool] = {}

    def no_kill(pid, sig):  # pragma: no cover - the test fails when it is called
        raise AssertionError(f"os.kill({pid}, {sig}) called: on Windows it ends the process")

    monkeypatch.setattr(recovery, "fcntl", None)
    monkeypatch.setattr(os, "kill", no_kill)
    monkeypatch.setattr(recovery, "_WINDOWS", True)
    monkeypatch.setattr(recovery, "_windows_process_alive", lambda pid: alive.get(pid, False))
    return alive


def test_a_running_windows_lock_is_held_and_its_process_untouched(tmp_path, windows):
    lock = tmp_path / "autosave.lock"
    lock.write_text("4242 lab-pc\n")
    windows[4242] = True
    assert recovery._lock_is_held(lock)


def test_a_crashed_windows_lock_is_free(tmp_path, windows):
    lock = tmp_path / "autosave.lock"
    lock.write_text("4243 lab-pc\n")
    assert not recovery._lock_is_held(lock)


def test_an_unreadable_lock_is_free_and_no_lock_is_free(tmp_path, windows):
    lock = tmp_path / "autosave.lock"
    lock.write_text("not a pid\n")
    assert not recovery._lock_is_held(lock)
    assert not recovery._lock_is_held(tmp_path / "none.lock")


def test_on_posix_the_process_check_sees_this_process_and_not_a_dead_one():
    assert recovery._process_alive(os.getpid())
    child = os.fork() if hasattr(os, "fork") else None
    if child is None:
        pytest.skip("no fork here")
    if child == 0:  # pragma: no cover - the child
        os._exit(0)
    os.waitpid(child, 0)  # reaped: its pid no longer names a process
    assert not recovery._process_alive(child)
