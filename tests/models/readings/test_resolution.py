"""The step of readings as entered (models.readings.resolution)."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given
from hypothesis import strategies as st

from models.readings.resolution import GRID, coarse, readings_step


@given(step=st.integers(1, 10**5), offset=st.integers(-10**6, 10**6),
       multiples=st.lists(st.integers(-500, 500), min_size=2, max_size=40))
def test_the_step_found_is_the_coarsest_grid_every_reading_lies_on(step, offset, multiples):
    values = (offset + step * np.asarray(multiples)) * GRID  # typed decimals, as floats
    found = readings_step(values)
    whole = math.gcd(*(abs(k - multiples[0]) for k in multiples))
    if whole == 0:
        assert found is None  # all equal: nothing to measure a step by
        return
    assert found is not None
    assert math.isclose(found, step * whole * GRID, rel_tol=1e-9)
    ratios = (values - values[0]) / found
    assert np.allclose(ratios, np.round(ratios), atol=1e-6)


def test_typed_readings_give_their_last_digit():
    assert math.isclose(readings_step(np.array([12.31, 12.35, 12.4, 11.98])), 0.01)
    assert math.isclose(readings_step(np.array([-1.0, 2.0, 0.0, 1.0])), 1.0)
    # an encoder's counts of 0.36" (0.0001°)
    assert math.isclose(readings_step(0.36 * np.array([3, -7, 12, 5])), 0.36)


def test_readings_on_no_grid_have_no_step():
    rng = np.random.default_rng(1)
    assert readings_step(rng.normal(0.0, 1.0, 20)) is None  # converted, full precision
    assert readings_step(np.array([0.5, 0.5, 0.5])) is None
    assert readings_step(np.array([0.5])) is None
    assert readings_step(np.array([0.5, np.nan])) is None
    assert readings_step(np.array([1e308, 0.0])) is None  # no grid of whole steps that far


def test_coarse_is_a_scatter_below_half_the_step():
    assert coarse(1.0, 0.3)
    assert not coarse(1.0, 0.5)
    assert not coarse(None, 0.0)
    assert not coarse(1.0, math.nan)
