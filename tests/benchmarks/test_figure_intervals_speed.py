"""The figure intervals' Monte Carlo against the plain computation a reader would write
(numpy's reductions along each test's row of targets; Laird's EM one step after the other):
processor time, best of several runs in turn (the machine's load falls on both), reported as
a ratio. That they give the same figures bit for bit is a test:
tests/models/uncertainty/test_figure_intervals_bit_for_bit.py."""

from __future__ import annotations

import time

from models.uncertainty.figure_intervals import _ensemble, axis_figures
from tests.models.uncertainty.test_figure_intervals_bit_for_bit import (
    _draws,
    _ensemble_cases,
    _plain_ensemble,
    _plain_figures,
)


def _cpu_ratio(fast, plain, repeats: int) -> float:
    """Best processor time of ``fast`` over the best of ``plain``, run in turn."""
    best = [float("inf"), float("inf")]
    for _ in range(repeats):
        for i, f in enumerate((fast, plain)):
            start = time.process_time()
            f()
            best[i] = min(best[i], time.process_time() - start)
    return best[0] / best[1]


def test_figures_of_2000_tests_against_the_plain_reductions(report):
    """2000 tests of 12 targets (the bootstrap's draws of the bundled sample's size): 0.17
    of the plain reductions' time on a 2-core machine under a load of 7 (0.27 and 0.33 at
    72 and 24 targets); before, 0.73–0.78 (0.6–0.62 at 72 and 24)."""
    stats = _draws((2000,), 12, seed=5)

    def fast():
        for _ in range(10):
            axis_figures(stats)

    def plain():
        for _ in range(10):
            _plain_figures(stats)

    ratio = _cpu_ratio(fast, plain, repeats=7)
    report("9a-figure-interval-reductions", [
        "## Figure intervals: the figures of 2000 bootstrap tests (12 targets)",
        f"axis_figures in blocks, targets first: {ratio:.2f} of the plain reductions' CPU time "
        "(best of 7 in turn; bit for bit the same figures)"])
    assert ratio < 0.45


def test_triple_goal_world_against_the_plain_em(report):
    """A curve of 12 targets that makes all 3000 steps: 0.59 of the plain EM's time on a
    2-core machine under a load of 7; before, 1.04."""
    values, se2 = _ensemble_cases()[0]
    assert _plain_ensemble(values, se2)[1] == 3000
    ratio = _cpu_ratio(lambda: _ensemble(values, se2),
                       lambda: _plain_ensemble(values, se2), repeats=5)
    report("9b-figure-interval-em", [
        "## Figure intervals: the triple-goal world's EM (12 targets, 3000 steps)",
        f"_ensemble, steps checked 64 at a time: {ratio:.2f} of the plain EM's CPU time "
        "(best of 5 in turn; bit for bit the same world)"])
    assert ratio < 0.85
