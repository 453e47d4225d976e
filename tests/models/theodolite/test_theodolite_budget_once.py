"""The theodolite's reading error counted once, with its nature (issue 39).

The rig simulates the set-up from first principles (tests/theodolite_passes_simulator.py,
numpy only, nothing from the code it checks): the frame of ../shared/SPEC.md §1 (OZ plumb
down, OX the azimuth zero), the axis tilted by ψ towards α, the mirror normal at the axis' zero [cos β, 0,
−sin β], turned right-handed about the axis by its TRUE rotation θ − d(θ) (Rodrigues); the
theodolite reads atan2(y, x) and asin z, each with normal noise σ. The laboratory states
the theodolite at u = σ per reading — the same error as the noise, as a consistent
statement does. Each point's corrected error is then the difference of two noisy azimuth
readings (the point's and θ₀'s) less the identified set-up model: its scatter is about
√2·σ, and its U must be about twice that — not the √2·σ of the standard on top of two
readings' s (2σ, the noise counted twice).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.readings.sheet import ParsedReadings
from models.theodolite.analysis import THEODOLITE
from models.theodolite.model import analyze_run
from models.theodolite.report import (
    READING_INPUT,
    REFERENCE_READING_INPUT,
    theodolite_budget,
)
from models.uncertainty.conformity import _draws_by_nature
from tests.theodolite_passes_simulator import mirror_readings

SIGMA = 0.5  # arcsec, the reading noise in azimuth and elevation
THETA = np.arange(-20.0, 20.1, 2.0)  # 21 points
ZERO = int(np.argmin(np.abs(THETA)))
PSI, ALPHA, BETA = 2.0, 40.0, 3.0  # deg


def _readings(true_rotation_deg: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Azimuth and elevation (deg) of the mirror normal, noise-free (this file's set-up)."""
    return mirror_readings(true_rotation_deg, PSI, ALPHA, BETA)


def _axis_error() -> np.ndarray:
    """The axis' own error (indicated − true, arcsec): 1″ and 0.5″ harmonics, 0 at θ₀."""
    t = np.radians(THETA)
    d = np.sin(4.0 * t + 0.3) + 0.5 * np.cos(9.0 * t)
    return d - d[ZERO]


META = CertificateMetadata(standards=(ReferenceStandard(
    "Autocollimating theodolite", certificate_no="NIM-1", uncertainty=SIGMA, basis="u"),))


def _runs(count: int, seed: int):
    rng = np.random.default_rng(seed)
    truth = _axis_error()
    clean_az, clean_el = _readings(THETA - truth / 3600.0)
    for _ in range(count):
        az = clean_az + rng.normal(0.0, SIGMA, THETA.size) / 3600.0
        el = clean_el + rng.normal(0.0, SIGMA, THETA.size) / 3600.0
        result = analyze_run(THETA, az, el, reference_index=ZERO)
        yield truth, result, theodolite_budget(result, META)


def test_per_point_u_is_twice_the_actual_scatter_with_the_standard_stated_at_sigma():
    """(a) Over 240 runs, U at each point / (2 × the scatter of the corrected error about
    the truth at that point) is about 1 (it was about 1.5 with the noise counted twice)."""
    errors, big_u = [], []
    for truth, result, budget in _runs(240, 39):
        errors.append(result.corrected_error_arcsec - truth)
        big_u.append(budget.expanded)
    errors, big_u = np.array(errors), np.array(big_u)
    others = np.arange(THETA.size) != ZERO
    scatter = np.std(errors, axis=0, ddof=1)
    # the simulation's own check: two readings' noise at a point, none at θ₀
    assert np.median(scatter[others]) == pytest.approx(math.sqrt(2.0) * SIGMA, rel=0.1)
    assert scatter[ZERO] < 1e-6 and np.all(big_u[:, ZERO] == 0.0)
    ratio = np.mean(big_u, axis=0)[others] / (2.0 * scatter[others])
    assert 0.9 <= float(np.median(ratio)) <= 1.2, ratio
    # every point within the scatter of a standard deviation from 240 runs (±5 % each)
    assert np.all((ratio > 0.8) & (ratio < 1.35)), ratio


def test_half_range_draws_carry_two_readings_not_three_or_four():
    """(b) The half range's Monte Carlo draws the reading error once per point and once for
    θ₀ (one value per trial): per-point sd ≈ σ√2 at every point but θ₀ (not √3σ with the
    standard's √2 on top of one s, nor 2σ with it on top of two), 0 at θ₀."""
    _, result, budget = next(_runs(1, 7))
    draws = sum(_draws_by_nature(budget, np.arange(THETA.size), 40000,
                                 np.random.default_rng(3)))
    sd = np.std(draws, axis=0)
    others = np.arange(THETA.size) != ZERO
    assert sd[ZERO] == pytest.approx(0.0, abs=1e-9)
    # the set-up model's own share is small here: within 10 % of the two readings alone
    assert np.all(np.abs(sd[others] / (math.sqrt(2.0) * SIGMA) - 1.0) < 0.12), sd[others]
    assert np.max(sd[others]) < 0.9 * math.sqrt(3.0) * SIGMA
    # the draws agree with the budget's own u_c (the same inputs, the same nature)
    np.testing.assert_allclose(sd[others], budget.combined[others], rtol=0.06)


def test_one_reading_input_the_larger_of_scatter_and_standard_with_its_nature():
    _, result, _ = next(_runs(1, 11))
    dof = THETA.size - 3
    res = result.elevation_residuals_arcsec
    s = float(np.sqrt(np.sum(res**2) / dof))
    for stated, governs in ((3.0 * SIGMA, "standard"), (0.1 * SIGMA, "scatter")):
        meta = CertificateMetadata(standards=(ReferenceStandard(
            "Autocollimating theodolite", uncertainty=2.0 * stated, basis="U95"),))
        budget = theodolite_budget(result, meta)
        rows = {r["name"]: r for r in budget.table()}
        # the standard's own line is gone: its per-reading error is the reading error
        assert "Autocollimating theodolite" not in rows
        own, zero = rows[READING_INPUT], rows[REFERENCE_READING_INPUT]
        expected = max(s, stated)
        assert own["u"] == pytest.approx(expected) and zero["u"] == pytest.approx(expected)
        assert (own["evaluation"], own["dof"]) == (("B", math.inf) if governs == "standard"
                                                    else ("A", dof))
        assert f"the {governs} governs" in own["note"]
        comps = {c.name: c for c in budget.components}
        assert not comps[READING_INPUT].common and comps[REFERENCE_READING_INPUT].common
        # √2·u_read at a point (with the model's share), 0 at θ₀
        i = (ZERO + 3) % THETA.size
        model = result.model_uncertainty_arcsec
        model_i = float(np.broadcast_to(model, THETA.shape)[i])
        assert budget.combined[i] == pytest.approx(math.sqrt(2.0 * expected**2 + model_i**2))
        assert budget.combined[ZERO] == pytest.approx(float(np.broadcast_to(model, THETA.shape)
                                                            [ZERO]), abs=1e-12)


# -- n readings a point (#39): the mean's noise counted once --------------------------------
#
# Each point is read n times in a row. Two errors per reading, as the budget's note argues:
# the pointing noise (σ, new in every reading, averaging over n) and the instrument's own
# error at that circle position: one value per point and run, the SAME in each of its n
# readings, drawn with standard deviation u_sys. The laboratory states the theodolite at one
# reading's whole error, u = √(u_sys² + σ²) per reading (0.8.6; before, at u_sys alone, and
# the budget took u_std whole as the circle's: with the theodolite stated at its pointing
# noise, u = σ and nothing fixed at a circle position, U came out twice what the mean's
# error needs); with u_sys = 0 it states none, or (``stated_noise``) σ. Either both circles carry it
# (the vertical readings then show it to the fit) or the horizontal circle alone (the
# elevations barely move over a run: the vertical circle's error is one offset, which the
# fit takes up). The readings go through the workbench as a sheet gives them (n rows a point).


def _repeat_runs(count: int, n: int, u_sys: float, seed: int, circles: str = "both",
                 stated_noise: bool = False):
    rng = np.random.default_rng(seed)
    truth = _axis_error()
    clean_az, clean_el = _readings(THETA - truth / 3600.0)
    m = THETA.size
    stated = math.hypot(u_sys, SIGMA) if u_sys or stated_noise else 0.0
    meta = CertificateMetadata(standards=(ReferenceStandard(
        "Autocollimating theodolite", uncertainty=stated, basis="u"),)) if stated else \
        CertificateMetadata()
    settings = THEODOLITE.settings_with_defaults({"readings_per_point": n,
                                                  "reference_row": ZERO * n + 1})
    for _ in range(count):
        circle_az, circle_el = rng.normal(0.0, 1.0, (2, m)) * u_sys
        if circles == "horizontal":
            circle_el = np.zeros(m)
        az = (clean_az + circle_az / 3600.0)[:, None] + rng.normal(0.0, SIGMA, (m, n)) / 3600.0
        el = (clean_el + circle_el / 3600.0)[:, None] + rng.normal(0.0, SIGMA, (m, n)) / 3600.0
        sheet = ParsedReadings({"theta_deg": np.repeat(THETA, n), "azimuth_deg": az.ravel(),
                                "elevation_deg": el.ravel(), "run": np.full(m * n, np.nan),
                                "direction": np.full(m * n, "", dtype=object)},
                               np.arange(m * n))
        result = THEODOLITE.analyze(sheet, settings)
        yield truth, (az, el), result, theodolite_budget(result, meta)


@pytest.mark.slow
@pytest.mark.parametrize("n, u_sys, circles, stated_noise", [
    (1, 0.0, "both", False), (1, 0.5 * SIGMA, "both", False), (1, SIGMA, "both", False),
    (4, 0.0, "both", False), (4, 0.5 * SIGMA, "both", False), (4, SIGMA, "both", False),
    (4, 0.5 * SIGMA, "horizontal", False), (4, SIGMA, "horizontal", False),
    (4, 0.0, "both", True)])
def test_u_is_twice_the_actual_scatter_with_n_readings_and_a_standard_that_does_not_average(
        n, u_sys, circles, stated_noise):
    """Over 200 runs (400 with 4 readings), U at each point / (2 × the scatter of the
    corrected error about the truth there) is within 0.9–1.2 (the median over the points),
    for 1 and 4 readings a point and the standard at 0, 0.5σ and σ. With 4 readings and no
    standard it was 1.6 (1.53 in the author's study): the means' noise in the fit's scatter,
    and s/√n again as its own input. (With 4 readings and no standard the rule's own ratio is
    about 1.11: the larger of two estimates of one σ/√n, and k for the fit's ν = 18; the
    scatter of 200 runs moves it by ±0.04, hence 400.)"""
    errors, big_u = [], []
    runs = 200 if n == 1 else 400
    seed = 390 + 10 * n + int(4 * u_sys) + (5 if circles == "horizontal" else 0) + \
        (7 if stated_noise else 0)
    for truth, _, result, budget in _repeat_runs(runs, n, u_sys, seed, circles, stated_noise):
        errors.append(result.corrected_error_arcsec - truth)
        big_u.append(budget.expanded)
    errors, big_u = np.array(errors), np.array(big_u)
    others = np.arange(THETA.size) != ZERO
    scatter = np.std(errors, axis=0, ddof=1)[others]
    # the simulation's own check: two means' errors, √2 · √(u_sys² + σ²/n)
    expected = math.sqrt(2.0 * (u_sys**2 + SIGMA**2 / n))
    assert float(np.median(scatter)) == pytest.approx(expected, rel=0.1)
    ratio = np.mean(big_u[:, others], axis=0) / (2.0 * scatter)
    assert 0.9 <= float(np.median(ratio)) <= 1.2, ratio
    assert np.all((ratio > 0.8) & (ratio < 1.35)), ratio
    coverage = np.mean(np.abs(errors[:, others]) <= big_u[:, others])
    assert 0.93 <= coverage <= 0.985, coverage


def test_with_n_readings_one_input_the_scatter_or_the_standard_with_the_repeats():
    """The reading error of a point's mean is ONE input: max(s_fit, √(u_c² +
    (s_repeat/√n)²)), s_repeat/√n pooled over the points' azimuth repeats (ν = points ·
    (n − 1)) and u_c = √max(u_std² − s_repeat², 0) the part of the stated u per reading
    that the repeats do not show to scatter (the circle's error, not divided by √n); no
    'Repeated readings' input beside it; its ν that of the figure that governs
    (Welch–Satterthwaite for the root sum of squares, u_c's ν = ∞)."""
    n = 4
    _, (az, _), result, _ = next(_repeat_runs(1, n, 0.0, 5))
    m = THETA.size
    dof_fit, dof_rep = m - 3, m * (n - 1)
    s_fit = float(np.sqrt(np.sum(result.elevation_residuals_arcsec**2) / dof_fit))
    # the pooled s/√n of the azimuth repeats, from the simulated readings themselves
    s_rep = math.sqrt(np.mean(np.var(az * 3600.0, axis=1, ddof=1)) / n)
    assert s_rep == pytest.approx(SIGMA / math.sqrt(n), rel=0.2)  # 63 degrees of freedom
    assert s_fit == pytest.approx(SIGMA / math.sqrt(n), rel=0.35)  # 18 degrees of freedom
    repeats = max(s_fit, s_rep), "A", dof_rep if s_rep > s_fit else dof_fit, (
        "repeated readings govern" if s_rep > s_fit else "scatter governs")
    # a standard the repeats' scatter shows whole (u_std ≤ s_repeat): it averages, as they do
    small = 0.2 * s_rep * math.sqrt(n)
    # one well above it: the rest of it is the circle's, √(u² − s_repeat²), with s/√n on top
    large = 3.0 * SIGMA
    circle = math.sqrt(large**2 - n * s_rep**2)
    both = math.hypot(circle, s_rep)
    for stated, u, evaluation, dof, governs in (
            (None, *repeats), (small, *repeats),
            (large, both, "B", math.floor(both**4 / (s_rep**4 / dof_rep)),
             "standard with the repeated readings governs")):
        meta = CertificateMetadata() if stated is None else CertificateMetadata(standards=(
            ReferenceStandard("Autocollimating theodolite", uncertainty=stated, basis="u"),))
        budget = theodolite_budget(result, meta)
        rows = {r["name"]: r for r in budget.table()}
        assert not any(name.startswith("Repeated readings") for name in rows), rows
        own, zero = rows[READING_INPUT], rows[REFERENCE_READING_INPUT]
        assert own["u"] == pytest.approx(u, rel=1e-9) and zero["u"] == pytest.approx(u)
        assert (own["evaluation"], own["dof"]) == (evaluation, dof)
        assert f"the {governs}" in own["note"] and "4 readings" in own["note"], own["note"]
        i = (ZERO + 3) % m
        model_i = float(np.broadcast_to(result.model_uncertainty_arcsec, THETA.shape)[i])
        assert budget.combined[i] == pytest.approx(math.sqrt(2.0 * u**2 + model_i**2))
