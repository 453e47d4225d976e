"""The certificate's PDF: its sections in print order, its metadata and its /ID (the same
document gives the same bytes); refused when some text cannot be printed as written."""

from __future__ import annotations

import datetime as dt
import hashlib
from pathlib import Path

from fpdf import FPDF

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.fonts import close_fonts, right_to_left, unprintable
from app.writers.certificate_pdf.front import _created, draw_front
from app.writers.certificate_pdf.method import draw_method
from app.writers.certificate_pdf.results import (
    draw_curves,
    draw_parameters,
    draw_results,
    draw_statistics,
)
from app.writers.certificate_pdf.signatures import draw_end
from app.writers.certificate_pdf.statements import draw_conformity, draw_statements
from app.writers.certificate_pdf.traceability import draw_traceability
from app.writers.certificate_pdf.uncertainty import draw_uncertainty
from app.writers.certificate_pdf.wording import label
from models.certificate.document import CertificateDocument
from models.project.atomic_write import write_bytes_atomic
from models.software import software_identity


def _render(document: CertificateDocument) -> FPDF:
    pdf = _CertificatePdf(document)
    try:
        return _drawn(pdf, document)
    except BaseException:
        close_fonts(pdf)  # a page that could not be laid out left the font files open
        raise


def _drawn(pdf, document: CertificateDocument) -> FPDF:
    meta = document.metadata
    pdf.set_title(f"{label(document, document.title)} {meta.certificate_number}".strip())
    pdf.set_author(meta.lab_name)
    pdf.set_subject(pdf.say(document.kind_title))
    pdf.set_creator(f"AngleBench {software_identity().printed}")
    pdf.set_producer("AngleBench (fpdf2)")
    created = _created(document)
    pdf.set_creation_date(created)
    if document.register_head:
        from models.register.chain import CONTENT_MARK, HEAD_MARK, PROOF_MARK

        keywords = f"{HEAD_MARK}{document.register_head}"
        if document.register_content:
            keywords += f" {CONTENT_MARK}{document.register_content}"
        if document.register_proof:
            keywords += f" {PROOF_MARK}{document.register_proof}"
        pdf.set_keywords(keywords)
    pdf.add_page()
    draw_front(pdf, document, created)
    draw_traceability(pdf, document)
    draw_method(pdf, document)
    draw_parameters(pdf, document)
    draw_curves(pdf, document)
    draw_statistics(pdf, document)
    draw_uncertainty(pdf, document)
    draw_conformity(pdf, document)
    draw_statements(pdf, document)
    draw_results(pdf, document)
    draw_end(pdf)
    digest = hashlib.md5(_identity(document, created).encode(), usedforsecurity=False).hexdigest()
    pdf.file_id = lambda *_: f"<{digest}><{digest}>"
    return pdf


def _identity(document: CertificateDocument, created: dt.datetime) -> str:
    """What makes two certificates the same document: for the PDF's /ID."""
    parts = [document.kind_key, repr(document.metadata.to_dict()), created.isoformat(),
             document.source_name, repr(document.results.rows), repr(document.parameters.rows)]
    return "\x1f".join(parts)


def certificate_pdf_bytes(document: CertificateDocument) -> bytes:
    """The PDF; ValueError when some text has characters no bundled font can print (Hangul,
    for one): refused rather than printed with those characters silently missing."""
    missing = unprintable(document)
    if missing:
        raise ValueError(f"the certificate's text has characters no bundled font can print: "
                         f"'{missing[:20]}'; write those details in Latin or Chinese script")
    backwards = right_to_left(document)
    if backwards:
        raise ValueError(f"the certificate's text has right-to-left script ('{backwards[:20]}'"
                         f"), which the certificate cannot print in its order (it would read "
                         f"reversed); write those details in Latin or Chinese script")
    final = _render(document)
    try:
        return bytes(final.output())
    finally:
        close_fonts(final)


def write_certificate_pdf(path: str | Path, document: CertificateDocument) -> None:
    """Write the certificate atomically (temp file + rename)."""
    write_bytes_atomic(path, certificate_pdf_bytes(document))
