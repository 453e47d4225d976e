import json

import pytest

from models.project.atomic_write import write_text_atomic
from models.project.file import (
    Project,
    ProjectFileError,
    WorkbenchState,
    load_project,
    project_from_json,
    save_project,
)
from models.project.recovery import RecoveryStore


def make_project():
    return Project(
        workbenches={
            "theodolite": WorkbenchState([["0", "0", "1°61'"], ["1", "1.0", "中文"]],
                                         {"method": "elevation", "psi_max_deg": 45.0}),
            "polygon": WorkbenchState([], {"grade": 3}),
        },
        metadata={"operator": "张三"},
    )


def test_round_trip_keeps_bad_cells_and_unicode(tmp_path):
    path = tmp_path / "p.anglebench.json"
    save_project(path, make_project())
    back = load_project(path)
    assert back == make_project()


def test_newer_schema_and_damaged_file_give_clear_messages(tmp_path):
    path = tmp_path / "new.json"
    path.write_text(json.dumps({"format": "anglebench-project", "schema_version": 99}))
    with pytest.raises(ProjectFileError, match="newer AngleBench.*schema 99.*Nothing was changed"):
        load_project(path)
    path.write_text('{"format": "anglebench-project", "schema_version": 1, "workbenches": {')
    with pytest.raises(ProjectFileError, match=r"damaged project file \(line 1"):
        load_project(path)
    with pytest.raises(ProjectFileError, match="not an AngleBench project"):
        project_from_json("[1, 2]")
    with pytest.raises(ProjectFileError, match="'rows' must be a list of lists"):
        project_from_json(json.dumps({"format": "anglebench-project", "schema_version": 1,
                                      "workbenches": {"x": {"rows": "oops"}}}))


def test_atomic_write_leaves_old_file_on_failure(tmp_path, monkeypatch):
    path = tmp_path / "p.json"
    path.write_text("old")

    def broken_replace(src, dst):
        raise OSError("disk full")

    monkeypatch.setattr("os.replace", broken_replace)
    with pytest.raises(OSError):
        write_text_atomic(path, "new")
    assert path.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["p.json"]


def test_recovery_store(tmp_path):
    store = RecoveryStore(tmp_path / "rec")
    store.claim()
    assert not store.exists()
    store.write(make_project(), "/labs/run.anglebench.json")
    assert store.exists()
    other = RecoveryStore(tmp_path / "rec")
    assert other.orphans() == []  # the writer is alive: nothing to recover
    store._lock_fd, fd = None, store._lock_fd
    import os

    os.close(fd)  # the writer dies
    assert other.orphans() == [store.path]
    back = other.load(store.path)
    assert back.workbenches == make_project().workbenches
    assert "autosaved_at" in back.metadata
    assert back.metadata["project_path"] == "/labs/run.anglebench.json"
    other.adopt(store.path)
    assert not store.exists() and other.orphans() == []
    broken = tmp_path / "rec" / "recovery-old.anglebench.json"
    broken.write_text("{broken")
    with pytest.raises(ProjectFileError):
        other.load(broken)
    assert not broken.exists()
    assert len(list((tmp_path / "rec").glob("recovery-old.anglebench.json.damaged-*.json"))) == 1
