"""The statement of conformity (rule, decided quantity, zones), the statements and the
remarks; on a bilingual certificate each of these in Chinese, then in English."""

from __future__ import annotations

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.page import GREY, INK
from app.writers.certificate_pdf.wording import _in_both, _translatable, label
from models.certificate.document import CertificateDocument
from models.messages import QT_TR_NOOP, joined, message

#: how far a bilingual item's English stands in under its Chinese (mm, past the "• ")
_UNDER_BULLET = 3.2


def draw_conformity(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    """The customer's key sentence: on a bilingual certificate the statement in Chinese and
    then in English (the same figures in both), then the decided quantity, the rule and
    the zones in Chinese, then in English."""
    pdf.heading(label(document, "Statement of conformity"))
    conformity = document.conformity
    pdf.paragraph_in_both(conformity.statement)
    details = []
    if conformity.quantity:
        details.append(message(QT_TR_NOOP("Decided quantity: {quantity}."),
                               quantity=_translatable(conformity.quantity)))
    details.append(message(QT_TR_NOOP("Decision rule: {rule}."),
                           rule=_translatable(conformity.rule)))
    if conformity.zones:
        details.append(message(QT_TR_NOOP("Zones: {zones}."),
                               zones=_translatable(conformity.zones)))
    languages = [_in_both(document, text) for text in details]
    for block in range(max(map(len, languages))):  # Chinese, then English
        if block:
            pdf.ln(1)
        for said in languages:
            if block < len(said):  # (a text with no Chinese: once, as it is)
                pdf.paragraph(said[block], 8, GREY)


def _items(pdf: _CertificatePdf, document: CertificateDocument, texts) -> None:
    """Each text a bulleted item; on a bilingual certificate its English under its
    Chinese."""
    for text in texts:
        said = _in_both(document, _translatable(text))
        pdf.paragraph(joined(["• ", said[0]]))
        for english in said[1:]:
            pdf.paragraph(english, 9, INK, indent=_UNDER_BULLET)


def draw_statements(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    meta = document.metadata
    pdf.heading(label(document, "Statements"))
    _items(pdf, document, (*document.statements,
                           QT_TR_NOOP("The results relate only to the item tested, as "
                                      "received, under the conditions stated.")
                           if document.is_test_report else
                           QT_TR_NOOP("The results relate only to the item calibrated, as "
                                      "received, under the conditions stated.")))
    if document.warnings or meta.notes:
        pdf.heading(label(document, "Remarks"))
        _items(pdf, document, document.warnings)
        if meta.notes:
            pdf.paragraph(meta.notes)
