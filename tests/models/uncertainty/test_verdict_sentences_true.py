"""Every verdict sentence is true beside the probability printed after it (assessment 76
L4): a guarded binary "fail" said "The item does not conform" beside an 84.75 %
probability that it conforms, and simple acceptance said "The item conforms" (or does
not) whatever its probability. Under each rule and verdict the sentence claims conformity
(non-conformity) only where the probability printed beside it proves it at the stated
coverage probability; the JSON's verdicts stay as they were."""

from __future__ import annotations

import math
import re
from types import SimpleNamespace

import numpy as np
import pytest

from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity

P = 0.9544997361036416
#: the probability printed after the verdict, and which one
RISK = re.compile(r"Probability of a false (acceptance|rejection) at this decision: "
                  r"(?:at most )?(< 0\.01|[\d.]+) %")


def _half_range(value: float, lower: float, upper: float, t: float, rule: str):
    estimate = SimpleNamespace(value=value, u_lower=lower, u_upper=upper, probability=P,
                               measured=value, trials=1000, seed=1, stride=1)
    budget = UncertaintyBudget((BudgetComponent("noise", "B", "normal", 1e-6, 1.0, 1.0,
                                                math.inf),), 2, P)
    return decide_conformity(np.array([value, -value]), budget, t, rule, "half_range",
                             estimate=estimate)


def _risk(statement: str) -> tuple[str, float]:
    found = RISK.search(statement)
    assert found, statement
    figure = 0.0 if found[2] == "< 0.01" else float(found[2])
    return found[1], figure


def test_the_assessors_guarded_binary_fail_is_not_accepted_not_non_conforming():
    """The assessment's case (t_fail): 0.95″ −0.49″/+0.50″ against T = 1.2″, guarded binary.
    The rule rejects (its rejection zone includes the guard band), the item conforms with a
    probability of 84 %: the statement says it is not accepted and that conformity is not
    proven, never that the item does not conform."""
    c = _half_range(0.9476, 0.492, 0.492, 1.2, "guarded_binary")
    assert c.verdict == "fail"  # the JSON's verdict, the documented contract, as it was
    which, figure = _risk(c.statement)
    assert which == "rejection" and 80.0 < figure < 90.0  # the probability it conforms
    assert "does not conform" not in c.statement
    assert ("Not accepted (fail): the result lies beyond the acceptance limit, T less the "
            "guard band, in the rejection zone of the binary rule, which includes the guard "
            "band; conformity to the specification ±1.2\" is not proven at the stated "
            "coverage probability."
            ) in c.statement


@pytest.mark.parametrize("value, verdict, which", [
    (0.95, "pass", "acceptance"),  # within T, 46 % probability it does not conform
    (1.05, "fail", "rejection"),  # beyond T, 37 % probability it conforms
])
def test_simple_acceptance_claims_no_conformity_it_cannot_prove(value, verdict, which):
    """Simple acceptance (T = 1.0″, U = 0.5″) accepts or rejects on the value alone: with a
    probability of a wrong decision of tens of percent beside it, the statement says the
    result is accepted (not) and where it lies, not that the item conforms (does not)."""
    c = _half_range(value, 0.5, 0.5, 1.0, "simple")
    assert c.verdict == verdict
    said, figure = _risk(c.statement)
    assert said == which and 30.0 < figure < 50.0
    assert "conforms" not in c.statement and "does not conform" not in c.statement
    where = "within" if verdict == "pass" else "beyond"
    accepted = "Accepted" if verdict == "pass" else "Not accepted"
    assert (f"{accepted} under simple acceptance (no guard band): the result lies {where} "
            f"±1\" ({verdict}).") in c.statement


@pytest.mark.parametrize("rule", ["guarded", "guarded_binary"])
def test_a_pass_beyond_the_guard_band_says_the_item_conforms(rule):
    """Where the whole interval lies within T (0.3″ +0.5″ ≤ 1.0″) conformity is proven at the
    stated coverage probability: the probability of a false acceptance is below its
    one-sided tail (2.3 %), and the statement says the item conforms, as before."""
    c = _half_range(0.3, 0.5, 0.5, 1.0, rule)
    assert c.verdict == "pass"
    which, figure = _risk(c.statement)
    assert which == "acceptance" and figure <= 100 * (1 - P) / 2
    assert "The item conforms to the specification ±1\" (pass)." in c.statement


def test_a_guarded_fail_beyond_the_guard_band_says_the_item_does_not_conform():
    """Under the guarded rule a fail lies beyond T + U₋ (1.6″ −0.5″ > 1.0″): the probability
    that it conforms is below the one-sided tail, so "does not conform" is true; within the
    guard band the rule says a conditional fail, that non-conformity is not proven."""
    c = _half_range(1.6, 0.5, 0.5, 1.0, "guarded")
    assert c.verdict == "fail"
    which, figure = _risk(c.statement)
    assert which == "rejection" and figure <= 100 * (1 - P) / 2
    assert "The item does not conform to the specification ±1\" (fail)." in c.statement
    c = _half_range(1.3, 0.5, 0.5, 1.0, "guarded")
    assert c.verdict == "conditional fail" and "non-conformity is not proven" in c.statement
    which, figure = _risk(c.statement)
    assert which == "rejection" and figure > 100 * (1 - P) / 2


def test_every_point_under_the_binary_rule_rejects_without_saying_non_conformity():
    """Every point deciding, guarded binary: a point at 0.9″ ± 0.5″ against T = 1.0″ is
    rejected (its interval reaches beyond T) though it conforms with a probability of
    about 65 %: not accepted, not "does not conform"."""
    e = np.array([0.1, -0.2, 0.9, 0.3])
    budget = UncertaintyBudget((BudgetComponent("noise", "B", "normal", 0.25, 1.0, 1.0,
                                                math.inf),), e.size, P)
    c = decide_conformity(e, budget, 1.0, "guarded_binary", "points")
    assert c.verdict == "fail"
    which, figure = _risk(c.statement)
    assert which == "rejection" and 50.0 < figure < 80.0
    assert "does not conform" not in c.statement and "Not accepted (fail)" in c.statement


@pytest.mark.parametrize("rule", ["simple", "guarded_binary"])
def test_a_fail_its_interval_proves_says_the_item_does_not_conform_under_any_rule(rule):
    """A result whose whole interval lies beyond T (1.6″ ± 0.5″ against 1.0″; the sample
    axis' target 60° ↓ at 10.3″ ± 1.5″ against ±5″) does not conform at the stated coverage
    probability whatever the rule: said so, not merely "not accepted"; and a pass within
    T − U₊ under simple acceptance conforms."""
    c = _half_range(1.6, 0.5, 0.5, 1.0, rule)
    assert c.verdict == "fail"
    which, figure = _risk(c.statement)
    assert which == "rejection" and figure <= 100 * (1 - P) / 2
    assert "The item does not conform to the specification ±1\" (fail)." in c.statement
    assert "Not accepted" not in c.statement
    c = _half_range(0.3, 0.5, 0.5, 1.0, rule)
    assert c.verdict == "pass" and "The item conforms to the specification ±1\" (pass)." in (
        c.statement)
    e = np.array([0.1, -0.2, 10.3, 0.3])
    budget = UncertaintyBudget((BudgetComponent("noise", "B", "normal", 0.75, 1.0, 1.0,
                                                math.inf),), e.size, P)
    c = decide_conformity(e, budget, 5.0, rule, "points")
    assert c.verdict == "fail" and "The item does not conform to the specification ±5\" (fail)." \
        in c.statement, c.statement
