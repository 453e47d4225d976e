"""A lone UTF-16 surrogate made a project unsavable (rev61 F1): repaired and named as the
file is read, written as its escape when typed; the save gives the SHA-256 of what it wrote
(the window's check of a file changed behind it, F2)."""

from __future__ import annotations

import hashlib
import json

import pytest

from models.capture.raw_record import raw_digest
from models.project.file import (
    Project,
    ProjectFileError,
    WorkbenchState,
    load_project,
    project_from_json,
    save_project,
)


def _document(cell: str, setting: str = "a", customer: str = "ACME") -> str:
    """A project file's text as a LIMS or a script writes it (ASCII, JSON escapes)."""
    return json.dumps({
        "format": "anglebench-project", "schema_version": 2, "app_version": "0.1.0",
        "metadata": {"certificates": {"theodolite": {"customer": customer}}},
        "workbenches": {"theodolite": {"rows": [["-20", "21.56", ""], ["-19", "26.5", cell]],
                                       "settings": {"operator": setting}}}})


def test_a_lone_surrogate_is_replaced_on_opening_and_each_place_named(tmp_path):
    path = tmp_path / "lims.anglebench.json"
    path.write_text(_document("x\ud800y", setting="Li \udc00", customer="ACME \ud83d"))
    assert "\\ud800" in path.read_text()  # the escape, in an ASCII file
    project = load_project(path)
    bench = project.workbenches["theodolite"]
    assert bench.rows[1] == ["-19", "26.5", "x\ufffdy"]
    assert bench.settings == {"operator": "Li \ufffd"}
    assert project.metadata["certificates"]["theodolite"]["customer"] == "ACME \ufffd"
    assert project.repairs == [
        f"{path}: certificate details of workbench 'theodolite', 'customer': a broken character "
        "(U+D83D: half of a UTF-16 pair) was replaced by U+FFFD (\ufffd)",
        f"{path}: workbench 'theodolite', row 2, column 3: a broken character (U+D800: half of "
        "a UTF-16 pair) was replaced by U+FFFD (\ufffd)",
        f"{path}: workbench 'theodolite', setting 'operator': a broken character (U+DC00: half "
        "of a UTF-16 pair) was replaced by U+FFFD (\ufffd)"]
    save_project(tmp_path / "saved.anglebench.json", project)  # it raised UnicodeEncodeError
    assert load_project(tmp_path / "saved.anglebench.json") == project
    # a whole character written as its pair of escapes is no repair
    whole = project_from_json(_document("\ud83d\ude00"))
    assert whole.workbenches["theodolite"].rows[1][2] == "\U0001f600" and whole.repairs == []


def test_a_lone_surrogate_in_memory_is_saved_as_its_escape_and_the_digest_returned(tmp_path):
    project = Project({"theodolite": WorkbenchState([["0", "1\udfff"]], {"note": "\\ud800"})})
    path = tmp_path / "p.anglebench.json"
    digest = save_project(path, project)  # it raised UnicodeEncodeError
    data = path.read_bytes()
    assert digest == hashlib.sha256(data).hexdigest()
    data.decode("utf-8")  # valid UTF-8
    assert b'["0","1\\udfff"]' in data and b'"note":"\\\\ud800"' in data
    back = load_project(path)
    assert back.workbenches["theodolite"].rows == [["0", "1\ufffd"]]
    assert back.workbenches["theodolite"].settings == {"note": "\\ud800"}  # typed text, kept
    assert back.repairs == [f"{path}: workbench 'theodolite', row 1, column 2: a broken "
                            "character (U+DFFF: half of a UTF-16 pair) was replaced by U+FFFD "
                            "(\ufffd)"]
    assert back.file_sha256 == digest


def test_a_lone_surrogate_in_the_raw_frames_is_refused_naming_it():
    text = _document("1")[:-1] + ', "raw_capture": {"theodolite\\udc80": {"sha256": ' \
        f'"{raw_digest([])}", "sessions": []}}}}}}'
    assert project_from_json(text.replace("\\udc80", "")).raw_capture == {"theodolite": []}
    with pytest.raises(ProjectFileError, match=r"raw_capture › theodolite\ufffd'.*U\+DC80.*raw "
                                               "frames; nothing was changed"):
        project_from_json(text, "f.json")
