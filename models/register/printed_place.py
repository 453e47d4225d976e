"""A certificate's PDF presented for verification against the place in the register's chain
its printed head gives it: its own record there, deleted (then recorded as missing), or
another record in its place; and a PDF found in the register whose printed head is no
longer the chain before its record. What is found is said through ``out`` as Message
lines; ``anglebench register verify`` (app/register_cli.py) prints them and the register
window's "Verify a PDF…" (app/register_presenter.py) shows them, the same findings from
the same checks (rev64 F8)."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable

from models.messages import QT_TR_NOOP, Message, message, reason_of
from models.register.chain import content_form, content_in_pdf, head_in_pdf
from models.register.signing import KEY_ENV_VAR
from models.register.store import CertificateRecord, Register, RegisterError

__all__ = ["ALTERED_COPY", "ALTERED_INTACT_RECORD", "ALTERED_OR_REPLACED", "CANNOT_TELL",
           "NOT_THIS_REGISTERS_FIRST", "content_changed",
           "digest_missing", "embedded_pdf", "head_before_changed", "in_this_chain",
           "lost_and_acknowledged", "record_lost", "say_its_place"]

#: a PDF that prints a head of the chain whose next record is another: the PDF altered, or
#: the record replaced — which, the register cannot tell (``register verify`` counts it as
#: a file it did not issue, exit 1, unless the register's own checks find a change)
ALTERED_OR_REPLACED = QT_TR_NOOP(
    "CHANGED AFTER ISSUE: {path} ({number}) prints the head before record {seq}, but "
    "record {seq} is {other}, not this PDF{elsewhere}: the PDF was altered after issue, "
    "or the register's record of it was replaced")


#: a copy that carries the content digest of its number's record at its place, in a register
#: whose records are proven intact (signed with the lab's key, every signature and the chain
#: checked): the record cannot have been replaced, so the copy was altered (day74 #4: it
#: was "altered, or the register's record of it was replaced")
ALTERED_INTACT_RECORD = QT_TR_NOOP(
    "ALTERED: {path} ({number}) is not the PDF the register issued as record {seq}: it "
    "carries the digest of that record's content ({digest}…), and the record is intact and "
    "signed with the laboratory's key, but the file's SHA-256 is {sha}…, the issued PDF's "
    "{issued}…: the copy was altered after issue")

#: a PDF printing the all-zero head — the head before every register's first certificate —
#: whose record digest is no record's here: another register's certificate No. 1 is not
#: this register's record 1 altered (day74 #4)
NOT_THIS_REGISTERS_FIRST = QT_TR_NOOP(
    "NOT ISSUED BY THIS REGISTER: {path} ({number}) prints the all-zero head that every "
    "register's first certificate prints, and the digest of its record's content it carries "
    "({carried}…) is no record's in this register: a certificate of another register (or a "
    "copy altered together with its digest), not one this register issued")

#: a copy whose number's record is at its place with another content digest, the copy
#: carrying no proof of the lab's key that it was issued so (reg73 #4): the copy differs from
#: the record — a file not issued as it is (exit 1), not a certificate the register lost
ALTERED_COPY = QT_TR_NOOP(
    "ALTERED: {path} ({number}) is not the certificate the register issued as record {seq}: "
    "record {seq} is {number}, whose content digest is {actual}…, and this copy carries "
    "{carried}…: the copy was altered after issue{unless}")

#: a PDF printing the head where the chain ends, no record holding it, and no proof of the
#: lab's key that this register issued it: recorded as nothing (reg73 #3)
CANNOT_TELL = QT_TR_NOOP(
    "{path} ({number}) prints the head before record {seq}, where the register's chain ends, "
    "and no record has its SHA-256: the register cannot tell whether this was issued here — "
    "a certificate whose record was deleted after issue, or a file made to print the "
    "register's head, which anyone can read — because {why}; nothing is recorded. If it is "
    "the laboratory's own certificate (compare it with the lab's copy and its log of heads), "
    "its record was deleted: restore the register from a backup")


def say_its_place(register: Register, path: str, data: bytes,
                  out: Callable[[Message], None], embedded: bool = False) -> bool:
    """A certificate's PDF whose printed head (the chain before it) is in the register's
    chain: its own record, its number and SHA-256, must be the next one (rev64 F8: a tail
    deleted with its state row set back left "the history up to it is still there" said of
    a certificate the register no longer held, and its number free). Its record gone — the
    chain ending at that head, no record with its SHA-256 — is recorded in the register
    (Register.record_missing), which then issues nothing until a person records the loss
    (Register.acknowledge_loss; restoring a backup, older than the certificate, did not end
    it: reg73 #5) — only when the PDF carries the proof made with the lab's key that this
    register issued it (Register.issued_here; reg73 #3: a text file printing the public head
    stopped all issuing); else nothing is recorded and the register says it cannot tell. A
    copy whose number's record is at its place with another content digest is ALTERED unless
    its proof says the register issued it so (then the number was issued again, recorded
    likewise; reg73 #2, #4). ``embedded``: ``data`` is the PDF a DCC presented embeds (the
    lines say so). False when it is not in its place (or prints no head of this chain)."""
    check = register.printed_head(data)
    if check is None or check.place is None:
        return False
    name = check.number or message(QT_TR_NOOP("SHA-256 {sha}…"), sha=check.sha256[:16])
    place = check.place + 1
    if check.there:
        assert check.record is not None
        out(message(QT_TR_NOOP(
            "{path}: the PDF embedded in it is {number}'s, record {seq}, right after that "
            "head, identical to the record's PDF (SHA-256); the file itself is not the one "
            "recorded (see above)") if embedded else QT_TR_NOOP(
            "{path}: {number} is record {seq}, right after that head, identical to the record "
            "(SHA-256)"), path=path, number=check.record.number, seq=place))
        return True
    proven = register.issued_here(data)
    if check.recorded_missing:
        out(message(QT_TR_NOOP(
            "CHANGED AFTER ISSUE: {path} ({number}) was issued as record {seq}, right after "
            "the head it prints; its record was found deleted and that is recorded (see "
            "above)"), path=path, number=name, seq=place))
        return False
    if check.missing and proven == "refuted":
        out(message(QT_TR_NOOP(
            "{path} ({number}) prints the head before record {seq}, where the register's chain "
            "ends, but the proof it carries that this register issued it is not the "
            "laboratory key's: it was not issued by this register (made to look so, or "
            "another register's); nothing is recorded"), path=path, number=name, seq=place))
        return False
    if check.missing and proven != "proven":
        out(message(CANNOT_TELL, path=path, number=name, seq=place, why=message(QT_TR_NOOP(
            "it carries no proof made with the laboratory's key (issued before AngleBench "
            "0.8.22 or without the key)")) if register.signed else message(QT_TR_NOOP(
                "the register has no laboratory key ({setting}), so its certificates carry no "
                "proof of issue"), setting=KEY_ENV_VAR)))
        return False
    if check.missing:
        out(message(QT_TR_NOOP(
            "CHANGED AFTER ISSUE: {path} ({number}) was issued as record {seq}, right after "
            "the head it prints, but the register's chain ends at that head and no record has "
            "its SHA-256: its record was deleted after issue"), path=path, number=name,
            seq=place))
        if register.problems:
            return False  # issuing is refused already
        try:
            register.record_missing(check)
        except RegisterError as exc:
            out(message(QT_TR_NOOP(
                "  it could not be recorded in the register ({reason}): issuing is not "
                "stopped by it"), reason=reason_of(exc)))
        else:
            out(message(QT_TR_NOOP(
                "  recorded in the register: nothing is issued, its number not again, until "
                "the loss is recorded with 'anglebench register acknowledge-loss --by NAME "
                "--reason TEXT --last-number NUMBER'")))
        return False
    if check.place == 0 and proven != "proven" and _digest_of_no_record(register, data):
        # every register's first certificate prints the all-zero head: it places nothing
        out(message(NOT_THIS_REGISTERS_FIRST, path=path, number=name,
                    carried=content_in_pdf(data)[:16]))
        return False
    if _number_reissued(register, check, data) and proven != "proven":
        assert check.record is not None
        out(message(ALTERED_COPY, path=path, number=name, seq=place,
                    actual=register.record_content_digest(check.record)[:16],
                    carried=content_in_pdf(data)[:16], unless="" if proven == "refuted" else
                    message(QT_TR_NOOP(
                        " — or its record was deleted and the number issued again, which the "
                        "register cannot rule out for a copy that carries no proof made with "
                        "the laboratory's key")) if register.signed else message(QT_TR_NOOP(
                            " — or, in this register without the laboratory's key, its record "
                            "was deleted and the number issued again: compare the head with "
                            "the lab's log"))))
        return False
    if _number_reissued(register, check, data):
        assert check.record is not None
        out(message(QT_TR_NOOP(
            "CHANGED AFTER ISSUE: {path} ({number}) was issued as record {seq}, right after "
            "the head it prints, but record {seq} is now another certificate of the same "
            "number (SHA-256 {other}…): its record was deleted after issue and the number "
            "issued again"), path=path, number=name, seq=place,
            other=check.record.pdf_sha256[:16]))
        _record_reissue(register, check, out)
        return False
    if _record_proven_intact(register, check, data):
        assert check.record is not None
        out(message(ALTERED_INTACT_RECORD, path=path, number=name, seq=place,
                    digest=content_in_pdf(data)[:16], sha=check.sha256[:16],
                    issued=check.record.pdf_sha256[:16]))
        return False
    other = (check.record.number if check.record is not None else check.after
             or message(QT_TR_NOOP("not there")))
    out(message(ALTERED_OR_REPLACED, path=path, number=name, seq=place,
        other=other, elsewhere=message(QT_TR_NOOP(" (its SHA-256 is record {numbers}'s)"),
                                       numbers=check.elsewhere) if check.elsewhere else ""))
    return False


def _digest_of_no_record(register: Register, data: bytes) -> bool:
    """The PDF carries a digest of its record's content and no record of the register
    has that content (a PDF carrying none, issued before 0.8.21, is not said to be this)."""
    carried = content_in_pdf(data)
    return bool(carried) and all(register.record_content_digest(record) != carried
                                 for record in register.list())


def _record_proven_intact(register: Register, check, data: bytes) -> bool:
    """The record at the PDF's place is of its number and has the content the PDF carries
    the digest of, in a register that proves its records intact: the lab's key checks
    every signature (the right key, none left unchecked) and the audit finds nothing. Then
    the record was not replaced: a PDF that is not the record's was altered after issue
    (day74 #4). Without the key a rewrite with the chain recomputed is not ruled out."""
    record = check.record
    carried = content_in_pdf(data)
    if record is None or not check.number or record.number != check.number or not carried:
        return False
    if not register.signed or register.key_problem is not None or register.signed_unchecked():
        return False
    return register.record_content_digest(record) == carried and not register.audit(pdfs=True)


def _record_reissue(register: Register, check, out: Callable[[Message], None]) -> None:
    """A number found issued twice is recorded in the register, which then issues nothing
    until a person acknowledges the loss (reg73 #2: it was said and forgotten)."""
    if register.problems:
        return  # issuing is refused already
    try:
        recorded = register.record_reissued(check)
    except RegisterError as exc:
        out(message(QT_TR_NOOP(
            "  it could not be recorded in the register ({reason}): issuing is not "
            "stopped by it"), reason=reason_of(exc)))
        return
    if recorded:
        out(message(QT_TR_NOOP(
            "  recorded in the register: nothing is issued until the loss is recorded with "
            "'anglebench register acknowledge-loss --by NAME --reason TEXT'")))


def lost_and_acknowledged(register: Register, path: str, data: bytes,
                          out: Callable[[Message], None]) -> bool:
    """A certificate the register holds no record of, whose number an acknowledged loss
    covers (Register.lost_acknowledged: issued before a restore, its record lost): said as
    lost and acknowledged, not as a file from elsewhere (reg73 #5). False when no
    acknowledged loss covers its number."""
    from models.register.chain import number_in_pdf

    number = number_in_pdf(data)
    loss = register.lost_acknowledged(number)
    if loss is None:
        return False
    out(message(QT_TR_NOOP(
        "LOST, ACKNOWLEDGED: {path} names {number}, a number the register issued before a "
        "loss recorded on {date} by {by} ({reason}): its record was lost, so the register "
        "cannot tell whether this copy is as issued; ask the laboratory for its own copy"),
        path=path, number=number, date=str(loss.get("recorded_at", "?"))[:10],
        by=loss.get("by", "?"), reason=loss.get("reason", "?")))
    return True


def in_this_chain(register: Register, data: bytes) -> bool:
    """The PDF prints a head the register's chain passed through (its record followed
    it): worth :func:`say_its_place` when the register holds no record of it."""
    printed = head_in_pdf(data)
    return bool(printed) and register.find_head(printed) is not None


def head_before_changed(register: Register, path: str, data: bytes,
                        record: CertificateRecord) -> Message | None:
    """Of a PDF found in the register as ``record``: the head it prints is the chain before
    that record as issued; a different chain before it now is said (the history before it
    rewritten). None when it prints no head or the same one."""
    printed = head_in_pdf(data)
    actual = register.chain_before(record.number)
    if not printed or printed == actual:
        return None
    return message(QT_TR_NOOP(
        "CHANGED AFTER ISSUE: {path} prints the chain head {printed} before it, but the "
        "register's chain before {number} is now {actual}"), path=path, printed=printed,
        number=record.number, actual=actual)


def _number_reissued(register: Register, check, data: bytes) -> bool:
    """The record at the PDF's place is another certificate of the number the PDF names:
    another record's content than the one the PDF carries the digest of (a PDF altered
    after issue carries its own record's digest; a PDF that carries none, issued before
    0.8.21, cannot be told from one altered: not said to be this)."""
    carried = content_in_pdf(data)
    return (check.record is not None and bool(check.number) and bool(carried)
            and check.record.number == check.number
            and check.record.pdf_sha256 != check.sha256 and not check.elsewhere
            and register.record_content_digest(check.record) != carried)


def record_lost(register: Register, data: bytes) -> bool:
    """A certificate's PDF the register holds no record of, though the head it prints and
    the number it names say this register issued it there: its record deleted after issue
    (the chain ending at that head, or recorded as missing), or another certificate of its
    number in its place (the number issued again). Not a forgery: the register LOST it
    (reg72 #1) — said only of a PDF that proves this register issued it (reg73 #3, #4:
    a file printing the public head, or a copy altered with its digest, is not)."""
    if not in_this_chain(register, data):
        return False
    check = register.printed_head(data)
    if check is None or check.place is None:
        return False
    if check.recorded_missing:
        return True
    return (check.missing or _number_reissued(register, check, data)) \
        and register.issued_here(data) == "proven"


def embedded_pdf(dcc: bytes) -> bytes:
    """The PDF a DCC embeds (its dataBase64), or b"" when it embeds none that can be read."""
    import base64
    import binascii
    import re

    found = re.search(rb"dataBase64>\s*([A-Za-z0-9+/=\s]+?)\s*</", dcc)
    if not found:
        return b""
    try:
        return base64.b64decode(b"".join(found.group(1).split()), validate=True)
    except (binascii.Error, ValueError):
        return b""


def content_changed(register: Register, path: str, data: bytes,
                    record: CertificateRecord) -> Message | None:
    """Of a PDF found in the register as ``record`` (or a DCC, by the PDF it embeds): the
    digest of its record's content it carries (AngleBench 0.8.21 on) against the record's
    content now. A record rewritten after issue — readings, results, details — with its
    chain recomputed is found so from the customer's copy, key or no key (reg72 #2). None
    when it carries no digest (issued before) or the same one."""
    carried = content_in_pdf(data)
    if not carried:
        return None
    actual = register.record_content_digest(record)
    if actual == carried:
        return None
    return message(QT_TR_NOOP(
        "CHANGED AFTER ISSUE: {path}: the register's record of {number} is not the record "
        "it was issued from: the file carries the digest {carried}… of its record's content "
        "({covered}), the record now gives {actual}…: the record was rewritten after issue"),
        path=path, number=record.number, carried=carried[:16], actual=actual[:16],
        covered=_covered(record))


def _covered(record: CertificateRecord) -> str:
    """What the digest a record's PDF carries covers, by its form, as a message."""
    if content_form(dataclasses.asdict(record)) >= 2:
        return message(QT_TR_NOOP(
            "form 2: readings, results and details as recorded, the document's kind and its "
            "DCC"))
    return message(QT_TR_NOOP("form 1: readings, results and details as recorded"))


def digest_missing(path: str, data: bytes, record: CertificateRecord) -> Message | None:
    """Of a PDF found in the register as ``record`` (or a DCC, by the PDF it embeds): a
    record whose PDF carried a digest of its content when issued (chain format 5 on), the
    file carrying none (reg73 #10: a stored PDF with its digest stripped verified clean)."""
    if content_form(dataclasses.asdict(record)) < 1 or content_in_pdf(data) \
            or not head_in_pdf(data):
        return None
    return message(QT_TR_NOOP(
        "{path}: it carries no digest of its record's content, which {number}'s PDF carried "
        "when it was issued (AngleBench 0.8.21 on): a copy made before 0.8.21, or altered"),
        path=path, number=record.number)
