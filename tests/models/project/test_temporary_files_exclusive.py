"""reg72 #9: the autosave wrote its pending file through a symbolic link planted at that
name and replaced the link's target (an issued PDF). A name of the program's own is never
written through: the link is replaced, its target left as it was."""

from __future__ import annotations

import hashlib
import os

import pytest

from models.project.file import Project
from models.project.recovery import RecoveryStore


@pytest.mark.skipif(not hasattr(os, "symlink") or os.name == "nt", reason="POSIX links")
def test_the_autosave_never_writes_through_a_link_planted_at_its_pending_name(tmp_path):
    victim = tmp_path / "issued.pdf"
    victim.write_bytes(b"%PDF-1.4 an issued certificate\n%%EOF\n")
    before = hashlib.sha256(victim.read_bytes()).hexdigest()
    store = RecoveryStore(tmp_path / "autosave")
    store.claim()
    try:
        pending = store.path.with_name(f".{store.path.name}.pending.tmp")
        pending.parent.mkdir(parents=True, exist_ok=True)
        os.symlink(victim, pending)
        store.write(Project())
        assert hashlib.sha256(victim.read_bytes()).hexdigest() == before
        assert store.path.is_file() and b"anglebench-project" in store.path.read_bytes()
    finally:
        store.release()
