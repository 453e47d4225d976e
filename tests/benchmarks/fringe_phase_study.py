"""Study: the U of the fringe signal parameters (the JSON's ``expanded_uncertainty_*``, the
certificate's and the XLSX's "Signal parameters identified"), the phases c1, c3, c5 of both
channels above all, by the first-principles rig tests/fringe_sampling_rig.py (the audit 69
cells FA, FD and the controls FG, FE; a clock with timing jitter, an ADC with an offset and gain
ratio drawn once a run, noise, rounding), through the workbench's analysis and its JSON.

Per cell and parameter, over ``runs`` runs (seeded):

* covered: runs with |estimate − truth| ≤ U, of the runs with a U; the floor (least count not
  significantly low, one-sided binomial 5 % at 95.45 %) and P (the binomial probability of
  so few or fewer);
* U/oracle: the median U against the 95.45 % quantile of |estimate − truth| over the runs;
* spread/u (a phase): the standard deviation of estimate − truth over the runs against the
  median standard uncertainty stated for it (models.fringe.parameter_uncertainty; 1 where
  that u is the spread), and mean/u its mean against the same u.

Run: ``nice -n 10 python -m tests.benchmarks.fringe_phase_study [runs] [cell …]`` from the
worktree (10–40 ms a run). Cells: those of the rig, and each with ``-nojitter`` (the clock
exact, no phase reference u stated) or ``-jitterX`` (X degrees of timing jitter, stated).
"""

from __future__ import annotations

import dataclasses
import math
import sys

import numpy as np
from scipy import stats

from models.certificate.metadata import CertificateMetadata
from models.fringe.analysis import FRINGE
from models.fringe.parameter_uncertainty import parameter_uncertainty
from models.readings.sheet import ParsedReadings
from tests.fringe_sampling_rig import AUDIT_CELLS, SampledHead, wrapped

P = 0.9545
NAMES = [f"{c}_{p}" for c in ("sin", "cos") for p in ("A0", "A1", "c1", "A3", "c3", "A5", "c5")]


def cell_of(name: str) -> SampledHead:
    base, _, variant = name.partition("-")
    cell = AUDIT_CELLS[base]
    if variant == "nojitter":
        return dataclasses.replace(cell, jitter_deg=0.0)
    if variant.startswith("jitter"):
        return dataclasses.replace(cell, jitter_deg=float(variant[len("jitter"):]))
    if variant:
        raise SystemExit(f"unknown variant {variant!r}")
    return cell


def run_cell(cell: SampledHead, runs: int, seed: int = 70
             ) -> dict[str, list[tuple[float, float, float]]]:
    """{"cos_c1": [(error, U or NaN, the stated u of a phase or NaN), …], …,
    "quadrature": …} over ``runs`` runs."""
    metadata = CertificateMetadata.from_dict({})
    truth = cell.parameters()
    rng = np.random.default_rng(seed)
    out: dict[str, list[tuple[float, float, float]]] = {n: [] for n in [*NAMES, "quadrature"]}
    for _ in range(runs):
        u_sin, u_cos, theta_deg = cell.readings(rng)
        parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos, "theta_deg": theta_deg},
                                np.arange(u_sin.size))
        result = FRINGE.analyze(parsed, cell.settings())
        data = FRINGE.certified_json(result, metadata)
        stated = parameter_uncertainty(result)
        for label in ("sin", "cos"):
            params = data[f"{label}_params"]
            for key in ("A0", "A1", "c1", "A3", "c3", "A5", "c5"):
                error = params[key] - truth[label][key]
                u = math.nan
                if key.startswith("c"):
                    error = wrapped(error)
                    u = stated.channels[label][key]
                big_u = params[f"expanded_uncertainty_{key}"]
                out[f"{label}_{key}"].append((error, math.nan if big_u is None else big_u, u))
        quadrature_u = data["expanded_uncertainty_quadrature_error_deg"]
        out["quadrature"].append((result.quadrature_error_deg - cell.quadrature_deg,
                                  math.nan if quadrature_u is None else quadrature_u,
                                  math.degrees(stated.quadrature_rad)))
    return out


def floor(runs: int, p: float = P) -> int:
    """The least count not significantly low (one-sided binomial, 5 %)."""
    for k in range(runs + 1):
        if stats.binom.cdf(k, runs, p) >= 0.05:
            return k
    return runs


def scores(rows: list[tuple[float, float, float]]) -> dict[str, float]:
    a = np.array(rows, dtype=float)
    with_u = a[np.isfinite(a[:, 1])]
    n = len(with_u)
    covered = int(np.sum(np.abs(with_u[:, 0]) <= with_u[:, 1]))
    oracle = float(np.quantile(np.abs(a[:, 0]), P))
    stated_u = a[np.isfinite(a[:, 2]), 2]
    return dict(n=n, covered=covered, floor=floor(n) if n else 0,
                p=float(stats.binom.cdf(covered, n, P)) if n else math.nan,
                u_oracle=float(np.median(with_u[:, 1])) / oracle if n else math.nan,
                spread_u=float(np.std(a[:, 0], ddof=1) / np.median(stated_u)) if stated_u.size
                else math.nan,
                bias_u=float(np.mean(a[:, 0]) / np.median(stated_u)) if stated_u.size else math.nan)


def main(argv: list[str]) -> None:
    runs = int(argv[0]) if argv else 400
    names = argv[1:] or list(AUDIT_CELLS)
    out = sys.stdout
    for name in names:
        result = run_cell(cell_of(name), runs)
        out.write(f"\n{name} ({runs} runs)\n"
                  "| parameter | covered/n | floor | P | U/oracle | spread/u | mean/u |\n"
                  "|---|---|---|---|---|---|---|\n")
        for key, rows in result.items():
            s = scores(rows)
            out.write(f"| {key} | {s['covered']}/{s['n']} | {s['floor']} | {s['p']:.3g} | "
                      f"{s['u_oracle']:.3f} | {s['spread_u']:.3f} | {s['bias_u']:+.3f} |\n")
        out.flush()


if __name__ == "__main__":
    main(sys.argv[1:])
