"""The laboratory's scope: its smallest U for a quantity (its CMC) as a floor on every U.

A laboratory states on a certificate no U below its calibration and measurement capability
(ILAC-P14:09/2020, 5.4): a budget that gives less (a cross-calibrated polygon's 0.018″, say)
shows what these readings alone support, not what the laboratory can claim. Each workbench
declares the CMC as a setting per quantity (0: none stated, and then nothing is said); the
budget applies it (:attr:`UncertaintyBudget.floor`) to every point's U, the decided
quantity's interval (models.uncertainty.conformity) and the coverage intervals of the ISO
230-2 / VDI/DGQ 3441 figures (models.uncertainty.figure_intervals) are held to it by one
rule (:func:`held_to_cmc`), and the certificate names it with the points whose U and the
figures whose interval were raised to it. Such a result is within the scope, its
U stated as the CMC (ILAC-P14 5.4): "outside the scope" is reserved for what truly is (a
range the scope does not cover), which a CMC alone does not say.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import numpy as np

from models.messages import QT_TR_NOOP, listed, message, separated
from models.parameters import Parameter

if TYPE_CHECKING:  # a budget's module is loaded by whoever makes one (not a plain analyze)
    from models.uncertainty.budget import UncertaintyBudget

__all__ = ["CMC_NOT_STATED", "HeldToCmc", "cmc_of", "cmc_parameter", "cmc_quantity", "held_to_cmc",
           "scope_statement"]


#: each setting made by cmc_parameter → what it is the CMC of (the JSON's laboratory_cmc)
_QUANTITIES: dict[Parameter, str] = {}


def cmc_quantity(parameter: Parameter) -> str:
    """What ``parameter`` is the laboratory's CMC of ("axis error" …); "" when it is not a
    setting of :func:`cmc_parameter`."""
    return _QUANTITIES.get(parameter, "")


def cmc_parameter(key: str, label: str, unit: str, what: str) -> Parameter:
    """The setting of the laboratory's CMC for one quantity of a workbench (``what``: "the
    axis error", "a polygon's face deviations" …): a floor on every U stated, named on the
    certificate; 0: none stated, nothing said."""
    parameter = Parameter(key, label, "float", 0.0, unit, 0.0, 3600.0, decimals=4, step=0.01,
                     zero="none stated",
                     help="The laboratory's calibration and measurement capability (CMC) for "
                          f"{what}: the smallest U of its scope. Every U stated is at least this, "
                          "the decided quantity's interval included; a result whose computed U is "
                          "below it is stated with the CMC as its U (ILAC-P14). 0: none stated, "
                          "nothing said")
    _QUANTITIES[parameter] = what.removeprefix("the ").removeprefix("an ").removeprefix("a ")
    return parameter


def cmc_of(settings: Mapping[str, Any] | None, key: str) -> float:
    """The CMC the ``settings`` a result was analysed with state under ``key`` (a setting
    of :func:`cmc_parameter`): the budget's floor. The settings are passed to the budget,
    never copied into the result, so the CMC the certificate lists and the one its U is
    held to are one figure. 0: none stated (no settings: the default, none)."""
    return float((settings or {}).get(key, 0.0) or 0.0)


@dataclass(frozen=True)
class HeldToCmc:
    """An interval about ``value`` whose half-widths (``minus`` below the value, ``plus``
    above it) are held to the laboratory's CMC (:func:`held_to_cmc`); ``raised``: whether
    each (minus, plus) was below it and is now the CMC; None when no CMC is set or the
    interval is not determined (then nothing was changed)."""

    value: float
    minus: float
    plus: float
    raised: tuple[bool, bool] | None
    non_negative: bool = True

    @property
    def low(self) -> float:
        """The interval's lower end, value − minus; never below 0 for a quantity that cannot
        be negative (the coverage is not lowered by it)."""
        low = self.value - self.minus
        return max(low, 0.0) if self.non_negative else low

    @property
    def high(self) -> float:
        return self.value + self.plus


def held_to_cmc(value: float, minus: float, plus: float, cmc: float, *,
                non_negative: bool = True) -> HeldToCmc:
    """The interval value − ``minus`` … value + ``plus`` with each half-width raised to the
    laboratory's CMC ``cmc`` (ILAC-P14:09/2020 5.4: no U stated below it), and whether each
    was: the one rule for every interval a certificate states beside a CMC — the decided
    quantity's (a half range: models.uncertainty.conformity) and every ISO 230-2 / VDI/DGQ
    3441 figure's (E, M, B, B̄, R, A, P …: models.uncertainty.figure_intervals).

    The CMC is stated for the error at a point. The half range is the error at the curve's
    two extreme points about their mid-value, (e_max − e_min)/2; a figure is a range of
    points' errors (E, M, A, P), a largest one (B, U), a mean (B̄) or a scatter of readings
    at a point (R, Ps). Were the points' errors independent, a range's U would be √2 larger
    than theirs and a mean's smaller; but a CMC states only the smallest U the laboratory
    claims, not how its inputs correlate from point to point (a systematic part moves both
    extremes alike, a part that differs moves them apart) nor how they enter a scatter, so
    nothing below the CMC itself can be claimed for any of them, and nothing above it is
    implied: the interval computed stands where it is wider. Each half-width is held (the
    lower guards a fail, the upper a pass); the value is not moved (an interval wholly below
    a biased value keeps it inside: its upper half-width, negative, becomes the CMC), and a
    quantity that cannot be negative (``non_negative``) has its lower end at 0 at the
    lowest. The probability stated beside the interval is kept: the interval only grew, so
    it covers at least as often. Never narrows; applied again, changes nothing."""
    value, minus, plus, cmc = float(value), float(minus), float(plus), float(cmc)
    if not (cmc > 0 and math.isfinite(cmc) and math.isfinite(value) and math.isfinite(minus)
            and math.isfinite(plus)):
        return HeldToCmc(value, minus, plus, None, non_negative)
    raised = (minus < cmc, plus < cmc)
    return HeldToCmc(value, max(minus, cmc), max(plus, cmc), raised, non_negative)


#: an accredited calibration certificate whose CMC is not stated: its U was not compared with
#: the scope (assessment 76 L7)
CMC_NOT_STATED = QT_TR_NOOP(
    "No calibration and measurement capability (CMC) of the laboratory is stated for this "
    "quantity in the analysis settings, so the U stated here has not been compared with the "
    "CMC of its scope of accreditation (ILAC-P14:09/2020 5.4: no U smaller than the CMC is "
    "stated under accreditation).")


def scope_statement(budget: UncertaintyBudget, unit: str = "\"",
                    figures: Sequence[str] = (), accredited: bool = False) -> Any:
    """The certificate's statement of the laboratory's CMC, the points outside its scope and
    the ``figures`` (their names as printed) whose coverage interval was raised to it; where
    no CMC is stated, "" unless the certificate is an ``accredited`` calibration certificate,
    which then says that its U was not compared with the CMC (:data:`CMC_NOT_STATED`).

    An assessor reads "laboratory's CMC: none stated" under an accreditation mark as a U that
    may lie below the scope's (ILAC-P14 5.4): until 0.8.24 such a certificate printed it with
    no word (assessment 76 L7). The certificate is still issued — the CMC is the laboratory's
    to state, and the software cannot know it — but says what was not checked."""
    if not budget.points:
        return ""
    if not budget.floor > 0:
        return message(CMC_NOT_STATED) if accredited else ""
    below = budget.below_floor
    cmc = f"{budget.floor:g}{unit}"
    held = "" if not figures else message(QT_TR_NOOP(
        "The coverage interval of {figures} is held to it as well: each half-width these "
        "readings give below the CMC is stated as the CMC about the figure's value (the lower "
        "end not below 0 where the figure cannot be negative), with the probability printed "
        "beside it, which the wider interval covers at least."), figures=listed(figures))
    if not np.any(below):
        return separated([message(QT_TR_NOOP(
            "The laboratory's calibration and measurement capability (CMC) for this quantity is "
            "U = {cmc}; every U stated here is at or above it."), cmc=cmc), held], " ")
    lowest = float(np.min(budget.computed_expanded[below]))
    return separated([message(QT_TR_NOOP(
        "The laboratory's calibration and measurement capability (CMC) for this quantity is "
        "U = {cmc}. At {count} of the {points} points the U these readings give (down to "
        "{lowest}) is below it, so their U is stated as the CMC, with the same coverage factor "
        "k (ILAC-P14 5.4); there U/k is the CMC's standard uncertainty, not the budget's u_c."),
        cmc=cmc, count=int(np.count_nonzero(below)), points=budget.points,
        lowest=f"{lowest:.2g}{unit}"), held], " ")
