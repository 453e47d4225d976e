"""The certificate's fixed words in its language: Chinese headings (JJF 1001-2011 terms), a
text translated on a Chinese certificate, both languages on a bilingual one, and the
punctuation and list joining of composed texts."""

from __future__ import annotations

import functools
from collections.abc import Callable

from models.certificate.document import CertificateDocument
from models.certificate.report_terms import report_translator
from models.messages import JOINS, Message, in_language, joined, message, separated, translator
from models.uncertainty.conformity import VERDICT_WORDS

#: the certificate's fixed words in Chinese, metrology terms as JJF 1001-2011 names them;
#: other words as the window and the register say them (day review 67 F9: the register
#: listed 制造商 where the certificate printed 制造单位)
CHINESE = {
    "Calibration certificate": "校准证书", "Test report": "检测报告",
    "Certificate number": "证书编号", "Date of issue": "签发日期", "Laboratory": "校准机构",
    "Accreditation": "认可", "Customer": "委托方", "Item calibrated": "被校准对象",
    "Manufacturer": "制造商", "Serial number": "出厂编号",
    "Grade / specification": "准确度等级/技术指标", "Date of calibration": "校准日期",
    "Environment": "环境条件", "Readings": "原始记录",
    "Reference standards and traceability": "计量标准及计量溯源性", "Method": "校准方法",
    "Analysis settings": "分析设置", "Error curves": "误差曲线", "Statistics": "统计结果",
    "Measurement uncertainty": "测量不确定度", "Statement of conformity": "符合性声明",
    "Statements": "声明", "Remarks": "备注", "Uncertainty budget": "不确定度分量一览表",
    "Figures of the axis": "轴线定位指标", "Test": "检测", "Sign convention": "符号约定",
    "Model": "型号", "Place of calibration": "校准地点", "Reference": "参考文献",
    "Instrument output": "仪器原始输出", "Changes after capture": "采集后变动",
    "Report number": "报告编号", "Date of test": "检测日期", "Place of test": "检测地点",
    # the results file's (XLSX) own labels and statements (app/writers/results_export.py):
    # its *Certificate* sheet's rows, and the columns a printed figure is split into
    "Status": "状态", "Revision": "版次", "Instrument output SHA-256": "仪器原始输出的 SHA-256",
    "Separate calibration from certificate(s), which stay valid": "独立校准，有别于以下证书（仍然有效）",
    "Why it is a calibration of its own": "作为独立校准的理由",
    "Separate test from report(s), which stay valid": "独立检测，有别于以下报告（仍然有效）",
    "Why it is a test of its own": "作为独立检测的理由",
    "{revision} of {certificate}": "{certificate} 的{revision}",
    "Certificate PDF SHA-256": "证书 PDF 的 SHA-256", "Report PDF SHA-256": "报告 PDF 的 SHA-256",
    "DCC SHA-256": "DCC 的 SHA-256", "Grade": "准确度等级", "Operator": "校准员",
    "Tested by": "检测员", "Approver": "批准人", "Temperature": "温度",
    "Relative humidity": "相对湿度", "Expanded uncertainty U, largest": "扩展不确定度 U（最大值）",
    "No U stated because": "未给出 U 的原因", "Coverage factor k there": "该处的包含因子 k",
    "Coverage probability": "包含概率", "Tolerance ±": "允差 ±", "Decided quantity": "判定的量",
    "Decided value": "判定值",
    "U of the decided value, below it (U−)": "判定值向下的 U（U−）",
    "U of the decided value, above it (U+)": "判定值向上的 U（U+）",
    "Decided value: interval low": "判定值：区间下端", "Decided value: interval high": "判定值：区间上端",
    "Decided value: coverage probability": "判定值：包含概率",
    "Probability of conformity": "符合概率", "Probability of a wrong decision": "误判概率",
    "Probabilities stated as": "概率的给出方式",
    "Verdict": "结论", "No statement of conformity because": "未作符合性声明的原因",
    "Conformity": "符合性", "Decision rule": "判定规则", "Zones": "判定区间",
    "Inputs not stated, so not in U": "未给出、因而未计入 U 的输入量", "Notes": "备注",
    "Statement {i}": "声明 {i}", "Setting: {label}": "设置：{label}", "Standard {i}": "计量标准 {i}",
    "Standard {i} uncertainty": "计量标准 {i} 的不确定度",
    "serial {serial}": "出厂编号 {serial}", "certificate {certificate}": "证书编号 {certificate}",
    "Value": "量值", "from": "起", "to": "止", "first": "第一个", "second": "第二个",
    "{column}: unit": "{column}：单位",
    "not issued: these results were written apart from any certificate's issue, so they are "
    "no certificate's record; a certificate number or date of issue typed in the details is "
    "not shown": "未签发：这些结果在签发任何证书之外写出，因而不是任何证书的记录；信息中填写的证书编号"
                 "或签发日期不予给出",
    "not issued: these results were written apart from any report's issue, so they are no "
    "report's record; a report number or date of issue typed in the details is not shown":
        "未签发：这些结果在签发任何报告之外写出，因而不是任何报告的记录；信息中填写的报告编号或签发日期"
        "不予给出",
    "issued: the results of certificate {number}, written when the register issued it; the "
    "register holds this file's SHA-256 ('anglebench register verify FILE' checks it)":
        "已签发：证书 {number} 的结果，在登记册签发该证书时写出；登记册保存本文件的 SHA-256"
        "（用“anglebench register verify 文件”核对）",
    "issued: the results of test report {number}, written when the register issued it; the "
    "register holds this file's SHA-256 ('anglebench register verify FILE' checks it)":
        "已签发：检测报告 {number} 的结果，在登记册签发该报告时写出；登记册保存本文件的 SHA-256"
        "（用“anglebench register verify 文件”核对）",
}

#: a test report's own words for the fields a calibration certificate names after the
#: calibration (ISO/IEC 17025 7.8.2.1 a): the document identifies itself as what it is)
REPORT_WORDS = {"Certificate number": "Report number", "Date of calibration": "Date of test",
                # the item, as each document calls it (day 74 finding 13: "被校准对象 / Item under
                # test" on a calibration certificate; "the item calibrated" in its statements)
                "Item calibrated": "Item under test",
                "Place of calibration": "Place of test", "Operator": "Tested by",
                "Certificate PDF SHA-256": "Report PDF SHA-256",
                "Separate calibration from certificate(s), which stay valid":
                    "Separate test from report(s), which stay valid",
                "Why it is a calibration of its own": "Why it is a test of its own"}
#: and in Chinese, where the certificate's term says 校准 (JJF 1001-2011: 检测 for a test)
REPORT_CHINESE = {"Laboratory": "检测机构", "Item under test": "被检测对象", "Method": "检测方法"}
#: the results file's (XLSX) *Certificate* sheet's row naming the workbench's test
#: ("Polygon encoder test"): a key of its own, in English "Test" as before; in Chinese 校准项目
#: on a calibration certificate's sheet, 检测项目 on a test report's (the PDF's "Test", 检测,
#: titles a table and stays as it is)
#: (app/writers/results_export.py SHEET_TEST)
SHEET_WORDS = {"Test (the test performed)": "Test"}
#: a verdict in Chinese as the statement of conformity words it (合格, not the catalogue's
#: 通过 of a check passed: assessment 72 L1); the window's verdict line says the same
VERDICT_CHINESE = VERDICT_WORDS["zh"]
SHEET_CHINESE = {"Test (the test performed)": "校准项目"}
REPORT_SHEET_CHINESE = {"Test (the test performed)": "检测项目"}


def label(document: CertificateDocument, english: str, separator: str = " ") -> str:
    """``english``, with its Chinese in front on a bilingual certificate, or in Chinese
    alone on a Chinese one."""
    language = document.metadata.language
    chinese_words = CHINESE
    if document.is_test_report:
        english = REPORT_WORDS.get(english, english)
        chinese_words = {**CHINESE, **REPORT_CHINESE}
    if language == "zh+en":
        # the fixed words, else the catalogue's, as a Chinese certificate says it (zh81: a
        # workbench's own table titles, "Set-up parameters identified", English only)
        chinese = chinese_words.get(english) or _say("zh", document.is_test_report)(english)
        return english if chinese == str(english) else f"{chinese}{separator}{english}"
    if language == "zh":
        return chinese_words.get(english) or _say("zh", document.is_test_report)(english)
    return english


def own_words(document: CertificateDocument, english):
    """``english``, a label of the certificate, in a test report's own words ("Report number"
    for "Certificate number"); a calibration certificate's as it is."""
    if document.is_test_report and not isinstance(english, Message):
        return REPORT_WORDS.get(english, english)
    return english


def in_chinese(document: CertificateDocument, english) -> str:
    """``english`` (a label, perhaps ending in its unit, or a :class:`Message` of the
    certificate's own words) in Chinese as :func:`label` gives it: the certificate's fixed
    words (a test report's own), else the catalogue's, the unit kept."""
    return in_language(own_words(document, english), _chinese_words(document.is_test_report))


@functools.cache
def _chinese_words(report: bool) -> Callable[[str], str]:
    words = {**CHINESE, **REPORT_CHINESE} if report else CHINESE
    catalogue = report_translator(translator("zh_CN")) if report else translator("zh_CN")
    return lambda text: words.get(text) or catalogue(text)


@functools.cache
def _say(language: str, report: bool = False):
    """How the certificate's texts are printed in ``language``: a :class:`Message` in the
    translated template with its own figures, another text looked up whole (a column's
    name, a setting's label), anything else — user input, numbers — as it is. Only a
    Chinese certificate is translated throughout: the bilingual one keeps the English body
    under its two-language headings, except what :func:`_in_both` prints twice. ``report``:
    a test report's, which names the item in its own terms
    (models.certificate.report_terms)."""
    if language != "zh":
        return str
    words = report_translator(translator("zh_CN")) if report else translator("zh_CN")
    return lambda text: in_language(text, words)


def _in_both(document: CertificateDocument, text) -> list[str]:
    """``text`` as the certificate prints it: on a bilingual certificate in Chinese, then in
    English, from the one message, so with the same figures (once, when it has no Chinese:
    a lab's own words); else once, in the certificate's language (the page translates a
    Chinese one). For the texts a bilingual certificate gives in both languages: the
    statement of conformity with its rule, decided quantity and zones, the statements and
    the remarks, the traceability statement, the method and the uncertainty's statement of
    U, k and p, and the cells of the statistics table (each its Chinese above its English:
    :meth:`~app.writers.certificate_pdf.tables.TableDrawing.data_table`; the other tables'
    headers are in both)."""
    if document.metadata.language != "zh+en" or not text:
        return [text]
    return _chinese_then_english(text, document.is_test_report)


def _chinese_then_english(text, report: bool = False) -> list[str]:
    """``text`` in Chinese, then in English, from the one message (:func:`_in_both`); once,
    as it is, where it has no Chinese (a figure, a lab's own words). ``report``: a test
    report's, which names the item in its own terms."""
    chinese, english = _say("zh", report)(text), str(text)
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
