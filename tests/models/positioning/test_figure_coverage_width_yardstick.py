"""What the positioning coverage record measures a figure's width against (#39, width81): the
oracle spread, 2 z σ of measured − truth over the tests of one case, is the width of an
interval that knew σ along that axis, not of a correct one, and the record says so; for R↑
and A↑ it also states their width against the narrowest interval that holds whatever σ does,
the number tests/benchmarks/least_favourable_width_study.py measures (a small run of it here);
for B, E↑ and E against the narrowest of simple bounds that hold every curve and σ pattern of
tests/benchmarks/reversal_range_width_study.py (width81b; a small run of it here).
"""

from __future__ import annotations

import numpy as np
import pytest

from models.positioning import figure_coverage
from models.positioning.figure_coverage import (
    FIGURES,
    NARROWEST_CORRECT_RATIO,
    NARROWEST_OF_MEANS,
    FigureCoverage,
    figure_coverage_cases,
)
from models.validation.cases import ValidationCase
from tests.benchmarks.least_favourable_width_study import cochran_c, narrowest_widths
from tests.benchmarks.reversal_range_width_study import study

#: the narrowest simple bounds' width ÷ the oracle spread on the flat curve, σ alike
#: (reversal_range_width_study, 100 000 draws a pattern)
B_FLAT_NARROW, E_UP_FLAT_NARROW = 2.27, 2.56

ORACLE = "the spread of measured − truth in each case (an interval that knew σ along the axis)"


@pytest.fixture
def record(monkeypatch) -> dict[str, str]:
    """The record's obtained text per case name, on a study of made-up rows (20 tests a
    figure, 1 missed, width 3 × the oracle spread): the wording, not the simulation."""

    def study(cases, tests):
        rows = {}
        for key in FIGURES:
            row = FigureCoverage(key, hits=19, tests=20, probability=0.9545)
            row.widths, row.needed = [3.0] * 20, [1.0] * 20
            rows[key] = row
        return rows

    monkeypatch.setattr(figure_coverage, "coverage_study", study)
    cases = figure_coverage_cases(200, ValidationCase)
    return {str(case.name): str(case.obtained) for case in cases}


def test_record_states_the_oracle_spread_not_a_correct_interval(record):
    assert len(record) == len(FIGURES) + 1  # and the decided quantity's
    for name, obtained in record.items():
        assert "a correct interval" not in obtained, name
        assert obtained.startswith("95.0 % (1 missed); width 3.00 × " + ORACLE), name


def test_narrowest_correct_ratio_stated_for_the_measured_figures_only(record):
    assert set(NARROWEST_CORRECT_RATIO) == {"R_up", "A_up", "B", "E_up", "E"}
    assert set(NARROWEST_OF_MEANS) == {"B", "E_up", "E"}
    for name, obtained in record.items():
        key = name.split("interval of ")[-1].split(" covers")[0]
        if key in NARROWEST_OF_MEANS or name.startswith("interval of the decided quantity"):
            continue  # their own wording (below)
        if key in NARROWEST_CORRECT_RATIO:
            assert obtained.endswith(
                f"; {NARROWEST_CORRECT_RATIO[key]:.2f} × the narrowest interval that holds "
                "whatever σ does (σ alike, width study; aim ≤ 1.6 ×)"), key
        else:
            assert "narrowest" not in obtained, name


def test_narrowest_correct_ratio_is_the_width_study_s():
    """R↑ at 12 targets, 5 runs, on 50 000 draws (the benchmark: 200 000, 12 and 36 targets,
    1.11 and 1.13): ours is 4.1 × the oracle spread where σ is alike, the narrowest design
    that holds every σ pattern 3.6–3.8 ×, so ours ÷ it is 1.08–1.15, at most the record's
    1.13 within this run's noise; the narrowest that holds one target × 2 alone is 1.8 ×."""
    ours, _, designs, widths = narrowest_widths("R_up", 12, 5, np.random.default_rng(81),
                                                draws=50_000)
    label, mine, narrow = widths["-"][0]
    assert label == "alike"
    assert mine == pytest.approx(4.10, abs=0.1)
    assert 3.55 <= narrow["every K"] <= 3.85
    assert 1.08 <= mine / narrow["every K"] <= NARROWEST_CORRECT_RATIO["R_up"] + 0.02
    assert narrow["K <= 2"] == pytest.approx(1.82, abs=0.08)
    upper, lower = designs["-"]["every K"]
    assert upper[0] < ours[0] and lower[0] >= ours[1]  # a narrower factor where C accepts


def test_means_figures_ratio_stated_against_the_simple_bounds(record):
    """B, E↑ and E (and the decided quantity, E's) are stated against the reversal and range
    width study's family of simple bounds, in its own words (not 'whatever σ does')."""
    for name, obtained in record.items():
        key = name.split("interval of ")[-1].split(" covers")[0]
        if key in NARROWEST_OF_MEANS or name.startswith("interval of the decided quantity"):
            figure = key if key in NARROWEST_OF_MEANS else "E"
            assert obtained.endswith(
                f"; {NARROWEST_CORRECT_RATIO[figure]:.2f} × the narrowest of the width study's "
                "simple bounds that hold every curve and σ pattern it tries (its largest over "
                "the curves and σ it measures; aim ≤ 1.6 ×)"), name


def test_means_figures_ratio_is_the_reversal_range_study_s():
    """A reduced run of tests/benchmarks/reversal_range_width_study.py (20 000 draws a
    pattern, the benchmark 100 000; ours on 40 tests of the flat curve with σ alike, the
    benchmark 200): the narrowest simple bounds that hold every pattern are wider than the
    oracle spread by what the benchmark found, and ours ÷ them where σ is alike is at most the
    record's (its largest over the patterns), within this run's noise."""
    got = study(narrow_n=20_000, verify_n=0, eval_n=5_000, tests=40,
                figures=("B", "E_up"), only=("flat, σ alike",))
    (_, (b_row,)), (_, (e_row,)) = got["B"], got["E_up"]
    for row, figure, narrow in ((b_row, "B", B_FLAT_NARROW), (e_row, "E_up", E_UP_FLAT_NARROW)):
        label, mine, narrowest, ratio = row[:4]
        assert label == "flat, σ alike"
        assert narrowest == pytest.approx(narrow, rel=0.08), figure
        assert mine > 1.0, figure  # ours is wider than the oracle spread
        assert ratio <= NARROWEST_CORRECT_RATIO[figure] + 0.1, figure


def test_ps_max_narrowest_over_sigma_alike_both_ways_is_not_correct():
    """Ps_max (width81b): the width study's narrowest over σ patterns that scale both
    directions alike is narrower than ours where σ is alike (1.75 × in the benchmark) only
    because its grid lacks a target whose σ↓ is far below its σ↑, where ours is exact: there
    the narrowest misses above far beyond the tail, ours does not; so it is not a record's
    number."""
    assert "Ps_max" not in NARROWEST_CORRECT_RATIO
    rng = np.random.default_rng(81)
    ours, _, designs, widths = narrowest_widths("Ps_max", 12, 5, rng, draws=50_000)
    label, mine, narrow = widths["-"][0]
    assert label == "alike" and mine / narrow["every K"] > 1.6
    (factor, crit, _), _ = designs["-"]["every K"]
    draws = np.random.default_rng(82)
    nu, m = 4, 12
    up, down = (np.sqrt(draws.chisquare(nu, (100_000, m)) / nu) for _ in range(2))
    sigma_up, sigma_down = np.ones(m), np.ones(m)
    sigma_up[0], sigma_down[0] = 6.0, 1e-6  # one target: σ↑ 6 × the others', σ↓ → 0
    mean_s = 0.5 * (up * sigma_up + down * sigma_down)
    truth = 0.5 * float(np.max(sigma_up + sigma_down))
    f = np.where(cochran_c(mean_s) > crit, ours[0], factor)
    assert np.mean(f * mean_s.max(axis=1) < truth) > 0.04  # the tail: 0.02275
    assert np.mean(ours[0] * mean_s.max(axis=1) < truth) < 0.005
