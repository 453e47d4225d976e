"""A date of calibration set before the readings were taken, across a standard's due date.

The instruments' sessions behind captured readings (models/capture/raw_record.py) carry when
they started (``started_utc``); the date of calibration is typed. Typed before the first
reading was taken, it can move the calibration to before a standard's calibration was due,
and a test report (the standard expired: no traceability) then prints as a calibration
certificate (hostile78 F5). Refused where it does: the date typed is before the day of the
first take (a day's grace for the time zones) and a standard's due date lies between them.
"""

from __future__ import annotations

import datetime as dt
from collections.abc import Iterable
from typing import Any

from models.certificate.metadata import CertificateMetadata
from models.messages import QT_TR_NOOP, Message, message

__all__ = ["first_capture_date", "dated_before_capture_past_due"]


def first_capture_date(sessions: Iterable[dict[str, Any]] | None) -> dt.date | None:
    """The UTC date the first session with a take started; None when no session with a take
    says when it started (the command line's capture record does not)."""
    dates = []
    for session in sessions or ():
        if not isinstance(session, dict) or not session.get("takes"):
            continue
        try:
            started = dt.datetime.fromisoformat(str(session.get("started_utc") or ""))
        except ValueError:
            continue
        if started.tzinfo is not None:
            started = started.astimezone(dt.timezone.utc)
        dates.append(started.date())
    return min(dates) if dates else None


def dated_before_capture_past_due(meta: CertificateMetadata,
                                  sessions: Iterable[dict[str, Any]] | None) -> Message | None:
    """Why ``meta``'s date of calibration may not stand (above), or None."""
    first = first_capture_date(sessions)
    try:
        calibrated = dt.date.fromisoformat(meta.calibration_date)
    except (TypeError, ValueError):
        return None
    if first is None or calibrated >= first - dt.timedelta(days=1):
        return None
    for standard in meta.standards:
        try:
            due = dt.date.fromisoformat(standard.due_date)
        except (TypeError, ValueError):
            continue
        if calibrated <= due < first:
            return message(QT_TR_NOOP(
                "the date of calibration {calibrated} is before the readings were taken: the "
                "instruments' sessions behind the captured readings started on {first}, after "
                "the calibration of {standard} was due ({due}); dated so, a standard that had "
                "expired would read as in date. Type the date the readings were taken"),
                calibrated=calibrated.isoformat(), first=first.isoformat(),
                standard=standard.description or standard.certificate_no or "—",
                due=due.isoformat())
    return None
