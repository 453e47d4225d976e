"""The coverage intervals of the axis figures (#39): seeded from the readings, the truth of
the simulation rig agreeing with the standard's formulas, a bias the plain Monte Carlo left
in, and a smoke version of the coverage study (the study itself: anglebench validate and
tests/benchmarks/test_positioning_figures.py)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.stats import binom

from models.uncertainty.figure_intervals import axis_figures, figure_intervals, world_truth
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


def test_the_study_holds_axes_whose_sigma_changes_along_the_axis():
    """The rig's σ along the axis (AxisCase's ``along``): at random in 1–2 × for each target
    and direction, rising 1 → 3 ×, one target's × 3; the study holds each of them for every
    shape at 12 and 36 targets (24 axes appended: the first 96 keep their truths and
    streams), and ``anglebench validate`` runs two of them."""
    from models.positioning.figure_coverage import STUDY_CASES, VALIDATE_CASES

    plain = AxisCase("rough", 12, 1.0, seed=5)
    base = plain.sigma["up"][0]
    random = AxisCase("rough", 12, 1.0, seed=5, along="random")
    assert np.array_equal(random.mu["up"], plain.mu["up"])  # the same curve
    for d, factor in (("up", 1.0), ("down", 1.1)):
        ratio = random.sigma[d] / (factor * base)
        assert np.all((ratio >= 1.0) & (ratio <= 2.0)) and np.ptp(ratio) > 0.5, d
    ramp = AxisCase("smooth", 12, 1.0, along="ramp")
    assert ramp.sigma["up"] / ramp.sigma["up"][0] == pytest.approx(np.linspace(1.0, 3.0, 12))
    one = AxisCase("spike", 36, 1.0, along="one")
    assert np.flatnonzero(one.sigma["up"] != one.sigma["up"][0]).tolist() == [12]
    assert one.truth()["R_up"] == pytest.approx(12.0 * one.sigma["up"][0])
    with pytest.raises(ValueError):
        AxisCase("smooth", 12, 1.0, along="sideways")
    along = [c for c in STUDY_CASES if c.along]
    assert len(STUDY_CASES) == 120 and STUDY_CASES[96:] == tuple(along)
    assert {(c.shape, c.targets, c.along) for c in along} == {
        (s, m, a) for s in SHAPES for m in (12, 36) for a in ("random", "ramp", "one")}
    assert all(c.truth() == AxisCase(c.shape, c.targets, c.noise_ratio, c.varying,
                                     seed=c.seed).truth() for c in STUDY_CASES[:96])
    assert [(c.shape, c.along) for c in VALIDATE_CASES if c.along] == [
        ("smooth", "ramp"), ("rough", "random")]


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


def test_the_ensemble_world_has_as_many_targets_near_the_crests_as_the_truth():
    """A sine over 72 targets has 15 targets within a tenth of its range below its crest;
    measured with a scatter of 0.3 of its amplitude, the triple-goal world (the true means'
    distribution by NPMLE, values by rank) keeps about as many there, the constrained Bayes
    world (spread matched only) one to four: its range's bias came out too small and E's
    interval fell short below on smooth curves."""
    from models.uncertainty.figure_intervals import _ensemble, _shrunk

    mu = np.sin(np.linspace(0.0, 2 * np.pi, 72, endpoint=False))
    near_truth = int(np.sum(mu > mu.max() - 0.2)) + int(np.sum(mu < mu.min() + 0.2))
    ensemble, shrunk = [], []
    for seed in range(10):
        x = mu + 0.3 * np.random.default_rng(seed).standard_normal(72)
        for world, counts in ((_ensemble(x, np.full(72, 0.09)), ensemble),
                              (_shrunk(x, np.full(72, 0.09)), shrunk)):
            span = 0.1 * np.ptp(world)
            counts.append(int(np.sum(world > world.max() - span))
                          + int(np.sum(world < world.min() + span)))
    assert near_truth == 30
    assert np.mean(ensemble) > 0.5 * near_truth
    assert np.mean(shrunk) < 0.25 * near_truth


def test_the_ensemble_world_follows_the_readings_when_the_scatter_is_small():
    """With a scatter far below the curve's steps the world is the measured means (to the
    grid's step): nothing is made up."""
    from models.uncertainty.figure_intervals import ENSEMBLE_GRID, _ensemble

    x = np.sin(np.linspace(0.0, 2 * np.pi, 24, endpoint=False)) + 0.3 * np.arange(24) / 24
    world = _ensemble(x, np.full(24, 1e-8))
    assert np.max(np.abs(world - x)) <= np.ptp(x) / (ENSEMBLE_GRID - 1)
    assert np.array_equal(np.argsort(world, kind="stable"), np.argsort(x, kind="stable"))


def _interval_runs(case: AxisCase, key: str, tests: int, seed: int):
    """(value, low, high) of ``key`` over ``tests`` simulated tests, and its truth."""
    rng = np.random.default_rng(seed)
    rows = []
    for k in range(tests):
        means, sds, runs = _stats(case, rng)
        interval = figure_intervals(means, sds, runs, 0.9545, seed=k)[key]
        rows.append((interval.value, interval.low, interval.high))
    return np.array(rows), case.truth()[key]


#: the suite's tests a study (the smoke version) and the long form's (tests/benchmarks/
#: test_positioning_studies_full.py, ``make bench``): the same checks; the long form keeps
#: the counts of misses it allowed at 40 tests, the suite allows at 20 what a correct
#: interval exceeds in fewer than 1 in 1000 studies (:func:`smoke_misses`)
SMOKE_TESTS, FULL_TESTS = 20, 40
TAIL = 0.5 * (1.0 - 0.9545)  # each side's share of the interval's tail


def smoke_misses(tests: int, share: float) -> int:
    """The most misses a correct interval, missing at ``share`` of tests, exceeds in fewer
    than 1 in 1000 studies of ``tests`` tests (the binomial test at 0.1 %)."""
    return int(binom.ppf(0.999, tests, share))


@pytest.mark.slow
def test_b_covers_a_reversal_whose_largest_value_stands_clear():
    """The smoke version of :func:`check_b_covers_a_clear_reversal`: 20 tests, at most 3
    missed each side (:func:`smoke_misses`); with B's upper end left at the worlds' (no
    targets' own bounds) it fails."""
    most = smoke_misses(SMOKE_TESTS, TAIL)
    check_b_covers_a_clear_reversal(SMOKE_TESTS, most, most)


def check_b_covers_a_clear_reversal(tests: int, most_above: int, most_below: int) -> None:
    """A rough reversal over 72 targets whose largest value stands one standard uncertainty
    of a target's reversal clear of the next (repeatability 0.1 × the signal): the worlds
    fitted to the readings see many targets near the top and put B's upper end too low (20
    to 30 % of tests missed above); the largest of the targets' own one-sided bounds, which
    holds whatever the shape, keeps the misses at the tail's share."""
    case = AxisCase("rough", 72, 0.1, seed=18)
    reversal = np.sort(np.abs(case.mu["up"] - case.mu["down"]))
    se = math.sqrt((case.sigma["up"][0] ** 2 + case.sigma["down"][0] ** 2) / case.runs)
    assert reversal[-1] - reversal[-2] > 0.9 * se  # the rig's truth is as described
    rows, truth = _interval_runs(case, "B", tests, 11)
    assert int(np.sum(truth > rows[:, 2])) <= most_above
    assert int(np.sum(truth < rows[:, 1])) <= most_below


@pytest.mark.slow
def test_b_holds_one_target_standing_three_uncertainties_above_an_even_reversal():
    """The smoke version of :func:`check_b_holds_one_target_above_an_even_reversal`: 20
    tests, at most 3 missed each side (:func:`smoke_misses`); with B's upper end left at the
    worlds' it fails."""
    most = smoke_misses(SMOKE_TESTS, TAIL)
    check_b_holds_one_target_above_an_even_reversal(SMOKE_TESTS, most, most)


def check_b_holds_one_target_above_an_even_reversal(tests: int, most_above: int,
                                                    most_below: int) -> None:
    """An even reversal over 36 targets with one target 3 u(B_i) above the rest (a backlash
    jump at one position), repeatability 0.1 × the signal: the readings often show that
    target only 1–2 u clear of the others' largest, which an even reversal gives too, and
    every model fitted to them takes it for one of many near the top (the triple-goal
    world, with or without the unshrunk: 13–21 of 40 tests missed above). B's upper end at
    the targets' own one-sided bounds holds it; at max(|B_i| + 0.5 u) 8 of 40 tests missed
    above, at max(|B_i| + 1 u) 3 of 40. Why B's interval is as wide as it is where the
    reversal is even (docs/user-guide/positioning.md)."""
    case = AxisCase("spike", 36, 0.1, seed=3)
    se = math.sqrt((case.sigma["up"][0] ** 2 + case.sigma["down"][0] ** 2) / case.runs)
    reversal = case.mu["up"] - case.mu["down"]
    assert np.ptp(reversal) == pytest.approx(0.0, abs=1e-12)  # even, as described
    reversal[18] += 3.0 * se
    middle = 0.5 * (case.mu["up"] + case.mu["down"])
    case.mu = {"up": middle + 0.5 * reversal, "down": middle - 0.5 * reversal}
    rows, truth = _interval_runs(case, "B", tests, 11)
    assert int(np.sum(truth > rows[:, 2])) <= most_above
    assert int(np.sum(truth < rows[:, 1])) <= most_below


@pytest.mark.slow
def test_e_interval_is_not_wider_than_needed_on_a_spike_in_scatter():
    """The smoke version of :func:`check_e_not_wider_than_needed`: 20 tests, at most 5
    missed (:func:`smoke_misses`), the same width bound (1.93 here since 0.8.30, 1.41 before);
    an interval twice as wide as it was (the width the constrained Bayes world gave) fails it."""
    check_e_not_wider_than_needed(SMOKE_TESTS, smoke_misses(SMOKE_TESTS, 2.0 * TAIL))


def check_e_not_wider_than_needed(tests: int, most_missed: int) -> None:
    """One target off a small sine, 72 targets, repeatability as large as the signal: E's
    interval holds the truth and is at most 2.0 times the oracle spread (4 standard
    deviations of E − truth over the tests; 1.7 until 0.8.30); with the constrained Bayes
    world and its calibration it was 2.8 times. Since 0.8.30 the lower end is 0 where the
    measured range is within what the noise alone makes on a flat axis
    (figure_intervals._range_within_noise): here the range of the 144 means mostly is, and
    nothing in the readings tells this axis from a flat one, on which the lower end stood
    above the truth 0 in 13 % of tests against 7.5 % allowed."""
    case = AxisCase("spike", 72, 1.0, seed=1)
    rows, truth = _interval_runs(case, "E", tests, 12)
    missed = int(np.sum((truth < rows[:, 1]) | (truth > rows[:, 2])))
    needed = 4.0 * float(np.std(rows[:, 0] - truth, ddof=1))
    assert missed <= most_missed
    assert float(np.mean(rows[:, 2] - rows[:, 1])) <= 2.0 * needed


def test_the_probability_stated_is_the_highest_no_axis_falls_short_of():
    """figure_coverage.achieved_probability, how ACHIEVED is derived: 95.45 % where every
    axis holds; an axis with 10 of 40 missed (the binomial test at 1 % allows 6 at 93 %,
    7 at 91 % …) takes it down to the first step it passes; the pooled coverage caps it."""
    from scipy.stats import binom

    from models.positioning.figure_coverage import PROBABILITY_STEPS, achieved_probability

    assert achieved_probability(np.full(48, 39), 40) == 0.9545
    hits = np.full(48, 40)
    hits[7] = 30
    p = achieved_probability(hits, 40)
    assert p in PROBABILITY_STEPS and p < 0.93
    assert binom.ppf(0.99, 40, 1.0 - p) >= 10
    assert binom.ppf(0.99, 40, 1.0 - (p + 0.005)) < 10
    assert achieved_probability(np.full(48, 37), 40) == 0.925  # pooled 92.5 %
    assert achieved_probability(np.full(48, 20), 40) is None



def _twelve_targets_both_ways():
    """Means, standard deviations and runs (3) of a sine over 12 targets, 0.3 apart
    between the directions, with scatter: the pair-widening tests' axis."""
    rng = np.random.default_rng(3)
    theta = np.linspace(0.0, 1.0, 12)
    curve = np.sin(2 * math.pi * theta)
    means = {d: curve + s * 0.3 + rng.normal(0.0, 0.2, theta.size)
             for d, s in (("up", 0.5), ("down", -0.5))}
    stds = {d: np.full(theta.size, 0.35) for d in means}
    runs = {d: np.full(theta.size, 3) for d in means}
    return means, stds, runs

def test_a_pair_bound_widens_without_type_b_and_at_the_rest_of_the_tail():
    """``pair_u`` with no Type B input at any target (a theodolite whose stated u the scatter
    does not show over its point estimate, but does not exclude): E's and M's upper ends are
    the readings' own interval at the rest of the tail, (1 − pair_spent) · tail each side,
    plus z(1 − rest/2) · pair_u; B, which the errors the same both ways do not enter, is
    unchanged. Before, with every target's Type B u 0 no widening was made at all."""
    from scipy.special import ndtri

    means, stds, runs = _twelve_targets_both_ways()
    p, spent, pair = 0.9545, 0.25, 0.6
    kw = dict(seed=11, trials=800, outer=0, inner=0)
    plain = figure_intervals(means, stds, runs, p, **kw)
    rest = 0.5 * (1.0 - p) * (1.0 - spent)
    far = figure_intervals(means, stds, runs, 1.0 - rest, **kw)
    wide = figure_intervals(means, stds, runs, p, pair_u=pair, pair_spent=spent, **kw)
    shift = float(ndtri(1.0 - 0.5 * rest)) * pair
    for key in ("E", "M", "A"):
        assert wide[key].high == pytest.approx(far[key].high + shift, rel=1e-12), key
        assert wide[key].low == pytest.approx(max(min(plain[key].low, far[key].low - shift),
                                                  0.0), abs=1e-12), key
    assert wide["B"] == plain["B"]


def test_errors_within_their_u_widen_by_their_largest_range_at_the_whole_rest_of_the_tail():
    """``pair_envelope``: errors the same at a target in every run, each within its U at the
    probability (k · u, k the two-sided normal factor: 2 at 95.45 %), of any shape. A range
    or a largest value less a smallest one moves by at most their range, k · pair_u, a bias
    and not a scatter: E's, M's and A's ends are the readings' own interval at the whole rest
    of the tail, (1 − pair_spent) · tail each side, moved out by k · pair_u. That is
    narrower at both ends than the union bound (z(1 − rest/2) · pair_u on the readings'
    interval at half the rest), which until then sized the theodolite's circle error; B,
    which such errors do not enter, is unchanged."""
    from scipy.special import ndtri

    means, stds, runs = _twelve_targets_both_ways()
    p, spent, pair = 0.9545, 0.25, 0.6
    kw = dict(seed=11, trials=800, outer=0, inner=0)
    plain = figure_intervals(means, stds, runs, p, **kw)
    rest = 0.5 * (1.0 - p) * (1.0 - spent)  # each side
    far = figure_intervals(means, stds, runs, 1.0 - 2.0 * rest, **kw)
    bound = figure_intervals(means, stds, runs, p, pair_u=pair, pair_spent=spent, **kw)
    within = figure_intervals(means, stds, runs, p, pair_u=pair, pair_spent=spent,
                              pair_envelope=True, **kw)
    shift = float(ndtri(0.5 * (1.0 + p))) * pair  # 2.0 · pair
    assert shift == pytest.approx(2.0 * pair, rel=1e-3)
    for key in ("E", "M", "A"):
        assert within[key].high == pytest.approx(far[key].high + shift, rel=1e-12), key
        assert within[key].low == pytest.approx(max(min(plain[key].low, far[key].low - shift),
                                                    0.0), abs=1e-12), key
        assert within[key].high < bound[key].high, key
        assert within[key].low >= bound[key].low, key
        assert within[key].high - within[key].low < bound[key].high - bound[key].low, key
    assert within["B"] == plain["B"]


def _spike_in_rough_curve() -> AxisCase:
    """The coverage audit's axis (cov76 F3): 25 targets, a random curve (1.5″ rms) with a
    5″ spike at the tenth, a random reversal (2 ± 0.5″), σ 1.5–2″ drawn at random for each
    target and direction, 5 runs, drawn as the audit's rig draws it (its seed 7)."""
    r = np.random.default_rng(7)
    curve = 1.5 * r.standard_normal(25)
    curve[9] += 5.0
    reversal = 2.0 + 0.5 * r.standard_normal(25)
    sigma_up, sigma_down = 1.5 + 0.5 * r.random(25), 1.5 + 0.5 * r.random(25)
    case = AxisCase("rough", 25, 1.0)
    case.mu = {"up": curve + 0.5 * reversal, "down": curve - 0.5 * reversal}
    case.sigma = {"up": sigma_up, "down": sigma_down}
    return case


@pytest.mark.parametrize(("draw", "keys"), [(1, ("E",)), (38, ("E_up",)), (57, ("E", "E_down"))])
def test_e_upper_end_holds_a_spike_whose_mean_came_out_low(draw, keys):
    """The audit's axis (:func:`_spike_in_rough_curve`), three tests of the seeded stream in
    which the spike's mean came out more than one standard uncertainty low (its readings
    then look like one of a crowd at the top). In each, the errors (measured − truth) of
    the figures checked are inside the central 95.45 % of their own distribution (20 000
    draws from the true axis), so the basic interval of the true distribution, at the tail
    asked for, covers the truth; the figures' intervals must too. Both worlds of the
    bootstrap took the crowd for the truth, their pivot's lower tail was too short and the
    truth lay above each of these intervals (the audit: above E's in 10 % of 250 tests,
    E 88.8 % and E↓ 87.6 % covered against 92.5 % and 93.5 % printed). Of the first 60
    tests of the stream 11 have the spike that low; before, the truth lay above E's, E↑'s or
    E↓'s interval in 10 of them; now in 5, and in 3 of those 5 the missed figure's error is
    beyond its true distribution's central 95.45 % (a correct interval misses there too).
    The three here are three of the 5 it now covers (seeded: the same readings and the same bootstrap
    every run, so this is no Monte Carlo and needs no binomial allowance)."""
    case = _spike_in_rough_curve()
    truth = case.truth()
    rng = np.random.default_rng(76)
    for _ in range(draw):
        case.readings(rng)
    means, sds, runs = _stats(case, rng)
    se_spike = case.sigma["up"][9] / math.sqrt(case.runs)
    assert means["up"][9] < case.mu["up"][9] - se_spike  # the spike came out low
    # the true distribution of each figure's error
    draws = np.random.default_rng(1).standard_normal((2, 20000, 25))
    true_stats = {d: (case.mu[d] + case.sigma[d] / math.sqrt(case.runs) * draws[j],
                      np.broadcast_to(case.sigma[d], (20000, 25)))
                  for j, d in enumerate(("up", "down"))}
    true_errors = axis_figures(true_stats)
    intervals = figure_intervals(means, sds, runs, 0.9545, seed=draw)
    for key in keys:
        q_low, q_high = np.quantile(true_errors[key] - truth[key], (TAIL, 1.0 - TAIL))
        error = intervals[key].value - truth[key]
        assert q_low <= error <= q_high, key  # a correct interval covers this test
        assert intervals[key].low <= truth[key] <= intervals[key].high, key


def _lone_crests_sigma_at_random() -> AxisCase:
    """pos77's axis: 25 targets over 0…360°, a rough curve (every harmonic to the 12th,
    amplitudes 1/k, random phases, and a random part of 0.4) scaled to 4″ peak to peak whose
    crest and trough each stand alone (the bidirectional mean 1.99″ at the crest, the next
    target 1.44″; −2.01″ and −1.48″ at the trough), a reversal about 0.4″, σ drawn at random in
    1–2″ for each target and direction, 5 runs; drawn as pos77's rig draws it (its seed 7713)."""
    r = np.random.default_rng(7713)
    t = np.radians(np.linspace(0.0, 360.0, 25))
    k = np.arange(1, 13)
    curve = np.sum(np.sin(np.outer(t, k) + r.uniform(0.0, 2 * np.pi, k.size)) / k, axis=1)
    curve = curve + 0.4 * r.standard_normal(25)
    reversal = 0.8 + 0.25 * r.standard_normal(25)
    scale = 4.0 / np.ptp(curve)
    curve, reversal = curve * scale, 0.5 * reversal * scale
    case = AxisCase("rough", 25, 1.0)
    case.mu = {"up": curve + 0.5 * reversal, "down": curve - 0.5 * reversal}
    case.sigma = {"up": r.uniform(1.0, 2.0, 25), "down": r.uniform(1.0, 2.0, 25)}
    return case


@pytest.mark.parametrize("draw", [14, 49, 83])
def test_m_upper_end_holds_a_lone_crest_read_low_where_sigma_changes_at_random(draw):
    """pos77's axis (:func:`_lone_crests_sigma_at_random`), three tests of a seeded stream in
    which M (the range of the bidirectional means) came out 0.45–0.6″ below its truth, 4.00″.
    In each, M's error is inside the central 95.45 % of its own distribution (20 000 draws
    from the true axis), so a correct interval covers the truth; M's and Pa's must too. Until
    0.8.26 their upper end was the calibrated bootstrap's alone, whose worlds took the lone
    crest and trough read low for ones among a crowd, and the truth lay above them (pos77,
    through the command line: M 125 and 130 of 150 tests of two streams against 92.5 %
    printed, every miss above). Their upper end now also reaches the unshrunk world's pivot at
    an eighth of the tail, as E's (figure_intervals.UPPER_REACH_FIGURES): of the stream's
    first 150 tests the truth lay above M's interval in 18, now in 10 (4 of them beyond M's
    true central 95.45 %, where a correct interval misses too). Seeded: the same readings and
    bootstrap every run."""
    case = _lone_crests_sigma_at_random()
    truth = case.truth()
    assert truth["M"] == pytest.approx(4.0)
    rng = np.random.default_rng(5)
    for _ in range(draw):
        _stats(case, rng)
    means, sds, runs = _stats(case, rng)
    draws = np.random.default_rng(1).standard_normal((2, 20000, 25))
    true_stats = {d: (case.mu[d] + case.sigma[d] / math.sqrt(case.runs) * draws[j],
                      np.broadcast_to(case.sigma[d], (20000, 25)))
                  for j, d in enumerate(("up", "down"))}
    q_low, q_high = np.quantile(axis_figures(true_stats)["M"] - truth["M"], (TAIL, 1.0 - TAIL))
    intervals = figure_intervals(means, sds, runs, 0.9545, seed=draw)
    error = intervals["M"].value - truth["M"]
    assert -0.7 < error < -0.4  # M came out low
    assert q_low <= error <= q_high  # a correct interval covers this test
    for key in ("M", "Pa"):
        assert intervals[key].low <= truth[key] <= intervals[key].high, key
