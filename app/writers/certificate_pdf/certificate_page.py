"""The certificate's page: the lab and the certificate number at the head, the reproduction
notice and the software at the foot, the register's chain head, a DRAFT or SPECIMEN
watermark."""

from __future__ import annotations

from app.writers.certificate_pdf.fonts import _needs_fallback
from app.writers.certificate_pdf.page import INK
from app.writers.certificate_pdf.report_pdf import ReportPdf
from app.writers.certificate_pdf.wording import _in_both, _say
from models.certificate.document import CertificateDocument
from models.messages import QT_TR_NOOP, message
from models.software import software_identity


class _CertificatePdf(ReportPdf):
    def __init__(self, document: CertificateDocument) -> None:
        meta = document.metadata
        # a test report speaks of itself as a report throughout (ISO/IEC 17025 7.8.2.1 a))
        report = document.is_test_report
        say = _say(meta.language, report)
        notice = (QT_TR_NOOP("This report shall not be reproduced except in full without the "
                             "laboratory's written approval.") if report else
                  QT_TR_NOOP("This certificate shall not be reproduced except in full without "
                             "the laboratory's written approval."))
        super().__init__(
            # the number in Chinese, then in English on a bilingual certificate (zh81)
            (meta.lab_name or say(QT_TR_NOOP("Laboratory not stated")),
             " ".join(say(part) for part in _in_both(document, message(
                 QT_TR_NOOP("Test report {number}") if report else
                 QT_TR_NOOP("Certificate {number}"), number=meta.certificate_number)
                 if meta.certificate_number else
                 message(QT_TR_NOOP("Test report no number") if report else
                         QT_TR_NOOP("Certificate no number"))))),
            # the notice in Chinese above the English on a bilingual certificate (zh81)
            ("\n".join(say(line) for line in _in_both(document, message(notice))),
             say(message(QT_TR_NOOP("Test report {number} · AngleBench {version}") if report else
                         QT_TR_NOOP("Certificate {number} · AngleBench {version}"),
                         number=meta.certificate_number or "—",
                         version=software_identity().short))),
            cjk=_needs_fallback(document) or document.metadata.language != "en",
            language=meta.language)
        self.say = say  # and names its item in its own terms (被检测对象, not 被校对象)
        self.document = document

    def paragraph_in_both(self, text, size: float = 9, color=INK) -> None:
        """``text`` as a paragraph: on a bilingual certificate in Chinese and then in English
        (:func:`~app.writers.certificate_pdf.wording._in_both`: from the one message, so with
        the same figures; once where it has no Chinese), else once in the certificate's
        language."""
        for i, said in enumerate(_in_both(self.document, text)):
            if i:
                self.ln(1)
            self.paragraph(said, size, color)

    def header(self) -> None:
        super().header()
        if self.document.specimen:
            self._watermark(QT_TR_NOOP("SPECIMEN"), 60)
        elif self.document.is_draft:
            self._watermark(QT_TR_NOOP("DRAFT"), 90)

    def _watermark(self, word: str = QT_TR_NOOP("DRAFT"), size: float = 90) -> None:
        x, y = self.get_x(), self.get_y()
        with (self.local_context(text_color=(235, 200, 200)),
              self.rotation(45, self.w / 2, self.h / 2)):
            self.mixed_text(self.w / 2 - 60, self.h / 2 + 12, self.say(word), size, "B")
        self.set_xy(x, y)

    def _foot_anchor(self) -> None:
        head = self.document.register_head
        if head:
            self.set_xy(self.l_margin, self.h - 6)
            # in Chinese, then in English on the one line of a bilingual certificate (zh81)
            self.cell(self.epw, 3.5, " ".join(self.say(said) for said in _in_both(
                self.document, message(
                    QT_TR_NOOP("Register chain head before this report: {head}…")
                    if self.document.is_test_report else
                    QT_TR_NOOP("Register chain head before this certificate: {head}…"),
                    head=head[:16]))))
