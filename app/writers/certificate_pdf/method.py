"""The method: its text and reference, what validates it (a standard's implementation or a
published non-standard method), the sign convention and the analysis settings."""

from __future__ import annotations

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.page import GREY
from app.writers.certificate_pdf.wording import _colon, _in_both, _stop, _translatable, label
from models.certificate.document import CertificateDocument
from models.messages import QT_TR_NOOP, joined, message
from models.software import software_identity


def draw_method(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    pdf.heading(label(document, "Method"))
    # the method and what validates it in Chinese, then in English on a bilingual certificate
    # (assessment 76 L1: English only); the published reference as written
    pdf.paragraph_in_both(_translatable(document.method))
    if document.method_reference:
        # the published reference once, as written, after its label in both on a bilingual
        # certificate, as the sign convention's (zh81: "Reference:" English only)
        pdf.paragraph(joined([label(document, "Reference"), ": ", document.method_reference,
                              "."]) if pdf.language == "zh+en" else
                      message(QT_TR_NOOP("Reference: {reference}."),
                              reference=document.method_reference), 8, GREY)
    if document.standard:
        pdf.paragraph_in_both(message(QT_TR_NOOP(
            "The evaluation follows {standard}, implemented in AngleBench {version}; its "
            "verification is the validation report of that version (anglebench validate): "
            "simulations with known truth and hand-computed examples, each with its result."),
            standard=document.standard, version=software_identity().printed), 8, GREY)
    else:
        pdf.paragraph_in_both(message(QT_TR_NOOP(
            "This is a non-standard method, published in the reference above and implemented "
            "in AngleBench {version}. Its validation record (ISO/IEC 17025 7.2.2) is the "
            "validation report of that version (anglebench validate): the reference figures of "
            "the publication and exact simulations with known truth, each with its result."),
            version=software_identity().printed), 8, GREY)
    pdf.paragraph(joined([label(document, "Sign convention"), _colon(document),
                          _translatable(document.sign_convention), _stop(document)]), 8.5)
    if document.settings:
        pdf.heading(label(document, "Analysis settings"), keep_with=30)
        # each label and value in Chinese above its English on a bilingual certificate (zh81)
        pdf.key_values([("\n".join(_in_both(document, key)), "\n".join(_in_both(document, value)))
                        for key, value in document.settings])
