"""The statement of conformity as ILAC-G8:09/2019 makes it: the guard band from the decided
value's own interval, the decision at the edges of every zone, the probability of a wrong
decision (JCGM 106), and no statement when U is incomplete, U ≥ T or the figure withheld.
U printed as GUM 7.2.6 asks (two significant digits at most)."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.stats import norm

import models.uncertainty.conformity as conformity_module
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import (
    decide_conformity,
    expanded_text,
    gum_rounded,
    probability_conforming,
    significant_decimals,
)

P = 0.9544997361036416  # k = 2 exactly for a normal distribution
K = norm.ppf(0.5 * (1 + P))


def _budget(u: float, n: int) -> UncertaintyBudget:
    """Every point with the standard uncertainty u, exactly known (k = 2)."""
    return UncertaintyBudget((BudgetComponent("noise", "B", "normal", u, 1.0, 1.0, math.inf),),
                             n, P)


# --- GUM 7.2.6 --------------------------------------------------------------------------

def _significant_digits(text: str) -> int:
    digits = text.replace(".", "").lstrip("0")
    return len(digits)


@settings(max_examples=300, deadline=None)
@given(st.floats(min_value=1e-6, max_value=99.0), st.floats(min_value=-1e3, max_value=1e3))
def test_u_has_at_most_two_significant_digits_and_the_value_its_decimal(u, value):
    value_text, u_text = gum_rounded(value, u)
    assert _significant_digits(u_text) <= 2, (u, u_text)
    decimals = len(u_text.split(".")[1]) if "." in u_text else 0
    assert (len(value_text.split(".")[1]) if "." in value_text else 0) == decimals
    step = 10.0 ** -decimals
    # U rounded up (issue 39): never below U, less than one digit above; the value to the
    # nearest digit shown: never off by more than half of it
    assert u * (1 - 1e-12) <= float(u_text) < u + step * (1 + 1e-9)
    assert abs(float(value_text) - value) <= 0.5 * step * (1 + 1e-9)


@pytest.mark.parametrize(("u", "text"), [(2.03, "2.1"), (3.54, "3.6"), (0.0996, "0.10"),
                                         (0.094, "0.094"), (1.35, "1.4"), (0.0123, "0.013"),
                                         (12.6, "13"), (0.9996, "1.0"), (0.994, "1.0"),
                                         (2.0, "2.0")])
def test_printed_u_examples(u, text):
    assert gum_rounded(1.0, u)[1] == text
    assert significant_decimals(u) == (len(text.split(".")[1]) if "." in text else 0)


def test_zero_u_is_a_reference_point_never_0_00():
    assert str(expanded_text(0.0)) == "reference point, by definition"
    assert expanded_text(0.25) == "0.25\""


# --- decisions at the edges of the zones -------------------------------------------------

T = 1.0
U = float(_budget(0.1, 1).expanded[0])  # u = 0.1, k = 2 (to the last bit as computed)


@pytest.mark.parametrize(("edge", "rule", "verdict"), [
    # decided on the figures as printed (issue 39): U = 0.2 prints "0.20" (U rounded up, the
    # same beside any value: assessment 72 H1), the value to the nearest 0.01
    (lambda: T - U, "guarded", "pass"),
    (lambda: T - U + 1e-6, "guarded", "pass"),  # printed 0.80 + 0.20 = 1.00: at T as printed
    (lambda: T - U + 0.006, "guarded", "conditional pass"),  # printed 0.81 + 0.20 > T
    (lambda: T, "guarded", "conditional pass"),
    (lambda: T + 0.004, "guarded", "conditional pass"),  # printed 1.00: at T as printed
    (lambda: T + 0.006, "guarded", "conditional fail"),  # printed 1.01
    (lambda: T + U, "guarded", "conditional fail"),
    (lambda: T + U + 0.004, "guarded", "conditional fail"),  # 1.20 − 0.20 is not beyond T
    (lambda: T + U + 0.006, "guarded", "fail"),  # 1.21 − 0.20 = 1.01 > T
    (lambda: T - U, "guarded_binary", "pass"),
    (lambda: T - U + 0.006, "guarded_binary", "fail"),
    (lambda: T, "simple", "pass"), (lambda: T + 0.004, "simple", "pass"),
    (lambda: T + 0.006, "simple", "fail"),
    (lambda: -(T + U + 0.016), "guarded", "fail"),  # |e| decides
])
def test_points_rule_at_the_band_edges(edge, rule, verdict):
    error = edge()
    errors = np.array([0.0, 0.1, error, -0.05])
    c = decide_conformity(errors, _budget(0.1, errors.size), T, rule, "points")
    assert c.verdict == verdict
    assert c.value == pytest.approx(error)  # signed: the deciding point's error
    assert c.interval_low == pytest.approx(error - U)
    assert c.interval_high == pytest.approx(error + U)


def _fixed_half_range(monkeypatch, value: float, lower: float, upper: float) -> None:
    estimate = SimpleNamespace(value=value, u_lower=lower, u_upper=upper, probability=P,
                               measured=value + 0.05, trials=1000, seed=1, stride=1)
    monkeypatch.setattr(conformity_module, "half_range_monte_carlo", lambda e, b: estimate)


@pytest.mark.parametrize(("value", "verdict"), [
    (1.0 - 0.3, "pass"), (1.0 - 0.3 + 1e-6, "pass"),  # printed 0.70 + 0.30: at T as printed
    (1.0 - 0.3 + 0.006, "conditional pass"), (1.0, "conditional pass"),
    (1.0 + 0.1, "conditional fail"), (1.0 + 0.1 + 1e-6, "conditional fail"),
    (1.0 + 0.11 + 1e-6, "fail")])
def test_asymmetric_interval_upper_half_width_guards_acceptance(monkeypatch, value, verdict):
    """The interval −0.1/+0.3: acceptance needs value + 0.3 ≤ T, rejection value − 0.1 > T,
    on the figures as printed (to 0.01: 1.10 − 0.10 is not beyond T, 1.11 − 0.10 is)."""
    _fixed_half_range(monkeypatch, value, 0.1, 0.3)
    c = decide_conformity(np.zeros(8), _budget(0.01, 8), 1.0, "guarded", "half_range")
    assert c.verdict == verdict
    assert (c.interval_low, c.interval_high) == pytest.approx((value - 0.1, value + 0.3))


def test_probability_of_false_acceptance_is_the_normal_tail(monkeypatch):
    """At the acceptance limit with a symmetric interval the true value exceeds T with the
    normal tail beyond k = 2: 2.275 %."""
    p = probability_conforming(T - U, U, U, T, P)
    assert 1 - p == pytest.approx(norm.sf(K), rel=1e-9)
    _fixed_half_range(monkeypatch, T - U, U, U)
    c = decide_conformity(np.zeros(8), _budget(0.01, 8), T, "guarded", "half_range")
    assert c.verdict == "pass" and c.decision_risk == pytest.approx(norm.sf(K), rel=1e-6)
    assert "2.28 %" in c.statement
    # simple acceptance at the limit: half the time the item is out
    _fixed_half_range(monkeypatch, T, U, U)
    c = decide_conformity(np.zeros(8), _budget(0.01, 8), T, "simple", "half_range")
    assert c.verdict == "pass" and c.decision_risk == pytest.approx(0.5)
    # a fail: the probability of a false rejection
    _fixed_half_range(monkeypatch, T + 1.5 * U, U, U)
    c = decide_conformity(np.zeros(8), _budget(0.01, 8), T, "guarded", "half_range")
    assert c.verdict == "fail" and c.decision_risk == pytest.approx(norm.cdf(-1.5 * K))
    assert "false rejection" in c.statement


def test_split_normal_holds_the_interval_at_its_probability():
    """Drawn independently: each side of the value a half normal with the side's σ; the
    interval −a/+b holds P of the draws and the tail beyond T is what is stated."""
    rng = np.random.default_rng(5)
    value, lower, upper, t = 2.0, 0.3, 0.9, 2.5
    side = rng.random(400_000) < 0.5
    half = np.abs(rng.standard_normal(side.size))
    draws = np.where(side, value + half * upper / K, value - half * lower / K)
    inside = np.mean((draws >= value - lower) & (draws <= value + upper))
    assert inside == pytest.approx(P, abs=0.002)
    assert probability_conforming(value, lower, upper, t, P) == pytest.approx(
        np.mean(draws <= t), abs=0.002)


def test_points_false_acceptance_is_bounded_by_the_sum_over_points():
    errors = np.array([T - U, -(T - U), 0.0])  # two points at the acceptance limit
    c = decide_conformity(errors, _budget(0.1, 3), T, "guarded", "points")
    tail = norm.sf(K)
    assert c.verdict == "pass"
    assert c.decision_risk == pytest.approx(2 * tail + 2 * norm.sf(18 * K / 2) + norm.sf(10 * K),
                                            rel=1e-3)


# --- no statement ------------------------------------------------------------------------

def test_incomplete_u_makes_no_statement_but_gives_the_figures():
    errors = np.array([0.0, 0.1, 0.3, -0.05])
    c = decide_conformity(errors, _budget(0.05, 4), T, "guarded", "points",
                          not_stated=("Temperature", "Misalignment of the reference"))
    assert c.verdict == "not assessed" and c.conforms is None
    assert "Temperature, Misalignment of the reference" in c.reason
    assert "not stated" in c.reason and "not stated" in c.statement
    assert c.value == pytest.approx(0.3) and c.interval_high == pytest.approx(0.4)
    assert math.isnan(c.decision_risk)


def test_u_not_smaller_than_t_makes_no_statement():
    errors = np.array([0.0, 0.1, 0.3, -0.05])
    c = decide_conformity(errors, _budget(0.5, 4), T, "guarded", "points")
    assert c.verdict == "not assessed"
    assert "not smaller than" in c.reason and math.isfinite(c.value)


def test_u_not_smaller_than_t_on_the_half_range(monkeypatch):
    _fixed_half_range(monkeypatch, 0.2, 0.5, 1.2)
    c = decide_conformity(np.zeros(8), _budget(0.01, 8), T, "simple", "half_range")
    assert c.verdict == "not assessed" and "not smaller than" in c.reason
    assert c.value == pytest.approx(0.2) and c.interval_high == pytest.approx(1.4)
    assert c.interval_low == 0.0  # a half range is never negative


def test_withheld_figure_makes_no_statement(monkeypatch):
    _fixed_half_range(monkeypatch, float("nan"), float("nan"), float("nan"))
    c = decide_conformity(np.zeros(8), _budget(0.01, 8), T, "guarded", "half_range")
    assert c.verdict == "not assessed" and "withheld" in c.reason
    c = decide_conformity(np.array([0.1, np.nan]), _budget(0.01, 2), T, "guarded", "points")
    assert c.verdict == "not assessed" and "withheld" in c.reason


def test_invalid_run_keeps_the_figures(monkeypatch):
    _fixed_half_range(monkeypatch, 0.3, 0.1, 0.1)
    c = decide_conformity(np.zeros(8), _budget(0.01, 8), T, "guarded", "half_range",
                          invalid_reason="the run is invalid (closure failed)")
    assert c.verdict == "not assessed" and "closure failed" in c.reason
    assert c.value == pytest.approx(0.3)


# --- assessment 70 L5, M1: the probability and the interval as the figures table prints them

@pytest.mark.parametrize("probability, said", [(0.925, "92.5"), (0.92, "92"), (P, "95.45")])
def test_the_statement_gives_the_interval_probability_as_the_figures_table(probability, said):
    """An interval evaluated at 92.5 % (positioning's E/2 at half_range) is "92.5 %" in the
    statement, as in the figures table, not "92.50 %"."""
    from models.uncertainty.conformity import HalfRangeEstimate

    estimate = HalfRangeEstimate(measured=6.4, bias=0.0, value=6.4, u_upper=1.2, u_lower=1.5,
                                 probability=probability, trials=0, seed=0)
    c = decide_conformity(np.array([6.4, -6.4]), _budget(0.3, 2), 15.0, "guarded",
                          "half_range", estimate=estimate)
    assert f"coverage probability {said} %" in c.statement


@settings(max_examples=200, deadline=None)
@given(value=st.floats(0.05, 50.0), lower=st.floats(0.01, 5.0), upper=st.floats(0.01, 5.0))
def test_printed_value_plus_minus_printed_u_is_the_printed_interval(value, lower, upper):
    """M1: "x, coverage interval a … b (U = −U₋/+U₊)": x − U₋ = a and x + U₊ = b as printed;
    each printed U is the computed U rounded up (GUM 7.2.6), the value the nearest (assessment
    72 H1: the U every other document gives), so the printed interval's ends lie within half
    a printed digit of the computed ones or outside them."""
    import re

    from models.uncertainty.conformity import HalfRangeEstimate

    lower = min(lower, value)
    estimate = HalfRangeEstimate(measured=value, bias=0.0, value=value, u_upper=upper,
                                 u_lower=lower, probability=P, trials=0, seed=0)
    c = decide_conformity(np.array([value, -value]), _budget(0.01, 2), 1000.0, "guarded",
                          "half_range", estimate=estimate)
    found = re.search(r": ([\d.]+)\" as measured, coverage interval ([\d.]+)\" … ([\d.]+)\" "
                      r"\(U = (?:±([\d.]+)\"|−([\d.]+)\"/\+([\d.]+)\")", c.statement)
    assert found, c.statement
    x, a, b = (float(found.group(i)) for i in (1, 2, 3))
    minus = float(found.group(4) or found.group(5))
    plus = float(found.group(4) or found.group(6))
    assert x - minus == pytest.approx(a, abs=1e-9) and x + plus == pytest.approx(b, abs=1e-9)
    digit = 10.0 ** -len(found.group(1).partition(".")[2])
    assert a <= value - lower + digit / 2 + 1e-9 and b >= value + upper - digit / 2 - 1e-9
    assert upper - 1e-9 <= plus < upper + digit + 1e-9
    assert a == 0.0 or lower - 1e-9 <= minus < lower + digit + 1e-9
