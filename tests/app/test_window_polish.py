"""Layout and plot polish (#31 item 9): the left pane keeps its width whatever its caption
says; the plots' text reads at WCAG's 4.5:1 on white; each positioning run its own colour,
the direction by line style; harmonic orders on whole-number ticks; the empty register
history on dates; a file that takes a while to read shows that it is being read."""

from __future__ import annotations

import datetime as dt

import pyqtgraph as pg
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QColor
from PySide6.QtWidgets import QSplitter

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)


def _luminance(colour: QColor) -> float:
    def channel(c: float) -> float:
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4

    return (0.2126 * channel(colour.redF()) + 0.7152 * channel(colour.greenF())
            + 0.0722 * channel(colour.blueF()))


def contrast_on_white(colour: QColor) -> float:
    return 1.05 / (_luminance(colour) + 0.05)


def test_the_left_pane_keeps_its_width_whatever_the_caption(window):
    window.presenter("positioning").load_sample()  # the workbench looked at
    view = window.presenter("positioning").view
    splitter = next(s for s in view.findChildren(QSplitter)
                    if s.orientation() == Qt.Orientation.Horizontal)
    left = splitter.widget(0)
    before = left.minimumSizeHint().width()
    view.set_readings_caption("Readings — 130 used, 12 bad cell(s) — fewer than 5 runs: "
                              "flagged — and a much longer caption than any window has")
    assert left.minimumSizeHint().width() <= before
    assert view.readings_label.text().endswith("window has")  # shown, wrapped


def test_every_plot_text_reads_on_white(window):
    """Axis titles, tick labels and legends at 4.5:1 or more (pyqtgraph's grey: 3:1)."""
    window.load_all_samples()
    window.show_register()
    checked = 0
    for root in (window, window.register_window):
        for view in root.findChildren(pg.GraphicsView):
            for item in view.scene().items():
                if isinstance(item, pg.AxisItem):
                    colour = item.textPen().color()
                elif isinstance(item, pg.LegendItem):
                    colour = pg.mkColor(item.opts["labelTextColor"]
                                        or pg.getConfigOption("foreground"))
                elif isinstance(item, pg.LabelItem) and item.text:
                    colour = pg.mkColor(item.opts.get("color")
                                        or pg.getConfigOption("foreground"))
                else:
                    continue
                assert contrast_on_white(colour) >= 4.5, (type(item).__name__, colour.name())
                checked += 1
    assert checked > 50


def test_each_run_has_its_own_colour_and_the_direction_its_line_style(window):
    window.presenter("positioning").load_sample()  # the workbench looked at
    plot = window.presenter("positioning").view.readings_plot
    runs = {}
    for curve in plot.curves:
        pen = curve.opts["pen"]
        runs.setdefault(pen.color().name(), set()).add(pen.style())
    assert len(runs) == 5  # the sample's five runs
    assert all(styles == {Qt.PenStyle.SolidLine, Qt.PenStyle.DashLine}
               for styles in runs.values())
    names = [label.text for _s, label in plot.legend.items]
    assert names == ["1", "2", "3", "4", "5"]


def test_harmonic_orders_have_whole_number_ticks(window):
    from widgets.plot_grid import IntegerAxis

    for key in ("polygon", "fringe"):  # the workbenches looked at
        window.presenter(key).load_sample()
    window.show()
    axes = [window.presenter("polygon").view.harmonics.plot.getAxis("bottom"),
            window.presenter("fringe").view.plots.spectrum.getAxis("bottom")]
    for axis in axes:
        assert isinstance(axis, IntegerAxis)
        for low, high, size in ((0.5, 12.5, 600), (0.6, 5.4, 900), (0, 36, 200), (1, 3, 800)):
            for _spacing, values in axis.tickValues(low, high, size):
                assert all(float(v).is_integer() for v in values), (low, high, values)


def test_the_empty_register_history_reads_as_dates(window):
    window.show_register()
    x0, x1 = window.register_window.history_plot.getViewBox().viewRange()[0]
    first = dt.date(1970, 1, 1) + dt.timedelta(seconds=x0)
    assert first.year >= dt.date.today().year - 1 and x1 - x0 > 300 * 86400


def test_a_file_that_takes_a_while_shows_it_is_being_read(window, samples_dir, monkeypatch):
    presenter = window.presenter("fringe")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    window.show()
    shown = []
    real = presenter.view.show_reading
    monkeypatch.setattr(presenter.view, "show_reading",
                        lambda text: shown.append((text, presenter.view.busy.isVisibleTo(
                            presenter.view))) or real(text))
    presenter.start_import(samples_dir / "fringe_interferometer_sample.csv")  # 216 kB
    assert shown[0][0] == "Reading fringe_interferometer_sample.csv …" and shown[-1][0] == ""
    assert not presenter.view.busy.isVisibleTo(presenter.view)
    assert "Reading" not in presenter.view.summary.toPlainText()
    assert presenter.result is not None and presenter.sheet.row_count == 12_000
    shown.clear()
    presenter.start_import(samples_dir / "fringe_sample.csv")  # 20 kB: at once, no bar
    assert shown == []
