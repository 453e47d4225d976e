"""``anglebench register``: the certificate register for audits, without a window.

    anglebench register list [SEARCH] [--json] newest first, aligned under a header (number,
                                               date of issue, workbench / document, customer,
                                               serial, state: issued, withdrawn, amended or
                                               replaced by …; app/register_listing.py);
                                               SEARCH in number, serial, customer
    anglebench register show NUMBER            the record (--pdf OUT, --dcc OUT.xml, --project OUT
                                               to extract), its chain value and the head before it
    anglebench register verify [FILE.pdf|.xml|.xlsx|.csv] the hash chain, every stored PDF
                                               and DCC; is this PDF (or DCC, or results file
                                               written with one), byte for byte, one we issued?
                                               --head VALUE (or
                                               --head-from CERT.pdf): does the register still
                                               hold the history up to that head (and, right
                                               after it, that certificate's record)?
    anglebench register head                   the chain's head now, for the lab's log
    anglebench register withdraw NUMBER --reason TEXT   withdraw (void) a certificate
    anglebench register signatories [NAME …] [--distinct] [--clear]   the lab's authorised
                                               signatories (without arguments: shown)
    anglebench register export OUT.zip         every record: index.csv, PDFs, projects
    anglebench register interval SERIAL DAYS  set an instrument's calibration interval
    anglebench register continue SCHEME NEXT   continue numbering after hand-issued numbers

``--register URL`` (or ANGLEBENCH_REGISTER) chooses the register; the default is the
SQLite file in the user's data folder. A SQLite register that is not there is refused by
the commands that read one (:data:`NEEDS_A_REGISTER`), never made: issuing makes it, and
the set-up commands (continue, interval, signatories NAME …). Exit 2 with one line for a refusal; ``verify``
exits 0 when everything it checked is as issued, 1 for a file (PDF, DCC, results file) the
register did not issue (altered, a draft, another register's), 2 for a command it cannot
carry out (the arguments, a file that cannot be read, a register that cannot be reached) and
3 for a register whose records were changed after issue (the hash chain, the stored files,
a head no longer in the chain; checked on every opening: each command warns) — 3 before 1
when both are found — and 4 for a file as issued whose certificate is no longer valid
(superseded by an amendment or a replacement, or withdrawn), after 3 and 1. What it
prints, its help included, is in the language of ``--language`` (default: the system's);
the listing's workbench keys and the export's ``index.csv`` keep the register's own English
words.
"""

from __future__ import annotations

import argparse
import csv
import hashlib
import io
import os
import sys
import zipfile
from pathlib import Path

from app.command_line import EXIT_BAD_INPUT, Parser, add_language_option, language_asked, speaking
from app.command_line import say as _say
from models.messages import (
    QT_TR_NOOP,
    Message,
    declared_text,
    joined,
    message,
    reason_of,
    rendered,
)
from models.project.atomic_write import is_temporary_name, write_bytes_atomic
from models.project.file_kind import file_kind as kind_of_bytes
from models.project.output_guard import (
    OutputRefused,
    check_outputs,
    refuse_other_kinds,
    refuse_other_project,
    register_files,
)
from models.register.location import register_url
from models.register.wording import kind_words, revision_words, status_words
from models.spreadsheet_cell import spreadsheet_safe

#: ``verify``'s exit status when everything it checked is as issued
EXIT_VERIFIED = 0
#: ``verify``'s exit status for a file (PDF, DCC, results file) the register did not issue
EXIT_NOT_ISSUED = 1
#: ``verify``'s exit status for a register whose records were changed after issue ("CHANGED
#: AFTER ISSUE"): it wins over :data:`EXIT_NOT_ISSUED` (a command that cannot be carried
#: out — the arguments, an unreadable file, an unreachable register — is EXIT_BAD_INPUT, 2)
EXIT_REGISTER_CHANGED = 3
#: ``verify``'s exit status for a file as issued whose certificate is no longer valid:
#: superseded (amended, replaced) or withdrawn since (day review 65 F12: it exited 0, as a
#: current certificate, and a script checking by exit status accepted it); 3 and 1 before it
EXIT_NO_LONGER_VALID = 4
#: what ``verify`` says of a file as issued whose certificate is no longer valid
SUPERSEDED = QT_TR_NOOP("{path}: {number} is no longer valid: superseded by {by} (see "
                        "'anglebench register show {by}')")
WITHDRAWN = QT_TR_NOOP("{path}: {number} is no longer valid: withdrawn ({reason})")
#: how every finding of a change after issue begins (the English text of its message)
CHANGED_AFTER_ISSUE = "CHANGED AFTER ISSUE"

#: what ``show`` lists of a record, named as the register's columns (translated as names)
SHOWN = (QT_TR_NOOP("supersedes"), QT_TR_NOOP("superseded_by"), QT_TR_NOOP("issue_date"),
         QT_TR_NOOP("calibration_date"), QT_TR_NOOP("workbench"),
         QT_TR_NOOP("item_description"), QT_TR_NOOP("item_manufacturer"),
         QT_TR_NOOP("item_serial"), QT_TR_NOOP("customer"), QT_TR_NOOP("operator"),
         QT_TR_NOOP("workstation"), QT_TR_NOOP("issued_at"), QT_TR_NOOP("pdf_sha256"))
#: shown as well (registers of schema version 4): who approved and who issued it (the
#: operating-system user), why it was withdrawn, its value in the hash chain
SHOWN_V4 = (QT_TR_NOOP("approver"), QT_TR_NOOP("os_user"), QT_TR_NOOP("withdrawn_reason"),
            QT_TR_NOOP("chain_sha256"))
#: shown as well (schema version 5): the SHA-256 of the DCC issued with the PDF
SHOWN_V5 = (QT_TR_NOOP("dcc_sha256"),)
COLUMNS = ("number", "status", "revision", "document_kind", *SHOWN)


def _parser(words) -> argparse.ArgumentParser:
    """The command line, its help in the language of ``words`` (a translator)."""
    p = Parser(prog="anglebench register",
               description=words(QT_TR_NOOP("The certificate register")))
    p.add_argument("--register", metavar="URL", default="",
                   help=words(QT_TR_NOOP("sqlite:///path, a file path or "
                                         "postgresql://user@host/db")))
    add_language_option(p, words)
    sub = p.add_subparsers(dest="command", required=True, metavar="COMMAND")
    listing = sub.add_parser("list", help=words(QT_TR_NOOP("the certificates, newest first")))
    listing.add_argument("search", nargs="?", default="",
                         help=words(QT_TR_NOOP("text to find in the number, the serial or the "
                                               "customer")))
    listing.add_argument("--json", action="store_true",  # the register's own English words
                         help=words(QT_TR_NOOP("print JSON instead of a summary")))
    show = sub.add_parser("show", help=words(QT_TR_NOOP("one certificate's record")))
    show.add_argument("number", help=words(QT_TR_NOOP("the certificate number")))
    show.add_argument("--pdf", metavar="OUT.pdf",
                      help=words(QT_TR_NOOP("also write the PDF as issued")))
    show.add_argument("--dcc", metavar="OUT.xml",
                      help=words(QT_TR_NOOP("also write the digital calibration certificate "
                                            "(DCC XML) as issued")))
    show.add_argument("--project", metavar="OUT.anglebench.json",
                      help=words(QT_TR_NOOP("also write the project behind it")))
    verify = sub.add_parser("verify", help=words(QT_TR_NOOP(
        "is this PDF, byte for byte, one the register issued?")))
    verify.add_argument("pdf", nargs="?", default="", help=words(QT_TR_NOOP(
        "the PDF to check (without it: the register's hash chain and stored PDFs only); a "
        ".xml file is checked as a digital calibration certificate (DCC) the register "
        "issued, a .xlsx or .csv file as the results file written with one")))
    verify.add_argument("--head", default="", metavar="VALUE", help=words(QT_TR_NOOP(
        "a chain head noted earlier (12 to 64 hex digits): the register must still hold the "
        "history up to it")))
    verify.add_argument("--head-from", default="", metavar="CERT.pdf", help=words(QT_TR_NOOP(
        "the chain head printed on a certificate (the head before it): the register must "
        "still hold the history up to it, and the certificate's own record right after it")))
    head = sub.add_parser("head", help=words(QT_TR_NOOP(
        "the register's chain head now (note it in the lab's log)")))
    withdraw = sub.add_parser("withdraw", help=words(QT_TR_NOOP(
        "withdraw (void) a certificate, with the reason: a new record")))
    withdraw.add_argument("number", help=words(QT_TR_NOOP("the certificate number")))
    withdraw.add_argument("--reason", required=True, help=words(QT_TR_NOOP(
        "why it is withdrawn")))
    export = sub.add_parser("export", help=words(QT_TR_NOOP(
        "every record: index.csv, the PDFs and the projects")))
    export.add_argument("out", metavar="OUT.zip", help=words(QT_TR_NOOP("the archive to write")))
    export.add_argument("--overwrite", action="store_true", help=words(QT_TR_NOOP(
        "replace OUT.zip when it exists (a file the register issued is never replaced)")))
    counter = sub.add_parser("continue", help=words(QT_TR_NOOP(
        "continue numbering from hand-issued numbers")))
    counter.add_argument("scheme", help=words(QT_TR_NOOP("e.g. AB-{year}-{seq:04d}")))
    counter.add_argument("next", type=int,
                         help=words(QT_TR_NOOP("the next sequence number to issue")))
    counter.add_argument("--date", default="", help=words(QT_TR_NOOP(
        "YYYY-MM-DD for the scheme's date fields (default today)")))
    interval = sub.add_parser("interval", help=words(QT_TR_NOOP(
        "set an instrument's calibration interval")))
    interval.add_argument("serial", help=words(QT_TR_NOOP("the instrument's serial number")))
    interval.add_argument("days", type=int, help=words(QT_TR_NOOP("0 clears it")))
    interval.add_argument("--manufacturer", default="", help=words(QT_TR_NOOP(
        "the manufacturer whose item it is (a serial is unique only within its maker); "
        "without it: every maker's item of the serial that has no interval of its own")))
    signatories = sub.add_parser("signatories", help=words(QT_TR_NOOP(
        "the lab's authorised signatories: an approver must be one of them")))
    signatories.add_argument("names", nargs="*", help=words(QT_TR_NOOP(
        "the names (without any: show the list)")))
    signatories.add_argument("--distinct", action="store_true", help=words(QT_TR_NOOP(
        "the approver must differ from the operator")))
    signatories.add_argument("--clear", action="store_true", help=words(QT_TR_NOOP(
        "no list: any named approver is accepted")))
    lost = sub.add_parser("acknowledge-loss", help=words(QT_TR_NOOP(
        "record that records were lost (an older copy restored): who, why, the last number "
        "known issued; the counters move past it and issuing resumes")))
    lost.add_argument("--by", required=True, help=words(QT_TR_NOOP(
        "who acknowledges the loss (a name)")))
    lost.add_argument("--reason", required=True, help=words(QT_TR_NOOP(
        "why: what was lost and restored")))
    lost.add_argument("--last-number", default="", metavar="NUMBER", help=words(QT_TR_NOOP(
        "the last certificate number known issued (from the lab's log, the customers' "
        "copies): no number up to it is issued again")))
    lost.add_argument("--scheme", default="", help=words(QT_TR_NOOP(
        "the number scheme of --last-number when the register restored has no counter of it "
        "(e.g. AB-{year}-{seq:04d})")))
    clock = sub.add_parser("clock-correction", help=words(QT_TR_NOOP(
        "record that the register's last record was dated by a clock set ahead: with this "
        "clock right, issuing resumes")))
    clock.add_argument("--by", required=True, help=words(QT_TR_NOOP(
        "who records the correction (a name)")))
    clock.add_argument("--reason", required=True, help=words(QT_TR_NOOP(
        "why: which clock was wrong")))
    clock.add_argument("--confirm-date", required=True, metavar="YYYY-MM-DD", help=words(
        QT_TR_NOOP("today's date, as you know it: it must be the computer's")))
    for command in (listing, show, verify, export, counter, interval, head, withdraw,
                    signatories, lost, clock):
        add_language_option(command, words, subcommand=True)
    return p


def _detail(record, key: str) -> str:
    """A certificate detail (``checker``, ``separate_from``) from the project state recorded
    with it (the record has no column for it); empty when it has none."""
    from models.project.file import project_from_json
    from models.registry import KINDS

    try:
        details = project_from_json(record.project_json, kinds=KINDS).metadata["certificates"][
            record.workbench]
    except (TypeError, ValueError, KeyError):
        return ""
    value = details.get(key, "") if isinstance(details, dict) else ""
    return value if isinstance(value, str) else ""


def _checker(record) -> str:
    """The checker (核验员) of the certificate's details; empty when the lab's template has
    none."""
    return _detail(record, "checker")


def _digest_form_line(record) -> Message:
    """Which form of record digest the record's PDF carries (models/register/chain.py)."""
    import dataclasses

    from models.register.chain import content_form

    form = content_form(dataclasses.asdict(record))
    return message(QT_TR_NOOP(
        "  record digest on its PDF: form 2 (readings, results and details, the document's "
        "kind and its DCC)") if form >= 2 else QT_TR_NOOP(
        "  record digest on its PDF: form 1 (readings, results and details; not the "
        "document's kind nor its DCC)") if form == 1 else QT_TR_NOOP(
        "  record digest on its PDF: none (issued before AngleBench 0.8.21)"))


def _print_record(record, register, words) -> None:
    revision = ("" if record.revision == "original"
                else joined((", ", revision_words(record.revision))))
    lines = [message(QT_TR_NOOP("{number}  ({status}{revision})"), number=record.number,
                     status=status_words(record.status), revision=revision),
             # a calibration certificate or a test report (schema version 6; "not recorded"
             # for a record issued before: never guessed)
             message(QT_TR_NOOP("  {field}: {value}"), field=message(QT_TR_NOOP("Document")),
                     value=kind_words(record.document_kind))]
    for key in (*SHOWN, *SHOWN_V4, *SHOWN_V5):
        value = getattr(record, key)
        if value:
            lines.append(message(QT_TR_NOOP("  {field}: {value}"), field=message(key),
                                 value=value))
    checker = _checker(record)
    if checker:  # kept in the project state recorded with it (the record has no column)
        lines.append(message(QT_TR_NOOP("  {field}: {value}"), field=message(
            QT_TR_NOOP("checker")), value=checker))
    # what an amendment changed, or why a calibration of its own is separate, and from which
    # certificates (#61 re-check: the link was on the PDF only)
    separate = _detail(record, "separate_from")
    if separate:
        lines.append(message(QT_TR_NOOP("  {field}: {value}"), field=message(
            QT_TR_NOOP("separate_from")), value=separate))
    if record.change_note:
        lines.append(message(QT_TR_NOOP("  {field}: {value}"), field=message(
            QT_TR_NOOP("change_note")), value=record.change_note))
    # an original in place of a withdrawn certificate of its calibration (hostile78 F3)
    for key in (QT_TR_NOOP("replaces_withdrawn"), QT_TR_NOOP("withdrawn_note")):
        value = _detail(record, key)
        if value:
            lines.append(message(QT_TR_NOOP("  {field}: {value}"), field=message(key),
                                 value=value))
    lines.append(message(QT_TR_NOOP("  chain head before it (printed on it): {head}"),
                         head=register.chain_before(record.number)))
    lines.append(_digest_form_line(record))
    for name, value in record.headline.items():  # a figure's name as the certificate has it
        lines.append(message(QT_TR_NOOP("  headline {name}: {value}"),
                             name=declared_text(name, words), value=f"{value:.6g}"))
    lines.append(message(QT_TR_NOOP("  software: {versions}"), versions=", ".join(
        f"{k} {v}" for k, v in record.software.items())))
    for entry in register.results_records(record.number):  # rev62 M4: never listed before
        lines.append(message(QT_TR_NOOP(
            "  results file: {file}, SHA-256 {sha256}, recorded {recorded_at}") if entry["first"]
            else QT_TR_NOOP("  results file: {file}, SHA-256 {sha256}, recorded {recorded_at} "
                            "(a second one: CHANGED AFTER ISSUE, a certificate has one)"),
            file=entry["file"], sha256=entry["sha256"], recorded_at=entry["recorded_at"]))
        # the file of that name here, when it is not the recorded one, and the recorded one
        # beside it (rev64 F15: after a killed issue, r.xlsx held another certificate's)
        lines += _results_elsewhere(entry, Path.cwd(), "  ")
    # the user's word that the item is another maker's than that of a current certificate
    # of the same serial and date (rev65 F1: a maker spelt otherwise passed unasked)
    for entry in register.another_maker_confirmations(record.number):
        lines.append(message(QT_TR_NOOP(
            "  another maker's item, as {user} confirmed at issue ({recorded_at}): {maker}, not "
            "the maker of {others}"), user=entry["os_user"] or "—",
            recorded_at=entry["recorded_at"], maker=entry["manufacturer"] or "—",
            others=", ".join(f"{o.get('number', '')} ({o.get('manufacturer', '')})"
                             for o in entry["others"])))
    # the user's word that a serial one look-alike from another certificate's is another
    # item (rev65 F7: "1ra-0815" issued as another item than LRA-0815, unasked)
    for entry in register.lookalike_serial_confirmations(record.number):
        lines.append(message(QT_TR_NOOP(
            "  another item, as {user} confirmed at issue ({recorded_at}): serial {serial}, not "
            "the item of {others}"), user=entry["os_user"] or "—",
            recorded_at=entry["recorded_at"], serial=entry["serial"] or "—",
            others=", ".join(f"{o.get('number', '')} ({o.get('serial', '')})"
                             for o in entry["others"])))
    # the user's word that the readings are those of another item's certificates, and why
    # (hostile78 F7: one item's readings issued as nine others', nothing said)
    for entry in register.readings_of_another_item_confirmations(record.number):
        lines.append(message(QT_TR_NOOP(
            "  readings of another item, as {user} said at issue ({recorded_at}): those of "
            "{others}: {reason}"), user=entry["os_user"] or "—",
            recorded_at=entry["recorded_at"], reason=entry["reason"] or "—",
            others=", ".join(f"{o.get('number', '')} ({o.get('item', '')})"
                             for o in entry["others"])))
    # the user's word that a calibration of its own holds the readings and details of a
    # current certificate of its item and date, and why
    for entry in register.same_readings_confirmations(record.number):
        lines.append(message(QT_TR_NOOP(
            "  the same readings as {others}, each within the last digit it was typed to, "
            "and the same details, as {user} said at issue ({recorded_at}): {reason}"),
            user=entry["os_user"] or "—",
            recorded_at=entry["recorded_at"], reason=entry["reason"] or "—",
            others=", ".join(o.get("number", "") for o in entry["others"])))
    due = register.due_date(record.item_serial, record.item_manufacturer or "") \
        if record.item_serial else None
    if due:
        lines.append(message(QT_TR_NOOP("  next calibration of {serial} due: {date}"),
                             serial=record.item_serial, date=due.isoformat()))
    elif record.item_serial and register.maker_needed(record.item_serial,
                                                      record.item_manufacturer or ""):
        # a certificate naming no maker: another maker's due date is never borrowed (rev65 F4)
        lines.append(message(QT_TR_NOOP(
            "  next calibration of {serial}: not known — this certificate names no "
            "manufacturer, and the serial's certificates name {makers}: the due date is "
            "told per maker's item"), serial=record.item_serial,
            makers=", ".join(register.maker_needed(record.item_serial, ""))))
    sys.stdout.write("\n".join(rendered(line, words) for line in lines) + "\n")


def _export(register, out: str, words) -> int:
    from models.register.record_links import record_links

    records = register.list()
    same_readings: dict[str, list[str]] = {}
    for entry in register.same_readings_confirmations():
        same_readings.setdefault(entry["number"], []).extend(
            o.get("number", "") for o in entry["others"])
    index = io.StringIO()
    writer = csv.writer(index)
    # the register's own words: nothing to neutralise; "links": what links a record to
    # other certificates, in the command line's language (record_links)
    writer.writerow(COLUMNS + ("headline", "links"))
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for record in records:
            # a customer, a serial or a note typed as =HYPERLINK(…) is shown, never run
            links = "; ".join(rendered(link, words) for link in record_links(
                record, same_readings.get(record.number, ())))
            writer.writerow([spreadsheet_safe(getattr(record, c) or "") for c in COLUMNS]
                            + [spreadsheet_safe(record.headline_json), spreadsheet_safe(links)])
            safe = record.number.replace("/", "_")
            pdf = register.pdf(record.number, checked=False)  # the audit's copy: all of it
            changed = hashlib.sha256(pdf).hexdigest() != record.pdf_sha256
            archive.writestr(f"pdf/{safe}{'.CHANGED-AFTER-ISSUE' if changed else ''}.pdf", pdf)
            archive.writestr(f"project/{safe}.anglebench.json", record.project_json)
            if record.dcc_sha256:
                dcc = register.dcc(record.number, checked=False)
                changed = hashlib.sha256(dcc).hexdigest() != record.dcc_sha256
                archive.writestr(f"dcc/{safe}{'.CHANGED-AFTER-ISSUE' if changed else ''}.xml",
                                 dcc)
        archive.writestr("index.csv", index.getvalue())
        # the results files recorded at issue (the register keeps their SHA-256, not the
        # files): listed, as in 'register show' (rev62 M4)
        results = io.StringIO()
        listing = csv.writer(results)
        listing.writerow(("number", "file", "sha256", "recorded_at", "first"))
        for entry in register.results_records():
            listing.writerow([spreadsheet_safe(str(entry[key])) for key in
                              ("number", "file", "sha256", "recorded_at", "first")])
        archive.writestr("results.csv", results.getvalue())
    write_bytes_atomic(out, buffer.getvalue())
    _say(rendered(message(QT_TR_NOOP("{n} certificate(s) exported to {out}"), n=len(records),
                          out=out), words))
    return 0


def _verify(register, path: str, words, head: str = "", head_from: str = "") -> int:
    """The register's hash chain and stored PDFs; then, if given, the PDF at ``path`` and
    the head ``head`` (or the one printed on the certificate ``head_from``). The exit
    status: :data:`EXIT_REGISTER_CHANGED` when any finding is a change after issue, else
    :data:`EXIT_NOT_ISSUED` for a file the register did not issue, else
    :data:`EXIT_NO_LONGER_VALID` for a file as issued whose certificate was superseded or
    withdrawn since, else :data:`EXIT_VERIFIED`. The files named are read first: one that
    cannot be read (or a certificate that prints no head) is a RegisterError, said before anything is checked
    (exit 2), never after the register's own findings (they were: a tampered register and a
    mistyped file name both exited 2)."""
    from models.register.chain import head_in_pdf
    from models.register.printed_place import ALTERED_OR_REPLACED
    from models.register.store import RegisterError

    changed = invalid = False

    def out(text) -> None:
        nonlocal changed, invalid
        invalid = invalid or getattr(text, "template", "") in (SUPERSEDED, WITHDRAWN)
        # a PDF altered or its record replaced (the register cannot tell which): the file
        changed = changed or (str(text).startswith(CHANGED_AFTER_ISSUE) and getattr(
            text, "template", "") != ALTERED_OR_REPLACED)
        sys.stdout.write(rendered(text, words) + "\n")

    certificate = _read(head_from) if head_from else b""
    if head_from:
        head = head_in_pdf(certificate)
        if not head:
            raise RegisterError(message(QT_TR_NOOP(
                "{path}: no register chain head printed in it (a draft, a specimen, or issued "
                "before AngleBench printed the head)"), path=head_from))
    data = _read(path) if path else b""
    status = _verify_findings(register, path, data, out, head, head_from, certificate)
    if changed or status == EXIT_REGISTER_CHANGED:
        return EXIT_REGISTER_CHANGED
    if register.key_problem is not None:  # the key named is not the register's: a setting
        return EXIT_BAD_INPUT
    if status:
        return EXIT_NOT_ISSUED
    return EXIT_NO_LONGER_VALID if invalid else EXIT_VERIFIED


def _verify_findings(register, path: str, data: bytes, out, head: str, head_from: str,
                     certificate: bytes) -> int:
    """What :func:`_verify` finds, said through ``out``: 1 when something is not as issued
    (:data:`EXIT_REGISTER_CHANGED` when the register's records say they were changed in a
    line that does not begin "CHANGED AFTER ISSUE"), else 0."""
    from models.register.chain import number_in_pdf
    from models.register.printed_place import (
        content_changed,
        digest_missing,
        embedded_pdf,
        head_before_changed,
        in_this_chain,
        lost_and_acknowledged,
        record_lost,
        say_its_place,
    )

    problems = register.audit(pdfs=True)
    if register.key_problem is not None:  # a wrong key: no signature checked (reg73 #7)
        out(register.key_problem)
    for problem in problems:
        out(message(QT_TR_NOOP("CHANGED AFTER ISSUE: {problem}"), problem=problem))
    if not problems:
        out(message(QT_TR_NOOP("register: hash chain intact over {n} record(s), every stored PDF "
                               "and DCC matches its SHA-256; chain head {head}"),
                    n=register.chain_records(), head=register.chain_head()))
        out(message(QT_TR_NOOP("  of them: {certificates} certificate(s) and {results} results "
                               "file(s) recorded at issue"), certificates=len(register.list()),
                    results=len(register.results_records())))
    unchecked = register.signed_unchecked()
    if unchecked:  # reg72 #3: a keyless verify said "intact" of a signed register
        out(message(QT_TR_NOOP(
            "  {n} record(s) are signed with the laboratory's key: their signatures and the "
            "register's signed state are NOT checked without the key (set "
            "ANGLEBENCH_REGISTER_KEY); a rewrite by someone with write access to the "
            "database is not detectable without it: compare the head with your log"),
            n=unchecked))
    elif not register.signed:
        out(message(QT_TR_NOOP(
            "  unsigned register (no laboratory key): someone with write access to the "
            "database can rewrite records and recompute the chain undetectably; the digest "
            "each certificate issued since 0.8.21 carries finds its record rewritten, and a "
            "head noted outside ('anglebench register head') finds the rest")))
    failed = bool(problems)
    if head:
        found = register.find_head(head)
        if found is None:
            failed = True
            out(message(QT_TR_NOOP(
                "CHANGED AFTER ISSUE: head {head} is not in the register's chain: the history "
                "up to it was rewritten or removed (or it is another register's)"), head=head))
        else:
            out(message(QT_TR_NOOP(
                "head {head}: in the register's chain at record {seq}; the history up to it "
                "is still there"), head=found[1], seq=found[0]))
            if certificate and not say_its_place(register, head_from, certificate, out):
                failed = True
    if not path:
        return 1 if failed else 0
    if is_temporary_name(path):
        out(message(QT_TR_NOOP(
            "{path}: the name of an unfinished write left by an interrupted issue or save "
            "(a temporary file): what it holds is checked below; the file at the final name, "
            "if any, is the one that was issued"), path=path))
    kind = file_kind(data)
    found_pdf = register.verify_all(data)
    found_dcc = register.verify_dcc(data) if not found_pdf else []
    digest = hashlib.sha256(data).hexdigest()
    is_results = not found_pdf and not found_dcc and (
        any(entry["sha256"] == digest for entry in register.results_records())
        or kind in ("xlsx", "csv"))
    if is_results:  # a results file issued with a certificate, whatever its name
        return _verify_results(register, path, data, out) or int(failed)
    is_dcc = bool(found_dcc) or (not found_pdf and kind == "dcc")
    found = found_dcc if is_dcc else found_pdf
    pdf_inside = embedded_pdf(data) if is_dcc else data
    if len(found) > 1:
        out(message(QT_TR_NOOP(
            "{path}: its SHA-256 is in {n} records ({numbers}): a certificate is issued once, "
            "so all but one were copied into the register after issue"), path=path,
            n=len(found), numbers=", ".join(r.number for r in found)))
        return EXIT_REGISTER_CHANGED  # the register's records, not the file, were changed
    record = found[0] if found else None
    if record is None:
        if pdf_inside and lost_and_acknowledged(register, path, pdf_inside, out):
            return EXIT_REGISTER_CHANGED  # its record lost: not to be taken as verified
        if pdf_inside and record_lost(register, pdf_inside):
            # issued by this register (the head it prints, its number), its record gone:
            # the register LOST it — not a forgery (reg72 #1)
            out(message(QT_TR_NOOP(
                "CHANGED AFTER ISSUE: {path} was issued by this register ({number}), but the "
                "register has LOST its record: see below"), path=path,
                number=number_in_pdf(pdf_inside) or "?"))
            say_its_place(register, path, pdf_inside, out)
            return EXIT_REGISTER_CHANGED
        out(message(QT_TR_NOOP(
            "{path}: NOT in the register (no issued DCC has its SHA-256: altered, or from "
            "another register)") if is_dcc else QT_TR_NOOP(
            "{path}: NOT in the register (no issued PDF has its SHA-256: altered, a "
            "draft, or from another register)") if kind == "pdf" else QT_TR_NOOP(
            "{path}: NOT in the register (no issued PDF, DCC or results file has its "
            "SHA-256, and it is none of them: altered, or from another register)"), path=path))
        if pdf_inside and kind in ("pdf", "dcc") and in_this_chain(register, pdf_inside):
            # it prints a head of this chain, so its record followed that head: is it gone?
            say_its_place(register, path, pdf_inside, out, embedded=is_dcc)
        return 1
    out(message(_by_kind(record, QT_TR_NOOP(
        "{path}: certificate {number}, issued {issued_at}, {status}; identical to "
        "the record (SHA-256)"), QT_TR_NOOP(
        "{path}: test report {number}, issued {issued_at}, {status}; identical to "
        "the record (SHA-256)"), QT_TR_NOOP(
        "{path}: document {number}, issued {issued_at}, {status}; identical to "
        "the record (SHA-256)")), path=path, number=record.number,
        issued_at=record.issued_at, status=status_words(record.status)))
    if is_dcc:
        out(message(QT_TR_NOOP("  it is the certificate's DCC (digital calibration "
                               "certificate)")))
    _say_if_no_longer_valid(record, path, out)
    rewritten = content_changed(register, path, pdf_inside, record) if pdf_inside else None
    if rewritten is not None:
        out(rewritten)
        failed = True
    stripped = digest_missing(path, pdf_inside, record) if pdf_inside else None
    if stripped is not None:  # reg73 #10: a PDF with its digest stripped verified clean
        out(stripped)
    moved = None if is_dcc else head_before_changed(register, path, data, record)
    if moved is not None:
        out(moved)
        failed = True
    return 1 if failed else 0


#: the register's names for what models.project.file_kind finds: a results file is an XLSX
#: or a CSV, a DCC an XML document
_REGISTER_KIND = {"pdf": "pdf", "zip": "xlsx", "xml": "dcc", "text": "csv"}


def file_kind(data: bytes) -> str:
    """What a file is by its content, not its name (reg72 #6: the same bytes named .tmp,
    .dcc or .xlsx were "NOT in the register"): "pdf", "dcc" (XML), "xlsx" (a ZIP), "csv"
    (other text) or "" (none of them)."""
    return _REGISTER_KIND.get(kind_of_bytes(data), "")


def _by_kind(record, certificate: str, report: str, unknown: str) -> str:
    """The text that names what ``record`` is, as the register recorded it: a calibration
    certificate, a test report, or — issued before the register recorded the kind
    (``None``) — a document, never a guess."""
    return {"calibration": certificate, "test": report}.get(record.document_kind, unknown)


def _say_if_no_longer_valid(record, path: str, out) -> None:
    """A verified file's certificate superseded or withdrawn since: said, naming why."""
    if record.superseded_by:
        out(message(SUPERSEDED, path=path, number=record.number, by=record.superseded_by))
    if record.status == "withdrawn":
        out(message(WITHDRAWN, path=path, number=record.number,
                    reason=record.withdrawn_reason or "—"))


def _results_elsewhere(entry: dict, folder: Path, indent: str = "") -> list:
    """What to say of the recorded results file ``entry`` (``register.results_records``) in
    ``folder``: when the file there of the name it was recorded under is not it (another
    file written under that name since), and where a file beside it is — the temporary
    name an issue stopped before naming it left (``.r.xlsx.*.tmp``), or the name it was
    kept under (``r.AB-2026-0002.xlsx``, app/issued_outputs.keep_in_sight). rev64 F15:
    within ten minutes of a killed issue nothing pointed at the only copy, and ``register
    show`` named a file that held another certificate's results."""
    import glob
    import hashlib

    from app.issued_outputs import kept_name
    from models.project.atomic_write import _temp_prefix

    def sha256(file: Path) -> str | None:
        try:
            return hashlib.sha256(file.read_bytes()).hexdigest() if file.is_file() else None
        except OSError:
            return None

    named = folder / entry["file"]
    actual = sha256(named)
    if actual == entry["sha256"]:
        return []
    kept = kept_name(named, entry["number"])
    beside = sorted(folder.glob(f"{glob.escape(_temp_prefix(named))}*.tmp")) + sorted(
        folder.glob(f"{glob.escape(kept.stem)}*{glob.escape(kept.suffix)}"))
    found = [file for file in beside if sha256(file) == entry["sha256"]]
    said = []
    if actual is not None:
        said.append(message(QT_TR_NOOP(
            "{indent}{path} is not the results file recorded under that name with "
            "certificate {number} (its SHA-256 is {sha256}: another file written under the "
            "name since)"), indent=indent, path=str(named), number=entry["number"],
            sha256=actual))
    if found:
        said.append(message(QT_TR_NOOP(
            "{indent}the results file recorded with certificate {number} is {path} (SHA-256 "
            "as recorded): give it a name of its own"), indent=indent, number=entry["number"],
            path=str(found[0])))
    return said


def _is_project(data: bytes) -> bool:
    """Whether ``data`` is an AngleBench project file (its ``format``), not a results CSV."""
    import json

    from models.project.file import FORMAT_NAME

    if not data.lstrip(b"\xef\xbb\xbf \t\r\n").startswith(b"{"):
        return False
    try:
        parsed = json.loads(data.decode("utf-8-sig"))
    except (UnicodeDecodeError, ValueError):
        return False
    return isinstance(parsed, dict) and parsed.get("format") == FORMAT_NAME


def _verify_project(register, path: str, data: bytes, out) -> int:
    """A project file given to verify (hostile78 V1: the register's own export of a project,
    untouched, was "NOT in the register … altered" as a results file): the project recorded
    with a certificate, byte for byte as `register show N --project` and `register export`
    write it, is said to be that record's (its certificate's state as for a PDF); any other
    project is no file the register issued, and is said to be a project (exit 1)."""
    matched = [record for record in register.list()
               if record.project_json.encode("utf-8") == data]
    if not matched:
        out(message(QT_TR_NOOP(
            "{path}: an AngleBench project file, which is not the project recorded with any "
            "certificate (changed since, or saved from the window): verify judges a "
            "certificate's PDF, its DCC and its results file; the project recorded with a "
            "certificate is written by anglebench register show N --project OUT.json"),
            path=path))
        return EXIT_NOT_ISSUED
    record = matched[0]
    out(message(QT_TR_NOOP(
        "{path}: the project (readings, settings and details) recorded with certificate "
        "{number}, byte for byte as the register holds it; a project is no document issued "
        "to the customer"), path=path, number=record.number))
    if record.superseded_by:
        out(message(SUPERSEDED, path=path, number=record.number, by=record.superseded_by))
    if record.status == "withdrawn":
        out(message(WITHDRAWN, path=path, number=record.number,
                    reason=record.withdrawn_reason or "—"))
    return EXIT_VERIFIED  # 4 when superseded or withdrawn: said above, _verify counts it


def _verify_results(register, path: str, data: bytes, out) -> int:
    """A results file (CSV or XLSX): the certificate it was recorded with when issued, or
    1 when the register holds no results file with its SHA-256, when it is recorded under
    more than one certificate or as a second results file of one, or when what an XLSX says
    of its certificate (number, PDF and DCC SHA-256) is not that record's (rev62 F7)."""
    import hashlib

    from app.writers.results_export import issue_stated, neutralise

    digest = hashlib.sha256(data).hexdigest()
    records = register.results_records()
    found = [entry for entry in records if entry["sha256"] == digest]
    # recorded under this name, but this is another file: said, and where the recorded one
    # is when it is beside it (rev64 F15)
    elsewhere = [said for entry in records
                 if entry["file"] == os.path.basename(path) and entry["sha256"] != digest
                 for said in _results_elsewhere(entry, Path(path).parent)]
    if not found and _is_project(data):  # hostile78 V1: called an altered results file
        return _verify_project(register, path, data, out)
    if not found:
        out(message(QT_TR_NOOP(
            "{path}: NOT in the register (no results file written with an issued certificate "
            "has its SHA-256: altered, written without issuing one, or from another "
            "register)"), path=path))
        named = _results_of_issued(register, path, data, records)
        if named is not None:  # reg73 #1: the register's entry rewritten, or this copy
            out(named)
        for said in elsewhere:
            out(said)
        return 1
    failed = False
    numbers = sorted({entry["number"] for entry in found})
    if len(numbers) > 1:
        out(message(QT_TR_NOOP(
            "CHANGED AFTER ISSUE: {path}: its SHA-256 is recorded as the results file of {n} "
            "certificates ({numbers}): a results file is written with one certificate, so all "
            "but one were recorded after issue"), path=path, n=len(numbers),
            numbers=", ".join(numbers)))
        failed = True
    stated = issue_stated(data) if file_kind(data) == "xlsx" else None
    for entry in found:
        record = register.get(entry["number"])
        if not entry["first"]:
            out(message(QT_TR_NOOP(
                "CHANGED AFTER ISSUE: {path}: recorded {recorded_at} as a second results file "
                "of certificate {number}, whose results file was already recorded: a "
                "certificate has one, recorded at its issue"), path=path,
                recorded_at=entry["recorded_at"], number=record.number))
            failed = True
            continue
        if stated is not None and (
                stated["number"] not in (record.number, neutralise(record.number))
                or stated["pdf_sha256"] != record.pdf_sha256
                or stated["dcc_sha256"] != (record.dcc_sha256 or "")):
            out(message(QT_TR_NOOP(
                "CHANGED AFTER ISSUE: {path}: recorded as the results file of certificate "
                "{number}, but it says it is that of certificate {stated} (PDF SHA-256 "
                "{pdf}): it is not the file written with {number}"), path=path,
                number=record.number, stated=stated["number"] or "—",
                pdf=stated["pdf_sha256"][:16] or "—"))
            failed = True
            continue
        out(message(_by_kind(record, QT_TR_NOOP(
            "{path}: the results file of certificate {number}, recorded {recorded_at}, "
            "{status}; identical to the record (SHA-256)"), QT_TR_NOOP(
            "{path}: the results file of test report {number}, recorded {recorded_at}, "
            "{status}; identical to the record (SHA-256)"), QT_TR_NOOP(
            "{path}: the results file of document {number}, recorded {recorded_at}, "
            "{status}; identical to the record (SHA-256)")), path=path, number=record.number,
            recorded_at=entry["recorded_at"], status=status_words(record.status)))
        _say_if_no_longer_valid(record, path, out)
    for said in elsewhere:
        out(said)
    return 1 if failed else 0


def _results_of_issued(register, path: str, data: bytes, records: list) -> Message | None:
    """Of a results file the register holds no entry of: the certificate it says it is of
    (an XLSX's *Certificate* sheet: its number and PDF SHA-256), when that is an issued
    record's with a results file recorded — which is then another file (reg73 #1: the
    newest results entry rewritten with its chain recomputed called the customer's genuine
    workbook "NOT in the register" and nothing more). With the lab's key and its signatures
    intact the register's entry is its own: the copy was altered; without, either."""
    from app.writers.results_export import issue_stated

    if file_kind(data) != "xlsx":
        return None
    try:
        stated = issue_stated(data)
    except (ValueError, OSError, KeyError):
        return None
    if not stated or not stated.get("pdf_sha256"):
        return None
    numbers = {number for number, kind in register.issued_file(stated["pdf_sha256"])
               if kind == "pdf"}
    recorded = [entry for entry in records if entry["number"] in numbers and entry["first"]]
    if not recorded:
        return None
    entry = recorded[0]
    intact = register.signed and not register.problems and register.key_problem is None
    return message(QT_TR_NOOP(
        "{path} says it is the results file of certificate {number} (its PDF SHA-256 "
        "{pdf}…), whose results file the register recorded as another (SHA-256 {recorded}…, "
        "{file}): this copy was altered after issue") if intact else QT_TR_NOOP(
        "{path} says it is the results file of certificate {number} (its PDF SHA-256 "
        "{pdf}…), whose results file the register recorded as another (SHA-256 {recorded}…, "
        "{file}): this copy was altered after issue, or — in a register without the "
        "laboratory's key — the register's record of it was rewritten; compare it with the "
        "lab's copy"), path=path, number=entry["number"],
        pdf=stated["pdf_sha256"][:16], recorded=entry["sha256"][:16], file=entry["file"])


def _holds(path: str, register, record, flag: str) -> bool:
    """Whether ``path`` already holds, byte for byte, what ``show --pdf``/``--dcc`` would
    write there (saving an issued file again over itself changes nothing)."""
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except OSError:
        return False
    digest = hashlib.sha256(data).hexdigest()
    return (flag == "--pdf" and digest == record.pdf_sha256) or (
        flag == "--dcc" and digest == record.dcc_sha256)


#: the commands that read a register, or record what only a register with records can
#: have (a withdrawal, a loss, a clock correction): a SQLite register that is not there is
#: refused, never made (contract75 F10: 'register --register ./typo.sqlite verify' made an
#: empty register, folders included, and said "hash chain intact over 0 record(s)", exit 0).
#: Issuing makes one; so do the lab's set-up commands (continue, interval, signatories
#: NAME …), which come before a register's first certificate.
NEEDS_A_REGISTER = frozenset(("list", "show", "verify", "head", "export", "withdraw",
                              "acknowledge-loss", "clock-correction"))


def _missing_register(url: str, args: argparse.Namespace) -> Message | None:
    """Why the command is refused when its SQLite register does not exist (None when it
    exists, is a server's, or the command may make it)."""
    from models.project.output_guard import sqlite_path_of_url

    reads = args.command in NEEDS_A_REGISTER or (
        args.command == "signatories" and not (args.names or args.clear or args.distinct))
    database = sqlite_path_of_url(url)
    if not reads or database is None or os.path.lexists(database):
        return None
    return message(QT_TR_NOOP(
        "anglebench register: there is no register at {path}; nothing was created (a "
        "register is made by its first certificate): check --register or "
        "ANGLEBENCH_REGISTER"), path=str(database))


def _read(path: str) -> bytes:
    from models.register.store import RegisterError

    try:
        with open(path, "rb") as handle:
            return handle.read()
    except OSError as exc:
        raise RegisterError(message(QT_TR_NOOP("{path}: cannot read ({value})"),
                                    path=path, value=exc.strerror)) from None


def run_register(argv: list[str]) -> int:
    language = language_asked(argv)
    with speaking(language) as words:
        args = _parser(words).parse_args(argv)
    from models.register.store import Register, RegisterError, RegisterTampered

    url = register_url(explicit=args.register)
    outputs = ((("--pdf", args.pdf), ("--dcc", args.dcc), ("--project", args.project))
               if args.command == "show"
               else (("OUT.zip", args.out),) if args.command == "export" else ())
    try:
        # before the register is opened: nothing written, the register untouched
        check_outputs(outputs, register_files(url))
    except OutputRefused as exc:
        _say(f"anglebench register: {rendered(reason_of(exc), words)}")
        return EXIT_BAD_INPUT
    missing = _missing_register(url, args)
    if missing is not None:
        _say(rendered(missing, words))
        return EXIT_BAD_INPUT
    try:
        if args.command == "verify":  # a file that cannot be read: exit 2, nothing checked
            for named in (args.pdf, args.head_from):
                if named:
                    _read(named)
        try:
            register = Register(url)
        except RegisterTampered as exc:
            if args.command != "verify":
                raise
            sys.stdout.write(rendered(message(QT_TR_NOOP("CHANGED AFTER ISSUE: {problem}"),
                                              problem=reason_of(exc)), words) + "\n")
            return EXIT_REGISTER_CHANGED
        # a write that waits for another's lock says so at once, not after a silent minute
        register.on_wait = lambda said: _say(f"anglebench register: {rendered(said, words)}")
        with register:
            if args.command != "verify":
                for problem in register.problems:
                    _say(rendered(message(QT_TR_NOOP("anglebench register: WARNING: {problem}"),
                                          problem=problem), words))
            if args.command == "list":
                from app.register_listing import listing_json, listing_lines

                records = register.list(args.search)
                revisions = {r.number: r.revision for r in records}

                def revision_of(number: str) -> str:  # of the one that superseded a record
                    if number not in revisions:
                        try:
                            revisions[number] = register.get(number).revision
                        except RegisterError:
                            revisions[number] = ""
                    return revisions[number]

                if args.json:
                    import json

                    sys.stdout.write(json.dumps(listing_json(records, revision_of), indent=1,
                                                ensure_ascii=False) + "\n")
                    return 0
                for line in listing_lines(records, revision_of, words):
                    sys.stdout.write(line + "\n")
                return 0
            if args.command == "show":
                record = register.get(args.number)
                if any(path for _flag, path in outputs):
                    from app.certificate_issue import refuse_issued_files

                    try:  # an issued file (another certificate's PDF…) is never replaced
                        for said in refuse_issued_files(register, [
                                (flag, path) for flag, path in outputs
                                if path and not _holds(path, register, record, flag)]):
                            _say(f"anglebench register: {rendered(said, words)}")  # kept
                        refuse_other_kinds(outputs)  # nor a file of another kind
                        if args.project:  # nor a project of other readings
                            refuse_other_project(args.project,
                                                 record.project_json.encode("utf-8"))
                    except OutputRefused as exc:
                        _say(f"anglebench register: {rendered(reason_of(exc), words)}")
                        return EXIT_BAD_INPUT
                _print_record(record, register, words)
                if args.pdf:
                    write_bytes_atomic(args.pdf, register.pdf(record.number))
                if args.dcc:
                    write_bytes_atomic(args.dcc, register.dcc(record.number))
                if args.project:
                    write_bytes_atomic(args.project, record.project_json.encode("utf-8"))
                return 0
            if args.command == "verify":
                return _verify(register, args.pdf, words, args.head, args.head_from)
            if args.command == "head":
                sys.stdout.write(register.chain_head() + "\n")
                return 0
            if args.command == "signatories":
                if args.names or args.clear or args.distinct:
                    register.set_signatories([] if args.clear else args.names, args.distinct)
                names, distinct = register.signatories()
                sys.stdout.write(rendered(message(QT_TR_NOOP(
                    "authorised signatories: {names}; approver and operator {rule}"),
                    names=", ".join(names) or message(QT_TR_NOOP("none listed (any named "
                                                                 "approver)")),
                    rule=message(QT_TR_NOOP("must differ") if distinct
                                 else QT_TR_NOOP("may be the same"))), words) + "\n")
                return 0
            if args.command == "withdraw":
                register.withdraw(args.number, args.reason)
                sys.stdout.write(rendered(message(QT_TR_NOOP(
                    "{number} withdrawn ({reason}); chain head now {head}"),
                    number=args.number, reason=args.reason, head=register.chain_head()),
                    words) + "\n")
                return 0
            if args.command == "acknowledge-loss":
                from models.register.recoveries import loss_recorded

                body = register.acknowledge_loss(args.by, args.reason, args.last_number,
                                                 args.scheme)
                sys.stdout.write(rendered(loss_recorded(body, register.chain_head()), words)
                                 + "\n")
                for problem in register.problems:
                    _say(rendered(message(QT_TR_NOOP("anglebench register: WARNING: {problem}"),
                                          problem=problem), words))
                return 0
            if args.command == "clock-correction":
                from models.register.clock_rules import parse_confirmed_date
                from models.register.recoveries import clock_corrected

                body = register.correct_clock(args.by, args.reason,
                                              parse_confirmed_date(args.confirm_date))
                sys.stdout.write(rendered(clock_corrected(body), words) + "\n")
                return 0
            if args.command == "continue":
                import datetime as dt

                try:
                    date = dt.date.fromisoformat(args.date) if args.date else dt.date.today()
                except ValueError:
                    raise RegisterError(message(QT_TR_NOOP("--date {date}: not YYYY-MM-DD"),
                                                date=args.date)) from None
                number = register.continue_numbering(args.scheme, date, args.next)
                sys.stdout.write(rendered(message(QT_TR_NOOP(
                    "the next certificate of {scheme} will be {number}"), scheme=args.scheme,
                    number=number), words) + "\n")
                return 0
            if args.command == "interval":
                register.set_interval(args.serial, args.days or None, args.manufacturer)
                return 0
            from app.certificate_issue import refuse_issued_files

            try:  # an issued PDF, DCC or results file is never replaced (rev63 F5)
                for said in refuse_issued_files(register, [("", args.out)]):
                    _say(f"anglebench register: {rendered(said, words)}")  # a file kept
            except OutputRefused as exc:
                _say(f"anglebench register: {rendered(reason_of(exc), words)}")
                return EXIT_BAD_INPUT
            if os.path.lexists(args.out) and not args.overwrite:
                _say(rendered(message(QT_TR_NOOP(
                    "anglebench register: {out} exists; nothing was written: choose another "
                    "name, or add --overwrite to replace it"), out=args.out), words))
                return EXIT_BAD_INPUT
            return _export(register, args.out, words)
    except RegisterError as exc:
        _say(f"anglebench register: {rendered(reason_of(exc), words)}")
        return EXIT_BAD_INPUT
    except OSError as exc:
        import errno

        if isinstance(exc, BrokenPipeError):
            raise  # a closed pipe (register list | head): the console script ends quietly
        if exc.errno in (errno.ENOSPC, getattr(errno, "EDQUOT", errno.ENOSPC)) and \
                args.command == "export":
            # the file the user named (not the temporary one beside it), exit 2 as analyze's
            # outputs (models.project.write_failure)
            _say(rendered(message(QT_TR_NOOP(
                "anglebench register: {path} cannot be written: the disk is full; nothing was "
                "written there and the register is unchanged (free some space and try again)"),
                path=args.out), words))
            return EXIT_BAD_INPUT
        if exc.errno in (errno.ENOSPC, getattr(errno, "EDQUOT", errno.ENOSPC)):
            # said in words, where (the folder written into), not "[Errno 28] …" (stop 63)
            folder = os.path.dirname(os.path.abspath(exc.filename)) if exc.filename else "?"
            _say(rendered(message(QT_TR_NOOP(
                "anglebench register: the disk is full at {path}: nothing was written there; "
                "the register is unchanged (free some space and try again)"), path=folder),
                words))
            return 1
        _say(rendered(message(QT_TR_NOOP("anglebench register: cannot write: {reason}"),
                              reason=str(exc)), words))
        return 1
