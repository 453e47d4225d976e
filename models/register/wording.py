"""How a record's status and revision read to a person, in any language: the register
keeps the English words (``issued``, ``amendment 2``) as its data; these are the same
words as :class:`models.messages.Message` templates for the window and the command line."""

from __future__ import annotations

import re

from models.messages import QT_TR_NOOP, message

__all__ = ["revision_words", "status_words"]

_STATUSES = {"issued": QT_TR_NOOP("issued"), "superseded": QT_TR_NOOP("superseded"),
             "withdrawn": QT_TR_NOOP("withdrawn")}
_REVISIONS = {"original": QT_TR_NOOP("original"), "replacement": QT_TR_NOOP("replacement")}


def status_words(status: str) -> str:
    """``issued``, ``superseded`` or ``withdrawn`` as a message (any other text as it is)."""
    return message(_STATUSES[status]) if status in _STATUSES else status


def revision_words(revision: str) -> str:
    """``original``, ``replacement`` or ``amendment N`` as a message (any other text as it
    is)."""
    if revision in _REVISIONS:
        return message(_REVISIONS[revision])
    amendment = re.fullmatch(r"amendment (\d+)", revision)
    if amendment:
        return message(QT_TR_NOOP("amendment {n}"), n=int(amendment.group(1)))
    return revision
