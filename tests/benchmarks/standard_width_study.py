"""Study (#39's widths): the intervals of E, M and the decided half range (E/2) of a rotary
axis read with a reference standard whose U is stated for any angle (a laser rotary
calibrator), before and after 0.8.20's two changes:

* the per-target part of such a standard drawn at u/√2 (two targets' errors differ by one more
  angle, u), not at u (models.positioning.report._type_b_per_target);
* E's (E↑'s, E↓'s) readings' interval moved out by k · pair taken at the level at which it
  misses at the tail at the least favourable bias
  (models.uncertainty.figure_intervals.bias_aware_tail), not at the tail. The first run of
  this study (#39's widths) took M's so too, and M covered 173 of 200 at ``worst:37`` (floor
  176): M keeps its interval at the tail (BIAS_LEVEL_FIGURES), and its "after" is the first
  change alone, which holds the first run's interval test by test (the same draws and seeds;
  an interval at a less extreme level lies within the one at the tail), so covers at least
  as often.

The axes are those of the coverage study (models.validation.axis_figures_rig, numpy only:
STUDY_CASES' shapes × 12 and 72 targets × repeatability 0.1, 0.5 and 2 × the signal, σ varying
along the axis); the reference's error, the same at a target in every run and both
directions, is simulated here from first principles, one draw a test of one of five shapes
within the statement (u = U/2 for any angle, so the difference of two targets' errors has a
standard deviation of at most u):

* ``offset``: c ~ N(0, u²) at every target (it cancels in every figure);
* ``scale``: ε θ/360°, ε ~ N(0, u²);
* ``turn``: a once-a-turn error a sin(θ + φ), a ~ N(0, (u/2)²);
* ``independent``: N(0, u²/2) at each target on its own;
* ``curve``: the axis's own curve's shape, g ∈ [−1, 1], times N(0, (u/2)²).

Cells ``worst``: the curve's shape at its full U (a range of U) against the curve, every test
(the bias the statement allows at its U: the envelope's case).

Per cell: coverage of the truth (the axis's E, M, E/2) against the floor (one-sided binomial
1 % at the probability printed), and the mean width against the oracle's, the spread of
value − truth between the (1 − p)/2 and (1 + p)/2 quantiles over the cell's tests.

The intervals are models.uncertainty.figure_intervals' with the positioning workbench's
arguments, without the iterated bootstrap's calibration (outer = inner = 0: E's interval does
not use it; M's is calibrated in the workbench) to keep the study within its CPU.

Run: ``nice -n 10 python -m tests.benchmarks.standard_width_study TESTS [CELL …]`` from the
worktree (CELL: an index of STUDY_CASES, or ``worst:INDEX``).
"""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np
from scipy.stats import binom

from models.positioning.figure_coverage import STUDY_CASES
from models.uncertainty.figure_intervals import ACHIEVED, figure_intervals
from models.validation.axis_figures_rig import AxisCase

#: the standard's expanded uncertainty (k = 2), stated for any angle (″): a quarter of the
#: axes' curves' peak-to-peak
U = 0.5
SHAPES = ("offset", "scale", "turn", "independent", "curve")
#: 12 and 72 targets × 0.1, 0.5, 2 × the four shapes, σ varying along the axis
CELLS = tuple(i for i, c in enumerate(STUDY_CASES)
              if c.targets in (12, 72) and c.noise_ratio in (0.1, 0.5, 2.0) and c.varying)
PROBABILITY = 0.9545
KEYS = ("E", "M")


def _unit_curve(case: AxisCase) -> np.ndarray:
    f = case.f
    return (f - 0.5 * (f.max() + f.min())) / (0.5 * float(np.ptp(f)))


def reference_error(case: AxisCase, shape: str, u: float, rng: np.random.Generator
                    ) -> np.ndarray:
    """The standard's error at each target, one draw of ``shape`` within u for any angle."""
    theta = np.radians(case.angles)
    if shape == "offset":
        return np.full(case.targets, rng.normal(0.0, u))
    if shape == "scale":
        return rng.normal(0.0, u) * case.angles / 360.0
    if shape == "turn":
        return rng.normal(0.0, 0.5 * u) * np.sin(theta + rng.uniform(0.0, 2.0 * math.pi))
    if shape == "independent":
        return rng.normal(0.0, u / math.sqrt(2.0), case.targets)
    if shape == "curve":
        return rng.normal(0.0, 0.5 * u) * _unit_curve(case)
    if shape == "worst":
        return -U * 0.5 * _unit_curve(case)  # a range of U, against the curve
    raise ValueError(shape)


def test_statistics(case: AxisCase, error: np.ndarray, rng: np.random.Generator):
    """Means, s and runs per direction of one simulated test with the reference's error."""
    values: dict[str, list[list[float]]] = {"up": [[] for _ in case.angles],
                                            "down": [[] for _ in case.angles]}
    where = {float(a): i for i, a in enumerate(case.angles)}
    for target, _, sign, x in case.readings(rng):
        i = where[target]
        values["up" if sign == "+" else "down"][i].append(x + float(error[i]))
    means = {k: np.array([np.mean(v) for v in rows]) for k, rows in values.items()}
    stds = {k: np.array([np.std(v, ddof=1) for v in rows]) for k, rows in values.items()}
    runs = {k: np.full(case.targets, case.runs) for k in values}
    return means, stds, runs


def cell(index: int, tests: int, worst: bool = False) -> dict:
    case = STUDY_CASES[index]
    rng = np.random.default_rng([39, index, int(worst)])
    truth = case.truth()
    u = 0.5 * U
    rows: dict[str, list[tuple[float, float, float, float, float]]] = {k: [] for k in KEYS}
    for t in range(tests):
        shape = "worst" if worst else SHAPES[t % len(SHAPES)]
        means, stds, runs = test_statistics(case, reference_error(case, shape, u, rng), rng)
        seed = int(rng.integers(2**62))
        kw: dict[str, Any] = dict(seed=seed, outer=0, inner=0, pair_u=u, pair_envelope=True, cache={})
        before = figure_intervals(means, stds, runs, PROBABILITY, np.full(case.targets, u), **kw)
        after = figure_intervals(means, stds, runs, PROBABILITY,
                                 np.full(case.targets, u / math.sqrt(2.0)),
                                 pair_bias_level=True, **kw)
        for key in KEYS:
            rows[key].append((before[key].value, before[key].low, before[key].high,
                              after[key].low, after[key].high))
    out = {"cell": f"{'worst ' if worst else ''}{case.shape} {case.targets} "
                   f"{case.noise_ratio:g}×", "tests": tests}
    for key in KEYS:
        a = np.array(rows[key])
        p = min(PROBABILITY, ACHIEVED.get(key, PROBABILITY))
        err = a[:, 0] - truth[key]
        q = np.quantile(err, [(1 - p) / 2, (1 + p) / 2])
        oracle = float(q[1] - q[0])
        floor = int(binom.ppf(0.01, tests, p))
        for name, lo, hi in (("before", 1, 2), ("after", 3, 4)):
            hits = int(np.sum((a[:, lo] <= truth[key] + 1e-12)
                              & (truth[key] - 1e-12 <= a[:, hi])))
            out[f"{key} {name}"] = (hits, floor, float(np.mean(a[:, hi] - a[:, lo])) / oracle)
    return out


def main(tests: int = 200, names: list[str] | None = None) -> None:
    out = sys.stdout
    out.write("| cell | tests | E before: covered (floor), width/oracle | E after | "
              "M before | M after |\n|---|---|---|---|---|---|\n")
    for name in names or [str(i) for i in CELLS]:
        worst = name.startswith("worst:")
        c = cell(int(name.split(":")[-1]), tests, worst)
        parts = [f"{c[k][0]}/{tests} (≥{c[k][1]}), {c[k][2]:.2f}"
                 for k in ("E before", "E after", "M before", "M after")]
        out.write(f"| {c['cell']} | {tests} | " + " | ".join(parts) + " |\n")
        out.flush()


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 200, sys.argv[2:] or None)
