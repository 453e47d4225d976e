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
from tests.pseudo_translation import pseudo_translated
from widgets.fringe.presenter import FringePresenter
from widgets.fringe.view import FringeView
from widgets.polygon.presenter import PolygonPresenter
from widgets.polygon.view import PolygonView
from widgets.positioning.presenter import PositioningPresenter
from widgets.positioning.view import PositioningView
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


@pytest.mark.slow
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
    bad = tmp_path / "cert.csv"
    bad.write_text("1,0.1\n1,0.2\n")
    view.ask_certificate_file.return_value = str(bad)
    short = tmp_path / "short.csv"
    short.write_text("1,0.1\n2,0.2\n")
    with pseudo_translated():  # what the presenter says goes through the translations
        presenter.table_model.set_cells([(24, 3, "25.0")])  # the closure reading far off
        presenter.refresh()
        caption = view.append_to_readings_caption.call_args.args[0]
        presenter.load_certificate_dialog()
        title, text = view.tell.call_args.args
        view.ask_certificate_file.return_value = str(short)
        presenter.load_certificate_dialog()
        missing = view.tell.call_args.args[1]
        undo_before = presenter.undo_stack.count()
        good = tmp_path / "good.csv"
        good.write_text("".join(f"{i},0.{i:02d}\n" for i in range(1, 25)))
        view.ask_certificate_file.return_value = str(good)
        presenter.load_certificate_dialog()
        undo_text = presenter.undo_stack.text(undo_before)
    assert not presenter.result.valid
    assert all(said.startswith("‹") and said.endswith("›")
               for said in (caption, title, text, missing, undo_text))
    # a models Message: its template translated, the file and position put in after
    assert str(bad) in text
    assert str(short) in missing and "position 3 (row 3" in missing
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


@pytest.mark.slow
def test_positioning_presenter_flags_few_runs_and_tells_what_it_cannot_write(qtbot, samples_dir,
                                                                             tmp_path):
    presenter, view = make(PositioningPresenter, PositioningView, qtbot)
    presenter.export_compensation_dialog()  # no result yet: nothing asked
    view.ask_compensation_path.assert_not_called()
    rows = map_columns(read_table(samples_dir / presenter.kind.sample_file), presenter.kind.columns)
    presenter.table_model.replace_all([r for r in rows if r[1] in ("1", "2", "3")])
    presenter.refresh()
    deviation, _, readings = view.show_figures.call_args.args
    assert len(readings.series) == 6  # three runs each way …
    view.append_to_readings_caption.assert_called_with(" — fewer than 5 runs: flagged")  # … flagged
    view.append_to_readings_caption.reset_mock()
    load(presenter, samples_dir)
    view.append_to_readings_caption.assert_not_called()  # five runs: no flag
    view.ask_compensation_path.return_value = ""  # cancelled: nothing written, nothing told
    presenter.export_compensation_dialog()
    assert view.ask_compensation_path.call_args.args == ("compensation.csv", "csv")
    view.show_status.assert_not_called()
    view.tell.assert_not_called()
    view.ask_compensation_path.return_value = str(tmp_path / "no" / "such" / "dir" / "c.csv")
    presenter.export_compensation_dialog()
    title, text = view.tell.call_args.args
    assert title == "Cannot export the compensation table" and "c.csv" in text
    view.show_status.assert_not_called()
    assert not (tmp_path / "no").exists()


@pytest.mark.slow
def test_positioning_presenter_asks_the_controller_options_and_keeps_them(qtbot, samples_dir,
                                                                         tmp_path):
    presenter, view = make(PositioningPresenter, PositioningView, qtbot)
    load(presenter, samples_dir)
    presenter.set_settings({**presenter.settings, "compensation_format": "fanuc",
                            "compensation_tables": "bidirectional", "compensation_step": 30.0,
                            "compensation_controller_options": "axis=4, modulo=360"})
    presenter.refresh()
    view.ask_controller_options.return_value = None  # cancelled: no file asked for
    presenter.export_compensation_dialog()
    controller, fields = view.ask_controller_options.call_args.args
    assert controller == "FANUC"
    values = {key: value for key, _, value in fields}
    assert values["axis"] == "4" and values["modulo"] == "360"  # the set-up's text, read
    assert values["detection_unit"] == "0.001" and values["reference_number"] == "-1"  # defaults
    assert all(help_text for _, help_text, _ in fields)
    view.ask_compensation_path.assert_not_called()
    assert presenter.settings["compensation_controller_options"] == "axis=4, modulo=360"
    view.ask_controller_options.return_value = {**values, "axis": " 2 ", "reference": ""}
    out = tmp_path / "PITCH.TXT"
    view.ask_compensation_path.return_value = str(out)
    presenter.export_compensation_dialog()
    assert view.ask_compensation_path.call_args.args == ("PITCH.TXT", "fanuc")
    kept = presenter.settings["compensation_controller_options"]
    assert kept.startswith("axis=2, detection_unit=0.001,") and "reference=" not in kept
    assert out.is_file() and "FANUC" in view.show_status.call_args.args[0]
    presenter.set_settings({**presenter.settings, "compensation_controller_options": "axis"})
    view.ask_controller_options.reset_mock()
    presenter.export_compensation_dialog()  # text that does not read: told, no form
    view.ask_controller_options.assert_not_called()
    title, text = view.tell.call_args.args
    assert title == "Cannot export the compensation table" and "'axis' is not KEY=VALUE" in text


@pytest.mark.parametrize("presenter_class, view_class", [
    (TheodolitePresenter, TheodoliteView), (PolygonPresenter, PolygonView),
    (FringePresenter, FringeView), (PositioningPresenter, PositioningView)])
def test_unreadable_readings_clear_the_view(qtbot, presenter_class, view_class):
    presenter, view = make(presenter_class, view_class, qtbot)
    presenter.table_model.replace_all([["x"] * len(presenter.kind.columns)] * 3)
    presenter.refresh()
    view.clear_result.assert_called()
    assert view.set_summary.call_args.args[0].startswith("No result")


def test_fringe_refusal_is_said_once_and_the_folded_order_is_warned(qtbot):
    """Day review 67 F5, in the fringe workbench: the refusal's long sentence stood both in
    the bold line and in the pane below it; following its advice (highest harmonic 3 at
    N = 8) gave a result with no remark, A3 holding the 5th. Channels from first principles
    (tests/fringe_channels.py)."""
    from tests.fringe_channels import Channels, equal_steps

    head = Channels(amplitudes_v=(0.5, 0.49), noise_v=0.0003,
                    sin_harmonics={3: (0.005, 0.4), 5: (0.004, 1.1)},
                    cos_harmonics={3: (0.003, -0.3), 5: (0.0025, 0.2)})
    u_sin, u_cos = head.sample(equal_steps(64 * 8, 8), np.random.default_rng(4))
    presenter, view = make(FringePresenter, FringeView, qtbot)
    keys = [c.key for c in presenter.sheet.columns]
    presenter.table_model.replace_all([[{"u_sin": f"{s:.9f}", "u_cos": f"{c:.9f}"}.get(k, "")
                                        for k in keys] for s, c in zip(u_sin, u_cos,
                                                                        strict=True)])
    presenter.set_settings({**presenter.settings, "samples_per_period": 8, "max_order": 5})
    presenter.refresh()
    qtbot.waitUntil(lambda: bool(presenter.problem))
    summary = view.set_summary.call_args.args[0]
    assert summary.startswith("No result") and "orders 3 and 5 alias at N = 8" in summary
    verdict = view.set_verdict.call_args.args[0]
    assert verdict.startswith("No result") and "alias" not in verdict  # said once, below
    presenter.set_settings({**presenter.settings, "max_order": 3})
    presenter.refresh()
    qtbot.waitUntil(lambda: presenter.result is not None)
    shown = " ".join(view.set_warnings.call_args.args[0])
    assert "A3 and B3 hold any harmonic of order 5: orders 5 and 3 alias at N = 8" in shown
