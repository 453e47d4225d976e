"""The coverage intervals of the axis figures (#39): seeded from the readings, the truth of
the simulation rig agreeing with the standard's formulas, a bias the plain Monte Carlo left
in, and a smoke version of the coverage study (the study itself: anglebench validate and
tests/benchmarks/test_positioning_figures.py)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from models.positioning.figure_intervals import axis_figures, figure_intervals, world_truth
from models.validation.axis_figures_rig import SHAPES, AxisCase, true_figures


def _stats(case: AxisCase, rng):
    """x̄, s, n per direction from one simulated test (numpy only, as a user would)."""
    pos = {a: i for i, a in enumerate(case.angles)}
    dev = {d: [[] for _ in case.angles] for d in ("up", "down")}
    for angle, _, sign, x in case.readings(rng):
        dev["up" if sign == "+" else "down"][pos[angle]].append(x)
    means = {d: np.array([np.mean(v) for v in dev[d]]) for d in dev}
    sds = {d: np.array([np.std(v, ddof=1) for v in dev[d]]) for d in dev}
    runs = {d: np.array([len(v) for v in dev[d]]) for d in dev}
    return means, sds, runs


@pytest.mark.parametrize("shape", SHAPES)
def test_rig_truth_is_the_standards_figures_of_the_true_distribution(shape):
    """The rig's own truth and the workbench's formulas, fed the true μ and σ, agree."""
    case = AxisCase(shape, 12, 0.5, varying=True, seed=2)
    ours = world_truth(case.mu, case.sigma)
    for key, value in true_figures(case.mu["up"], case.mu["down"], case.sigma["up"],
                                   case.sigma["down"]).items():
        assert ours[key] == pytest.approx(value, abs=1e-12), key


def test_same_readings_same_intervals_and_r_bias_handled():
    """A flat axis with σ = 1 everywhere: R↑ = 4 max s over 12 targets is biased high (the
    measured R↑ is above the truth 4σ in most tests); the interval, seeded from the readings,
    is the same for the same readings and holds the truth, where the measured value ±
    its scatter did not."""
    case = AxisCase("smooth", 12, 20.0, seed=1)  # the curve is 1/40 of the scatter: flat
    rng = np.random.default_rng(3)
    covered, above = 0, 0
    for k in range(4):
        means, sds, runs = _stats(case, rng)
        first = figure_intervals(means, sds, runs, 0.9545, seed=k)
        again = figure_intervals(means, sds, runs, 0.9545, seed=k)
        assert first["R_up"] == again["R_up"]
        truth = 4.0 * case.sigma["up"].max()
        above += first["R_up"].value > truth
        covered += first["R_up"].low <= truth <= first["R_up"].high
    assert above >= 3 and covered >= 3


def test_b_mean_interval_is_the_mean_of_the_reversals_u():
    """B̄ is linear in the means: its interval is ± 2 √(Σ (s↑² + s↓²)/n)/m by hand, here
    up to a third wider (each target's scatter taken as the larger of its own s and the
    moderated σ: on the safe side)."""
    case = AxisCase("sample", 24, 0.5, seed=4)
    means, sds, runs = _stats(case, np.random.default_rng(5))
    b_mean = figure_intervals(means, sds, runs, 0.9545, seed=1)["B_mean"]
    hand = 2.0 * math.sqrt(float(np.sum(sds["up"] ** 2 + sds["down"] ** 2)) / 5) / 24
    assert 0.9 * hand < b_mean.value - b_mean.low < 1.35 * hand
    assert 0.9 * hand < b_mean.high - b_mean.value < 1.35 * hand


def test_axis_figures_of_one_row_are_world_truth():
    rng = np.random.default_rng(0)
    mu = {d: rng.normal(size=7) for d in ("up", "down")}
    sigma = {d: rng.uniform(0.1, 1.0, 7) for d in ("up", "down")}
    row = axis_figures({d: (mu[d][None, :], sigma[d][None, :]) for d in mu})
    assert {k: float(v[0]) for k, v in row.items()} == world_truth(mu, sigma)


def test_json_gives_each_figure_with_its_interval(tmp_path, capsys):
    """`analyze positioning --json`: each figure an object beside the old keys, the same
    numbers for the same readings."""
    from pathlib import Path

    from app.main import main

    path = str(Path(__file__).parents[3] / "resources" / "samples" / "positioning_sample.csv")
    outputs = []
    for _ in range(2):
        assert main(["analyze", "positioning", path, "--json"]) == 0
        outputs.append(json.loads(capsys.readouterr().out))
    data = outputs[0]
    assert outputs[0]["iso230_2_figures"] == outputs[1]["iso230_2_figures"]
    assert data["coverage_probability"] == pytest.approx(0.9545, abs=1e-4)
    assert data["figure_intervals_reason"] is None
    for key, value in data["iso230_2"].items():
        figure = data["iso230_2_figures"][key]
        assert figure["value"] == pytest.approx(value)
        assert figure["interval_low"] <= figure["interval_high"]
        assert 0.5 < figure["coverage_probability"] <= 0.9545 + 1e-9
    for key, value in data["vdi3441"].items():
        assert data["vdi3441_figures"][key]["value"] == pytest.approx(value)


def test_results_sheet_has_the_intervals_as_numbers():
    """--results: the interval cell "a″ … b″" and "p %" become number columns."""
    from app.writers.results_export import _figure_columns
    from models.certificate.metadata import CertificateMetadata
    from models.positioning.analysis import POSITIONING
    from models.readings.sheet import ReadingsSheet

    case = AxisCase("sample", 12, 0.3, seed=6)
    rows = [[f"{t:.6f}", str(run), sign, f"{x:.6f}", ""]
            for t, run, sign, x in case.readings(np.random.default_rng(7))]
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), {})
    document = POSITIONING.certificate(result, CertificateMetadata())
    header, cells = _figure_columns(document.statistics.header, document.statistics.rows)
    low = header.index("Coverage interval (from) (\")")
    high = header.index("Coverage interval (to) (\")")
    first = cells[0]
    assert isinstance(first[low], float) and isinstance(first[high], float)
    assert first[low] <= first[high]
    assert isinstance(first[header.index("Probability (%)")], float)


@pytest.mark.slow
def test_coverage_study_smoke():
    """A few tests of two axes through the whole analysis: every figure has an interval and
    most of them hold the truth (the full study: the benchmark)."""
    from models.positioning.figure_coverage import FIGURES, coverage_study

    study = coverage_study([AxisCase("sample", 12, 0.5, seed=1),
                            AxisCase("spike", 12, 2.0, varying=True, seed=2)], tests=4)
    for key in FIGURES:
        assert study[key].tests == 8, key
        assert study[key].hits >= 5, key
