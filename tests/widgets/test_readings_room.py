"""The readings table has room to type into on a laptop screen (#31: at 1280×720 the
positioning table showed ~3 rows, fringe 6, polygon 7 with its last column behind a
horizontal scroll bar; the set-up form below it took the height)."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QApplication

from models.registry import KINDS

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)


def _rows_visible(table) -> float:
    """Rows the table's viewport shows whole."""
    return table.viewport().height() / table.verticalHeader().defaultSectionSize()


@pytest.mark.parametrize("size", [(1280, 720), (1280, 800)], ids=lambda s: f"{s[0]}x{s[1]}")
def test_the_readings_table_shows_ten_rows_on_a_laptop(window, size):
    window.load_all_samples()
    window.resize(*size)
    window.show()
    for key in KINDS:
        presenter = window.presenter(key)
        window.tabs.setCurrentIndex(window.presenters.index(presenter))
        for _ in range(3):
            QApplication.processEvents()
        view = presenter.view
        table = view.table
        rows = _rows_visible(table)
        assert rows >= 10, (key, rows)
        assert not table.horizontalScrollBar().isVisible(), key  # every column in sight
        area = view.settings_area  # the set-up scrolls to every field
        assert area.widget().height() <= area.viewport().height() + area.verticalScrollBar().maximum()
        assert view.plot_tabs.currentWidget().height() >= view.PANEL_MIN_HEIGHT


def test_the_readings_pane_gives_way_where_the_window_is_narrow(window):
    """The readings pane is as wide as its columns where the result keeps 340 px beside it;
    narrower (200 % on a 1280×720 screen: 627 px of window), the table scrolls sideways and
    the window is no wider (its least width was every column: 876 px for the polygon). A line
    dragged by the technician is left where it is until the window is resized."""
    from PySide6.QtCore import Qt
    from PySide6.QtWidgets import QSplitter

    window.load_all_samples()
    window.tabs.setCurrentIndex(window.presenters.index(window.presenter("polygon")))
    view = window.presenter("polygon").view
    splitter = next(s for s in view.findChildren(QSplitter)
                    if s.orientation() == Qt.Orientation.Horizontal)
    window.resize(1280, 720)
    window.show()
    QApplication.processEvents()
    sideways = view.table.horizontalScrollBar()
    assert not sideways.isVisible()  # every column in sight
    splitter.moveSplitter(300, 1)  # dragged: more room for the result
    QApplication.processEvents()
    assert splitter.sizes()[0] < 400 and sideways.isVisible()  # (held at 524 px before)
    window.resize(627, 331)
    QApplication.processEvents()
    assert window.width() == 627
    assert splitter.sizes()[1] >= 340 and sideways.isVisible()
    window.resize(1280, 720)
    QApplication.processEvents()
    assert not sideways.isVisible()  # the columns in sight again
