"""What the compensated error and the correction table hold where orders not fitted fold into
fitted ones at the sampled phases (models.fringe.folded_orders; day review 68 F8).

At the sampled phases the compensated error is the readings' own (atan2 of the samples
against θ, less the model's correction there, where the folded model matches the signals);
between them the correction table is the model's, whose folded amplitudes are not the
signals' harmonics, so what the table leaves there is not determined (the same reason the
half range over the whole period is withheld). The figure at the samples is kept, and the
window's line, the summary, the table export and the certificate say where it holds."""

from __future__ import annotations

from models.fringe.result import FringeResult
from models.messages import QT_TR_NOOP, message, separated

__all__ = ["COMPENSATION_AT_SAMPLES", "FOUND_AT_SAMPLES", "compensation_caveat"]

#: where the compensated error and the table hold, where orders fold
COMPENSATION_AT_SAMPLES = QT_TR_NOOP(
    "at the sampled phases only: between them the correction table is built from fitted "
    "orders that hold orders not fitted ({folds}), and the error it leaves there is not "
    "determined")

#: where the error as found holds, where orders fold: the readings' own at the samples, its
#: peak-to-peak the sampled phases' (day review 69 F1: 0.497″ at the 8 phases of a head whose
#: whole period holds 0.671″, printed with no note beside the qualified after side)
FOUND_AT_SAMPLES = QT_TR_NOOP(
    "at the sampled phases only: the error between them is not determined")


def compensation_caveat(result: FringeResult) -> str:
    """Where orders fold into fitted ones, what the compensated error and the correction
    table hold (:data:`COMPENSATION_AT_SAMPLES`); "" when none folds."""
    folds = getattr(result, "folded_orders", ())
    if not folds:
        return ""
    return message(COMPENSATION_AT_SAMPLES, folds=separated(
        [message(QT_TR_NOOP("order {order} into order {into}"), order=order, into=into)
         for order, into in folds], ", "))
