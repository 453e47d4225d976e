"""A standard listed with no stated U: no statement of conformity in any output of the issue
(assessment 70, H1). The theodolite sample with real details whose autocollimating
theodolite has ``"uncertainty": null`` stated "The item conforms to the specification ±3″
(pass)" in the PDF, the XLSX and the DCC, and the JSON's uncertainty_inputs_not_stated was
empty. Each output now names the standard as an input not stated and makes no statement
(models/certificate/test_no_statement_without_traceability.py: every workbench)."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import pytest
from openpyxl import load_workbook

from app.main import main
from tests.pdf_text import pdf_text

pytestmark = pytest.mark.slow  # a certificate, its DCC and workbook

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"


def _main(args: list[str]) -> str:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


def test_a_theodolite_without_stated_u_gets_no_statement_in_json_xlsx_pdf_and_dcc(
        tmp_path, monkeypatch):
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text(encoding="utf-8"))
    details.update(example=False, certificate_number="AB-2026-0700", approver="Dr. Li")
    details["standards"][0]["uncertainty"] = None
    name = details["standards"][0]["description"]
    meta = tmp_path / "details.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    common = ["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"), "--metadata",
              str(meta), "--language", "en"]
    text = _main([*common, "--json"])
    data = json.loads(text[text.index("{"):])
    assert data["uncertainty_inputs_not_stated"] == [name]
    assert data["decided_quantity"]["verdict"] is None
    assert name in data["decided_quantity"]["reason"]
    pdf, xml, xlsx = tmp_path / "c.pdf", tmp_path / "c.xml", tmp_path / "c.xlsx"
    _main([*common, "--certificate", str(pdf), "--dcc", str(xml), "--results", str(xlsx)])
    sheet = {r[0]: r[1] for r in _details_sheet(load_workbook(xlsx)).iter_rows(values_only=True)}
    assert sheet["Verdict"] == "not assessed"
    assert name in sheet["No statement of conformity because"]
    printed = pdf_text(pdf.read_bytes())
    assert "No statement of conformity: U is incomplete" in printed
    assert "conforms to the specification" not in printed
    dcc = xml.read_text(encoding="utf-8")
    assert "<dcc:conformity>" not in dcc and "<dcc:traceable>true</dcc:traceable>" not in dcc
    assert f"Inputs not stated, so not in U: {name}" in dcc


def _details_sheet(book):
    """The sheet of the document's details: *Report* on a test report's file (assessment 73
    L4), else *Certificate*."""
    return book["Report" if "Report" in book.sheetnames else "Certificate"]
