"""The register window's presenter: the list and its search, the project behind a
certificate, re-verifying a PDF, saving a PDF from the register, starting an amendment or
a replacement, and an instrument's history with its due date. No widgets: it asks its
view (widgets/register_window.py) and the main window (``open_project_state``)."""

from __future__ import annotations

import datetime as dt
from collections.abc import Callable
from typing import Any, Protocol

from PySide6.QtCore import QT_TR_NOOP

from app.certificate_presenter import CertificatePresenter, PendingRevision
from app.register_recovery_pointer import recovery_pointer
from models.messages import as_sentence
from models.register.recoveries import LOSS, recovery_answering
from models.register.store import CertificateRecord, RegisterError
from models.register.wording import kind_words, revision_words, status_words
from widgets.i18n import declared, explained, tr, translated
from widgets.register_recoveries import CorrectionTyped, LossTyped

__all__ = ["RegisterPresenter", "RegisterView"]

COLUMNS = (QT_TR_NOOP("Number"), QT_TR_NOOP("Status"), QT_TR_NOOP("Revision"),
           QT_TR_NOOP("Document"), QT_TR_NOOP("Issued"), QT_TR_NOOP("Calibrated"), QT_TR_NOOP("Workbench"),
           QT_TR_NOOP("Serial"), QT_TR_NOOP("Manufacturer"), QT_TR_NOOP("Customer"),
           # what links it to other certificates (models/register/record_links: amends,
           # superseded by, in place of withdrawn, readings of another item …)
           QT_TR_NOOP("Links"))


class RegisterView(Protocol):
    def show_location(self, url: str) -> None: ...

    def show_records(self, header: tuple[str, ...], rows: list[tuple[str, ...]]) -> None: ...

    def selected_row(self) -> int: ...  # −1 when none

    def show_history(self, serial: str, series: dict[str, tuple[list[float], list[float]]],
                     dates: list[str], due: str, interval_days: int,
                     makers: tuple[str, ...] = (), manufacturer: str = "",
                     makerless: tuple[str, ...] = ()) -> None:
        """``makers``: the item's certificate names no maker and the serial's name these
        (no due date without the maker). ``manufacturer``: whose item the history is ("":
        named by its serial alone); ``makerless``: the dates of calibration of the
        certificates in it that name no manufacturer (a maker's history holds them: said,
        not taken for that maker's)."""

    def ask_pdf_to_verify(self) -> str: ...

    def ask_pdf_path(self, suggested: str) -> str: ...

    def tell(self, title: str, text: str) -> None: ...

    def print_certificate(self, pdf: bytes, number: str) -> int: ...  # pages; 0: cancelled

    def in_background(self, work: Callable[[], Any], done: Callable[[Any], None]) -> None:
        """Run ``work`` on a worker thread; ``done(its result or the exception)`` on the GUI
        thread."""

    def show_pdf_check(self, text: str, warning: bool, detail: str = "") -> None:
        """The window's state line: ``text``; ``detail`` (what was found, in full) where
        the user points at it."""

    def ask_loss(self, last_number_needed: bool,
                 record: Callable[[LossTyped], str]) -> None:
        """What ``anglebench register acknowledge-loss`` asks (the last number required
        when ``last_number_needed``), handed to ``record`` until it returns "" (recorded)
        or the user cancels; a refusal it returns is shown, what was typed kept."""

    def ask_clock_correction(self, record: Callable[[CorrectionTyped], str]) -> None:
        """What ``anglebench register clock-correction`` asks, handed to ``record`` as
        :meth:`ask_loss` does."""


def _workbench_title(key: str) -> str:
    """A workbench as its tab names it, in the window's language (rev62 F14: the keys
    ``polygon``/``positioning`` in the Chinese window); a key no longer known as it is."""
    from models.registry import KINDS

    try:
        return declared(KINDS[key].title)
    except KeyError:
        return key


def _when(stamp: str) -> dt.datetime:
    """An ISO time of the register (a record's issue, an entry's recording), comparable: a
    time written without its offset is taken as UTC; one that does not read is the
    earliest (listed last, not dropped)."""
    try:
        when = dt.datetime.fromisoformat(stamp)
    except (TypeError, ValueError):
        return dt.datetime.min.replace(tzinfo=dt.timezone.utc)
    return when if when.tzinfo is not None else when.replace(tzinfo=dt.timezone.utc)


def _recovery_row(entry: dict, numbers: list[str], zone) -> tuple[str, ...]:
    """A loss acknowledged or a clock correction as a row of the register's list (its
    columns: :data:`COLUMNS`): the numbers lost (or the record dated ahead), what it is,
    the day it was recorded in the lab's time zone, and who recorded it and why."""
    from models.register.recoveries import numbers_lost
    from models.register.store import LOSS_ACKNOWLEDGED

    body = entry["body"]
    when = _when(entry["recorded_at"])
    day = when.astimezone(zone).date().isoformat() if when.year > 1 else ""
    by, reason = str(body.get("by", "?")), str(body.get("reason", "?"))
    if entry["kind"] == LOSS_ACKNOWLEDGED:
        lost = numbers_lost(body, numbers)
        return (", ".join(lost) or "—", tr("issued and lost"), "", tr("Loss acknowledged"),
                day, "", "", "", "", tr("recorded by {by}: {reason}").format(
                    by=by, reason=reason), "")
    from models.register.wording import recorded_words

    ahead = translated(recorded_words(str(body.get("ahead", ""))))  # in words, not "entry …"
    return (ahead, tr("dated by a clock set ahead"), "", tr("Clock correction"), day, "", "",
            "", "", tr("recorded by {by}: {reason}; {ahead} was dated {at}").format(
                by=by, reason=reason, ahead=ahead or "?", at=body.get("ahead_at", "?")), "")


def _days(date: str) -> float:
    return float(dt.date.fromisoformat(date).toordinal()) if date else float("nan")


class RegisterPresenter:
    """``open_project_state(project_json, workbench)`` loads a project into the window (it
    asks about unsaved work; False when the user kept it)."""

    def __init__(self, view: RegisterView, certificates: CertificatePresenter,
                 open_project_state: Callable[..., bool]) -> None:
        self.view = view
        self.certificates = certificates
        self.open_project_state = open_project_state
        self.records: list[CertificateRecord] = []
        #: the list's rows in order: a certificate's record, or None for a row that records
        #: a loss or a clock correction
        self.listed: list[CertificateRecord | None] = []
        self.search = ""
        #: the instrument whose history is shown: its serial and manufacturer (#64 review
        #: F6: two makers' items of one serial are two histories)
        self._instrument = ("", "")
        #: what the register was found changed in, as the window last opened or refreshed it:
        #: kept in the window's state line while it holds (day74 #7 a)
        self.held: list = []
        #: the findings told in a box in this window, by register: each told once (day74 #7
        #: a: four identical boxes in one session — on opening, each verify, each refresh)
        self._told: set[tuple[str, str]] = set()

    def _register(self):
        return self.certificates.open_register()

    def refresh(self, search: str | None = None) -> None:
        if search is not None:
            self.search = search
        self.view.show_location(self.certificates.register_url())
        from models.register.record_links import record_links

        recorded: list[tuple[int, tuple[str, ...]]] = []
        same_readings: dict[str, list[str]] = {}
        try:
            with self._register() as register:
                self.records = register.list(self.search)
                for entry in register.same_readings_confirmations():
                    same_readings.setdefault(entry["number"], []).extend(
                        o.get("number", "") for o in entry["others"])
                problems = register.problems
                recoveries = register.recoveries_recorded()
                if recoveries:  # a loss's numbers are written as the register's are
                    # every number (the list shown is a search's, when searched)
                    every = register.list() if self.search else self.records
                    numbers = [r.number for r in every]
                    recorded = [(int(e["seq"]), _recovery_row(
                        e, numbers, register.timezone)) for e in recoveries]
        except RegisterError as exc:
            self.records, problems = [], []
            self.view.tell(tr("Register"), explained(exc))
        self.held = list(problems)
        if search is None:  # checked on opening: said once, not per keystroke
            self._tell_new(problems)
        if search is None and self.records:  # on opening: the stored PDFs, in the background
            self.check_pdfs()
        elif search is None:
            self._show_state([])
        wanted = self.search.casefold().strip()
        recorded = [(when, row) for when, row in recorded
                    if not wanted or wanted in " ".join(row).casefold()]
        # the recoveries among the certificates, newest first, each at its place in the
        # chain (day74 #7 d: after a loss the list showed only the survivors, the gap
        # unexplained)
        self.listed = []
        rows: list[tuple[str, ...]] = []
        for r in self.records:
            while recorded and r.seq is not None and recorded[-1][0] > r.seq:
                rows.append(recorded.pop()[1])
                self.listed.append(None)
            rows.append((r.number, translated(status_words(r.status)),
                         translated(revision_words(r.revision)),
                         translated(kind_words(r.document_kind)), r.issue_date,
                         r.calibration_date, _workbench_title(r.workbench), r.item_serial,
                         r.item_manufacturer or "", r.customer,
                         "; ".join(translated(link) for link in record_links(
                             r, same_readings.get(r.number, ())))))
            self.listed.append(r)
        while recorded:
            rows.append(recorded.pop()[1])
            self.listed.append(None)
        self.view.show_records(COLUMNS, rows)

    def _tell_new(self, problems: list) -> None:
        """The findings not yet told in this window, in one box with the window's recovery
        that answers them (its button above the list); those told before are not told again
        — the window's state line keeps them in sight."""
        url = self.certificates.register_url()
        new = [p for p in problems if (url, str(p)) not in self._told]
        if not new:
            return
        self._told.update((url, str(p)) for p in new)
        pointers = dict.fromkeys(filter(None, (recovery_pointer(p, in_register_window=True)
                                               for p in new)))
        self.view.tell(tr("Register changed after issue"), "\n".join(
            [*(translated(p) for p in new[:20]), *pointers]))

    def _show_state(self, found: list) -> None:
        """The window's state line: what the register was found changed in (it issues
        nothing while that holds), the stored PDFs found changed, or that every stored PDF
        matches its record — that alone only when nothing else is found (regwin74: said of
        a register that refused every issue)."""
        lines, details = [], [translated(p) for p in [*self.held, *found][:20]]
        if self.held:  # short: at 200 % the findings in full hid the list (in the tooltip)
            lines.append(tr("The register issues nothing: it was changed after issue "
                            "(told on opening; point here for what was found)")
                         + (" — " + tr("Acknowledge a loss… records the loss.") if any(
                             recovery_answering(p) == LOSS for p in self.held) else ""))
        if found:
            lines.append(tr("Stored PDFs changed after issue: {problems}").format(
                problems="; ".join(translated(p) for p in found[:3])))
        if lines:
            self.view.show_pdf_check("\n".join(lines), True, "\n".join(details))
        else:
            self.view.show_pdf_check(tr("Every stored PDF matches its record."), False)

    def check_pdfs(self) -> None:
        """Check every stored PDF against the SHA-256 recorded at issue on a worker thread
        (its own connection; the window stays responsive); a mismatch is shown as a warning
        in the register window."""
        from models.register.store import Register

        url, zone = self.certificates.register_url(), self.certificates.lab_timezone()
        self._pdf_check = getattr(self, "_pdf_check", 0) + 1
        ticket = self._pdf_check

        def work() -> list:
            with Register(url, timezone=zone) as register:
                opened = {str(p) for p in register.problems}
                return [p for p in register.audit(pdfs=True) if str(p) not in opened]

        def done(found) -> None:
            if ticket != self._pdf_check:  # a later check (another register) replaced it
                return
            if isinstance(found, BaseException):
                self.view.show_pdf_check(tr("The stored PDFs could not be checked: {reason}")
                                         .format(reason=explained(found)), True)
            else:
                self._show_state(list(found))

        if self.held:  # the register's state stays in sight while the files are checked
            self._show_state([])
        else:
            self.view.show_pdf_check(tr("Checking the stored PDFs…"), False)
        self.view.in_background(work, done)

    def set_location(self, url: str) -> None:
        self.certificates.set_register_url(url)
        self.refresh()

    def selected(self) -> CertificateRecord | None:
        row = self.view.selected_row()
        listed = self.listed
        if 0 <= row < len(listed) and listed[row] is not None:
            return listed[row]
        if 0 <= row < len(listed):
            self.view.tell(tr("Register"), tr(
                "That row records a loss or a clock correction, not a certificate: select a "
                "certificate."))
            return None
        self.view.tell(tr("Register"), tr("Select a certificate first."))
        return None

    # -- actions ---------------------------------------------------------------------
    def open_project(self) -> bool:
        record = self.selected()
        return record is not None and self.open_project_state(record.project_json,
                                                              record.workbench)

    def revise(self, replacement: bool = False) -> bool:
        """Open the project behind the selected certificate; its workbench's next certificate
        then amends (or replaces) it."""
        record = self.selected()
        if record is None:
            return False
        if record.status != "issued":
            self.view.tell(tr("Register"), tr("{number} was superseded by {newer}: amend or "
                                              "replace that one.").format(
                number=record.number, newer=record.superseded_by))
            return False
        # said before the window's work is replaced (rev62 F3: a bare "Save the changes?")
        question = (tr("Replace… opens the readings and details {number} was issued from in "
                       "place of the readings now in the window. Save the window's changes to "
                       "their project first? (Discard: they are lost)") if replacement else
                    tr("Amend… opens the readings and details {number} was issued from in "
                       "place of the readings now in the window. Save the window's changes to "
                       "their project first? (Discard: they are lost)")).format(
            number=record.number)
        if not self.open_project_state(record.project_json, record.workbench, question):
            return False
        self.certificates.start_revision(PendingRevision(record.workbench, record.number,
                                                         replacement))
        text = (tr("The readings and details of {number} are open in place of the window's. "
                   "Change what is needed; File › Export certificate then issues a replacement "
                   "of {number} and asks what changed. Until then the status bar says "
                   "\"Replacing {number}\"; opening another project ends it.") if replacement else
                tr("The readings and details of {number} are open in place of the window's. "
                   "Change what is needed; File › Export certificate then issues an amendment "
                   "to {number} and asks what changed. Until then the status bar says "
                   "\"Amending {number}\"; opening another project ends it."))
        self.view.tell(tr("Register"), text.format(number=record.number))
        return True

    def save_pdf(self) -> bool:
        record = self.selected()
        if record is None:
            return False
        path = self.view.ask_pdf_path(f"{record.number.replace('/', '-')}.pdf")
        if not path:
            return False
        from models.project.atomic_write import write_bytes_atomic
        from models.project.output_guard import check_output

        try:
            check_output(path, self.certificates.protected())
            # nor a file the register issued (rev64 F1: a certificate's PDF saved over another
            # certificate's results file, the only copy, replaced it)
            self.certificates.refuse_issued(path)
            with self._register() as register:
                write_bytes_atomic(path, register.pdf(record.number))
        except (RegisterError, OSError) as exc:
            self.view.tell(tr("Cannot save"), explained(exc))
            return False
        return True

    def print_pdf(self) -> int:
        """Print the selected certificate as it was issued (its PDF from the register)."""
        record = self.selected()
        if record is None:
            return 0
        try:
            with self._register() as register:
                pdf = register.pdf(record.number)
            return self.view.print_certificate(pdf, record.number)
        except (RegisterError, OSError) as exc:
            self.view.tell(tr("Cannot print"), explained(exc))
            return 0

    def verify_pdf(self) -> CertificateRecord | None:
        """A PDF chosen by the user: the record that issued it, byte for byte, and what the
        register says of the place its printed head gives it — the findings of ``anglebench
        register verify FILE.pdf`` (models/register/printed_place.py): a record deleted
        after issue is named by that head and recorded as missing when the register can be
        written; another record in its place is said; a record found whose chain before it
        was rewritten is said."""
        from models.register.printed_place import (
            ALTERED_COPY,
            ALTERED_INTACT_RECORD,
            ALTERED_OR_REPLACED,
            content_changed,
            digest_missing,
            head_before_changed,
            in_this_chain,
            lost_and_acknowledged,
            record_lost,
            say_its_place,
        )

        path = self.view.ask_pdf_to_verify()
        if not path:
            return None
        findings: list = []
        try:
            with open(path, "rb") as handle:
                data = handle.read()
            with self._register() as register:
                found = register.verify_all(data)
                problems = register.audit(pdfs=True)  # the stored PDFs too, on demand
                if register.key_problem is not None:  # a setting, not a forgery (reg73 #7)
                    self.view.tell(tr("Not the register's key"),
                                   translated(register.key_problem))
                lost = False
                if len(found) == 1:
                    moved = head_before_changed(register, path, data, found[0])
                    findings += [moved] if moved is not None else []
                    # its record rewritten since (the content digest it carries: reg72 #2)
                    rewritten = content_changed(register, path, data, found[0])
                    findings += [rewritten] if rewritten is not None else []
                    stripped = digest_missing(path, data, found[0])
                    findings += [stripped] if stripped is not None else []
                elif not found and lost_and_acknowledged(register, path, data,
                                                         findings.append):
                    lost = True  # issued before a loss recorded since (reg73 #5)
                elif not found and record_lost(register, data):
                    lost = True  # issued here, its record gone: not a forgery (reg72 #1)
                    say_its_place(register, path, data, findings.append)
                elif not found and in_this_chain(register, data):
                    # it prints a head of this chain, so its record followed it: is it gone?
                    say_its_place(register, path, data, findings.append)
        except (OSError, RegisterError) as exc:
            self.view.tell(tr("Cannot verify"), explained(exc))
            return None
        self._tell_new(problems)  # what this window told before is not told again
        said = "".join("\n" + translated(line) for line in findings)
        record = found[0] if len(found) == 1 else None
        if len(found) > 1:
            self.view.tell(tr("Not in the register"), tr(
                "{path}: its SHA-256 is in {n} records ({numbers}): a certificate is issued "
                "once, so all but one were copied into the register after issue.").format(
                path=path, n=len(found), numbers=", ".join(r.number for r in found)))
        elif record is None and lost:
            self.view.tell(tr("Register changed after issue"), tr(
                "{path} was issued by this register, but the register has LOST its record."
                ).format(path=path) + said)
        elif record is None and (place := next(
                (getattr(line, "template", "") for line in findings if getattr(
                    line, "template", "") in (ALTERED_COPY, ALTERED_INTACT_RECORD,
                                              ALTERED_OR_REPLACED)), None)):
            # its number's record is at its place with another content: the copy was
            # altered after issue (or, without the key's proof, the record replaced), as
            # ``register verify`` says — not "not in the register", a draft or another
            # register's
            self.view.tell(tr("Changed after issue") if place == ALTERED_OR_REPLACED
                           else tr("Altered after issue"), said.lstrip("\n"))
        elif record is None:
            self.view.tell(tr("Not in the register"), tr(
                "{path}: no certificate issued from this register has this PDF (SHA-256): it "
                "was altered, is a draft, or comes from another register.").format(path=path)
                + said)
        else:
            self.view.tell(tr("Register changed after issue") if findings else tr("Verified"), tr(
                "{path} is certificate {number} as issued on {date} ({status}), byte for byte.")
                .format(path=path, number=record.number, date=record.issued_at,
                        status=translated(status_words(record.status)))
                + ("" if not record.superseded_by else "\n" + tr(
                    "It is no longer valid: superseded by {by}.").format(by=record.superseded_by))
                + ("" if record.status != "withdrawn" else "\n" + tr(
                    "It is no longer valid: withdrawn ({reason}).").format(
                    reason=record.withdrawn_reason or "—")) + said)
        return record

    # -- the recorded recoveries (models/register/recoveries.py) ----------------------------
    def acknowledge_loss(self) -> None:
        """As ``anglebench register acknowledge-loss``: asks who, why, the last number known
        issued (required where the register has no signed high-water mark to tell it) and
        its scheme; records them with Register.acknowledge_loss, says what was recorded, or
        shows the register's refusal in the dialog."""
        try:
            with self._register() as register:
                last_number_needed = not register.high_water_mark()
        except RegisterError as exc:
            self.view.tell(tr("Register"), explained(exc))
            return

        def record(typed: LossTyped) -> str:
            from models.register.recoveries import loss_recorded

            try:
                with self._register() as register:
                    body = register.acknowledge_loss(typed.by, typed.reason, typed.last_number,
                                                     typed.scheme)
                    said, left = loss_recorded(body, register.chain_head()), register.problems
            except (RegisterError, OSError) as exc:
                return as_sentence(explained(exc))  # the command's words, opening the line
            self._recorded(tr("Loss recorded"), said, left)
            return ""

        self.view.ask_loss(last_number_needed, record)

    def correct_clock(self) -> None:
        """As ``anglebench register clock-correction``: asks who, why and today's date
        (typed: the confirmation); records them with Register.correct_clock, says what was
        recorded, or shows the register's refusal in the dialog."""
        def record(typed: CorrectionTyped) -> str:
            from models.register.clock_rules import parse_confirmed_date
            from models.register.recoveries import clock_corrected

            try:
                with self._register() as register:
                    body = register.correct_clock(typed.by, typed.reason,
                                                  parse_confirmed_date(typed.confirmed_date))
                    left = register.problems
            except (RegisterError, OSError) as exc:
                return as_sentence(explained(exc))  # the command's words, opening the line
            self._recorded(tr("Clock correction recorded"), clock_corrected(body), left)
            return ""

        self.view.ask_clock_correction(record)

    def _recorded(self, title: str, said, left: list) -> None:
        """What was recorded, with any finding the register still holds (it still refuses
        issuing for those), then the list again."""
        self.view.tell(title, "\n".join([as_sentence(translated(said)), *(
            tr("Still found: {problem}").format(problem=translated(p)) for p in left[:20])]))
        self.refresh(self.search)

    def show_history(self) -> None:
        record = self.selected()
        if record is None or not record.item_serial:
            return
        self._history(record.item_serial, record.item_manufacturer or "")

    def _history(self, serial: str, manufacturer: str = "") -> None:
        self._instrument = (serial, manufacturer)
        with self._register() as register:
            records = register.history(serial, manufacturer)
            due = register.due_date(serial, manufacturer)
            interval = register.interval(serial, manufacturer) or 0
            makers = register.maker_needed(serial, manufacturer)
        series: dict[str, tuple[list[float], list[float]]] = {}
        for r in records:
            for name, value in r.headline.items():
                xs, ys = series.setdefault(name, ([], []))
                xs.append(_days(r.calibration_date or r.issue_date))
                ys.append(value)
        # a named maker's history holds the serial's certificates naming no maker: said
        # (rev65: a reader took them for that maker's)
        makerless = tuple(r.calibration_date or r.issue_date for r in records
                          if manufacturer.strip() and not (r.item_manufacturer or "").strip())
        self.view.show_history(serial, series, [r.calibration_date for r in records],
                               due.isoformat() if due else "", interval, makers,
                               " ".join(manufacturer.split()), makerless)

    def set_interval(self, serial: str, days: int) -> None:
        """The interval of the instrument whose history is shown: its serial's item of its
        certificate's manufacturer (stop 63: set per serial, two makers' "001" shared it)."""
        shown, manufacturer = self._instrument
        manufacturer = manufacturer if shown == serial else ""
        try:
            with self._register() as register:
                register.set_interval(serial, days or None, manufacturer)
        except RegisterError as exc:
            self.view.tell(tr("Register"), explained(exc))
            return
        self._history(serial, manufacturer)
