"""Assessment 73 M6: with every point deciding, the probability of a false acceptance is
bounded by Boole's inequality (at most the sum over the points of each one's probability of
lying outside ±T), not computed. 0.8.21 printed the bound as the probability: a pass beside
"Probability of a false acceptance at this decision: 100.00 %" (the sum reached 1), and the
XLSX "Probability of conformity < 0.01 %". The statement now says "at most" (rounded up, so
the printed bound still holds), or that the method does not bound it where the sum reaches
100 %; one point alone is no bound.

The sums are computed here from the normal distribution (U = 2σ at 95.45 %), nothing from
the code checked."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
from scipy.stats import norm

from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity

P = 0.9544997361036416  # k = 2


def _decide(errors, expanded, t):
    e, u = np.asarray(errors, float), np.asarray(expanded, float)
    budget = UncertaintyBudget((BudgetComponent("noise", "B", "normal", u / 2.0, 1.0, 1.0,
                                                math.inf),), e.size, P, "arcsec")
    return decide_conformity(e, budget, t, "simple", "points")


def _outside(e: float, u: float, t: float) -> float:
    sigma = u / 2.0
    return float(norm.sf((t - abs(e)) / sigma) + norm.cdf((-t - abs(e)) / sigma))


def test_a_sum_beyond_one_is_said_not_to_bound_the_risk():
    errors, expanded, t = np.full(10, 9.5), np.full(10, 2.0), 10.0
    total = sum(_outside(e, u, t) for e, u in zip(errors, expanded, strict=True))
    assert total > 1.0  # the case: the bound says nothing
    c = _decide(errors, expanded, t)
    assert c.verdict == "pass"
    assert "100.00 %" not in c.statement and "< 0.01 %" not in c.statement
    assert "false acceptance at this decision: not bounded by this method" in c.statement


def test_a_sum_below_one_is_printed_as_at_most_and_holds():
    errors, expanded, t = np.array([9.0, 2.0, -1.0, 0.5]), np.full(4, 2.0), 10.0
    total = sum(_outside(e, u, t) for e, u in zip(errors, expanded, strict=True))
    c = _decide(errors, expanded, t)
    found = re.search(r"false acceptance at this decision: at most ([0-9.]+) %", c.statement)
    assert c.verdict == "pass" and found, c.statement
    printed = float(found.group(1))
    assert 100 * total <= printed <= 100 * total + 0.01 + 1e-9


@pytest.mark.parametrize("rule_case", ["pass", "fail"])
def test_one_point_alone_is_its_probability_not_a_bound(rule_case):
    e = 9.0 if rule_case == "pass" else 10.5
    c = _decide([e], [2.0], 10.0)
    assert c.verdict == rule_case and "at most" not in c.statement
    assert "not bounded" not in c.statement


@pytest.mark.parametrize("rule", ["simple", "guarded_binary", "guarded"])
def test_the_point_that_fails_most_surely_decides_a_fail(rule):
    """Assessment 76 L3: 10.0″ ± 2.1″ (|e| + U = 12.1″) and 10.3″ ± 1.5″ (11.8″) against
    ±5″: both fail, the second more surely (its probability of lying within ±T the lower:
    5.3″ is 7.1 σ beyond T against 4.8 σ), so it decides and its probability is the one
    printed, a bound the first would loosen. Until 0.8.24 |e| + U chose the first."""
    errors, expanded, t = np.array([1.0, 10.0, -10.3, 2.0]), np.array([1.0, 2.1, 1.5, 1.0]), 5.0
    e, u = errors, expanded
    budget = UncertaintyBudget((BudgetComponent("noise", "B", "normal", u / 2.0, 1.0, 1.0,
                                                math.inf),), e.size, P, "arcsec")
    c = decide_conformity(e, budget, t, rule, "points",
                          point_names=["a", "b", "c", "d"])
    assert c.verdict == "fail" and c.point == "c"
    assert c.value == pytest.approx(-10.3) and c.expanded == pytest.approx(1.5)
    assert "the deciding point is c: |e| = 10.3\", U = 1.5\"" in c.statement
    within = 1.0 - _outside(-10.3, 1.5, t)
    assert within < 1.0 - _outside(10.0, 2.1, t)
    assert c.decision_risk == pytest.approx(within, rel=1e-6)
    assert c.conforming_probability == pytest.approx(within, rel=1e-6)
