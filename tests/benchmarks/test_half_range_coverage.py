"""The decided quantity's interval (half the peak-to-peak): its coverage by simulation over
the shapes that occur (smooth, rough, a single spike, the bundled samples' real curves),
noise 0.1 to 2 times the half range, 12 to 72 points, 100 runs a cell; and through each
workbench's own analysis and budget (the 3-D rigs), 200 runs each. Every cell must cover at
least the stated 95.45 % within the binomial scatter (fewer hits than a true 95.45 % gives
in 1 % of studies fail); the mean width against what a correct interval needs is reported
(the aim, 1.6 times, is not a condition: see models.validation.half_range). The figures the
certificate prints (models.uncertainty.conformity.HALF_RANGE_COVERAGE) are this study's
lowest cells, checked to agree.

The width study (issue #39's measure) runs the theodolite, polygon and positioning through
their analysis and budget, each decided as its certificate decides (positioning: E/2 with
E's own interval), over shapes × 12, 36, 72 points × noise 0.1, 0.5, 1, 2, 100 runs a cell:
every cell's coverage against the binomial floor, and its width against the oracle's (the
2.275 %–97.725 % spread of value − truth, at Hazen's plotting positions) reported — the aim
of 1.6 × is not a condition, and the table says where it is not reached."""

from __future__ import annotations

import time

from models.uncertainty.conformity import HALF_RANGE_COVERAGE
from models.validation.half_range import (
    coverage_study,
    fringe_coverage,
    polygon_coverage,
    summary,
    theodolite_coverage,
    width_study,
)

RUNS = 100
WIDTH_RUNS = 100  # a cell of the width study (144 cells, each run through a workbench)


def test_half_range_interval_covers(report):
    start = time.perf_counter()
    cells = coverage_study(RUNS)
    lines = ["| shape | points | noise/half range | coverage | width/needed |",
             "|---|---|---|---|---|"]
    lines += [f"| {c.shape} | {c.points} | {c.noise:g} | {100 * c.coverage:.1f} % | "
              f"{c.width_ratio:.2f} |" for c in cells]
    shapes = summary(cells)
    lines += ["", "| shape | lowest cell | pooled | runs | widest |", "|---|---|---|---|---|"]
    lines += [f"| {k} | {100 * s['lowest']:.1f} % | {100 * s['pooled']:.2f} % | {s['runs']} | "
              f"{s['width']:.2f} |" for k, s in shapes.items()]
    workbenches = [study(200) for study in (theodolite_coverage, polygon_coverage,
                                            fringe_coverage)]
    lines += ["", "| workbench | runs | coverage | width/needed |", "|---|---|---|---|"]
    lines += [f"| {w.workbench} ({w.describe}) | {w.runs} | {100 * w.coverage:.1f} % | "
              f"{w.width_ratio:.2f} |" for w in workbenches]
    lines.append(f"\n{time.perf_counter() - start:.0f} s")
    report("8-half-range", lines)
    assert all(c.accepted for c in cells), [c for c in cells if not c.accepted]
    assert all(w.accepted for w in workbenches), workbenches
    for shape, s in shapes.items():
        assert HALF_RANGE_COVERAGE[shape] >= 0.9545, shape  # what the certificate prints
        assert HALF_RANGE_COVERAGE[shape] == round(s["pooled"], 3), shape  # is what this found
        assert s["accepted"], shape  # and no cell short of 95.45 % beyond its binomial scatter


def test_half_range_width_through_the_workbenches(report):
    start = time.perf_counter()
    cells = width_study(WIDTH_RUNS)
    lines = ["| workbench | shape | points | noise/half range | coverage | misses low/high | "
             "width/oracle |", "|---|---|---|---|---|---|---|"]
    lines += [f"| {c.workbench} | {c.shape} | {c.points} | {c.noise:g} | "
              f"{100 * c.coverage:.1f} % | {c.low_misses}/{c.high_misses} | "
              f"{c.width_ratio:.2f} |" for c in cells]
    lines.append(f"\n{time.perf_counter() - start:.0f} s")
    report("8-half-range-width", lines)
    assert all(c.accepted for c in cells), [c for c in cells if not c.accepted]
