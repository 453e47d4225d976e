"""The page the certificate and the validation report are made of."""

from __future__ import annotations

from app.writers.certificate_pdf.plots import PlotDrawing
from app.writers.certificate_pdf.tables import TableDrawing


class ReportPdf(TableDrawing, PlotDrawing):
    """An A4 page with the bundled fonts, a running head and foot, headings, paragraphs,
    tables and vector plots: the certificate and the validation report are made of it.

    ``head`` is (left, right) text at the top of every page, ``foot`` the lines at the
    bottom (the first gets "Page x of y" beside it).
    """
