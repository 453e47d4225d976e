"""Recovery that lost work (rev61): the orphan was deleted before the recovering window's
own autosave was written (F3); a save during a long autosave left a stale one (F4)."""

from __future__ import annotations

import os

from models.project.file import Project, WorkbenchState
from models.project.recovery import RecoveryStore


def _crashed_store(folder) -> RecoveryStore:
    """A window's autosave left by kill -9: its file stays, its lock is let go."""
    store = RecoveryStore(folder)
    store.claim()
    store.write(Project({"theodolite": WorkbenchState([["0", "12.5"]])}), "/lab/run.json")
    os.close(store._lock_fd)
    store._lock_fd = None
    return store


def test_an_adopted_orphan_is_this_windows_autosave_at_once(tmp_path):
    crashed = _crashed_store(tmp_path / "rec")
    survivor = RecoveryStore(tmp_path / "rec")
    survivor.claim()
    assert survivor.orphans() == [crashed.path]
    text = crashed.path.read_bytes()
    survivor.adopt(crashed.path)
    # the work is on disk under the survivor's name (it was deleted, nothing written yet)
    assert survivor.exists() and survivor.path.read_bytes() == text
    assert not crashed.path.exists() and not crashed.lock_path.exists()
    survivor._lock_fd, fd = None, survivor._lock_fd
    os.close(fd)  # the survivor crashes too, before its own autosave
    third = RecoveryStore(tmp_path / "rec")
    assert third.orphans() == [survivor.path]
    assert third.load(survivor.path).workbenches["theodolite"].rows == [["0", "12.5"]]


def test_an_orphan_not_renamed_stays_until_this_windows_autosave_is_written(tmp_path):
    crashed = _crashed_store(tmp_path / "rec")
    survivor = RecoveryStore(tmp_path / "rec")
    survivor.claim()
    survivor.write(Project({"polygon": WorkbenchState([["1"]])}))  # an autosave of its own
    survivor.adopt(crashed.path)
    assert crashed.path.is_file()  # not deleted before the survivor's autosave holds it
    survivor.write(Project({"theodolite": WorkbenchState([["0", "12.5"]])}))
    assert not crashed.path.exists() and survivor.orphans() == []


def test_an_autosave_taken_before_a_save_is_not_put_back_after_it(tmp_path):
    store = RecoveryStore(tmp_path / "rec")
    store.claim()
    store.write(Project({"theodolite": WorkbenchState([["0", "1"]])}))
    calls = []

    def project_saved_meanwhile():  # the window saves while the autosave thread writes
        if not calls:
            store.discard()
        calls.append(1)

    big = Project({"theodolite": WorkbenchState([[str(i), "2"] for i in range(50_000)])})
    written = store.write(big, None, project_saved_meanwhile)
    assert calls and not store.exists()  # the rename put the stale autosave back
    assert written is False
    assert [p.name for p in store.folder.iterdir()] == [store.lock_path.name]  # no temp left
    generation = store.generation
    store.discard()  # a save after the project was taken: its autosave is dropped
    assert store.write(big, None, None, generation) is False and not store.exists()
    assert store.write(big) is True and store.exists()
