"""The bound of one end of a target's band, μ + kσ, from its own readings
(models.uncertainty.figure_intervals._band_edge_bound: the one-sided tolerance bound by the
noncentral t), which A's, A↑'s, A↓'s and P's intervals are made of (#39)."""

from __future__ import annotations

import numpy as np

from models.uncertainty.figure_intervals import _band_edge_bound


def test_a_bands_end_bound_is_the_one_sided_tolerance_bound():
    """μ + k σ ≤ x̄ + K s: K is the one-sided tolerance factor of ISO 16269-6 (its tables of k,
    and NIST/SEMATECH 7.2.6.3) for a proportion p = Φ(k) at confidence 1 − tail: 95 % of
    the population at 95 % confidence from n = 3, 5 and 10 readings, K = 7.656, 4.203 and
    2.911. Readings x̄ = 10.000″, s = 0.500″: the bound of μ + 1.645σ is 13.828″, 12.101″,
    11.456″; the lower bound of μ − 1.645σ the same distance below."""
    k95 = 1.6448536269514722  # Φ⁻¹(0.95)
    n = np.array([3.0, 5.0, 10.0])
    x, s = np.full(3, 10.0), np.full(3, 0.5)
    upper = _band_edge_bound(x, s, n, k95, 0.05, upper=True)
    np.testing.assert_allclose(upper, 10.0 + 0.5 * np.array([7.656, 4.203, 2.911]), atol=1e-3)
    lower = _band_edge_bound(x, s, n, -k95, 0.05, upper=False)
    np.testing.assert_allclose(lower, 20.0 - upper, atol=1e-12)


def test_a_bands_end_bound_holds_at_its_confidence_for_readings_drawn():
    """Drawn readings (normal, μ = 3″, σ = 0.8″; 3 and 5 readings, 40 000 samples each):
    x̄ + K s ≥ μ + 2σ in 1 − tail of the samples at tail = 1.14 % (half of 95.45 %'s tail),
    and its lower bound ≤ μ + 2σ at the same; μ − 2σ's bounds likewise (within 4 binomial
    standard deviations)."""
    rng = np.random.default_rng(11)
    tail, mu, sigma = 0.011375, 3.0, 0.8
    for runs in (3, 5):
        readings = mu + sigma * rng.standard_normal((40_000, runs))
        x, s = readings.mean(axis=1), readings.std(axis=1, ddof=1)
        n = float(runs)
        sd = 4.0 * np.sqrt(tail * (1.0 - tail) / x.size)
        for reach in (2.0, -2.0):
            edge = mu + reach * sigma
            missed_above = np.mean(_band_edge_bound(x, s, n, reach, tail, True) < edge)
            missed_below = np.mean(_band_edge_bound(x, s, n, reach, tail, False) > edge)
            assert abs(missed_above - tail) < sd, (runs, reach, missed_above)
            assert abs(missed_below - tail) < sd, (runs, reach, missed_below)
