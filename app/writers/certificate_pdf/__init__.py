"""Print a :class:`~models.certificate.document.CertificateDocument` as a PDF.

fpdf2 writes the page: text stays selectable (embedded, subset TrueType
fonts), the plots are drawn as vector paths, and the same inputs give the
same bytes (fixed creation date and document ID). User text is printed as
plain text — fpdf2 interprets no markup unless asked — and wraps inside its
cell, so a long name or a CJK note cannot break the layout.

Fonts (resources/fonts): DejaVu Sans for Latin, Greek and symbols (Bitstream
Vera / DejaVu licence), Droid Sans Fallback for Chinese, Japanese and Korean
(Apache License 2.0), used for any glyph DejaVu lacks.

One module per thing drawn: the fonts and what they print (fonts), the certificate's
fixed words and its language (wording), where a line may break (line_breaks), the page
with its running head and foot, headings and paragraphs (page), tables (tables), vector
plots (plots), the page every certificate and report is made of (report_pdf), the
certificate's own head, foot and watermark (certificate_page), and the certificate's
sections in print order: front page (front), reference standards and traceability
(traceability), method (method), the measured results (results), measurement uncertainty
(uncertainty), conformity, statements and remarks (statements), signatures and end
(signatures); render puts them together.
"""

from app.writers.certificate_pdf.fonts import close_fonts, font_files
from app.writers.certificate_pdf.render import certificate_pdf_bytes, write_certificate_pdf
from app.writers.certificate_pdf.report_pdf import ReportPdf
from app.writers.certificate_pdf.traceability import _traceability

__all__ = ["ReportPdf", "_traceability", "certificate_pdf_bytes", "close_fonts", "font_files",
           "write_certificate_pdf"]
