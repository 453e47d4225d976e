"""The certificate's close: the signatures (operator, checker, approver), the end line and
the register's chain head before it."""

from __future__ import annotations

from fpdf.enums import XPos, YPos

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.fonts import FONT
from app.writers.certificate_pdf.page import GREY, INK
from app.writers.certificate_pdf.wording import _colon, _in_both, _say
from models.messages import QT_TR_NOOP, message


def draw_end(pdf: _CertificatePdf) -> None:
    document = pdf.document
    meta = document.metadata
    _signatures(pdf)
    pdf.set_font(FONT, "", 8)
    report = document.is_test_report  # a report, never "certificate" (ISO/IEC 17025 7.8.2.1 a))
    # in Chinese, then in English on a bilingual certificate (zh81: English only)
    with pdf.local_context(text_color=GREY):
        for said in _in_both(document, message(
                QT_TR_NOOP("— End of test report {number} —") if report else
                QT_TR_NOOP("— End of certificate {number} —"),
                number=meta.certificate_number or "—")):
            pdf.multi_cell(0, 5, pdf.say(said), align="C", new_x=XPos.LMARGIN,
                           new_y=YPos.NEXT)
        if document.register_head:
            pdf.set_font(FONT, "", 7)
            for said in _in_both(document, message(
                    QT_TR_NOOP("The laboratory's certificate register, before this report, "
                               "ended at chain head {head}; 'anglebench register verify --head' "
                               "proves the register still holds that history.") if report else
                    QT_TR_NOOP("The laboratory's certificate register, before this "
                               "certificate, ended at chain head {head}; 'anglebench register "
                               "verify --head' proves the register still holds that history."),
                    head=document.register_head)):
                pdf.multi_cell(0, 4, pdf.say(said), align="C", new_x=XPos.LMARGIN,
                               new_y=YPos.NEXT)


def _signatures(pdf: _CertificatePdf) -> None:
    meta = pdf.document.metadata
    if pdf.will_page_break(34):
        pdf.add_page()
    pdf.ln(8)
    y = pdf.get_y()
    # a test report's operator tested (检测员), never "calibrated" (校准员: "Operator" in Chinese)
    report = pdf.document.is_test_report
    signers = [(QT_TR_NOOP("Tested by") if report else QT_TR_NOOP("Operator"), meta.operator),
               (QT_TR_NOOP("Approved by"), meta.approver)]
    if meta.checker_role:  # the lab's template asks for a checker (核验员, JJF 1071)
        signers = [(QT_TR_NOOP("Tested by") if report else QT_TR_NOOP("Calibrated by"),
                    meta.operator),
                   (QT_TR_NOOP("Checked by"), meta.checker),
                   (QT_TR_NOOP("Approved by"), meta.approver)]
    half = pdf.epw / len(signers)
    for i, (role, name) in enumerate(signers):
        x = pdf.l_margin + i * half
        pdf.set_xy(x, y + 12)
        pdf.set_draw_color(*INK)
        pdf.line(x, y + 12, x + half - 12, y + 12)
        pdf.set_font(FONT, "", 8)
        # each role and "Signature and date" in Chinese and English on a bilingual
        # certificate (zh81: English only without a checker)
        said = (f"{_say('zh', report)(role)} {role}" if pdf.language == "zh+en"
                else pdf.say(role))
        pdf.cell(half - 12, 4.5, f"{said}{_colon(pdf.document)}{name or '—'}",
                 new_x=XPos.LEFT, new_y=YPos.NEXT)
        pdf.set_x(x)
        pdf.cell(half - 12, 4.5, " ".join(pdf.say(part) for part in _in_both(
            pdf.document, QT_TR_NOOP("Signature and date"))), new_x=XPos.LEFT, new_y=YPos.NEXT)
    pdf.set_y(y + 24)
