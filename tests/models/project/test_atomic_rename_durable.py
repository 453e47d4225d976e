"""A file renamed into place has its folder fsync'ed after the rename (s62): the file's own
fsync does not make its new name durable, and after a power loss the rename (the save, the
autosave) could be lost. A folder that cannot be fsync'ed is not a failed save: the file is
there."""

from __future__ import annotations

import errno
import logging
import os
import stat

import pytest

from models.project import atomic_write
from models.project.atomic_write import write_text_atomic
from models.project.file import Project, load_project, save_project
from models.project.recovery import RecoveryStore

pytestmark = pytest.mark.skipif(not hasattr(os, "O_DIRECTORY"), reason="POSIX folders")


@pytest.fixture
def events(monkeypatch):
    """Every os.fsync and os.replace, in order: ("fsync", "dir"|"file", inode) and
    ("replace", source name, target name)."""
    seen = []
    real_fsync, real_replace = os.fsync, os.replace

    def fsync(fd):
        info = os.fstat(fd)
        seen.append(("fsync", "dir" if stat.S_ISDIR(info.st_mode) else "file", info.st_ino))
        return real_fsync(fd)

    def replace(src, dst, *args, **kwargs):
        seen.append(("replace", os.path.basename(src), os.path.basename(dst)))
        return real_replace(src, dst, *args, **kwargs)

    monkeypatch.setattr(os, "fsync", fsync)
    monkeypatch.setattr(os, "replace", replace)
    return seen


def _after_rename(seen, target):
    """What happened after the rename to ``target``'s name."""
    last = max(i for i, e in enumerate(seen) if e[0] == "replace" and e[2] == target.name)
    return seen[last + 1:]


def test_the_folder_is_fsynced_after_the_file_is_renamed_into_place(tmp_path, events):
    target = tmp_path / "job.anglebench.json"
    target.write_text("old")
    write_text_atomic(target, "new")
    assert target.read_text() == "new"
    folder = tmp_path.stat().st_ino
    kinds = [e[:2] for e in events]
    assert kinds == [("fsync", "file"), ("replace", events[1][1]), ("fsync", "dir")]
    assert events[1][1].startswith(".job.anglebench.json.") and events[1][2] == target.name
    assert events[2] == ("fsync", "dir", folder)  # the folder the file is in, after the rename


def test_a_saved_project_is_durable_in_its_folder(tmp_path, events):
    path = tmp_path / "sub" / "run3.anglebench.json"
    path.parent.mkdir()
    save_project(path, Project())
    assert _after_rename(events, path) == [("fsync", "dir", path.parent.stat().st_ino)]


def test_the_autosave_is_renamed_for_good_before_the_orphans_it_adopted_go(tmp_path, events):
    folder = tmp_path / "recovery"
    crashed = RecoveryStore(folder)
    crashed.write(Project())
    orphan = crashed.path
    store = RecoveryStore(folder)
    store.adopt(orphan)  # the crashed window's work becomes this window's autosave
    assert store.path.exists() and not orphan.exists()
    assert _after_rename(events, store.path)[0] == ("fsync", "dir", folder.stat().st_ino)
    events.clear()
    store.write(Project())  # written beside, renamed into place, the folder fsync'ed
    assert [e for e in events if e[0] == "replace"][-1][2] == store.path.name
    assert _after_rename(events, store.path) == [("fsync", "dir", folder.stat().st_ino)]
    events.clear()
    kept = store.set_aside(store.path, "damaged")
    assert kept.exists()
    assert _after_rename(events, kept) == [("fsync", "dir", folder.stat().st_ino)]
    store.release()
    crashed.release()


def test_a_folder_that_cannot_be_fsynced_is_not_a_failed_save(tmp_path, monkeypatch, caplog):
    """EINVAL: a file system that cannot fsync a folder (some network shares and FUSE).
    The file is in place, every program reads it: the save succeeds, the log says it."""
    real_fsync = os.fsync

    def fsync(fd):
        if stat.S_ISDIR(os.fstat(fd).st_mode):
            raise OSError(errno.EINVAL, "Invalid argument")
        return real_fsync(fd)

    monkeypatch.setattr(os, "fsync", fsync)
    path = tmp_path / "run3.anglebench.json"
    with caplog.at_level(logging.WARNING, logger=atomic_write.__name__):
        save_project(path, Project(metadata={"operator": "A. Colleague"}))
    assert load_project(path).metadata["operator"] == "A. Colleague"
    assert [p.name for p in tmp_path.iterdir()] == [path.name]  # no temporary file left
    assert caplog.messages == [f"cannot fsync {tmp_path} (a rename in it may not survive a "
                               "power loss): [Errno 22] Invalid argument"]
    assert atomic_write.fsync_directory(tmp_path) is False


def test_where_a_folder_cannot_be_opened_the_write_goes_on(tmp_path, monkeypatch, events):
    """Windows: no O_DIRECTORY (a folder is not opened); the file is written all the same."""
    monkeypatch.delattr(os, "O_DIRECTORY")
    path = tmp_path / "out.csv"
    write_text_atomic(path, "a,b\n")
    assert path.read_text() == "a,b\n"
    assert [e[:2] for e in events if e[0] == "fsync"] == [("fsync", "file")]
    assert atomic_write.fsync_directory(tmp_path) is False
