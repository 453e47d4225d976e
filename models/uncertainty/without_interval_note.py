"""The note on figures printed with no coverage interval at all (a target or θ read once, its
readings alike, or entered coarser than they scatter): why, and the place every figure is
then printed rounded to (models.uncertainty.rounding.without_interval_decimals) with what set
it — the readings' pooled scatter, the step they were entered in, or neither known. One text
for the positioning and theodolite workbenches, on the certificate, the command line's
summary and the window alike (leftovers 80: the theodolite summary said "No coverage
intervals: …" and nothing of the place its figures were rounded to)."""

from __future__ import annotations

import math

from models.messages import QT_TR_NOOP, Message, message
from models.uncertainty.rounding import fixed_places, without_interval_decimals

__all__ = ["FIGURES_WITHOUT_INTERVAL_NOTE", "figures_without_interval_note", "place_basis",
           "rounding_place"]

FIGURES_WITHOUT_INTERVAL_NOTE = QT_TR_NOOP(
    "No coverage interval is given for the figures: {reason}. {basis}")

#: what set the place, by :func:`place_basis`
_BASES = {
    "scatter": QT_TR_NOOP(
        "Each figure is printed rounded to {place}, the first significant place of the "
        "readings' pooled standard deviation ({s}): without an interval nothing says it is "
        "known more closely."),
    # a theodolite run of one pass each way: no scatter over the passes; the vertical
    # readings' about the set-up fit, each reading's pointing noise
    "fit": QT_TR_NOOP(
        "Each figure is printed rounded to {place}, the first significant place of the "
        "readings' scatter about the set-up fit ({s}; one pass gives no scatter over the "
        "passes): without an interval nothing says it is known more closely."),
    "step": QT_TR_NOOP(
        "Each figure is printed rounded to {place}, the last place of the step the readings "
        "were entered in ({step}): without an interval nothing says it is known more "
        "closely."),
    "neither": QT_TR_NOOP(
        "Each figure is printed rounded to {place}: the readings show neither their scatter "
        "nor the step they were entered in, and without an interval nothing says how "
        "closely it is known."),
}


def rounding_place(decimals: int, symbol: str) -> str:
    """The place a figure printed to ``decimals`` is rounded to, with its unit: "10″" for
    −1, "1″" for 0, "0.01″" for 2."""
    return f"{fixed_places(10.0 ** -decimals, max(decimals, 0))}{symbol}"


def place_basis(scatter: float, step: float | None) -> str:
    """What sets the place :func:`without_interval_decimals` gives: "scatter" where the
    pooled s's first significant place does, "step" where the readings' step is coarser or
    s is unknown, "neither" where both are unknown (three decimals)."""
    with_s = (without_interval_decimals(scatter, None)
              if math.isfinite(scatter) and scatter > 0 else None)
    if with_s is not None and with_s == without_interval_decimals(scatter, step):
        return "scatter"
    if step is not None and math.isfinite(step) and step > 0:
        return "step"
    return "neither"


def figures_without_interval_note(reason: Message | str, scatter: float, step: float | None,
                                  symbol: str, about_fit: bool = False) -> Message:
    """The note for figures that have no interval at all: ``reason`` why, and the place they
    are printed to (from the readings' pooled ``scatter`` and their ``step``, in the unit
    ``symbol``) and what set it; ``about_fit``: the scatter is the readings' about a fit, not
    over repeated runs (models.theodolite.figures.figures_scatter)."""
    decimals = without_interval_decimals(scatter, step)
    basis = place_basis(scatter, step)
    said = "fit" if basis == "scatter" and about_fit else basis
    return message(FIGURES_WITHOUT_INTERVAL_NOTE, reason=reason, basis=message(
        _BASES[said], place=rounding_place(decimals, symbol),
        s=f"{scatter:.2g}{symbol}" if basis == "scatter" else "",
        step=f"{step:g}{symbol}" if basis == "step" else ""))
