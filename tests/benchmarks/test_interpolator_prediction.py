"""Interpolator look-up tables (#45): the residual predicted after quantisation against the
residual the quantised table leaves on the true head, over random heads recorded with noise.

Each head (first principles, tests/fringe_signal_simulator.py): amplitudes, ratio 0.85–1.15,
quadrature ±8°, offsets ±3 %, 2nd, 3rd and 5th harmonics up to 2 %, 0.5–2 mV noise on
0.5 V; 64 periods of 64 samples, fitted by the workbench. The prediction is made on the
fit; the table's codes are then applied by an independent chip model to the head's true
signals. The gap is set against the fit's own noise: σ·√(2/n)/A rad a coefficient, ten
coefficients (orders 1–5 of two channels), the largest over a period about three RSS.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np

from models.fringe.analysis import FRINGE
from models.fringe.interpolator_table import IC_TW8, chip_profile, design_table
from models.readings.sheet import ParsedReadings
from tests.fringe_signal_simulator import Head, chip_phase, equal_phase, ideal_terms

CASES, PER, PERIODS = 100, 64, 64


def _actual(head, table, points=50_021):
    theta = np.arange(points) * (2 * math.pi / points)
    clean = Head(head.peak_a, head.peak_b, head.quadrature_deg, head.offset_a, head.offset_b,
                 head.harmonics)
    u_a, u_b = ideal_terms(head, *clean.signals(theta), table.terms.applied)
    p = table.profile
    e = np.angle(np.exp(1j * (chip_phase(u_a, u_b, table.codes, table.lsb_period,
                                         p.interpolation, p.sign) - theta)))
    e -= np.mean(e)
    return float(np.max(np.abs(e))) / (2 * math.pi)


def test_predicted_residual_against_the_true_head(report):
    rng = np.random.default_rng(45)
    profiles = {"generic 256×10 linear": dataclasses.replace(chip_profile("generic", 256, 10),
                                                             interpolation="linear"),
                "ic-tw8": IC_TW8}
    gaps = {k: [] for k in profiles}
    within = {k: 0 for k in profiles}
    theta = equal_phase(PERIODS, PER)
    for _ in range(CASES):
        noise = rng.uniform(5e-4, 2e-3)
        head = Head(peak_a=0.5, peak_b=0.5 * rng.uniform(0.85, 1.15),
                    quadrature_deg=rng.uniform(-8, 8), offset_a=rng.uniform(-0.015, 0.015),
                    offset_b=rng.uniform(-0.015, 0.015),
                    harmonics={k: (rng.uniform(0, 0.02), rng.uniform(-math.pi, math.pi))
                               for k in (2, 3, 5)}, noise=noise)
        u_a, u_b = head.signals(theta, rng)
        parsed = ParsedReadings({"u_sin": u_a, "u_cos": u_b,
                                 "theta_deg": np.full(theta.size, np.nan)},
                                np.arange(theta.size))
        result = FRINGE.analyze(parsed, {"samples_per_period": PER, "max_order": 5,
                                         "harmonics": "all"})
        bound = 3 * math.sqrt(10) * noise * math.sqrt(2 / theta.size) / 0.5 / (2 * math.pi)
        for key, profile in profiles.items():
            table = design_table(result, profile)
            gap = abs(_actual(head, table) - table.residual.max_abs)
            gaps[key].append(gap / bound)
            within[key] += gap <= bound
    lines = ["| profile | gap / fit-noise bound: median | p95 | max | within the bound |",
             "|---|---|---|---|---|"]
    for key in profiles:
        g = np.array(gaps[key])
        lines.append(f"| {key} | {np.median(g):.2f} | {np.percentile(g, 95):.2f} | "
                     f"{g.max():.2f} | {within[key]}/{CASES} |")
    report("interpolator_prediction", [
        "## Interpolator tables: predicted residual against the true head (#45)", "",
        f"{CASES} random heads (see the module's docstring); the gap |actual − predicted| of "
        "the largest residual, as a share of the fit's noise bound.", "", *lines])
    for key in profiles:
        assert within[key] >= 0.95 * CASES
