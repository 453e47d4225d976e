"""A plot's right-click menu is built when it is first opened (widgets/lazy_menu_view_box.py):
a main window's 31 plots each built pyqtgraph's menu, two axis forms of ~20 widgets, when
the window was made (~0.1 s of a window's ~0.6 s), for a menu a user opens on a plot or two.
The menu a right-click opens is the one the window always showed: the image actions, in the
window's language, without pyqtgraph's English-only entries."""

from __future__ import annotations

import pyqtgraph as pg
import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QApplication, QMenu

pytestmark = pytest.mark.slow  # a window, shown


def _view_boxes(window) -> list[pg.ViewBox]:
    return [item for view in window.findChildren(pg.GraphicsView)
            for item in view.scene().items() if isinstance(item, pg.ViewBox)]


def _texts(menu: QMenu) -> list[str]:
    """Every entry of ``menu`` and of its submenus, by text."""
    found = []
    for action in menu.actions():
        found.append(action.text())
        if action.menu() is not None:
            found += [action.menu().title(), *_texts(action.menu())]
    return found


def test_no_plot_menu_is_built_with_the_window(window):
    boxes = _view_boxes(window)
    assert len(boxes) >= 25  # every workbench's plots
    assert [vb for vb in boxes if vb.menu is not None] == []


# (a menu popped up grabs the keyboard, which the offscreen platform cannot)
@pytest.mark.qt_log_ignore("This plugin does not support grabbing the keyboard")
def test_a_right_click_opens_the_plot_menu_with_its_image_actions(window, qtbot):
    window.resize(1280, 900)
    window.show()
    qtbot.waitExposed(window)
    plot = window.presenter("theodolite").view.error_plot
    graphics = plot.graphics
    qtbot.waitUntil(lambda: graphics.isVisible() and graphics.width() > 100)
    vb = plot.main_plot.getViewBox()
    where = graphics.mapFromScene(vb.sceneBoundingRect().center())
    qtbot.mouseClick(graphics.viewport(), Qt.MouseButton.RightButton, pos=where)
    qtbot.waitUntil(lambda: isinstance(QApplication.activePopupWidget(), QMenu))
    menu = QApplication.activePopupWidget()
    try:
        assert menu is vb.menu
        texts = _texts(menu)
        assert {"View All", "X axis", "Y axis", "Copy image", "Save image…"} <= set(texts)
        # pyqtgraph's English-only entries left out (its export dialog, its plot options)
        assert not {"Mouse Mode", "Plot Options", "Export..."} & set(texts), texts
        # the other plots' menus are still to be built
        assert [b for b in _view_boxes(window) if b.menu is not None] == [vb]
    finally:
        menu.close()
