"""Certificate control: each workbench's certificate details, the lab's defaults, the
certificate numbers, and the export of the certificate and of the results.

A presenter with no widgets: it asks its view (the main window, through the calls
of :class:`CertificateView`) for the details, for a file name, and to tell the user
something; it keeps the details in the project's metadata and the lab's defaults
in the settings store. Tested with a mock view, no window.
"""

from __future__ import annotations

import json
from collections.abc import Callable, MutableMapping
from typing import Any, Protocol

from app.writers.results_export import write_results_csv, write_results_xlsx
from models.certificate.metadata import CertificateMetadata, MetadataError

__all__ = ["CertificatePresenter", "CertificateView"]

LAB_DEFAULTS_KEY = "certificate/lab_defaults"
SEQUENCE_KEY = "certificate/next_sequence"


class CertificateView(Protocol):
    """What the certificate presenter asks of the window."""

    def edit_certificate_details(self, meta: CertificateMetadata, sequence: int,
                                 problems: dict[str, str], raw: dict
                                 ) -> tuple[CertificateMetadata | None, bool]:
        """The details entered (None if cancelled), and whether the sequence was used."""

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
        self.raw: dict = {}

    # -- the lab's defaults ------------------------------------------------------
    def lab_defaults(self) -> dict:
        text = self.store.value(LAB_DEFAULTS_KEY, "")
        try:
            data = json.loads(text) if text else {}
        except (TypeError, ValueError):
            data = {}
        return data if isinstance(data, dict) else {}

    def save_lab_defaults(self, defaults: dict) -> None:
        self.store.setValue(LAB_DEFAULTS_KEY, json.dumps(defaults, ensure_ascii=False))

    # -- a workbench's details -----------------------------------------------------
    def details(self, key: str) -> CertificateMetadata:
        """The workbench's details from the project, the lab's defaults filled in; a stored
        detail that no longer reads is kept aside (``problems``), not the others blanked."""
        stored = self._metadata().get("certificates", {}).get(key)
        meta, self.problems = CertificateMetadata.from_dict_lenient(stored)
        self.raw = stored if isinstance(stored, dict) else {}
        try:
            return meta.with_lab_defaults(self.lab_defaults())
        except MetadataError:
            return meta

    def store_details(self, key: str, meta: CertificateMetadata) -> None:
        metadata = self._metadata()
        certificates = dict(metadata.get("certificates", {}))
        if certificates.get(key) != meta.to_dict():
            certificates[key] = meta.to_dict()
            metadata["certificates"] = certificates
            self._mark_modified()  # the details are saved with the project

    def edit_details(self, meta: CertificateMetadata) -> CertificateMetadata | None:
        sequence = int(self.store.value(SEQUENCE_KEY, 1) or 1)
        entered, used = self.view.edit_certificate_details(meta, sequence, self.problems, self.raw)
        if entered is not None and used:
            self.store.setValue(SEQUENCE_KEY, sequence + 1)
        return entered

    # -- exports ------------------------------------------------------------------
    def export_certificate(self, kind, result, settings: dict, source_name: str) -> bool:
        entered = self.edit_details(self.details(kind.key))
        if entered is None:
            return False
        self.store_details(kind.key, entered)
        suggested = (entered.certificate_number or f"{kind.key}-certificate").replace("/", "-")
        path = self.view.choose_save_path("Export certificate", f"{suggested}.pdf", "PDF (*.pdf)")
        if not path:
            return False
        if not path.lower().endswith(".pdf"):
            path += ".pdf"
        from app.writers.certificate_pdf import write_certificate_pdf  # fpdf2 on first export

        self.view.wait_cursor(True)
        try:
            document = kind.certificate_document(result, entered, source_name, settings)
            write_certificate_pdf(path, document)
        except (OSError, ValueError) as exc:
            self.view.tell("Cannot export", f"{path}: {exc}. Nothing else was changed.")
            return False
        finally:
            self.view.wait_cursor(False)
        draft = (" — DRAFT: " + ", ".join(entered.missing_fields()) + " missing"
                 if document.is_draft else "")
        self.view.show_status(f"Certificate written to {path}{draft}", 10000)
        return True

    def export_results(self, kind, result, settings: dict, source_name: str) -> bool:
        path = self.view.choose_save_path("Export results", f"{kind.key}-results.csv",
                                          "CSV (*.csv);;Excel workbook (*.xlsx)")
        if not path:
            return False
        try:
            document = kind.certificate_document(result, self.details(kind.key), source_name,
                                                 settings)
            if path.lower().endswith(".xlsx"):
                write_results_xlsx(path, document)
            else:
                write_results_csv(path, document)
        except (OSError, ValueError) as exc:
            self.view.tell("Cannot export", f"{path}: {exc}")
            return False
        self.view.show_status(f"Results written to {path}", 8000)
        return True
