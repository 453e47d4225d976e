"""The laboratory's scope: its smallest U for a quantity (its CMC) as a floor on every U.

A laboratory states on a certificate no U below its calibration and measurement capability
(ILAC-P14:09/2020, 5.4): a budget that gives less (a cross-calibrated polygon's 0.018″, say)
shows what these readings alone support, not what the laboratory can claim. Each workbench
declares the CMC as a setting per quantity (0: none stated, and then nothing is said); the
budget applies it (:attr:`UncertaintyBudget.floor`) to every point's U, the decided
quantity's interval is held to it (models.uncertainty.conformity), and the certificate
names it with the points whose U was raised to it. Such a result is within the scope, its
U stated as the CMC (ILAC-P14 5.4): "outside the scope" is reserved for what truly is (a
range the scope does not cover), which a CMC alone does not say.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import TYPE_CHECKING, Any

import numpy as np

from models.messages import QT_TR_NOOP, message
from models.parameters import Parameter

if TYPE_CHECKING:  # a budget's module is loaded by whoever makes one (not a plain analyze)
    from models.uncertainty.budget import UncertaintyBudget

__all__ = ["cmc_of", "cmc_parameter", "cmc_quantity", "scope_statement"]


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


def scope_statement(budget: UncertaintyBudget, unit: str = "\"") -> str:
    """The certificate's statement of the laboratory's CMC and the points outside its scope
    ("" when no CMC is stated)."""
    if not budget.floor > 0 or not budget.points:
        return ""
    below = budget.below_floor
    cmc = f"{budget.floor:g}{unit}"
    if not np.any(below):
        return message(QT_TR_NOOP(
            "The laboratory's calibration and measurement capability (CMC) for this quantity is "
            "U = {cmc}; every U stated here is at or above it."), cmc=cmc)
    lowest = float(np.min(budget.computed_expanded[below]))
    return message(QT_TR_NOOP(
        "The laboratory's calibration and measurement capability (CMC) for this quantity is "
        "U = {cmc}. At {count} of the {points} points the U these readings give (down to "
        "{lowest}) is below it, so their U is stated as the CMC, with the same coverage factor "
        "k (ILAC-P14 5.4); there U/k is the CMC's standard uncertainty, not the budget's u_c."),
        cmc=cmc, count=int(np.count_nonzero(below)), points=budget.points,
        lowest=f"{lowest:.2g}{unit}")
