"""A decided half range whose interval reaches further below than T but not above it
(assessment 76 M2, L2): U₊ guards acceptance (pass needs value + U₊ ≤ T), U₋ rejection
(fail needs value − U₋ > T), so U₋ ≥ T stops no statement under any of the three rules of
ILAC-G8:09/2019 4.2; U₊ ≥ T does (no result could be shown to lie within T), and the reason
then names U₊ with its printed figure. No "Compared with T" follows "no statement".

The estimate is the theodolite sample's at T = 0.8″ (certificate AB-2026-0011 of the
assessment): 0.95″, −0.94″/+0.50″, measured 1.44″.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import HalfRangeEstimate, decide_conformity

P = 0.9545


def _budget(n: int = 41) -> UncertaintyBudget:
    return UncertaintyBudget((BudgetComponent("reading noise", "A", "normal", 0.3, 1.0, 1.0,
                                              math.inf),), n, P)


def _decided(value: float, lower: float, upper: float, t: float, rule: str):
    estimate = HalfRangeEstimate(value + 0.49, 0.49, value, upper, lower, P, 5000, 1)
    return decide_conformity(np.zeros(41), _budget(), t, rule, "half_range",
                             estimate=estimate)


@pytest.mark.parametrize(("rule", "t", "verdict", "risk"), [
    # 0.95″ beyond T = 0.8″, its lower end 0.01″ within it: non-conformity not proven
    ("guarded", 0.8, "conditional fail", 0.3748),
    # the binary rule's fail zone holds its guard band (ILAC-G8 4.2.2)
    ("guarded_binary", 0.8, "fail", 0.3748),
    # simple acceptance: the value against T alone (the assessment's t_simfail)
    ("simple", 0.9, "fail", 0.4576),
])
def test_a_lower_half_width_beyond_t_stops_no_statement(rule, t, verdict, risk):
    c = _decided(0.95, 0.94, 0.492, t, rule)
    assert c.verdict == verdict, c.statement
    assert c.reason == ""
    assert "No statement" not in c.statement
    # the probability of a false rejection from the interval's lower side: P(Y ≤ T)
    assert c.decision_risk == pytest.approx(risk, abs=1e-4)
    assert f"{100 * risk:.2f} %" in c.statement


def test_the_zones_print_u_minus_beyond_t():
    c = _decided(0.95, 0.94, 0.492, 0.8, "guarded")
    assert c.zones == ('pass ≤ 0.30" (T − U₊, U₊ = 0.50") < conditional pass ≤ 0.8" (T) < '
                       'conditional fail ≤ 1.74" (T + U₋, U₋ = 0.94") < fail')


@pytest.mark.parametrize("rule", ["simple", "guarded_binary", "guarded"])
def test_acceptance_is_reached_with_u_minus_beyond_t(rule):
    """0.20″ −0.94″/+0.30″ (its lower end held at 0) against T = 0.8″: 0.20 + 0.30 ≤ 0.8,
    shown to lie within T, a pass by every rule."""
    c = _decided(0.2, 0.94, 0.3, 0.8, rule)
    assert c.verdict == "pass", c.statement
    assert c.interval_low == 0.0 and c.interval_high == pytest.approx(0.5)


@pytest.mark.parametrize("rule", ["simple", "guarded_binary", "guarded"])
def test_u_plus_not_below_t_gives_its_own_figure_as_the_reason(rule):
    c = _decided(0.95, 0.94, 0.492, 0.4, rule)
    assert c.verdict == "not assessed"
    assert c.reason == 'U₊ = 0.50" is not smaller than T = 0.4"'
    assert ('No statement of conformity is possible: the interval\'s upper half-width '
            'U₊ = 0.50", which guards acceptance, is not smaller than the tolerance T = 0.4", '
            'so no result could be shown to lie within it.') in c.statement
    assert "0.94\" is not smaller" not in c.statement
    assert math.isnan(c.decision_risk)


def test_a_symmetric_interval_names_its_u():
    c = _decided(0.95, 0.5, 0.5, 0.5, "guarded")
    assert c.verdict == "not assessed"
    assert c.reason == 'U = 0.50" is not smaller than T = 0.5"'


def test_no_comparison_with_t_beside_no_statement():
    """L2: simple acceptance, T = 0.3″ stated to a coarser place than U's digit: the value
    compared with T is said beside a decision, never after "no statement"."""
    c = _decided(0.95, 0.94, 0.492, 0.3, "simple")
    assert c.verdict == "not assessed"
    assert "Compared with T" not in c.statement
    assert c.compared is None
    stated = _decided(0.95, 0.94, 0.492, 0.9, "simple")
    assert "Compared with T: 0.95\"" in stated.statement  # said where it decided
