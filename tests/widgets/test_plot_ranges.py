"""Plots show their data (#31): the Lissajous figure whole at every window size, on both
fringe samples (its 1:1 aspect and the legend's room fought: only 1.7–5.3 V of a ±3.7 V
figure was in view); new data re-range a plot, a user's zoom or drag kept only while the
data stay the same; a printout shows its data."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtTest import QTest
from PySide6.QtWidgets import QApplication

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)

# the sizes the window was tried at: 1600×1000, 1280×720, and 200 % on 2560×1600 (1280×800
# logical: Qt lays the window out in logical pixels, the fonts' sizes in them the same)
SIZES = [(1600, 1000), (1280, 720), (1280, 800)]


@pytest.fixture(scope="module")
def _window_of_the_module(qapp, tmp_path_factory):
    """One window for the cases that each set what they look at themselves (the workbench in
    front, its readings or sample, the language, the window's size, the plot's tab): a window
    each took ~0.45 s of CPU."""
    from tests.conftest import window_of_a_module

    yield from window_of_a_module(tmp_path_factory.mktemp("plot_ranges_window"))


@pytest.fixture
def shared_window(_window_of_the_module, qtbot):
    """:func:`_window_of_the_module`, in English again after each case (a case that asks for
    no language finds the window as a fresh one, in English)."""
    yield _window_of_the_module
    if _window_of_the_module.language != "en":
        _window_of_the_module.set_language("en")


def _settle(widget) -> None:
    for _ in range(3):
        QApplication.processEvents()
    widget.grab()  # a paint: pyqtgraph applies its auto-range when it paints


def _inside(plot_item, curves) -> list[str]:
    """The curves with a point outside the view (empty: every point is in view)."""
    (x0, x1), (y0, y1) = plot_item.getViewBox().viewRange()
    out = []
    for curve in curves:
        x, y = curve.getData()
        if x is None or len(x) == 0:
            continue
        ok = np.isfinite(x) & np.isfinite(y)
        x, y = x[ok], y[ok]
        if x.min() < x0 or x.max() > x1 or y.min() < y0 or y.max() > y1:
            out.append(f"{curve.opts['name']}: x {x.min():.3g}…{x.max():.3g}, y {y.min():.3g}…"
                       f"{y.max():.3g} in view x {x0:.3g}…{x1:.3g}, y {y0:.3g}…{y1:.3g}")
    return out


@pytest.mark.parametrize("size", SIZES, ids=lambda s: f"{s[0]}x{s[1]}")
def test_the_lissajous_figure_is_shown_whole(shared_window, samples_dir, size):
    window = shared_window
    presenter = window.presenter("fringe")
    plots = presenter.view.plots
    window.resize(*size)
    window.show()
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.view.plot_tabs.setCurrentIndex(2)
    for sample in ("fringe_sample.csv", "fringe_interferometer_sample.csv"):
        presenter.import_file(samples_dir / sample)
        _settle(plots.lissajous)
        curves = (plots.liss_raw, plots.liss_ellipse, plots.liss_ideal)
        assert all(len(c.getData()[0]) for c in curves)
        assert not _inside(plots.lissajous.getPlotItem(), curves), (sample, _inside(
            plots.lissajous.getPlotItem(), curves))


def _drag(plot_item, dx: float, dy: float) -> None:
    """What a mouse drag does to a ViewBox (pyqtgraph's mouseDragEvent)."""
    vb = plot_item.getViewBox()
    (x0, x1), (y0, y1) = vb.viewRange()
    vb.translateBy(x=dx * (x1 - x0), y=dy * (y1 - y0))
    vb.sigRangeChangedManually.emit(vb.state["mouseEnabled"])


def test_new_readings_after_file_new_are_in_view(window):
    """File › New, then a run typed with 1/10 of the sample's amplitude: the drift per
    period (whose top the legend had raised, turning its auto-range off) shows it."""
    presenter = window.presenter("fringe")
    presenter.load_sample()  # the workbench looked at
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.view.plot_tabs.setCurrentIndex(4)
    plots = presenter.view.plots
    window.show()
    _settle(plots.drift)
    window.projects.new_project()
    phase = np.arange(640) * 2 * np.pi / 64
    cells = [(r, c, f"{v:.5f}") for r, p in enumerate(phase)
             for c, v in enumerate((0.37 * np.sin(p) + 0.01, 0.36 * np.cos(p) - 0.02))]
    presenter.table_model.set_cells(cells, "typed")
    presenter.refresh()
    _settle(plots.drift)
    drift = (plots.drift_a1, plots.drift_b1, plots.drift_a3, plots.drift_b3)
    assert len(plots.drift_a1.getData()[0]) >= 5
    assert not _inside(plots.drift.getPlotItem(), drift)
    for plot, curves in ((plots.signals, (plots.sin_points, plots.cos_points)),
                         (plots.lissajous, (plots.liss_raw,))):
        _settle(plot)
        assert not _inside(plot.getPlotItem(), curves)


def test_a_drag_is_kept_for_the_same_data_and_given_up_for_new_data(window, samples_dir,
                                                                    tmp_path):
    theodolite = window.presenter("theodolite")
    theodolite.load_sample()  # the workbench looked at
    window.show()
    plot = theodolite.view.error_plot
    _settle(plot)
    main = plot.main_plot
    _drag(main, 3.0, 2.0)  # the curves dragged out of sight
    _settle(plot)
    dragged = main.getViewBox().viewRange()
    assert _inside(main, [plot.raw_curve])
    theodolite._redraw()  # the same readings drawn again (a language or unit change)
    _settle(plot)
    assert np.allclose(main.getViewBox().viewRange(), dragged)
    # a dropped file with other readings: in view
    lines = (samples_dir / "theodolite_sample.csv").read_text().splitlines()
    shifted = [lines[0]] + [f"{float(line.split(',')[0]) + 100:g}," + line.split(",", 1)[1]
                            for line in lines[1:]]
    other = tmp_path / "run2.csv"
    other.write_text("\n".join(shifted) + "\n")
    theodolite.start_import(other)
    _settle(plot)
    for panel, curves in ((plot.main_plot, [plot.raw_curve, plot.model_curve]),
                          (plot.corrected_plot, [plot.corrected_curve]),
                          (plot.residual_plot, [plot.residual_curve])):
        assert not _inside(panel, curves)
    # Send to positioning after a drag there: the positioning plots show the run
    positioning = window.presenter("positioning")
    window.tabs.setCurrentIndex(window.presenters.index(positioning))
    deviation = positioning.view.deviation_plot
    _settle(deviation)
    _drag(deviation.plot.getPlotItem(), -4.0, 3.0)
    window.tabs.setCurrentIndex(0)
    assert window.send_to_positioning()
    _settle(deviation)
    assert not _inside(deviation.plot.getPlotItem(), deviation.curves)


def test_print_shows_the_plots_data(window, tmp_path):
    from PySide6.QtPrintSupport import QPrinter

    window.current.load_sample()  # the workbench in front, printed
    window.show()
    view = window.current.view
    plot = view.error_plot
    _settle(plot)
    _drag(plot.main_plot, 5.0, 5.0)  # dragged off, same data: the screen keeps the drag …
    _settle(plot)
    assert _inside(plot.main_plot, [plot.raw_curve])
    printer = QPrinter(QPrinter.PrinterMode.ScreenResolution)
    printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
    printer.setOutputFileName(str(tmp_path / "print.pdf"))
    window.print_to(printer)  # … the printout does not print an empty frame
    assert not _inside(plot.main_plot, [plot.raw_curve, plot.model_curve])
    assert (tmp_path / "print.pdf").stat().st_size > 10_000


@pytest.mark.parametrize("language", ["en", "zh_CN"])
@pytest.mark.parametrize("size", SIZES, ids=lambda s: f"{s[0]}x{s[1]}")
def test_the_positioning_deviation_plot_shows_every_point(shared_window, size, language):
    """Mean deviation per target, in English and in Chinese: the envelope of A (a
    two-point line) and the ±2s bands stay in view when the legend makes its room (the
    Chinese legend, wider, found no free corner: the view was cut at the lowest mean
    point, ~−7″, leaving the lower envelope at −9.5″ and the ↑ band's bottom out). Only the
    positioning workbench's sample is loaded: with all five (~0.5 s of CPU more a case, their
    language switched too) the window, the plot's size, the legend's place and the view's
    range were the same at every size and in both languages (compared 2026-12-07). The six
    cases share one window (each loads the sample and sets its language and size: a case
    after another at the same data is resized and relabelled, then checked)."""
    window = shared_window
    positioning = window.presenter("positioning")
    positioning.load_sample()
    window.set_language(language)
    window.resize(*size)
    window.show()
    window.tabs.setCurrentIndex(window.presenters.index(positioning))
    positioning.view.plot_tabs.setCurrentIndex(0)
    deviation = positioning.view.deviation_plot
    _settle(deviation)
    item = deviation.plot.getPlotItem()
    assert len(deviation.curves) >= 4 and any(len(c.getData()[0]) == 2 for c in deviation.curves)
    assert not _inside(item, deviation.curves)
    (x0, x1), (y0, y1) = item.getViewBox().viewRange()
    for band in deviation.bands:
        for edge in band.curves:
            x, y = edge.getData()
            assert y0 <= y.min() and y.max() <= y1, (y.min(), y.max(), y0, y1)


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_a_legend_above_a_narrow_plot_never_pushes_its_right_out_of_view(
        shared_window, samples_dir, language, monkeypatch):
    """Review 62, F13: with the certificate's tolerance and U bands the legend has seven
    entries; above a plot as narrow as with the instrument panel docked, in one title line,
    it made the plot wider than its view, which cut off the right: the 330° and 360° targets
    and the legend's end ("tolerance ±T al…"). Its entries now wrap to the plot's width."""
    import json

    from models.certificate.metadata import CertificateMetadata

    details = CertificateMetadata.from_dict(json.loads(
        (samples_dir / "certificate_positioning.json").read_text(encoding="utf-8")))
    window = shared_window
    positioning = window.presenter("positioning")
    monkeypatch.setattr(positioning, "certificate_details", lambda: details)
    window.set_language(language)
    positioning.load_sample()
    window.resize(1000, 662)
    window.show()
    window.tabs.setCurrentIndex(window.presenters.index(positioning))
    positioning.view.plot_tabs.setCurrentIndex(0)
    deviation = positioning.view.deviation_plot
    for _ in range(5):  # the layout settles over a few passes (the legend placed on each)
        _settle(deviation)
        QTest.qWait(50)
    item = deviation.plot.getPlotItem()
    assert item.legend_corner == "above" and len(deviation.curves) >= 7  # ±T and U drawn
    visible = deviation.plot.viewport().width()
    assert item.sceneBoundingRect().right() <= visible + 1, (item.sceneBoundingRect(), visible)
    assert not _inside(item, deviation.curves)  # the 360° target with the others


def _lab(rgb) -> np.ndarray:
    """CIE L*a*b* (D65) of an sRGB colour: distances in it are differences as seen."""
    c = np.asarray(rgb, float) / 255
    c = np.where(c > 0.04045, ((c + 0.055) / 1.055) ** 2.4, c / 12.92)
    xyz = np.array([[0.4124, 0.3576, 0.1805], [0.2126, 0.7152, 0.0722],
                    [0.0193, 0.1192, 0.9505]]) @ c / np.array([0.9505, 1.0, 1.089])
    f = np.where(xyz > 0.008856, np.cbrt(xyz), 7.787 * xyz + 16 / 116)
    return np.array([116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])])


@pytest.mark.parametrize("key", ["polygon", "theodolite"])
def test_what_if_legends_keep_every_entry_off_the_curves_in_distinct_colours(shared_window, key):
    """#31: at 1280×720 the What-if legends covered the curves and lost their last entry;
    ω = 90° and 135° were two greens."""
    window = shared_window
    presenter = window.presenter(key)
    sim = presenter.view.simulation
    window.resize(1280, 720)
    window.show()
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    index = next(i for i in range(presenter.view.plot_tabs.count())
                 if presenter.view.plot_widget(i) is sim)
    presenter.view.plot_tabs.setCurrentIndex(index)
    _settle(sim)
    sim.update_curves()
    _settle(sim)
    drawn = [c for c in sim.top_curves if len(c.getData()[0] if c.getData()[0] is not None else [])]
    assert len(drawn) == 5
    colours = [_lab(c.opts["pen"].color().getRgb()[:3]) for c in drawn]
    closest = min(np.linalg.norm(a - b) for i, a in enumerate(colours) for b in colours[i + 1:])
    assert closest > 50, closest  # ΔE*ab; pyqtgraph's 9 hues: 90° and 135° were 32 apart
    for plot, curves in ((sim.top_plot, sim.top_curves), (sim.bottom_plot, sim.bottom_curves)):
        item = plot.getPlotItem()
        legend = item.legend
        named = [label.text for _, label in legend.items]
        assert len(named) == 5  # one entry a drawn curve
        if item.legend_corner == "above":  # every entry in the title line, none lost
            assert all(name.split(" = ")[1] in item.titleLabel.text for name in named)
        else:  # inside: the whole legend in the plot, over no curve's point
            vb = item.getViewBox()
            box = legend.mapRectToItem(vb, legend.boundingRect())
            assert vb.rect().contains(box)
            assert not _inside(item, drawn if plot is sim.top_plot else
                               [c for c in curves if c.getData()[0] is not None])


def _wheel(widget, steps: int) -> None:
    from PySide6.QtCore import QPoint, QPointF, Qt
    from PySide6.QtGui import QWheelEvent

    target = widget.viewport()
    centre = QPointF(target.width() / 2, target.height() / 2)
    event = QWheelEvent(centre, QPointF(target.mapToGlobal(centre.toPoint())), QPoint(0, 0),
                        QPoint(0, 120 * steps), Qt.MouseButton.NoButton,
                        Qt.KeyboardModifier.NoModifier, Qt.ScrollPhase.NoScrollPhase, False)
    QApplication.sendEvent(target, event)


def test_the_wheel_scrolls_past_a_plot_and_zooms_it_once_clicked(window):
    """#31: scrolling the panel with the wheel zoomed the plot under the pointer."""
    positioning = window.presenter("positioning")
    positioning.load_sample()  # the workbench looked at (its plot's size as with all five)
    window.resize(1280, 720)
    window.show()
    window.tabs.setCurrentIndex(window.presenters.index(positioning))
    plot = positioning.view.deviation_plot.plot
    _settle(plot)
    vb = plot.getPlotItem().getViewBox()
    before = np.array(vb.viewRange())
    window.tabs.setFocus()
    _wheel(plot, -5)
    _settle(plot)
    assert np.allclose(vb.viewRange(), before)  # not focused: no zoom
    plot.setFocus()
    QApplication.processEvents()
    _wheel(plot, -5)
    _settle(plot)
    assert not np.allclose(vb.viewRange(), before)  # clicked (focused): the wheel zooms


def _plot_items(presenter):
    import pyqtgraph as pg

    out = []
    for index in range(presenter.view.plot_tabs.count()):
        widget = presenter.view.plot_tabs.widget(index)
        for view in widget.findChildren(pg.GraphicsView):
            out += [(presenter.view.plot_tabs.tabText(index), item) for item in view.scene().items()
                    if isinstance(item, pg.PlotItem)]
    return out


def test_a_plot_with_no_data_shows_a_neutral_view_and_says_so(window):
    """#41 review: emptied, a plot showed pyqtgraph's range of no point, a y axis of ±5e-05
    (±8e-05 with the zero line); it shows ±1 and "No data", and its data again when they come."""
    from widgets.plot_range import EMPTY_RANGE, has_data

    window.resize(1280, 720)
    window.show()
    window.load_all_samples()
    for index, presenter in enumerate(window.presenters):
        window.tabs.setCurrentIndex(index)
        rows = [[presenter.sheet.text(r, c) for c in range(presenter.sheet.column_count)]
                for r in range(presenter.sheet.row_count)]
        drawn = {id(item) for _, item in _plot_items(presenter) if has_data(item)}
        presenter.table_model.replace_all([], "emptied")
        presenter.refresh()
        _settle(window)
        emptied = 0
        for tab, item in _plot_items(presenter):
            assert not has_data(item), f"{presenter.kind.key} › {tab}"
            vb = item.getViewBox()
            where = f"{presenter.kind.key} › {tab}: {vb.viewRange()}"
            assert vb.viewRange()[1][1] - vb.viewRange()[1][0] >= 1.0, where
            if id(item) not in drawn:
                continue  # (never drawn here: the what-if plots before their tab is shown)
            emptied += 1
            if not vb.state["aspectLocked"]:  # (the Lissajous keeps its 1:1)
                assert tuple(vb.viewRange()[1]) == pytest.approx(EMPTY_RANGE[1]), where
            assert vb.empty_text.isVisible() and vb.empty_text.toPlainText() == "No data", where
        assert emptied, presenter.kind.key
        presenter.table_model.replace_all(rows, "back")
        presenter.refresh()
        _settle(window)
        for tab, item in _plot_items(presenter):
            text = getattr(item.getViewBox(), "empty_text", None)
            if has_data(item):
                assert text is None or not text.isVisible(), f"{presenter.kind.key} › {tab}"


def test_the_title_above_a_legend_follows_a_change_of_language(shared_window, samples_dir,
                                                               monkeypatch):
    """rev62day F14: with the legend in the title line (a tolerance's bands, a narrow plot),
    the title stayed "Mean positional deviation with ±2s" in the Chinese window: the title
    kept above the legend was the one of the first placement, never relabelled."""
    import json

    from models.certificate.metadata import CertificateMetadata

    details = CertificateMetadata.from_dict(json.loads(
        (samples_dir / "certificate_positioning.json").read_text(encoding="utf-8")))
    window = shared_window
    positioning = window.presenter("positioning")
    monkeypatch.setattr(positioning, "certificate_details", lambda: details)
    window.set_language("en")
    positioning.load_sample()
    window.resize(1000, 662)
    window.show()
    window.tabs.setCurrentIndex(window.presenters.index(positioning))
    positioning.view.plot_tabs.setCurrentIndex(0)
    deviation = positioning.view.deviation_plot
    item = deviation.plot.getPlotItem()

    def settled_title() -> str:
        for _ in range(5):
            _settle(deviation)
            QTest.qWait(50)
        return item.titleLabel.text

    assert item.legend_corner == "above" or settled_title()
    assert item.legend_corner == "above"
    assert settled_title().startswith("Mean positional deviation with ±2s<br>")
    window.set_language("zh_CN")
    title = settled_title()
    assert title.startswith("平均位置偏差及 ±2s<br>") and "Mean positional" not in title
    assert "允差 ±T" in title  # the legend's entries, in Chinese, under it
    window.set_language("en")
    assert settled_title().startswith("Mean positional deviation with ±2s<br>")
