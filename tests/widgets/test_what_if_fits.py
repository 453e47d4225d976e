"""The What-if tab fits its tab with the instrument panel docked at 1280×720 (the polygon's
needed a horizontal scroll bar: its set-up choice held the form at 486 px of the tab's
494), and stacks its form above the plots where they have no room beside it."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QComboBox, QScrollArea

from widgets.family_simulation import FamilySimulation

pytestmark = pytest.mark.slow  # the window with every sample


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
    window.load_all_samples()
    window.resize(1280, 720)
    window.show()
    window.capture_panel.show()  # Instrument › Connect… docks it, at the right by default
    qtbot.waitExposed(window)
    scroll, what_if = _what_if(window, key)
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
