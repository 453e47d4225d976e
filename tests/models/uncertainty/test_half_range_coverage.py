"""Coverage of the decided quantity's interval (half the peak-to-peak, JCGM 101) over a
defined set of curve shapes: the certificate prints the coverage this study achieved
(models.uncertainty.conformity.HALF_RANGE_COVERAGE), and this test re-measures it (seeded).

Each shape is a true error curve of 36 points (41 for the real sample: the bundled
theodolite run's corrected error), with half range 3σ; a measurement adds normal noise σ
per point, the budget states σ; the interval [value − U₋, value + U₊] covers the truth or
not. The study behind the printed figures ran 300 measurements of each shape (seed
20261201, binomial standard error ≈ 1.7 %): smooth 88.3 %, rough 91.7 %, spike 90.0 %,
the real sample 89.3 %; it
falls short of the stated 95.45 %, and the certificate prints what it achieved. This test
runs 40 of each on its own seed and checks the printed figures within 3.5 standard errors.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import HALF_RANGE_COVERAGE, half_range_monte_carlo

POINTS = 36
TRIALS = 1000  # the interval's own Monte Carlo (the certificate's runs 10 000 on short curves)


def _real_sample() -> np.ndarray:
    """The bundled theodolite sample's corrected error (a real axis), as a true curve."""
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    kind = KINDS["theodolite"]
    table = read_table(f"resources/samples/{kind.sample_file}")
    parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
    result = kind.analyze(parsed, kind.settings_with_defaults({}))
    return np.asarray(result.corrected_error_arcsec, dtype=float)


def _shape(name: str) -> np.ndarray:
    th = np.arange(POINTS) * 2 * np.pi / POINTS
    if name == "smooth":  # eccentricity and ellipticity
        return np.sin(th) + 0.5 * np.sin(2 * th + 0.7)
    if name == "rough":  # ten harmonics, amplitude 1/k, fixed phases
        phases = np.random.default_rng(5).uniform(0, 2 * np.pi, 10)
        return sum(np.sin(k * th + phases[k - 1]) / k for k in range(1, 11))
    if name == "spike":  # one point off a flat curve
        out = np.zeros(POINTS)
        out[POINTS // 3] = 1.0
        return out
    return _real_sample()


SHAPES = ("smooth", "rough", "spike", "sample")


def coverage(name: str, repeats: int, seed: int, snr: float = 3.0) -> tuple[int, int]:
    """(hits, repeats): how often the interval covers the true half range."""
    shape = _shape(name)
    truth = snr * shape / (0.5 * np.ptp(shape))  # true half range = snr·σ, σ = 1
    half_range = 0.5 * float(np.ptp(truth))
    budget = UncertaintyBudget((BudgetComponent("noise", "A", "normal", 1.0, 1.0, 1.0,
                                                math.inf),), truth.size)
    rng = np.random.default_rng(seed)
    hits = 0
    for r in range(repeats):
        e = truth + rng.standard_normal(truth.size)
        mc = half_range_monte_carlo(e, budget, trials=TRIALS, seed=seed + r + 1)
        hits += mc.value - mc.u_lower <= half_range <= mc.value + mc.u_upper
    return hits, repeats


@pytest.mark.slow
@pytest.mark.parametrize("name", SHAPES)
def test_printed_coverage_is_what_the_interval_achieves(name):
    repeats = 40
    hits, n = coverage(name, repeats, seed=7)
    stated = HALF_RANGE_COVERAGE[name]
    se = math.sqrt(stated * (1 - stated) / n) if 0 < stated < 1 else 1 / n
    assert abs(hits / n - stated) <= 3.5 * se + 1 / n, (name, hits / n, stated)


def test_the_certificate_prints_the_coverage_achieved():
    from models.uncertainty.conformity import decide_conformity

    budget = UncertaintyBudget((BudgetComponent("noise", "A", "normal", 0.3, 1.0, 1.0, 30),), 36)
    errors = np.sin(np.arange(36) * np.pi / 18)
    c = decide_conformity(errors, budget, 3.0, "guarded", "half_range")
    assert ("coverage achieved in validation (true half range 3σ): 88 % on a smooth curve, 92 % "
            "on a rough one, 90 % on a single spike, 89 % on a real axis' curve, against the "
            "95.45 % stated") in str(c.quantity)
