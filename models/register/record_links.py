"""What links a certificate's record to others, in words: the certificate it amends or
replaces and the one that superseded it, its withdrawal, the withdrawn certificates it was
issued in place of, those it is a separate calibration from, and those whose readings it
holds (another item's, or its own calibration's said why).

`register show` and the PDF/DCC said them; the register window and the register's export
listed none (hostile78's links: "Issued in place of withdrawn N", readings of another item).
One wording for both, from what the record holds: its columns and the details recorded in
its project state (in the chain)."""

from __future__ import annotations

import json
from collections.abc import Iterable
from typing import Any

from models.messages import QT_TR_NOOP, Message, message

__all__ = ["record_links"]


def _details(record: Any) -> dict:
    """The certificate details recorded with ``record`` (its project state); {} when none."""
    try:
        data = json.loads(record.project_json or "{}")
        details = data["metadata"]["certificates"][record.workbench]
    except (TypeError, ValueError, KeyError, AttributeError):
        return {}
    return details if isinstance(details, dict) else {}


def _text(details: dict, key: str) -> str:
    value = details.get(key, "")
    return " ".join(value.split()) if isinstance(value, str) else ""


def record_links(record: Any, same_readings: Iterable[str] = ()) -> tuple[Message, ...]:
    """``record``'s links to other certificates (a
    :class:`models.register.store.CertificateRecord`), each a message, in this order: what
    it corrects, what superseded it or why it was withdrawn, what it was issued in place
    of, what it is separate from, whose readings it holds. ``same_readings``: the numbers
    whose readings and details it holds, said why at issue (the register's chained
    entries: Register.same_readings_confirmations)."""
    details = _details(record)
    out: list[Message] = []
    if record.supersedes:
        out.append(message(QT_TR_NOOP("replaces {number}") if record.revision == "replacement"
                           else QT_TR_NOOP("amends {number}"), number=record.supersedes))
    if record.superseded_by:
        out.append(message(QT_TR_NOOP("superseded by {number}"),
                           number=record.superseded_by))
    if record.status == "withdrawn":
        out.append(message(QT_TR_NOOP("withdrawn: {reason}"),
                           reason=record.withdrawn_reason or "—"))
    withdrawn = _text(details, "replaces_withdrawn")
    if withdrawn:
        out.append(message(QT_TR_NOOP("issued in place of withdrawn {numbers}"),
                           numbers=withdrawn))
    separate = _text(details, "separate_from")
    if separate:
        out.append(message(QT_TR_NOOP("separate calibration from {numbers}"),
                           numbers=separate))
    another = _text(details, "readings_of_another_item")
    if another:
        out.append(message(QT_TR_NOOP("readings of another item's {numbers}"),
                           numbers=another))
    same = ", ".join(n for n in same_readings if n)
    if same:
        out.append(message(QT_TR_NOOP("readings and details of {numbers}, said why"),
                           numbers=same))
    return tuple(out)
