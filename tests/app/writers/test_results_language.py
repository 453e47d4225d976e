"""The XLSX results file speaks the certificate's language and a test report's own words
(note N6 of stop 61).

Each workbench's results file, written from the same analysis with the details in English,
in Chinese and bilingual (``language``: en, zh, zh+en): the Chinese one has no English of
ours left (symbols, units and the Results sheet's column names, which are the JSON's, stay);
the bilingual one gives every label the Chinese beside the English and every text of ours
on the *Certificate* sheet in both; every number cell is the English file's, in the same
place; the sheets keep their documented names. A test report's file says "Report number",
"Date of test" (报告编号, 检测日期) as its PDF does, never "Certificate number" or
"calibration" (证书编号, 校准) in a label.
"""

from __future__ import annotations

import io
import re
from dataclasses import replace

import pytest
from openpyxl import load_workbook

from app.writers.results_export import results_xlsx_bytes
from models.certificate.metadata import CertificateMetadata
from models.registry import KINDS
from tests.app.writers.test_certificate_chinese import SYMBOLS, WORD
from tests.app.writers.test_certificate_export import _analysed

pytestmark = pytest.mark.slow  # five analyses, fifteen workbooks

#: the details typed in Chinese, so that no English in the file is the lab's own
DETAILS = CertificateMetadata.from_dict({
    "lab_name": "精密角度计量实验室", "customer_name": "长春光机所", "item_description": "圆光栅编码器",
    "item_serial": "编号一", "item_grade": "三级", "calibration_date": "2026-11-20",
    "issue_date": "2026-11-24", "created": "2026-11-24T10:00:00", "operator": "王工",
    "approver": "李博士", "temperature_c": 20.1, "humidity_pct": 45, "notes": "备注",
    "standards": [{"description": "参考自准直仪", "serial": "甲-1", "certificate_no": "国家-1",
                   "uncertainty": 0.4}]})
#: Latin words that may stay on a Chinese sheet besides the Chinese certificate's (symbols,
#: units, names of standards and cited authors): the hash's name and the files it is of
#: and a standard's role as it is typed in the details' *Role* column (角色（reference、
#: autocollimator、adc）), which the reason asks to state (assessment 78 H1)
KEPT = SYMBOLS | {"SHA", "PDF", "DCC", "Tian", "reference"}
CJK = re.compile(r"[\u4e00-\u9fff]")


def _meta(key: str, language: str) -> CertificateMetadata:
    meta = replace(DETAILS, language=language)
    return replace(meta, tolerance=None) if key == "polygon" else replace(meta, tolerance=3.0)


@pytest.fixture(scope="module", params=sorted(KINDS))
def books(request):
    """A workbench's document and its results file in each language."""
    key = request.param
    kind, result = _analysed(key)
    out = {}
    for language in ("en", "zh", "zh+en"):
        document = kind.certificate_document(result, _meta(key, language), kind.sample_file)
        out[language] = (document, load_workbook(io.BytesIO(results_xlsx_bytes(document))))
    return key, out


def _cells(book):
    return {(ws.title, r, c): v for ws in book.worksheets
            for r, row in enumerate(ws.iter_rows(values_only=True))
            for c, v in enumerate(row) if v is not None}


def _numbers(book):
    return {at: v for at, v in _cells(book).items() if not isinstance(v, str)}


def _rows(book, title):
    # the details' sheet: *Report* on a test report's file (assessment 73 L4)
    if title == "Certificate" and "Report" in book.sheetnames:
        title = "Report"
    return list(book[title].iter_rows(values_only=True))


def test_a_chinese_results_file_has_no_english_of_ours_and_the_same_numbers(books):
    key, out = books
    english, chinese = out["en"][1], out["zh"][1]
    assert chinese.sheetnames == english.sheetnames == [
        "Results", "Parameters", "Statistics", "Uncertainty budget",
        "Report" if out["en"][0].is_test_report else "Certificate"]
    assert _numbers(chinese) == _numbers(english) and _numbers(english)
    left = {}
    for (title, r, c), value in _cells(chinese).items():
        if not isinstance(value, str) or (title == "Results" and r == 0):
            continue  # a number, or a column's name as the JSON's (documented)
        words = set(WORD.findall(value)) - KEPT
        if words:
            left[f"{title}!{r},{c}: {value[:80]}"] = sorted(words)
    assert not left, f"{key}: English left on the Chinese file: {left}"
    # the labels are the certificate's words (JJF 1001), as its PDF prints them
    labels = [row[0] for row in _rows(chinese, "Certificate")]
    assert ("报告编号" if out["zh"][0].is_test_report else "证书编号") in labels
    assert "签发日期" in labels and "状态" in labels
    assert any(str(label).startswith("扩展不确定度 U（最大值）") for label in labels)


def test_a_bilingual_results_file_gives_both_languages_and_the_same_numbers(books):
    key, out = books
    english, chinese, both = out["en"][1], out["zh"][1], out["zh+en"][1]
    assert both.sheetnames == english.sheetnames
    assert _numbers(both) == _numbers(english)
    # every label: the Chinese, then the English (once where the two are the same)
    for zh, en, said in zip(_rows(chinese, "Certificate"), _rows(english, "Certificate"),
                            _rows(both, "Certificate"), strict=True):
        assert said[0] == (en[0] if zh[0] == en[0] else f"{zh[0]} {en[0]}"), said[0]
        assert CJK.search(said[0]), said[0]
        if isinstance(en[1], str) and en[1]:  # a text of ours in both, typed text once
            assert said[1] in (en[1], f"{zh[1]}\n{en[1]}"), said
            if en[1] != zh[1]:
                assert said[1] == f"{zh[1]}\n{en[1]}", said
    for title in ("Parameters", "Statistics", "Uncertainty budget"):
        for zh, en, said in zip(_rows(chinese, title)[0], _rows(english, title)[0],
                                _rows(both, title)[0], strict=True):
            assert said == (en if zh == en else f"{zh} {en}"), (title, said)
        # the tables' cells in English, as the bilingual certificate prints them
        assert _rows(both, title)[1:] == _rows(english, title)[1:]


def test_a_test_reports_results_file_speaks_of_a_report(books):
    key, out = books
    if not out["en"][0].is_test_report:
        pytest.skip(f"the {key} sample's document is a calibration certificate")
    english = [row[0] for row in _rows(out["en"][1], "Certificate")]
    chinese = [row[0] for row in _rows(out["zh"][1], "Certificate")]
    for label in english:
        assert "Certificate number" not in label and "calibration" not in label.lower(), label
        assert not label.startswith("Certificate"), label
    for label in chinese:
        assert "证书编号" not in label and "校准" not in label, label
    # the PDF's words for a test report (wording.REPORT_WORDS, REPORT_CHINESE)
    assert {"Report number", "Date of test", "Tested by", "Report PDF SHA-256"} <= set(english)
    assert {"报告编号", "检测日期", "检测员", "检测机构", "被检测对象"} <= set(chinese)
    status = dict(_rows(out["en"][1], "Certificate"))["Status"]
    assert "report" in status and "certificate" not in status
    assert "报告" in dict(_rows(out["zh"][1], "Certificate"))["状态"]


def test_a_calibration_certificates_results_file_keeps_its_words():
    kind, result = _analysed("theodolite")
    document = kind.certificate_document(result, _meta("theodolite", "en"), kind.sample_file)
    assert not document.is_test_report
    labels = [row[0] for row in load_workbook(io.BytesIO(results_xlsx_bytes(document)))[
        "Certificate"].iter_rows(values_only=True)]
    assert {"Certificate number", "Date of calibration", "Operator",
            "Certificate PDF SHA-256"} <= set(labels)


def test_an_issued_amendments_record_in_chinese_and_in_both():
    """The register's record on the *Certificate* sheet: its status and revision in the
    certificate's language (the revision in the register's words, as its window says it)."""
    from types import SimpleNamespace

    kind, result = _analysed("theodolite")
    record = SimpleNamespace(number="AB-2026-0001-A2", revision="amendment 2",
                             supersedes="AB-2026-0001", pdf_sha256="ab" * 32,
                             dcc_sha256="cd" * 32, issue_date="2026-11-25")
    said = {}
    for language in ("zh", "zh+en"):
        document = kind.certificate_document(result, _meta("theodolite", language),
                                             kind.sample_file)
        book = load_workbook(io.BytesIO(results_xlsx_bytes(document, issued=record)))
        said[language] = dict(book["Certificate"].iter_rows(values_only=True))
        cell = next(c for (c,) in book["Certificate"].iter_rows(min_col=2, max_col=2)
                    if c.value and c.value.startswith("已签发"))
        assert bool(cell.alignment.wrap_text) == (language == "zh+en")  # two lines shown as two
    assert said["zh"]["证书编号"] == "AB-2026-0001-A2"
    assert said["zh"]["状态"] == ("已签发：证书 AB-2026-0001-A2 的结果，在登记册签发该证书时写出；"
                                "登记册保存本文件的 SHA-256（用“anglebench register verify 文件”核对）")
    assert said["zh"]["版次"] == "AB-2026-0001 的第 2 次修订"
    assert said["zh"]["签发日期"] == "2026-11-25"
    assert said["zh+en"]["版次 Revision"] == "AB-2026-0001 的第 2 次修订\namendment 2 of AB-2026-0001"
    assert said["zh+en"]["状态 Status"].endswith(
        "\nissued: the results of certificate AB-2026-0001-A2, written when the register issued "
        "it; the register holds this file's SHA-256 ('anglebench register verify FILE' checks it)")
