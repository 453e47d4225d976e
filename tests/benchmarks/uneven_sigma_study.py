"""The coverage study of every axis figure's interval where the repeatability differs from
target to target (#39: A at 3 runs each way, one target's σ × 3): the cells of
tests/uneven_sigma_axes.py through models.uncertainty.figure_intervals as the workbench
calls it. Run as a script to compare two checkouts (the rig from this checkout, the code
under study from ROOT):

    nice -n 10 python tests/benchmarks/uneven_sigma_study.py ROOT TESTS OUT.json
"""

from __future__ import annotations

import json
import os
import sys

import numpy as np

FIGURES = ("E", "E_up", "E_down", "M", "B", "B_mean", "R", "R_up", "R_down", "A", "A_up",
           "A_down", "Pa", "U_max", "Ps_max", "P")
DESIGNS = ((12, 5), (12, 3), (36, 3))  # targets × runs each way


def _rig():
    try:
        from tests import uneven_sigma_axes
    except ImportError:
        import uneven_sigma_axes  # type: ignore[import-not-found]
    return uneven_sigma_axes


def _tally():
    """tests/benchmarks/repeatability_study.py (its ``summary``): from this checkout's tests
    package, or from this file's folder when a script compares another checkout."""
    try:
        from tests.benchmarks import repeatability_study
    except ImportError:
        import repeatability_study  # type: ignore[import-not-found]
    return repeatability_study


def summary(records: list[dict]) -> dict:
    """Per figure: covered, below, above, the lowest probability printed, and the median
    width ÷ the oracle's (repeatability_study.summary over this study's figures)."""
    return _tally().summary(records, FIGURES)


def cell(pattern: str, m: int, runs: int, tests: int, seed: int) -> list[dict]:
    """``tests`` tests of a cell through figure_intervals, as the workbench calls it."""
    from models.uncertainty.figure_intervals import figure_intervals, readings_seed

    rig = _rig()
    rng = np.random.default_rng(seed)
    records = []
    for _ in range(tests):
        readings, true = rig.positioning_test(pattern, m, runs, rng)
        means, stds, n = rig.summary_stats(readings)
        found = figure_intervals(means, stds, n, 0.9545,
                                 seed=readings_seed(readings["up"], readings["down"]))
        records.append({k: {"value": found[k].value, "low": found[k].low,
                            "high": found[k].high, "p": found[k].probability,
                            "truth": true[k]} for k in FIGURES if k in found})
    return records


def cell_seed(pattern: str, m: int, runs: int) -> int:
    return 3900 + 100 * _rig().PATTERNS.index(pattern) + m + runs


def main(argv: list[str]) -> None:
    root, tests, out_path = argv[0], int(argv[1]), argv[2]
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    sys.path.insert(0, root)
    result = {}
    for pattern in _rig().PATTERNS:
        for m, runs in DESIGNS:
            result[f"{pattern}_{m}x{runs}"] = summary(
                cell(pattern, m, runs, tests, cell_seed(pattern, m, runs)))
            with open(out_path + ".part", "w") as f:
                json.dump(result, f, indent=1)
    os.replace(out_path + ".part", out_path)


if __name__ == "__main__":
    main(sys.argv[1:])
