"""A Chinese test report names the item 被检测对象 throughout, as its header does (assessment
70, M9): its statement of conformity, statistics rows and statements said 被校对象, the
calibrated item, in the PDF, the XLSX and the DCC. A calibration certificate keeps
被校对象."""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest
from lxml import etree
from openpyxl import load_workbook

from app.main import main

pytestmark = pytest.mark.slow  # Chinese certificates printed (seconds each)

CALIBRATED = ("被校对象", "被校准对象")
SAMPLES = {"fringe": "fringe_sample.csv", "theodolite": "theodolite_sample.csv"}


def _issue(tmp_path: Path, samples_dir: Path, key: str, capsys, **details):
    data = json.loads((samples_dir / f"certificate_{key}.json").read_text("utf-8"))
    meta = tmp_path / f"{key}.json"
    meta.write_text(json.dumps({**data, "language": "zh", **details}), "utf-8")
    pdf, xml, xlsx = (tmp_path / f"{key}.{ext}" for ext in ("pdf", "xml", "xlsx"))
    assert main(["analyze", key, str(samples_dir / SAMPLES[key]), "--metadata", str(meta),
                 "--certificate", str(pdf), "--dcc", str(xml), "--results", str(xlsx)]) == 0
    capsys.readouterr()
    text = subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True,
                          check=True, text=True).stdout
    cells = [str(c) for sheet in load_workbook(xlsx, read_only=True).worksheets
             for row in sheet.iter_rows(values_only=True) for c in row if c is not None]
    dcc = [e.text or "" for e in etree.parse(str(xml)).iter()
           if e.get("lang") == "zh"]
    return re.sub(r"\s+", "", text), "\n".join(cells), "\n".join(dcc)


def test_the_fringe_test_report_names_the_item_as_tested(tmp_path, samples_dir, capsys):
    """The bundled fringe record: a test report (its error is not traceable). Its
    statistics row "after compensation (not applied to the item)" and its statements."""
    text, sheets, dcc = _issue(tmp_path, samples_dir, "fringe", capsys)
    assert "检测报告" in text
    for where, said in (("PDF", text), ("XLSX", sheets), ("DCC", dcc)):
        assert not [w for w in CALIBRATED if w in said], where
    assert "补偿后（未施加于被检测对象）" in text
    assert "补偿后（未施加于被检测对象）" in sheets
    assert "除非修正表已载入被检测对象" in dcc


def test_a_test_reports_statement_of_conformity_names_the_item_as_tested(
        tmp_path, samples_dir, capsys):
    """The theodolite sample issued as a test report: "被检测对象符合技术要求"."""
    text, sheets, dcc = _issue(tmp_path, samples_dir, "theodolite", capsys,
                               document_type="test")
    assert "检测报告" in text
    assert "被检测对象符合技术要求" in text
    for where, said in (("PDF", text), ("XLSX", sheets), ("DCC", dcc)):
        assert not [w for w in CALIBRATED if w in said], where


def test_a_calibration_certificate_keeps_the_calibrated_item(tmp_path, samples_dir, capsys):
    text, _, _ = _issue(tmp_path, samples_dir, "theodolite", capsys)
    assert "校准证书" in text
    assert "被校对象符合技术要求" in text and "被检测对象" not in text
