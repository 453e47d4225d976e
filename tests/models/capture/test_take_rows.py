"""The captured readings follow their rows (review 61 F5), a deleted one is said as deleted,
a take that cannot be checked is said so and a session is bound to its workbench (review 61
F7)."""

from __future__ import annotations

import hashlib
import json

import pytest

from app.certificate_issue import readings_edited_after_capture
from models.capture.raw_record import session_json
from models.capture.take_rows import TakeRows, deleted_at, deleted_row, session_takes
from models.project.file import Project, ProjectFileError, WorkbenchState, load_project, save_project
from models.registry import KINDS

POLYGON = KINDS["polygon"]
FRAMES = [(0.0, b"3 003 12.500 -3.250", True), (0.1, b"3 003 21.560 1.000", True),
          (0.2, b"3 003 7.250 0.500", True)]
ROWS = [["1", "0", "0", "99", "9"], ["1", "0", "0", "12.5", "-3.25"],
        ["2", "45", "0", "21.56", "1"], ["3", "90", "0", "7.25", "0.5"]]


def _session(takes, frames=FRAMES, **extra):
    return session_json("autocollimator", "/dev/ttyUSB0", 9600, "2026-12-02T01:02:03+00:00",
                        frames, takes, **extra)


def _said(rows, sessions, kind=POLYGON):
    return [str(e.text()) for e in readings_edited_after_capture(kind, {}, rows, sessions)]


def test_takes_move_with_rows_inserted_and_deleted_and_come_back_on_undo():
    session = _session([[1, 0, 0], [2, 1, 1], [3, 2, 2]])
    takes = TakeRows(lambda: session_takes([session]))
    takes.inserted(0, 2)  # two rows at the top: every take two rows down
    assert [t[0] for t in session["takes"]] == [3, 4, 5]
    detached = takes.removed(0, 2)  # and out again: nothing captured was in them
    assert detached == [] and [t[0] for t in session["takes"]] == [1, 2, 3]
    detached = takes.removed(2, 1)  # the row of the second take: detached, row 2 kept
    assert [t[0] for t in session["takes"]] == [1, -4, 2]
    assert deleted_at(-4) == 2 and deleted_row(2) == -4 and deleted_at(-1) is None
    takes.inserted(2, 1)  # the undo: the row back, then its take
    takes.reattach(detached)
    assert [t[0] for t in session["takes"]] == [1, 2, 3]
    detached = takes.replaced()  # the sheet replaced: every take detached
    assert [t[0] for t in session["takes"]] == [-3, -4, -5]
    takes.reattach(detached)
    assert [t[0] for t in session["takes"]] == [1, 2, 3]


def test_a_take_replaced_by_a_later_one_is_neither_moved_nor_detached():
    session = _session([[-1, 0, 0], [2, 1, 1]])
    takes = TakeRows(lambda: session_takes([session]))
    takes.inserted(0, 1)
    assert takes.replaced() == [(("autocollimator", "/dev/ttyUSB0",
                                  "2026-12-02T01:02:03+00:00", 1, 1), 3)]
    assert [t[0] for t in session["takes"]] == [-1, -5]


def test_takes_moved_with_the_rows_check_as_captured():
    # row 0 typed, rows 1-3 captured; row 0 deleted: the readings are rows 0-2 now
    session = _session([[1, 0, 0], [2, 1, 1], [3, 2, 2]])
    TakeRows(lambda: session_takes([session])).removed(0, 1)
    assert _said(ROWS[1:], [session]) == []
    # the rows not moved (as before the fix) make every reading look edited
    assert _said(ROWS[1:], [_session([[1, 0, 0], [2, 1, 1], [3, 2, 2]])])[0] == \
        "reading of row 2 edited after capture: 12.5 → 21.56"


def test_a_deleted_captured_reading_is_said_with_the_row_it_had_and_its_values():
    session = _session([[1, 0, 0], [2, 1, 1], [3, 2, 2]])
    TakeRows(lambda: session_takes([session])).removed(2, 1)
    rows = ROWS[:2] + ROWS[3:]
    assert _said(rows, [session]) == ["reading of row 3 deleted after capture: 21.56, 1"]


def test_a_take_whose_frames_hold_no_reading_is_said_unverifiable():
    # the frame behind row 2's take set from a reading (1) to not one (0) by hand
    frames = [FRAMES[0], (0.1, b"3 003 21.560 1.000", False)]
    said = _said(ROWS[1:3], [_session([[0, 0, 0], [1, 1, 1]], frames)])
    assert said == ["reading of row 2 cannot be checked against the capture: its frames give "
                    "no value of this sheet"]


def test_a_session_of_another_workbench_is_said_and_refused_on_opening(tmp_path):
    moved = _session([[0, 0, 0]], workbench="polygon")
    theodolite = KINDS["theodolite"]
    assert _said([["-20", "-19.9", "-1.5"]], [moved], theodolite) == [
        "capture session started 2026-12-02T01:02:03+00:00 was recorded on workbench "
        "'polygon': its readings cannot be checked here"]
    # 0.8.10's session names no workbench: its readings still cannot be checked on the
    # theodolite (no column of it takes an autocollimator's value), which is said
    legacy = _session([[0, 0, 0]])
    assert _said([["-20", "-19.9", "-1.5"]], [legacy], theodolite) == [
        "reading of row 1 cannot be checked against the capture: its frames give no value "
        "of this sheet"]
    path = tmp_path / "p.anglebench.json"
    save_project(path, Project({"polygon": WorkbenchState(ROWS[1:2], {})}, {},
                               {"polygon": [moved]}))
    document = json.loads(path.read_text(encoding="utf-8"))
    document["raw_capture"] = {"theodolite": document["raw_capture"]["polygon"]}
    path.write_text(json.dumps(document, ensure_ascii=False), encoding="utf-8")
    with pytest.raises(ProjectFileError, match="session 1: recorded on workbench 'polygon', "
                                               "not this one"):
        load_project(path, {"polygon": POLYGON, "theodolite": theodolite})


def test_a_session_without_its_workbench_0_8_10_and_a_deleted_take_round_trip(tmp_path):
    old = _session([[1, 0, 0], [deleted_row(2), 1, 1]])  # as 0.8.10 wrote it: no workbench
    path = tmp_path / "p.anglebench.json"
    save_project(path, Project({"polygon": WorkbenchState(ROWS, {})}, {}, {"polygon": [old]}))
    entry = json.loads(path.read_text(encoding="utf-8"))["raw_capture"]["polygon"]
    # the digest is of the sessions as stored, their takes' rows included
    assert entry["sha256"] == hashlib.sha256(json.dumps(
        entry["sessions"], ensure_ascii=False, separators=(",", ":")).encode()).hexdigest()
    assert entry["sessions"][0]["takes"] == [[1, 0, 0], [-4, 1, 1]]
    project = load_project(path, {"polygon": POLYGON})
    assert project.raw_capture["polygon"] == [old]
    assert _said(ROWS, project.raw_capture["polygon"]) == [
        "reading of row 3 deleted after capture: 21.56, 1"]


def test_an_undone_take_claims_no_row_and_its_redo_puts_it_back():
    """Review 62 F4: the undo of a take left it in its row; a reading typed there was then
    said "edited after capture" with the undone take's values."""
    session = _session([[1, 0, 0], [2, 1, 1], [3, 2, 2]])
    takes = TakeRows(lambda: session_takes([session]))
    key = dict(session_takes([session]))
    third = next(k for k, t in key.items() if t[1] == 2)
    takes.undone([(third, 3)])
    assert [t[0] for t in session["takes"]] == [1, 2, -1]
    typed = [*ROWS[:3], ["3", "90", "0", "40.00", "3.00"]]  # row 4 typed by hand since
    assert _said(typed, [session]) == []
    takes.redone([(third, 3)])
    assert [t[0] for t in session["takes"]] == [1, 2, 3]
    assert _said(typed, [session]) == ["reading of row 4 edited after capture: 7.25 → 40.00",
                                       "reading of row 4 edited after capture: 0.5 → 3.00"]
    # the undo of a replacement undoes the takes made into it, not those it detached
    detached = takes.replaced()
    session["takes"].append([0, 2, 2])  # a take into the replacement (the fringe's own)
    made = takes.undo_replacement()
    takes.reattach(detached)
    assert [t[0] for t in session["takes"]] == [1, 2, 3, -1]
    takes.detach(detached)  # its redo
    takes.redone(made)
    assert [t[0] for t in session["takes"]] == [-3, -4, -5, 0]


AGAIN = ("reading of row {row} captured again, superseding an earlier take (both kept in the "
         "instrument output)")


def test_a_take_into_a_row_supersedes_the_older_take_of_its_instrument_and_undo_restores_it(
        tmp_path):
    """Review 62 F1: row 2's cells cleared and the reading taken again (the newer take made
    at -1, then in its row: the panel's order). The older take is marked superseded with
    the newer's key, the row said captured again once, never edited; the undo of the newer
    gives the row back to the older (its cells cleared: said cleared); a readout's take of
    the same row, which wrote another column, is not superseded; the file keeps the mark."""
    session = _session([[1, 0, 0], [2, 1, 1]])
    readout = session_json("readout", "tcp://r:1", 9600, "2026-12-02T01:02:04+00:00",
                           [(0.0, b"45.0", True)], [[2, 0, 0]])
    takes = TakeRows(lambda: session_takes([session, readout]))
    keys = dict(session_takes([session, readout]))
    older = next(k for k, t in keys.items() if k[0] == "autocollimator" and t[1] == 1)
    takes.columns[older] = frozenset({"ac_x_arcsec", "ac_y_arcsec"})
    takes.columns[next(k for k in keys if k[0] == "readout")] = frozenset({"encoder_deg"})
    cleared = [*ROWS[:2], ["2", "45", "0", "", ""], ROWS[3]]
    assert _said(cleared, [session]) == ["reading of row 3 cleared after capture: 21.56",
                                         "reading of row 3 cleared after capture: 1"]
    session["takes"].append([-1, 2, 2])  # the retake, undone until its command's redo
    newer = ("autocollimator", "/dev/ttyUSB0", "2026-12-02T01:02:03+00:00", 2, 2)
    takes.taken([(newer, 2)], {newer: frozenset({"ac_x_arcsec", "ac_y_arcsec"})})
    assert session["takes"] == [[1, 0, 0], [-1, 1, 1, list(newer)], [2, 2, 2]]
    assert readout["takes"] == [[2, 0, 0]]  # another instrument's: its own reading
    retaken = [*ROWS[:2], ["2", "45", "0", "7.25", "0.5"], ROWS[3]]
    # was: "reading of row 3 edited after capture: 21.56 → 7.25" (and 1 → 0.5)
    assert _said(retaken, [session]) == [AGAIN.format(row=3)]
    path = tmp_path / "p.anglebench.json"
    save_project(path, Project({"polygon": WorkbenchState(retaken, {})}, {}, {"polygon": [session]}))
    opened = load_project(path, {"polygon": POLYGON}).raw_capture["polygon"]
    assert opened == [session] and _said(retaken, opened) == [AGAIN.format(row=3)]
    takes.inserted(0, 1)  # a row above: the newer moves, the mark stays with the older
    assert session["takes"] == [[2, 0, 0], [-1, 1, 1, list(newer)], [3, 2, 2]]
    takes.removed(0, 1)
    takes.untaken([(newer, 2)])  # Edit › Undo of the retake: the older claims row 3 again
    assert session["takes"] == [[1, 0, 0], [2, 1, 1], [-1, 2, 2]]
    assert _said(cleared, [session]) == ["reading of row 3 cleared after capture: 21.56",
                                         "reading of row 3 cleared after capture: 1"]
    takes.taken([(newer, 2)])  # its redo: superseded again
    assert session["takes"] == [[1, 0, 0], [-1, 1, 1, list(newer)], [2, 2, 2]]


def test_a_readout_take_supersedes_an_older_one_only_over_its_own_column():
    """A readout into "the current cell": two takes into two columns of one row are two
    readings (the older stays checked, so an edit of it is said); into the same column, the
    newer supersedes; an older one whose column is not known (a project opened) stays."""
    readout = session_json("readout", "tcp://r:1", 9600, "t",
                           [(0.0, b"1", True), (0.1, b"2", True), (0.2, b"3", True)],
                           [[0, 0, 0]])
    takes = TakeRows(lambda: session_takes([readout]))
    first, second, third = (("readout", "tcp://r:1", "t", i, i) for i in range(3))
    readout["takes"].append([-1, 1, 1])
    takes.taken([(second, 0)], {second: frozenset({"encoder_deg"})})
    assert readout["takes"] == [[0, 0, 0], [0, 1, 1]]  # the first's column not known
    takes.columns[first] = frozenset({"polygon_dev_arcsec"})
    readout["takes"].append([-1, 2, 2])
    takes.taken([(third, 0)], {third: frozenset({"encoder_deg"})})
    assert readout["takes"] == [[0, 0, 0], [-1, 1, 1, list(third)], [0, 2, 2]]


def test_an_undone_take_is_superseded_by_a_take_into_its_row_as_a_cleared_one_is():
    """The row an undone take was in moves with the rows (not with its stored -1); a take of
    its instrument into that row supersedes it and is said "captured again", as for a take
    whose cells were cleared; the undo of that take undoes the older one again."""
    session = _session([[-1, 0, 0], [-1, 1, 1], [-1, 2, 2]])
    takes = TakeRows(lambda: session_takes([session]))
    key = [k for k, _ in session_takes([session])]
    takes.taken([(key[0], 1)])
    takes.undone([(key[0], 1)])  # Edit › Undo of the take into row 2
    assert takes.undone_rows == {key[0]: 1}
    takes.inserted(0, 1)  # a row above: row 3 now
    assert takes.undone_rows == {key[0]: 2} and session["takes"][0][:1] == [-1]
    takes.taken([(key[1], 3)])  # into another row: a first take
    assert [t[0] for t in session["takes"]] == [-1, 3, -1] and len(session["takes"][0]) == 3
    takes.taken([(key[2], 2)])  # into its row: the undone take superseded
    assert session["takes"][0] == [-1, 0, 0, list(key[2])] and takes.undone_rows == {}
    rows = [["0", "0", "0", "1", "1"], ROWS[0], ROWS[3], ROWS[2]]
    assert _said(rows, [session]) == ["reading of row 3 captured again, superseding an "
                                      "earlier take (both kept in the instrument output)"]
    takes.untaken([(key[2], 2)])  # the undo of the newer take: both undone, of row 3
    assert [t[0] for t in session["takes"]] == [-1, 3, -1] and len(session["takes"][0]) == 3
    assert takes.undone_rows == {key[0]: 2, key[2]: 2}
    takes.removed(2, 1)  # their row deleted: of no row any more
    assert takes.undone_rows == {}
    takes.inserted(2, 1)  # a new row in its place: another row
    takes.taken([(key[2], 2)])
    assert [t[0] for t in session["takes"]] == [-1, 3, 2] and len(session["takes"][0]) == 3
