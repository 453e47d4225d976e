"""The What-if tab fits its tab with the instrument panel docked at 1280×720 (the polygon's
needed a horizontal scroll bar: its set-up choice held the form at 486 px of the tab's
494), and stacks its form above the plots where they have no room beside it."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QComboBox, QScrollArea

from widgets.family_simulation import FamilySimulation

pytestmark = pytest.mark.slow  # a window

# Each test loads the sample of the workbench it looks at only: with every sample loaded
# (the other four analysed, and translated again at a change of language: ~0.5 s of CPU more
# a test) the window, the tab, the form and the plots' and axes' sizes were the same, pixel
# for pixel, at 1280×720 in English and in Chinese (compared 2026-12-07)


def _what_if(window, key: str) -> tuple[QScrollArea, FamilySimulation]:
    """The workbench ``key``'s What-if tab, chosen as a user does (its two tabs clicked)."""
    index, presenter = next((i, p) for i, p in enumerate(window.presenters) if p.kind.key == key)
    window.tabs.setCurrentIndex(index)
    tabs = presenter.view.plot_tabs
    at = next(i for i in range(tabs.count()) if tabs.widget(i).findChild(FamilySimulation)
              or isinstance(tabs.widget(i).widget(), FamilySimulation))
    tabs.tabBar().setCurrentIndex(at)
    scroll = tabs.widget(at)
    return scroll, scroll.widget()


@pytest.mark.parametrize("key", ["polygon", "theodolite"])
def test_the_what_if_tab_fits_beside_the_docked_panel(window, qtbot, key):
    window.presenter(key).load_sample()  # the workbench looked at (above)
    window.resize(1280, 720)
    window.show()
    qtbot.waitExposed(window)
    scroll, what_if = _what_if(window, key)
    # Instrument › Connect… on this workbench docks it, at the right by default (0.8.14: the
    # panel is open only on the workbenches where it was used)
    window.capture_panel.show()
    qtbot.waitUntil(lambda: what_if.isVisible() and what_if.width() > 0)
    qtbot.wait(100)  # its layout settled (a resize may turn it from beside to above)
    room = scroll.viewport().width()
    assert room < 620  # the tab as narrow as the docked panel leaves it (494 px, polygon)
    assert what_if.minimumSizeHint().width() <= room, (what_if.minimumSizeHint(), room)
    assert not scroll.horizontalScrollBar().isVisible()
    assert what_if.width() <= room
    for choice in what_if.form.findChildren(QComboBox):  # each choice's text shown whole
        assert choice.width() >= choice.sizeHint().width(), choice.currentText()
    # the plots keep the tab's width: beside the form only where both have room
    for plot in (what_if.top_plot, what_if.bottom_plot):
        assert plot.width() >= min(300, room - what_if.form.width() - 30) or \
            plot.width() >= room - 40, (plot.width(), room)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
@pytest.mark.parametrize("key", ["polygon", "theodolite"])
def test_each_plots_y_axis_title_is_shown_whole(window, qtbot, key, language):
    """Beside the docked panel at 1280×720 each What-if plot's y axis holds its title: the
    polygon's plots had 138 px, their y axes 68 px, and "ε_x induced error (\")" (126 px)
    and "ε_y vertical (\")" (91 px) were cut at both ends — in Chinese too (106 px, 70 px).
    The tab scrolls (up and down) instead; it never scrolls sideways. The language is
    chosen as a user does (View › Language), after the window was laid out in English."""
    import pyqtgraph as pg
    from PySide6.QtCore import QRectF

    from tests.app.test_status_line_language import choose_language

    def axis_title_length(axis) -> float:
        """The title's length along its axis: its text, the text item's margins aside."""
        label = axis.label
        return label.boundingRect().width() - 2 * label.document().documentMargin()

    window.presenter(key).load_sample()  # the workbench looked at (above)
    window.resize(1280, 720)
    window.show()
    qtbot.waitExposed(window)
    scroll, what_if = _what_if(window, key)
    window.capture_panel.show()  # opened on this workbench
    qtbot.waitUntil(lambda: what_if.isVisible() and what_if.width() > 0)
    try:
        choose_language(window, language)
        qtbot.wait(200)  # laid out again, in the language's titles
        panel = window.capture_panel
        assert panel.isVisible() and not panel.isFloating()  # docked beside the tab
        assert scroll.viewport().width() < 1280 - panel.width()
        for plot in (what_if.top_plot, what_if.bottom_plot):
            axis = plot.getPlotItem().getAxis("left")
            title = axis_title_length(axis)
            assert title > 20, axis.labelText
            for _ in range(30):  # the plots' least heights follow their legends' places
                if axis.geometry().height() >= title:
                    break
                qtbot.wait(100)
            # was: 68 px of axis for the 126 px of "ε_x induced error (\")"
            assert axis.geometry().height() >= title, (axis.labelText, title,
                                                       axis.geometry().height())
            # drawn inside the plot, from end to end (its text item's margins aside)
            margin = axis.label.document().documentMargin()
            drawn = axis.label.sceneBoundingRect().adjusted(margin, margin, -margin, -margin)
            assert QRectF(0, 0, plot.width(), plot.height()).contains(drawn), (
                axis.labelText, drawn, plot.size())
            # and along its axis, not over the legend or the x axis
            along = axis.sceneBoundingRect()
            assert along.top() - 1 <= drawn.top() and drawn.bottom() <= along.bottom() + 1, (
                axis.labelText, drawn, along)
            assert isinstance(plot, pg.PlotWidget) and plot.height() >= plot.minimumHeight()
        assert not scroll.horizontalScrollBar().isVisible()
        assert what_if.height() >= what_if.minimumSizeHint().height()
    finally:
        choose_language(window, "en")
