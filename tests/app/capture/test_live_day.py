"""#41, the technician's day under X11 (1280×720, 200 %, en/zh, two simulated instruments):
what that review found, each pinned here on model state and widget geometry."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QApplication

from models.registry import KINDS

pytestmark = pytest.mark.slow  # a window each


def _settle() -> None:
    for _ in range(6):
        QApplication.processEvents()


def test_the_result_text_keeps_its_width_beside_the_docked_panel(window):
    """With the instrument panel docked at the right of a 1280×720 window, the result's
    text was 70–80 px wide on four workbenches ("24-face polygo n, 2 set(s)") and the
    plot lost its right half: the readings table's least width had ratcheted up to 663 px,
    counting its stretched last column as a column to keep in sight."""
    window.load_all_samples()
    window.resize(1280, 720)
    window.show()
    _settle()
    window.capture_panel.show()
    _settle()
    for key in KINDS:
        view = window.presenter(key).view
        window.tabs.setCurrentIndex(window.presenters.index(window.presenter(key)))
        _settle()
        table, header = view.table, view.table.horizontalHeader()
        natural = sum(header.sectionSize(i) for i in range(header.count() - 1)) + \
            header.sectionSizeHint(header.count() - 1)
        assert table.minimumWidth() <= natural + table.verticalHeader().width() + 60, key
        assert view.summary.width() >= 200, (key, view.summary.width())
        assert view.plot_tabs.width() >= 450, (key, view.plot_tabs.width())
        assert not table.horizontalScrollBar().isVisible(), key  # every column in sight
