"""The pointing noise's confidence bounds from its scatter s on ν degrees of freedom
(models.uncertainty.stated_excess), checked against a simulation of s from σ: s² ~ σ² χ²_ν/ν,
drawn here from normal readings, not from the module's χ² quantiles."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from models.uncertainty.stated_excess import (
    excess_not_excluded,
    scatter_lower_bound,
    scatter_upper_bound,
)

S = st.floats(min_value=1e-6, max_value=1e3, allow_nan=False)
NU = st.floats(min_value=1.0, max_value=1e5, allow_nan=False)
#: a share of a coverage interval's tail (γ (1 − p) with p ≥ 68 %: at most 0.08); above about
#: 0.2 the bound at ν = 1 is above s (χ²₁ exceeds 1 with probability 0.32) and falls with ν
BETA = st.floats(min_value=1e-4, max_value=0.1)


@given(S, NU, BETA)
def test_the_lower_bound_is_below_s_and_the_upper_above(s, nu, beta):
    lo = scatter_lower_bound(s, nu, beta)
    assert 0.0 < lo <= s <= scatter_upper_bound(s, nu)


@given(S, NU, NU, BETA)
@settings(max_examples=200)
def test_the_lower_bound_rises_towards_s_with_the_degrees_of_freedom(s, nu_a, nu_b, beta):
    few, many = sorted((nu_a, nu_b))
    assert scatter_lower_bound(s, few, beta) <= scatter_lower_bound(s, many, beta) * (1 + 1e-12)


def test_the_lower_bound_holds_sigma_at_its_probability():
    """σ = 1, ν = 10 (11 normal readings each): σ ≥ s_lo in 1 − β of 40,000 samples, β =
    0.0114 (a quarter of the 95.45 % interval's tail): 1.14 % ± 0.16 % below it."""
    rng = np.random.default_rng(7)
    readings = rng.normal(0.0, 1.0, (40_000, 11))
    s = np.std(readings, axis=1, ddof=1)
    beta = 0.25 * (1.0 - 0.9545)
    below = np.mean([scatter_lower_bound(v, 10.0, beta) > 1.0 for v in s])
    assert abs(below - beta) < 0.0016, below


def test_the_largest_excess_not_excluded():
    """u = √(σ² + u_c²): the part over s_lo is at least u_c whenever σ ≥ s_lo; 0 where u ≤
    s_lo; the whole u with no scatter known."""
    assert excess_not_excluded(1.0, 2.0, 20.0, 0.01) == 0.0
    lo = scatter_lower_bound(1.5, 22.0, 0.0114)
    assert lo < 1.5
    assert excess_not_excluded(math.hypot(1.5, 0.4), 1.5, 22.0, 0.0114) == math.sqrt(
        1.5**2 + 0.4**2 - lo**2)
    assert excess_not_excluded(0.7, math.nan, 10.0, 0.01) == 0.7
    assert scatter_lower_bound(1.2, math.inf, 0.01) == 1.2
    assert scatter_lower_bound(1.2, 0.5, 0.01) == 0.0
