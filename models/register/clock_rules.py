"""The register's rules for the computer's clock at issue (reg73 #6, #8).

A register cannot tell a right clock from a wrong one; it can only compare the time of an
issue with its own records. Two rules follow:

* **set back**: an issue timed before the register's last chained record — of any kind: a
  certificate, a withdrawal, a results file, a clock correction … (reg73 #8: only the last
  certificate was compared) — is refused, naming that record, its workstation and user. When
  that record was dated by a clock that was *ahead* (the year typed wrong) the right clock is
  refused too; a person then records ``anglebench register clock-correction`` (who, why,
  today's date confirmed): a chained entry timed by the right clock, after which right clocks
  issue again. The future-dated record stays in the chain as issued, the correction after it.
* **far after**: an issue dated more than :data:`CONFIRM_AFTER_DAYS` days after the last
  chained record is issued only when the person confirms today's date (``--confirm-date
  YYYY-MM-DD``; the window asks, showing the date): a clock a year ahead is then seen by the
  person before anything is dated by it, and a lab that issues once a year needs no setting
  (reg73 #6: ``ANGLEBENCH_REGISTER_MAX_DAYS`` had to be set for a yearly lab, and a clock a
  year ahead a minute after the last issue was accepted). The confirmation is recorded in
  the chain with the certificate (an entry ``date_confirmed``).

Beside them, dates of issue never go backwards against the numbers (:func:`date_backwards`:
the lab's time zone changed between two issues).
"""

from __future__ import annotations

import datetime as dt
from dataclasses import dataclass

from models.messages import QT_TR_NOOP, Message, message
from models.register.register_error import RegisterError
from models.register.wording import chained_words

__all__ = ["BEFORE_LAST", "CONFIRM_AFTER_DAYS", "DateToConfirm", "LastChained", "clock_checked",
           "correction_refusal", "date_backwards", "last_certificate_since_correction",
           "last_chained", "parse_confirmed_date"]

#: an issue timed before the register's last chained record: the clock set back, or that
#: record dated by a clock set ahead (then a clock correction answers it)
BEFORE_LAST = QT_TR_NOOP(
    "the computer's clock says {now}, before the register's last record ({what}, "
    "{then}, on {workstation} by {user}): either this clock was set back — correct "
    "it — or that record was dated by a clock set ahead; then, with this clock "
    "right, record it with 'anglebench register clock-correction --by NAME --reason "
    "TEXT --confirm-date {today}'. Nothing is issued until then")
#: an issue dated more than this many days after the register's last chained record asks
#: the person to confirm today's date (a lab that issues weekly is not asked; a clock a
#: month or a year ahead is seen before it dates a certificate)
CONFIRM_AFTER_DAYS = 30


@dataclass(frozen=True)
class LastChained:
    """The register's last chained record (the highest place): a certificate or an entry."""

    seq: int
    at: dt.datetime  # its time (UTC)
    what: str  # in words: "certificate AB-2026-0001", "a clock correction" … (chained_words)
    workstation: str
    os_user: str
    # as the chain records it where an entry names it (a date confirmed's "last", a clock
    # correction's subject): its number, or "entry KIND SUBJECT", the form kept since 0.8.22
    recorded: str = ""


class DateToConfirm(RegisterError):
    """The issue is dated far after the register's last record: issued only when the person
    confirms ``date`` (the lab's local date the computer's clock gives) as today's."""

    def __init__(self, text, date: dt.date, days: int, last: LastChained) -> None:
        super().__init__(text)
        self.date, self.days, self.last = date, days, last


def last_chained(conn, sa, schema) -> LastChained | None:
    """The record or entry at the highest place of the chain, None in an empty register."""
    c, e = schema.CERTIFICATES.c, schema.ENTRIES.c
    cert = conn.execute(sa.select(c.seq, c.issued_at, c.number, c.workstation, c.os_user)
                        .where(c.seq.is_not(None)).order_by(c.seq.desc()).limit(1)).first()
    entry = conn.execute(sa.select(e.seq, e.recorded_at, e.kind, e.subject, e.workstation,
                                   e.os_user).order_by(e.seq.desc()).limit(1)).first()
    # each named in words, as the messages say it (day 74 finding 8: "entry
    # loss_acknowledged —", the database's kind and an empty subject)
    if entry is not None and (cert is None or entry.seq > cert.seq):
        return LastChained(entry.seq, _parse_time(entry.recorded_at),
                           chained_words(kind=entry.kind, subject=entry.subject),
                           entry.workstation or "?", entry.os_user or "?",
                           f"entry {entry.kind} {entry.subject}")
    if cert is not None:
        return LastChained(cert.seq, _parse_time(cert.issued_at), chained_words(cert.number),
                           cert.workstation or "?", cert.os_user or "?", cert.number)
    return None


def last_certificate_since_correction(conn, sa, schema):
    """The last certificate (its number, times, date of issue, workstation) chained after the
    register's last clock correction, or None: the one an issue's date is compared with so
    that dates of issue do not go backwards (reg72 #10), a record dated by a clock set ahead
    and corrected since aside."""
    c, e = schema.CERTIFICATES.c, schema.ENTRIES.c
    corrected = conn.execute(sa.select(sa.func.max(e.seq)).where(
        e.kind == "clock_correction")).scalar_one_or_none() or 0
    return conn.execute(sa.select(c.issued_at, c.number, c.workstation, c.issue_date)
                        .where(c.seq > corrected).order_by(c.seq.desc()).limit(1)).first()


def parse_confirmed_date(text: str) -> dt.date | None:
    """``--confirm-date``'s value: None when not given; RegisterError when not YYYY-MM-DD."""
    text = (text or "").strip()
    if not text:
        return None
    try:
        return dt.date.fromisoformat(text)
    except ValueError:
        raise RegisterError(message(QT_TR_NOOP(
            "--confirm-date {date}: not a date YYYY-MM-DD"), date=text)) from None


def clock_checked(last: LastChained | None, now: dt.datetime, issue_date: dt.date,
                  confirmed: dt.date | None) -> dict | None:
    """The clock rules for an issue at ``now`` dated ``issue_date`` (the lab's local date):
    RegisterError when the clock is before the last chained record; :class:`DateToConfirm`
    when the issue is far after it and ``confirmed`` is not given; RegisterError when the
    date confirmed is not the computer's. Returns what is recorded of a confirmation (the
    body of a ``date_confirmed`` entry), None when none was needed."""
    if last is None:
        return None
    if last.at > now:
        raise RegisterError(message(
            BEFORE_LAST, now=now.isoformat(), what=last.what, then=last.at.isoformat(),
            workstation=last.workstation, user=last.os_user, today=issue_date.isoformat()))
    days = (now - last.at).days
    if days <= CONFIRM_AFTER_DAYS:
        return None
    if confirmed is None:
        raise DateToConfirm(message(QT_TR_NOOP(
            "this certificate would be dated {date}, {days} days after the register's last "
            "record ({what}, {then}): a clock set ahead would date it wrongly, and refuse "
            "every issue on a right clock until then. If today is {date}, confirm it "
            "(on the command line: --confirm-date {date}); else correct the computer's "
            "clock"), date=issue_date.isoformat(), days=days, what=last.what,
            then=last.at.date().isoformat()), issue_date, days, last)
    if confirmed != issue_date:
        raise RegisterError(message(QT_TR_NOOP(
            "today was confirmed as {confirmed}, but the computer's clock gives {date}: "
            "nothing is issued until the clock is right"),
            confirmed=confirmed.isoformat(), date=issue_date.isoformat()))
    return {"date": issue_date.isoformat(), "days_after_last": days, "last": last.recorded,
            "last_at": last.at.isoformat()}


def correction_refusal(last: LastChained | None, now: dt.datetime, today: dt.date,
                       confirmed: dt.date | None):
    """Why a clock correction is not recorded now (a Message), None when it is: the last
    chained record must be dated after the computer's clock, and today's date confirmed."""
    if last is None:
        return message(QT_TR_NOOP(
            "nothing to correct: the register holds no record yet; a clock correction records "
            "that a record was dated by a clock set ahead"))
    if last.at <= now:
        return message(QT_TR_NOOP(
            "nothing to correct: the register's last record ({what}) is not dated after the "
            "computer's clock ({now}); a clock correction records that a record was dated by "
            "a clock set ahead"), what=last.what, now=now.isoformat())
    if confirmed != today:
        return message(QT_TR_NOOP(
            "a clock correction is recorded with today's date confirmed (--confirm-date "
            "{date}: the computer's date now); correct the clock first if it is not today"),
            date=today.isoformat())
    return None


def date_backwards(last, issue_date: dt.date, now: dt.datetime, zone: dt.tzinfo) -> Message:
    """Why a certificate dated ``issue_date`` is not issued after ``last``, dated later
    (:func:`last_certificate_since_correction`): the lab's time zone of this call, ``zone``,
    is another than that of the last issue (``ANGLEBENCH_TIMEZONE`` per call, the window's
    setting changed), and the dates of issue would go backwards against the numbers (reg72
    #10: AB-2026-0001 dated 2026-12-07, AB-2026-0002 dated 2026-12-06). Refused rather than
    dated otherwise: the date printed is the lab's local date of issue, and no other date is
    right for this call; the refusal ends when the lab's date reaches the last one (a day at
    most)."""
    offset = now.astimezone(zone).strftime("%z")
    from_then = dt.datetime.combine(dt.date.fromisoformat(last.issue_date), dt.time(), zone)
    return message(QT_TR_NOOP(
        "this certificate would be dated {date} in the lab's time zone of this issue, "
        "{zone} (UTC{offset}), before the register's last certificate, {number}, dated "
        "{then} (issued {at}; the zone it was dated in is not recorded): the dates of "
        "issue would go backwards against the numbers. The lab's time zone changed "
        "between the two issues (ANGLEBENCH_TIMEZONE, or the window's setting): issue "
        "in the zone the lab dates its certificates in, or in this zone from {resumes} "
        "on"),
        date=issue_date.isoformat(), zone=str(zone), offset=f"{offset[:3]}:{offset[3:]}",
        number=last.number, then=last.issue_date, at=last.issued_at,
        resumes=from_then.isoformat())


def _parse_time(text: str) -> dt.datetime:
    """A recorded ISO time, UTC where it names no zone (the earliest time where unreadable)."""
    try:
        stamp = dt.datetime.fromisoformat(text)
    except ValueError:
        return dt.datetime.min.replace(tzinfo=dt.timezone.utc)
    return stamp if stamp.tzinfo else stamp.replace(tzinfo=dt.timezone.utc)
