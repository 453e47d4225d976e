"""The certificate's fixed words in its language: Chinese headings (JJF 1001-2011 terms), a
text translated on a Chinese certificate, both languages on a bilingual one, and the
punctuation and list joining of composed texts."""

from __future__ import annotations

import functools

from models.certificate.document import CertificateDocument
from models.messages import JOINS, Message, in_language, joined, message, separated, translator

#: the certificate's fixed words in Chinese, metrology terms as JJF 1001-2011 names them
CHINESE = {
    "Calibration certificate": "校准证书", "Test report": "检测报告",
    "Certificate number": "证书编号", "Date of issue": "签发日期", "Laboratory": "校准机构",
    "Accreditation": "认可", "Customer": "委托方", "Item under test": "被校准对象",
    "Manufacturer": "制造单位", "Serial number": "出厂编号",
    "Grade / specification": "准确度等级/技术指标", "Date of calibration": "校准日期",
    "Environment": "环境条件", "Readings": "原始记录",
    "Reference standards and traceability": "计量标准及计量溯源性", "Method": "校准方法",
    "Analysis settings": "分析设置", "Error curves": "误差曲线", "Statistics": "统计结果",
    "Measurement uncertainty": "测量不确定度", "Statement of conformity": "符合性声明",
    "Statements": "声明", "Remarks": "备注", "Uncertainty budget": "不确定度分量一览表",
    "Figures of the axis": "轴线定位指标", "Test": "检测", "Sign convention": "符号约定",
    "Model": "型号", "Place of calibration": "校准地点",
    "Instrument output": "仪器原始输出", "Edited after capture": "采集后修改",
    "Report number": "报告编号", "Date of test": "检测日期", "Place of test": "检测地点",
}

#: a test report's own words for the fields a calibration certificate names after the
#: calibration (ISO/IEC 17025 7.8.2.1 a): the document identifies itself as what it is)
REPORT_WORDS = {"Certificate number": "Report number", "Date of calibration": "Date of test",
                "Place of calibration": "Place of test"}
#: and in Chinese, where the certificate's term says 校准 (JJF 1001-2011: 检测 for a test)
REPORT_CHINESE = {"Laboratory": "检测机构", "Item under test": "被检测对象", "Method": "检测方法"}


def label(document: CertificateDocument, english: str, separator: str = " ") -> str:
    """``english``, with its Chinese in front on a bilingual certificate, or in Chinese
    alone on a Chinese one."""
    language = document.metadata.language
    chinese_words = CHINESE
    if document.is_test_report:
        english = REPORT_WORDS.get(english, english)
        chinese_words = {**CHINESE, **REPORT_CHINESE}
    if language == "zh+en" and english in chinese_words:
        return f"{chinese_words[english]}{separator}{english}"
    if language == "zh":
        return chinese_words.get(english) or _say("zh")(english)
    return english


@functools.cache
def _say(language: str):
    """How the certificate's texts are printed in ``language``: a :class:`Message` in the
    translated template with its own figures, another text looked up whole (a column's
    name, a setting's label), anything else — user input, numbers — as it is. Only a
    Chinese certificate is translated throughout: the bilingual one keeps the English body
    under its two-language headings, except what :func:`_in_both` prints twice."""
    if language != "zh":
        return str
    words = translator("zh_CN")
    return lambda text: in_language(text, words)


def _in_both(document: CertificateDocument, text) -> list[str]:
    """``text`` as the certificate prints it: on a bilingual certificate in Chinese, then in
    English, from the one message, so with the same figures (once, when it has no Chinese:
    a lab's own words); else once, in the certificate's language (the page translates a
    Chinese one). For the texts a bilingual certificate gives in both languages: the
    statement of conformity with its rule, decided quantity and zones, the statements and
    the remarks (not the tables, whose headers are already in both)."""
    if document.metadata.language != "zh+en" or not text:
        return [text]
    chinese, english = _say("zh")(text), str(text)
    return [english] if chinese == english else [chinese, english]


def _both(text):
    """A column's name in Chinese above the English (a bilingual certificate's headers)."""
    if not text:
        return text
    chinese, english = _say("zh")(text), str(text)
    return english if chinese == english else f"{chinese}\n{english}"


def _colon(document: CertificateDocument) -> str:
    return "：" if document.metadata.language == "zh" else ": "


def _stop(document: CertificateDocument) -> str:
    return "。" if document.metadata.language == "zh" else "."


def _translatable(text: str) -> str:
    """``text`` as a part of a composed text that a Chinese certificate translates: a
    :class:`Message` as it is, any other text looked up whole."""
    return text if isinstance(text, Message) or not text else message(text)


def _between(separator: str, parts) -> list:
    """The non-empty ``parts`` with ``separator`` between them (for :func:`joined`): "; ",
    ", " and " " through :func:`separated`, so that a Chinese certificate joins them with
    its own punctuation ("；", "，"), any other separator (a line break) as it is."""
    kept = [_translatable(part) for part in parts if part]
    if separator in JOINS:
        return [separated(kept, separator)] if kept else []
    out: list = []
    for part in kept:
        out += ([separator] if out else []) + [part]
    return out


def _listed(names) -> str:
    return joined(_between(", ", names))
