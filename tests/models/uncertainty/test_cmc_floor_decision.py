"""The laboratory's CMC held in the statement of conformity (ILAC-P14 5.4): the decided half
range's interval, its guard bands and its probabilities use no U below the CMC; and the
statement says which U its rule uses when a point's U is not smaller than T."""

from __future__ import annotations

import math

import numpy as np
from scipy.stats import norm

from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity

T = 3.0


def _curve_and_budget(floor: float) -> tuple[np.ndarray, UncertaintyBudget]:
    theta = np.linspace(0.0, 2.0 * math.pi, 24, endpoint=False)
    errors = 0.6 * np.sin(theta) + 0.2 * np.cos(3.0 * theta)
    noise = BudgetComponent("reading noise", "B", "normal", 0.1, 1.0, 1.0, math.inf)
    return errors, UncertaintyBudget((noise,), theta.size, floor=floor)


def test_the_half_ranges_interval_and_guard_bands_are_held_to_the_cmc():
    errors, bare = _curve_and_budget(0.0)
    free = decide_conformity(errors, bare, T, "guarded", "half_range")
    assert free.expanded < 0.5 and free.lower_half_width < 0.5  # what the readings give
    cmc = 2.0
    errors, budget = _curve_and_budget(cmc)
    held = decide_conformity(errors, budget, T, "guarded", "half_range")
    x = held.value
    assert x == free.value  # the value is not moved
    assert held.expanded == cmc and held.lower_half_width == cmc
    assert held.interval_high == x + cmc and held.interval_low == max(0.0, x - cmc)
    # the guard band of acceptance is the CMC: pass ≤ T − 2 = 1.0" (U to two significant
    # digits, GUM 7.2.6); that of rejection the statement's U₋, the value where the lower end
    # is held at 0 (assessment 72 M4), else the CMC: conditional fail ≤ T + 2 = 5.0"
    assert 'pass ≤ 1.0" (T − ' in held.zones
    minus = f"{x:.1f}" if x < cmc else "2.0"
    assert (f'≤ {T + float(minus):.1f}" (T + U₋, U₋ = {minus}")' in held.zones if x < cmc
            else '≤ 5.0" (T + w)' in held.zones), held.zones
    # U₋ printed after the end is held at 0 (0.8.14: ±2.0″ beside 0.0″ … 2.7″), and why
    if x < cmc:
        assert f"U = −{x:.1f}\"/+2.0\"" in held.statement, held.statement
        assert "held to the laboratory's CMC U = 2\" reaches below 0" in held.statement
    else:
        assert "U = ±2.0\"" in held.statement
    assert held.verdict == "pass"
    # the probability of a false acceptance recomputed: the upper side a normal whose
    # (1 + p)/2 quantile lies at x + CMC
    sigma = cmc / norm.ppf(0.5 * (1.0 + budget.probability))
    risk = norm.sf((T - x) / sigma)
    assert math.isclose(held.decision_risk, risk, rel_tol=1e-9)
    assert held.decision_risk > 10 * free.decision_risk
    assert f"{100 * risk:.2f} %" in held.statement
    assert "held to at least the laboratory's CMC U = 2\"" in held.quantity


def test_no_statement_when_the_cmc_is_not_smaller_than_t():
    errors, budget = _curve_and_budget(3.0)
    held = decide_conformity(errors, budget, T, "guarded", "half_range")
    assert held.verdict == "not assessed"
    # the lower end held at 0 prints U₋ as the value, so U₊, the one that guards acceptance
    assert "U₊ = 3.0\" is not smaller than T = 3\"" in held.reason


def test_the_statement_says_which_u_its_rule_uses_when_a_points_u_reaches_t():
    """A point's U (0.2″) is not smaller than T = 0.2″, the half range's own interval is:
    a statement is made, and it says that its U is the half range's, not a point's."""
    errors, budget = _curve_and_budget(0.0)
    point_u = float(budget.max_expanded)
    t = round(point_u, 1)
    assert point_u >= t
    errors = errors * 0.2  # a half range within T
    decided = decide_conformity(errors, budget, t, "guarded", "half_range")
    assert max(decided.expanded, decided.lower_half_width) < t
    assert decided.stated
    assert ("the U of the decision rule (its guard bands and its test U₊ < T) is this "
            "quantity's own, the half-widths U₋ and U₊ of its coverage interval, not the U of "
            f"a point (up to {point_u:.2f}\", not smaller than T = {t:g}\")") in decided.quantity
    # below T, nothing to explain
    assert "the U of the decision rule" not in decide_conformity(
        errors, budget, 2 * t, "guarded", "half_range").quantity
