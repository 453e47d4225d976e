"""Issue 40 item 10: an autosave that fails is said in the window (the status bar, and a
warning that stays until a save succeeds), and a value still being typed in a cell's editor
is autosaved: after kill -9 it is in the recovery file, the typed readings with it."""

from __future__ import annotations

import errno
import os
import stat

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

from app.main_window import MainWindow
from models.project.file import load_project
from models.project.recovery import RecoveryStore

pytestmark = pytest.mark.slow  # a window each


@pytest.fixture
def make_window(qtbot, tmp_path):
    made = []

    def factory(folder="recovery"):
        settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
        window = MainWindow(settings=settings, recovery=RecoveryStore(tmp_path / folder))
        window.told = []
        window.tell = lambda title, text: window.told.append(text)
        window.ask = lambda *a: QMessageBox.StandardButton.Yes
        qtbot.addWidget(window)
        made.append(window)
        return window

    yield factory
    from PySide6.QtCore import QCoreApplication, QEvent

    for window in made:
        window.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


def _warning(window) -> str:
    label = getattr(window, "autosave_warning", None)
    return label.text() if label is not None and not label.isHidden() else ""


def test_a_full_folder_is_said_and_the_warning_stays_until_a_save_succeeds(
        make_window, qtbot, tmp_path, monkeypatch):
    window = make_window()
    store = window.projects.recovery
    real_write = store.write

    def full(*args, **kwargs):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(store, "write", full)
    bench = window.presenter("theodolite")
    bench.table_model.set_cells([(0, 0, "1.5")])
    window.projects.autosave()
    qtbot.waitUntil(lambda: bool(_warning(window)), timeout=3000)
    assert "Autosave failed" in _warning(window) and "No space left on device" in _warning(window)
    assert "Autosave failed" in window.statusBar().currentMessage()
    assert window.projects.autosave_problem
    bench.table_model.set_cells([(1, 0, "2.5")])  # still failing: still said
    window.projects.autosave()
    qtbot.wait(50)
    assert "No space left on device" in _warning(window)
    window.statusBar().showMessage("Ready")  # another message does not hide it
    assert "Autosave failed" in _warning(window)
    monkeypatch.setattr(store, "write", real_write)  # room again
    window.projects.autosave()
    qtbot.waitUntil(lambda: not _warning(window), timeout=3000)
    assert not window.projects.autosave_problem and store.exists()


@pytest.mark.skipif(os.geteuid() == 0, reason="root writes into a read-only folder")
def test_a_read_only_folder_is_said(make_window, qtbot, tmp_path):  # pragma: no cover - root
    window = make_window()
    folder = window.projects.recovery.folder
    folder.chmod(stat.S_IRUSR | stat.S_IXUSR)
    try:
        window.presenter("theodolite").table_model.set_cells([(0, 0, "1.5")])
        window.projects.autosave()
        qtbot.waitUntil(lambda: bool(_warning(window)), timeout=3000)
    finally:
        folder.chmod(stat.S_IRWXU)


def test_a_save_of_the_project_clears_the_warning(make_window, qtbot, tmp_path, monkeypatch):
    window = make_window()

    def full(*args, **kwargs):
        raise OSError(errno.EROFS, "Read-only file system")

    monkeypatch.setattr(window.projects.recovery, "write", full)
    window.presenter("theodolite").table_model.set_cells([(0, 0, "1.5")])
    window.projects.autosave()
    qtbot.waitUntil(lambda: "Read-only file system" in _warning(window), timeout=3000)
    assert window.projects.save_to(tmp_path / "safe.anglebench.json")
    assert not _warning(window)


def test_the_value_being_typed_is_autosaved_and_recovered_after_kill_9(make_window, qtbot):
    window = make_window()
    window.show()
    bench = window.presenter("theodolite")
    bench.table_model.set_cells([(0, 0, "-20"), (0, 1, "21.56"), (1, 0, "-19")])
    table = window.current.view.table if window.current is bench else bench.view.table
    index = table.model().index(1, 1)
    table.setCurrentIndex(index)
    table.edit(index)
    qtbot.waitUntil(lambda: table._typing_delegate.editor is not None, timeout=3000)
    editor = table._typing_delegate.editor
    qtbot.keyClicks(editor, "26.56")  # typed, not yet entered
    assert table.pending_edit() == (1, 1, "26.56")
    assert bench.sheet.text(1, 1) == ""  # the sheet has not got it
    assert window.projects.autosave_timer.isActive()  # typing asks for an autosave
    window.projects.autosave()
    saved = load_project(window.projects.recovery.path)  # what a kill -9 leaves
    rows = saved.workbenches["theodolite"].rows
    assert rows[0][:2] == ["-20", "21.56"] and rows[1][:2] == ["-19", "26.56"]
    assert saved.metadata["pending_edits"]["theodolite"] == {"row": 2, "column": 2,
                                                             "text": "26.56", "was": ""}
    assert bench.sheet.text(1, 1) == ""  # the autosave changed nothing in the sheet
    # the window dies (kill -9): its lock goes with the process, the autosave stays
    os.close(window.projects.recovery._lock_fd)
    window.projects.recovery._lock_fd = None
    window.projects.autosave_timer.stop()
    survivor = make_window()
    assert survivor.projects.offer_recovery()
    recovered = survivor.presenter("theodolite")
    assert recovered.sheet.text(1, 1) == "26.56" and recovered.sheet.text(0, 1) == "21.56"
    assert "still being typed (row 2, column 2)" in survivor.statusBar().currentMessage()
    assert "pending_edits" not in survivor.projects.metadata
    editor.setText("26.56")
    table.commitData(editor)
    table.closeEditor(editor, table.itemDelegate().EndEditHint.NoHint)
    assert table.pending_edit() is None


def test_a_value_typed_in_a_large_record_goes_into_its_snapshot_only():
    """A record of numbers (a million rows would be) keeps its arrays: the typed value is set
    as an edited row of the autosave's snapshot; the sheet's own rows are untouched."""
    import numpy as np

    from app.project_presenter import ProjectPresenter
    from models.project.file import Project, WorkbenchState, project_to_json
    from models.readings.sheet import NumericRows
    from models.registry import KINDS

    columns = KINDS["fringe"].columns
    values = {c.key: np.arange(5, dtype=float) + i for i, c in enumerate(columns)}
    rows = NumericRows(columns, values, 5)
    snapshot = rows.snapshot()
    project = ProjectPresenter._with_pending(
        Project({"fringe": WorkbenchState(snapshot, {})}, {}), {"fringe": (3, 1, "7.25")})
    assert project.workbenches["fringe"].rows is snapshot
    assert snapshot.cell(3, 1) == "7.25" and rows.cell(3, 1) != "7.25"
    assert '"7.25"' in project_to_json(project)
    assert project.metadata["pending_edits"] == {"fringe": {"row": 4, "column": 2,
                                                            "text": "7.25",
                                                            "was": rows.cell(3, 1)}}
