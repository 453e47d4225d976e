"""Where the window points when the register refuses for a reason one of its recorded
recoveries answers (models/register/recoveries.py): to the register window's own action,
naming the command too — a technician at the bench needs no terminal."""

from __future__ import annotations

from models.register.recoveries import CLOCK, LOSS, recovery_answering
from widgets.i18n import tr

__all__ = ["recovery_pointer"]


def recovery_pointer(reason: str, in_register_window: bool = False) -> str:
    """The sentence that points from ``reason`` (a refusal, a finding of the register) to the
    window's recovery that answers it; "" when none does. ``in_register_window``: said in
    the register window itself, whose buttons are above the list (regwin74: it pointed to
    File › Certificate register, the window the user was in)."""
    answer = recovery_answering(reason)
    if in_register_window and answer == LOSS:
        return tr("To record the loss here: the button Acknowledge a loss… above the list "
                  "(the same as 'anglebench register acknowledge-loss').")
    if in_register_window and answer == CLOCK:
        return tr("If that record was dated by a clock set ahead and this computer's clock is "
                  "right, record it here: the button Clock correction… above the list (the "
                  "same as 'anglebench register clock-correction').")
    if answer == LOSS:
        return tr("To record the loss here: File › Certificate register, Acknowledge a loss… "
                  "(the same as 'anglebench register acknowledge-loss').")
    if answer == CLOCK:
        return tr("If that record was dated by a clock set ahead and this computer's clock is "
                  "right, record it here: File › Certificate register, Clock correction… (the "
                  "same as 'anglebench register clock-correction').")
    return ""
