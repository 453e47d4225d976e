"""Coverage of the ISO 230-2 repeatability figures' intervals R↑, R↓ and R (audit of #39,
finding 1) where σ changes from target to target: the cells of tests/repeatability_rig.py
(equal σ, σ varying 1.0–1.3×, one target's σ × 2 and × 3) at 13 targets × 5 runs, 12 × 3 and
41 × 5, each test through models.uncertainty.figure_intervals as the workbench calls it
(tests/benchmarks/repeatability_study.py; the theodolite with passes through the command
line: run that script with ``theodolite``). A figure passes a cell when its count covered is
not below the binomial floor (1 %) at the probability printed beside it."""

from __future__ import annotations

import time

from scipy.stats import binom

from tests.benchmarks.repeatability_study import (
    POSITIONING_DESIGNS,
    positioning_cell,
    summary,
)
from tests.repeatability_rig import PATTERNS

TESTS_PER_CELL = 80


def test_repeatability_intervals_cover_when_sigma_changes_along_the_axis(report):
    start = time.perf_counter()
    lines = ["## Repeatability figures R↑, R↓, R: coverage where σ changes along the axis", "",
             "| cell | figure | covered / tests | printed p | floor (1 %) | width ÷ oracle |",
             "|---|---|---|---|---|---|"]
    failed = []
    for pattern in PATTERNS:
        for m, runs in POSITIONING_DESIGNS:
            seed = 7000 + 100 * PATTERNS.index(pattern) + m + runs
            cell = summary(positioning_cell(pattern, m, runs, TESTS_PER_CELL, seed))
            for key in ("R_up", "R_down", "R"):
                row = cell[key]
                floor = int(binom.ppf(0.01, row["tests"], row["p"]))
                lines.append(f"| {pattern} {m}×{runs} | {key} | {row['covered']} / "
                             f"{row['tests']} | {100 * row['p']:.2f} % | {floor} | "
                             f"{row['width_oracle']:.2f} |")
                if row["covered"] < floor:
                    failed.append((pattern, m, runs, key))
    lines += ["", f"({time.perf_counter() - start:.0f} s)"]
    report("6b-repeatability-figures", lines)
    assert not failed, f"coverage below the printed probability: {failed}"
