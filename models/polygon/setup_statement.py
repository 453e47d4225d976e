"""How a polygon run's set-up was assumed and how a technician tells which one the bench is
(the certificate's, the summary's and the window's words), apart from the certificate's
builder so that a plain analysis does not load it."""

from __future__ import annotations

from models.messages import QT_TR_NOOP, message, separated
from models.polygon.model import PolygonResult

__all__ = ["setup_statement"]


def setup_statement(result: PolygonResult) -> str:
    """Which set-up the correction assumed, and how a technician tells which one the bench
    is, in words (certificate, summary, window)."""
    if result.ac_alignment == "levelled":
        frame = message(QT_TR_NOOP(
            "Set-up assumed: autocollimator and rotary axis levelled (the autocollimator's "
            "vertical along the shaft); the pyramidal correction is that set-up's, by exact 3-D "
            "rotation: the polygon's own term plus the autocollimator's roll times the vertical "
            "reading's change."))
    else:
        frame = message(QT_TR_NOOP(
            "Set-up assumed: the autocollimator's vertical along the polygon's axis, rolled "
            "with its tilt, not along the shaft (the frame of Tian et al. 2015); the pyramidal "
            "correction is that paper's eqs 3–7."))
    if result.roll_corrected:
        roll = message(QT_TR_NOOP("Autocollimator roll measured {roll} (u = {u}) and corrected."),
                       roll=f"{result.ac_roll_measured_arcmin:+g}′",
                       u=f"{result.u_ac_roll_arcmin:g}′")
    else:
        roll = message(QT_TR_NOOP("Autocollimator roll not measured: up to ±{roll}, not "
                                  "corrected, in the uncertainty."),
                       roll=f"{result.ac_roll_arcmin:g}′")
    tell = message(QT_TR_NOOP(
        "To tell which set-up a bench is: tip a mirror on the shaft (or the polygon on its "
        "seat) about a horizontal axis so that the vertical reading changes by Δy, and watch "
        "the horizontal reading: on a levelled bench "
        "it moves by less than the roll bound times Δy; if it moves more, measure that ratio "
        "(the roll) and enter it."))
    # sentence after sentence through the join a translation punctuates (Chinese: none after
    # "。"; a plain " " left "。 " between its sentences, cert77)
    return separated((frame, roll, tell), " ")
