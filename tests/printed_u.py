"""A U as a certificate prints it beside its figure (issue 39), worked out here from its
definition with decimals, for tests that read printed tables: U to two significant digits
(GUM 7.2.6), the figure to the same decimal, rounded to the nearest; U the smallest figure
on that grid that is at least U rounded up and with which the printed figure ± U reaches
the computed interval [value − U, value + U] (each end rounded outward)."""

from __future__ import annotations

import math
from decimal import ROUND_CEILING, ROUND_FLOOR, ROUND_HALF_EVEN, Decimal


def two_significant(u: float) -> int:
    """Decimals that show u with two significant digits after rounding it up (0.994 is
    1.0), never negative."""
    d = 1 - math.floor(math.log10(u))
    if _grid(u, d, ROUND_CEILING) >= Decimal(10) ** (2 - d):
        d -= 1
    return max(0, d)


def _grid(x: float, d: int, how) -> Decimal:
    step = Decimal(1).scaleb(-d)
    exact = Decimal(x)
    near = exact.quantize(step, ROUND_HALF_EVEN)
    if abs(exact - near) < Decimal("1e-9") * step:  # on the grid but for binary noise
        return near
    return exact.quantize(step, how)


def u_beside(value: float, u: float) -> str:
    """The U printed beside ``value`` (its text, to the figure's decimal)."""
    d = two_significant(u)
    shown = Decimal(value).quantize(Decimal(1).scaleb(-d), ROUND_HALF_EVEN)
    plus = _grid(value + u, d, ROUND_CEILING) - shown
    minus = shown - _grid(value - u, d, ROUND_FLOOR)
    return f"{max(_grid(u, d, ROUND_CEILING), plus, minus):.{d}f}"
