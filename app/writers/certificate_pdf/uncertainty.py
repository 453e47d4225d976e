"""The measurement uncertainty: U and how it was evaluated, the budget at its worst point
and each input's note."""

from __future__ import annotations

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.page import GREY
from app.writers.certificate_pdf.wording import _colon, _in_both, _translatable, label
from models.certificate.document import CertificateDocument, budget_table
from models.messages import QT_TR_NOOP, joined, message
from models.uncertainty.printed_figure import printed


def draw_uncertainty(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    pdf.heading(label(document, "Measurement uncertainty"))
    # U, k, p and the GUM in Chinese, then in English on a bilingual certificate (assessment
    # 76 L1: English only; CNAS assessors read the k and p statement in Chinese)
    big_u = document.expanded_uncertainty
    budget_ = document.budget
    if document.uncertainty_withheld:
        evaluated = budget_.max_expanded
        pdf.paragraph_in_both(message(QT_TR_NOOP(
            "No expanded uncertainty is stated for the results: {reason}. The budget below "
            "holds only the inputs that could be evaluated; they alone give {u} at most (k = "
            "{k}, {p} %), a lower bound of U, not U."),
            reason=document.uncertainty_withheld,
            u=printed(evaluated, document.unit, rounding="up"),
            p=f"{100 * budget_.probability:.2f}", k=f"{budget_.coverage_factor:.2f}"))
    else:
        pdf.paragraph_in_both(message(QT_TR_NOOP(
            "The expanded uncertainty of the error is U = {u} (the largest over the points; each "
            "point's U is in the results table). At each point it is the combined standard "
            "uncertainty multiplied by the coverage factor k of Student's t for that point's "
            "effective degrees of freedom (Welch–Satterthwaite) and a coverage probability of "
            "{p} %; at the largest, k = {k}. The uncertainty was evaluated according to the GUM "
            "(JCGM 100:2008)."), u=printed(big_u, document.unit, rounding="up"),
            p=f"{100 * budget_.probability:.2f}", k=f"{budget_.coverage_factor:.2f}"))
        if budget_.points and bool(budget_.below_floor.any()):
            pdf.paragraph_in_both(message(QT_TR_NOOP(
                "Where that product is below the laboratory's CMC, U = {cmc}, the U stated is "
                "the CMC (ILAC-P14 5.4), with the same k; the budget's last line gives it."),
                cmc=f"{budget_.floor:g}{document.unit}"))
    budget = budget_table(document.budget, document.budget_point, document.unit,
                          bool(document.uncertainty_withheld))
    # its inputs, their notes and the table's note in Chinese, then in English on a
    # bilingual certificate (zh81: English only under "不确定度分量一览表")
    pdf.data_table(budget, (46, 9, 19, 15, 13, 13, 10, 15, 14, 20),
                   ("LEFT", "CENTER", "LEFT") + ("RIGHT",) * 7, size=7, rows_in_both=True,
                   report=document.is_test_report)
    notes = [joined([_translatable(row[0]), _colon(document), _translatable(c.note)])
             for row, c in zip(budget.rows, document.budget.components, strict=False) if c.note]
    for note in notes:
        for said in _in_both(document, note):
            pdf.paragraph(said, 7.5, GREY)
    if document.not_in_u_statement:  # what U lacks, with the budget (GUM 7.2.7)
        pdf.paragraph_in_both(document.not_in_u_statement, 8.5)
