"""A test report's own Chinese word for the item where the catalogue's translations name the
calibrated one.

The window's catalogue translates "the item" of a statement as 被校对象 (the calibrated
item, JJF 1001-2011), right on a calibration certificate (校准证书). A test report (检测报告)
names the item 被检测对象 in its header (app/writers/certificate_pdf/wording.py
REPORT_CHINESE); its statement of conformity, statistics rows and statements said 被校对象
(assessment 70 M9). The English says "the item" in both documents, so the English source
stays one text, and the Chinese is chosen by the document's kind after translation: a
translated text (never typed text, which comes back from the catalogue as it is) of a test
report has its calibration terms replaced by the test report's.
"""

from __future__ import annotations

from collections.abc import Callable

#: the calibrated item's terms in the catalogue's translations → a test report's, as the
#: report's header names the item (被检测对象, JJF 1001-2011 检测)
REPORT_ITEM_TERMS = {"被校准对象": "被检测对象", "被校对象": "被检测对象"}


def in_report_terms(chinese: str) -> str:
    """``chinese``, a translated text, with the calibrated item's terms of
    :data:`REPORT_ITEM_TERMS` replaced by a test report's."""
    for calibrated, tested in REPORT_ITEM_TERMS.items():
        chinese = chinese.replace(calibrated, tested)
    return chinese


def report_translator(translate: Callable[[str], str]) -> Callable[[str], str]:
    """``translate`` (English → Chinese, a text it does not know as it is) for a test
    report: what it translates in the report's terms (:func:`in_report_terms`), what it
    returns unchanged (typed text, figures) as it is."""

    def said(text: str) -> str:
        chinese = translate(text)
        return chinese if chinese == text else in_report_terms(chinese)

    return said
