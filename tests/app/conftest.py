"""Fixtures of the window tests under tests/app."""

from __future__ import annotations

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
