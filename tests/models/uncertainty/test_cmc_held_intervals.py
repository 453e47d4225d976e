"""The one rule by which every interval stated beside the laboratory's CMC is held to it
(ILAC-P14 5.4; models.uncertainty.lab_scope.held_to_cmc): the decided quantity's and each
ISO 230-2 / VDI/DGQ 3441 figure's. Properties over any interval and CMC: it never narrows,
never moves the value, keeps the lower end of a figure that cannot be negative at 0 at the
lowest, leaves each half-width at least the CMC, and applied again changes nothing."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.uncertainty.conformity import HalfRangeEstimate, _held_to_cmc
from models.uncertainty.figure_intervals import (
    SIGNED_FIGURES,
    FigureInterval,
    held_to_cmc_figures,
)
from models.uncertainty.lab_scope import held_to_cmc

finite = st.floats(min_value=-50.0, max_value=50.0, allow_nan=False, allow_infinity=False)
positive = st.floats(min_value=0.0, max_value=20.0, allow_nan=False, allow_infinity=False)
cmc = st.floats(min_value=1e-6, max_value=20.0, allow_nan=False, allow_infinity=False)


@st.composite
def figure_interval(draw):
    """A figure's interval as figure_intervals gives it: a non-negative figure's ends not
    below 0, the interval possibly wholly below the value (a range biased high)."""
    key = draw(st.sampled_from(["E", "R", "B", "A_up", "Ps_max", "B_mean"]))
    signed = key in SIGNED_FIGURES
    value = draw(finite if signed else positive)
    a, b = sorted((draw(finite), draw(finite)))
    low, high = (a, b) if signed else (max(a, 0.0), max(b, 0.0))
    probability = draw(st.sampled_from([0.9545, 0.925, 0.945]))
    return key, FigureInterval(value, low, high, probability)


@settings(max_examples=400, deadline=None)
@given(figure_interval(), cmc)
def test_a_figures_interval_held_never_narrows_never_moves_and_stays_held(case, floor):
    key, before = case
    held = held_to_cmc_figures({key: before}, floor)[key]
    assert held.value == before.value  # the value not moved
    assert held.probability == before.probability  # the interval only grew: kept
    assert held.low <= before.low and held.high >= before.high  # never narrows
    # each half-width at least the CMC, the lower end of a non-negative figure at 0 at most
    assert held.high >= before.value + floor - 1e-12
    if key in SIGNED_FIGURES:
        assert held.low <= before.value - floor + 1e-12
    else:
        assert held.low >= 0.0
        assert held.low <= max(before.value - floor, 0.0) + 1e-12
    # raised exactly where the readings' half-width was below the CMC, an end not raised kept
    minus, plus = before.value - before.low, before.high - before.value
    assert held.raised_to_cmc == (minus < floor, plus < floor)
    if not minus < floor:
        assert held.low == before.low
    if not plus < floor:
        assert held.high == before.high
    # idempotent: held again, the same interval and the same marks
    again = held_to_cmc_figures({key: held}, floor)[key]
    assert (again.low, again.high, again.raised_to_cmc) == (held.low, held.high,
                                                            held.raised_to_cmc)


@settings(max_examples=200, deadline=None)
@given(figure_interval())
def test_without_a_cmc_a_figures_interval_is_not_touched(case):
    key, before = case
    assert held_to_cmc_figures({key: before}, 0.0)[key] is before


@settings(max_examples=300, deadline=None)
@given(positive, finite, finite, cmc)
def test_the_rule_on_half_widths(value, minus, plus, floor):
    held = held_to_cmc(value, minus, plus, floor)
    assert held.value == value
    assert held.minus == max(minus, floor) and held.plus == max(plus, floor)
    assert held.raised == (minus < floor, plus < floor)
    assert held.low == max(value - held.minus, 0.0) and held.high == value + held.plus
    signed = held_to_cmc(value, minus, plus, floor, non_negative=False)
    assert signed.low == value - signed.minus
    again = held_to_cmc(held.value, held.minus, held.plus, floor)
    assert (again.minus, again.plus) == (held.minus, held.plus)


@pytest.mark.parametrize("minus, plus", [(math.nan, 1.0), (1.0, math.inf)])
def test_an_interval_not_determined_is_not_held(minus, plus):
    held = held_to_cmc(1.0, minus, plus, 2.0)
    assert held.raised is None
    assert held.minus is minus or (math.isnan(minus) and math.isnan(held.minus))


@settings(max_examples=200, deadline=None)
@given(positive, positive, finite, cmc)
def test_the_decided_half_range_is_held_by_the_same_rule(value, lower, upper, floor):
    mc = HalfRangeEstimate(measured=value, bias=0.0, value=value, u_upper=upper, u_lower=lower,
                           probability=0.9545, trials=10, seed=1)
    held, raised = _held_to_cmc(mc, floor)
    rule = held_to_cmc(value, lower, upper, floor)
    assert raised == rule.raised
    assert (held.u_lower, held.u_upper) == (rule.minus, rule.plus)
    assert held.value == value and held.probability == mc.probability
