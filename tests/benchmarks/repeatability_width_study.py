"""Coverage and width of R's (and R↑'s, R↓'s, B's) intervals (#39) over the cells of
tests/repeatability_width_axes.py (smooth and rough curves × reversal none or large × σ
constant, varying or one target's × 3 × 12 and 36 targets × 3 and 5 runs each way), through
models.uncertainty.figure_intervals as the workbench calls it (R's interval is the
per-target bounds, which do not depend on the bootstrap; B's lower end takes the
bootstrap's, here at 400 trials). Run as a script to compare two checkouts (the rig from
this checkout, the code under study from ROOT):

    nice -n 10 python tests/benchmarks/repeatability_width_study.py ROOT TESTS OUT.json

The run of #39's R change (200 tests a cell, 48 cells; the code before it and after, the same
readings): R covered 191–200 of 200 in every cell before and after (the binomial floor at
1 % is 184; the misses all below the lower end, which now uses its tail: 0–9 a cell, 0–7
before), its width 0.61–0.66 of before at 3 runs and 0.67–0.79 at 5 where the two-way term
or both σ's make R, 0.69–0.74 and 0.87–0.95 with one target's σ × 3 (its 4σ makes R, and
its bound is as before); width ÷ oracle 9.3–17.0 at 3 runs, 4.7–8.5 at 5 (15–27 and 6.3–12
before), 1.8–5.0 with one target × 3 (2.0–6.8). R↑, R↓ and B (unchanged) the same numbers
in both: R↑, R↓ 190–200, B 185–200 covered, B's width ÷ oracle 1.2–2.9.
"""

from __future__ import annotations

import json
import os
import sys

import numpy as np

DESIGNS = ((12, 3), (12, 5), (36, 3), (36, 5))  # targets × runs each way


def _rig():
    try:
        from tests import repeatability_width_axes
    except ImportError:
        import repeatability_width_axes  # type: ignore[import-not-found]
    return repeatability_width_axes


def cell(curve: str, reversal: str, pattern: str, m: int, runs: int, tests: int,
         seed: int) -> dict:
    """Per figure: tests, covered, below, above, lowest probability printed, median width,
    its ends, the truth, and the width ÷ the oracle's (the spread of value − truth between
    its (1 ∓ p)/2 quantiles over the tests: the width an interval about the value needs;
    the values, and so the oracle, are the same in every checkout)."""
    from models.uncertainty.figure_intervals import figure_intervals, readings_seed

    rig = _rig()
    rng = np.random.default_rng(seed)
    rows: dict[str, list] = {k: [] for k in rig.KEYS}
    for _ in range(tests):
        readings, true = rig.axis_test(curve, reversal, pattern, m, runs, rng)
        means = {k: v.mean(axis=0) for k, v in readings.items()}
        stds = {k: v.std(axis=0, ddof=1) for k, v in readings.items()}
        n = {k: np.full(m, runs) for k in readings}
        found = figure_intervals(means, stds, n, 0.9545, trials=400, outer=0,
                                 seed=readings_seed(readings["up"], readings["down"]))
        for k in rig.KEYS:
            f = found[k]
            rows[k].append((f.low, f.high, f.probability, true[k], f.value))
    try:
        from tests.interval_study_scores import interval_scores
    except ImportError:
        from interval_study_scores import interval_scores  # type: ignore[import-not-found,no-redef]
    return interval_scores(rows)


def main(argv: list[str]) -> None:
    root, tests, out_path = argv[0], int(argv[1]), argv[2]
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    sys.path.insert(0, root)
    rig = _rig()
    result = {}
    for ci, curve in enumerate(rig.CURVES):
        for ri, reversal in enumerate(rig.REVERSALS):
            for pi, pattern in enumerate(rig.PATTERNS):
                for m, runs in DESIGNS:
                    seed = 9100 + 1000 * ci + 400 * ri + 100 * pi + m + runs
                    result[f"{curve}_{reversal}_{pattern}_{m}x{runs}"] = cell(
                        curve, reversal, pattern, m, runs, tests, seed)
                    with open(out_path + ".part", "w") as f:
                        json.dump(result, f, indent=1)
    os.replace(out_path + ".part", out_path)


if __name__ == "__main__":
    main(sys.argv[1:])
