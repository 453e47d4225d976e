"""Coverage and width of the band figures' intervals (A, A↑, A↓, P, Ps_max; #39) over the
cells of tests/band_width_axes.py (smooth and rough curves × σ varying or one target × 3 ×
12 and 36 targets × 3 and 5 runs each way), through models.uncertainty.figure_intervals as
the workbench calls it (these figures' intervals are the per-target bounds, which do not
depend on the bootstrap: it runs with few trials here). Run as a script to compare two
checkouts (the rig from this checkout, the code under study from ROOT):

    nice -n 10 python tests/benchmarks/band_width_study.py ROOT TESTS OUT.json
"""

from __future__ import annotations

import json
import os
import sys

import numpy as np

DESIGNS = ((12, 3), (12, 5), (36, 3), (36, 5))  # targets × runs each way


def _rig():
    try:
        from tests import band_width_axes
    except ImportError:
        import band_width_axes  # type: ignore[import-not-found]
    return band_width_axes


def cell(curve: str, pattern: str, m: int, runs: int, tests: int, seed: int) -> dict:
    """Per figure: tests, covered, below, above, lowest probability printed, median width,
    and the width ÷ the oracle's (tests/benchmarks/repeatability_study.py: the spread of
    value − truth between its (1 ∓ p)/2 quantiles, the width an interval about the value
    needs; the values, and so the oracle, are the same in every checkout)."""
    from models.uncertainty.figure_intervals import figure_intervals, readings_seed

    rig = _rig()
    rng = np.random.default_rng(seed)
    rows: dict[str, list] = {k: [] for k in rig.BAND_KEYS}
    for _ in range(tests):
        readings, true = rig.axis_test(curve, pattern, m, runs, rng)
        means = {k: v.mean(axis=0) for k, v in readings.items()}
        stds = {k: v.std(axis=0, ddof=1) for k, v in readings.items()}
        n = {k: np.full(m, runs) for k in readings}
        found = figure_intervals(means, stds, n, 0.9545, trials=200, outer=0,
                                 seed=readings_seed(readings["up"], readings["down"]))
        for k in rig.BAND_KEYS:
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
        for pi, pattern in enumerate(rig.PATTERNS):
            for m, runs in DESIGNS:
                seed = 7200 + 1000 * ci + 100 * pi + m + runs
                result[f"{curve}_{pattern}_{m}x{runs}"] = cell(curve, pattern, m, runs,
                                                               tests, seed)
                with open(out_path + ".part", "w") as f:
                    json.dump(result, f, indent=1)
    os.replace(out_path + ".part", out_path)


if __name__ == "__main__":
    main(sys.argv[1:])
