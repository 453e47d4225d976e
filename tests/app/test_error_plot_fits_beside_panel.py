"""The polygon's error plot at 1280×720 beside the docked instrument panel, in Chinese and
in English: its area never scrolls sideways (day review 64 P5: the crosshair's readout of
three curves, on one line, held the plot ~740 px wide in a ~470 px area; the area scrolled
sideways, the legend "修正值 −(ε…" was cut at its right edge and the curves past ~200° were
out of sight until scrolled)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, Qt
from PySide6.QtWidgets import QApplication

from tests.app.test_status_line_language import choose_language


@pytest.mark.parametrize("language", ["zh_CN", "en"])
def test_the_error_plot_fits_its_area_with_the_readout_shown(window, qtbot, language):
    window.resize(1280, 720)
    window.show()
    qtbot.waitExposed(window)
    panel = window.capture_panel
    window.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, panel)
    bench = window.presenter("polygon")
    window.tabs.setCurrentIndex(window.presenters.index(bench))
    panel.show()  # opened on this workbench (0.8.14: open only where it was used)
    bench.load_sample()
    qtbot.waitUntil(lambda: bench.result is not None and not bench.analysis_pending,
                    timeout=10000)
    try:
        choose_language(window, language)
        for _ in range(5):
            QApplication.processEvents()
        plot = bench.view.error_plot
        area = bench.view.plot_tabs.currentWidget()
        assert area.widget() is plot
        # the mouse over the raw error's plot, a third of the way along: the readout says
        # each curve's value there
        view = plot.graphics
        inside = view.mapFromScene(plot.main_plot.sceneBoundingRect().center()).x()
        spot = QPoint(inside // 2 + 10, view.mapFromScene(
            plot.main_plot.sceneBoundingRect().center()).y())
        qtbot.mouseMove(view.viewport(), spot)
        qtbot.waitUntil(lambda: "@" in plot.readout.text(), timeout=3000)
        assert plot.readout.text().count("@") == 3, plot.readout.text()
        for _ in range(5):
            QApplication.processEvents()
        room = area.viewport().width()
        assert room < 560  # beside the docked panel at 1280 px: the cramped case
        assert plot.minimumSizeHint().width() <= room, (plot.minimumSizeHint().width(), room)
        assert plot.width() <= room
        assert area.horizontalScrollBar().maximum() == 0
    finally:
        choose_language(window, "en")
