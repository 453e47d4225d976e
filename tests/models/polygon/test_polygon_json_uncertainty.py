"""The U the JSON gives each polygon error array covers the truth (issue 39): the mean over
the sets (the certificate's) and each set's own corrected error, the rig's polygon drawn
about its certificate and its readings noisy (models/validation/polygon_rig.py imports
nothing from the code it checks)."""

from __future__ import annotations

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_json_budgets
from models.readings.sheet import ReadingsSheet
from models.validation.polygon_rig import PolygonRig

FACES = 24


def _coverage(directions: tuple[int, ...], trials: int, seed: int) -> dict[str, float]:
    rng = np.random.default_rng(seed)
    theta = np.radians(np.arange(FACES) * 360.0 / FACES)
    truth = 1.5 * np.sin(theta + 0.3) + 0.4 * np.sin(2 * theta)
    certificate_dev = np.random.default_rng(5).normal(0.0, 0.2, FACES)
    meta = CertificateMetadata(standards=(ReferenceStandard("polygon", uncertainty=0.20,
                                                            basis="U95"),))
    hits: dict[str, list[int]] = {"mean": [0, 0], "per_set": [0, 0]}
    for _ in range(trials):
        true_dev = certificate_dev + rng.normal(0.0, 0.10, FACES)
        rig = PolygonRig(FACES, truth, psi_arcsec=60.0, omega_deg=70.0, face_dev_arcsec=true_dev,
                         certificate_error_arcsec=certificate_dev - true_dev, noise_arcsec=0.3,
                         rng=rng)
        rows = []
        for k, d in enumerate(directions):
            rows += rig.set_rows(k + 1, reverse=d < 0, start_face=1 if d > 0 else 7)
        # one set cannot evaluate its reading noise: the lab states it (the rig's)
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(),
                                 {"grade": 5, "ac_roll_arcmin": 0.0,
                                  **({"reading_noise_arcsec": 0.3} if len(directions) == 1
                                     else {})})
        budgets = polygon_json_budgets(result, meta)
        t = rig.truth_arcsec()
        per_set = np.concatenate([s.corrected_error_arcsec for s in result.sets])
        for name, errors, u in (
                ("mean", result.mean_corrected_arcsec,
                 budgets["mean_corrected_error_arcsec"].expanded),
                ("per_set", per_set, budgets["corrected_error_arcsec"].expanded)):
            inside = np.abs(errors - np.tile(t, errors.size // FACES)) <= u
            hits[name][0] += int(np.sum(inside[u > 0]))
            hits[name][1] += int(np.sum(u > 0))
    return {k: v[0] / v[1] for k, v in hits.items() if v[1]}


@pytest.mark.slow
@pytest.mark.parametrize("directions", [(1, -1, 1, -1), (1,)])
def test_per_point_u_of_the_json_covers_the_truth(directions):
    """20 runs × 23 faces (seconds on 2 cores): the coverage of 95.45 % is estimated to about
    ±2 % (the faces of one run share inputs, so more loosely): within 90 … 99.5 %. With 60
    runs it was 96.3 % (mean) and 96.9 % (each set) for four sets, 98.0 % for one."""
    coverage = _coverage(directions, 20, 11)
    for name, achieved in coverage.items():
        assert 0.90 <= achieved <= 0.995, (name, achieved)
