"""Study: a polygon encoder test of ONE set (issue 39), by the first-principles rig
tests/polygon_one_set_rig.py, through the workbench's analysis and its certificate's decision.

Per cell (faces, the σ of a reading stated or not), ``runs`` runs, each a new artefact (face
errors, faces' own pyramidal errors) and new noise:

* decided: how often the decided half range's printed interval holds its truth (half the
  true curve's peak-to-peak), and its mean width against the oracle's (the 2.275–97.725 %
  spread of measured half range − truth over the runs);
* per point: how often |error − truth| ≤ U (faces 2…n; face 1 is the zero), and the mean U
  against 2 × the errors' own scatter about the truth (rms over the runs);
* withheld: the runs where the certificate gave no U (UncertaintyWithheld).

Run: ``nice -n 10 python -m tests.benchmarks.one_set_polygon_study [runs]`` from the
worktree (about a second a run).
"""

from __future__ import annotations

import math
import sys

import numpy as np

from models.certificate.metadata import CertificateMetadata, MetadataError
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget
from models.readings.sheet import ReadingsSheet
from tests.polygon_one_set_rig import OneSetBench


def cell(faces: int, stated: bool, runs: int, pyramidal_sd: float = 1.5, seed: int = 0
         ) -> dict[str, float]:
    rng = np.random.default_rng(seed + faces + (7 if stated else 0))
    meta = CertificateMetadata.from_dict({})
    hit = width = withheld = decided = 0
    covered, points, sizes, deviations, spread = 0, 0, [], [], []
    for run in range(runs):
        bench = OneSetBench(faces=faces, face_pyramidal_sd_arcsec=pyramidal_sd, seed=run)
        settings = {"ac_roll_arcmin": 0.0, "grade": 5}
        if stated:
            settings["reading_noise_arcsec"] = math.hypot(bench.sigma_enc_arcsec,
                                                          bench.sigma_ac_arcsec)
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, bench.rows(rng)).parse(), settings)
        dev = result.mean_corrected_arcsec - bench.truth_arcsec()
        deviations.append(dev[1:])
        truth = bench.truth_half_range()
        spread.append(0.5 * float(np.ptp(result.mean_corrected_arcsec)) - truth)
        try:
            big_u = polygon_budget(result, meta, settings).expanded
            conformity = POLYGON.certificate_document(result, meta, "", settings).conformity
        except MetadataError:
            withheld += 1
            continue
        covered += int(np.sum(np.abs(dev[1:]) <= big_u[1:]))
        points += faces - 1
        sizes.append(big_u[1:])
        low, high = conformity.interval_low, conformity.interval_high
        if math.isfinite(low) and math.isfinite(high):
            decided += 1
            hit += int(low <= truth <= high)
            width += high - low
    scatter = np.sqrt(np.mean(np.square(deviations), axis=0))
    q = np.percentile(spread, [2.275, 97.725])
    return {"faces": faces, "stated": stated, "runs": runs, "withheld": withheld,
            "decided": decided, "decided_hits": hit,
            "decided_width_ratio": (width / decided) / float(q[1] - q[0]) if decided else math.nan,
            "point_coverage": covered / points if points else math.nan,
            "u_ratio": float(np.mean(np.mean(sizes, axis=0) / (2.0 * scatter)))
            if sizes else math.nan}


def main(runs: int = 64) -> None:
    out = sys.stdout
    out.write("| faces | σ stated | runs | withheld | decided covered | decided width/oracle | "
              "per point | U/oracle |\n|---|---|---|---|---|---|---|---|\n")
    for faces in (12, 24):
        for stated in (False, True):
            c = cell(faces, stated, runs)
            out.write(f"| {faces} | {'yes' if stated else 'no'} | {c['runs']} | {c['withheld']} | "
                      f"{c['decided_hits']}/{c['decided']} | {c['decided_width_ratio']:.2f} | "
                      f"{100 * c['point_coverage']:.1f} % | {c['u_ratio']:.2f} |\n")
            out.flush()


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 64)
