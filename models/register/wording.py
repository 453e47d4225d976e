"""How a record's status and revision read to a person, in any language: the register
keeps the English words (``issued``, ``amendment 2``) as its data; these are the same
words as :class:`models.messages.Message` templates for the window and the command line."""

from __future__ import annotations

import re

from models.messages import QT_TR_NOOP, message

__all__ = ["DOCUMENT_KINDS", "issued_file_words", "kind_words", "revision_words",
           "status_words"]

#: what a record's ``document_kind`` may be (schema version 6): the keys of the document
#: types a certificate's details choose from (models.certificate.metadata.DOCUMENT_TYPES)
DOCUMENT_KINDS = ("calibration", "test")

_STATUSES = {"issued": QT_TR_NOOP("issued"), "superseded": QT_TR_NOOP("superseded"),
             "withdrawn": QT_TR_NOOP("withdrawn")}
_REVISIONS = {"original": QT_TR_NOOP("original"), "replacement": QT_TR_NOOP("replacement")}


def status_words(status: str) -> str:
    """``issued``, ``superseded`` or ``withdrawn`` as a message (any other text as it is)."""
    return message(_STATUSES[status]) if status in _STATUSES else status


def kind_words(kind: str | None) -> str:
    """What a record's document is, as a message: "Calibration certificate" or "Test
    report"; "not recorded" for a record issued before the register recorded it (None:
    never guessed from the record); any other text as it is."""
    from models.certificate.metadata import DOCUMENT_TYPES

    if kind is None:
        return message(QT_TR_NOOP("not recorded"))
    return message(DOCUMENT_TYPES[kind]) if kind in DOCUMENT_KINDS else kind


def revision_words(revision: str) -> str:
    """``original``, ``replacement`` or ``amendment N`` as a message (any other text as it
    is)."""
    if revision in _REVISIONS:
        return message(_REVISIONS[revision])
    amendment = re.fullmatch(r"amendment (\d+)", revision)
    if amendment:
        return message(QT_TR_NOOP("amendment {n}"), n=int(amendment.group(1)))
    return revision


_ISSUED_FILES = {"pdf": QT_TR_NOOP("the PDF of certificate {number}"),
                 "dcc": QT_TR_NOOP("the DCC of certificate {number}"),
                 "results": QT_TR_NOOP("the results file of certificate {number}")}


def issued_file_words(kind: str, number: str) -> str:
    """"the PDF of certificate AB-2026-0001" (``kind``: "pdf", "dcc" or "results"), as a
    message."""
    return message(_ISSUED_FILES.get(kind, _ISSUED_FILES["pdf"]), number=number)
