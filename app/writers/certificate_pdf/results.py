"""The measured results: the parameters identified, the error curves, the statistics and the
results table."""

from __future__ import annotations

from app.writers.certificate_pdf.certificate_page import _CertificatePdf
from app.writers.certificate_pdf.wording import label
from models.certificate.document import CertificateDocument

#: how far (mm) a bilingual table's heading needs below it for its two-line header and a
#: first row in both languages (zh81: "轴线定位指标 Figures of the axis" alone at a page's foot)
_BILINGUAL_KEEP_WITH = 30.0


def draw_parameters(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    pdf.heading(label(document, document.parameters.title),
                keep_with=_BILINGUAL_KEEP_WITH if pdf.language == "zh+en" else 18.0)
    pdf.data_table(document.parameters, (70, 60, 44), ("LEFT", "RIGHT", "RIGHT"),
                   rows_in_both=True, report=document.is_test_report)


def draw_curves(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    pdf.heading(label(document, "Error curves"), keep_with=75.0)
    for figure in document.plots:
        pdf.plot(figure)


def draw_statistics(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    pdf.heading(label(document, document.statistics.title),
                keep_with=_BILINGUAL_KEEP_WITH if pdf.language == "zh+en" else 18.0)
    # its rows and notes in Chinese above the English on a bilingual certificate, as the
    # header (zh81: a theodolite run's note on figures without an interval English only)
    both = {"rows_in_both": True, "report": document.is_test_report}
    if len(document.statistics.header) == 5:  # figures with their coverage interval
        pdf.data_table(document.statistics, (46, 26, 42, 24, 36),
                       ("LEFT", "RIGHT", "RIGHT", "RIGHT", "LEFT"), **both)
    else:
        pdf.data_table(document.statistics, (56, 42, 76), ("LEFT", "RIGHT", "LEFT"), **both)


def draw_results(pdf: _CertificatePdf, document: CertificateDocument) -> None:
    # the heading with the table's header and a row at least, never alone at the foot of a
    # page: a bilingual header takes two lines (its heading was left alone on the theodolite's)
    pdf.heading(label(document, document.results.title),
                keep_with=26.0 if pdf.language == "zh+en" else 18.0)
    n_cols = len(document.results.header)
    # a text cell ("reference point, by definition") and the table's note in both (zh81)
    pdf.data_table(document.results, (174 / n_cols,) * n_cols, ("RIGHT",) * n_cols,
                   rows_in_both=True, report=document.is_test_report)
