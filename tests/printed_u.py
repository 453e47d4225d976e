"""A U as a certificate prints it beside its figure (issue 39, assessment 72 H1), worked out
here from its definition with decimals, for tests that read printed tables: U rounded up to
two significant digits (GUM 7.2.6), the figure to the same decimal, rounded to the nearest;
the same U as the JSON's rounded up, whatever the figure beside it (until 0.8.20 one digit
more where the rounded figure ± U fell short of the computed interval's end)."""

from __future__ import annotations

import math
from decimal import ROUND_CEILING, ROUND_HALF_EVEN, Decimal


def two_significant(u: float) -> int:
    """Decimals that show u with two significant digits after rounding it up (0.994 is
    1.0); negative from 100 on (168 is 170, to the tens: assessment 76 M1)."""
    d = 1 - math.floor(math.log10(u))
    if _grid(u, d, ROUND_CEILING) >= Decimal(10) ** (2 - d):
        d -= 1
    return d


def _grid(x: float, d: int, how) -> Decimal:
    step = Decimal(1).scaleb(-d)
    exact = Decimal(x)
    near = exact.quantize(step, ROUND_HALF_EVEN)
    if abs(exact - near) < Decimal("1e-9") * step:  # on the grid but for binary noise
        return near
    return exact.quantize(step, how)


def u_beside(value: float, u: float) -> str:
    """The U printed beside ``value`` (its text, to U's decimal): U rounded up, the same
    beside any value."""
    d = two_significant(u)
    return f"{_grid(u, d, ROUND_CEILING):.{max(0, d)}f}"
