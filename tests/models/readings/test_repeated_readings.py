"""Repeated readings per point (issue 31, item 10a): n readings of one θ point, target or
face are averaged, and their s/√n (ν = n − 1) enters the budget as a Type A input (the
theodolite's: one candidate of its one reading-error input, #39).

The repeated readings are simulated here: the bundled samples' readings are taken as the
truth and each is read n times with Gaussian noise of a known σ (numpy only; nothing from
the averaging code). The expected averages and standard deviations of the mean are
computed from the noise that was drawn.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PySide6.QtGui import QGuiApplication

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.project.file import Project, WorkbenchState, load_project, save_project
from models.readings.repeats import average_repeats
from models.readings.sheet import Column, ColumnKind, ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

META = CertificateMetadata.from_dict({"standards": [
    {"description": "Reference AC", "uncertainty": 0.4}]})
TYPE_A = "Repeated readings (s/√n)"


def _sample(key, samples_dir):
    kind = KINDS[key]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    return kind, rows, ReadingsSheet(kind.columns, rows).parse()


def _analyse(kind, rows, **settings):
    return kind.analyze(ReadingsSheet(kind.columns, rows).parse(),
                        kind.settings_with_defaults(settings))


def _component(budget, name):
    return next(c for c in budget.components if c.name == name)


# -- the averaging itself ---------------------------------------------------------------------

COLUMNS = (Column("point", "p", "", ColumnKind.INTEGER),
           Column("angle", "a", "deg", ColumnKind.ANGLE_DEG),
           Column("x", "x", "", ColumnKind.NUMBER, required=False),
           Column("dir", "d", "", ColumnKind.TEXT, required=False, choices=("+", "-")))


def _average(rows, n):
    parsed = ReadingsSheet(COLUMNS, rows).parse()
    return average_repeats(parsed, n, ("point", "dir"), ("angle", "x"), angles=("angle",))


@pytest.mark.slow
@settings(max_examples=80, deadline=None)
@given(st.integers(2, 6), st.integers(1, 5), st.data())
def test_mean_and_standard_deviation_of_the_mean_of_any_readings(n, points, data):
    values = np.array(data.draw(st.lists(st.floats(-1e4, 1e4), min_size=n * points,
                                         max_size=n * points))).reshape(points, n)
    rows = [[str(p + 1), f"{10.0 + p}", repr(float(v)), "+"] for p in range(points)
            for v in values[p]]
    averaged, repeats = _average(rows, n)
    assert averaged.n == points and repeats.n == n and repeats.dof == n - 1
    for p in range(points):
        expected_mean = sum(values[p].tolist()) / n
        expected_s = math.sqrt(sum((v - expected_mean) ** 2 for v in values[p].tolist()) /
                               (n - 1)) / math.sqrt(n)
        assert averaged["x"][p] == pytest.approx(expected_mean, rel=1e-9, abs=1e-9)
        assert repeats.s_mean["x"][p] == pytest.approx(expected_s, rel=1e-7, abs=1e-9)
    np.testing.assert_array_equal(repeats.rows, np.arange(n * points).reshape(points, n))
    np.testing.assert_array_equal(averaged.row_index, np.arange(0, n * points, n))


def test_one_reading_per_point_changes_nothing():
    parsed = ReadingsSheet(COLUMNS, [["1", "1", "2", "+"], ["1", "1", "3", "+"]]).parse()
    same, repeats = average_repeats(parsed, 1, ("point",), ("x",))
    assert same is parsed and repeats is None


def test_angles_either_side_of_zero_average_where_they_are():
    averaged, repeats = _average([["1", "359.9999", "", ""], ["1", "0.0001", "", ""],
                                  ["1", "0.0003", "", ""]], 3)
    assert averaged["angle"][0] == pytest.approx(360.0001, abs=1e-9)
    s = np.std([-0.0001, 0.0001, 0.0003], ddof=1) / math.sqrt(3)
    assert repeats.s_mean["angle"][0] == pytest.approx(s, rel=1e-6)
    assert np.isnan(averaged["x"][0])  # blank in every reading: blank


@pytest.mark.parametrize("rows, n, words", [
    ([["1", "1", "2", ""], ["1", "1", "2", ""], ["2", "2", "2", ""]], 2,
     "the last point has 1 (row 3 on)"),
    ([["1", "1", "2", ""], ["2", "1", "2", ""]], 2,
     "rows 2 and 1 are readings 2 and 1 of one point (2 readings per point), but their "
     "'point' differs"),
    ([["1", "1", "2", "+"], ["1", "1", "2", "-"]], 2, "'dir' differs"),
    ([["1", "1", "2", ""], ["1", "1", "", ""]], 2, "row 2: 'x' is blank"),
])
def test_a_group_that_is_not_one_point_is_refused_naming_its_rows(rows, n, words):
    with pytest.raises(ValueError, match=words.replace("(", r"\(").replace(")", r"\)")):
        _average(rows, n)


# -- round trips through each workbench -------------------------------------------------------

@pytest.mark.parametrize("key", ["theodolite", "positioning", "polygon"])
@pytest.mark.slow
def test_n_identical_readings_give_the_single_reading_result_exactly(key, samples_dir):
    kind, rows, _ = _sample(key, samples_dir)
    single = json.dumps(kind.to_json(_analyse(kind, rows)))
    assert json.dumps(kind.to_json(_analyse(kind, rows, readings_per_point=1))) == single
    tripled = [list(r) for r in rows for _ in range(3)]
    result = _analyse(kind, tripled, readings_per_point=3)
    assert json.dumps(kind.to_json(result)) == single
    budget = kind.certificate_document(result, META).budget
    if key == "theodolite":  # s/√n = 0 is one candidate of the reading error (#39): U as before
        assert not any(c.name == TYPE_A for c in budget.components)
        once = kind.certificate_document(_analyse(kind, rows), META).budget
        np.testing.assert_allclose(budget.expanded, once.expanded, rtol=1e-12)
    else:
        assert np.all(np.asarray(_component(budget, TYPE_A).value) == 0.0)


def test_theodolite_noisy_repeats_average_and_their_s_mean_counts_once(samples_dir):
    """The theodolite's n readings are averaged; their s/√n, pooled over the points
    (ν = points · (n − 1)), is part of the one reading-error input, with the standard's u:
    max(s_fit, √(u_std² + (s/√n)²)) (#39: the fit's scatter of the means already holds the
    means' noise, so s/√n is not a second input beside it)."""
    kind, rows, truth = _sample("theodolite", samples_dir)
    n, sigma = 4, 0.5  # arcsec
    rng = np.random.default_rng(31)
    noise_a = rng.normal(0.0, sigma, (truth.n, n))
    noise_e = rng.normal(0.0, sigma, (truth.n, n))
    az, el = truth["azimuth_deg"], truth["elevation_deg"]
    repeated = [[rows[i][0], f"{az[i] + noise_a[i, j] / 3600:.10f}",
                 f"{el[i] + noise_e[i, j] / 3600:.10f}", "", ""]
                for i in range(truth.n) for j in range(n)]
    result = _analyse(kind, repeated, readings_per_point=n)
    mean_rows = [[rows[i][0], f"{az[i] + noise_a[i].mean() / 3600:.10f}",
                  f"{el[i] + noise_e[i].mean() / 3600:.10f}", "", ""] for i in range(truth.n)]
    of_means = _analyse(kind, mean_rows)
    np.testing.assert_allclose(result.corrected_error_arcsec, of_means.corrected_error_arcsec,
                               atol=2e-5)
    exact = _analyse(kind, rows)
    assert np.max(np.abs(result.corrected_error_arcsec - exact.corrected_error_arcsec)) < \
        5 * sigma / math.sqrt(n) * math.sqrt(2)
    s_mean = noise_a.std(axis=1, ddof=1) / math.sqrt(n)
    pooled = math.sqrt(np.mean(s_mean**2))
    # the s of the means scatter about σ/√n (41 points × 3 degrees of freedom)
    assert pooled == pytest.approx(sigma / math.sqrt(n), rel=0.15)
    budget = kind.certificate_document(result, META).budget
    assert not any(c.name.startswith("Repeated readings") for c in budget.components)
    reading = _component(budget, "Reading error (pointing)")
    dof_fit = truth.n - 3
    s_fit = math.sqrt(np.sum(result.elevation_residuals_arcsec**2) / dof_fit)
    u_std = 0.4 / 2  # META's standard, U95 → u = 0.2″, not divided by √n
    both = math.hypot(u_std, pooled)
    expected = max(s_fit, both)
    assert reading.value == pytest.approx(expected, abs=2e-5)
    nu = truth.n * (n - 1)
    assert reading.dof == (math.floor(both**4 / (pooled**4 / nu)) if both > s_fit else dof_fit)
    # the means' noise once: √2 · u_read at a point with the set-up model's share
    ref = result.reference_index
    k = 5 if ref != 5 else 6
    model = float(np.broadcast_to(result.model_uncertainty_arcsec, (truth.n,))[k])
    assert budget.combined[k] == pytest.approx(math.sqrt(2 * expected**2 + model**2), rel=1e-6)


@pytest.mark.slow
def test_positioning_noisy_repeats_per_approach(samples_dir):
    kind, rows, truth = _sample("positioning", samples_dir)
    n, sigma = 3, 0.8
    noise = np.random.default_rng(7).normal(0.0, sigma, (truth.n, n))
    dev = truth["deviation"]
    repeated = [[rows[i][0], rows[i][1], rows[i][2], f"{dev[i] + noise[i, j]:.9f}", ""]
                for i in range(truth.n) for j in range(n)]
    result = _analyse(kind, repeated, readings_per_point=n)
    np.testing.assert_allclose(result.deviations, dev + noise.mean(axis=1), atol=1e-8)
    s_mean = noise.std(axis=1, ddof=1) / math.sqrt(n)
    targets = np.array([float(r[0]) for r in rows])
    signs = np.array([1.0 if r[2] == "+" else -1.0 for r in rows])
    expected = []
    for sign in (1.0, -1.0):
        for t in np.unique(targets):
            here = (targets == t) & (signs == sign)
            expected.append(math.sqrt(np.sum(s_mean[here] ** 2)) / np.sum(here))
    budget = kind.certificate_document(result, META).budget
    component = _component(budget, TYPE_A)
    np.testing.assert_allclose(component.value, expected, atol=1e-8)
    assert component.dof == n - 1
    assert _component(budget, "Repeatability of the mean (s/√n)").dof == \
        _component(kind.certificate_document(_analyse(kind, rows), META).budget,
                   "Repeatability of the mean (s/√n)").dof


def test_polygon_noisy_repeats_per_face(samples_dir):
    kind, rows, truth = _sample("polygon", samples_dir)
    n, sigma = 2, 0.3
    rng = np.random.default_rng(3)
    noise_x = rng.normal(0.0, sigma, (truth.n, n))
    noise_a = rng.normal(0.0, sigma, (truth.n, n))
    a, x = truth["encoder_deg"], truth["ac_x_arcsec"]
    repeated = [[rows[i][0], f"{a[i] + noise_a[i, j] / 3600:.10f}", rows[i][2],
                 f"{x[i] + noise_x[i, j]:.8f}", rows[i][4], rows[i][5], rows[i][6]]
                for i in range(truth.n) for j in range(n)]
    result = _analyse(kind, repeated, readings_per_point=n)
    u = np.hypot(noise_a.std(axis=1, ddof=1), noise_x.std(axis=1, ddof=1)) / math.sqrt(n)
    sets = np.array([int(r[5]) for r in rows])
    per_set = []
    for s in np.unique(sets):
        index = np.nonzero(sets == s)[0][:-1]  # the last row of a set is its closure reading
        faces = np.zeros(result.faces)
        faces[np.array([int(rows[i][0]) for i in index]) - 1] = u[index]
        per_set.append(faces)
    per_set = np.array(per_set)
    budget = kind.certificate_document(result, META).budget
    component = _component(budget, TYPE_A)
    np.testing.assert_allclose(component.value,
                               np.sqrt(np.sum(per_set**2, axis=0)) / len(per_set), atol=2e-5)
    assert component.dof == n - 1
    single = _analyse(kind, rows)
    assert result.closure_rows == {r for c in single.closure_rows for r in (2 * c, 2 * c + 1)}
    zero = _component(budget, "Repeated readings at the zero face (s/√n)")
    assert zero.value == pytest.approx(per_set[0, result.zero_face - 1], abs=2e-5)


# -- the command line, the project file and the window ----------------------------------------

def _tripled_csv(samples_dir, tmp_path, key, n=3):
    lines = (samples_dir / KINDS[key].sample_file).read_text(encoding="utf-8").splitlines()
    path = tmp_path / f"{key}_x{n}.csv"
    path.write_text("\n".join([lines[0]] + [line for line in lines[1:] for _ in range(n)]) + "\n",
                    encoding="utf-8")
    return path


def test_command_line_takes_readings_per_point(capsys, samples_dir, tmp_path):
    sample = samples_dir / "theodolite_sample.csv"
    assert main(["analyze", "theodolite", str(sample), "--json"]) == 0
    single = capsys.readouterr().out
    tripled = _tripled_csv(samples_dir, tmp_path, "theodolite")
    assert main(["analyze", "theodolite", str(tripled), "--readings-per-point", "3",
                 "--json"]) == 0
    assert capsys.readouterr().out == single
    assert main(["analyze", "theodolite", str(tripled), "--readings-per-point", "2",
                 "--json"]) != 0
    assert "readings per point" in capsys.readouterr().err


@pytest.mark.slow
def test_project_file_keeps_readings_per_point(tmp_path, samples_dir):
    kind, rows, _ = _sample("positioning", samples_dir)
    tripled = [list(r) for r in rows for _ in range(3)]
    path = tmp_path / "repeats.anglebench"
    save_project(path, Project({"positioning": WorkbenchState(tripled,
                                                              {"readings_per_point": 3})}))
    loaded = load_project(path).workbenches["positioning"]
    assert loaded.settings["readings_per_point"] == 3 and loaded.rows == tripled
    again = kind.analyze(ReadingsSheet(kind.columns, loaded.rows).parse(),
                         kind.settings_with_defaults(loaded.settings))
    assert json.dumps(kind.to_json(again)) == json.dumps(kind.to_json(_analyse(kind, rows)))


@pytest.mark.slow
def test_window_pasted_repeats_with_the_setting_averaged(qtbot, samples_dir):
    from widgets.theodolite.presenter import TheodolitePresenter

    presenter = TheodolitePresenter()
    qtbot.addWidget(presenter.view)
    kind, rows, truth = _sample("theodolite", samples_dir)
    noise = np.random.default_rng(5).normal(0.0, 0.4, (truth.n, 3))
    az = truth["azimuth_deg"]
    repeated = [[rows[i][0], f"{az[i] + noise[i, j] / 3600:.10f}", rows[i][2]]
                for i in range(truth.n) for j in range(3)]
    presenter.view.settings.field("readings_per_point").setValue(3)
    QGuiApplication.clipboard().setText("\n".join("\t".join(r) for r in repeated))
    presenter.view.table.setCurrentIndex(presenter.table_model.index(0, 0))
    presenter.view.table.paste_action.trigger()
    qtbot.waitUntil(lambda: presenter.result is not None and presenter.result.repeats is not None
                    and presenter.result.theta_deg.size == truth.n, timeout=10000)
    expected = _analyse(kind, [r + ["", ""] for r in repeated], readings_per_point=3)
    np.testing.assert_allclose(presenter.result.corrected_error_arcsec,
                               expected.corrected_error_arcsec, atol=1e-9)
    x, y = presenter.view.error_plot.corrected_curve.getData()
    assert len(x) == truth.n
    presenter.view.settings.field("readings_per_point").setValue(2)  # 123 rows: not pairs
    qtbot.waitUntil(lambda: presenter.result is None, timeout=10000)


@pytest.mark.slow
def test_typed_entry_fills_a_point_s_nominal_n_times(window, qtbot):
    """With 2 readings per point and a nominal step of 2°, Return after a point's first
    reading keeps its θ, after its second goes on to the next θ; the two typed readings
    of each point are averaged."""
    from PySide6.QtCore import Qt

    presenter = window.presenter("theodolite")
    view, table = presenter.view, presenter.view.table
    view.settings.field("readings_per_point").setValue(2)
    qtbot.waitUntil(lambda: table.readings_per_point == 2)
    view.step.setValue(2.0)
    readings = [("-4.0001", "0.1"), ("-4.0003", "0.1002"), ("-1.9999", "0.2"), ("-2.0001", "0.2")]
    table.setCurrentIndex(presenter.table_model.index(0, 0))
    qtbot.keyClick(table, Qt.Key.Key_F2)
    qtbot.keyClicks(table.focusWidget(), "-4")
    qtbot.keyClick(table.focusWidget(), Qt.Key.Key_Tab)
    for r, (az, el) in enumerate(readings):
        for text in (az, el):
            qtbot.keyClick(table, Qt.Key.Key_F2)
            qtbot.keyClicks(table.focusWidget(), text)
            qtbot.keyClick(table.focusWidget(),
                           Qt.Key.Key_Tab if text == az else Qt.Key.Key_Return)
        qtbot.waitUntil(lambda r=r: table.currentIndex().row() == r + 1, timeout=2000)
    assert [presenter.sheet.text(r, 0) for r in range(5)] == ["-4", "-4", "-2", "-2", "0"]
    parsed = presenter.sheet.parse()
    averaged, repeats = average_repeats(parsed, 2, ("theta_deg", "run", "direction"),
                                        ("azimuth_deg", "elevation_deg"))
    assert averaged["azimuth_deg"].tolist() == pytest.approx([-4.0002, -2.0])
    assert repeats.s_mean["azimuth_deg"][0] == pytest.approx(0.0001, rel=1e-6)
