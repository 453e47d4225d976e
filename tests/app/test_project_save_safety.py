"""Saves that lost work (rev61), on the project presenter with mock views: any failure of a
save or an autosave is said and the work stays (F1); a project file changed on disk since
it was read or written is not replaced unasked (F2); recovered work is on disk at every
moment (F3); a save during a long autosave leaves no autosave older than itself (F4)."""

from __future__ import annotations

import json
import os
import threading

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

from app import project_presenter
from app.main_window import MainWindow
from models.project import recovery as recovery_module
from models.project.file import load_project
from models.project.recovery import RecoveryStore
from tests.app.test_project_presenter import (  # noqa: F401 - the fixture is used by name
    _delete_presenters_at_teardown,
    make,
)


def _rows(path):
    return load_project(path).workbenches["theodolite"].rows


# -- F1: a failure of any kind is a save that did not happen, said ----------------------
@pytest.mark.parametrize("error", [
    UnicodeEncodeError("utf-8", "x\ud800", 1, 2, "surrogates not allowed"),
    MemoryError(), TypeError("Object of type set is not JSON serializable")])
def test_a_save_that_fails_in_any_way_is_said_and_the_work_stays(qtbot, tmp_path, monkeypatch,
                                                                 error):
    presenter, view, (theodolite, _) = make(qtbot, tmp_path)
    theodolite.table_model.set_cells([(0, 0, "-20"), (0, 1, "21.56")])

    def failing(*_args, **_kwargs):
        raise error

    monkeypatch.setattr(project_presenter, "save_project", failing)
    path = tmp_path / "job.anglebench.json"
    assert presenter.save_to(path) is False  # it raised: the slot died without a word
    title, text = view.tell.call_args.args
    reason = {UnicodeEncodeError: "'utf-8' codec can't encode character '\\ud800' in position 1:"
              " surrogates not allowed", MemoryError: "MemoryError",
              TypeError: "Object of type set is not JSON serializable"}[type(error)]
    assert (title, text) == ("Cannot save", f"{path}: {reason}. Your readings are still here.")
    assert presenter.is_modified and presenter.path is None and not path.exists()
    presenter.path = path  # closing the window: "Save the changes first?" Save
    view.ask_save_changes.return_value = True
    assert presenter.confirm_discard() is False  # the window stays open
    assert theodolite.sheet.copy_rows()[0][:2] == ["-20", "21.56"]


def test_an_autosave_that_fails_in_any_way_is_said(qtbot, tmp_path, monkeypatch):
    presenter, view, (theodolite, _) = make(qtbot, tmp_path)
    theodolite.table_model.set_cells([(0, 0, "-20")])

    def failing(*_args, **_kwargs):
        raise ValueError("Out of range float values are not JSON compliant")

    monkeypatch.setattr(presenter.recovery, "write", failing)
    presenter.autosave()  # it raised (and killed the autosave thread of a large sheet)
    assert presenter.autosave_problem == (f"{presenter.recovery.path}: Out of range float "
                                          "values are not JSON compliant")
    view.show_autosave_problem.assert_called_once()


def test_a_file_with_a_broken_character_opens_repaired_said_and_saves(qtbot, tmp_path):
    path = tmp_path / "lims.anglebench.json"
    path.write_text(json.dumps({
        "format": "anglebench-project", "schema_version": 2, "app_version": "0.1.0",
        "metadata": {}, "workbenches": {"theodolite": {"rows": [["-20", "21.56", "x\ud800"]],
                                                       "settings": {}}}}))
    presenter, view, (theodolite, _) = make(qtbot, tmp_path)
    assert presenter.open_project(path)
    view.tell.assert_called_once_with(
        "Opened with repairs", f"{path}: workbench 'theodolite', row 1, column 3: a broken "
        "character (U+D800: half of a UTF-16 pair) was replaced by U+FFFD (\ufffd)")
    assert theodolite.sheet.copy_rows()[0][:3] == ["-20", "21.56", "x\ufffd"]
    assert presenter.is_modified  # differs from its file
    theodolite.table_model.set_cells([(1, 0, "-19"), (1, 1, "26.56")])  # the day's work
    assert presenter.save()
    assert [r[:3] for r in _rows(path)] == [["-20", "21.56", "x\ufffd"], ["-19", "26.56", ""]]


@pytest.mark.slow
def test_the_window_does_not_close_when_its_work_was_not_saved(qtbot, tmp_path, monkeypatch):
    window = MainWindow(settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat),
                        recovery=RecoveryStore(tmp_path / "rec"))
    qtbot.addWidget(window)
    told = []
    window.tell = lambda title, text: told.append((title, text))
    window.ask = lambda *a: QMessageBox.StandardButton.Save
    window.projects.start()
    window.show()
    window.presenter("theodolite").table_model.set_cells([(0, 0, "-20")])

    def broken():
        raise RuntimeError("a dialog that failed")

    monkeypatch.setattr(window.projects, "confirm_discard", broken)
    assert window.close() is False and window.isVisible()  # it closed, the work in no file
    assert told == [("Cannot save", "The project could not be saved (a dialog that failed). "
                                    "The window stays open with your readings.")]
    monkeypatch.undo()
    window.ask = lambda *a: QMessageBox.StandardButton.Discard
    assert window.close()


# -- F2: a file changed behind the window is not replaced unasked ----------------------
def test_a_save_over_a_file_changed_since_it_was_opened_asks(qtbot, tmp_path):
    path = tmp_path / "job.anglebench.json"
    a, a_view, (a_bench, _) = make(qtbot, tmp_path)
    a_bench.table_model.set_cells([(0, 0, "-20"), (0, 1, "21.56")])
    assert a.save_to(path)
    b, b_view, (b_bench, _) = make(qtbot, tmp_path)
    assert b.open_project(path)
    a_bench.table_model.set_cells([(r, 0, str(-20 + r)) for r in range(1, 40)])
    assert a.save()  # unchanged since A wrote it: not asked
    a_view.ask_overwrite_changed.assert_not_called()
    assert len(_rows(path)) == 40
    b_bench.table_model.set_cells([(0, 2, "0.5")])
    b_view.ask_overwrite_changed.return_value = None  # cancel
    assert b.save() is False  # it replaced A's 40 rows with 1, without a word
    b_view.ask_overwrite_changed.assert_called_once_with("job.anglebench.json")
    assert len(_rows(path)) == 40 and b.is_modified
    b_view.ask_overwrite_changed.return_value = False  # save under another name
    b_view.ask_save_path.return_value = str(tmp_path / "b-copy")
    assert b.save()
    assert len(_rows(path)) == 40 and len(_rows(tmp_path / "b-copy.anglebench.json")) == 1
    assert b.path == tmp_path / "b-copy.anglebench.json"
    # another program rewrites the file A has open; the same bytes again are no change
    os.utime(path, (1, 1))
    a_bench.table_model.set_cells([(40, 0, "20")])
    assert a.save()
    a_view.ask_overwrite_changed.assert_not_called()
    path.write_text(path.read_text().replace('"-20"', '"-21"'))
    a_bench.table_model.set_cells([(41, 0, "21")])
    a_view.ask_overwrite_changed.return_value = True  # replace it
    assert a.save()
    a_view.ask_overwrite_changed.assert_called_once_with("job.anglebench.json")
    assert _rows(path)[0][0] == "-20" and len(_rows(path)) == 42


def test_recovered_work_asks_before_replacing_a_file_saved_since(qtbot, tmp_path):
    path = tmp_path / "job.anglebench.json"
    crashed, _, (bench, _) = make(qtbot, tmp_path)
    bench.table_model.set_cells([(0, 0, "-20")])
    assert crashed.save_to(path)
    bench.table_model.set_cells([(0, 1, "21.56")])
    crashed.autosave()
    os.close(crashed.recovery._lock_fd)  # kill -9
    crashed.recovery._lock_fd = None
    crashed.autosave_timer.stop()
    other, _, (other_bench, _) = make(qtbot, tmp_path)  # a colleague saves meanwhile
    assert other.open_project(path)
    other_bench.table_model.set_cells([(1, 0, "-19")])
    assert other.save()
    other.close()
    survivor, view, _ = make(qtbot, tmp_path)
    view.ask_recover.return_value = True
    assert survivor.offer_recovery()
    view.ask_overwrite_changed.return_value = None
    assert survivor.save() is False
    view.ask_overwrite_changed.assert_called_once_with("job.anglebench.json")
    assert [r[:1] for r in _rows(path)] == [["-20"], ["-19"]]  # the colleague's rows stay
    survivor.close()


# -- F3: the orphan is this window's autosave from the moment it is adopted ------------
def test_recovered_work_is_on_disk_before_this_windows_own_autosave(qtbot, tmp_path,
                                                                    monkeypatch):
    crashed, _, (bench, _) = make(qtbot, tmp_path)
    bench.table_model.set_cells([(0, 0, "-20"), (0, 1, "12.5")])
    crashed.autosave()
    os.close(crashed.recovery._lock_fd)
    crashed.recovery._lock_fd = None
    crashed.autosave_timer.stop()
    survivor, view, _ = make(qtbot, tmp_path)
    view.ask_recover.return_value = True
    # its own autosave not written yet (a large sheet's runs on a thread for seconds)
    monkeypatch.setattr(survivor, "autosave", lambda: None)
    assert survivor.offer_recovery()
    assert survivor.recovery.exists()  # the only copy was deleted: a crash now lost it all
    assert not crashed.recovery.path.exists()
    os.close(survivor.recovery._lock_fd)  # the survivor is killed too
    survivor.recovery._lock_fd = None
    third, view3, (third_bench, _) = make(qtbot, tmp_path)
    view3.ask_recover.return_value = True
    assert third.offer_recovery()
    assert third_bench.sheet.copy_rows()[0][:2] == ["-20", "12.5"]
    third.close()


# -- F4: a save during a background autosave leaves no stale autosave -----------------
def test_a_save_while_the_autosave_thread_writes_leaves_no_autosave(qtbot, tmp_path,
                                                                     monkeypatch):
    presenter, _, (bench, _) = make(qtbot, tmp_path)
    bench.table_model.set_cells([(0, 0, "-20"), (0, 2, "first")])
    path = tmp_path / "job.anglebench.json"
    assert presenter.save_to(path)
    monkeypatch.setattr(project_presenter, "AUTOSAVE_THREAD_ROWS", 0)  # the thread's way
    writing, may_finish = threading.Event(), threading.Event()
    real_save = recovery_module.save_project

    def slow_save(*args, **kwargs):  # the autosave of a large sheet takes seconds
        writing.set()
        may_finish.wait(10)
        return real_save(*args, **kwargs)

    monkeypatch.setattr(recovery_module, "save_project", slow_save)
    bench.table_model.set_cells([(0, 2, "second")])
    presenter.autosave()
    assert writing.wait(10)
    bench.table_model.set_cells([(0, 2, "third")])
    assert presenter.save()  # Save pressed while the thread writes
    may_finish.set()
    presenter._autosave_thread.join(10)
    assert not presenter.is_modified and _rows(path)[0][2] == "third"
    # the thread's rename put an autosave of "second" back: offered after a crash, over "third"
    assert not presenter.recovery.exists()
    assert presenter.recovery.orphans() == []
    presenter.close()


def test_the_window_asks_replace_save_as_or_cancel_save_as_by_default():
    from unittest import mock

    from app.project_dialogs import ProjectDialogs

    window = mock.Mock()
    dialogs = ProjectDialogs(window)
    button = QMessageBox.StandardButton
    for answer, meaning in ((button.Yes, True), (button.No, False), (button.Cancel, None),
                            (None, None)):
        window.ask.return_value = answer
        assert dialogs.ask_overwrite_changed("job.anglebench.json") is meaning
    title, text, buttons, default = window.ask.call_args.args
    assert title == "Project changed on disk" and default == button.No
    assert buttons == button.Yes | button.No | button.Cancel
    assert text == ("job.anglebench.json was changed on disk since this window opened or saved "
                    "it (by another window, a colleague or a program): saving replaces those "
                    "changes.\n\nYes: replace it with this window's project. No: save this "
                    "window's project under another name. Cancel: do not save.")
