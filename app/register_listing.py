"""``anglebench register list``: the register's certificates as a lab clerk reads them —
number, date of issue, workbench and document, customer, serial number, manufacturer and
state (issued, withdrawn, amended or replaced, and by which) — in columns aligned on a
terminal (a Chinese character two columns wide), under a header, in the language asked; or, with ``--json``,
the same records with the register's own English keys and words for scripts.

(stop 63: it printed number, status, document kind, date, workbench, serial and customer
separated by tabs, without a header: the third column read "not recorded" or "Calibration
certificate" with nothing to say what it was, and an amended certificate read
"superseded". Stop 67: no manufacturer, though a serial is unique only within its maker
and the calibration interval and due date are per serial and maker: Acme's "001" and
Zeta's "001" read as one item.)
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from app.command_line import display_width
from models.messages import QT_TR_NOOP, message, rendered
from models.register.wording import kind_words

__all__ = ["HEADERS", "listing_json", "listing_lines", "state_of"]

#: the columns' headers, in their order
HEADERS = (QT_TR_NOOP("Number"), QT_TR_NOOP("Date of issue"),
           QT_TR_NOOP("Workbench / document"), QT_TR_NOOP("Customer"),
           QT_TR_NOOP("Serial number"), QT_TR_NOOP("Manufacturer"), QT_TR_NOOP("State"))
#: between two columns
GAP = "  "


def state_of(record, revision_of: Callable[[str], str]) -> tuple[str, str]:
    """The record's state as the register's English word — ``issued``, ``withdrawn``,
    ``amended`` (superseded by an amendment) or ``replaced`` (by a replacement) — and the
    number that superseded it ("" when none). ``revision_of(number)``: that record's
    revision (``amendment 1``, ``replacement``)."""
    if record.status == "withdrawn":
        return "withdrawn", ""
    if record.status == "superseded" or record.superseded_by:
        by = record.superseded_by or ""
        return ("replaced" if by and revision_of(by) == "replacement" else "amended"), by
    return record.status, ""


def _state_words(state: str, by: str):
    """The state as a message: "amended by AB-2026-0001-A1"."""
    if state == "amended" and by:
        return message(QT_TR_NOOP("amended by {number}"), number=by)
    if state == "replaced" and by:
        return message(QT_TR_NOOP("replaced by {number}"), number=by)
    return message({"issued": QT_TR_NOOP("issued"), "withdrawn": QT_TR_NOOP("withdrawn"),
                    "amended": QT_TR_NOOP("amended"), "replaced": QT_TR_NOOP("replaced")
                    }.get(state, state))


def listing_lines(records: Sequence, revision_of: Callable[[str], str],
                  words: Callable[[str], str]) -> list[str]:
    """The header and a line a record, each column padded to its widest cell (in terminal
    columns); no line at all when there is no record. The workbench is its key, as the
    register keeps it; the document, the state and the headers are in ``words``'
    language."""
    if not records:
        return []
    rows = [[rendered(message(header), words) for header in HEADERS]]
    for record in records:
        state, by = state_of(record, revision_of)
        rows.append([record.number, record.issue_date or "—",
                     f"{record.workbench} / {rendered(kind_words(record.document_kind), words)}",
                     record.customer or "—", record.item_serial or "—",
                     " ".join((record.item_manufacturer or "").split()) or "—",
                     rendered(_state_words(state, by), words)])
    widths = [max(display_width(row[c]) for row in rows) for c in range(len(HEADERS))]
    lines = []
    for row in rows:
        cells = [cell + " " * (widths[c] - display_width(cell)) for c, cell in enumerate(row)]
        lines.append(GAP.join(cells).rstrip())
    return lines


def listing_json(records: Sequence, revision_of: Callable[[str], str]) -> list[dict[str, Any]]:
    """The records for a script: the register's own English keys and words (``state``:
    issued, withdrawn, amended or replaced; ``document_kind``: calibration, test or null,
    not recorded; ``item_manufacturer``: "" when the certificate names none)."""
    out = []
    for record in records:
        state, by = state_of(record, revision_of)
        out.append({"number": record.number, "issue_date": record.issue_date,
                    "workbench": record.workbench, "document_kind": record.document_kind,
                    "customer": record.customer, "item_serial": record.item_serial,
                    "item_manufacturer": record.item_manufacturer or "", "state": state,
                    "superseded_by": by or None,
                    "revision": record.revision, "status": record.status})
    return out
