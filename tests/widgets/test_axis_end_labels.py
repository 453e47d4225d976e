"""Every tick label of a plot's x axis is drawn whole, those at its ends too: pyqtgraph left
out (or clipped to the view's edge) a label reaching past the axis' end, so the polygon's
"Each set" plot lost the last face's angle ("330" cut to "3"). Read from the axis' own
geometry: the labels it draws, each as wide as its font makes it, inside the plot."""

from __future__ import annotations

import json

import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QFontMetricsF, QImage, QPainter

from models.certificate.metadata import CertificateMetadata
from widgets.polygon.presenter import PolygonPresenter

pytestmark = pytest.mark.slow  # a sample analysed (a second or two)


def _drawn_labels(plot_widget) -> list[tuple[str, QRectF]]:
    """The x axis' tick labels as it draws them: each text and its rect in the widget's
    coordinates, as wide as the text is in the axis' font."""
    axis = plot_widget.getAxis("bottom")
    image = QImage(8, 8, QImage.Format.Format_ARGB32)
    painter = QPainter(image)
    try:
        specs = axis.generateDrawSpecs(painter)
    finally:
        painter.end()
    metrics = QFontMetricsF(axis.style["tickFont"] or axis.font())
    out = []
    for rect, _flags, text in specs[2]:
        width = metrics.horizontalAdvance(text)
        whole = QRectF(rect.center().x() - width / 2, rect.top(), width, rect.height())
        scene = axis.mapRectToScene(whole)
        out.append((text, plot_widget.mapFromScene(scene).boundingRect().toRectF()))
    return out


@pytest.fixture
def each_set(qtbot, samples_dir):
    presenter = PolygonPresenter()
    qtbot.addWidget(presenter.view)
    details = CertificateMetadata.from_dict(json.loads(
        (samples_dir / "certificate_polygon.json").read_text(encoding="utf-8")))
    presenter.certificate_details = lambda: details
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.result is not None and presenter.analyse_if_due(),
                    timeout=60000)
    view = presenter.view
    view.resize(900, 700)
    view.show()
    tabs = view.plot_tabs
    tabs.tabBar().setCurrentIndex(next(i for i in range(tabs.count())
                                       if view.plot_widget(i) is view.sets_plot))
    qtbot.waitExposed(view)
    return view.sets_plot.plot


@pytest.mark.parametrize("end", ["300", "250"])
def test_the_label_at_the_x_axis_end_is_drawn_whole(each_set, qtbot, end):
    """The user sets the x range to end at a tick (right-click › X axis, its range typed)."""
    plot = each_set
    menu = plot.getViewBox().getMenu(None)
    ctrl = menu.ctrl[0]
    ctrl.minText.setText("0")
    ctrl.maxText.setText(end)
    ctrl.maxText.editingFinished.emit()  # as Return in the field does
    qtbot.waitUntil(lambda: abs(plot.getViewBox().viewRange()[0][1] - float(end)) < 1e-6)
    qtbot.wait(50)
    labels = _drawn_labels(plot)
    assert end in [text for text, _ in labels], labels  # the last tick's label is there
    inside = QRectF(plot.rect())
    for text, rect in labels:
        assert inside.contains(rect), (text, rect, inside)


def test_each_label_is_drawn_whole_at_the_default_range(each_set):
    plot = each_set
    labels = _drawn_labels(plot)
    assert len(labels) >= 4
    inside = QRectF(plot.rect())
    assert all(inside.contains(rect) for _, rect in labels), labels
    axis = plot.getAxis("bottom")
    clip = axis.mapRectToScene(axis.boundingRect())
    for _, rect in labels:  # within what the axis paints (it clips its text to its bounds)
        assert plot.mapFromScene(clip).boundingRect().toRectF().adjusted(
            -1, -1, 1, 1).contains(rect), (rect, clip)
