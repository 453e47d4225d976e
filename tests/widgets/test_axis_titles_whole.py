"""A plot tab of one plot keeps its y axis' title whole however little room the tab has:
the tab scrolls down instead (widgets/plot_grid.keep_axis_title_room, through
WorkbenchView.add_plot_tab).

Day review 65: at 200 % on a 1280×720 screen beside the docked instrument panel the
polygon's "Vertical readings / tilt" plot had 62 px of y axis for its title "AC vertical −
zero (\\")" (131 px; 160 px in Chinese), the fringe's "Signal quality" 60 px for "Phase B −
A − 90° (°)" (136 px): each panel kept only its 150 px floor, and a title longer than its
axis is drawn centred on it and cut at both ends. Here the same room is made as a user
makes it at 1280×720: the result pane dragged down over the plot tabs."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QRectF

from tests.app.test_status_line_language import choose_language

pytestmark = pytest.mark.slow  # a window

# Each case loads the sample of the workbench it looks at only: with every sample loaded (the
# other four analysed, and translated again at the change of language: ~0.5 s of CPU more a
# case) the window, the splitter, the tab's viewport, the plot, its y axis and the scroll
# range were the same, pixel for pixel, in English and in Chinese (compared 2026-12-07)


def _title_length(axis) -> float:
    label = axis.label
    return label.boundingRect().width() - 2 * label.document().documentMargin()


@pytest.mark.parametrize("language", ["en", "zh_CN"])
@pytest.mark.parametrize("key,tab,plot_of", [
    ("polygon", "tilt", lambda view: view.tilt_plot.plot),
    ("fringe", "signal quality", lambda view: view.signal_quality.findChild(
        __import__("pyqtgraph").PlotWidget)),
])
def test_a_cramped_plot_tab_scrolls_and_keeps_its_y_title_whole(window, qtbot, key, tab,
                                                                 plot_of, language):
    window.presenter(key).load_sample()  # the workbench looked at (above)
    window.resize(1280, 720)
    window.show()
    window.capture_panel.show()
    qtbot.waitExposed(window)
    index, bench = next((i, p) for i, p in enumerate(window.presenters) if p.kind.key == key)
    window.tabs.setCurrentIndex(index)
    view = bench.view
    plot = plot_of(view)
    at = next(i for i in range(view.plot_tabs.count()) if view.plot_widget(i).isAncestorOf(plot))
    view.plot_tabs.tabBar().setCurrentIndex(at)
    try:
        choose_language(window, language)
        # the result pane dragged down: the plot tabs keep ~130 px
        total = sum(view.result_splitter.sizes())
        view.result_splitter.setSizes([total - 130, 130])
        qtbot.wait(300)
        area = view.plot_tabs.widget(at)
        assert area.viewport().height() < 150, area.viewport().height()  # cramped
        axis = plot.getPlotItem().getAxis("left")
        title = _title_length(axis)
        assert title > 50, axis.labelText
        for _ in range(30):  # the panel's least height follows its plot's layout
            if axis.geometry().height() >= title:
                break
            qtbot.wait(100)
        # was: 150 px of panel, ~60 px of axis for a title of 130 px or more
        assert axis.geometry().height() >= title, (axis.labelText, title,
                                                   axis.geometry().height())
        margin = axis.label.document().documentMargin()
        drawn = axis.label.sceneBoundingRect().adjusted(margin, margin, -margin, -margin)
        assert QRectF(0, 0, plot.width(), plot.height()).contains(drawn)
        assert area.verticalScrollBar().maximum() > 0  # the tab scrolls down instead
        assert area.horizontalScrollBar().maximum() == 0
    finally:
        choose_language(window, "en")
