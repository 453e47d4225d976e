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
