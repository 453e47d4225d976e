"""A figure in a message: fixed decimals as a reading is written, or scientific where that
would be a wall of digits (contract75 F13: an encoder cell of 1e308 was printed as a
309-digit number, ``f"{1e308:.4f}"``)."""

from __future__ import annotations

import math

__all__ = ["LARGEST_FIXED", "fixed"]

#: from this size on a figure is written in scientific form (no angle, deviation or reading
#: of the workbenches comes near it; only a mistyped or absurd cell does)
LARGEST_FIXED = 1e9


def fixed(value: float, decimals: int, sign: bool = False) -> str:
    """``value`` to ``decimals`` places (``+`` before a positive one with ``sign``), or in
    scientific form to 6 significant digits when it is LARGEST_FIXED or more (or not
    finite)."""
    plus = "+" if sign else ""
    if not math.isfinite(value) or abs(value) >= LARGEST_FIXED:
        return f"{value:{plus}.6g}"
    return f"{value:{plus}.{decimals}f}"
