"""Main window: project save/open, damaged files, autosave and recovery, recent files."""

import json
import os

import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

from app.main_window import MainWindow
from models.project.recovery import RecoveryStore

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)


@pytest.fixture
def make_window(qtbot, tmp_path):
    def factory(answer=QMessageBox.StandardButton.Yes):
        settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
        window = MainWindow(settings=settings, recovery=RecoveryStore(tmp_path / "recovery"))
        window.told = []
        window.tell = lambda title, text: window.told.append(text)
        window.ask = lambda *a: answer
        qtbot.addWidget(window)
        made.append(window)
        return window

    made = []
    yield factory
    from PySide6.QtCore import QCoreApplication, QEvent

    for window in made:  # deleted: a closed window's shortcuts would meet the next test's
        window.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


def test_tabs_and_menus(_window_of_the_module):
    window = _window_of_the_module
    titles = [window.tabs.tabText(i) for i in range(window.tabs.count())]
    assert titles[0] == "Theodolite run"
    menus = [a.text() for a in window.menuBar().actions()]
    assert menus == ["&File", "&Edit", "&View", "&Instrument", "&Help"]


def test_save_and_reopen_round_trip(make_window, tmp_path, samples_dir):
    window = make_window()
    window.load_all_samples()
    bench = window.presenter("theodolite")
    bench.table_model.set_cells([(0, 1, "bad°")])
    bench.set_settings({"accuracy_arcsec": 0.7})
    assert window.projects.is_modified and window.windowTitle().endswith("*")
    path = tmp_path / "run.anglebench.json"
    assert window.projects.save_to(path)
    assert not window.projects.is_modified
    other = make_window()
    assert other.projects.open_project(path)
    reopened = other.presenter("theodolite")
    assert reopened.sheet.copy_rows() == bench.sheet.copy_rows()
    assert reopened.settings["accuracy_arcsec"] == 0.7
    assert other.projects.recent_files()[0] == str(path)


def test_damaged_or_newer_project_keeps_current_work(_window_of_the_module, tmp_path):
    """(The window of the module, its questions answered Discard; the workbench whose work
    is checked holds its sample.)"""
    window = _window_of_the_module
    window.presenter("theodolite").load_sample()
    before = window.presenter("theodolite").sheet.copy_rows()
    told = len(window.told)
    damaged = tmp_path / "damaged.json"
    damaged.write_text('{"format": "anglebench-project", "schema_version": 1, "workb')
    assert not window.projects.open_project(damaged)
    newer = tmp_path / "newer.json"
    newer.write_text(json.dumps({"format": "anglebench-project", "schema_version": 7}))
    assert not window.projects.open_project(newer)
    assert "damaged project file" in window.told[told] and "newer AngleBench" in window.told[told + 1]
    assert window.presenter("theodolite").sheet.copy_rows() == before


def crash(window) -> None:
    """The window's process dies: no closeEvent, the kernel drops its lock, the file stays."""
    os.close(window.projects.recovery._lock_fd)
    window.projects.recovery._lock_fd = None
    window.projects.autosave_timer.stop()


def test_autosave_and_recovery_after_a_crash(make_window, tmp_path):
    window = make_window()
    window.load_all_samples()
    assert window.projects.save_to(tmp_path / "run.anglebench.json")
    window.presenter("theodolite").table_model.set_cells([(0, 0, "-20.5")])
    window.projects.autosave()
    assert window.projects.recovery.exists()
    crash(window)
    survivor = make_window(answer=QMessageBox.StandardButton.Yes)
    asked = []
    survivor.ask = lambda title, text, *a: asked.append(text) or QMessageBox.StandardButton.Yes
    assert survivor.projects.offer_recovery()
    assert "run.anglebench.json" in asked[0] and "autosaved 20" in asked[0]
    assert survivor.presenter("theodolite").sheet.text(0, 0) == "-20.5"
    assert survivor.projects.is_modified
    assert survivor.projects.path == tmp_path / "run.anglebench.json"  # Ctrl+S saves it there
    assert survivor.windowTitle().endswith("run.anglebench.json *")


def test_an_edit_is_autosaved_within_seconds(make_window, qtbot):
    window = make_window()
    window.presenter("theodolite").table_model.set_cells([(0, 0, "1")])
    qtbot.waitUntil(window.projects.recovery.exists, timeout=6000)


def test_two_windows_never_take_each_others_work(make_window):
    a = make_window()
    a.presenter("theodolite").table_model.set_cells([(0, 0, "111")])
    a.projects.autosave()
    b = make_window()
    assert not b.projects.offer_recovery()  # A is alive: its autosave is not a crash
    b.presenter("theodolite").table_model.set_cells([(0, 0, "222")])
    b.projects.autosave()
    assert a.projects.recovery.path != b.projects.recovery.path
    b.ask = lambda *args: QMessageBox.StandardButton.Discard
    b.close()
    assert a.projects.recovery.exists() and not b.projects.recovery.exists()
    crash(a)
    c = make_window(answer=QMessageBox.StandardButton.Yes)
    assert c.projects.offer_recovery()
    assert c.presenter("theodolite").sheet.text(0, 0) == "111"


def test_damaged_autosaves_are_kept_aside_each_under_its_own_name(make_window, tmp_path):
    folder = tmp_path / "recovery"
    folder.mkdir(exist_ok=True)
    for i in range(2):
        (folder / f"recovery-dead{i}.anglebench.json").write_text("{damaged")
        window = make_window()
        assert not window.projects.offer_recovery()
        assert "kept aside" in window.told[0]
    assert len(list(folder.glob("*.damaged-*.json"))) == 2


def test_stale_temp_files_of_killed_saves_are_swept(make_window, tmp_path):
    folder = tmp_path / "recovery"
    folder.mkdir(exist_ok=True)
    stale = folder / ".recovery-x.anglebench.json.abc.tmp"
    stale.write_bytes(b"x" * 100)
    os.utime(stale, (1, 1))
    fresh = folder / ".recovery-y.anglebench.json.def.tmp"
    fresh.write_bytes(b"y")
    make_window()
    assert not stale.exists() and fresh.exists()


@pytest.fixture(scope="module")
def _all_samples_project(qapp, tmp_path_factory):
    """A good project (every workbench holding its sample) as the window saves it: made once
    for the damaged-project cases below, which each damage their own copy (a window and five
    analyses each took ~1 s of CPU per case)."""
    from PySide6.QtCore import QCoreApplication, QEvent

    folder = tmp_path_factory.mktemp("all_samples_project")
    source = MainWindow(settings=QSettings(str(folder / "settings.ini"),
                                           QSettings.Format.IniFormat),
                        recovery=RecoveryStore(folder / "recovery"))
    source.tell = source.ask = lambda *a: pytest.fail(f"the source window asked: {a}")
    try:
        source.load_all_samples()
        path = folder / "good.anglebench.json"
        assert source.projects.save_to(path)
        return path.read_text()
    finally:
        source.deleteLater()
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


@pytest.fixture(scope="module")
def _window_of_the_module(qapp, tmp_path_factory):
    """One window for the cases that only read it (its tabs and menus) and for those that
    check that opening a damaged or newer project changes nothing (each against the window
    as it found it, so each finds it as the last left it): a window each took ~0.4 s of
    CPU. What it would tell is kept in ``told``, its questions answered Discard (as
    ``make_window(Discard)``)."""
    from tests.conftest import answered_window, delete_window

    window = answered_window(tmp_path_factory.mktemp("window_of_the_module"))
    yield window
    window.projects.autosave_timer.stop()
    window.close()
    delete_window(window)


@pytest.mark.parametrize("change", [
    lambda d: d["workbenches"]["polygon"]["settings"].update(faces="x"),
    lambda d: d["workbenches"]["fringe"]["settings"].update(lut_size=100_000_000),
    lambda d: d.update(metadata=["a", "list"]),
    lambda d: d.update(metadata={"certificates": {"polygon": "x"}}),
    lambda d: d["workbenches"].update(mystery={"rows": [], "settings": {}}),
    lambda d: d["workbenches"]["theodolite"].update(rows=[["1", "2", "3", "4", "5", "6", "7", "8"]]),
])
def test_opening_a_damaged_project_changes_nothing(_window_of_the_module, tmp_path,
                                                  change, _all_samples_project):
    document = json.loads(_all_samples_project)
    change(document)
    bad = tmp_path / "bad.anglebench.json"
    bad.write_text(json.dumps(document))
    window = _window_of_the_module
    theodolite = window.presenter("theodolite")
    theodolite.table_model.set_cells([(0, 0, "7"), (1, 0, "8")])
    rows, title = theodolite.sheet.copy_rows(), window.windowTitle()
    undo = theodolite.undo_stack.count()
    assert not window.projects.open_project(bad)
    assert "nothing was changed" in window.told[-1]
    assert theodolite.sheet.copy_rows() == rows and window.windowTitle() == title
    assert theodolite.undo_stack.count() == undo and window.projects.path is None


def test_clean_close_removes_recovery_file(make_window):
    window = make_window(answer=QMessageBox.StandardButton.Discard)
    window.presenter("theodolite").table_model.set_cells([(0, 0, "1")])
    window.projects.autosave()
    assert window.projects.recovery.exists()
    window.close()
    assert not window.projects.recovery.exists()


def test_close_can_be_cancelled(make_window):
    window = make_window(answer=QMessageBox.StandardButton.Cancel)
    window.show()
    window.presenter("theodolite").table_model.set_cells([(0, 0, "1")])
    assert not window.close()
    assert window.isVisible()


def test_import_bad_file_reports_and_keeps_readings(make_window, tmp_path):
    window = make_window()
    window.presenter("theodolite").load_sample()  # the workbench whose readings are checked
    before = window.presenter("theodolite").sheet.copy_rows()
    bad = tmp_path / "bad.csv"
    bad.write_text("foo,bar\n1,2\n")
    assert not window.import_file(bad, "theodolite")
    assert "no column 'theta_deg'" in window.told[0]
    assert window.presenter("theodolite").sheet.copy_rows() == before


def test_import_is_undoable(make_window, tmp_path):
    window = make_window()
    window.presenter("theodolite").load_sample()  # the workbench whose readings are checked
    bench = window.presenter("theodolite")
    before = bench.sheet.copy_rows()
    good = tmp_path / "good.csv"
    good.write_text("theta_deg,azimuth_deg,elevation_deg\n0,0,0\n1,1,0\n2,2,0\n3,3,0\n")
    assert window.import_file(good, "theodolite")
    assert bench.sheet.row_count == 4
    window.menus.undo_action.trigger()
    assert bench.sheet.copy_rows() == before


def test_load_sample_menu_is_one_undo_step(make_window):
    window = make_window()
    bench = window.presenter("theodolite")
    bench.table_model.set_cells([(0, 0, "5")])
    window.menus.sample_action.trigger()
    assert bench.sheet.row_count == 41
    window.menus.undo_action.trigger()
    assert bench.sheet.text(0, 0) == "5" and bench.sheet.row_count == 1


def test_a_sheet_grown_large_waits_the_large_autosave_delay(make_window, monkeypatch):
    """The timer started on a small edit (a setting) and a million rows arrived before it
    ran out: it does not write them then, beside the user's first edits, but waits the
    large sheets' delay from the same first edit; then it writes."""
    import app.project_presenter as project_presenter

    window = make_window()
    fringe = window.presenter("fringe")
    fringe.set_settings({**fringe.settings, "samples_per_period": 64})
    assert window.projects.autosave_timer.isActive()
    assert window.projects.autosave_timer.interval() == project_presenter.AUTOSAVE_DELAY_MS
    written = []
    monkeypatch.setattr(window.projects, "autosave", lambda: written.append(True))
    monkeypatch.setattr(project_presenter, "AUTOSAVE_THREAD_ROWS", -1)  # every sheet counts as large
    window.projects._autosave_when_due()  # the short delay ran out
    assert written == [] and window.projects.autosave_timer.isActive()
    left_ms = window.projects.autosave_timer.interval()
    large_ms = project_presenter.AUTOSAVE_DELAY_LARGE_MS
    assert large_ms - 500 < left_ms <= large_ms
    window.projects._unsaved_since -= large_ms / 1000.0  # its time came
    window.projects._autosave_when_due()
    assert written == [True]
    window.projects.autosave_timer.stop()
