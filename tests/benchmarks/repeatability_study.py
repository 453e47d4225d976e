"""The coverage study of the repeatability figures' intervals (R↑, R↓, R; A and E beside them
as a check that they did not move): the cells of tests/repeatability_rig.py, positioning
through models.uncertainty.figure_intervals as the workbench calls it, the theodolite with
passes through the command line's analysis. Run as a script to compare two checkouts:

    nice -n 10 python tests/benchmarks/repeatability_study.py positioning ROOT TESTS OUT.json
    nice -n 10 python tests/benchmarks/repeatability_study.py theodolite ROOT TESTS OUT.json
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile

import numpy as np

FIGURES = ("R_up", "R_down", "R", "A", "E")
POSITIONING_DESIGNS = ((13, 5), (12, 3), (41, 5))  # targets × runs
SIGMA = 0.5  # arcsec


def _rig():
    """tests/repeatability_rig.py: from this checkout's tests package, or (a script comparing
    another checkout, which has none) from this file's tests/ folder put on the path."""
    try:
        from tests import repeatability_rig
    except ImportError:
        import repeatability_rig  # type: ignore[import-not-found]
    return repeatability_rig


def _hazen(x: np.ndarray, q: float) -> float:
    x = np.sort(np.asarray(x, float))
    pos = min(max(q * x.size + 0.5, 1.0), float(x.size))
    lo = int(pos)
    hi = min(lo + 1, x.size)
    return float(x[lo - 1] + (pos - lo) * (x[hi - 1] - x[lo - 1]))


def summary(records: list[dict], figures: tuple[str, ...] = FIGURES) -> dict:
    """Per figure of ``figures``: coverage against the printed probability (covered, below,
    above, the lowest probability printed), and the median width ÷ the oracle's (the spread
    of value − truth between the (1 ∓ p)/2 quantiles: the width an interval about the value
    needs)."""
    out = {}
    for key in figures:
        rows = [r[key] for r in records if r.get(key) and r[key]["low"] is not None]
        if not rows:
            continue
        p = min(r["p"] for r in rows)
        err = np.array([r["value"] - r["truth"] for r in rows])
        oracle = _hazen(err, (1 + p) / 2) - _hazen(err, (1 - p) / 2)
        width = float(np.median([r["high"] - r["low"] for r in rows]))
        out[key] = {"tests": len(rows), "covered": sum(r["low"] <= r["truth"] <= r["high"]
                                                       for r in rows),
                    "below": sum(r["truth"] < r["low"] for r in rows),
                    "above": sum(r["truth"] > r["high"] for r in rows),
                    "p": p, "width": width, "width_oracle": width / oracle if oracle > 0
                    else float("nan")}
    return out


def positioning_cell(pattern: str, m: int, runs: int, tests: int, seed: int) -> list[dict]:
    """``tests`` tests of a cell through figure_intervals, as the workbench calls it."""
    from models.uncertainty.figure_intervals import figure_intervals, readings_seed

    positioning_test = _rig().positioning_test
    rng = np.random.default_rng(seed)
    records = []
    for _ in range(tests):
        readings, true = positioning_test(pattern, m, runs, SIGMA, rng)
        means = {k: v.mean(axis=0) for k, v in readings.items()}
        stds = {k: v.std(axis=0, ddof=1) for k, v in readings.items()}
        n = {k: np.full(m, runs) for k in readings}
        found = figure_intervals(means, stds, n, 0.9545,
                                 seed=readings_seed(readings["up"], readings["down"]))
        records.append({k: {"value": found[k].value, "low": found[k].low,
                            "high": found[k].high, "p": found[k].probability,
                            "truth": true[k]} for k in FIGURES})
    return records


def theodolite_cell(root: str, pattern: str, m: int, passes: int, tests: int, seed: int
                    ) -> list[dict]:
    """``tests`` theodolite records through ``root``'s command-line analysis."""
    theodolite_passes_csv = _rig().theodolite_passes_csv
    rng = np.random.default_rng(seed)
    records = []
    env = dict(os.environ, PYTHONPATH=root, QT_QPA_PLATFORM="offscreen",
               HOME=tempfile.mkdtemp(prefix="rhet_home_"))
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "passes.csv")
        for _ in range(tests):
            text, true = theodolite_passes_csv(pattern, m, passes, 0.3, rng)
            with open(path, "w") as f:
                f.write(text)
            done = subprocess.run([sys.executable, "-m", "app.main", "analyze", "theodolite",
                                   path, "--accuracy-arcsec", "0.3", "--json"], cwd=root,
                                  env=env, capture_output=True, text=True)
            figures = json.loads(done.stdout)["iso230_2_figures"]
            records.append({k: {"value": figures[k]["value"], "low": figures[k]["interval_low"],
                                "high": figures[k]["interval_high"],
                                "p": figures[k]["coverage_probability"], "truth": true[k]}
                            for k in FIGURES})
    return records


def main(argv: list[str]) -> None:
    bench, root, tests, out_path = argv[0], argv[1], int(argv[2]), argv[3]
    # the rig from this checkout's tests/, the code under study from ``root``
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    sys.path.insert(0, root)
    PATTERNS = _rig().PATTERNS
    result = {}
    for pattern in PATTERNS:
        if bench == "positioning":
            for m, runs in POSITIONING_DESIGNS:
                seed = 7000 + 100 * PATTERNS.index(pattern) + m + runs
                result[f"{pattern}_{m}x{runs}"] = summary(
                    positioning_cell(pattern, m, runs, tests, seed))
        else:
            seed = 9000 + PATTERNS.index(pattern)
            result[f"{pattern}_13x5"] = summary(theodolite_cell(root, pattern, 13, 5, tests,
                                                                seed))
        with open(out_path, "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main(sys.argv[1:])
