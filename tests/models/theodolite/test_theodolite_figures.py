"""The ISO 230-2 figures of a theodolite run with passes carry coverage intervals that cover
(issue 39: every summary figure with an interval whose coverage a simulation shows).

The rig is tests/theodolite_passes_simulator.py (numpy only, nothing from the code it
checks): the frame of ../shared/SPEC.md §1, the mirror turned by the axis' TRUE rotation
(Rodrigues), the theodolite reading its normal's azimuth and elevation. The axis' error d
has a reversal: d↑ = d + b/2 forward, d↓ = d − b/2 backward. Each pass reads
every θ once, forward then backward; the runs repeat the passes. Two worlds of the reading
error: pointing noise alone (new in every reading), the theodolite stated at u = σ; or the
circle's own error at each θ (the same in every pass, standard deviation u_c) with a smaller
pointing noise, the theodolite stated at u = √(u_c² + σ²): the means over the passes hold
the circle's errors as if they were the axis', and the interval must hold them.

Truth (as ISO 230-2 defines the figures of the true distribution): E = range of d ± b/2,
M = range of d, B = |b|, B̄ = b, R↑ = R↓ = 4σ, R = 4σ + |b|, A = E + 4σ (the reference
reading θ₀ moves every error alike: no figure sees it).
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy.stats import binom

from tests.theodolite_passes_simulator import passes_record as _run
from tests.theodolite_run_json import run_json


def _figures(capsys, tmp_path, record, stated: float) -> dict:
    return run_json(capsys, tmp_path, record, stated)


#: the runs of the figures' coverage study in the suite (its smoke version) and in its long
#: form (tests/benchmarks/test_theodolite_studies_full.py, ``make bench``), the same check
FIGURES_RUNS = {"smoke": 15, "full": 30}


@pytest.mark.slow
@pytest.mark.parametrize("world", ["pointing", "circle"])
def test_the_iso_230_2_figures_intervals_cover_at_the_probability_printed(
        capsys, tmp_path, world):
    """The smoke version of :func:`check_figures_cover`: 15 runs, each figure's floor the
    binomial test's at 0.1 %; figures with no interval (before 0.8.6) fail it, and so, in
    the circle world, do intervals not widened for the circle's error (A: 7 of 15)."""
    check_figures_cover(capsys, tmp_path, world, FIGURES_RUNS["smoke"], 0.001)


def check_figures_cover(capsys, tmp_path, world: str, runs: int, false_alarm: float) -> None:
    """``runs`` runs of 3 × (forward, backward) passes with a reversal of 0.8": every
    figure's interval covers its truth in at least as many runs as the binomial test
    (``false_alarm``: 1 % in the long form's 30 runs) allows at the probability printed beside
    it. Before 0.8.6 the figures had no interval at all."""
    rng = np.random.default_rng(2026 + len(world))
    sigma, circle = (0.4, 0.0) if world == "pointing" else (0.15, 0.4)
    stated = math.hypot(sigma, circle)
    hits: dict[str, list[bool]] = {}
    probability: dict[str, float] = {}
    for i in range(runs):
        record = tmp_path / f"run{i}.csv"
        truth = _run(record, rng, 3, sigma, 0.8, circle)
        data = _figures(capsys, tmp_path, record, stated)
        assert data["iso230_2_figures_reason"] is None
        for key, true in truth.items():
            fig = data["iso230_2_figures"][key]
            assert fig["value"] == pytest.approx(data["iso230_arcsec"][key])
            hits.setdefault(key, []).append(fig["interval_low"] - 1e-9 <= true
                                            <= fig["interval_high"] + 1e-9)
            probability[key] = fig["coverage_probability"]
    for key, h in hits.items():
        floor = binom.ppf(false_alarm, len(h), probability[key])
        assert sum(h) >= floor, (key, sum(h), len(h), probability[key])


def test_a_theta_read_once_each_way_gives_the_figures_and_says_why_no_interval(
        capsys, tmp_path):
    """One pass each way: the figures of the means are stated, A and R are not (ISO 230-2),
    no figure has an interval, and the JSON and the certificate say why."""
    record = tmp_path / "once.csv"
    _run(record, np.random.default_rng(3), 1, 0.3, 0.5)
    data = _figures(capsys, tmp_path, record, 0.3)
    assert "fewer than twice" in data["iso230_2_figures_reason"]
    figures = data["iso230_2_figures"]
    assert figures["E"]["value"] > 0 and figures["E"]["interval_low"] is None
    assert all(f["interval_high"] is None for f in figures.values())
    # every figure of both directions listed, whatever the readings: A and R null (an audit
    # found their keys missing here)
    assert set(figures) == {"E_up", "R_up", "A_up", "E_down", "R_down", "A_down", "E", "M",
                            "B", "B_mean", "R", "A"}
    assert figures["R"]["value"] is None and figures["A_up"]["value"] is None
    assert "TRUE figure" in data["iso230_2_figures_note"]


def test_the_certificate_prints_each_figure_with_its_interval(tmp_path):
    """The statistics table: ISO 230-2 E with "coverage interval … (p %)" beside it."""
    from models.certificate.metadata import CertificateMetadata, ReferenceStandard
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.theodolite.analysis import THEODOLITE
    from models.theodolite.figures import theodolite_figure_intervals
    from models.theodolite.report import theodolite_budget, theodolite_certificate

    record = tmp_path / "passes.csv"
    truth = _run(record, np.random.default_rng(8), 3, 0.3, 0.6)
    rows = map_columns(read_table(record), THEODOLITE.columns)
    result = THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, rows).parse(),
                                THEODOLITE.settings_with_defaults({}))
    meta = CertificateMetadata(standards=(ReferenceStandard(
        "Autocollimating theodolite", uncertainty=0.3, basis="u"),))
    document = theodolite_certificate(result, meta)
    cells = {row[0]: row for row in document.statistics.rows}
    e = cells["ISO 230-2 E"]
    interval = theodolite_figure_intervals(result, theodolite_budget(result, meta), 0.3)["E"]
    # printed to the digits the interval's width leaves (0.8.15: about 2.5″ wide, to 0.1″)
    printed = re.findall(r"(\d+(?:\.(\d+))?)\"", e[-1])
    assert len(printed) == 2, e[-1]
    # each end rounded outwards from the computed one: within a digit, the interval held
    for (text, decimals), end, side in zip(printed, (interval.low, interval.high), (-1, 1),
                                           strict=True):
        assert abs(float(text) - end) < 10.0 ** -len(decimals) + 1e-12, (e[-1], end)
        assert side * (float(text) - end) >= -1e-12, (e[-1], end)
    assert "coverage interval" in e[-1]
    assert interval.low <= truth["E"] <= interval.high
    # the study's probability to its own digits (day review 66 F8: "92.00 %" of 60–80 runs)
    probability = re.search(r"\((\d+(?:\.\d+)?) %\)", e[-1]).group(1)
    assert float(probability) == pytest.approx(100.0 * interval.probability, abs=1e-9)
    assert not probability.endswith("0"), e[-1]


def test_a_direction_whose_errors_repeat_exactly_gives_no_interval(capsys, tmp_path):
    """Backward readings identical in every pass (rounded coarser than they scatter): R↓
    would get a zero-width interval; no figure gets one, and the JSON says why."""
    record = tmp_path / "coarse.csv"
    _run(record, np.random.default_rng(6), 2, 0.3, 0.5)
    lines = record.read_text().splitlines()
    header, rows = lines[0], [r.split(",") for r in lines[1:]]
    first = {r[0]: r for r in rows if r[3] == "1" and r[4] == "-"}
    rows = [first[r[0]][:3] + r[3:] if r[4] == "-" else r for r in rows]
    record.write_text("\n".join([header] + [",".join(r) for r in rows]) + "\n")
    data = _figures(capsys, tmp_path, record, 0.3)
    assert "identical over the passes in a direction" in data["iso230_2_figures_reason"]
    assert all(f["interval_low"] is None for f in data["iso230_2_figures"].values())


def test_the_intervals_do_not_depend_on_which_budget_asked_first(tmp_path):
    """The summary's budget (no details) and a certificate's (an item resolution stated)
    seed differently; the intervals were cached by (probability, u_b, pair) alone, so the
    certificate printed the summary's when it came second."""
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.theodolite.analysis import THEODOLITE
    from models.theodolite.figures import theodolite_figure_intervals
    from models.theodolite.report import theodolite_budget

    record = tmp_path / "passes.csv"
    _run(record, np.random.default_rng(9), 2, 0.3, 0.5)

    def analysed():
        return THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, map_columns(
            read_table(record), THEODOLITE.columns)).parse(), THEODOLITE.settings_with_defaults({}))

    meta = CertificateMetadata(item_resolution=0.5, item_resolution_unit="arcsec")
    fresh = analysed()
    alone = theodolite_figure_intervals(fresh, theodolite_budget(fresh, meta))
    second = analysed()
    theodolite_figure_intervals(second, theodolite_budget(second, CertificateMetadata()))
    after = theodolite_figure_intervals(second, theodolite_budget(second, meta))
    assert {k: (v.low, v.high) for k, v in alone.items()} == \
        {k: (v.low, v.high) for k, v in after.items()}


def _analysed(record):
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.theodolite.analysis import THEODOLITE
    return THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, map_columns(
        read_table(record), THEODOLITE.columns)).parse(), THEODOLITE.settings_with_defaults({}))


def test_the_set_up_models_error_modes_give_its_u_at_each_theta(tmp_path):
    """The modes the figures draw the set-up model's error from (one set of ψ, α, β for the
    run: correlated from θ to θ) have at each θ the model's standard uncertainty."""
    from models.theodolite.figures import model_at_each_theta, model_modes_at_each_theta

    record = tmp_path / "passes.csv"
    _run(record, np.random.default_rng(21), 2, 0.5, 0.5)
    result = _analysed(record)
    modes = model_modes_at_each_theta(result)
    assert modes.shape == (3, 13)
    u = model_at_each_theta(result)
    assert np.max(u) > 0.02
    np.testing.assert_allclose(np.sqrt(np.sum(modes**2, axis=0)), u, rtol=1e-4, atol=1e-6)


def test_the_circle_part_the_readings_do_not_exclude_holds_the_true_one(tmp_path):
    """Stated u = the pointing noise σ, no circle error: the part of u that the scatter does
    not show, √max(u² − s², 0) (circle_part, drawn at each θ and in the budgets), is above
    0.09″ (0.3 u) in about half the runs by chance. The largest part the readings do not
    exclude (circle_part_not_excluded, over the pointing noise's lower confidence bound at a
    quarter of the tail), which sizes the widening for a circle error of the curve's worst
    shape, is above 0 in every run: readings of a theodolite whose stated u is all pointing
    noise cannot exclude a circle error hidden under it. With a real one (0.4″ under 0.15″
    pointing; or under 1.5″, where the part the readings show at 95 % was 0 in nearly every
    run and the figures missed, #39) it is at least the true 0.4″ in every run."""
    from models.theodolite.figures import circle_part, circle_part_not_excluded

    rng = np.random.default_rng(22)
    none, point, found, hidden = [], [], [], []
    for i in range(30):
        record = tmp_path / f"p{i}.csv"
        _run(record, rng, 2, 0.3, 0.5)
        result = _analysed(record)
        none.append(circle_part_not_excluded(result, 0.3, 0.9545))
        point.append(circle_part(result, 0.3))
        _run(record, rng, 2, 0.15, 0.5, circle=0.4)
        found.append(circle_part_not_excluded(_analysed(record), math.hypot(0.15, 0.4), 0.9545))
        _run(record, rng, 2, 1.5, 0.5, circle=0.4)
        hidden.append(circle_part_not_excluded(_analysed(record), math.hypot(1.5, 0.4), 0.9545))
    assert sum(c > 0.09 for c in point) >= 8, point
    assert min(none) > 0.0, none
    assert min(found) >= 0.4 and min(hidden) >= 0.4, (found, hidden)
    assert 0.4 <= float(np.median(found)) <= 0.5, found


@pytest.mark.slow
def test_the_figures_of_the_means_with_the_theodolite_stated_at_its_pointing_noise(
        capsys, tmp_path):
    """Pointing noise alone, the theodolite stated at it: E, M and A's intervals cover at the
    probability printed, and are at most 5, 5 and 22 times the width the figure's own
    spread needs (2 z σ of value − truth over the runs; measured 4.46, 4.46, 19.5). A's
    interval is made of each θ's own bounds of μ ± 2σ from its 3 passes (x̄ + 19.4 s at
    98.9 %, models.uncertainty.figure_intervals._band_span_bounds), which hold however σ
    changes from θ to θ; the bootstrap's, 2.80 times, covered 45–70 of 80 positioning tests
    with one target's σ × 2 or × 3 (#39). The
    readings cannot tell such a theodolite from one whose u hides a circle error under the
    pointing noise, and the widening for a circle error of the curve's worst shape is sized
    by the largest part they do not exclude (0.8.15, #39): until then by the part they show
    at 95 %, 0 here, 1.84, 1.73 and 1.35 times, and a hidden circle error against the curve
    was missed (M 45 of 80 runs of σ = 1.5″, u_c = 0.4″). Before 0.8.7, the set-up model's
    error was drawn on its own at each θ and, as an envelope of unknown correlation,
    widened them by z · 2 max u(ζ) each way: 3.21, 3.19, 2.09."""
    from scipy.special import ndtri

    rng = np.random.default_rng(23)
    rows: dict[str, list[tuple[bool, float, float, float]]] = {}
    for i in range(40):
        record = tmp_path / f"w{i}.csv"
        truth = _run(record, rng, 3, 0.5, 0.6)
        data = _figures(capsys, tmp_path, record, 0.5)
        for key in ("E", "M", "A"):
            fig = data["iso230_2_figures"][key]
            rows.setdefault(key, []).append((
                fig["interval_low"] - 1e-9 <= truth[key] <= fig["interval_high"] + 1e-9,
                fig["interval_high"] - fig["interval_low"], fig["value"] - truth[key],
                fig["coverage_probability"]))
    for key, r in rows.items():
        p = min(x[3] for x in r)
        hits = sum(x[0] for x in r)
        needed = 2.0 * float(ndtri(0.5 + 0.5 * p)) * float(np.std([x[2] for x in r], ddof=1))
        ratio = float(np.mean([x[1] for x in r])) / needed
        assert hits >= binom.ppf(0.01, len(r), p), (key, hits)
        assert ratio <= {"E": 5.0, "M": 5.0, "A": 22.0}[key], (key, ratio)
