"""The error plot's y ranges follow the data without jittering on small changes."""

import numpy as np
import pytest

from widgets.error_plot import ErrorPlot


@pytest.mark.slow
def test_y_range_moves_only_when_needed_and_respects_a_zoom(qtbot):
    plot = ErrorPlot()
    qtbot.addWidget(plot)
    x = np.linspace(-20, 20, 41)
    y = np.sin(x / 5)
    plot.set_curves(x, y, y * 0.9, y * 0.1)
    vb = plot.main_plot.getViewBox()
    first = vb.viewRange()[1]
    assert first[0] < -1.0 + 1e-9 and first[1] > 1.0 - 1e-9
    plot.set_curves(x, y * 1.02, y * 0.9, y * 0.1)  # a small edit: the axes stay
    assert vb.viewRange()[1] == first
    plot.set_curves(x, y * 3, y * 0.9, y * 0.1)  # the data leave the view: it follows
    grown = vb.viewRange()[1]
    assert grown[1] >= 3.0 and grown[0] <= -3.0
    plot.set_curves(x, y * 0.2, y * 0.2, y * 0.1)  # shrinks well inside: it follows
    assert vb.viewRange()[1][1] < 1.0
    vb.setYRange(-10, 10, padding=0)
    vb.sigRangeChangedManually.emit([False, True])  # as a mouse zoom does
    plot.set_curves(x, y * 0.2, y * 0.2, y * 0.1)  # the same data drawn again
    assert vb.viewRange()[1] == [-10.0, 10.0]  # the user's zoom is kept
    plot.set_curves(x, y * 0.5, y * 0.5, y * 0.1)  # new data: the zoom is given up (#31)
    assert vb.viewRange()[1][1] < 1.0
    vb.setYRange(-10, 10, padding=0)
    vb.sigRangeChangedManually.emit([False, True])
    vb.enableAutoRange(y=True)  # the "A" button
    plot.set_curves(x, y * 0.5, y * 0.5, y * 0.1)
    assert vb.viewRange()[1][1] < 1.0


def test_the_legend_goes_where_the_data_is_not(qtbot):
    """A curve rising to the top right: the legend leaves that corner; a falling one: it
    stays top right (the default when it is empty)."""
    from widgets.error_plot import ErrorPlot

    plot = ErrorPlot()
    qtbot.addWidget(plot)
    plot.resize(800, 600)
    plot.show()
    x = np.linspace(0, 100, 200)
    plot.set_curves(x, raw=x ** 2 / 100, model=x ** 2 / 100, corrected=-x)
    assert plot.main_plot.legend_corner != "top-right"
    assert plot.corrected_plot.legend_corner == "top-right"  # −x leaves the top right empty
    plot.set_curves(x, raw=-x, model=-x, corrected=x)
    assert plot.main_plot.legend_corner == "top-right"
    assert plot.corrected_plot.legend_corner != "top-right"


@pytest.mark.slow
def test_a_cramped_plot_puts_its_legend_above_the_data_and_back_when_there_is_room(qtbot):
    """Data in every corner of a plot too small for a legend inside it (a small window at
    200 %): the entries go to the title line above the data area, with their colours;
    given room again, the legend returns inside, in a corner."""
    plot = ErrorPlot()
    qtbot.addWidget(plot)
    plot.resize(420, 330)
    plot.show()
    x = np.linspace(0, 100, 400)
    wave = np.sin(x / 3.0)  # fills every corner
    plot.set_curve_names("raw error", "set-up model", "corrected")
    plot.set_curves(x, raw=wave, model=0.9 * wave, corrected=wave)
    qtbot.waitUntil(lambda: plot.main_plot.legend_corner == "above")
    title = plot.main_plot.titleLabel.text
    assert "raw error" in title and "set-up model" in title and "#c0392b" in title.lower()
    assert not plot.legend.isVisible()
    plot.resize(1400, 1400)
    qtbot.waitUntil(lambda: plot.main_plot.legend_corner != "above")
    assert plot.legend.isVisible() and not plot.main_plot.titleLabel.isVisible()


def test_the_crosshair_is_cleared_with_the_data(qtbot):
    """After File › New (the plots cleared) the readout kept the old values (#41)."""
    plot = ErrorPlot()
    qtbot.addWidget(plot)
    plot.resize(600, 500)
    plot.show()
    x = np.linspace(-20, 20, 41)
    plot.set_curves(x, 0.1 * x, 0.05 * x, 0.05 * x)
    centre = plot.main_plot.sceneBoundingRect().center()
    plot._on_mouse_moved(centre)
    assert "@" in plot.readout.text() and plot.vline.isVisible()
    plot.clear()
    assert plot.readout.text().strip() == "" and not plot.vline.isVisible()
    assert plot.raw_curve.getData()[0] is None or len(plot.raw_curve.getData()[0]) == 0


def test_each_series_is_drawn_over_its_own_x(qtbot):
    """#44: show_figure took x from the first series, so every curve had to share it (a
    model on a fine grid beside the readings raised inside pyqtgraph). Each is drawn over
    its own x now; a series whose x and y differ is refused, named."""
    from models.plots import PlotFigure, PlotSeries

    plot = ErrorPlot()
    qtbot.addWidget(plot)
    readings = np.linspace(0.0, 330.0, 12)
    grid = np.linspace(0.0, 360.0, 181)
    figure = PlotFigure("errors", "θ (°)", "error (\")", (
        PlotSeries("raw error", readings, np.cos(np.radians(readings)), role="raw"),
        PlotSeries("set-up model", grid, 0.9 * np.cos(np.radians(grid)), role="model"),
        PlotSeries("corrected", readings, 0.1 * np.sin(np.radians(readings)), role="corrected")))
    plot.show_figure(figure)
    for curve, x, y in ((plot.raw_curve, readings, np.cos(np.radians(readings))),
                        (plot.model_curve, grid, 0.9 * np.cos(np.radians(grid))),
                        (plot.corrected_curve, readings, 0.1 * np.sin(np.radians(readings)))):
        drawn_x, drawn_y = curve.getData()
        np.testing.assert_array_equal(drawn_x, x)
        np.testing.assert_allclose(drawn_y, y)
    # the first series hidden: the others keep their own x (it used to be the first's)
    plot.show_figure(PlotFigure("errors", "θ (°)", "error (\")", figure.series[1:]))
    assert plot.raw_curve.getData()[0] is None or len(plot.raw_curve.getData()[0]) == 0
    np.testing.assert_array_equal(plot.model_curve.getData()[0], grid)
    broken = PlotFigure("errors", "θ (°)", "error (\")", (
        figure.series[0], PlotSeries("set-up model", readings, np.zeros(5), role="model")))
    with pytest.raises(ValueError, match="the model series 'set-up model' has 5 values over "
                                         "12 x values"):
        plot.show_figure(broken)


@pytest.mark.slow
def test_a_titled_plot_s_legend_above_it_is_not_cut_at_the_top(qtbot):
    """A plot with a title whose legend goes above the data (the positioning plot "Mean
    positional deviation with ±2s" at 1280×720, live78): the title and the legend's line
    are two lines, which pyqtgraph's 30 px title row cut at the top (gui78); the row holds
    them all."""
    plot = ErrorPlot()
    qtbot.addWidget(plot)
    plot.resize(420, 330)
    plot.show()
    plot.main_plot.setTitle("Mean positional deviation with ±2s")
    x = np.linspace(0, 100, 400)
    wave = np.sin(x / 3.0)  # fills every corner
    plot.set_curve_names("raw error", "set-up model", "corrected")
    plot.set_curves(x, raw=wave, model=0.9 * wave, corrected=wave)
    qtbot.waitUntil(lambda: plot.main_plot.legend_corner == "above")
    label = plot.main_plot.titleLabel
    assert label.text.startswith("Mean positional deviation with ±2s<br>"), label.text
    lines = label.item.boundingRect().height()
    assert lines > 30, lines  # two lines, more than pyqtgraph's row
    qtbot.waitUntil(lambda: label.geometry().height() > 0)  # laid out
    qtbot.wait(50)
    assert label.geometry().height() >= lines, (label.geometry(), lines)
    assert label.item.pos().y() >= 0, label.item.pos()  # its top line not above the row
