"""The polygon's repeated readings counted once (issue 39).

With n readings at each face averaged and the test repeated in sets, the reading noise is
the sets' scatter about their direction's mean: the scatter of the MEANS, Var = σ_b² +
σ_w²/n, which already holds the means' own s/√n. Before, the s/√n entered again (at each
face and at the zero face), so the noise of the mean was counted twice.

The readings come from the exact 3-D rig (models/validation/polygon_rig.py, nothing from the
code it checks) read without noise, each stop then read n times here with fresh normal noise
σ on the autocollimator's horizontal and vertical readings (the same stop, as a technician
reads a face n times without turning the shaft).
"""

from __future__ import annotations

import math

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.polygon.report import polygon_budget
from models.readings.sheet import ReadingsSheet
from models.validation.polygon_rig import PolygonRig

FACES, SETS, N, SIGMA = 24, 3, 3, 0.1
THETA = np.arange(FACES) * 360.0 / FACES
TRUTH = 1.5 * np.sin(np.radians(THETA) + 0.3) + 0.4 * np.sin(2 * np.radians(THETA))
SETTINGS = {"grade": 5, "ac_roll_arcmin": 0.0, "readings_per_point": N}


def _rows(rng: np.random.Generator) -> tuple[list[list[str]], np.ndarray]:
    rig = PolygonRig(FACES, TRUTH, psi_arcsec=60.0, omega_deg=70.0, rng=rng)
    rows = []
    for k in range(SETS):
        for row in rig.set_rows(k + 1):
            for _ in range(N):  # columns: position, encoder, dev, ac_x, ac_y, set, direction
                x, y = float(row[3]), float(row[4])
                rows.append(row[:3] + [repr(x + rng.normal(0.0, SIGMA)),
                                       repr(y + rng.normal(0.0, SIGMA))] + row[5:])
    return rows, rig.truth_arcsec()


def test_repeated_readings_in_sets_are_counted_once():
    rng = np.random.default_rng(39)
    deviations, big_u, names = [], [], set()
    for _ in range(200):
        rows, truth = _rows(rng)
        result = POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), SETTINGS)
        budget = polygon_budget(result, CertificateMetadata())
        deviations.append(result.mean_corrected_arcsec - truth)
        big_u.append(budget.expanded)
        names |= {c.name for c in budget.components}
    assert not any(name.startswith("Repeated readings") for name in names), names
    deviations, big_u = np.array(deviations), np.array(big_u)
    scatter = np.std(deviations, axis=0, ddof=1)[1:]  # face 1 is the zero
    # the simulation's own check: the mean of 3 sets of means of 3, and set 1's zero mean
    expected = SIGMA / math.sqrt(N) * math.sqrt(1.0 / SETS + 1.0)
    assert abs(np.median(scatter) / expected - 1.0) < 0.1
    ratio = np.mean(big_u, axis=0)[1:] / (2.0 * scatter)
    # 1.0–1.15 expected (k from ν_eff and the spread of s), to 1.25 with the zero drift
    # that the closures, within their noise, could carry from set to set; 1.4 with s/√n
    # counted again
    assert 0.9 <= float(np.median(ratio)) <= 1.25, ratio
    assert np.all((ratio > 0.8) & (ratio < 1.4)), ratio
