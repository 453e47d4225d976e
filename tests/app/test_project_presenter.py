"""The project presenter with an autospec'd mock view and workbench presenters on mock
views: no window, no dialog (Mantid workbench's MVP tests are the model). Save, open,
the question about unsaved work, recent files, dropped files, autosave and the offer of
a crashed window's work."""

from __future__ import annotations

import os
from unittest import mock

import pytest
import shiboken6
from PySide6.QtWidgets import QWidget

from app import project_presenter
from app.project_presenter import ProjectPresenter, ProjectView
from models.project.file import project_to_json
from models.project.recovery import RecoveryStore
from models.readings.tabular_import import map_columns, read_table
from widgets.positioning.presenter import PositioningPresenter
from widgets.positioning.view import PositioningView
from widgets.theodolite.presenter import TheodolitePresenter
from widgets.theodolite.view import TheodoliteView

_OWNERS: list[QWidget] = []


@pytest.fixture(autouse=True)
def _delete_presenters_at_teardown():
    """The presenters are owned by a widget deleted here, at once (see test_presenters.py)."""
    yield
    while _OWNERS:
        shiboken6.delete(_OWNERS.pop())


class Store(dict):
    def value(self, key, default=None):
        return self.get(key, default)

    def setValue(self, key, value):  # noqa: N802 - QSettings' name
        self[key] = value


def make(qtbot, tmp_path, store=None, current=0):
    """A project presenter on a mock view, holding theodolite and positioning workbenches
    (each on a mock view), with an autosave folder of the test's own; ``current`` is the
    index of the workbench in front."""
    owner = QWidget()
    _OWNERS.append(owner)
    workbenches = []
    for presenter_class, view_class in ((TheodolitePresenter, TheodoliteView),
                                        (PositioningPresenter, PositioningView)):
        view = mock.create_autospec(view_class, instance=True)
        view.settings_values.return_value = {}
        workbenches.append(presenter_class(view, parent=owner))
    view = mock.create_autospec(ProjectView, instance=True)
    presenter = ProjectPresenter(view, workbenches, RecoveryStore(tmp_path / "recovery"),
                                 Store() if store is None else store,
                                 lambda: workbenches[current], owner)
    presenter.start()
    return presenter, view, workbenches


def load_sample(workbench, samples_dir) -> None:
    rows = map_columns(read_table(samples_dir / workbench.kind.sample_file), workbench.kind.columns)
    workbench.table_model.replace_all(rows)


def test_save_and_open_round_trip_with_title_and_recent_files(qtbot, tmp_path, samples_dir):
    presenter, view, (theodolite, _) = make(qtbot, tmp_path)
    assert view.show_title.call_args.args[0].endswith("— untitled")
    view.show_recent.assert_called_once_with([])
    load_sample(theodolite, samples_dir)
    theodolite.set_settings({**theodolite.settings, "accuracy_arcsec": 0.7})
    assert presenter.is_modified and view.show_title.call_args.args[0].endswith("untitled *")
    path = tmp_path / "run.anglebench.json"
    assert presenter.save_to(path)
    assert not presenter.is_modified and presenter.path == path
    assert view.show_title.call_args.args[0].endswith("— run.anglebench.json")
    assert view.show_status.call_args.args == (f"Saved {path}", 5000)
    view.show_recent.assert_called_with([str(path)])
    other, other_view, (reopened, _) = make(qtbot, tmp_path, store=presenter.store)
    assert other.open_project(path)
    assert reopened.sheet.copy_rows() == theodolite.sheet.copy_rows()
    assert reopened.settings["accuracy_arcsec"] == 0.7
    assert other.recent_files() == [str(path)] and other.last_dir() == str(tmp_path)
    other_view.ask_save_changes.assert_not_called()  # nothing was unsaved
    other_view.tell.assert_not_called()


@pytest.mark.slow
def test_unsaved_work_is_saved_kept_or_let_go_as_answered(qtbot, tmp_path, samples_dir):
    presenter, view, (theodolite, _) = make(qtbot, tmp_path)
    load_sample(theodolite, samples_dir)
    rows = theodolite.sheet.copy_rows()
    view.ask_save_changes.return_value = None  # cancel: the work stays as it is
    presenter.new_project()
    assert theodolite.sheet.copy_rows() == rows and presenter.is_modified
    view.ask_save_changes.return_value = True  # save first: asked for a name …
    view.ask_save_path.return_value = ""  # … and cancelled: nothing is lost
    assert not presenter.confirm_discard()
    assert theodolite.sheet.copy_rows() == rows
    view.ask_save_path.return_value = str(tmp_path / "kept")  # the suffix is added
    assert presenter.confirm_discard()
    assert (tmp_path / "kept.anglebench.json").is_file() and not presenter.is_modified
    assert presenter.last_dir() == str(tmp_path)  # the next file dialog opens there
    theodolite.table_model.set_cells([(0, 1, "1")])
    view.ask_save_changes.return_value = False  # discard: a new, empty project
    presenter.new_project()
    assert theodolite.sheet.copy_rows() == [] and presenter.path is None
    assert not presenter.is_modified


def test_a_damaged_file_or_an_unwritable_folder_is_told_and_the_work_stays(qtbot, tmp_path,
                                                                           samples_dir):
    presenter, view, (theodolite, _) = make(qtbot, tmp_path)
    load_sample(theodolite, samples_dir)
    rows = theodolite.sheet.copy_rows()
    damaged = tmp_path / "damaged.anglebench.json"
    damaged.write_text("{ not json")
    view.ask_save_changes.return_value = False
    assert not presenter.open_project(damaged)
    title, text = view.tell.call_args.args
    assert title == "Cannot open project" and text.endswith("Your current work is as it was.")
    assert theodolite.sheet.copy_rows() == rows and presenter.path is None
    assert not presenter.save_to(tmp_path / "no" / "such" / "dir" / "p.anglebench.json")
    title, text = view.tell.call_args.args
    assert title == "Cannot save" and text.endswith("Your readings are still here.")
    assert presenter.is_modified and presenter.recent_files() == []


def test_a_dropped_readings_file_is_imported_a_project_opened(qtbot, tmp_path, samples_dir):
    presenter, view, (theodolite, positioning) = make(qtbot, tmp_path, current=1)
    assert presenter.droppable(["/a/run.CSV", "/a/notes.pdf", "/a/p.anglebench.json",
                                "/a/log.xlsx"]) == ["/a/run.CSV", "/a/p.anglebench.json",
                                                    "/a/log.xlsx"]
    with mock.patch.object(positioning, "start_import") as start_import, \
            mock.patch.object(theodolite, "start_import") as not_in_front:
        presenter.drop(str(samples_dir / "positioning_sample.csv"))
    start_import.assert_called_once_with(str(samples_dir / "positioning_sample.csv"))
    not_in_front.assert_not_called()
    load_sample(theodolite, samples_dir)
    path = tmp_path / "p.anglebench.json"
    assert presenter.save_to(path)
    theodolite.table_model.replace_all([])
    view.ask_save_changes.return_value = False
    presenter.drop(str(path))
    assert theodolite.sheet.row_count == 41 and presenter.path == path


@pytest.mark.slow
def test_the_project_behind_a_certificate_opens_untitled_at_its_workbench(qtbot, tmp_path,
                                                                          samples_dir):
    source, _, (theodolite, _) = make(qtbot, tmp_path)
    load_sample(theodolite, samples_dir)
    project_json = project_to_json(source.project())
    presenter, view, (opened, _) = make(qtbot, tmp_path)
    presenter.path = tmp_path / "earlier.anglebench.json"
    assert presenter.open_project_state(project_json, "theodolite")
    view.show_workbench.assert_called_once_with("theodolite")
    assert opened.sheet.copy_rows() == theodolite.sheet.copy_rows() and presenter.path is None
    assert not presenter.open_project_state("{ damaged", "theodolite")
    assert view.tell.call_args.args[0] == "Cannot open"


@pytest.mark.slow
def test_an_edit_is_autosaved_and_offered_back_after_a_crash(qtbot, tmp_path, samples_dir):
    crashed, _, (theodolite, _) = make(qtbot, tmp_path)
    load_sample(theodolite, samples_dir)
    assert crashed.save_to(tmp_path / "run.anglebench.json")
    theodolite.table_model.set_cells([(0, 1, "12.5")])
    assert crashed.autosave_timer.isActive()
    assert crashed.autosave_timer.interval() == project_presenter.AUTOSAVE_DELAY_MS
    qtbot.waitUntil(crashed.recovery.exists, timeout=6000)  # the timer wrote it
    os.close(crashed.recovery._lock_fd)  # the process is killed: its lock goes, its file stays
    crashed.recovery._lock_fd = None
    crashed.autosave_timer.stop()
    declining, view, _ = make(qtbot, tmp_path)
    view.ask_recover.return_value = False
    assert not declining.offer_recovery()
    assert view.ask_recover.call_args.args[0] == "run.anglebench.json"
    assert "kept aside" in view.show_status.call_args.args[0]
    assert not declining.offer_recovery()  # kept aside: not offered again
    declining.close()


@pytest.mark.slow
def test_recovered_work_is_unsaved_work_of_the_same_file(qtbot, tmp_path, samples_dir):
    crashed, _, (theodolite, _) = make(qtbot, tmp_path)
    load_sample(theodolite, samples_dir)
    assert crashed.save_to(tmp_path / "run.anglebench.json")
    theodolite.table_model.set_cells([(0, 1, "12.5")])
    crashed.autosave()
    os.close(crashed.recovery._lock_fd)
    crashed.recovery._lock_fd = None
    crashed.autosave_timer.stop()
    survivor, view, (recovered, _) = make(qtbot, tmp_path)
    view.ask_recover.return_value = True
    assert survivor.offer_recovery()
    assert recovered.sheet.copy_rows() == theodolite.sheet.copy_rows()
    assert survivor.is_modified and survivor.path == tmp_path / "run.anglebench.json"
    assert survivor.recovery.exists()  # now the survivor's own autosave
    assert view.show_title.call_args.args[0].endswith("— run.anglebench.json *")
    survivor.close()
    assert not survivor.recovery.exists()


def test_a_damaged_file_is_told_in_the_windows_language(qtbot, tmp_path, samples_dir):
    """In a Chinese window the reason a project cannot be opened is Chinese too (until 0.8.22
    the ProjectFileError's English text was put into the Chinese sentence)."""
    from widgets.i18n import install_language

    presenter, view, (theodolite, _) = make(qtbot, tmp_path)
    damaged = tmp_path / "damaged.anglebench.json"
    damaged.write_text("{ not json")
    view.ask_save_changes.return_value = False
    install_language("zh_CN")
    try:
        assert not presenter.open_project(damaged)
    finally:
        install_language("en")
    _, text = view.tell.call_args.args
    assert "damaged project file" not in text and "damaged.anglebench.json" in text, text
