"""gui80: two sets of a polygon captured from noise-free simulators (every reading repeated
exactly, as quantised displays do) gave the budget a reading noise of 9.76e-17″ — the
doubles' rounding of angles converted and differenced, taken as the readings' scatter — and
the window printed it ("reading noise (9.76e-17″ …)"). Readings that differ by no more than
the arithmetic show no scatter: nothing to tell the noise from, so no noise (None: the σ
stated, or the budget says it is not evaluated), never a noise of ~0."""

from __future__ import annotations

import math

import numpy as np
import pytest

from models.polygon.model import reversal_pair_noise


def _errors_through_degrees(angles_arcsec: np.ndarray, offset_deg: float) -> np.ndarray:
    """Errors made as the analysis makes them from angles read in degrees: the reading as a
    nominal angle plus its error, converted to degrees and back, less the nominal."""
    nominal = offset_deg + np.arange(angles_arcsec.size) * 15.0
    read_deg = nominal + angles_arcsec / 3600.0
    return (read_deg - nominal) * 3600.0


def test_a_reverse_set_that_repeats_the_forward_one_tells_no_noise():
    rng = np.random.default_rng(80)
    errors = np.round(rng.normal(0.0, 0.4, 24), 2)  # readings to 0.01″, noise-free
    forward = _errors_through_degrees(errors, 123.4)
    reverse = _errors_through_degrees(errors, 303.4) - 0.19  # a reversal, no noise
    d = forward - reverse
    assert np.ptp(d) > 0  # the arithmetic's differences are there …
    assert np.ptp(d) < 1e-9
    values, directions = np.array([forward, reverse]), np.array([1, -1])
    assert reversal_pair_noise(values, directions) is None  # … and tell no noise


@pytest.mark.parametrize("sigma", [1e-4, 0.003, 0.05])
def test_a_reading_noise_at_a_display_s_finest_step_is_still_told(sigma):
    rng = np.random.default_rng(81)
    errors = rng.normal(0.0, 0.4, 24)
    forward = errors + rng.normal(0.0, sigma, 24)
    reverse = errors - 0.19 + rng.normal(0.0, sigma, 24)
    found = reversal_pair_noise(np.array([forward, reverse]), np.array([1, -1]))
    assert found is not None
    noise, dof = found
    assert dof == 23
    assert noise == pytest.approx(sigma, rel=0.5)
    assert math.isfinite(noise)
