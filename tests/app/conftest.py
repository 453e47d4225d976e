"""Fixtures of the window tests under tests/app."""

from __future__ import annotations

import os

import pytest
from PySide6.QtCore import QCoreApplication, QEvent, QSettings
from PySide6.QtWidgets import QMessageBox


@pytest.fixture
def recovering_window(qtbot, tmp_path):
    """``recovering_window(tag="settings", recovery="recovery")``: a main window with settings
    of its own (``tag``.ini) and an autosave folder (``recovery``: windows made with the same
    folder recover each other's work, and always agree to); its messages kept in ``told``,
    its questions answered Discard. Every window made is closed and deleted after the test."""
    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    made = []

    def factory(tag: str = "settings", recovery: str = "recovery"):
        settings = QSettings(str(tmp_path / f"{tag}.ini"), QSettings.Format.IniFormat)
        window = MainWindow(settings=settings, recovery=RecoveryStore(tmp_path / recovery))
        window.told = []
        window.tell = lambda title, text: window.told.append(text)
        window.ask = lambda *a: QMessageBox.StandardButton.Discard
        window.projects.view.ask_recover = lambda name, when: True
        qtbot.addWidget(window)
        made.append(window)
        return window

    yield factory
    for window in made:
        window.projects.autosave_timer.stop()
        window.capture_panel.close()
        window.deleteLater()
    QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)


@pytest.fixture
def lab_key(tmp_path, monkeypatch) -> str:
    """The laboratory's key (ANGLEBENCH_REGISTER_KEY), a file of the test's own."""
    path = tmp_path / "keys" / "lab.key"
    path.parent.mkdir()
    path.write_bytes(os.urandom(32))
    monkeypatch.setenv("ANGLEBENCH_REGISTER_KEY", str(path))
    return str(path)


@pytest.fixture
def told(monkeypatch) -> list[tuple[str, str]]:
    """What the register window tells (its message boxes), kept instead of shown."""
    said: list[tuple[str, str]] = []
    from widgets.register_window import RegisterWindow

    monkeypatch.setattr(RegisterWindow, "tell", lambda _self, title, text: said.append(
        (title, text)))
    return said


@pytest.fixture
def pdf_stand_in(monkeypatch):
    """A certificate's PDF a stand-in wherever the window and the command line print one
    (tests/pdf_stand_in.py): for a test that never reads a PDF's pages."""
    from tests.pdf_stand_in import print_stand_ins

    print_stand_ins(monkeypatch)
