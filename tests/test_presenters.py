"""Each workbench's presenter with an autospec'd mock of its view: no window, no widget,
no dialog (Mantid workbench's MVP tests are the model). The presenter decides; the
tests read what it asked the view to show."""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest
import shiboken6
from PySide6.QtWidgets import QWidget

from models.readings.tabular_import import map_columns, read_table
from widgets.fringe.presenter import FringePresenter
from widgets.fringe.view import FringeView
from widgets.polygon.presenter import PolygonPresenter
from widgets.polygon.view import PolygonView
from widgets.theodolite.presenter import TheodolitePresenter
from widgets.theodolite.view import TheodoliteView

_OWNERS: list[QWidget] = []


@pytest.fixture(autouse=True)
def _delete_presenters_at_teardown():
    """Each presenter is owned by a widget deleted here, at once: left to Python's cyclic
    collector (the mock holds the presenter it was subscribed with), it could be freed in
    the middle of a later test's event loop."""
    yield
    while _OWNERS:
        shiboken6.delete(_OWNERS.pop())


def make(presenter_class, view_class, qtbot):
    """A presenter on an autospec'd mock of its view."""
    view = mock.create_autospec(view_class, instance=True)
    view.settings_values.return_value = {}
    owner = QWidget()
    _OWNERS.append(owner)
    return presenter_class(view, parent=owner), view


def load(presenter, samples_dir) -> None:
    rows = map_columns(read_table(samples_dir / presenter.kind.sample_file), presenter.kind.columns)
    presenter.table_model.replace_all(rows)
    presenter.refresh()


def test_theodolite_presenter_asks_for_curves_in_theta_order(qtbot, samples_dir):
    presenter, view = make(TheodolitePresenter, TheodoliteView, qtbot)
    assert view.add_setting.call_count == len(presenter.kind.parameters)
    view.subscribe.assert_called_once_with(presenter)
    load(presenter, samples_dir)
    errors, residuals = view.show_figures.call_args.args
    raw, model, corrected = (errors.by_role(r) for r in ("raw", "model", "corrected"))
    assert np.all(np.diff(raw.x) >= 0)
    np.testing.assert_allclose(raw.y - model.y, corrected.y)
    assert residuals.by_role("residual").y.size == raw.y.size
    assert "Set-up identified" in view.set_summary.call_args.args[0]
    view.settings_values.return_value = {"method": "azimuth"}
    presenter.settings_edited()
    presenter.refresh()
    assert presenter.result.identification.method == "azimuth"
    assert any("absorb" in w for w in view.set_warnings.call_args.args[0])


@pytest.mark.slow
def test_polygon_presenter_marks_a_failed_closure_and_tells_a_bad_certificate(qtbot, samples_dir,
                                                                               tmp_path):
    presenter, view = make(PolygonPresenter, PolygonView, qtbot)
    load(presenter, samples_dir)
    errors, residuals, tilt, harmonics = view.show_figures.call_args.args
    raw, correction, corrected = (errors.by_role(r) for r in ("raw", "model", "corrected"))
    np.testing.assert_allclose(raw.y + correction.y, corrected.y, atol=1e-9)
    assert len(raw.x) == 24 and residuals is not None and tilt is not None
    assert harmonics.series[0].y.size == 12
    presenter.table_model.set_cells([(24, 3, "25.0")])  # the closure reading far off
    presenter.refresh()
    view.append_to_readings_caption.assert_called_with(" — RUN INVALID (closure failed)")
    bad = tmp_path / "cert.csv"
    bad.write_text("1,0.1\n1,0.2\n")
    view.ask_certificate_file.return_value = str(bad)
    presenter.load_certificate_dialog()
    title, text = view.tell.call_args.args
    assert title == "Cannot read certificate" and "position 1 appears twice" in text
    view.ask_certificate_file.return_value = ""  # cancelled: nothing asked, nothing changed
    view.tell.reset_mock()
    presenter.load_certificate_dialog()
    view.tell.assert_not_called()


def test_fringe_presenter_hands_the_view_every_curve_and_exports(qtbot, samples_dir, tmp_path):
    presenter, view = make(FringePresenter, FringeView, qtbot)
    load(presenter, samples_dir)
    drawn = view.show_figures.call_args.args[0]
    raw, comp = drawn["errors"].by_role("raw"), drawn["errors"].by_role("corrected")
    assert len(raw.x) == len(raw.y) == len(comp.y) > 0
    assert drawn["errors"].y_label == "interp. error (\")"
    measured, ellipse, _ = drawn["lissajous"].series
    assert len(ellipse.x) == 361 and len(measured.x) == 512
    out = tmp_path / "table.csv"
    view.ask_table_path.return_value = str(out)
    presenter.export_table_dialog()
    assert out.read_text().startswith("# AngleBench fringe correction table")


@pytest.mark.parametrize("presenter_class, view_class", [
    (TheodolitePresenter, TheodoliteView), (PolygonPresenter, PolygonView),
    (FringePresenter, FringeView)])
def test_unreadable_readings_clear_the_view(qtbot, presenter_class, view_class):
    presenter, view = make(presenter_class, view_class, qtbot)
    presenter.table_model.replace_all([["x"] * len(presenter.kind.columns)] * 3)
    presenter.refresh()
    view.clear_result.assert_called()
    assert view.set_summary.call_args.args[0].startswith("No result")
