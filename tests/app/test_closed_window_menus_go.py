"""A main window deleted takes its plots' right-click menus with it (pyqtgraph's menus are
windows of their own, held by a reference cycle): they stayed alive, and the language went
on setting their ~580 texts again at every change of language, for every window made since
the program started (a test session's late language tests took minutes), until Python's
cyclic collector ran."""

from __future__ import annotations

import pyqtgraph as pg
import shiboken6
from PySide6.QtCore import QCoreApplication, QEvent, QSettings

from app.main_window import MainWindow
from models.project.recovery import RecoveryStore
from widgets.i18n import application_language


def _alive_texts() -> int:
    return sum(1 for ref, *_ in application_language()._live
               if ref() is not None and shiboken6.isValid(ref()))


def test_a_deleted_window_leaves_no_plot_menu_and_no_text_to_set_again(qtbot, tmp_path):
    before = _alive_texts()
    window = MainWindow(settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat),
                        recovery=RecoveryStore(tmp_path / "recovery"))
    # every plot's menu opened, as a right-click opens it (a plot's menu is built then)
    menus = [item.getMenu(None) for view in window.findChildren(pg.GraphicsView)
             for item in view.scene().items()
             if isinstance(item, pg.ViewBox) and item.getMenu(None) is not None]
    assert len(menus) >= 10 and _alive_texts() > before + 200
    window.deleteLater()
    for _ in range(2):  # the window, then what its deletion posted
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    assert [m for m in menus if shiboken6.isValid(m)] == []
    assert _alive_texts() == before
