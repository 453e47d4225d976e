"""A certificate's PDF as a stand-in, for the tests of what is said about an issue or of where
its files go, which never read a PDF's pages: printing one costs ~0.5 s of CPU (the fringe
sample's ~3 s). The stand-in names the document's number, kind, language and revision, so
two documents never share one. The printing on these paths is tested end to end elsewhere
(tests/app/test_document_kind_said.py, test_register_cli.py, test_translations.py's Chinese
draft, tests/app/writers/)."""

from __future__ import annotations

import pytest

__all__ = ["print_stand_ins", "stand_in_pdf"]


def stand_in_pdf(document) -> bytes:
    """The stand-in of ``document``'s PDF."""
    meta = document.metadata
    return (f"%PDF-1.4\n% stand-in: {meta.certificate_number} "
            f"{'test report' if document.is_test_report else 'certificate'} "
            f"{meta.language} {meta.revision}\n%%EOF\n").encode()


def print_stand_ins(mp: pytest.MonkeyPatch) -> None:
    """Through ``mp``: the window and the command line print :func:`stand_in_pdf` wherever
    they print a certificate (app.writers.certificate_pdf, app.certificate_issue)."""
    import app.certificate_issue as issue
    import app.writers.certificate_pdf as printer

    mp.setattr(printer, "certificate_pdf_bytes", stand_in_pdf)
    mp.setattr(issue, "certificate_pdf_bytes", stand_in_pdf)
