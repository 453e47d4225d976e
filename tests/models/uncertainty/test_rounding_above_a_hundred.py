"""U of any size with two significant digits at most, rounded up, and the value to its place
(GUM 7.2.6, JJF 1059.1): a U of 100 or more rounds to the tens, hundreds … (assessment 76
M1: until 0.8.24 the decimals stopped at the unit, "168", "2245"); and a figure that rounds
to zero has no sign (assessment 76 L6)."""

from __future__ import annotations

import math
from decimal import Decimal

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.uncertainty.conformity import gum_rounded
from models.uncertainty.rounding import (
    fixed_places,
    interval_decimals,
    printed_range,
    significant_decimals,
    stated_interval,
    stated_pair,
)


@pytest.mark.parametrize(("u", "decimals", "text"), [
    (168.3, -1, "170"), (222.0, -1, "230"), (101.0, -1, "110"), (99.6, -1, "100"),
    (360.000000986, -1, "370"), (360.0, -1, "360"), (1081.5, -2, "1100"), (12.6, 0, "13"),
    (1.436, 1, "1.5"), (0.0996, 2, "0.10"),
])
def test_u_to_two_significant_digits_rounded_up_at_any_size(u, decimals, text):
    assert significant_decimals(u) == decimals
    assert gum_rounded(0.0, u)[1] == text


@pytest.mark.parametrize(("value", "u", "printed"), [
    (998.3, 222.0, ("1000", "230")), (-138.2, 168.3, ("-140", "170")),
    (2245.2, 1081.5, ("2200", "1100")), (-4.9, 168.3, ("0", "170")),
])
def test_the_value_to_the_place_of_its_u(value, u, printed):
    assert gum_rounded(value, u) == printed


def test_a_pair_and_an_interval_above_a_hundred():
    assert stated_pair(998.3, 222.0) == (1000.0, 230.0, -1)
    shown = stated_interval(998.3, 222.0, 222.0, -1)
    assert shown == {"value": 1000.0, "lower": 230.0, "upper": 230.0, "low": 770.0,
                     "high": 1230.0}
    assert interval_decimals(1556.0, 3719.0) == -2


@pytest.mark.parametrize(("value", "decimals", "sign", "text"), [
    (168.3, -1, "", "170"), (-1549.0, -2, "+", "-1500"), (1550.0, -2, "+", "+1600"),
    (-0.04, 1, "+", "0.0"), (0.0, 1, "+", "0.0"), (-0.0, 2, "", "0.00"), (0.04, 1, "+", "0.0"),
    (-4.0, -1, "+", "0"), (0.06, 1, "+", "+0.1"),
])
def test_fixed_places(value, decimals, sign, text):
    assert fixed_places(value, decimals, sign) == text


def test_a_range_that_ends_at_zero_has_no_sign_on_it():
    assert printed_range(-0.004, 1.26, 1) == ("0.0", "+1.3", "1.3")
    assert printed_range(-149.0, 1549.0, -2) == ("-100", "+1500", "1600")


def _significant(text: str) -> int:
    return len(text.lstrip("+-").replace(".", "").lstrip("0").rstrip("0") or "0")


@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=1e-6, max_value=1e6), st.floats(min_value=-1e7, max_value=1e7))
def test_any_u_has_at_most_two_significant_digits_and_the_value_its_place(u, value):
    value_text, u_text = gum_rounded(value, u)
    assert _significant(u_text) <= 2, (u, u_text)
    step = 10.0 ** -significant_decimals(u)
    # U rounded up: never below U, less than one step above; the value to the nearest step
    assert u * (1 - 1e-12) <= float(u_text) < u + step * (1 + 1e-9)
    assert abs(float(value_text) - value) <= 0.5 * step * (1 + 1e-6) + 1e-15 * abs(value)
    assert float(Decimal(value_text) % Decimal(repr(step))) == 0.0  # on U's grid
    assert math.isclose(float(u_text) / step, round(float(u_text) / step), abs_tol=1e-6)
