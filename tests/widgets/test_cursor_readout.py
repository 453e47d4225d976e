"""The error plot's readout under the cursor shows the errors to the decimals the
certificate prints them to, in the unit shown (it showed three decimals of every curve,
of arcseconds, µrad and mdeg alike: +0.254″ where the certificate prints +0.25″)."""

from __future__ import annotations

import json
import re

import numpy as np
import pytest
from PySide6.QtCore import QPoint, QPointF
from PySide6.QtTest import QTest

from models.certificate.metadata import CertificateMetadata
from models.display_units import angle_unit
from widgets.error_plot import ErrorPlot
from widgets.polygon.presenter import PolygonPresenter

pytestmark = pytest.mark.slow  # a sample analysed (a second or two)


def _hover(plot: ErrorPlot, x: float, y: float) -> str:
    """The mouse moved over the upper panel to the point (x, y) of its data; the readout."""
    scene = plot.main_plot.vb.mapViewToScene(QPointF(x, y))
    at = plot.graphics.mapFromScene(scene)
    QTest.mouseMove(plot.graphics.viewport(), at + QPoint(7, 7))  # from elsewhere: the
    QTest.mouseMove(plot.graphics.viewport(), at)  # cursor may already be there (a test before)
    QTest.qWait(20)
    return plot.readout.text()


def _figures(text: str) -> list[str]:
    """The errors the readout shows (not its x or its "@ θ")."""
    return re.findall(r" ([+-]\d+(?:\.\d+)?)(?:″|\"| µrad| mdeg)", text)


@pytest.fixture
def polygon(qtbot, samples_dir):
    presenter = PolygonPresenter()
    qtbot.addWidget(presenter.view)
    details = CertificateMetadata.from_dict(json.loads(
        (samples_dir / "certificate_polygon.json").read_text(encoding="utf-8")))
    presenter.certificate_details = lambda: details
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.result is not None and presenter.analyse_if_due(),
                    timeout=60000)
    view = presenter.view
    view.resize(1200, 800)
    view.show()
    view.plot_tabs.setCurrentWidget(view.plot_tabs.widget(0))
    qtbot.waitExposed(view)
    return presenter


def test_the_readout_shows_the_printed_decimals(polygon):
    presenter = polygon
    plot = presenter.view.error_plot
    decimals = presenter.printed_rounding(presenter.result)
    assert isinstance(decimals, int) and decimals != 3  # the sample's U: 0.01″ figures
    x, y = plot.corrected_curve.getData()
    face = 5
    text = _hover(plot, float(x[face]), float(np.asarray(plot.raw_curve.getData()[1])[face]))
    figures = _figures(text)
    assert len(figures) == 3, text  # raw, model, corrected
    assert all(len(f.partition(".")[2]) == decimals for f in figures), (text, decimals)
    assert f"{y[face]:+.{decimals}f}" in figures  # the corrected error at the face hovered


@pytest.mark.parametrize(("unit", "more"), [("urad", 0), ("mdeg", 1)])
def test_the_readout_follows_the_unit_shown(polygon, unit, more):
    """0.01″ is 0.05 µrad (two decimals, not three) and 0.003 mdeg (a decimal more)."""
    presenter = polygon
    plot = presenter.view.error_plot
    decimals = presenter.printed_rounding(presenter.result) + more
    presenter.set_angle_unit(angle_unit(unit))
    x, y = plot.corrected_curve.getData()
    text = _hover(plot, float(x[3]), float(y[3]))
    figures = _figures(text)
    assert angle_unit(unit).symbol in text and len(figures) == 3, text
    assert all(len(f.partition(".")[2]) == decimals for f in figures), text
    assert f"{y[3]:+.{decimals}f}" in figures


def test_without_a_certificate_rounding_the_readout_goes_by_the_data(qtbot):
    plot = ErrorPlot()
    qtbot.addWidget(plot)
    plot.resize(600, 500)
    plot.show()
    x = np.linspace(0, 330, 12)
    raw = 400.0 * np.sin(np.radians(x))  # a 800″ span: to 0.1″
    plot.set_curves(x, raw, raw * 0.99, raw * 0.01)
    text = _hover(plot, float(x[4]), float(raw[4]))
    figures = _figures(text)
    assert f"{raw[4]:+.1f}" in figures and f"{raw[4] * 0.01:+.1f}" in figures, text
