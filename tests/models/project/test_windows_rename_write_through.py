"""On Windows a folder cannot be fsync'ed, and ``os.replace`` (MoveFileExW with
MOVEFILE_REPLACE_EXISTING only) returns before the rename is on the disk: a power cut just
after "saved" could give back the old file (#63 winlock). Every rename into place there is
MoveFileExW with MOVEFILE_WRITE_THROUGH. The tests run on Linux: the module's Windows switch
is turned on (os.name itself is left alone) and kernel32 is a fake that records each call
and does the move."""

from __future__ import annotations

import ctypes
import errno
import hashlib
import logging
import os
from pathlib import Path

import pytest

from models.project import durable_rename
from models.project.atomic_write import write_bytes_atomic, write_text_atomic
from models.project.file import Project, load_project, save_project
from models.project.recovery import RecoveryStore

REPLACE_EXISTING, WRITE_THROUGH = 0x1, 0x8
_TEXTS = {5: "Access is denied.", 183: "Cannot create a file when that file already exists."}


class FakeKernel32:
    """kernel32's MoveFileExW as Windows does it; ``refuse`` (a Windows error code) makes
    every move fail with that error, moving nothing."""

    def __init__(self) -> None:
        self.calls: list[tuple[str, str, int]] = []
        self.refuse = 0
        self.last_error = 0

    def MoveFileExW(self, src, dst, flags):  # noqa: N802 - kernel32's name
        self.calls.append((os.path.basename(src), os.path.basename(dst), flags))
        if self.refuse:
            self.last_error = self.refuse
            return 0
        if not flags & REPLACE_EXISTING and os.path.lexists(dst):
            self.last_error = 183  # ERROR_ALREADY_EXISTS
            return 0
        os.rename(src, dst)
        return 1


@pytest.fixture
def kernel32(monkeypatch):
    """durable_rename as on Windows, with a fake kernel32; os.replace and os.link must not
    be called (they are the renames that are not written through)."""
    fake = FakeKernel32()

    def not_on_windows(*args, **_kwargs):  # pragma: no cover - the test fails when called
        raise AssertionError(f"a rename not written through: {args}")

    monkeypatch.setattr(durable_rename, "_WINDOWS", True)
    monkeypatch.setattr(durable_rename, "_kernel32", lambda: fake)
    monkeypatch.setattr(ctypes, "get_last_error", lambda: fake.last_error, raising=False)
    monkeypatch.setattr(ctypes, "WinError", lambda code: OSError(None, _TEXTS[code], None, code),
                        raising=False)
    monkeypatch.setattr(os, "replace", not_on_windows)
    monkeypatch.setattr(os, "link", not_on_windows)
    return fake


def test_a_saved_file_is_renamed_into_place_written_through(tmp_path, kernel32):
    target = tmp_path / "job.anglebench.json"
    target.write_text("old")
    write_text_atomic(target, "new")
    assert target.read_text() == "new"
    ((src, dst, flags),) = kernel32.calls
    assert src.startswith(".job.anglebench.json.") and dst == target.name
    assert flags == REPLACE_EXISTING | WRITE_THROUGH
    assert [p.name for p in tmp_path.iterdir()] == [target.name]


def test_every_rename_into_place_is_written_through(tmp_path, kernel32):
    """The project, the autosave (written, adopted from a crashed window, set aside)."""
    path = tmp_path / "run3.anglebench.json"
    save_project(path, Project(metadata={"operator": "A. Colleague"}))
    folder = tmp_path / "recovery"
    crashed = RecoveryStore(folder)
    crashed.write(Project())
    orphan = crashed.path
    store = RecoveryStore(folder)
    store.adopt(orphan)
    assert store.path.exists() and not orphan.exists()
    store.write(Project(metadata={"operator": "B"}))
    kept = store.set_aside(store.path, "damaged")
    assert kept.exists() and load_project(kept).metadata["operator"] == "B"
    def pending(store):  # an autosave is written beside its place (atomically), then put there
        return f".{store.path.name}.pending.tmp"

    assert [dst for _src, dst, _flags in kernel32.calls] == [
        path.name, pending(crashed), crashed.path.name, store.path.name,
        pending(store), store.path.name, kept.name]
    assert {flags for *_names, flags in kernel32.calls} == {REPLACE_EXISTING | WRITE_THROUGH}
    assert load_project(path).metadata["operator"] == "A. Colleague"


def test_a_results_file_takes_its_name_written_through_never_over_a_file(tmp_path, kernel32):
    """The results file of an issue is named without replacing a file the register issued
    there meanwhile (rev63 F7: a hard link on POSIX); on Windows, a move without
    MOVEFILE_REPLACE_EXISTING, written through. A recorded one that cannot be put in place
    is kept beside it under a name no file has."""
    from app.certificate_issue import _place
    from app.issued_outputs import keep_in_sight

    class Register:
        def issued_file(self, _digest):
            return []

        def results_records(self):
            return []

    temp, target = tmp_path / ".r.xlsx.abcdefgh.tmp", tmp_path / "r.xlsx"
    temp.write_bytes(b"results")
    _place(Register(), str(temp), target)
    assert target.read_bytes() == b"results" and not temp.exists()
    assert kernel32.calls == [(temp.name, "r.xlsx", WRITE_THROUGH)]

    temp.write_bytes(b"recorded")
    (tmp_path / "r.AB-2026-0007.xlsx").write_bytes(b"another file")
    kernel32.calls.clear()
    kept = keep_in_sight(temp, target, "AB-2026-0007")
    assert kept == str(tmp_path / "r.AB-2026-0007-2.xlsx")
    assert (tmp_path / "r.AB-2026-0007.xlsx").read_bytes() == b"another file"
    assert Path(kept).read_bytes() == b"recorded" and not temp.exists()
    assert kernel32.calls == [(temp.name, "r.AB-2026-0007.xlsx", WRITE_THROUGH),
                              (temp.name, "r.AB-2026-0007-2.xlsx", WRITE_THROUGH)]

    temp.write_bytes(b"second results")  # the name taken (an unissued file): replaced
    kernel32.calls.clear()
    _place(Register(), str(temp), target)
    assert target.read_bytes() == b"second results"
    assert kernel32.calls == [(temp.name, "r.xlsx", WRITE_THROUGH),
                              (temp.name, "r.xlsx", REPLACE_EXISTING | WRITE_THROUGH)]


def test_a_refused_move_raises_the_windows_error_and_leaves_the_file(tmp_path, kernel32):
    target = tmp_path / "job.anglebench.json"
    target.write_text("old")
    kernel32.refuse = 5  # ERROR_ACCESS_DENIED: e.g. the file is open in another program
    with pytest.raises(OSError) as caught:
        write_bytes_atomic(target, b"new")
    assert caught.value.strerror == "Access is denied."
    assert caught.value.filename.endswith(".tmp") and caught.value.filename2 == str(target)
    assert target.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == [target.name]  # no temporary file left


def test_a_taken_name_is_file_exists_whatever_the_error_class(tmp_path, kernel32):
    src, dst = tmp_path / "a.tmp", tmp_path / "b.csv"
    src.write_text("a")
    dst.write_text("b")
    with pytest.raises(FileExistsError):
        durable_rename.rename_new_durably(src, dst)
    assert src.read_text() == "a" and dst.read_text() == "b"


def test_without_movefileexw_the_rename_is_made_and_the_log_says_so(tmp_path, monkeypatch,
                                                                   caplog):
    """kernel32 cannot be had (a stripped-down Python): os.replace, as before, logged."""
    replaced = []
    real_replace = os.replace

    def no_kernel32():
        raise OSError(errno.ENOENT, "kernel32 not found")

    def replace(src, dst):
        replaced.append(os.path.basename(dst))
        real_replace(src, dst)

    monkeypatch.setattr(durable_rename, "_WINDOWS", True)
    monkeypatch.setattr(durable_rename, "_kernel32", no_kernel32)
    monkeypatch.setattr(os, "replace", replace)
    target = tmp_path / "out.csv"
    with caplog.at_level(logging.WARNING, logger=durable_rename.__name__):
        write_bytes_atomic(target, b"a,b\n")
    assert target.read_bytes() == b"a,b\n" and replaced == ["out.csv"]
    assert len(caplog.messages) == 1
    assert "without MOVEFILE_WRITE_THROUGH, it may not survive a power cut" in caplog.messages[0]
    assert hashlib.sha256(target.read_bytes()).hexdigest()  # readable, whole
