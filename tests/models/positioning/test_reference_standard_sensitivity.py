"""How a reference standard's stated U enters the positioning budget: a deviation is the
reading at the target less the datum reading set at the start, so a standard whose
certificate states U per reading (a theodolite, an autocollimator) takes √2, both readings'
errors; one whose U is stated for any angle measured from its own datum (a laser rotary
calibrator, an interferometer: applies_to "angle") takes 1. Tests simulated from first
principles (tests/reference_readings_simulator.py); the truth of each mean deviation is the
axis's own.

Measured (2000 tests of 12 targets × 2 directions, 5 runs, σ = 0.05″, u = 0.5″ stated as
U = 1″): per reading, U covered the truth at 84.6 % with c = 1 (up to 0.8.14), 95.6 % with
√2; per angle 95.4 %, its U unchanged.
"""

from __future__ import annotations

import dataclasses

import numpy as np

from models.certificate.metadata import CertificateMetadata
from models.positioning.analysis import POSITIONING
from models.positioning.report import figure_uncertainties, positioning_budget
from models.readings.sheet import ReadingsSheet
from models.uncertainty.budget import UncertaintyBudget
from tests.reference_readings_simulator import positioning_test

U_READING = 0.5  # the reference's standard uncertainty, ″ (its certificate: U = 1″, k = 2)
TESTS = 400  # per-test coverage spread ≈ 0.09: the mean's standard error ≈ 0.5 %


def _metadata(per: str) -> CertificateMetadata:
    return CertificateMetadata.from_dict({"standards": [{
        "description": "Reference", "uncertainty": 2 * U_READING, "uncertainty_unit": "arcsec",
        "basis": "U95", "applies_to": per}]})


def _coverage(per: str, seed: int) -> tuple[float, np.ndarray]:
    """(share of the mean deviations whose U covers the truth, the last test's U)."""
    rng = np.random.default_rng(seed)
    metadata = _metadata(per)
    hits = []
    for _ in range(TESTS):
        rows, truth = positioning_test(12, 5, 0.05, U_READING, per, rng)
        result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), {})
        budget = positioning_budget(result, metadata)
        means = np.concatenate([stats.mean for _, _, stats in result.directions_present()])
        hits.append(np.abs(means - np.tile(truth, 2)) <= budget.expanded)
    return float(np.mean(hits)), budget.expanded


def test_a_standard_stated_per_reading_takes_root_2_and_its_u_covers_95_percent():
    coverage, expanded = _coverage("reading", seed=7)
    assert abs(coverage - 0.9545) <= 0.03, coverage  # 0.846 with c = 1
    # U = 2 √(2 u² + s²/n): the datum reading's error and the target's
    assert np.allclose(expanded, 2 * np.sqrt(2 * U_READING**2), rtol=0.01), expanded


def test_the_figures_of_a_per_reading_standard_take_the_target_readings_part_alone():
    """The datum reading's error is one value for the run, common to every target: every
    figure (a range, a reversal) is a difference of targets and it drops out, so the
    figures' intervals are those of the target reading's error alone (u, c = 1), while each
    point's U holds both (c = √2). (150 simulated tests: E's and M's intervals covered the
    true E 150 times.)"""
    rows, _ = positioning_test(12, 5, 0.05, U_READING, "reading", np.random.default_rng(5))
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), {})
    budget = positioning_budget(result, _metadata("reading"))
    reference = next(c for c in budget.components if str(c.name) == "Reference")
    assert float(np.max(reference.sensitivity)) == np.sqrt(2.0)
    target_reading_only = UncertaintyBudget(
        tuple(dataclasses.replace(c, sensitivity=1.0, datum_reading=False) if c is reference
              else c for c in budget.components),
        budget.points, budget.probability, budget.unit, budget.floor)
    ours = figure_uncertainties(result, budget)
    alone = figure_uncertainties(result, target_reading_only)
    assert {k: (v.low, v.high) for k, v in ours.items()} == {
        k: (v.low, v.high) for k, v in alone.items()}


def test_a_standard_stated_per_angle_keeps_1_where_one_stated_per_reading_takes_root_2():
    coverage, expanded = _coverage("angle", seed=8)
    assert abs(coverage - 0.9545) <= 0.03, coverage
    assert np.allclose(expanded, 2 * U_READING, rtol=0.01), expanded  # c = 1: unchanged
    # on the same readings, a standard of the same U stated per reading gives √2 more
    rows, _ = positioning_test(12, 5, 0.05, U_READING, "angle", np.random.default_rng(9))
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), {})
    by_angle = positioning_budget(result, _metadata("angle"))
    by_reading = positioning_budget(result, _metadata("reading"))
    reference = [next(c for c in b.components if str(c.name) == "Reference")
                 for b in (by_angle, by_reading)]
    assert [float(np.max(c.sensitivity)) for c in reference] == [1.0, np.sqrt(2.0)]
    assert "per reading, the deviation a difference of two readings" in str(reference[1].note)
    assert "per angle between two readings" in str(reference[0].note)
    assert np.all(by_reading.expanded > 1.3 * by_angle.expanded)
