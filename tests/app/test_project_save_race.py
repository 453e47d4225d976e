"""Two Saves of one project close together (rev62 F5): "changed on disk?" was checked, then
the file written for as long as the save took; a Save in another process checked inside
that time, found the file unchanged too, and one technician's readings were in no file,
nobody asked. Now the check and the write are one step under the file's lock."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import time
from pathlib import Path

from app import project_presenter
from models.project.file import load_project
from models.project.save_lock import lock_path_of
from tests.app.test_project_presenter import (  # noqa: F401 - the fixture is used by name
    _delete_presenters_at_teardown,
    make,
)

ROOT = Path(__file__).resolve().parents[2]

#: window B, in a process of its own (another workstation): opens the project, types a
#: reading in row 21, and presses Save the moment window A's save has checked the file;
#: the question, if asked, is answered Cancel
_WINDOW_B = """
import json, sys, time
from pathlib import Path
from PySide6.QtWidgets import QApplication
app = QApplication([])
from tests.app.test_project_presenter import make
folder = Path(sys.argv[1]); path = folder / "job.anglebench.json"
presenter, view, (bench, _) = make(None, folder / "b")
assert presenter.open_project(path)
bench.table_model.set_cells([(20, 2, "B's reading")])
view.ask_overwrite_changed.return_value = None
(folder / "b-ready").touch()
while not (folder / "a-checked").exists():
    time.sleep(0.005)
saved = presenter.save()
print(json.dumps({"saved": saved, "modified": presenter.is_modified,
                  "asked": [c.args for c in view.ask_overwrite_changed.call_args_list],
                  "told": [c.args for c in view.tell.call_args_list],
                  "row 21": bench.sheet.copy_rows()[20][:3]}))
presenter.close()
"""


def test_two_saves_close_together_lose_nothing_the_second_is_asked(qtbot, tmp_path,
                                                                   monkeypatch):
    path = tmp_path / "job.anglebench.json"
    a, a_view, (a_bench, _) = make(qtbot, tmp_path / "a")
    a_bench.table_model.set_cells([(r, c, v) for r in range(45)
                                   for c, v in ((0, str(r - 20)), (1, f"{r - 19.99:.2f}"))])
    assert a.save_to(path)
    b = subprocess.Popen([sys.executable, "-c", _WINDOW_B, str(tmp_path)], cwd=ROOT,
                         env={**os.environ, "PYTHONPATH": str(ROOT), "QT_QPA_PLATFORM": "offscreen"},
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while not (tmp_path / "b-ready").exists():  # B has the file open, its reading typed
        assert b.poll() is None and time.monotonic() < deadline, b.communicate()
        time.sleep(0.01)
    a_bench.table_model.set_cells([(0, 2, "A's reading")])
    real_save = project_presenter.save_project
    seen = []

    def save_that_takes_a_while(*args, **kwargs):
        # A has checked the file (unchanged) and writes: a large project takes ~0.3 s,
        # here 3 s, while B presses Save
        lock = lock_path_of(path)
        seen.append(lock.read_text().split()[:2] if lock.exists() else None)
        (tmp_path / "a-checked").touch()
        time.sleep(3)
        return real_save(*args, **kwargs)

    monkeypatch.setattr(project_presenter, "save_project", save_that_takes_a_while)
    assert a.save()
    out, err = b.communicate(timeout=120)
    assert b.returncode == 0, err
    b_result = json.loads(out.strip().splitlines()[-1])
    a_view.ask_overwrite_changed.assert_not_called()
    # B checked while A wrote: "unchanged", saved; A's rename then replaced B's reading
    assert b_result["asked"] == [["job.anglebench.json"]]
    assert (b_result["saved"], b_result["modified"], b_result["told"]) == (False, True, [])
    assert b_result["row 21"] == ["0", "0.01", "B's reading"]  # still in B's window
    rows = load_project(path).workbenches["theodolite"].rows
    assert rows[0][:3] == ["-20", "-19.99", "A's reading"] and rows[20][2:3] in ([], [""])
    assert seen == [[str(os.getpid()), socket.gethostname()]]  # A held the lock as it wrote
    assert not lock_path_of(path).exists()


def test_a_save_while_another_process_holds_the_file_writes_nothing_and_says_who(
        qtbot, tmp_path, monkeypatch):
    from models.project import save_lock
    from tests.models.project.test_save_lock import _holder

    path = tmp_path / "job.anglebench.json"
    a, view, (bench, _) = make(qtbot, tmp_path / "a")
    bench.table_model.set_cells([(0, 0, "-20"), (0, 1, "21.56")])
    assert a.save_to(path)
    before = path.read_bytes()
    bench.table_model.set_cells([(0, 2, "0.5")])
    monkeypatch.setattr(save_lock, "WAIT_SECONDS", 0.3)  # 15 s: a save of millions of rows
    holder = _holder(path, "hold")  # a save in another window that does not end
    try:
        assert a.save() is False
    finally:
        holder.kill()
        holder.communicate(timeout=30)
    view.tell.assert_called_once_with("Cannot save", (
        f"{path} is being saved from another window (computer {socket.gethostname()}, process "
        f"{holder.pid}). Nothing was written; your readings are still here: save again in a "
        "moment."))
    assert path.read_bytes() == before and a.is_modified
    view.ask_overwrite_changed.assert_not_called()
    # that window was killed half-way: its lock left behind does not stop saving
    assert lock_path_of(path).exists()
    assert a.save()
    view.ask_overwrite_changed.assert_not_called()
    assert load_project(path).workbenches["theodolite"].rows[0][:3] == ["-20", "21.56", "0.5"]
    assert not lock_path_of(path).exists() and not a.is_modified


def test_replace_it_is_checked_again_a_change_during_the_question_asks_again(qtbot, tmp_path):
    path = tmp_path / "job.anglebench.json"
    a, a_view, (a_bench, _) = make(qtbot, tmp_path / "a")
    a_bench.table_model.set_cells([(0, 0, "-20"), (0, 1, "21.56")])
    assert a.save_to(path)
    b, b_view, (b_bench, _) = make(qtbot, tmp_path / "b")
    assert b.open_project(path)
    a_bench.table_model.set_cells([(1, 0, "-19")])
    assert a.save()  # B's file is now changed on disk
    b_bench.table_model.set_cells([(0, 2, "B")])

    def answer(_name):
        if b_view.ask_overwrite_changed.call_count == 1:  # while B's question is open …
            a_bench.table_model.set_cells([(2, 0, "-18")])
            assert a.save()  # … A saves again
            return True  # replace (the version B was shown: A's 2 rows)
        return None  # cancel

    b_view.ask_overwrite_changed.side_effect = answer
    assert b.save() is False  # "replace" wrote over A's third row, shown to nobody
    assert b_view.ask_overwrite_changed.call_count == 2
    assert [r[:1] for r in load_project(path).workbenches["theodolite"].rows] == [
        ["-20"], ["-19"], ["-18"]]
    assert b.is_modified
    b_view.ask_overwrite_changed.side_effect = None
    b_view.ask_overwrite_changed.return_value = True
    assert b.save()  # replaced, asked once more, with nothing changed since: written
    assert b_view.ask_overwrite_changed.call_count == 3
    assert load_project(path).workbenches["theodolite"].rows[0][:3] == ["-20", "21.56", "B"]


def test_a_file_in_the_way_of_the_lock_is_named_and_nothing_is_lost(qtbot, tmp_path,
                                                                     monkeypatch):
    """rev63 F8/F9 in the window: a named pipe at the lock's name froze the window's Save; a
    colleague's stale lock that may not be removed said "save again in a moment" for ever.
    Both are said plainly, naming the file and what to do; nothing written, readings kept."""
    import errno
    import pwd

    from models.project import save_lock

    me = pwd.getpwuid(os.getuid()).pw_name
    path = tmp_path / "job.anglebench.json"
    a, view, (bench, _) = make(qtbot, tmp_path / "a")
    bench.table_model.set_cells([(0, 0, "-20"), (0, 1, "21.56")])
    assert a.save_to(path)
    before = path.read_bytes()
    bench.table_model.set_cells([(0, 2, "0.5")])
    lock = lock_path_of(path)
    os.mkfifo(lock)
    started = time.monotonic()
    assert a.save() is False
    assert time.monotonic() - started < 2
    view.tell.assert_called_once_with("Cannot save", (
        f"{lock} is in the way of the project's lock: it is a named pipe (user {me}), not a "
        f"lock AngleBench made. Nothing was written; your readings are still here. Remove "
        f"{lock}, then save again."))
    assert path.read_bytes() == before and a.is_modified
    os.unlink(lock)
    lock.write_text("4242 otherpc 1\n")
    eleven_minutes_ago = time.time() - 660
    os.utime(lock, (eleven_minutes_ago, eleven_minutes_ago))
    real_unlink = os.unlink

    def sticky(name, *args, **kwargs):  # a shared folder with the sticky bit: not ours
        if os.fspath(name) == str(lock):
            raise PermissionError(errno.EPERM, "Operation not permitted", str(name))
        return real_unlink(name, *args, **kwargs)

    monkeypatch.setattr(save_lock.os, "unlink", sticky)
    view.tell.reset_mock()
    assert a.save() is False
    view.tell.assert_called_once_with("Cannot save", (
        f"{lock} is the lock of a save that ended 11 minutes ago, but it belongs to user {me} "
        f"and cannot be removed from here (Operation not permitted). Nothing was written; your "
        f"readings are still here. Ask {me} or an administrator to delete {lock}, then save "
        f"again, or save under another name (File › Save as)."))
    assert path.read_bytes() == before and a.is_modified
    monkeypatch.undo()
    assert a.save() and not a.is_modified  # may be removed now: taken over, saved
    assert load_project(path).workbenches["theodolite"].rows[0][:3] == ["-20", "21.56", "0.5"]


def test_a_lock_dated_in_the_future_is_said_with_its_date_and_nothing_is_lost(
        qtbot, tmp_path, monkeypatch):
    """#63 winlock: a lock dated a day ahead (a computer whose clock is ahead made it) made
    every Save say "being saved from another window … save again in a moment" until that
    date came. Now the Save says the lock's date is in the future, what to do, and nothing
    is written; once it has been seen unchanged for STALE_SECONDS, Save takes it over."""
    from models.project import save_lock

    monkeypatch.setattr(save_lock, "WAIT_SECONDS", 0.3)  # 15 s: a save of millions of rows
    monkeypatch.setattr(save_lock, "STALE_SECONDS", 1.0)  # two minutes
    path = tmp_path / "job.anglebench.json"
    a, view, (bench, _) = make(qtbot, tmp_path / "a")
    bench.table_model.set_cells([(0, 0, "-20"), (0, 1, "21.56")])
    assert a.save_to(path)
    before = path.read_bytes()
    bench.table_model.set_cells([(0, 2, "0.5")])
    lock = lock_path_of(path)
    tomorrow = time.time() + 86400
    lock.write_text(f"4242 bench-7 {tomorrow:.3f}\n")
    os.utime(lock, (tomorrow, tomorrow))
    assert a.save() is False
    date = time.strftime("%Y-%m-%d %H:%M:%S", time.localtime(tomorrow))
    view.tell.assert_called_once_with("Cannot save", (
        f"{lock} is dated {date}, later than this computer's clock (a computer whose clock is "
        f"ahead made it, or this clock was set back), so its age cannot be told. Nothing was "
        f"written; your readings are still here. If no other window or computer is saving "
        f"this project, delete {lock} and save again; otherwise save again in 2 minutes: a "
        f"lock left unchanged that long is taken as left over."))
    assert path.read_bytes() == before and a.is_modified and lock.exists()
    time.sleep(1.1)  # unchanged since the first Save saw it: its save is gone
    assert a.save() and not a.is_modified
    assert load_project(path).workbenches["theodolite"].rows[0][:3] == ["-20", "21.56", "0.5"]
    assert not lock.exists()
