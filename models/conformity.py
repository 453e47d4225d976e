"""Statement of conformity with a tolerance ±T under a stated decision rule (ILAC-G8).

The quantity judged is the item's accuracy figure: half the peak-to-peak of
the corrected error curve (the ± band the curve fits in), with the expanded
uncertainty U of the curve's points as its uncertainty.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from models.certificate_metadata import DECISION_RULES

__all__ = ["Conformity", "decide_conformity", "significant_decimals", "uncertainty_decimals"]


def significant_decimals(expanded: float) -> int | None:
    """Decimals that show U with two significant digits (GUM 7.2.6); None if U is not
    a positive number."""
    if not math.isfinite(expanded) or expanded <= 0:
        return None
    return max(0, 1 - int(math.floor(math.log10(expanded))))


def uncertainty_decimals(expanded: float) -> int:
    """:func:`significant_decimals`, but never fewer than two (arcsec are printed to 0.01")."""
    decimals = significant_decimals(expanded)
    return 2 if decimals is None else max(2, decimals)


@dataclass(frozen=True)
class Conformity:
    verdict: str  # "conforms", "does not conform", "no statement", "not assessed"
    statement: str
    rule: str


def decide_conformity(half_range_arcsec: float, expanded_arcsec: float,
                      tolerance_arcsec: float | None, rule: str = "guarded",
                      valid: bool = True) -> Conformity:
    """Verdict on ``half_range_arcsec`` against ±``tolerance_arcsec`` under ``rule``."""
    rule_text = DECISION_RULES[rule]
    if not valid:
        return Conformity("not assessed", "No statement of conformity: the run is invalid "
                          "(closure failed).", rule_text)
    if tolerance_arcsec is None or not math.isfinite(half_range_arcsec):
        return Conformity("not assessed", "No statement of conformity: no tolerance was given.",
                          rule_text)
    x, u, t = half_range_arcsec, expanded_arcsec, tolerance_arcsec
    d = uncertainty_decimals(u)
    quantity = f"half the peak-to-peak corrected error, {x:.{d}f}\" (U = {u:.{d}f}\")"
    if rule == "simple":
        ok = x <= t
        verdict = "conforms" if ok else "does not conform"
        text = (f"The item {verdict} to ±{t:g}\": {quantity} is "
                f"{'within' if ok else 'outside'} the tolerance.")
        return Conformity(verdict, text, rule_text)
    if x + u <= t:
        return Conformity("conforms", f"The item conforms to ±{t:g}\": {quantity} plus U is "
                          "within the tolerance.", rule_text)
    if x - u > t:
        return Conformity("does not conform", f"The item does not conform to ±{t:g}\": "
                          f"{quantity} minus U is outside the tolerance.", rule_text)
    return Conformity("no statement", f"No statement of conformity to ±{t:g}\" can be made: "
                      f"{quantity} lies within U of the limit.", rule_text)
