"""What a tilt bound is said to be — at 0, unchecked by the readings, bounding the decided
half range, whose — in a module that imports nothing heavy: a plain analyze's summary and
settings use these words, and models.uncertainty.bounded_systematic_half_range (which loads
the budget and the half range's Monte Carlo) re-exports them."""

from __future__ import annotations

from models.messages import QT_TR_NOOP

__all__ = ["BOUND_UNCHECKED", "TILT_BOUNDED", "TILT_BOUNDED_DEFAULT", "TILT_BOUND_ZERO",
           "tilt_bound_origin"]

#: what a tilt bound of 0 is (the setting's field at 0, its range in the docs, the settings a
#: certificate lists): a tilt of nothing, which no set-up achieves, refused since 0.8.22
#: where the readings do not identify the tilt (the theodolite's, the polygon's and the
#: cross-calibration's setting; "none" read as "no bound")
TILT_BOUND_ZERO = QT_TR_NOOP("no tilt (refused where not identified)")

#: what a certificate says of a tilt bound whose effect enters U where the readings do not
#: identify the tilt, the words of the decisions below (the cross-calibration's set-up row)
BOUND_UNCHECKED = QT_TR_NOOP("the readings cannot check the bound (a larger tilt is not "
                             "covered)")

#: what the decision says of a tilt not identified that widens its interval, after how the
#: rest was made (the polygon's, and a theodolite's decided on the means over passes)
TILT_BOUNDED = QT_TR_NOOP(
    "the tilt, not identified and not removed, is one unknown error for the whole run, not "
    "noise: nothing is taken off the measured range for it; a tilt up to {bound} (stated) in "
    "any direction changes the half range by at most {change}, so the interval is widened by "
    "that at both ends and holds for any such tilt; the readings cannot check the bound (a "
    "larger tilt is not covered)")
#: the same where no bound was stated: the program's default, not the laboratory's figure
#: (audit 73 finding 3: it was printed "(stated)")
TILT_BOUNDED_DEFAULT = QT_TR_NOOP(
    "the tilt, not identified and not removed, is one unknown error for the whole run, not "
    "noise: nothing is taken off the measured range for it; a tilt up to {bound} (the "
    "program's default: no bound was stated) in any direction changes the half range by at "
    "most {change}, so the interval is widened by that at both ends and holds for any such "
    "tilt; the readings cannot check the bound (a larger tilt is not covered)")


def tilt_bound_origin(bound: float, default: float) -> str:
    """Whose a tilt bound is: "program default" where it is the workbench's ``default`` (the
    setting left as the program gives it), else "stated" (the laboratory's claim)."""
    return "program default" if bound == default else "stated"
