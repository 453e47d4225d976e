"""Certificate control: each workbench's certificate details, the lab's defaults, the
export of the certificate through the register (which allocates its number and keeps
the record), amendments and replacements, and the export of the results.

A presenter with no widgets: it asks its view (the calls of :class:`CertificateView`;
in the window, app/certificate_dialogs.py) for the details, for a file name, and to
tell the user something; it keeps the details in the project's metadata and the lab's
defaults in the settings store. Tested with a mock view, no window.
"""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Callable, MutableMapping
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Protocol

from app.issued_outputs import refuse_issued_outputs
from app.writers.results_export import write_results_csv, write_results_xlsx
from models.certificate.metadata import CertificateMetadata, MetadataError, readable_standards
from models.certificate.standards_fit import (
    STANDARDS_BY_WORKBENCH,
    standards_fit,
    standards_for,
    with_workbench_standards,
)
from models.display_units import ANGLE_UNITS, AngleUnit
from models.messages import as_sentence
from models.project.output_guard import check_output
from models.register.wording import revision_words
from models.workbench import IssuesCertificates
from widgets.i18n import explained, joined, tr, translated

if TYPE_CHECKING:
    from models.register.store import LookalikeSerial

__all__ = ["CertificatePresenter", "CertificateView", "PendingRevision"]

LAB_DEFAULTS_KEY = "certificate/lab_defaults"
#: the keys of ``problems`` that name a stored standard left out (the others kept): of the
#: workbench's stored details, of the lab defaults (models.certificate.metadata.readable_standards)
SKIPPED_STANDARD_KEYS = ("standards[", "lab_defaults.standards[")
#: the lab defaults' key of the test plans, per workbench ({workbench: {plan_…: value}})
TEST_PLANS = "test_plans"
#: the lab's signal tolerance presets (models/fringe/signal_tolerance.py LAB_DEFAULTS_KEY)
SIGNAL_PRESETS = "signal_tolerance_presets"


def _not_issued_after_no(question: LookalikeSerial) -> str:
    """What the window says after a No to a look-alike serial's question: nothing issued,
    and what to do instead — not the question's reasons again, nor its advice for a Yes
    (day review 67 F6)."""
    return tr("No certificate was written or recorded. {advice}").format(
        advice=translated(question.advice))


def _refusal(path: str, reason: str, with_path: str, without_path: str) -> str:
    """Why an export to ``path`` was refused, naming the file once: ``with_path`` ("{path}:
    {reason}. …") unless ``reason`` names it already (a file the register issued: "… .pdf
    is the PDF of certificate …"; day review 68 F12: the path was said twice), then
    ``without_path``."""
    if path and path in reason:  # the reason a sentence of its own (day 68 F9)
        return without_path.format(reason=as_sentence(reason))
    return with_path.format(path=path, reason=reason)


def plan_settings_of(settings: dict) -> dict:
    """The settings of a workbench's test (entry) plan: its ``plan_…`` settings."""
    return {k: v for k, v in settings.items() if k.startswith("plan_")}
#: details typed for one workbench that the next workbench's certificate is offered
SHARED_DETAILS = ("lab_name", "lab_address", "lab_accreditation", "customer_name",
                  "customer_address", "operator", "approver", "calibration_date",
                  "temperature_c", "humidity_pct")
REGISTER_KEY = "register/url"  # empty: the SQLite file in the user's data folder
#: the lab's time zone (an IANA name; empty: ANGLEBENCH_TIMEZONE, else the system's): the
#: date of issue is the lab's local date
TIMEZONE_KEY = "certificate/lab_timezone"
DCC_KEY = "certificate/write_dcc"  # also write the DCC (XML) beside every PDF
DCC_SCHEMA_KEY = "certificate/dcc_schema_dir"  # before #43's review: read when the lab defaults lack it
#: the lab's DCC settings, kept with the lab defaults (paths only: never a key's content):
#: PTB's schema folder (empty: not validated), the signing key and its X.509 certificate
#: (PEM files; empty: the environment's, else unsigned), the certificate a signature read
#: in is checked against (empty: the environment's)
DCC_SCHEMA = "dcc_schema_dir"
DCC_SIGNING = ("dcc_signing_key", "dcc_signing_certificate", "dcc_trusted_certificate")


@dataclass(frozen=True)
class PendingRevision:
    """The next certificate of ``workbench`` amends (or replaces) ``number``."""

    workbench: str
    number: str
    replacement: bool = False


class CertificateView(Protocol):
    """What the certificate presenter asks of the window (app/certificate_dialogs.py)."""

    def edit_certificate_details(self, meta: CertificateMetadata, problems: dict[str, str],
                                 raw: dict) -> CertificateMetadata | None:
        """The details entered (None if cancelled)."""

    def ask_change_note(self, revision: PendingRevision) -> str:
        """What changed and why (empty: cancel the amendment's export)."""

    def ask_separate_calibration(self, numbers: tuple[str, ...], reason: str) -> str:
        """``numbers`` report the item and date of calibration already (``reason``, the
        register's words): why this is a calibration of its own (empty: not issued)."""

    def confirm_another_maker(self, numbers: tuple[str, ...], reason: str) -> bool:
        """``numbers`` report the serial and date of calibration under another
        manufacturer's name (``reason``): is this another maker's item? (recorded when
        issued; No: not issued)"""

    def confirm_lookalike_serial(self, question: LookalikeSerial) -> bool:
        """The serial is in no certificate of the register but looks like that of
        ``question.numbers``, or the item has none beside that day's item of its
        description with one (``question``: the register's facts, question and advice): is
        this another item? (recorded when issued; No: not issued)"""

    def ask_readings_of_another_item(self, numbers: tuple[str, ...], reason: str) -> str:
        """The readings are those of certificates ``numbers`` of another item (``reason``,
        the register's words): why they are this item's (printed on the certificate and
        recorded in the register; empty: not issued)."""

    def ask_same_readings(self, numbers: tuple[str, ...], reason: str) -> str:
        """A calibration of its own whose readings (each within the last digit it was typed
        to) and details are those of the current certificates ``numbers`` of its item and
        date (``reason``, the register's words): why it is nevertheless a calibration of its
        own (stated on it and recorded in the register; empty: not issued)."""

    def confirm_issue_date(self, date: str, reason: str) -> bool:
        """The issue is dated far after the register's last record (``reason``): is today
        ``date``? (recorded when issued; No: not issued)"""

    def confirm_correction(self, revision: PendingRevision, reason: str) -> bool:
        """An amendment or replacement with another serial number or date of calibration
        than ``revision.number``'s: a correction of it (stated on it)? No: not an amendment."""

    def confirm_test_report(self, reasons: list[str]) -> bool:
        """The certificate asked for will be a test report (``reasons``: why traceability
        is not established): go on? (No: back, nothing written)"""

    def confirm_draft(self, missing: list[str], report: bool = False) -> bool:
        """Export a DRAFT although these details are missing? (``report``: a test report's
        draft, called one)"""

    def confirm_implausible(self, reason: str) -> bool:
        """Certify a result that shows figures no instrument of the kind has (``reason``)?"""

    def confirm_standards(self, warnings: list[str]) -> bool:
        """Go on with reference standards that look like another test's (``warnings``)?"""

    def choose_save_path(self, title: str, suggested: str, file_filter: str) -> str: ...

    def tell(self, title: str, text: str) -> None: ...

    def show_status(self, text: str, milliseconds: int) -> None: ...

    def wait_cursor(self, on: bool) -> None: ...


class SettingsStore(Protocol):
    def value(self, key: str, default: Any = None) -> Any: ...

    def setValue(self, key: str, value: Any) -> None: ...  # noqa: N802 - QSettings' name


class CertificatePresenter:
    """``metadata`` is the project's metadata dict (the details are saved with the
    project); ``mark_modified`` tells the project it changed."""

    def __init__(self, view: CertificateView, store: SettingsStore,
                 metadata: Callable[[], MutableMapping[str, Any]],
                 mark_modified: Callable[[], None]) -> None:
        self.view = view
        self.store = store
        self._metadata = metadata
        self._mark_modified = mark_modified
        self.problems: dict[str, str] = {}  # stored details that no longer read
        #: the "Readings:" line of the certificate being asked for, which its details dialog
        #: shows ("" none)
        self.readings_line: str = ""
        # per workbench, the stored standards left out that the status last said
        self._skipped_said: dict[str, tuple[str, ...]] = {}
        self.raw: dict = {}
        #: the pending amendment or replacement changed (the window shows it: rev62 F3)
        self.revision_changed: Callable[[], None] = lambda: None
        #: a certificate was issued (workbench, number) with details its issue stored in
        #: the project, changed (the project's: app/project_presenter.py details_issued)
        self.details_issued: Callable[[str, str], None] = lambda _key, _number: None
        #: the number of the certificate the last issue recorded ("" none)
        self.last_issued: str = ""
        self._pending: PendingRevision | None = None
        # the language of a certificate whose details do not name one: the window's
        # ("zh" in a Chinese window; the main window sets it)
        self.default_language = "en"
        #: the project open in the window (the main window sets it): no export may replace it
        self.open_project_path: Callable[[], Any] = lambda: None
        #: the readings files imported in this window (the main window sets it): inputs too
        self.inputs: Callable[[], list] = list
        #: the workbench whose details were last asked for ("" before any)
        self.editing = ""
        #: a workbench's settings now (the main window sets it): its test plan is saved
        #: with the lab defaults
        self.workbench_settings: Callable[[str], dict] = lambda _key: {}
        #: a workbench's details were changed (the main window redraws its plots: ±T, U)
        self.details_changed: Callable[[str], None] = lambda _key: None
        #: the lab defaults were saved (the main window redraws every workbench's plots: their
        #: U bands are drawn with the details the certificate would use, the defaults in)
        self.lab_defaults_changed: Callable[[], None] = lambda: None

    @property
    def pending(self) -> PendingRevision | None:
        """The amendment or replacement the next certificate of its workbench issues."""
        return self._pending

    @pending.setter
    def pending(self, revision: PendingRevision | None) -> None:
        changed = revision != self._pending
        self._pending = revision
        if changed:
            self.revision_changed()

    def pending_words(self) -> str:
        """The pending amendment or replacement as the window shows it until it is issued
        or ended ("" when none): rev62 F3, nothing on screen said the next export amends."""
        if self._pending is None:
            return ""
        return (tr("Replacing {number}") if self._pending.replacement else
                tr("Amending {number}")).format(number=self._pending.number)

    # -- the lab's defaults ------------------------------------------------------
    def lab_defaults(self, workbench: str = "") -> dict:
        """The lab's saved defaults; for ``workbench``, with that workbench's own reference
        standards (models/certificate/standards_fit.py: never another workbench's)."""
        text = self.store.value(LAB_DEFAULTS_KEY, "")
        try:
            data = json.loads(text) if text else {}
        except (TypeError, ValueError):
            data = {}
        data = data if isinstance(data, dict) else {}
        if workbench:
            data = {k: v for k, v in data.items() if k != STANDARDS_BY_WORKBENCH}
            data["standards"] = standards_for(self.lab_defaults(), workbench) or []
        return data

    def save_lab_defaults(self, defaults: dict, workbench: str = "") -> None:
        """The lab fields of a certificate's details kept as the lab's defaults; the
        reference standards as those of ``workbench`` (else of the workbench whose details
        were last asked for), the other workbenches' kept."""
        workbench = workbench or self.editing
        stored = self.lab_defaults()
        if workbench:
            defaults = with_workbench_standards(stored, defaults, workbench)
        # the test plans: the workbench's as set now, the others' kept (a new project
        # starts with them, test_plan)
        plans = dict(stored.get(TEST_PLANS) or {})
        if workbench:
            plans[workbench] = plan_settings_of(self.workbench_settings(workbench))
        if plans:
            defaults = {**defaults, TEST_PLANS: plans}
        # the lab's signal tolerance presets (#45) are kept: the certificate's dialog does not
        # hold them
        if SIGNAL_PRESETS in stored and SIGNAL_PRESETS not in defaults:
            defaults = {**defaults, SIGNAL_PRESETS: stored[SIGNAL_PRESETS]}
        # so are the lab's DCC settings (set beside the details: set_dcc_options)
        for key in (DCC_SCHEMA, *DCC_SIGNING):
            if key in stored and key not in defaults:
                defaults = {**defaults, key: stored[key]}
        self.store.setValue(LAB_DEFAULTS_KEY, json.dumps(defaults, ensure_ascii=False))
        self.lab_defaults_changed()

    def save_lab_defaults_entry(self, key: str, value: Any) -> None:
        """One entry of the lab defaults set, the others kept: a workbench's own (e.g. the
        fringe workbench's signal tolerance presets, models/fringe/signal_tolerance.py)."""
        data = {**self.lab_defaults(), key: value}
        self.store.setValue(LAB_DEFAULTS_KEY, json.dumps(data, ensure_ascii=False))

    def test_plan(self, workbench: str) -> dict:
        """The test plan's settings saved with the lab defaults for ``workbench`` ({}: none)."""
        plans = self.lab_defaults().get(TEST_PLANS)
        plan = plans.get(workbench) if isinstance(plans, dict) else None
        return plan_settings_of(plan) if isinstance(plan, dict) else {}

    # -- a workbench's details -----------------------------------------------------
    def details(self, key: str) -> CertificateMetadata:
        """The workbench's details from the project, the lab's defaults filled in; a stored
        detail that no longer reads is kept aside (``problems``), not the others blanked."""
        self.editing = key  # the lab defaults saved from its dialog are this workbench's
        meta, self.problems, self.raw = self._details_of(key)
        return meta

    def issue_details(self, key: str) -> CertificateMetadata:
        """The details a certificate of workbench ``key`` starts from now (its dialog's, as
        :meth:`details`), without taking ``key`` as the workbench being edited: what a
        figure sent or written as the certificate states it is made with."""
        return self._details_of(key)[0]

    def _details_of(self, key: str) -> tuple[CertificateMetadata, dict[str, str], dict]:
        certificates = self._metadata().get("certificates", {})
        stored = certificates.get(key)
        last = certificates.get(self._metadata().get("certificates_last", ""))
        if stored is None and isinstance(last, dict):  # offered what was typed for another
            stored = {k: last[k] for k in SHARED_DETAILS if k in last}
        meta, problems = CertificateMetadata.from_dict_lenient(stored)
        raw = stored if isinstance(stored, dict) else {}
        if "language" not in raw:
            meta = dataclasses.replace(meta, language=self.default_language)
        merged, skipped = self._with_lab_defaults(meta, key)
        problems = {**problems, **skipped}
        self._say_skipped(key, [text for name, text in problems.items()
                                if name.startswith(SKIPPED_STANDARD_KEYS)])
        return merged, problems, raw

    def _with_lab_defaults(self, meta: CertificateMetadata, key: str
                           ) -> tuple[CertificateMetadata, dict[str, str]]:
        """``meta`` with workbench ``key``'s lab defaults filled in, and the lab defaults'
        standards that do not read (each by itself, keyed ``lab_defaults.standards[N]``): one
        bad entry leaves out itself only, where it dropped every lab default unseen."""
        lab = self.lab_defaults(key)
        skipped: dict[str, str] = {}
        if "standards" in lab:
            lab["standards"], bad = readable_standards(lab["standards"], lab_defaults=True)
            if not meta.standards:  # only then do the lab defaults' standards fill them in
                skipped = {f"lab_defaults.{name}": text for name, text in bad.items()}
        try:
            return meta.with_lab_defaults(lab), skipped
        except MetadataError:
            return meta, skipped

    def _say_skipped(self, key: str, texts: list[str]) -> None:
        """The window's status says which stored standards were left out and why, once for
        each new set (the details are read on every redraw of the plots)."""
        said = tuple(texts)
        if said and said != self._skipped_said.get(key):
            self.view.show_status(joined("; ", (translated(t) for t in texts)), 20000)
        self._skipped_said[key] = said

    def stored_details(self, key: str) -> CertificateMetadata | None:
        """The details stored for workbench ``key``, the lab's defaults filled in, as its
        certificate would be made with them now (nothing else changed: the plots' tolerance
        band reads them); None when none are stored."""
        stored = self._metadata().get("certificates", {}).get(key)
        if not isinstance(stored, dict):
            return None
        meta, _problems = CertificateMetadata.from_dict_lenient(stored)
        return self._with_lab_defaults(meta, key)[0]

    def store_details(self, key: str, meta: CertificateMetadata) -> bool:
        """``meta`` as workbench ``key``'s details in the project; whether they changed."""
        metadata = self._metadata()
        certificates = dict(metadata.get("certificates", {}))
        if certificates.get(key) != meta.to_dict():
            certificates[key] = meta.to_dict()
            metadata["certificates"] = certificates
            metadata["certificates_last"] = key
            self._mark_modified()  # the details are saved with the project
            self.details_changed(key)
            return True
        return False

    def add_polygon_standard(self, key: str, reference) -> tuple:
        """Put the polygon read from its DCC (``reference``: a PolygonReference) among
        workbench ``key``'s standards in place of the polygon listed there
        (app/reference_dcc.placed_reference); stored with the project. Returns what to say;
        DccError (another polygon's DCC) or MetadataError (a standard the details cannot
        take), nothing stored."""

        meta, said = self.polygon_standard_placed(key, reference)
        self.store_details(key, meta)
        return said

    def polygon_standard_placed(self, key: str, reference) -> tuple:
        """The details of workbench ``key`` with the polygon of ``reference`` placed, and
        what to say, stored nowhere: the check before a DCC is applied."""
        from app.reference_dcc import placed_reference

        return placed_reference(self.details(key), reference)

    def keep_details(self, meta: CertificateMetadata) -> None:
        """The details of the workbench being edited kept with the project although its
        dialog was cancelled (they were saved as the lab defaults first: rev62day F15); the
        number is the register's, as when a certificate is exported."""
        if self.editing:
            self.store_details(self.editing, dataclasses.replace(meta, certificate_number=""))

    def edit_details(self, meta: CertificateMetadata) -> CertificateMetadata | None:
        return self.view.edit_certificate_details(meta, self.problems, self.raw)

    # -- the register ----------------------------------------------------------------
    def register_url(self) -> str:
        from models.register.location import register_url

        return register_url(str(self.store.value(REGISTER_KEY, "") or ""))

    def protected(self) -> list:
        """The files no export may replace: the register (with its journal files), the
        open project and the readings files imported (models/project/output_guard.py)."""
        from models.project.output_guard import input_files, open_project, register_files

        return (register_files(self.register_url()) + open_project(self.open_project_path())
                + input_files(self.inputs()))

    def refuse_issued(self, path: str) -> None:
        """Raise OutputRefused when ``path`` is a file the register issued (a certificate's
        PDF, DCC or results file): the workbenches' table exports call it (rev63 F6)."""
        self._refuse_issued((("", path),))

    def _refuse_issued(self, outputs) -> None:
        """:func:`refuse_issued_outputs`, telling of a recorded results file it kept from a
        killed save's leftovers (app/issued_outputs.py)."""
        for said in refuse_issued_outputs(self.register_url(), outputs):
            self.view.tell(tr("Results file kept"), translated(said))

    def lab_timezone(self) -> str:
        """The lab's time zone set in the window (empty: ANGLEBENCH_TIMEZONE, else the
        system's)."""
        return str(self.store.value(TIMEZONE_KEY, "") or "").strip()

    def dcc_options(self) -> tuple[bool, str]:
        """(write the DCC beside the PDF, the schema folder it is validated against: the lab
        defaults', else the window setting it was kept in before)."""
        stored = self.lab_defaults()
        folder = (str(stored.get(DCC_SCHEMA) or "") if DCC_SCHEMA in stored
                  else str(self.store.value(DCC_SCHEMA_KEY, "") or ""))
        return str(self.store.value(DCC_KEY, "false")).lower() == "true", folder.strip()

    def set_dcc_options(self, write: bool, schema_dir: str) -> None:
        """Write the DCC or not (this window's choice); the schema folder with the lab
        defaults."""
        self.store.setValue(DCC_KEY, "true" if write else "false")
        self.save_lab_defaults_entry(DCC_SCHEMA, schema_dir.strip())

    def dcc_signing_paths(self) -> tuple[str, str, str]:
        """The lab's DCC signing key, its certificate, and the trusted certificate (paths;
        "" each: the environment's, models/dcc/signature.py)."""
        stored = self.lab_defaults()
        return tuple(str(stored.get(key) or "").strip() for key in DCC_SIGNING)

    def set_dcc_signing_paths(self, key_file: str, cert_file: str, trusted_file: str) -> None:
        """Keep the three paths with the lab defaults (the files are read when a DCC is
        signed or checked: their content is never stored)."""
        for name, value in zip(DCC_SIGNING, (key_file, cert_file, trusted_file), strict=True):
            self.save_lab_defaults_entry(name, str(value or "").strip())

    def _dcc_path(self, pdf_path: str) -> str:
        """Where the DCC goes beside ``pdf_path`` ("" when it is not asked for)."""
        return str(Path(pdf_path).with_suffix(".xml")) if self.dcc_options()[0] else ""

    def _dcc_maker(self, kind, result, pdf_path: str, settings):
        """``dcc(document, pdf) -> bytes`` for issue_certificate (None: no DCC asked for),
        its budgets from the ``settings`` ``result`` was analysed with."""
        if not self._dcc_path(pdf_path):
            return None
        from app.dcc_issue import dcc_schema_dir, render_dcc

        folder = dcc_schema_dir(configured=self.dcc_options()[1])
        return lambda document, pdf: render_dcc(kind, result, document, pdf,
                                                Path(pdf_path).name, folder, settings)

    def _with_dcc(self, text: str, pdf_path: str) -> str:
        """A status text with where the DCC went, and whether it was validated."""
        dcc_path = self._dcc_path(pdf_path)
        if not dcc_path:
            return text
        from app.dcc_issue import dcc_schema_dir

        if dcc_schema_dir(configured=self.dcc_options()[1]):
            return text + tr("; its DCC (validated) written to {path}").format(path=dcc_path)
        return text + tr("; its DCC written to {path}, not validated (no DCC schema folder "
                         "set)").format(path=dcc_path)

    def _write_pdf_and_dcc(self, kind, result, document, path: str, settings) -> str:
        """The PDF of ``document`` and, when asked for, its DCC beside it (made first: when
        refused, neither is written); the DCC's path, or ""."""
        from app.writers.certificate_pdf import certificate_pdf_bytes
        from models.project.atomic_write import write_bytes_atomic

        pdf = certificate_pdf_bytes(document)
        make, dcc_path = self._dcc_maker(kind, result, path, settings), self._dcc_path(path)
        xml = make(document, pdf) if make else None
        write_bytes_atomic(path, pdf)
        if xml is not None:
            write_bytes_atomic(dcc_path, xml)
        return dcc_path if xml is not None else ""

    def set_lab_timezone(self, name: str) -> None:
        """Set the lab's time zone; RegisterError (nothing stored) for a name not known."""
        from models.register.store import lab_timezone

        if name.strip():
            lab_timezone(name)
        self.store.setValue(TIMEZONE_KEY, name.strip())

    def set_register_url(self, url: str) -> None:
        """The register's location changed: a pending Amend…/Replace… is ended, since its
        number is the old register's (rev63 F4: it amended the new register's certificate of
        that number, another item)."""
        before = self.register_url()
        self.store.setValue(REGISTER_KEY, url.strip())
        revision = self._pending
        if revision is not None and self.register_url() != before:
            self.end_revision()
            self.view.show_status(tr(
                "The amendment or replacement of {number} is ended: the register's location "
                "changed.").format(number=revision.number), 15000)

    def open_register(self):
        """The register (RegisterError when it cannot be opened). A write that waits for
        another process's write lock says so in the status line at once (reg72 #8: the
        window stood a silent minute, then said "database is locked")."""
        from models.register.store import BUSY_TIMEOUT_S, Register

        register = Register(self.register_url(), timezone=self.lab_timezone())
        register.on_wait = lambda said: self.view.show_status(
            translated(said), (BUSY_TIMEOUT_S + 10) * 1000)
        return register

    def _register_refuses(self) -> bool:
        """The register as it stands issues nothing (Register.issue_refusal), or cannot be
        opened: said as an issue's refusal is, with the window's recovery that answers it;
        True then."""
        from app.register_recovery_pointer import recovery_pointer
        from models.messages import reason_of
        from models.register.store import RegisterError

        try:
            with self.open_register() as register:
                # what opening found (a restore, a wrong key, a broken chain): the stored
                # files are read and hashed by the issue itself, not twice
                refused = register.issue_refusal(stored_files=False)
        except RegisterError as exc:
            refused = reason_of(exc)
        if refused is None:
            return False
        said = tr("{reason}. No certificate was written or recorded.").format(
            reason=as_sentence(translated(refused)))
        pointer = recovery_pointer(refused)
        self.view.tell(tr("Not issued"), said + ("\n\n" + pointer if pointer else ""))
        return True

    def start_revision(self, revision: PendingRevision) -> None:
        """The next certificate of that workbench amends or replaces ``revision.number``."""
        self.pending = revision

    def end_revision(self) -> None:
        """The next certificate is an original again (another project was opened; rev62 F1:
        a pending Amend… outlived File › Open and amended with another item's details)."""
        self.pending = None

    # -- exports ------------------------------------------------------------------
    def export_certificate(self, kind, result, settings: dict, source_name: str,
                           rows: list[list[str]] | None = None,
                           raw_capture: list | None = None) -> bool:
        """Ask for the details and a file; a complete certificate is issued through the
        register (number allocated there, record kept), a draft is written and nothing
        recorded."""
        from app.certificate_issue import draft_reasons, readings_stated

        incomplete = getattr(result, "incomplete", None)
        if incomplete is not None:  # before any dialog: a certificate needs every unit
            self.view.tell(tr("Certificate"), tr(
                "No certificate: {progress} is not complete. A certificate needs every set, "
                "mounting or run complete; finish it, or delete its rows to certify the "
                "complete ones.").format(progress=translated(incomplete.text())))
            return False
        refusal = (kind.certificate_refusal(result) if isinstance(kind, IssuesCertificates)
                   else "")
        if refusal:  # before any dialog: no details would make it issuable (day review 69 F6)
            self.view.tell(tr("Certificate"), tr("No certificate: {reason}.").format(
                reason=translated(refusal)))
            return False
        doubt = kind.certificate_doubt(result) if isinstance(kind, IssuesCertificates) else ""
        if doubt and not self.view.confirm_implausible(translated(doubt)):
            return False
        shown = self.details(kind.key)
        # the "Readings:" line the certificate will print, shown in the details dialog
        # before issue (day review 67 F7)
        self.readings_line = readings_stated(kind.key, source_name, rows or [], raw_capture,
                                             kind.columns, result)[0]
        stored = False  # the details entered changed the project's
        while True:
            entered = self.edit_details(shown)
            if entered is None:
                self.readings_line = ""
                return False
            stored = self.store_details(kind.key, dataclasses.replace(
                entered, certificate_number="")) or stored
            # a standard of another kind of quantity is refused, one as large as the
            # tolerance asked about, before it enters the budget (#41)
            refusals, warnings = standards_fit(entered, kind.error_unit(settings))
            if refusals:
                self.view.tell(tr("Cannot use these reference standards"),
                               "\n".join(translated(r) for r in refusals))
                shown, self.problems, self.raw = entered, {}, {}
                continue
            if warnings and not self.view.confirm_standards([translated(w) for w in warnings]):
                shown, self.problems, self.raw = entered, {}, {}
                continue
            draft = draft_reasons(entered)
            # "No, not a draft": back to the dialog, what was typed kept, to fill in the rest
            if entered.example or not draft or self.view.confirm_draft(
                    draft, self._is_test_report(kind, result, entered, source_name, settings)):
                break
            shown, self.problems, self.raw = entered, {}, {}  # what was stored now reads
        self.readings_line = ""
        try:  # details the result refuses (a grade that disagrees) told before the file dialog
            report = kind.certificate_document(result, entered, source_name,
                                               settings).is_test_report
        except ValueError as exc:
            self.view.tell(tr("Cannot export"), tr("{reason}. Nothing was written; the details "
                                                   "are kept.").format(
                reason=as_sentence(explained(exc))))  # a reason in lower case (day 68 F9)
            return False
        revision = self.pending if self.pending and self.pending.workbench == kind.key else None
        note, separate = "", ""
        if entered.example:  # the training switch: a specimen, neither draft nor revision
            draft, revision = [], None
        # a register that issues nothing refuses before any question about the document
        # (day74 #7 b: "Issue it as a test report?", then the refusal); a draft and a
        # specimen, never recorded, are still written
        if not draft and not entered.example and self._register_refuses():
            return False
        # asked for a certificate, issued as a test report: said, with why, before a file
        # name is asked (rev62 F7: learnt only from the status line after issue)
        if report and not draft and not entered.example and entered.document_type != "test" \
                and not self.view.confirm_test_report(self._why_test_report(
                    kind, result, entered, source_name, settings)):
            return False
        if revision is not None and not draft:
            note = self.view.ask_change_note(revision).strip()
            if not note:
                return False
        elif not draft and not entered.example and not entered.certificate_number:
            # a second original of a calibration already reported: asked before the file
            # name, where the register can tell (rev62 F10; a number typed is checked first
            # by the register, as before)
            numbers = self._reporting(kind.key, entered)
            if numbers:
                separate = " ".join(self.view.ask_separate_calibration(numbers, tr(
                    "{numbers} already reports this calibration (serial {serial}, calibrated "
                    "{date}). Readings or details changed since are a correction: amend or "
                    "replace {numbers} (File › Certificate register, Amend… or Replace…); a "
                    "calibration of its own (e.g. as left after an adjustment) is issued as "
                    "separate, saying why").format(
                        numbers=", ".join(numbers), serial=entered.item_serial or "—",
                        date=entered.calibration_date or "—")).split())
                if not separate:
                    self.view.tell(tr("Not issued"), tr(
                        "No certificate was written or recorded: {numbers} already reports this "
                        "calibration. To correct it, select it in File › Certificate register "
                        "and press Amend… or Replace….").format(numbers=", ".join(numbers)))
                    return False
        confirmed = (False, False)
        readings: tuple[str, str] | tuple[()] | None = ()
        if revision is None and not draft and not entered.example:
            # another maker's item, a look-alike serial: asked before the file name, where the
            # register can tell (rev65: a No after the file dialog left a file chosen for
            # nothing)
            answered = self._confirmed_before_file(kind.key, entered)
            if answered is None:
                return False
            confirmed = answered
            # another item's readings (hostile78 F7): why, asked before the file name
            readings = self._readings_of_another_item(kind.key, entered, rows or [], settings)
            if readings is None:
                return False
        # an amendment or a replacement is not filed under the original's number, which the
        # details hold (day review 65 F6: AB-2026-0001-A1 was issued into AB-2026-0001.pdf)
        number = (self._revision_number(revision) if revision is not None
                  else entered.certificate_number)
        suggested = (f"{kind.key}-specimen" if entered.example else number
                     or (f"{kind.key}-draft" if draft else
                         f"{kind.key}-report" if report else f"{kind.key}-certificate"))
        # the file dialog names what will be written (ISO/IEC 17025 7.8.2.1 a))
        path = self.view.choose_save_path(
            tr("Export test report") if report else tr("Export certificate"),
            f"{suggested.replace('/', '-')}.pdf", "PDF (*.pdf)")
        if not path:
            return False
        if not path.lower().endswith(".pdf"):
            path += ".pdf"
        self.view.wait_cursor(True)
        try:
            check_output(path, self.protected())
            if self._dcc_path(path):
                check_output(self._dcc_path(path), self.protected())
            self._refuse_issued((("", path), ("", self._dcc_path(path))))
            # a draft and a specimen say where the readings came from as the issued one would
            origin, digest = readings_stated(kind.key, source_name, rows or [], raw_capture,
                                             kind.columns, result)
            if entered.example:
                return self._specimen(kind, result, entered, settings, origin, path, digest)
            if draft:
                self._write_pdf_and_dcc(kind, result, dataclasses.replace(
                    kind.certificate_document(result, entered, origin, settings),
                    raw_data_sha256=digest), path, settings)
                # a test report's draft is called one (ISO/IEC 17025 7.8.2.1 a))
                said = (tr("Draft test report written to {path} — DRAFT: {missing} missing; "
                           "nothing was recorded in the register") if report else
                        tr("Draft written to {path} — DRAFT: {missing} missing; nothing was "
                           "recorded in the register"))
                self.view.show_status(self._with_dcc(said.format(
                    path=path, missing=joined(", ", (tr(m) for m in draft))), path), 10000)
                return True
            self.last_issued = ""
            issued = self._issue(kind, result, entered, settings, rows or [], source_name,
                                 path, revision, note, raw_capture, separate, confirmed,
                                 readings if revision is None and not draft else ())
            if stored and self.last_issued:  # issued: what it stored in the project said so
                self.details_issued(kind.key, self.last_issued)
            return issued
        except (OSError, ValueError) as exc:
            self.view.tell(tr("Cannot export"), _refusal(
                path, explained(exc), tr("{path}: {reason}. Nothing else was changed."),
                tr("{reason}. Nothing else was changed.")))
            return False
        finally:
            self.view.wait_cursor(False)

    def _asked(self, ask, *args):
        """``ask(*args)``, one of the view's questions put while issuing, without the wait
        cursor over it (back on after the answer)."""
        self.view.wait_cursor(False)
        try:
            return ask(*args)
        finally:
            self.view.wait_cursor(True)

    def _revision_number(self, revision: PendingRevision) -> str:
        """The number ``revision`` will be issued under when it is an amendment (the
        register's next ``<original>-A<n>``); "" for a replacement (its number comes from
        the number scheme at issue) or when the register cannot tell."""
        from models.register.store import RegisterError

        if revision.replacement:
            return ""
        try:
            with self.open_register() as register:
                return register.next_amendment_number(revision.number)
        except (RegisterError, OSError):
            return ""

    def _specimen(self, kind, result, entered, settings, origin, path, digest="") -> bool:
        """The training switch: a SPECIMEN written, nothing recorded (as ``"example": true``
        on the command line)."""
        from app.certificate_issue import specimen_document

        document = specimen_document(dataclasses.replace(
            kind.certificate_document(result, entered, origin, settings),
            raw_data_sha256=digest))
        self._write_pdf_and_dcc(kind, result, document, path, settings)
        self.view.show_status(self._with_dcc(tr(
            "SPECIMEN {number} written to {path} (training): watermarked SPECIMEN, not a "
            "certificate, and recorded in no register").format(
                number=document.metadata.certificate_number, path=path), path), 15000)
        return True

    def _issue(self, kind, result, entered, settings, rows, source_name, path, revision,
               note, raw_capture=None, separate: str = "",
               confirmed: tuple[bool, bool] = (False, False),
               readings: tuple[str, str] | tuple[()] | None = ()) -> bool:
        """``confirmed``: another maker's item, another item than a look-alike serial's,
        as the user said before the file dialog (else asked when the issue raises it);
        ``readings``: (N, why) the readings are those of certificate N of another item, as
        the user said before it (else asked when the issue raises it)."""
        from app.certificate_issue import IssuedNotWritten, issue_certificate
        from models.register.clock_rules import DateToConfirm
        from models.register.store import (
            AnotherMakersItem,
            LookalikeSerial,
            NotTheSameCalibration,
            ReadingsOfAnotherItem,
            RegisterError,
            SameCalibrationIssued,
            SameReadingsIssued,
        )

        corrected = False
        stated = readings or None  # (N, why): the readings of another item, said
        same_stated = None  # (N, why): the readings and details of a current one, said
        another_maker, another_item = confirmed
        date_confirmed = None  # today's date, confirmed when the register asks (reg73 #6)
        declined: LookalikeSerial | None = None  # the question answered No
        try:
            while True:
                try:
                    with self.open_register() as register:
                        record = issue_certificate(
                            register, kind, result, entered, settings, rows, source_name,
                            path, supersedes=revision.number if revision else "",
                            change_note=note, replacement=bool(revision and revision.replacement),
                            separate_calibration=separate, correction_confirmed=corrected,
                            another_makers_item=another_maker,
                            another_lookalike_item=another_item,
                            readings_of_another_item=stated, same_readings_as=same_stated,
                            raw_capture=raw_capture, confirmed_date=date_confirmed,
                            dcc=self._dcc_maker(kind, result, path, settings),
                            dcc_path=self._dcc_path(path), signing=self.dcc_signing_paths()[:2])
                    break
                except SameCalibrationIssued as exc:
                    # a reading changed and issued again made a second original of one
                    # calibration, neither naming the other (#61 assessor, 17025 7.8.8)
                    separate = " ".join(self._asked(self.view.ask_separate_calibration,
                                                    exc.numbers, explained(exc)).split())
                    if not separate:
                        raise
                except SameReadingsIssued as exc:
                    # the same readings and details as a current certificate of the
                    # calibration: that calibration issued again, unless the user says why
                    if same_stated:
                        raise
                    why = " ".join(self._asked(self.view.ask_same_readings, exc.numbers,
                                               translated(exc.facts)).split())
                    if not why:
                        raise
                    same_stated = (exc.numbers[0], why)
                except ReadingsOfAnotherItem as exc:
                    # one item's readings issued as another's (hostile78 F7): why, asked, and
                    # the answer printed on it and recorded
                    if stated:
                        raise
                    why = " ".join(self._asked(self.view.ask_readings_of_another_item,
                                               exc.numbers, translated(exc.facts)).split())
                    if not why:
                        raise
                    stated = (exc.numbers[0], why)
                except DateToConfirm as exc:
                    # far after the register's last record: the date shown and asked, a
                    # Yes recorded with the certificate
                    if date_confirmed is not None or not self._asked(
                            self.view.confirm_issue_date, exc.date.isoformat(), explained(exc)):
                        raise
                    date_confirmed = exc.date
                except AnotherMakersItem as exc:
                    # a maker's name spelt otherwise is not another maker (rev65 F1): asked,
                    # and a Yes recorded in the register
                    if another_maker:
                        raise
                    another_maker = self._asked(self.view.confirm_another_maker, exc.numbers,
                                                explained(exc))
                    if not another_maker:
                        raise
                except LookalikeSerial as exc:
                    # a serial one look-alike from an item's (rev65 F7): asked, a Yes recorded
                    if another_item:
                        raise
                    another_item = self._asked(self.view.confirm_lookalike_serial, exc)
                    if not another_item:
                        declined = exc
                        raise
                except NotTheSameCalibration as exc:
                    # another item's or another day's details: a correction only when the
                    # user says so, then stated on it (rev62 F1)
                    if revision is None or corrected or not exc.corrections:
                        raise
                    corrected = self._asked(self.view.confirm_correction, revision,
                                            explained(exc))
                    if not corrected:
                        self.pending = None
                        self.view.tell(tr("Not issued"), tr(
                            "No certificate was written or recorded. The amendment or "
                            "replacement of {number} is ended: the next certificate of this "
                            "workbench is an original (Amend… or Replace… in File › Certificate "
                            "register starts it again).").format(number=revision.number))
                        return False
        except RegisterError as exc:
            ended = revision is not None and self._revision_impossible(revision)
            if ended:  # refused for good: no later export is held to it (rev62 F1)
                self.pending = None
            said = _not_issued_after_no(exc) if exc is declined else tr(
                "{reason}. No certificate was written or recorded.").format(
                reason=as_sentence(explained(exc)))  # a reason in lower case (day 68 F9)
            # a loss or a clock set ahead: the register window's own action, named (the
            # register's words name the command)
            from app.register_recovery_pointer import recovery_pointer
            from models.messages import reason_of

            pointer = recovery_pointer(reason_of(exc))
            said += "\n\n" + pointer if pointer else ""
            self.view.tell(tr("Not issued"), said + ("\n\n" + tr(
                        "The amendment or replacement of {number} is ended: the next "
                        "certificate of this workbench is an original.").format(
                        number=revision.number) if ended else ""))
            return False
        except IssuedNotWritten as exc:  # committed: the record and its PDF are in the register
            said = (tr("Test report {number} is issued and recorded in the register, but "
                       "{reason}: save its PDF from File › Certificate register.")
                    if exc.record.document_kind == "test" else
                    tr("Certificate {number} is issued and recorded in the register, but "
                       "{reason}: save its PDF from File › Certificate register."))
            said = said.format(number=exc.record.number, reason=exc)
            self.last_issued = exc.record.number
            if exc.others:  # every file not written is named (reg72 #5)
                said += "\n\n" + tr("Not written either: {files}.").format(
                    files="; ".join(str(other) for other in exc.others))
            self.view.tell(tr("Issued, but the file was not written"), said)
            return False
        if revision is not None:
            self.pending = None
        self.last_issued = record.number
        number = record.number
        if record.supersedes:  # the register's revision words, in the window's language
            number = tr("{number} ({revision} of {supersedes})").format(
                number=record.number, revision=translated(revision_words(record.revision)),
                supersedes=record.supersedes)
        # a test report calls itself one (ISO/IEC 17025 7.8.2.1 a)), as it is recorded
        said = (tr("Test report {number} issued: written to {path} and recorded in the "
                   "register") if record.document_kind == "test" else
                tr("Certificate {number} issued: written to {path} and recorded in the register"))
        self.view.show_status(self._with_dcc(said.format(number=number, path=path), path),
                              10000)
        return True

    def _readings_of_another_item(self, workbench: str, entered: CertificateMetadata,
                                  rows: list[list[str]], settings: dict | None = None
                                  ) -> tuple[str, str] | tuple[()] | None:
        """The register's question about readings that are those of certificates of another
        item (Register.readings_of_another_item, with the workbench's ``settings``: its
        columns' units), asked before the file name: (N, why) as
        answered, () when not asked (none, or the register cannot be read now: the issue
        says why), None after a cancel (said: nothing issued)."""
        from models.register.store import RegisterError

        try:
            with self.open_register() as register:
                question = register.readings_of_another_item(workbench, entered, rows,
                                                             settings)
        except (RegisterError, OSError):
            return ()
        if question is None:
            return ()
        why = " ".join(self.view.ask_readings_of_another_item(question.numbers,
                                                              translated(question.facts)).split())
        if not why:
            self.view.tell(tr("Not issued"), tr(
                "No certificate was written or recorded: the readings are those of {numbers}, "
                "another item's. Issue this item's certificate from its own readings.").format(
                    numbers=", ".join(question.numbers)))
            return None
        return question.numbers[0], why

    def _confirmed_before_file(self, workbench: str, entered: CertificateMetadata
                               ) -> tuple[bool, bool] | None:
        """The register's questions about an original (Register.confirmations_needed:
        another maker's item, a look-alike serial), asked before the file name: (another
        maker's item, another item) as answered; None after a No (said: nothing issued).
        (False, False) when the register cannot be read now: the issue says why."""
        from models.register.store import AnotherMakersItem, RegisterError

        try:
            with self.open_register() as register:
                questions = register.confirmations_needed(workbench, entered)
        except (RegisterError, OSError):
            return False, False
        another_maker = another_item = False
        for question in questions:
            if isinstance(question, AnotherMakersItem):
                another_maker = said = self.view.confirm_another_maker(question.numbers,
                                                                       explained(question))
            else:
                another_item = said = self.view.confirm_lookalike_serial(question)
                if not said:
                    self.view.tell(tr("Not issued"), _not_issued_after_no(question))
                    return None
            if not said:
                self.view.tell(tr("Not issued"), tr(
                    "{reason}. No certificate was written or recorded.").format(
                    reason=as_sentence(explained(question))))
                return None
        return another_maker, another_item

    def _reporting(self, workbench: str, entered: CertificateMetadata) -> tuple[str, ...]:
        """The current certificates that already report this calibration (() when the
        register cannot be read now: the issue says why)."""
        from models.register.store import RegisterError

        try:
            with self.open_register() as register:
                return register.reports_calibration(workbench, entered)
        except (RegisterError, OSError):
            return ()

    @staticmethod
    def _why_test_report(kind, result, entered, source_name, settings) -> list[str]:
        """Why the document of these details is a test report, as it states it."""
        document = kind.certificate_document(result, entered, source_name, settings)
        return [translated(r) for r in (*document.untraceable, *document.traceability_gaps)]

    @staticmethod
    def _is_test_report(kind, result, entered, source_name, settings) -> bool:
        """Whether the document of these details is a test report (asked for, or a result
        whose U names inputs not stated); details it refuses are told after (as asked)."""
        try:
            return kind.certificate_document(result, entered, source_name,
                                             settings).is_test_report
        except ValueError:
            return entered.document_type == "test"

    def _revision_impossible(self, revision: PendingRevision) -> bool:
        """Whether ``revision.number`` can no longer be amended or replaced (superseded,
        withdrawn, not in the register, or on another workbench)."""
        from models.register.store import RegisterError

        try:
            with self.open_register() as register:
                record = register.get(revision.number)
        except (RegisterError, OSError):
            return False  # the register cannot be read now: the refusal says why
        return record is None or record.status != "issued" or \
            record.workbench != revision.workbench

    def export_results(self, kind, result, settings: dict, source_name: str,
                       unit: AngleUnit = ANGLE_UNITS["arcsec"],
                       rows: list[list[str]] | None = None,
                       raw_capture: list | None = None) -> bool:
        """Write the results (CSV or XLSX) of the result in front, not issued: where its
        readings came from (``rows`` and the instrument's sessions ``raw_capture``) stated
        as the certificate states it (day review 64 P8)."""
        from app.certificate_issue import readings_stated

        path = self.view.choose_save_path(tr("Export results"), f"{kind.key}-results.csv",
                                          tr("CSV (*.csv);;Excel workbook (*.xlsx)"))
        if not path:
            return False
        try:
            check_output(path, self.protected())
            self._refuse_issued((("", path),))  # rev62 F8
            origin, digest = readings_stated(kind.key, source_name, rows or [], raw_capture,
                                             kind.columns, result)
            document = dataclasses.replace(kind.certificate_document(
                result, self.details(kind.key), origin, settings), raw_data_sha256=digest)
            if path.lower().endswith(".xlsx"):
                write_results_xlsx(path, document, unit)
            else:
                write_results_csv(path, document, unit)
        except (OSError, ValueError) as exc:
            # what was refused: the results (day review 67 F9: "no certificate is issued"
            # was said, of an export where none was being issued)
            self.view.tell(tr("Cannot export"), _refusal(
                path, explained(exc), tr("{path}: {reason}. No results were written."),
                tr("{reason}. No results were written.")))
            return False
        self.view.show_status(tr("Results written to {path}").format(path=path), 8000)
        return True
