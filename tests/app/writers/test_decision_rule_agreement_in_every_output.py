"""Whether the decision rule was agreed with the customer, in every output of the issue
(assessment 76 L5; ISO/IEC 17025 7.1.3, ILAC-G8:09/2019). The theodolite sample against
±1″ by simple acceptance passed with a 41.57 % risk of a false acceptance and nothing said of
the rule's agreement. The details' ``decision_rule_agreed`` now says it: "agreed with the
customer" where true, else "the rule requested …; no agreement … is recorded" — in the PDF's
*Decision rule*, the XLSX's *Decision rule* row, the DCC's rule and the JSON's
``decided_quantity.rule_agreed``."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import pytest
from openpyxl import load_workbook

from app.main import main
from tests.pdf_text import pdf_text

pytestmark = pytest.mark.slow  # two certificates, their DCCs and workbooks

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
AGREED = "agreed with the customer (ISO/IEC 17025 7.1.3)"
REQUESTED = ("the rule requested with the specification; no agreement of it with the customer "
             "is recorded (ISO/IEC 17025 7.1.3)")


def _main(args: list[str]) -> str:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


@pytest.mark.parametrize("agreed", [True, False, None], ids=["agreed", "not", "field absent"])
def test_the_rules_agreement_is_said_in_json_xlsx_pdf_and_dcc(tmp_path, monkeypatch, agreed):
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text(encoding="utf-8"))
    details.update(example=False, certificate_number="AB-2026-0710", approver="Dr. Li",
                   tolerance=1.0, tolerance_unit="arcsec", decision_rule="simple")
    if agreed is not None:
        details["decision_rule_agreed"] = agreed
    meta = tmp_path / "details.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    said, other = (AGREED, REQUESTED) if agreed else (REQUESTED, AGREED)
    common = ["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"), "--metadata",
              str(meta), "--language", "en"]
    text = _main([*common, "--json"])
    decided = json.loads(text[text.index("{"):])["decided_quantity"]
    assert decided["verdict"] == "pass" and decided["rule"] == "simple"
    assert decided["rule_agreed"] is bool(agreed)
    assert round(100 * decided["decision_risk"], 2) == 41.57  # the risk the rule accepts
    pdf, xml, xlsx = tmp_path / "c.pdf", tmp_path / "c.xml", tmp_path / "c.xlsx"
    _main([*common, "--certificate", str(pdf), "--dcc", str(xml), "--results", str(xlsx)])
    sheet = {r[0]: r[1] for r in load_workbook(xlsx)["Certificate"].iter_rows(values_only=True)}
    assert sheet["Decision rule"].endswith(f"at the limit; {said}")
    printed = " ".join(pdf_text(pdf.read_bytes()).split())
    assert f"at the limit; {said}." in printed and other not in printed
    dcc = xml.read_text(encoding="utf-8")
    assert f"at the limit; {said}" in dcc and other not in dcc
