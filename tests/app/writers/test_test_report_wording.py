"""A test report speaks of itself as a report throughout (review 61, F8; ISO/IEC 17025
7.8.2.1 a)).

The fringe's document, titled "Test report", still printed "Certificate number", "Date of
calibration", "This certificate shall not be reproduced…" on every page, "— End of
certificate N —", "the item calibrated", the DCC's validity spoke of a certificate and the
command line said "Certificate N issued". In Chinese: 证书编号, 校准日期, 本证书, 校准员.
A calibration certificate keeps its words.
"""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest
from lxml import etree

from app.main import main
from models.dcc import vocabulary as v

NS = {"dcc": v.DCC_NAMESPACE}


def _issue(tmp_path: Path, samples_dir: Path, key: str, language: str, capsys):
    data = json.loads((samples_dir / f"certificate_{key}.json").read_text("utf-8"))
    meta = tmp_path / f"{key}-{language}.json"
    meta.write_text(json.dumps({**data, "example": False, "language": language}), "utf-8")
    pdf, xml = tmp_path / f"{key}-{language}.pdf", tmp_path / f"{key}-{language}.xml"
    sample = {"fringe": "fringe_sample.csv", "theodolite": "theodolite_sample.csv"}[key]
    assert main(["analyze", key, str(samples_dir / sample), "--metadata", str(meta),
                 "--certificate", str(pdf), "--dcc", str(xml)]) == 0
    said = capsys.readouterr()
    text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True,
                          check=True, text=True).stdout
    return said.out + said.err, re.sub(r"[ \t]+", " ", text), etree.parse(str(xml))


def _number(said: str) -> str:
    return re.search(r"AB-\d{4}-\d{4}", said).group(0)


@pytest.mark.slow
def test_the_english_test_report_calls_itself_a_report(tmp_path, samples_dir, capsys):
    said, text, dcc = _issue(tmp_path, samples_dir, "fringe", "en", capsys)
    number = _number(said)
    assert f"Test report {number} issued: written to" in said and "Certificate" not in said
    assert "Test report" in text
    for wrong in ("Certificate number", "Date of calibration", "Place of calibration",
                  "This certificate shall not be reproduced", "End of certificate",
                  "item calibrated", f"Certificate {number}", "before this certificate"):
        assert wrong not in text, wrong
    pages = int(re.search(r"Page 1 of (\d+)", text).group(1))
    assert text.count("This report shall not be reproduced except in full without the "
                      "laboratory's written approval.") == pages
    assert text.count(f"Test report {number} · AngleBench") == pages
    assert f"Report number {number}" in text and "Date of test 2026-11-20" in text
    assert f"— End of test report {number} —" in text
    assert "The results relate only to the item tested, as received" in text
    validity = dcc.find(".//dcc:statement[@refType='anglebench_validity']//dcc:content", NS)
    assert validity.text.startswith("The results relate only to the item tested, at the time "
                                    "and under the conditions of the test.")
    names = [e.text for e in dcc.iterfind(".//dcc:document/dcc:name/dcc:content", NS)]
    assert f"Test report {number} (PDF)" in names


@pytest.mark.slow
def test_the_chinese_test_report_calls_itself_a_report(tmp_path, samples_dir, capsys):
    said, text, _ = _issue(tmp_path, samples_dir, "fringe", "zh", capsys)
    number = _number(said)
    assert "检测报告" in text
    # (证书编号 stays a column of the standards table: their certificates' numbers)
    for wrong in (f"证书编号 {number}", "校准日期", "校准地点", "本证书", f"证书 {number}", "校准员",
                  "被校准对象", "所校准的对象"):
        assert wrong not in text, wrong
    assert f"报告编号 {number}" in text and "检测日期 2026-11-20" in text
    assert "未经本实验室书面批准，不得部分复制本报告。" in text
    assert f"— 检测报告 {number} 结束 —" in text
    assert "检测员" in text and "被检测对象" in text


@pytest.mark.slow
def test_a_calibration_certificate_keeps_its_words(tmp_path, samples_dir, capsys):
    said, text, dcc = _issue(tmp_path, samples_dir, "theodolite", "en", capsys)
    number = _number(said)
    assert f"Certificate {number} issued: written to" in said
    assert "Calibration certificate" in text and "Test report" not in text
    assert f"Certificate number {number}" in text and "Date of calibration" in text
    assert f"— End of certificate {number} —" in text
    assert "The results relate only to the item calibrated" in text
    validity = dcc.find(".//dcc:statement[@refType='anglebench_validity']//dcc:content", NS)
    assert validity.text.startswith("The results relate only to the item calibrated")
