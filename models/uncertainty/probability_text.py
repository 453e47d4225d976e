"""A coverage probability as a certificate prints it, in percent: to the digits it was
asked or reached with and no more (day review 66 F8: "92.00 %" and "93.50 %" of studies of
60–80 runs, whose probabilities are multiples of 0.5 %, overstated their precision)."""

from __future__ import annotations

__all__ = ["percent_text"]


def percent_text(probability: float) -> str:
    """``probability`` (0…1) in percent, without the sign, to at most two decimals and
    without trailing zeros: 0.92 → "92", 0.935 → "93.5", 0.9545 → "95.45"."""
    return f"{100.0 * probability:.2f}".rstrip("0").rstrip(".")
