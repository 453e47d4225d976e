"""The names of the polygon budget's inputs that other modules test for, without the budget
(models.polygon.report) and its imports: the window's and the DCC's notes name them."""

from __future__ import annotations

from typing import Any

from models.messages import QT_TR_NOOP

__all__ = ["PYRAMIDAL_INPUT", "ROLL_INPUT", "SET_UP_INPUTS", "TILT_BOUND_INPUT",
           "is_set_up_input"]

PYRAMIDAL_INPUT = QT_TR_NOOP("Pyramidal correction (ψ, ω)")
TILT_BOUND_INPUT = QT_TR_NOOP("Pyramidal tilt, not identified (bound)")
ROLL_INPUT = QT_TR_NOOP("Autocollimator roll ρ (cross-talk ρ·(y − y_z))")
#: the inputs of the set-up's error, which the pyramidal correction estimates and removes:
#: the tilt fits', a tilt not identified (its bound: no correction), the autocollimator's
#: roll (its cross-talk ρ·(y − y_z), corrected when measured). The raw error is before that
#: correction: what the readings give, the set-up's error in it, so its U has none of them
#: (as the theodolite's raw error has no set-up model input, the fringe's as found no model)
SET_UP_INPUTS = (PYRAMIDAL_INPUT, TILT_BOUND_INPUT, ROLL_INPUT)


def is_set_up_input(component: Any) -> bool:
    """Whether a budget input (a BudgetComponent) is one of the set-up's error
    (:data:`SET_UP_INPUTS`)."""
    return getattr(component.name, "template", component.name) in SET_UP_INPUTS
