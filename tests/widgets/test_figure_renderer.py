"""One renderer for declared figures: the window draws every series of a figure as it is
declared (data, colour, dash, markers, legend), in the style models/plot_style.py decides,
and the certificate's PDF writer draws from the same decisions."""

from __future__ import annotations

import numpy as np
import pyqtgraph as pg
import pytest
from PySide6.QtCore import Qt

from app.writers import certificate_pdf
from models.plot_style import ROLE_STYLES, series_style
from models.plots import PlotFigure, PlotSeries
from widgets.error_plot import CORRECTED_PEN, MODEL_PEN, RAW_PEN, RESIDUAL_PEN
from widgets.figure_plot import FigurePlot, FigureRenderer

X = np.linspace(0.0, 360.0, 13)


def _empty(curve) -> bool:
    x, _ = curve.getData()
    return x is None or len(x) == 0


def _figure() -> PlotFigure:
    return PlotFigure("Mean positional deviation with ±2s", "target position (°)", "deviation (\")", (
        PlotSeries("up", X, np.sin(np.radians(X)), (1, 2, 3), True, band=np.full(13, 0.2), role="raw"),
        PlotSeries("mean", X, 0.5 * np.sin(np.radians(X)), (4, 5, 6), role="model"),
        PlotSeries("dots", X, np.cos(np.radians(X)), (7, 8, 9), True, width=0, marker_size=3),
        PlotSeries("", X, -np.cos(np.radians(X)), (10, 11, 12), dashed=True, width=1.5),
    ))


def test_each_series_is_drawn_as_declared_in_the_shared_style(qtbot):
    plot = FigurePlot()
    qtbot.addWidget(plot)
    figure = _figure()
    plot.show_figure(figure)
    assert len(plot.curves) == 4 and len(plot.bands) == 1
    for curve, series in zip(plot.curves, figure.series, strict=True):
        x, y = curve.getData()
        np.testing.assert_array_equal(x, series.x)
        np.testing.assert_array_equal(y, series.y)
    up, mean, dots, lower = plot.curves
    # a role's colour, whatever the series declares; the set-up model dashed and under the rest
    assert up.opts["pen"].color().getRgb()[:3] == ROLE_STYLES["raw"].colour
    assert up.opts["symbol"] == "o" and up.opts["symbolSize"] == 6
    assert mean.opts["pen"].color().getRgb()[:3] == ROLE_STYLES["model"].colour
    assert mean.opts["pen"].style() == Qt.PenStyle.DashLine and mean.zValue() < up.zValue()
    assert dots.opts["pen"] is None and dots.opts["symbolSize"] == 3  # markers only
    assert pg.mkBrush(dots.opts["symbolBrush"]).color().getRgb()[:3] == (7, 8, 9)
    assert lower.opts["pen"].style() == Qt.PenStyle.DashLine and lower.opts["pen"].widthF() == 1.5
    # the legend names the labelled series only
    assert [label.text for _sample, label in plot.legend.items] == ["up", "mean", "dots"]
    assert plot.plot.getPlotItem().titleLabel.text == figure.title


def test_a_figure_of_fewer_series_empties_and_unnames_the_rest(qtbot):
    plot = FigurePlot()
    qtbot.addWidget(plot)
    plot.show_figure(_figure())
    short = PlotFigure("t", "x", "y", (PlotSeries("only", X, X, (1, 2, 3)),))
    plot.show_figure(short)
    assert all(_empty(c) for c in plot.curves[1:]) and plot.bands == []
    assert [label.text for _sample, label in plot.legend.items] == ["only"]
    plot.clear()
    assert plot.legend.items == [] and _empty(plot.curves[0])


def test_bars_of_log_amplitudes_rise_from_a_decade_below_the_smallest(qtbot):
    widget = pg.PlotWidget()
    qtbot.addWidget(widget)
    renderer = FigureRenderer(widget, titles=False, bars=True, bar_width=0.35, log_bars=True)
    logs = np.log10([3.7, 0.08, 0.002])
    renderer.show(PlotFigure("", "harmonic order", "amplitude (V, log10)", (
        PlotSeries("sin", np.array([1.0, 3.0, 5.0]), logs, (192, 57, 43)),)))
    bars = renderer.curves[0]
    assert bars.opts["y0"] == -4.0  # floor(log10 0.002) − 1
    np.testing.assert_allclose(bars.opts["height"], logs + 4.0)
    assert pg.mkBrush(bars.opts["brush"]).color().getRgb()[:3] == (192, 57, 43)


def test_the_error_plot_draws_each_role_as_the_certificate_does():
    for pen, role in ((RAW_PEN, "raw"), (MODEL_PEN, "model"), (CORRECTED_PEN, "corrected"),
                      (RESIDUAL_PEN, "residual")):
        assert pen.color().getRgb()[:3] == ROLE_STYLES[role].colour
        assert (pen.style() == Qt.PenStyle.DashLine) == ROLE_STYLES[role].dashed


@pytest.mark.parametrize("series, colour", [
    (PlotSeries("a", X, X, (1, 2, 3), role="corrected"), ROLE_STYLES["corrected"].colour),
    (PlotSeries("a", X, X, (1, 2, 3)), (1, 2, 3)),
])
@pytest.mark.slow
def test_the_certificate_draws_from_the_shared_style(monkeypatch, series, colour):
    """The PDF writer asks models/plot_style.py for each series' colour and dash: a style
    changed there is what the certificate draws."""
    seen = []

    def spy(s):
        style = series_style(s)
        seen.append(style)
        return style

    monkeypatch.setattr(certificate_pdf.plots, "series_style", spy)
    pdf = certificate_pdf.ReportPdf(("", ""), ("", ""))
    pdf.set_compression(False)
    pdf.add_page()
    pdf.plot(PlotFigure("t", "x", "y", (series,)))
    content = bytes(pdf.output()).decode("latin-1")
    certificate_pdf.close_fonts(pdf)
    assert seen and all(style.colour == colour for style in seen)
    stroke = " ".join(f"{c / 255:.4f}".rstrip("0").rstrip(".") or "0" for c in colour)
    assert f"{stroke} RG" in content


def _role_figure(points: int, scale: float = 1.0) -> PlotFigure:
    x = np.linspace(0.0, 360.0, points)
    wave = scale * np.sin(np.radians(x))
    return PlotFigure("", "θ (°)", "error (\")", (PlotSeries("raw", x, wave, role="raw"),
                                                   PlotSeries("model", x, 0.9 * wave, role="model")))


@pytest.mark.parametrize(("points", "symbol", "width"), [(24, "o", 2.0), (600, None, 2.0),
                                                         (3000, None, 1.0)])
@pytest.mark.slow
def test_a_panel_of_the_error_plot_draws_roles_by_their_point_count(qtbot, points, symbol, width):
    """The error plot's rules, now the renderer's: a role's own markers on a short curve, none
    beyond 500 points, a 1-px pen on a curve of points beyond 2000 (not on the model's line)."""
    widget = pg.PlotWidget()
    qtbot.addWidget(widget)
    renderer = FigureRenderer(widget, titles=False, role_markers=True, max_symbol_points=500,
                              dense_points=2000)
    renderer.show(_role_figure(points))
    raw, model = renderer.curves
    assert raw.opts["symbol"] == symbol and raw.opts["pen"].widthF() == width
    assert raw.opts["symbolSize"] == ROLE_STYLES["raw"].symbol_size
    assert model.opts["symbol"] is None and model.opts["pen"].widthF() == 2.0
    assert model.opts["pen"].style() == Qt.PenStyle.DashLine


def test_a_steady_y_range_moves_only_when_the_data_leave_it_or_shrink_well_inside(qtbot):
    widget = pg.PlotWidget()
    qtbot.addWidget(widget)
    renderer = FigureRenderer(widget, titles=False, steady_y=True, y_includes=(0.0,))
    vb = widget.getPlotItem().getViewBox()
    renderer.show(_role_figure(24))
    first = vb.viewRange()[1]
    assert first[0] < -1.0 and first[1] > 1.0 and not vb.state["autoRange"][1]
    renderer.show(_role_figure(24, 1.02))  # a small edit: the axes stay
    assert vb.viewRange()[1] == first
    renderer.show(_role_figure(24, 3.0))  # the data leave the view: it follows
    assert vb.viewRange()[1][1] > 3.0
    renderer.show(_role_figure(24, 0.2))  # shrinks well inside: it follows
    assert vb.viewRange()[1][1] < 0.5
