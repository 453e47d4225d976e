"""The Live signals window at the size of a 1280×720 screen at 150 % (853×480 logical px):
the Lissajous plot's title, which says what its rings are, is drawn whole inside its plot,
in English and in Chinese (day review 67: "Rings: amplitude band (green inside, amber
outer)" was one line wider than the plot, cut at both ends, and the plot laid out as
wide as it, the figure's right end cut too)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QRectF

from tests.widgets.fringe.live_signals_window import open_live_signals

pytestmark = pytest.mark.slow  # the window and its live window


def _drawn(plot) -> QRectF:
    """Where the plot's title text is drawn, in the plot's coordinates (its margins out)."""
    text = plot.getPlotItem().titleLabel.item
    margin = text.document().documentMargin()
    return text.sceneBoundingRect().adjusted(margin, margin, -margin, -margin)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_lissajous_title_is_whole_at_150_percent(window, qtbot, language):
    window.set_language(language)
    panel = open_live_signals(window, qtbot)
    try:
        panel.start_demonstration()  # the plots with their figures, as at the bench
        qtbot.waitUntil(lambda: panel.samples >= 2000, timeout=30000)
        for width in (1280, 853):  # the window made smaller, as on the small screen
            panel.resize(width, 480)
            qtbot.wait(300)
            plot = panel.lissajous
            title = plot.getPlotItem().titleLabel
            assert title.isVisible() and title.text, "the rings are explained"
            whole = QRectF(0, 0, plot.width(), plot.height())
            drawn = _drawn(plot)
            assert drawn.width() > 20, (title.text, drawn)
            assert whole.contains(drawn), (width, title.text, drawn, whole)
            # above the figure, not over it; the figure whole too (was: the plot laid out
            # as wide as the title, its right end and the x axis' last label cut)
            view_box = plot.getPlotItem().getViewBox().sceneBoundingRect()
            assert drawn.bottom() <= view_box.top() + 1, (drawn, view_box)
            assert whole.contains(view_box), (width, view_box, whole)
    finally:
        panel.disconnect_stream()
        panel.close()
        window.set_language("en")
