"""Assessment 73 L1: a tolerance stated in another unit is printed beside its conversion to
six significant digits with its trailing zeros kept ("±7.02979 µrad (1.45000″)" for
1.4499983″), so that a reader sees the converted figure for what it is; 0.8.21 printed
"(1.45″)", which read as exact or as the old three-digit figure.

The expected text is made here from the units' definitions (1 rad = 648000/π ″) and
decimal's formatting; nothing is taken from the code checked."""

from __future__ import annotations

import math
import re
from decimal import Decimal

import numpy as np
import pytest

from models.quantity import Quantity
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import decide_conformity

P = 0.9544997361036416
ARCSEC_PER = {"urad": 0.648 / math.pi, "mdeg": 3.6}
SYMBOL = {"urad": " µrad", "mdeg": " mdeg"}


def _six_with_zeros(value: float) -> str:
    """``value`` to six significant digits, trailing zeros kept (as a reader writes it)."""
    d = Decimal(repr(value))
    exponent = d.adjusted() - 5
    return str(d.quantize(Decimal(1).scaleb(exponent)))


@pytest.mark.parametrize(("number", "key"), [(7.02979, "urad"), (0.5555556, "mdeg"),
                                            (0.1388889, "mdeg"), (2.0, "urad"),
                                            (14.5, "urad")])
def test_the_converted_tolerance_keeps_six_significant_digits(number, key):
    budget = UncertaintyBudget((BudgetComponent("noise", "B", "normal", np.full(3, 0.05), 1.0,
                                                1.0, math.inf),), 3, P, "arcsec")
    c = decide_conformity(np.array([0.1, -0.2, 0.15]), budget, Quantity(number, key),
                          "guarded", "points")
    converted = _six_with_zeros(number * ARCSEC_PER[key])
    assert len(converted.replace(".", "").lstrip("0")) == 6
    typed = np.format_float_positional(number, trim="-") + SYMBOL[key]
    shown = re.findall(re.escape(typed) + r" \(([0-9.]+)\"\)", c.statement)
    assert shown and set(shown) == {converted}, c.statement
