"""The register's two recorded recoveries, which the command line and the register window
both offer: a loss acknowledged (``anglebench register acknowledge-loss``,
:meth:`Register.acknowledge_loss`: an older copy restored or replayed, the numbers issued
since moved past, so issuing resumes) and a clock correction (``anglebench register
clock-correction``, :meth:`Register.correct_clock`: the last record dated by a clock set
ahead, so right clocks issue again). Here: what each says once recorded, and which refusal
of an issue each answers (the window's "Not issued" then points to its own action and
names the command)."""

from __future__ import annotations

from models.messages import QT_TR_NOOP, Message, message
from models.register.clock_rules import BEFORE_LAST
from models.register.store import LOSS_FINDINGS
from models.register.wording import recorded_words

__all__ = ["CLOCK", "CLOCK_CORRECTED", "LOSS", "LOSS_RECORDED", "clock_corrected",
           "loss_recorded", "numbers_lost", "recovery_answering"]

#: the recovery that answers a refusal: a loss to acknowledge, a clock to correct
LOSS, CLOCK = "loss", "clock"

LOSS_RECORDED = QT_TR_NOOP(
    "loss recorded by {by} ({reason}); counters moved: {moved}; issuing resumes; chain head "
    "now {head}")
CLOCK_CORRECTED = QT_TR_NOOP(
    "clock correction recorded by {by} ({reason}): {ahead}, dated {at}, was dated by a clock "
    "set ahead; issuing resumes on this clock ({date})")


def loss_recorded(body: dict, head: str) -> Message:
    """What a loss acknowledged says (``body``: :meth:`Register.acknowledge_loss`'s; ``head``:
    the register's chain head after it): who, why, each counter moved."""
    moved = ", ".join(f"{name} {before} → {after}"
                      for name, (before, after) in body["counters"].items())
    return message(LOSS_RECORDED, by=body["by"], reason=body["reason"],
                   moved=moved or message(QT_TR_NOOP("none")), head=head)


def clock_corrected(body: dict) -> Message:
    """What a clock correction says (``body``: :meth:`Register.correct_clock`'s)."""
    return message(CLOCK_CORRECTED, by=body["by"], reason=body["reason"],
                   ahead=recorded_words(body["ahead"]),
                   at=body["ahead_at"], date=body["confirmed_date"])


def recovery_answering(reason: str) -> str:
    """Which recovery answers a refusal (``reason``: the Message an issue was refused with,
    a finding inside it included): :data:`LOSS`, :data:`CLOCK`, or "" for none (plain text,
    or a refusal no recovery answers: a record rewritten, a broken chain …)."""
    found: list[str] = []

    def visit(text) -> None:
        if not isinstance(text, Message):
            return
        found.append(text.template)
        for part in (*text.parts, *text.figures.values()):
            visit(part)

    visit(reason)
    if BEFORE_LAST in found:
        return CLOCK
    if any(template in LOSS_FINDINGS for template in found):
        return LOSS
    return ""


#: at most this many numbers lost are named one by one; more are named as a range
_NAMED_ONE_BY_ONE = 6


def numbers_lost(body: dict, numbers: list[str]) -> list[str]:
    """The certificate numbers a loss acknowledged (``body``: its entry's) says were issued
    and lost: each counter's values between where it stood and where the loss moved it,
    written as the register's numbers of that counter are (their digits, from ``numbers``:
    the register's numbers and the loss's own last number). A counter whose numbers' width
    is unknown is said by its name and values ("AB-2026-# 3–4"); more than a few numbers of
    a counter as a range (day74 #7 d)."""
    import re

    known = [n for n in [*numbers, str(body.get("last_issued") or "")] if n]
    said: list[str] = []
    for name, moved in dict(body.get("counters") or {}).items():
        before, after = int(moved[0]), int(moved[1])
        if after <= before:
            continue
        if name.count("#") != 1:
            said.append(f"{name} {before + 1}–{after}")
            continue
        head, tail = name.split("#")
        widths = [len(found.group(1)) for n in known if (found := re.fullmatch(
            re.escape(head) + r"(\d+)" + re.escape(tail), n))]
        if not widths:
            said.append(f"{name} {before + 1}–{after}" if after > before + 1
                        else f"{name} {after}")
            continue
        width = max(widths)
        values = range(before + 1, after + 1)
        if len(values) > _NAMED_ONE_BY_ONE:
            said.append(f"{head}{before + 1:0{width}d}{tail} – {head}{after:0{width}d}{tail}")
        else:
            said += [f"{head}{value:0{width}d}{tail}" for value in values]
    return said
