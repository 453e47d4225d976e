"""Study: the decided quantity's interval (the half peak-to-peak of the continuous as-found
error over the whole period) when the readings are typed to a few decimals of a volt with no
ADC LSB stated, by the first-principles rig tests/fringe_typed_rig.py, each record written as
a user's file and analysed through the command line (``analyze fringe … --json``).

Per cell (decimals, σ as a share of the typed step, N; 3 periods; ``runs`` records seeded):
covered (truth within [interval_low, interval_high]) against the one-sided binomial floor at
the printed probability (the least count not significantly low, 5 %), misses with the truth
below the interval, and width/oracle: the median interval width over the spread of
(value − truth) between its (1 − p)/2 and (1 + p)/2 quantiles.

Run: ``nice -n 10 python -m tests.benchmarks.fringe_typed_decided_study [runs] [cells…]``
from the worktree (a cell as "2_0_64": decimals, σ/step, N; ~0.1–0.3 s a record).

Measured (seed 72; covered/n, floor, width/oracle; before: 0.8.20, 60 records a cell; after:
100 records a cell, 200 in the first):

| typed | σ/step | N | before | after |
|---|---|---|---|---|
| 0.01 V | 0 | 64 | 46/60 ↓ (54), 0.71 | 200/200 (186), 3.22 |
| 0.001 V | 0 | 64 | 57/60 (54), 1.12 | 100/100 (92), 1.35 |
| 0.01 V | 0.2 | 64 | 58/60 (54), 1.17 | 100/100 (92), 1.90 |
| 0.001 V | 0.2 | 64 | 60/60 (54), 1.25 | 99/100 (92), 1.26 |
| 0.01 V | 0 | 256 | 52/60 ↓ (54), 0.76 | 100/100 (92), 4.91 |
| 0.001 V | 0 | 256 | 57/60 (54), 1.10 | 100/100 (92), 1.36 |
| 0.01 V | 0.2 | 256 | 59/60 (54), 1.09 | 100/100 (92), 2.51 |
| 0.001 V | 0.2 | 256 | 60/60 (54), 1.29 | 98/100 (92), 1.31 |
| 0.01 V | 1 | 64 | (dithered: no change) | 99/100 (92), 1.47 |
| 0.001 V | 1 | 64 | (dithered: no change) | 97/100 (92), 1.14 |
| 0.01 V | 1 | 256 | (dithered: no change) | 99/100 (92), 1.24 |
| 0.001 V | 1 | 256 | 95/100 (92), 1.01 | 93/100 (92), 1.01; 193/200 (186), 1.07 |

The σ = 1 step rows of 100 were run with a bound of 10⁻⁸ δ still drawn, which the code now
drops (models/fringe/report.py DITHERED): the same records, other Monte Carlo draws (0.001 V,
N = 256: 95/100 on 0.8.20); the row of 200 and the dithered records checked since give
0.8.20's intervals to the last digit.

The width where undithered is a stated LSB's: one pattern for the whole record within ±δ/2,
taken whole (the audit's cell with --adc-lsb-mv 10 stated: 3.63).
"""

from __future__ import annotations

import contextlib
import io
import json
import sys
import tempfile
from pathlib import Path

import numpy as np
from scipy import stats

from app.main import main as cli
from tests.fringe_typed_rig import METADATA, TypedHead

CELLS = [(d, r, n) for d in (2, 3) for r in (0.0, 0.2, 1.0) for n in (64, 256)]
PERIODS = 3


def decided(path: Path, metadata: Path, options: list[str]) -> dict:
    """The JSON's decided_quantity of one record analysed by the command line."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = cli(["analyze", "fringe", str(path), "--json", "--metadata", str(metadata),
                    *options])
    if code not in (0, None):
        raise RuntimeError(err.getvalue()[-500:])
    return json.loads(out.getvalue())["decided_quantity"]


def run_cell(decimals: int, ratio: float, per_period: int, runs: int, seed: int = 72
             ) -> dict[str, float]:
    design = TypedHead(per_period, PERIODS, decimals, ratio)
    truth = design.true_half_range_arcsec()
    rng = np.random.default_rng([seed, decimals, int(ratio * 10), per_period])
    rows = []
    with tempfile.TemporaryDirectory() as folder:
        meta = Path(folder) / "meta.json"
        meta.write_text(json.dumps(METADATA), encoding="utf-8")
        for _ in range(runs):
            q = decided(design.write(Path(folder) / "typed.csv", rng), meta, design.options())
            rows.append((q["value"], q["interval_low"], q["interval_high"],
                         q["coverage_probability"]))
    a = np.array(rows, dtype=float)
    p = float(np.median(a[:, 3]))
    covered = int(np.sum((a[:, 1] <= truth) & (truth <= a[:, 2])))
    below = int(np.sum(truth < a[:, 1]))
    floor = int(np.argmax(stats.binom.cdf(np.arange(runs + 1), runs, p) > 0.05))
    spread = np.quantile(a[:, 0] - truth, [(1 - p) / 2, (1 + p) / 2], method="hazen")
    return {"runs": runs, "covered": covered, "floor": floor, "below": below,
            "P": float(stats.binom.cdf(covered, runs, p)), "probability": p,
            "width_oracle": float(np.median(a[:, 2] - a[:, 1]) / (spread[1] - spread[0])),
            "truth": truth}


def main(argv: list[str]) -> None:
    runs = int(argv[0]) if argv else 200
    cells = ([tuple(float(x) if i == 1 else int(x) for i, x in enumerate(c.split("_")))
              for c in argv[1:]] or CELLS)
    sys.stdout.write(f"{runs} records a cell, {PERIODS} periods\n"
                     "| typed | σ/step | N | covered/n | floor | P | misses below | "
                     "width/oracle |\n|---|---|---|---|---|---|---|---|\n")
    for decimals, ratio, n in cells:
        s = run_cell(int(decimals), float(ratio), int(n), runs)
        sys.stdout.write(f"| {10.0 ** -decimals:g} V | {ratio:g} | {n} | {s['covered']}/"
                         f"{s['runs']} | {s['floor']} | {s['P']:.2g} | {s['below']} | "
                         f"{s['width_oracle']:.2f} |\n")
        sys.stdout.flush()


if __name__ == "__main__":
    main(sys.argv[1:])
