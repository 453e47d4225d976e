"""Study (issue 39's widths): the polygon workbench's decided half range where the
autocollimator's zero moved between the sets (the audit's draw: set 1's zero exact, each later
set's offset N(0, 1″) about it), by the first-principles rig tests/polygon_zero_jump_rig.py
(exact 3-D: polygon, autocollimator, the encoder's error, each face's pyramidal error; numpy
only), through the workbench's analysis and its certificate's decision.

Per cell (the encoder's curve smooth, rough or a spike of true half range 1″; the noise of
one error, encoder and autocollimator together, 0.1, 0.5 or 2 times it; 12, 24, 36 or 72
faces; 2 sets each way), ``runs`` runs, each a new curve, artefact and noise:

* covered: how often the decided half range's interval holds the truth (half the true
  curve's peak-to-peak at the faces), and the floor (the least count not significantly low,
  one-sided binomial 5 % at the printed probability);
* width/oracle: the median width of the interval over the oracle's, the spread of
  value − truth over the runs between its (1 − p)/2 and (1 + p)/2 quantiles;
* value − truth: the median.

Run: ``nice -n 10 python -m tests.benchmarks.polygon_zero_width_study [runs] [shape …]`` from
the worktree (a few hundredths of a second a run). ``… [runs] lower shape:noise:faces …``
prints :func:`lower_ends` for those cells instead (2026-12-06, 200 runs: smooth 0.5× 72 faces
199, 199, 189, 147 of 200 at 1.53, 1.46, 1.30, 1.02 times the oracle; spike 0.5× 72 faces
195, 193, 185, 161 at 1.39, 1.34, 1.26, 1.10; spike 0.1× 24 faces 199, 196, 189, 174; rough
0.5× 24 faces 194, 194, 189, 185; floor 186).
"""

from __future__ import annotations

import math
import sys
from typing import Any

import numpy as np
from scipy import stats

from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget, rounding_bounded_half_range
from models.readings.sheet import ReadingsSheet
from models.uncertainty.conformity import half_range_monte_carlo
from tests.polygon_zero_jump_rig import ZeroJumpRig

METADATA = {"decision_rule": "simple", "decision_quantity": "half_range",
            "standards": [{"description": "polygon (deviations from face 1)", "serial": "P1",
                           "certificate_no": "C1", "uncertainty": 0.1,
                           "uncertainty_unit": "arcsec", "basis": "U95",
                           "applies_to": "from face 1"}]}
#: grade 7 (closure limit 15″): at twice the signal's noise a closure of grade 3 (0.5″) fails
#: and the certificate states nothing
SETTINGS = {"grade": 7}
SHAPES = ("smooth", "rough", "spike")
NOISES = (0.1, 0.5, 2.0)  # the noise of one error over the true half range
FACES = (12, 24, 36, 72)


def floor_count(n: int, p: float) -> int:
    """The least count not significantly low (one-sided binomial, 5 %)."""
    return next(k for k in range(n + 1) if stats.binom.cdf(k, n, p) >= 0.05)


def rig(shape: str, noise: float, faces: int, jump_sd: float = 1.0) -> ZeroJumpRig:
    """The cell's rig: the noise of one error ``noise`` × the half range (1″), half of its
    variance the autocollimator's horizontal reading, half the encoder's."""
    sigma = noise / math.sqrt(2.0)
    return ZeroJumpRig(faces=faces, sets=4, sigma=sigma, sigma_enc=sigma, jump_sd=jump_sd,
                       shape=shape, half_range=1.0)


def cell(shape: str, noise: float, faces: int, runs: int, seed: int | None = None,
         jump_sd: float = 1.0) -> dict[str, Any]:
    if seed is None:
        seed = (39_000 + 1000 * SHAPES.index(shape) + 100 * NOISES.index(noise)
                + FACES.index(faces))
    the_rig = rig(shape, noise, faces, jump_sd)
    meta = CertificateMetadata.from_dict(METADATA)
    hits = decided = 0
    widths, offsets = [], []
    probability = math.nan
    for run in range(runs):
        lines, truth = the_rig.run(np.random.default_rng(seed + 7919 * run))
        rows = [line.split(",") for line in lines[1:]]
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), SETTINGS)
        true_half = 0.5 * float(np.ptp(truth))
        # the certificate's decided half range (models.polygon.report.certificate_document)
        mc = rounding_bounded_half_range(result, meta, SETTINGS) or half_range_monte_carlo(
            result.mean_corrected_arcsec, polygon_budget(result, meta, SETTINGS))
        low, high = max(0.0, mc.value - mc.u_lower), mc.value + mc.u_upper
        if result.valid and math.isfinite(low) and math.isfinite(high):
            decided += 1
            probability = mc.probability
            hits += int(low <= true_half <= high)
            widths.append(high - low)
            offsets.append(mc.value - true_half)
    p = probability if math.isfinite(probability) else 0.9545
    q = np.quantile(offsets, [(1 - p) / 2, (1 + p) / 2]) if offsets else (0.0, math.nan)
    return {"cell": f"{shape} {noise:g}× {faces}f", "runs": runs, "decided": decided,
            "hits": hits, "floor": floor_count(decided, p) if decided else 0, "p": p,
            "width_oracle": float(np.median(widths)) / float(q[1] - q[0])
            if widths else math.nan,
            "median_offset": float(np.median(offsets)) if offsets else math.nan}


def lower_ends(shape: str, noise: float, faces: int, runs: int) -> dict[str, tuple[int, float]]:
    """(covered, width/oracle) of the decided half range with its lower end as it is
    (models.uncertainty.conformity.LOWER_THRESHOLD, 3 standard deviations) and with the
    least favourable curve's gaps shrunk by 2 and 1 standard deviations, or not at all (the
    lower end on the measured curve, a plain parametric bootstrap); the upper end and the
    value as they are."""
    from models.uncertainty import conformity

    meta = CertificateMetadata.from_dict(METADATA)
    the_rig = rig(shape, noise, faces)
    ways: dict[str, list[tuple[float, float, float, float]]] = {
        "now": [], "2 sd": [], "1 sd": [], "measured curve": []}
    for run in range(runs):
        lines, truth = the_rig.run(np.random.default_rng(4242 + 31 * run))
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, [r.split(",") for r in lines[1:]])
                                 .parse(), SETTINGS)
        budget = polygon_budget(result, meta, SETTINGS)
        e = result.mean_corrected_arcsec
        true_half = 0.5 * float(np.ptp(truth))
        mc = half_range_monte_carlo(e, budget)
        high = mc.value + mc.u_upper
        ways["now"].append((mc.value, max(0.0, mc.value - mc.u_lower), high, true_half))
        draws = np.sum(conformity._draws_by_nature(
            budget, np.arange(e.size), mc.trials, np.random.default_rng(mc.seed),
            evaluated=np.zeros((mc.trials, e.size))), axis=0)
        for name, threshold in (("2 sd", 2.0), ("1 sd", 1.0), ("measured curve", 0.0)):
            excess = conformity._range_excess(draws, conformity._gaps(e, draws, threshold),
                                              conformity._gaps(-e, -draws, threshold))
            q = float(np.quantile(excess, 1.0 - 0.5 * (1.0 - budget.probability)))
            low = min(max(0.0, mc.measured - 0.5 * q), mc.value)
            ways[name].append((mc.value, low, high, true_half))
    out = {}
    for name, rows in ways.items():
        a = np.array(rows)
        q = np.quantile(a[:, 0] - a[:, 3], [0.02275, 0.97725])
        out[name] = (int(np.sum((a[:, 1] <= a[:, 3]) & (a[:, 3] <= a[:, 2]))),
                     float(np.median(a[:, 2] - a[:, 1])) / float(q[1] - q[0]))
    return out


def main(runs: int = 200, shapes: list[str] | None = None) -> None:
    out = sys.stdout
    out.write("| cell | covered (floor) | value − truth (median) | width/oracle |\n"
              "|---|---|---|---|\n")
    for shape in shapes or SHAPES:
        for noise in NOISES:
            for faces in FACES:
                c = cell(shape, noise, faces, runs)
                out.write(f"| {c['cell']} | {c['hits']}/{c['decided']} (≥{c['floor']}) | "
                          f"{c['median_offset']:+.3f}″ | {c['width_oracle']:.2f} |\n")
                out.flush()


if __name__ == "__main__":
    if sys.argv[2:3] == ["lower"]:
        for spec in sys.argv[3:]:
            shape, noise, faces = spec.split(":")
            ends = lower_ends(shape, float(noise), int(faces), int(sys.argv[1]))
            sys.stdout.write(spec + " " + "; ".join(
                f"{k} {c}/{sys.argv[1]} at {w:.2f}" for k, (c, w) in ends.items()) + "\n")
            sys.stdout.flush()
    else:
        main(int(sys.argv[1]) if len(sys.argv) > 1 else 200, sys.argv[2:] or None)
