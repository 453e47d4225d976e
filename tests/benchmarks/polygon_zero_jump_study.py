"""Study: a polygon encoder test, 2 sets each way, whose autocollimator's zero moves between
sets (an audit's finding, 2026-12-06), by the first-principles rig tests/polygon_zero_jump_rig.py,
through the workbench's analysis and its certificate's decision (grade 3, ±1″, simple
acceptance).

Per cell, ``runs`` runs, each a new encoder curve, artefact and noise:

* decided: how often the decided half range's interval holds its truth (half the true
  curve's peak-to-peak), the floor (least count not significantly low, one-sided binomial
  5 % at the interval's probability), the median value − truth, and the median width against
  the oracle's (the spread of value − truth over the runs at that probability);
* false pass: runs whose true half range exceeds the grade's 1″ and whose decision says
  "pass", of all runs (with a curve of 0.8″ rms nearly every truth is above 1″);
* per point: how often |error − truth| ≤ U (faces 2…n; face 1 is the zero), and the median U
  against the 95.45 % quantile of |error − truth| over the runs;
* warned: runs whose warnings say the autocollimator's zero moved between the sets.

Run: ``nice -n 10 python -m tests.benchmarks.polygon_zero_jump_study [runs]`` from the
worktree (about a second a run).
"""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np
from scipy import stats

from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget
from models.readings.sheet import ReadingsSheet
from tests.polygon_zero_jump_rig import ZeroJumpRig

METADATA = {"decision_rule": "simple", "decision_quantity": "half_range",
            "standards": [{"description": "polygon (deviations from face 1)", "serial": "P1",
                           "certificate_no": "C1", "uncertainty": 0.1,
                           "uncertainty_unit": "arcsec", "basis": "U95",
                           "applies_to": "from face 1"}]}

CELLS: dict[str, dict[str, Any]] = {
    "24f_jumps1.0": dict(faces=24, sigma=0.1, sigma_enc=0.1, jump_sd=1.0),
    "24f_rate0.02": dict(faces=24, sigma=0.1, sigma_enc=0.1, rate=0.02),
    "24f_jumps+rate": dict(faces=24, sigma=0.1, sigma_enc=0.1, jump_sd=1.0, rate=0.02),
    "24f_jumps+rate_spread": dict(faces=24, sigma=0.1, sigma_enc=0.1, jump_sd=1.0, rate=0.02,
                                  settings={"closure_drift": "spread"}),
    "24f_control": dict(faces=24, sigma=0.1, sigma_enc=0.1),
    "12f_jumps1.0": dict(faces=12, sigma=0.05, sigma_enc=0.05, jump_sd=1.0),
    "12f_rate0.02": dict(faces=12, sigma=0.05, sigma_enc=0.05, rate=0.02),
    "12f_control": dict(faces=12, sigma=0.05, sigma_enc=0.05),
    # the offsets drawn other ways (tests/polygon_zero_jump_rig.py ``offsets``): one zero
    # about which every set scatters, set 1's too; a zero that jumps on from where it was
    "24f_jumps1.0_each": dict(faces=24, sigma=0.1, sigma_enc=0.1, jump_sd=1.0, offsets="each"),
    "24f_jumps1.0_walk": dict(faces=24, sigma=0.1, sigma_enc=0.1, jump_sd=1.0, offsets="walk"),
    "12f_jumps1.0_each": dict(faces=12, sigma=0.05, sigma_enc=0.05, jump_sd=1.0, offsets="each"),
    "12f_jumps1.0_walk": dict(faces=12, sigma=0.05, sigma_enc=0.05, jump_sd=1.0, offsets="walk"),
    "12f_jumps0.3+rate0.01": dict(faces=12, sigma=0.05, sigma_enc=0.05, jump_sd=0.3, rate=0.01),
}


def floor_count(n: int, p: float) -> int:
    """The least count not significantly low (one-sided binomial, 5 %)."""
    return next(k for k in range(n + 1) if stats.binom.cdf(k, n, p) >= 0.05)


def cell(name: str, runs: int, seed: int | None = None) -> dict[str, Any]:
    seed = 6800 + 1000 * list(CELLS).index(name) if seed is None else seed
    options = dict(CELLS[name])
    settings = {"grade": 3, **options.pop("settings", {})}
    rig = ZeroJumpRig(**options)
    meta = CertificateMetadata.from_dict(METADATA)
    hits = decided = false_pass = covered = points = warned = 0
    offsets, widths, spread, dev_points, u_points = [], [], [], [], []
    probability = math.nan
    for run in range(runs):
        rng = np.random.default_rng(seed + run)
        lines, truth = rig.run(rng)
        rows = [line.split(",") for line in lines[1:]]
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), settings)
        true_half = 0.5 * float(np.ptp(truth))
        warned += int(any("zero moved between the sets" in w for w in result.warnings))
        big_u = polygon_budget(result, meta, settings).expanded
        dev = result.mean_corrected_arcsec - truth
        covered += int(np.sum(np.abs(dev[1:]) <= big_u[1:]))
        points += result.faces - 1
        dev_points.append(np.abs(dev[1:]))
        u_points.append(big_u[1:])
        conformity = POLYGON.certificate_document(result, meta, "", settings).conformity
        low, high = conformity.interval_low, conformity.interval_high
        if math.isfinite(low) and math.isfinite(high):
            decided += 1
            probability = conformity.probability
            hits += int(low <= true_half <= high)
            widths.append(high - low)
            offsets.append(conformity.value - true_half)
            spread.append(conformity.value - true_half)
        false_pass += int(true_half > 1.0 and conformity.verdict == "pass")
    p = probability if math.isfinite(probability) else 0.9545
    q = np.quantile(spread, [(1 - p) / 2, (1 + p) / 2]) if spread else (0.0, math.nan)
    return {"cell": name, "runs": runs, "decided": decided, "hits": hits,
            "floor": floor_count(decided, p) if decided else 0,
            "p": p, "width_oracle": float(np.median(widths)) / float(q[1] - q[0])
            if widths else math.nan,
            "median_offset": float(np.median(offsets)) if offsets else math.nan,
            "false_pass": false_pass, "warned": warned,
            "point_coverage": covered / points,
            "u_oracle": float(np.median(np.concatenate(u_points)))
            / float(np.quantile(np.concatenate(dev_points), 0.9545))}


def main(runs: int = 40, names: list[str] | None = None) -> None:
    out = sys.stdout
    out.write("| cell | runs | decided covered (floor) | value − truth (median) | width/oracle "
              "| false pass | per point | U/oracle | zero moved (warned) |\n"
              "|---|---|---|---|---|---|---|---|---|\n")
    for name in names or list(CELLS):
        c = cell(name, runs)
        out.write(f"| {name} | {c['runs']} | {c['hits']}/{c['decided']} (≥{c['floor']}) | "
                  f"{c['median_offset']:+.3f}″ | {c['width_oracle']:.2f} | "
                  f"{c['false_pass']}/{c['runs']} | {100 * c['point_coverage']:.1f} % | "
                  f"{c['u_oracle']:.2f} | {c['warned']}/{c['runs']} |\n")
        out.flush()


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 40, sys.argv[2:] or None)
