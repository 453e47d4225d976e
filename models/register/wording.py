"""How a record's status and revision read to a person, in any language: the register
keeps the English words (``issued``, ``amendment 2``) as its data; these are the same
words as :class:`models.messages.Message` templates for the window and the command line."""

from __future__ import annotations

import re

from models.messages import QT_TR_NOOP, message

__all__ = ["DOCUMENT_KINDS", "chained_words", "entry_words", "issued_file_words", "kind_words",
           "recorded_words", "revision_words", "status_words"]

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


#: a chained entry of the register by its kind, in words (day 74 finding 8: the 30-day date
#: confirmation named the last record "entry loss_acknowledged —", the database's kind and an
#: empty subject); ``{subject}`` is the entry's subject: a certificate's number, an item's
#: serial, a counter's name (the kinds written by models/register/store.py)
_ENTRIES = {
    "withdrawal": QT_TR_NOOP("the withdrawal of certificate {subject}"),
    "results": QT_TR_NOOP("the results file of certificate {subject}"),
    "date_confirmed": QT_TR_NOOP("the date confirmed for certificate {subject}"),
    "another_maker": QT_TR_NOOP("the note that certificate {subject} is of another maker's "
                                "item of the same serial"),
    "lookalike_serial": QT_TR_NOOP("the note that certificate {subject}'s serial only looks "
                                   "like another item's"),
    "readings_of_another_item": QT_TR_NOOP("the note why certificate {subject} holds the "
                                           "readings of another item's certificate"),
    "same_readings": QT_TR_NOOP("the note why certificate {subject} holds the readings and "
                                "details of a current certificate of its calibration"),
    "missing": QT_TR_NOOP("the note that certificate {subject} was shown whose record the "
                          "register no longer held"),
    "number_reissued": QT_TR_NOOP("the note that number {subject} was issued twice"),
    "loss_acknowledged": QT_TR_NOOP("the acknowledgement of a loss of records (last number "
                                    "known issued: {subject})"),
    "clock_correction": QT_TR_NOOP("a clock correction"),
    "numbering": QT_TR_NOOP("the numbering continued in {subject}"),
    "signatories": QT_TR_NOOP("the list of authorised signatories"),
    "interval": QT_TR_NOOP("the calibration interval of serial {subject}"),
}
#: the same where the entry names no subject ("" or the "—" a loss acknowledged without its
#: last number is recorded with)
_ENTRIES_WITHOUT_SUBJECT = {
    "loss_acknowledged": QT_TR_NOOP("the acknowledgement of a loss of records"),
}


def entry_words(kind: str, subject: str) -> str:
    """A chained entry of the register in words, as a message: "the withdrawal of
    certificate AB-2026-0001", "a clock correction" …; a kind this version does not know by
    its name, with its subject when it has one."""
    subject = (subject or "").strip()
    named = subject not in ("", "—")
    if not named and kind in _ENTRIES_WITHOUT_SUBJECT:
        return message(_ENTRIES_WITHOUT_SUBJECT[kind])
    template = _ENTRIES.get(kind)
    if template is not None and (named or "{subject}" not in template):
        return message(template, subject=subject)
    if not named:
        return message(QT_TR_NOOP("an entry of kind \"{kind}\""), kind=kind)
    return message(QT_TR_NOOP("an entry of kind \"{kind}\" ({subject})"), kind=kind,
                   subject=subject)


def chained_words(number: str | None = None, kind: str = "", subject: str = "") -> str:
    """A record of the register's chain in words: certificate ``number``, or the entry of
    ``kind`` and ``subject`` (:func:`entry_words`)."""
    if number is not None:
        return message(QT_TR_NOOP("certificate {number}"), number=number)
    return entry_words(kind, subject)


def recorded_words(recorded: str) -> str:
    """A record as an entry of the chain recorded it (a clock correction's subject and
    "ahead", a date confirmed's "last": the number, or "entry KIND SUBJECT") in words, as
    :func:`chained_words` says it; "" as it is."""
    recorded = (recorded or "").strip()
    if not recorded:
        return recorded
    if recorded.startswith("entry "):
        kind, _, subject = recorded[len("entry "):].partition(" ")
        return entry_words(kind, subject)
    return chained_words(recorded)
