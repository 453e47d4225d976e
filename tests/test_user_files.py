"""The app's files outside the project — settings in ~/.config/AngleBench, the register and
the autosaves in ~/.local/share/AngleBench — are never the user's own in a test (#31):
tests/conftest.py gives the suite a home of its own before Qt starts; a window made with
every default, edited, autosaved and closed, writes only there."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, QStandardPaths

from tests.conftest import TEST_HOME, USER_FILES_BEFORE, USER_HOME, _user_files_state


def _inside_test_home(path: str | Path) -> bool:
    return Path(path).resolve().is_relative_to(TEST_HOME.resolve())


def test_every_place_the_app_keeps_files_is_the_tests_own():
    from app.project_presenter import default_recovery_store
    from models.register.location import default_register_url

    assert _inside_test_home(Path.home()) and not _inside_test_home(USER_HOME)
    for location in (QStandardPaths.StandardLocation.AppDataLocation,
                     QStandardPaths.StandardLocation.AppConfigLocation,
                     QStandardPaths.StandardLocation.GenericConfigLocation,
                     QStandardPaths.StandardLocation.GenericDataLocation):
        assert _inside_test_home(QStandardPaths.writableLocation(location)), location
    assert _inside_test_home(QSettings("AngleBench", "AngleBench").fileName())
    # QSettings() (the column mappings remembered): each test's own folder (conftest)
    assert not Path(QSettings().fileName()).resolve().is_relative_to(USER_HOME.resolve())
    assert _inside_test_home(default_register_url().removeprefix("sqlite:///"))
    assert _inside_test_home(default_recovery_store().folder)


@pytest.mark.slow
def test_a_window_with_every_default_writes_only_in_the_tests_home(qtbot, monkeypatch):
    from app.main_window import MainWindow

    monkeypatch.delenv("ANGLEBENCH_REGISTER", raising=False)  # the default register too
    window = MainWindow()
    qtbot.addWidget(window)
    window.ask = lambda *a: None
    window.load_all_samples()
    theodolite = window.presenter("theodolite")
    theodolite.table_model.set_cells([(0, 1, "-19.9")], "typed")
    window.projects.autosave()
    window.show_register()  # opens (makes) the default register
    written = [p for p in TEST_HOME.rglob("*") if p.is_file()]
    assert any("AngleBench" in str(p) for p in written)
    for presenter in window.presenters:
        presenter.mark_saved()
    window.close()
    assert _user_files_state() == USER_FILES_BEFORE
