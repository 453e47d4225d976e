"""A theodolite run with repeated passes is decided on the means over the passes at each θ
and direction (0.8.6), with their own budget (models.theodolite.pass_means).

The rig is tests/theodolite_passes_simulator.py (first principles, nothing from the code it
checks). The decided quantity is half the peak-to-peak of the corrected error; its truth is
half the range of the axis' error d ± b/2 over both directions (E/2 of ISO 230-2)."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.stats import binom

from tests.theodolite_passes_simulator import passes_record
from tests.theodolite_run_json import run_json

pytestmark = pytest.mark.slow  # 30 runs, each decided by Monte Carlo


def _decided(capsys, tmp_path, record, stated: float, quantity: str = "half_range") -> dict:
    return run_json(capsys, tmp_path, record, stated, tolerance=10.0, tolerance_unit="arcsec",
                    decision_rule="guarded", decision_quantity=quantity)


#: each study's runs in the suite (its smoke version) and in its long form
#: (tests/benchmarks/test_theodolite_studies_full.py, ``make bench``), the same checks
MEANS_RUNS = {"smoke": 15, "full": 30}
AXIS_RUNS = {"smoke": 12, "full": 30}
SMOOTH_RUNS = {"smoke": 30, "full": 40}


@pytest.mark.parametrize("world", ["pointing", "circle"])
def test_the_means_decision_covers_and_sits_nearer_the_truth_than_every_reading(
        capsys, tmp_path, world):
    """The smoke version of :func:`check_means_decision`: 15 runs, the coverage floor the
    binomial test's at 0.1 %; decided on every reading (0.8.5), the pointing world's value
    is as far from the truth as every reading's and fails it (the circle world, where the
    two are about as near, guards the coverage)."""
    check_means_decision(capsys, tmp_path, world, MEANS_RUNS["smoke"], 0.001)


def check_means_decision(capsys, tmp_path, world: str, runs: int, false_alarm: float) -> None:
    """``runs`` runs of 3 × (forward, backward) passes over 13 θ with a reversal of 0.8": the
    decided interval covers E/2 at least as often as the binomial test (``false_alarm``: 1 %
    in the long form's 30 runs) allows at the probability printed; the value decided on the
    means is nearer the truth on average than
    every reading's half range less its noise (the all-readings decision of 0.8.5, kept for
    the points quantity), whose value ran high by the noise's excess over 78 readings; where
    the circle's error repeating in every pass dominates, averaging cannot take it out, and
    the two are about as near."""
    from models.certificate.metadata import CertificateMetadata, ReferenceStandard
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.theodolite.analysis import THEODOLITE
    from models.theodolite.report import theodolite_budget
    from models.uncertainty.conformity import half_range_monte_carlo

    rng = np.random.default_rng(40 + len(world))
    sigma, circle = (0.5, 0.0) if world == "pointing" else (0.2, 0.5)
    stated = float(np.hypot(sigma, circle))
    meta = CertificateMetadata(standards=(ReferenceStandard(
        "Autocollimating theodolite", uncertainty=stated, basis="u"),))
    hits, p, new_off, old_off = 0, 1.0, [], []
    for i in range(runs):
        record = tmp_path / f"run{i}.csv"
        truth = 0.5 * passes_record(record, rng, 3, sigma, 0.8, circle)["E"]
        decided = _decided(capsys, tmp_path, record, stated)["decided_quantity"]
        hits += decided["interval_low"] <= truth <= decided["interval_high"]
        p = min(p, decided["coverage_probability"])
        new_off.append(abs(decided["value"] - truth))
        result = THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, map_columns(
            read_table(record), THEODOLITE.columns)).parse(), THEODOLITE.settings_with_defaults({}))
        every = half_range_monte_carlo(result.corrected_error_arcsec,
                                       theodolite_budget(result, meta))
        old_off.append(abs(every.value - truth))
    assert hits >= binom.ppf(false_alarm, runs, p), (hits, p)
    # with the circle's error (which no averaging takes out) dominant, about the same (the
    # two differ by their Monte Carlo's scatter: 0.31" against 0.29" here)
    nearer = 0.8 if world == "pointing" else 1.15
    assert np.mean(new_off) < nearer * np.mean(old_off), (np.mean(new_off), np.mean(old_off))


def test_the_certificate_names_the_means_and_the_points_quantity_keeps_every_reading(
        capsys, tmp_path):
    """The JSON's decided quantity is the half range of the means (its measured value is
    half the ISO 230-2 E of the same run); with the points quantity every reading decides,
    as before."""
    record = tmp_path / "passes.csv"
    passes_record(record, np.random.default_rng(12), 3, 0.3, 0.5)
    data = _decided(capsys, tmp_path, record, 0.3)
    assert data["decided_quantity"]["measured"] == pytest.approx(
        0.5 * data["iso230_arcsec"]["E"], rel=1e-9)
    points = _decided(capsys, tmp_path, record, 0.3, "points")["decided_quantity"]
    worst = float(np.max(np.abs(np.asarray(data["corrected_error_arcsec"]))))
    assert abs(points["value"]) == pytest.approx(worst, abs=0.01)  # signed: the point's (0.8.17)


def test_an_axis_that_scatters_more_than_the_theodolite_keeps_the_circle_error(
        capsys, tmp_path):
    """The smoke version of :func:`check_axis_scatter_keeps_the_circle`: 12 runs, the
    coverage floor the binomial test's at 0.1 %; the axis' scatter taken for pointing
    leaves the circle's part 0 and fails it."""
    check_axis_scatter_keeps_the_circle(capsys, tmp_path, AXIS_RUNS["smoke"], 0.001)


def check_axis_scatter_keeps_the_circle(capsys, tmp_path, runs: int, false_alarm: float) -> None:
    """The passes' scatter holds the axis' own non-repeatability (0.5") besides the
    theodolite's pointing noise (0.1"): taken whole for the pointing noise, it left no part
    of the stated u (0.41") for the circle's error (0.4" at each θ, the same in every pass),
    and a reviewer's rig found 4 of 20 decided intervals missing. The pointing noise is now
    the smaller of the passes' scatter and the vertical readings' about the fit (the axis'
    rotation error barely moves the elevations): ``runs`` runs (30 in the long form) covered
    at least as the binomial test (``false_alarm``: 1 % there) allows."""
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.theodolite.analysis import THEODOLITE
    from models.theodolite.figures import circle_part

    rng = np.random.default_rng(77)
    stated = float(np.hypot(0.1, 0.4))
    hits, p, circles = 0, 1.0, []
    for i in range(runs):
        record = tmp_path / f"run{i}.csv"
        truth = 0.5 * passes_record(record, rng, 3, 0.1, 0.8, circle=0.4, axis_noise=0.5)["E"]
        decided = _decided(capsys, tmp_path, record, stated)["decided_quantity"]
        hits += decided["interval_low"] <= truth <= decided["interval_high"]
        p = min(p, decided["coverage_probability"])
        result = THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, map_columns(
            read_table(record), THEODOLITE.columns)).parse(), THEODOLITE.settings_with_defaults({}))
        circles.append(circle_part(result, stated))
    assert hits >= binom.ppf(false_alarm, runs, p), (hits, p)
    # the circle's part found (0 in every run before: the axis' 0.5" taken for pointing)
    assert 0.3 <= float(np.median(circles)) <= 0.45, circles


def test_passes_without_a_direction_column_are_decided_on_every_reading(capsys, tmp_path):
    """θ repeated back and forth with no direction column: averaging the passes would
    average forward with backward and lose the reversal (a reviewer's rig: 9 of 15 intervals
    missed), so every reading decides, as before 0.8.6."""
    record = tmp_path / "plain.csv"
    passes_record(record, np.random.default_rng(4), 3, 0.3, 0.8, directions=False)
    data = _decided(capsys, tmp_path, record, 0.3)
    every = 0.5 * float(np.ptp(np.asarray(data["corrected_error_arcsec"])))
    assert data["decided_quantity"]["measured"] == pytest.approx(every, rel=1e-9)


@pytest.mark.parametrize("directions", ["both", "forward"])
def test_a_smooth_circle_error_is_held_by_the_decided_interval(capsys, tmp_path, directions):
    """The smoke version of :func:`check_smooth_circle_held`: both directions in 30 runs, the
    coverage floor the binomial test's at 0.1 % (24 of 30); without the union with E's halved
    it fails (22 of 30 covered, seed 61). Forward only it stays at its 40 runs and the 1 %
    floor: E's looked up instead of E↑'s covers 24 of the first 30 runs, as many as a
    correct method may cover at 0.1 %, and 32 of 40."""
    if directions == "forward":  # the smoke version is the whole study (the docstring)
        check_smooth_circle_held(capsys, tmp_path, directions, SMOOTH_RUNS["full"], 0.01)
    else:
        check_smooth_circle_held(capsys, tmp_path, directions, SMOOTH_RUNS["smoke"], 0.001)


def check_smooth_circle_held(capsys, tmp_path, directions: str, runs: int,
                             false_alarm: float) -> None:
    """The circle's error one smooth wave over the span (0.4″, pointing 0.15″, 5 passes, a
    bowed axis curve): where it runs against the curve it lowers the measured range, and the
    Monte Carlo, which draws it on its own at each θ, put its interval too low (28 of 40
    covered here, every miss with the truth above; an independent audit: 216 and 224 of
    300). United with E's halved, which holds a circle error of any shape: covered at the
    probability printed (40 of 40; the binomial test at ``false_alarm``, 1 % in the long
    form's 40 runs). Read forward only, the union is with E↑'s (a reviewer:
    with E's looked up, there was none, and 26 of 40 covered)."""
    import math

    rng = np.random.default_rng(61)
    stated = math.hypot(0.15, 0.4)
    hits, probability, widths, values = 0, 1.0, [], []
    for i in range(runs):
        record = tmp_path / f"s{i}.csv"
        truth = passes_record(record, rng, 5, 0.15, 0.6, circle=0.4, circle_shape="sine",
                               curve="bow")
        if directions == "forward":
            lines = record.read_text().splitlines()
            record.write_text("\n".join([lines[0]] + [r for r in lines[1:]
                                                       if r.endswith(",+")]) + "\n")
        decided = _decided(capsys, tmp_path, record, stated)["decided_quantity"]
        half = 0.5 * truth["E" if directions == "both" else "E_up"]
        hits += decided["interval_low"] <= half <= decided["interval_high"]
        probability = min(probability, decided["coverage_probability"])
        widths.append(decided["interval_high"] - decided["interval_low"])
        values.append(decided["value"] - half)
    assert hits >= binom.ppf(false_alarm, runs, probability), hits
    # not bought with an interval of any width: 1.8 times the value's own spread (the Monte
    # Carlo's alone 1.1, covering 28 of 40)
    spread = np.percentile(values, 97.725) - np.percentile(values, 2.275)
    assert float(np.mean(widths)) <= 2.5 * spread


def test_an_overstated_theodolite_does_not_take_the_decided_value_to_zero(capsys, tmp_path):
    """The theodolite stated at 3 times the pointing noise it shows: the excess is read as a
    circle error at each θ (2.8 times the noise), an envelope that may be smaller than
    stated. Taken out of the range as noise, it took the decided value near 0 (an audit: 0.09″
    where 2″ was measured and 1.63″ true), which a customer reads as no error; the value is
    now not below the lower end the readings' own noise gives (median value / truth 0.84,
    before 0.09), and the interval still holds the truth."""
    rng = np.random.default_rng(62)
    values, hits = [], 0
    for i in range(12):
        record = tmp_path / f"o{i}.csv"
        truth = passes_record(record, rng, 3, 0.3, 0.6)
        decided = _decided(capsys, tmp_path, record, 0.9)["decided_quantity"]
        half = 0.5 * truth["E"]
        hits += decided["interval_low"] <= half <= decided["interval_high"]
        values.append(decided["value"] / half)
    assert hits >= 11, hits
    assert float(np.median(values)) >= 0.8, values


def test_passes_alike_in_every_reading_withhold_the_decided_half_range(capsys, tmp_path):
    """Exact readings (no pointing noise) in 3 × (forward, backward) passes, the theodolite
    stated at 0.5″: the readings show that u is not noise new in every reading, so the
    Monte Carlo's removal of the noise's bias would take off what is not there (an audit:
    decided 1.68″, interval 0.88″ … 2.12″, where 2.32″ was measured and true). The decided
    half range is withheld with the reason; its measured value is still stated."""
    record = tmp_path / "exact.csv"
    truth = 0.5 * passes_record(record, np.random.default_rng(8), 3, 0.0, 0.6)["E"]
    decided = _decided(capsys, tmp_path, record, 0.5)["decided_quantity"]
    assert decided["interval_low"] is None and decided["interval_high"] is None
    assert decided["verdict"] is None
    assert decided["coverage_probability"] is None  # no interval, no probability of one
    assert "withheld" in decided["reason"] and "identical over the passes" in decided["reason"]
    assert decided["value"] == pytest.approx(truth, abs=0.02)


def test_readings_shown_coarser_than_they_scatter_withhold_figures_and_decision(
        capsys, tmp_path):
    """The display rounds to 1″ and the pointing noise is 0.2″: most θ read alike in every
    pass, and where they differ it is by a whole step, so each mean's rounding error is not
    random. As the positioning workbench does (models.readings.resolution.coarse): the ISO
    230-2 figures' intervals and the decided half range are withheld, naming the step and
    the scatter. Shown to 0.1″, the same noise is random against its step: decided."""
    coarse_record, fine_record = tmp_path / "coarse.csv", tmp_path / "fine.csv"
    passes_record(coarse_record, np.random.default_rng(9), 3, 0.2, 0.6, step=1.0)
    passes_record(fine_record, np.random.default_rng(9), 3, 0.2, 0.6, step=0.1)
    coarse = _decided(capsys, tmp_path, coarse_record, 0.5)
    assert "coarser than they scatter" in coarse["iso230_2_figures_reason"]
    assert 'step 1"' in coarse["iso230_2_figures_reason"]
    assert all(f["interval_low"] is None for f in coarse["iso230_2_figures"].values())
    assert coarse["decided_quantity"]["interval_low"] is None
    assert "withheld" in coarse["decided_quantity"]["reason"]
    fine = _decided(capsys, tmp_path, fine_record, 0.5)
    assert fine["iso230_2_figures_reason"] is None
    assert fine["decided_quantity"]["interval_low"] is not None
    assert fine["decided_quantity"]["verdict"] == "pass"
