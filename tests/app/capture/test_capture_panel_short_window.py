"""gui81: the live bench day on a 1280×720 screen at 150 % (853×480 logical px) with the
capture panel docked at the bottom. There the panel made the window at least ~557 px tall
(past the screen: the panel and the plots' lower half off it), the readings table kept 1–4
rows in sight and the guidance ("下一步：转到第 4 面") was drawn in a 105 px column, a
character or two a line. A window lower than the panel at the bottom needs has it at the
right, and while the panel is open the readings keep 6 rows, the set-up giving way."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QApplication

from tests.app.capture.window_steps import show_workbench as _show

pytestmark = pytest.mark.slow  # a window shown and docked

#: 1280×720 at 150 %, in logical pixels
SCREEN = (853, 480)


def _settle() -> None:
    for _ in range(10):
        QApplication.processEvents()


def _rows_in_sight(table) -> int:
    """The rows wholly in the table's viewport."""
    height = table.viewport().height()
    first = table.rowAt(0)
    if first < 0:
        return 0
    return sum(1 for row in range(first, table.model().rowCount())
               if table.rowViewportPosition(row) >= 0
               and table.rowViewportPosition(row) + table.rowHeight(row) <= height)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_readings_keep_six_rows_beside_the_panel_at_150_percent(window, language):
    window.set_language(language)
    try:
        presenter = _show(window, "polygon")
        presenter.load_sample()  # more rows than the window shows
        presenter.set_settings({**presenter.settings, "faces": 24})
        window.resize(*SCREEN)
        window.show()
        _settle()
        panel = window.capture_panel
        window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, panel)
        panel.show()
        panel.update_guide()
        _settle()
        guide = panel.guide
        assert guide.text()
        # the window stays on the screen (it was made 557 px tall by the panel's least height)
        assert window.height() <= SCREEN[1], window.height()
        table = presenter.view.table
        assert table.mapTo(window, QPoint(0, table.height())).y() <= window.height()
        assert _rows_in_sight(table) >= 6, (table.viewport().height(), table.rowHeight(0))
        # the guidance whole: as tall as its lines, at most two (not a character or two a
        # line), inside the panel and the window
        assert guide.isVisible()
        lines = guide.heightForWidth(guide.width()) / guide.fontMetrics().lineSpacing()
        assert lines < 3, (guide.width(), guide.text())
        assert guide.height() >= guide.heightForWidth(guide.width())
        bottom = guide.mapTo(window, QPoint(0, guide.height())).y()
        assert bottom <= panel.mapTo(window, QPoint(0, panel.height())).y()
        assert bottom <= window.height()
    finally:
        window.set_language("en")


def test_a_window_of_1280x720_at_100_percent_keeps_the_panel_at_the_bottom(window):
    presenter = _show(window, "polygon")
    presenter.load_sample()
    window.resize(1254, 662)  # as fit_to_screen makes it on that screen
    window.show()
    _settle()
    panel = window.capture_panel
    window.addDockWidget(Qt.DockWidgetArea.BottomDockWidgetArea, panel)
    panel.show()
    _settle()
    assert window.dockWidgetArea(panel) == Qt.DockWidgetArea.BottomDockWidgetArea
    assert window.height() == 662
    assert _rows_in_sight(presenter.view.table) >= 6
