"""The statement of conformity (rule, decided quantity, zones), the statements and the
remarks."""

from __future__ import annotations

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.page import GREY
from app.writers.certificate_pdf.wording import _translatable, label
from models.certificate.document import CertificateDocument
from models.messages import QT_TR_NOOP, joined, message


def draw_conformity(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    pdf.heading(label(document, "Statement of conformity"))
    conformity = document.conformity
    pdf.paragraph(conformity.statement)
    if conformity.quantity:
        pdf.paragraph(message(QT_TR_NOOP("Decided quantity: {quantity}."),
                              quantity=_translatable(conformity.quantity)), 8, GREY)
    pdf.paragraph(message(QT_TR_NOOP("Decision rule: {rule}."),
                          rule=_translatable(conformity.rule)), 8, GREY)
    if conformity.zones:
        pdf.paragraph(message(QT_TR_NOOP("Zones: {zones}."),
                              zones=_translatable(conformity.zones)), 8, GREY)


def draw_statements(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    meta = document.metadata
    pdf.heading(label(document, "Statements"))
    for statement in (*document.statements,
                      QT_TR_NOOP("The results relate only to the item calibrated, as received, "
                                 "under the conditions stated.")):
        pdf.paragraph(joined(["• ", _translatable(statement)]))
    if document.warnings or meta.notes:
        pdf.heading(label(document, "Remarks"))
        for w in document.warnings:
            pdf.paragraph(joined(["• ", _translatable(w)]))
        if meta.notes:
            pdf.paragraph(meta.notes)
