"""The Live signals window at the size of a 1280×720 screen at 150 % (853×480 logical px):
the interpolation error's plot keeps its y axis' title whole and in view, the bars beside
it scrolling down (day review 66: the plots were as tall as the bars, 463 px in a 296 px
view, and "interpolation error (° el.)", centred on their axis, was partly out of view)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QRectF

from tests.widgets.fringe.live_signals_window import open_live_signals

pytestmark = pytest.mark.slow  # the window and its live window


def _title_length(axis) -> float:
    label = axis.label
    return label.boundingRect().width() - 2 * label.document().documentMargin()


def test_the_interpolation_errors_title_stays_whole_at_150_percent(window, qtbot):
    panel = open_live_signals(window, qtbot)
    try:
        panel.start_demonstration()  # the bars and plots with their figures, as at the bench
        qtbot.waitUntil(lambda: panel.samples >= 2000, timeout=30000)
        panel.resize(853, 480)
        qtbot.wait(300)
        for plot in (panel.error_plot, panel.lissajous):
            axis = plot.getPlotItem().getAxis("left")
            title = _title_length(axis)
            assert title > 50, axis.labelText
            for _ in range(30):  # the plot's least height follows its layout
                if axis.geometry().height() >= title:
                    break
                qtbot.wait(100)
            # was: 160 px of plot, ~110 px of axis for the 169 px title
            assert axis.geometry().height() >= title, (axis.labelText, title,
                                                       axis.geometry().height())
            margin = axis.label.document().documentMargin()
            drawn = axis.label.sceneBoundingRect().adjusted(margin, margin, -margin, -margin)
            assert QRectF(0, 0, plot.width(), plot.height()).contains(drawn)
            # and in the body's view, the body scrolled to its top (was: the plots as tall
            # as the bars beside them, 463 px in a 296 px view, the title centred on them)
            view = panel.body.viewport()
            top_left = plot.mapTo(view, drawn.topLeft().toPoint())
            bottom_right = plot.mapTo(view, drawn.bottomRight().toPoint())
            assert view.rect().contains(top_left) and view.rect().contains(bottom_right), (
                axis.labelText, top_left, bottom_right, view.rect())
        assert panel.body.verticalScrollBar().maximum() > 0  # the bars scroll down
    finally:
        panel.disconnect_stream()
        panel.close()
