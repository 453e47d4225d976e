"""The window's side of the certificate presenter (app/certificate_presenter.py): the
certificate dialog, the questions before a certificate is issued, the file dialog, the
wait cursor and the status bar.

Questions and messages go through the window's ``ask`` and ``tell`` so tests can answer
them."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QInputDialog,
    QLabel,
    QMessageBox,
)

from models.certificate.metadata import CertificateMetadata
from models.messages import as_sentence
from models.register.serial_differences import differences_named, serial_difference
from widgets.certificate_dialog import CertificateDialog
from widgets.i18n import tr, translated
from widgets.save_file import ask_save_file
from widgets.screen_fit import fit_to_screen
from widgets.unbroken_identifiers import unbroken

__all__ = ["LISTED_LOOKALIKES", "CertificateDialogs", "as_sentence", "lookalikes_listed"]

#: the earlier serials a look-alike question lists, one a line; the others are counted
LISTED_LOOKALIKES = 3


def lookalikes_listed(serial: str, lookalikes) -> str:
    """The facts of a look-alike question about ``serial`` with several earlier serials
    (``lookalikes``: each serial with the numbers of its certificates): a line each, its
    characters that differ from ``serial`` in brackets, at most :data:`LISTED_LOOKALIKES`,
    then how many more, and the characters that print alike named once (day review 68
    F11: with three look-alikes the question was a paragraph of 16 lines comparing the
    serial with each in turn). No "." at its end (the question's template puts it)."""
    shown = list(lookalikes[:LISTED_LOOKALIKES])
    out = [tr("Serial {serial} is in no certificate of the register, but looks like these "
              "serials (the characters that differ in brackets):").format(serial=serial)]
    for kept, numbers in shown:
        out.append(tr("• {serial} ({numbers})").format(
            serial=serial_difference(serial, kept).other_marked, numbers=", ".join(numbers)))
    if len(lookalikes) > LISTED_LOOKALIKES:
        out.append(tr("• and {count} more").format(count=len(lookalikes) - LISTED_LOOKALIKES))
    named = translated(differences_named(serial, [kept for kept, _numbers in shown]))
    out.append(tr("{differences}. If it is one of those items with its serial mistyped, a "
                  "certificate under this serial would split its history and due date").format(
                      differences=as_sentence(named)))
    return "\n".join(out)


class CertificateDialogs:
    """:class:`app.certificate_presenter.CertificateView` for ``window`` (the main window;
    its ``certificates`` is the presenter, its ``projects`` knows the last folder used)."""

    def __init__(self, window: Any) -> None:
        self.window = window

    def edit_certificate_details(self, meta: CertificateMetadata, problems: dict[str, str],
                                 raw: dict) -> CertificateMetadata | None:
        dialog = CertificateDialog(meta, self.window,
                                   timezone=self.window.certificates.lab_timezone())
        dialog.lab_defaults_saved.connect(self.window.certificates.save_lab_defaults)
        dialog.lab_timezone_set.connect(self.window.certificates.set_lab_timezone)
        dialog.set_dcc_options(*self.window.certificates.dcc_options())
        dialog.set_dcc_signing_paths(*self.window.certificates.dcc_signing_paths())
        # a DCC of this lab's own read in only as issued and current (hostile78 F4)
        dialog.dcc_register_url = self.window.certificates.register_url
        # what the certificate will say of where its readings came from (day review 67 F7)
        dialog.set_readings_line(getattr(self.window.certificates, "readings_line", ""))
        if problems:  # a stored detail that no longer reads: shown as stored, marked
            dialog.show_problems(problems, raw)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            # saved as lab defaults, then cancelled: what was typed is not lost
            if dialog.saved_details is not None:
                self.window.certificates.keep_details(dialog.saved_details)
            return None
        self.window.certificates.set_dcc_options(*dialog.dcc_options())
        self.window.certificates.set_dcc_signing_paths(*dialog.dcc_signing_paths())
        return dialog.metadata()

    def confirm_draft(self, missing: list[str], report: bool = False) -> bool:
        # a test report's draft is not a test report (not "not a certificate")
        said = (tr("These details are missing: {missing}. The PDF will be marked DRAFT, is "
                   "not a test report, and nothing is recorded in the register. Export the "
                   "draft anyway?") if report else
                tr("These details are missing: {missing}. The PDF will be marked DRAFT, is not "
                   "a certificate, and nothing is recorded in the register. Export the draft "
                   "anyway?"))
        return self._yes(
            tr("Export a draft?"), said.format(missing=", ".join(tr(m) for m in missing)))

    def confirm_correction(self, revision, reason: str) -> bool:
        """Another serial number or date of calibration than the certificate amended: a
        correction of it (stated on it)? (rev62 F1)"""
        question = (tr("{reason}.\n\nIs this replacement a correction of {number}'s serial "
                       "number or date of calibration? Yes: issue it, the correction stated on "
                       "it. No: nothing is issued, and the next certificate is an original.")
                    if revision.replacement else
                    tr("{reason}.\n\nIs this amendment a correction of {number}'s serial "
                       "number or date of calibration? Yes: issue it, the correction stated on "
                       "it. No: nothing is issued, and the next certificate is an original."))
        return self._yes(
            tr("Correct the serial number or date of calibration?"),
            question.format(reason=as_sentence(reason), number=revision.number))

    def confirm_test_report(self, reasons: list[str]) -> bool:
        return self._yes(
            tr("A test report, not a calibration certificate"),
            tr("These details and this result give a test report, not a calibration "
               "certificate: traceability to the SI cannot be stated.\n\n{reasons}\n\nIssue "
               "it as a test report? (No: nothing is written; state the missing inputs in the "
               "workbench's set-up, or the standards in the details, to issue a calibration "
               "certificate)").format(reasons="\n".join(f"• {r}" for r in reasons)))

    def confirm_implausible(self, reason: str) -> bool:
        return self._yes(
            tr("Certify these figures?"),
            tr("{reason}\n\nIssue a certificate on this result anyway? Only if you have "
               "checked the readings and the figures are right.").format(reason=reason))

    def confirm_standards(self, warnings: list[str]) -> bool:
        """A reference standard that looks like another test's: go on with it?"""
        return self._yes(
            tr("Use these reference standards?"),
            tr("{warnings}\n\nIssue the certificate with them anyway? (No: back to the "
               "details)").format(warnings="\n".join(warnings)))

    def ask_change_note(self, revision) -> str:
        question = (tr("This certificate replaces {number}. What changed, and why? (printed on "
                       "the certificate; ISO/IEC 17025 7.8.8)") if revision.replacement else
                    tr("This certificate amends {number}. What changed, and why? (printed on "
                       "the certificate; ISO/IEC 17025 7.8.8)"))
        # wrapped and fitted (QInputDialog.getMultiLineText's label does not wrap: 705 px
        # wide at 200 % on a 1280×720 laptop, 640 logical)
        return self._multiline_answer(tr("What changed"), question.format(number=revision.number))

    def confirm_another_maker(self, numbers, reason: str) -> bool:
        """A current certificate of the serial and date names another manufacturer: is this
        another maker's item? (rev65 F1; the answer Yes is recorded in the register)"""
        return self._yes(tr("Another manufacturer's item?"), tr(
            "{reason}.\n\nIs this item another manufacturer's than that of {numbers}? Yes: "
            "issue it; the register records that you said so. No: nothing is issued (to "
            "correct {numbers}, amend or replace it from File › Certificate register).")
            .format(reason=as_sentence(reason), numbers=", ".join(numbers)))

    def confirm_issue_date(self, date: str, reason: str) -> bool:
        """The issue is dated far after the register's last record (reg73 #6): is today
        ``date``? (the answer Yes is recorded in the register; No: nothing is issued)"""
        return self._yes(tr("Is today {date}?").format(date=date), tr(
            "{reason}.\n\nIs today {date}? Yes: issue it dated {date}; the register records "
            "that you confirmed the date. No: nothing is issued; correct the computer's "
            "clock.").format(reason=as_sentence(reason), date=date))

    def confirm_lookalike_serial(self, question) -> bool:
        """The serial is new to the register but looks like the serial of
        ``question.numbers`` (a :class:`models.register.store.LookalikeSerial`), or the item
        has none beside that day's item with one: is this another item? (rev65 F7; the
        answer Yes is recorded in the register). Asked from the register's facts, the
        differing characters marked, without the command line's option (day review 67 F6)."""
        serial = getattr(question, "serial", "")
        lookalikes = getattr(question, "lookalikes", ())
        facts: str
        asked: str
        if len(lookalikes) > 1:  # one a line, at most a few (day review 68 F11)
            facts, asked = lookalikes_listed(serial, lookalikes), tr(
                "Is {serial} a different item from each of them?").format(serial=serial)
        else:
            facts = as_sentence(translated(question.facts))
            asked = translated(question.question)
        marked = [serial_difference(serial, kept) for kept, _numbers in lookalikes]
        return self._yes(tr("Another item?"), unbroken(tr(
            "{facts}.\n\n{question} Yes: issue it; the register records that you said so. "
            "No: nothing is issued. {advice}").format(
                facts=facts, question=asked, advice=translated(question.advice)),
            [serial, *(kept for kept, _n in lookalikes), *(d.one_marked for d in marked),
             *(d.other_marked for d in marked)]))

    def _yes(self, title: str, text: str) -> bool:
        """Whether the user answers Yes to ``text`` (No the default: nothing is done)."""
        answer = self.window.ask(title, text,
                                 QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
                                 QMessageBox.StandardButton.No)
        return answer == QMessageBox.StandardButton.Yes

    def ask_separate_calibration(self, numbers, reason: str) -> str:
        return self._multiline_answer(tr("A calibration already reported"), tr(
            "{reason}.\n\nIf this is a calibration of its own, say why (printed on the "
            "certificate with the number of {numbers}, which stays valid); to correct {numbers}, "
            "cancel and amend or replace it from File › Certificate register.").format(
                reason=as_sentence(reason), numbers=", ".join(numbers)))

    def ask_readings_of_another_item(self, numbers, reason: str) -> str:
        return self._multiline_answer(tr("Readings of another item"), tr(
            "{reason}.\n\nIf these readings are indeed this item's, say why: printed on the "
            "certificate with the number, item and date of calibration of {numbers}, and "
            "recorded in the register. Otherwise cancel, and issue it from this item's own "
            "readings.").format(reason=as_sentence(reason), numbers=", ".join(numbers)))

    def ask_same_readings(self, numbers, reason: str) -> str:
        return self._multiline_answer(tr("The same calibration issued again"), tr(
            "{reason}.\n\nIf these are indeed the readings of a calibration of its own, say "
            "why: stated on the certificate and recorded in the register. Otherwise cancel: "
            "the copy of {numbers} is its PDF (Save PDF… in File › Certificate register), and "
            "a correction is its amendment or replacement.").format(
                reason=as_sentence(reason), numbers=", ".join(numbers)))

    def _multiline_answer(self, title: str, question: str) -> str:
        """A question answered in a few lines of text ("" when cancelled), its words wrapped
        and the dialog no wider than the screen (QInputDialog's own label does not wrap: the
        register's refusal made it 2096 px wide on a 1280 px screen)."""
        dialog = QInputDialog(self.window)
        dialog.setWindowTitle(title)
        dialog.setLabelText(question)
        dialog.setOption(QInputDialog.InputDialogOption.UsePlainTextEditForTextInput)
        for label in dialog.findChildren(QLabel):
            label.setWordWrap(True)
        fit_to_screen(dialog, 560 * dialog.logicalDpiX() // 96, dialog.sizeHint().height())
        return dialog.textValue() if dialog.exec() == QDialog.DialogCode.Accepted else ""

    def choose_save_path(self, title: str, suggested: str, file_filter: str) -> str:
        """The name written, with the chosen type's extension; a file of that name is not
        replaced unasked (the file dialog asked about the name as typed)."""
        return ask_save_file(self.window, title,
                             str(Path(self.window.projects.last_dir()) / suggested), file_filter,
                             self.window.ask)

    def tell(self, title: str, text: str) -> None:
        self.window.tell(title, text)

    def show_status(self, text: str, milliseconds: int) -> None:
        """A message of the certificate (issued, a draft, results written, a standard left
        out) is the workbench's in front, whose certificate it is: shown on its tab only, as
        a workbench's status message is (day review 74 F15: "Certificate … issued" of the
        polygon stayed on the Fringe tab)."""
        window = self.window
        bar = window.statusBar()
        of_workbench = getattr(window, "show_workbench_status", None)
        if of_workbench is not None and getattr(window, "presenters", None):
            of_workbench(window.current, text, milliseconds)
        else:
            bar.showMessage(text, milliseconds)
        # painted now: the register may be about to wait for another's lock on this thread
        # (no event is handled meanwhile, so nothing else can run)
        bar.repaint()

    def wait_cursor(self, on: bool) -> None:
        if on:
            QApplication.setOverrideCursor(Qt.CursorShape.WaitCursor)
        else:
            QApplication.restoreOverrideCursor()
