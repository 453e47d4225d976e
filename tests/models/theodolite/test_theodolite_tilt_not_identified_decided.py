"""The decided half range where the elevations do not identify the axis tilt (audit 72, finding 1).

A tilt not identified is ONE unknown error for the whole run, of a known shape family (its
effect at every θ for any direction and magnitude up to the bound), not scatter. Drawn as
noise, it was taken off the measured range: "0.00″, the measured 1.88″ less 1.88″", interval
0.00 … 0.00″, "pass" with T = 1″ where the truth was 1.98″. The rig
(tests/theodolite_tilt_rig.py: numpy only, OZ up, its own rotations) makes the runs; the truth
is half the peak-to-peak of the axis' own error against the reference reading.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.stats import binom

from models.certificate.metadata import CertificateMetadata, ReferenceStandard
from models.certificate.uncertainty_json import decided_quantity_json
from models.theodolite.model import analyze_run
from models.theodolite.report import theodolite_certificate
from tests.theodolite_tilt_rig import axis_error_curve, run, theta_grid


def _meta(tolerance: float, sigma: float) -> CertificateMetadata:
    return CertificateMetadata(tolerance=tolerance, decision_rule="simple", standards=(
        ReferenceStandard("Autocollimating theodolite", certificate_no="C-7", uncertainty=sigma,
                          basis="u"),))


def _floor(n: int, p: float) -> int:
    """The least covered count not significantly low (one-sided binomial, 5 %)."""
    k = 0
    while binom.cdf(k, n, p) < 0.05:
        k += 1
    return k


def test_the_default_bound_with_a_30_arcsec_tilt_no_longer_passes_a_failing_item():
    """The audit's second reproducer, in this rig: elevations copied, the default bound (300″),
    a true tilt of 30″, T = 1″ below the true half range (about 2″)."""
    rng = np.random.default_rng(7201)
    theta = theta_grid(24, rng)
    error = axis_error_curve(theta, "smooth", 2.0, rng)
    theta, az, el, truth = run(theta, error, 30.0, 140.0, 6.8, 0.3, rng)
    true = 0.5 * float(np.ptp(truth))
    result = analyze_run(theta, az, el, accuracy_arcsec=0.3)
    assert not result.identification.tilt_identified
    c = theodolite_certificate(result, _meta(1.0, 0.3)).conformity
    mc = c.monte_carlo
    measured = 0.5 * float(np.ptp(result.corrected_error_arcsec))
    assert mc.measured == pytest.approx(measured)
    # nothing taken off the measured range for the tilt: only the reading noise's excess
    assert mc.value > 0.8 * measured > 1.0
    assert mc.value - mc.u_lower <= true <= mc.value + mc.u_upper
    assert c.verdict != "pass"
    decided = decided_quantity_json(c, 1.0)  # the JSON's, from the certificate's decision
    assert decided is not None
    assert decided["value"] > 0.8 * measured and decided["verdict"] != "pass"
    assert decided["interval_low"] <= true <= decided["interval_high"]
    assert "not noise" in str(c.quantity)


@pytest.mark.parametrize("share", [0.0, 0.5, 1.0])
def test_the_decided_interval_holds_the_truth_for_any_tilt_up_to_the_bound(share):
    """Tilt 0, half the bound, the bound, in random directions; smooth and rough curves;
    noise 0.1–2 × the signal; 12 and 40 points: covered at least the binomial floor of the
    printed probability, no value printed near 0 while the measured range is well above
    the noise, no false pass (T below every truth)."""
    rng = np.random.default_rng(7300 + int(10 * share))
    bound, signal, tolerance = 40.0, 1.5, 1.2
    runs, covered, probability = 36, 0, 0.0
    for i in range(runs):
        points = 12 if i % 2 else 40
        sigma = signal * (0.1, 0.5, 2.0)[i % 3]
        theta = theta_grid(points, rng)
        error = axis_error_curve(theta, "smooth" if i % 4 < 2 else "rough", signal, rng)
        gamma = (1.0 if i % 5 < 3 else -1.0) * rng.uniform(2.0, 8.0)
        theta, az, el, truth = run(theta, error, share * bound, rng.uniform(0.0, 360.0), gamma,
                                   sigma, rng, "copied" if i % 3 else "tenth")
        result = analyze_run(theta, az, el, accuracy_arcsec=sigma, tilt_bound_arcsec=bound)
        assert not result.identification.tilt_identified
        c = theodolite_certificate(result, _meta(tolerance, sigma)).conformity
        mc = c.monte_carlo
        true = 0.5 * float(np.ptp(truth))
        covered += int(mc.value - mc.u_lower <= true <= mc.value + mc.u_upper)
        probability = mc.probability
        assert c.verdict != "pass", (i, mc)
        if mc.measured > 3.0 * sigma:  # a range well above the noise keeps a value
            assert mc.value > 0.5 * mc.measured, (i, mc)
    assert covered >= _floor(runs, probability), covered


def _rig_tilt_effect(theta, tilt, direction, gamma):
    """The tilt's effect on the corrected error at each θ (″), from the rig: the readings with
    the tilt less those without, no axis error and no noise."""
    rng = np.random.default_rng(0)
    _, az_tilted, _, _ = run(theta, lambda t: 0.0 * t, tilt, direction, gamma, 0.0, rng)
    _, az_plumb, _, _ = run(theta, lambda t: 0.0 * t, 0.0, 0.0, gamma, 0.0, rng)
    ref = int(np.argmin(np.abs(theta)))
    d = (az_tilted - az_tilted[ref]) - (az_plumb - az_plumb[ref])
    return d * 3600.0


@pytest.mark.parametrize("gamma", [-6.0, 0.5, 4.0])
def test_the_tilts_largest_change_to_the_half_range_is_the_rigs(gamma):
    """The widening is the largest half peak-to-peak of the tilt's effect over directions
    and magnitudes up to the bound: never below the rig's at any of them, and not far above
    its largest (only by the β ± 2 × bound the copied elevations leave)."""
    from models.theodolite.model import tilt_half_range_change

    theta = np.array([-35.0, -20.0, -7.0, 3.0, 11.0, 26.0, 38.0, 50.0])
    bound = 120.0
    change = tilt_half_range_change(theta - 3.0, gamma, bound)
    largest = 0.0
    for tilt in (0.25 * bound, 0.5 * bound, bound):
        for direction in np.arange(0.0, 360.0, 5.0):
            h = 0.5 * float(np.ptp(_rig_tilt_effect(theta, tilt, direction, gamma)))
            assert h <= change * (1 + 1e-6) + 1e-9
            largest = max(largest, h)
    beta_margin = 2.0 * bound / 3600.0
    slack = math.tan(math.radians(abs(gamma) + beta_margin)) / math.tan(math.radians(abs(gamma)))
    assert change <= largest * slack * 1.01 + 0.05


def test_decided_on_the_means_over_passes_the_tilt_is_not_taken_off_either():
    """Three passes each way (the half range decided on the means at each θ and direction):
    the tilt's bound is not drawn as the set-up model's noise and taken off the means' range;
    the interval holds the truth."""
    from models.theodolite.pass_means import decided_on_means

    sigma, covered, runs = 0.1, 0, 6
    for i in range(runs):
        rng = np.random.default_rng(7400 + i)
        th = np.round(theta_grid(11, rng), 2)
        error = axis_error_curve(th, "smooth" if i % 2 else "rough", 1.5, rng)
        passes = 3
        theta = np.concatenate([th] * (2 * passes))
        directions = np.concatenate([np.full(th.size, d) for _ in range(passes)
                                     for d in (1.0, -1.0)])
        theta, az, el, truth = run(theta, error, 60.0 * (i % 3) / 2.0, rng.uniform(0.0, 360.0),
                                   (5.0, -3.0)[i % 2], sigma, rng)
        result = analyze_run(theta, az, el, accuracy_arcsec=sigma, tilt_bound_arcsec=60.0,
                             directions=directions)
        result.directions = directions  # as the workbench's analysis keeps them
        assert not result.identification.tilt_identified and decided_on_means(result)
        conformity = theodolite_certificate(result, _meta(1.0, sigma)).conformity
        mc = conformity.monte_carlo
        assert mc is not None and "not noise" in str(conformity.quantity)
        # the means' noise is 0.1″/√3: nothing near the tilt's effect is taken off the range
        assert mc.value > mc.measured - 0.15, (i, mc)
        true = 0.5 * float(np.ptp(truth))
        covered += int(mc.value - mc.u_lower <= true <= mc.value + mc.u_upper)
    assert covered == runs
