"""Coverage of the positioning figures' intervals (ISO 230-2 / GB/T 17421.2, VDI/DGQ 3441),
#39: every study case of models/positioning/figure_coverage.py (4 shapes × 12, 36 and 72 targets
× repeatability 0.1, 0.5, 1 and 2 × the signal × constant or varying along the axis; 5 runs
each way), each test through the whole analysis. A figure passes when its misses are within
the binomial allowance at the probability printed beside it; its mean width is stated as a
multiple of the oracle spread (the width of an interval that knew σ along the axis; the aim
1.6 ×), and R↑'s and A↑'s against the narrowest interval that holds whatever σ does."""

from __future__ import annotations

import time

from models.positioning.figure_coverage import (
    NARROWEST_CORRECT_RATIO,
    NARROWEST_OF_MEANS,
    STUDY_CASES,
    WIDTH_LIMIT,
    coverage_study,
)

TESTS_PER_CASE = 40


def test_positioning_figure_intervals_cover(report):
    start = time.perf_counter()
    study = coverage_study(STUDY_CASES, TESTS_PER_CASE)
    seconds = time.perf_counter() - start
    lines = ["## Positioning figures: coverage of their intervals (#39)", "",
             f"{len(STUDY_CASES)} simulated axes × {TESTS_PER_CASE} tests, each through the "
             f"analysis ({seconds:.0f} s).", "",
             "| figure | printed p | achieved | missed / tests | width ÷ oracle spread | passes |",
             "|---|---|---|---|---|---|"]
    failed = []
    for key, row in study.items():
        # the width's aim is against the narrowest correct interval, where measured
        ok = row.coverage_passes and NARROWEST_CORRECT_RATIO.get(key, 0.0) <= WIDTH_LIMIT
        lines.append(f"| {key} | {100 * row.probability:.2f} % | {100 * row.coverage:.1f} % | "
                     f"{row.tests - row.hits} / {row.tests} | {row.width_ratio:.2f} | "
                     f"{'yes' if ok else 'NO'} |")
        if not row.coverage_passes:
            failed.append(key)
    # the decided quantity (half range of both directions' means) is E/2 with E's interval
    # halved: its coverage and width are E's (#39: one quantity, one interval)
    e = study["E"]
    lines += ["", f"Decided quantity (E/2, E's interval halved): {100 * e.coverage:.1f} % "
                  f"against {100 * e.probability:.2f} % printed, width {e.width_ratio:.2f} × "
                  "the spread of measured − truth in each case (an interval that knew σ along "
                  "the axis).", "",
                  "Width ÷ oracle spread: 2z × the standard deviation of measured − truth over "
                  "each case's tests, the width of an interval that knew σ along the axis. "
                  "Against the narrowest interval that holds whatever σ does (σ alike, 5 runs, "
                  "tests/benchmarks/least_favourable_width_study.py): " + ", ".join(
                      f"{key} {ratio:.2f} ×" for key, ratio in NARROWEST_CORRECT_RATIO.items()
                      if key not in NARROWEST_OF_MEANS)
                  + "; against the narrowest simple bounds that hold every curve and σ pattern "
                  "(the largest over its evaluation patterns, 5 runs, "
                  "tests/benchmarks/reversal_range_width_study.py): " + ", ".join(
                      f"{key} {ratio:.2f} ×" for key, ratio in NARROWEST_CORRECT_RATIO.items()
                      if key in NARROWEST_OF_MEANS) + "."]
    report("6-positioning-figures", lines)
    assert not failed, f"coverage below the printed probability: {failed}"
