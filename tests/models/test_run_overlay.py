"""Two runs overlaid (issue 31, item 10b): another run of the same workbench — a readings
file, a project file, a certificate from the register — drawn against today's on the same
axes, clearly labelled, following the angle unit, and removable."""

from __future__ import annotations

import csv
import json

import numpy as np
import pytest

from app.certificate_issue import issue_certificate
from models.certificate.metadata import CertificateMetadata
from models.display_units import ANGLE_UNITS
from models.project.file import Project, WorkbenchState, save_project
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from models.run_overlay import overlay_from_file


def _rows(samples_dir, key):
    kind = KINDS[key]
    return kind, map_columns(read_table(samples_dir / kind.sample_file), kind.columns)


def _corrected(kind, rows, settings=None):
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                          kind.settings_with_defaults(settings or {}))
    order = np.argsort(result.theta_deg, kind="stable")
    return result.theta_deg[order], result.corrected_error_arcsec[order]


def _earlier_theodolite(samples_dir, tmp_path):
    """The sample run with the axis 2" worse at every point past θ = 0 (an earlier run)."""
    kind, rows = _rows(samples_dir, "theodolite")
    parsed = ReadingsSheet(kind.columns, rows).parse()
    earlier = [[r[0], f"{a - (2.0 / 3600 if t > 0 else 0.0):.10f}", r[2]]
               for r, t, a in zip(rows, parsed["theta_deg"], parsed["azimuth_deg"], strict=True)]
    path = tmp_path / "before_compensation.csv"
    with path.open("w", newline="", encoding="utf-8") as out:
        csv.writer(out).writerows([["theta_deg", "azimuth_deg", "elevation_deg"], *earlier])
    return kind, earlier, path


def _open(window, key, qtbot):
    presenter = window.presenter(key)
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.result is not None, timeout=10000)
    return presenter


@pytest.mark.slow
def test_a_readings_file_is_overlaid_labelled_in_unit_and_removable(window, qtbot, samples_dir,
                                                                    tmp_path):
    presenter = _open(window, "theodolite", qtbot)
    kind, earlier, path = _earlier_theodolite(samples_dir, tmp_path)
    today_x, today_y = presenter.view.error_plot.corrected_curve.getData()
    assert window.run_overlays.overlay_file(str(path))
    overlay = window.run_overlays.overlays["theodolite"]
    plot = presenter.view.error_plot.corrected_plot
    assert overlay.curve in plot.listDataItems()
    assert presenter.view.error_plot.corrected_curve in plot.listDataItems()
    x, y = overlay.curve.getData()
    expected_x, expected_y = _corrected(kind, earlier)
    np.testing.assert_allclose(x, expected_x)
    np.testing.assert_allclose(y, expected_y, atol=1e-9)
    sample_x, sample_y = _corrected(*_rows(samples_dir, "theodolite"))
    np.testing.assert_allclose(today_y, sample_y, atol=1e-9)  # today's curve is untouched
    np.testing.assert_allclose(presenter.view.error_plot.corrected_curve.getData()[1], today_y)
    # the earlier run differs by the 2" put into it (the set-up identified takes a share)
    assert np.max(np.abs(y - sample_y)) > 1.0
    label = presenter.view.error_plot.corrected_legend.getLabel(overlay.curve)
    assert label is not None and "before_compensation.csv" in label.text
    lo, hi = plot.getViewBox().viewRange()[1]
    assert lo <= np.min(y) and np.max(y) <= hi  # both curves in view
    presenter.set_angle_unit(ANGLE_UNITS["urad"])
    np.testing.assert_allclose(overlay.curve.getData()[1],
                               expected_y * ANGLE_UNITS["urad"].per_arcsec, atol=1e-8)
    window.menus.remove_overlay_action.trigger()
    assert overlay.curve not in plot.listDataItems()
    assert presenter.view.error_plot.corrected_legend.getLabel(overlay.curve) is None
    assert len(overlay.curve.getData()[0] if overlay.curve.getData()[0] is not None else []) == 0
    assert presenter.view.error_plot.corrected_curve in plot.listDataItems()


@pytest.mark.slow
def test_the_overlay_stays_while_todays_readings_change(window, qtbot, samples_dir, tmp_path):
    presenter = _open(window, "theodolite", qtbot)
    kind, earlier, path = _earlier_theodolite(samples_dir, tmp_path)
    assert window.run_overlays.overlay_file(str(path))
    overlay = window.run_overlays.overlays["theodolite"]
    before = overlay.curve.getData()[1].copy()
    presenter.table_model.setData(presenter.table_model.index(3, 1), "-16.9")
    qtbot.waitUntil(lambda: presenter.result is not None and
                    presenter.result.theta_deg.size == 41, timeout=10000)
    np.testing.assert_allclose(overlay.curve.getData()[1], before)


def test_a_project_file_is_overlaid_with_its_own_settings(tmp_path, samples_dir):
    kind, rows = _rows(samples_dir, "theodolite")
    path = tmp_path / "earlier.anglebench.json"
    save_project(path, Project({"theodolite": WorkbenchState(rows, {"reference_row": 30})}))
    run = overlay_from_file(kind, path, kind.settings_with_defaults({}))
    expected_x, expected_y = _corrected(kind, rows, {"reference_row": 30})
    np.testing.assert_allclose(run.x, expected_x)
    np.testing.assert_allclose(run.y, expected_y, atol=1e-9)
    assert run.label == "earlier.anglebench.json"
    other = tmp_path / "polygon_only.anglebench.json"
    save_project(other, Project({"polygon": WorkbenchState([["1"]], {})}))
    with pytest.raises(ValueError, match="holds no readings of the Theodolite run workbench"):
        overlay_from_file(kind, other, {})


@pytest.mark.slow
def test_the_register_s_earlier_certificate_is_overlaid(window, qtbot, samples_dir, tmp_path):
    kind, rows = _rows(samples_dir, "polygon")
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": ""})
    with window.certificates.open_register() as register:
        record = issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                   kind.checked_settings({}), rows, "polygon_sample.csv",
                                   str(tmp_path / "earlier.pdf"))
    presenter = _open(window, "polygon", qtbot)
    changed = [list(r) for r in rows]
    changed[5][3] = f"{float(changed[5][3]) + 1.5:.2f}"  # today's face 6 reads 1.5" more
    presenter.table_model.setData(presenter.table_model.index(5, 3), changed[5][3])
    qtbot.waitUntil(lambda: presenter.result is not None and
                    abs(presenter.result.mean_corrected_arcsec[5] -
                        result.mean_corrected_arcsec[5]) > 0.5, timeout=10000)
    offered = []
    window.run_overlays.choose_record = lambda labels: offered.extend(labels) or 0
    assert window.run_overlays.overlay_record()
    assert offered[0].startswith(record.number)
    overlay = window.run_overlays.overlays["polygon"]
    x, y = overlay.curve.getData()
    np.testing.assert_allclose(x, result.theta_deg)
    np.testing.assert_allclose(y, result.mean_corrected_arcsec, atol=1e-9)
    _, today = presenter.view.error_plot.corrected_curve.getData()
    np.testing.assert_allclose(today, presenter.result.mean_corrected_arcsec)
    assert record.number in presenter.view.error_plot.corrected_legend.getLabel(
        overlay.curve).text


@pytest.mark.slow
def test_another_workbench_s_file_or_a_workbench_without_curve_is_refused(window, qtbot,
                                                                          samples_dir):
    _open(window, "theodolite", qtbot)
    assert not window.run_overlays.overlay_file(str(samples_dir / "positioning_sample.csv"))
    assert "positioning_sample.csv: row 1 (header): no column 'theta_deg'" in window.told[-1]
    assert "theodolite" not in window.run_overlays.overlays or \
        not window.run_overlays.overlays["theodolite"].shown
    # positioning: no error curve; its log after compensation is compared instead
    # (tests/widgets/positioning/test_positioning_after_compensation_window.py), a certificate is refused
    window.tabs.setCurrentIndex(window.presenters.index(window.presenter("positioning")))
    assert not window.run_overlays.overlay_record()
    assert "no error curve" in window.told[-1]
