"""The reference cases of the method validation report (``anglebench validate``).

Three kinds of case for each workbench:

* the seeds' check figures (../shared/SPEC.md), from the model's equations;
* exact simulations with known truth, made by the first-principles rigs of
  this package, run through the whole analysis;
* the GUM budget against a Monte Carlo simulation of repeated measurements
  (JCGM 101): the spread of (result − truth) against the budget's u.

This module holds the shared machinery: :class:`ValidationCase`, where a case's expected
value comes from, the helpers that make a case from a figure and the cases of the shared
uncertainty and decision code. Each workbench's own cases live in its folder
(``models/<kind>/validation_cases.py``, or its Workbench's ``validation_cases``) and
:func:`models.validation.run.run_validation` gathers them; this module imports no workbench.
The Monte Carlo comparisons are functions of their own (in each workbench's module) so that
the test suite runs them with more trials.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from models.messages import QT_TR_NOOP, message

__all__ = ["BUDGET_VS_MONTE_CARLO", "CHECK_FIGURE", "EXACT_SIMULATION", "HAND_COMPUTED", "TABLE",
           "ValidationCase", "agreement_case", "at_most_case", "budget_agreement", "close_case",
           "decision_machinery_cases", "uncertainty_cases"]


#: where a case's expected value comes from
CHECK_FIGURE = QT_TR_NOOP("check figure")
EXACT_SIMULATION = QT_TR_NOOP("exact simulation")
BUDGET_VS_MONTE_CARLO = QT_TR_NOOP("budget vs Monte Carlo")
HAND_COMPUTED = QT_TR_NOOP("hand-computed example")
TABLE = QT_TR_NOOP("published table")


@dataclass(frozen=True)
class ValidationCase:
    """One reference case. Its texts are English; ``workbench``, ``name`` and ``source`` are
    translatable (a :class:`models.messages.Message` when it holds figures, else a text
    looked up whole), ``expected`` and ``obtained`` are figures or messages."""

    workbench: str
    name: str
    source: str  # CHECK_FIGURE, EXACT_SIMULATION or BUDGET_VS_MONTE_CARLO (English)
    expected: str
    obtained: str
    passed: bool


def budget_agreement(deviations: np.ndarray, budgets: np.ndarray) -> tuple[float, float]:
    """(RMS spread / RMS budget u, worst single-point |spread/u − 1|) over the points
    whose budget is not zero."""
    spread = np.std(deviations, axis=0, ddof=1)
    budget_u = np.sqrt(np.mean(np.square(budgets), axis=0))
    keep = budget_u > 0
    spread, budget_u = spread[keep], budget_u[keep]
    ratio = float(np.sqrt(np.mean(spread**2) / np.mean(budget_u**2)))
    return ratio, float(np.max(np.abs(spread / budget_u - 1.0)))


# -- Monte Carlo runs ------------------------------------------------------------------------
# -- the cases ----------------------------------------------------------------------------
def close_case(workbench: str, name: str, source: str, expected: float, obtained: float,
           tolerance: float, unit: str = "\"", digits: int = 3) -> ValidationCase:
    return ValidationCase(workbench, name, source, f"{expected:.{digits}f}{unit} ± {tolerance:g}{unit}",
                          f"{obtained:.{digits}f}{unit}", abs(obtained - expected) <= tolerance)


def at_most_case(workbench: str, name: str, source: str, limit: float, obtained: float,
             unit: str = "\"", digits: int = 4) -> ValidationCase:
    return ValidationCase(workbench, name, source, f"≤ {limit:g}{unit}",
                          f"{obtained:.{digits}g}{unit}", obtained <= limit)


def agreement_case(workbench: str, run: Callable, trials: int, seed: int) -> ValidationCase:
    """The spread of N runs estimates u to about 1/√(2N): the ratio may be off by three
    times that (at least 10 %), one point by four times (at least 25 %)."""
    ratio, worst = budget_agreement(*run(trials, np.random.default_rng(seed)))
    ratio_tol = max(0.10, 3.0 / math.sqrt(2.0 * trials))
    point_tol = max(0.25, 4.0 / math.sqrt(2.0 * trials))
    return ValidationCase(workbench,
                          message(QT_TR_NOOP("GUM budget u against the spread of {trials} "
                                             "simulated runs"), trials=trials),
                          BUDGET_VS_MONTE_CARLO,
                          message(QT_TR_NOOP("ratio 1 ± {tolerance}, worst point within "
                                             "{point} %"), tolerance=f"{ratio_tol:.2f}",
                                  point=f"{100 * point_tol:.0f}"),
                          message(QT_TR_NOOP("ratio {ratio}, worst point {worst} %"),
                                  ratio=f"{ratio:.3f}", worst=f"{100 * worst:.0f}"),
                          abs(ratio - 1.0) <= ratio_tol and worst <= point_tol)


#: a decision's verdict and a rule's name, as the report prints them
VERDICT_WORDS = {"pass": QT_TR_NOOP("pass"), "conditional pass": QT_TR_NOOP("conditional pass"),
                 "conditional fail": QT_TR_NOOP("conditional fail"), "fail": QT_TR_NOOP("fail")}
RULE_NAMES = {"guarded": QT_TR_NOOP("guard band, non-binary"),
              "guarded_binary": QT_TR_NOOP("guard band, binary"),
              "simple": QT_TR_NOOP("simple acceptance")}


def uncertainty_cases() -> list[ValidationCase]:
    """k from ν (GUM table G.2, p = 95.45 %, to its two decimals) and the decision rules'
    verdicts either side of each zone's limit (ILAC-G8:09/2019, T = 1", w = 0.2")."""
    from models.uncertainty.budget import coverage_factor
    from models.uncertainty.conformity import _verdict

    w = QT_TR_NOOP("Uncertainty and decision (all workbenches)")
    cases = [close_case(w, message(QT_TR_NOOP("coverage factor k for ν = {nu}"),
                           nu="∞" if math.isinf(nu) else nu), TABLE,
                    k, coverage_factor(nu, 0.9545), 0.005, unit="", digits=2)
             for nu, k in ((3, 3.31), (8, 2.37), (20, 2.13), (math.inf, 2.00))]
    for rule, x, expected in (("guarded", 0.79, "pass"), ("guarded", 0.81, "conditional pass"),
                              ("guarded", 1.01, "conditional fail"), ("guarded", 1.21, "fail"),
                              ("simple", 0.99, "pass"), ("simple", 1.01, "fail"),
                              ("guarded_binary", 0.81, "fail"), ("guarded_binary", 0.79, "pass")):
        got = _verdict(x, 1.0, 0.2, rule)
        cases.append(ValidationCase(w, message(QT_TR_NOOP("decision rule {rule}: {x}\" against "
                                                          "T = 1\", w = 0.2\""),
                                               rule=message(RULE_NAMES[rule]), x=f"{x:.2f}"),
                                    HAND_COMPUTED, VERDICT_WORDS[expected],
                                    VERDICT_WORDS.get(got, got), got == expected))
    return cases + decision_machinery_cases()


def decision_machinery_cases() -> list[ValidationCase]:
    """ILAC-G8 with an asymmetric interval (its upper half-width guards acceptance, its lower
    rejection), the probability of a false acceptance at the acceptance limit (JCGM 106: the
    normal tail beyond k = 2, 2.275 %), the statements refused (U incomplete, U ≥ T) and U
    rounded to two significant digits (GUM 7.2.6), each against a hand-computed answer."""
    from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
    from models.uncertainty.conformity import (
        _verdict,
        decide_conformity,
        gum_rounded,
        probability_conforming,
    )

    w = QT_TR_NOOP("Uncertainty and decision (all workbenches)")
    cases = []
    for x, expected in ((0.70, "pass"), (0.75, "conditional pass"), (1.05, "conditional fail"),
                        (1.11, "fail")):
        got = _verdict(x, 1.0, 0.3, "guarded", 0.1)
        cases.append(ValidationCase(w, message(QT_TR_NOOP(
            "asymmetric interval −0.1\"/+0.3\": {x}\" against T = 1\" (acceptance guarded by "
            "+0.3\", rejection by −0.1\")"), x=f"{x:.2f}"), HAND_COMPUTED,
            VERDICT_WORDS[expected], VERDICT_WORDS.get(got, got), got == expected))
    risk = 1.0 - probability_conforming(0.8, 0.2, 0.2, 1.0, 0.9545)
    cases.append(close_case(w, QT_TR_NOOP("probability of a false acceptance at T − U (U = 2u), %"),
                        HAND_COMPUTED, 2.275, 100 * risk, 0.001, unit="", digits=3))
    budget = UncertaintyBudget((BudgetComponent("u", "B", "normal", 0.1, 1.0, 1.0, math.inf),),
                               3, 0.9545)
    incomplete = decide_conformity([0.1, 0.2, -0.1], budget, 1.0, "guarded", "points",
                                   not_stated=(QT_TR_NOOP("Temperature"),))
    too_large = decide_conformity([0.1, 0.2, -0.1], budget, 0.15, "guarded", "points")
    for name, decided in ((QT_TR_NOOP("U incomplete (an input not stated): no statement of "
                                      "conformity"), incomplete),
                          (QT_TR_NOOP("U ≥ T: no statement of conformity"), too_large)):
        cases.append(ValidationCase(w, name, HAND_COMPUTED, QT_TR_NOOP("not assessed"),
                                    QT_TR_NOOP("not assessed") if not decided.stated else
                                    VERDICT_WORDS.get(decided.verdict, decided.verdict),
                                    not decided.stated and math.isfinite(decided.value)))
    # rounded up, as every printed U (issue 39)
    for u, printed in ((2.03, "2.1"), (0.0996, "0.10"), (3.54, "3.6"), (0.094, "0.094")):
        got = gum_rounded(0.0, u)[1]
        cases.append(ValidationCase(w, message(QT_TR_NOOP("U = {u}\" printed to two significant "
                                                          "digits"), u=f"{u:g}"),
                                    HAND_COMPUTED, printed, got, got == printed))
    return cases
