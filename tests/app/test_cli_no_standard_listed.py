"""The command line with a tolerance and no reference standard listed (audit 71 finding 2):
positioning, theodolite and fringe, every input's u typed, stated "pass" in the JSON and "The
item conforms" in the PDF while the same PDF said traceability is "not established … no
reference standard with a calibration certificate". No statement is made: the JSON's verdict
null with the reason, the PDF and the XLSX say so; the figure and its interval are given.
The document is a test report, not a calibration certificate, the reason its traceability
statement (assessment 72 M3: titled "Calibration certificate" while it said traceability was
not established), a draft or a specimen alike."""

from __future__ import annotations

import io
import json
from pathlib import Path

import pytest
from openpyxl import load_workbook

from app.main import main
from tests.pdf_text import pdf_text

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"

#: (sample, the settings every input's u is stated with, the tolerance, the standards that
#: carry the measurand as the reason names them)
CASES = {
    "positioning": ("positioning_sample.csv",
                    ["--misalignment-u", "0.2", "--reference-resolution", "0.1",
                     "--temperature-u", "0.2"], 15.0, ["the reference measuring system"]),
    "theodolite": ("theodolite_sample.csv", [], 3.0, ["the autocollimating theodolite"]),
    "fringe": ("fringe_sample.csv",
               ["--samples-per-period", "64", "--phase-reference-u", "0.01", "--adc-lsb-mv", "0.3",
                "--adc-offset-u-mv", "0.5", "--adc-gain-u-pct", "0.02",
                "--adc-linearity-mv", "0.6"], 3.0,
               ["a phase or angle reference", "the ADC (its figures stated in the settings)"]),
}


@pytest.mark.parametrize("key", sorted(CASES))
def test_no_verdict_on_the_command_line_with_no_standard_listed(key, tmp_path, capsys):
    sample, settings, tolerance, roles = CASES[key]
    meta = tmp_path / "meta.json"
    # the audit's details: a tolerance, the simple rule, nothing else (a draft)
    meta.write_text(json.dumps({"tolerance": tolerance, "tolerance_unit": "arcsec",
                                "decision_rule": "simple", "decision_quantity": "half_range"}),
                    encoding="utf-8")
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"
    code = main(["analyze", key, str(SAMPLES / sample), "--json", *settings,
                 "--metadata", str(meta), "--certificate", str(pdf), "--results", str(xlsx)])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    out = json.loads(captured.out)
    decided = out["decided_quantity"]
    assert out["uncertainty_inputs_not_stated"] == []  # every input's u typed
    assert decided["verdict"] is None and decided["probability_conforming"] is None
    reason = decided["reason"]
    assert "none is listed, so the uncertainty holds no standard's calibration" in reason
    for role in roles:
        assert role in reason
    assert decided["value"] is not None
    assert decided["interval_low"] <= decided["value"] <= decided["interval_high"]
    text = pdf_text(pdf.read_bytes())
    assert "Test report" in text and "Calibration certificate" not in text
    assert "This document is a test report, not a calibration certificate" in text
    assert "Metrological traceability: not established for these results" in text
    assert "No statement of conformity" in text and "conforms to the specification" not in text
    assert "none is listed, so the uncertainty holds no standard" in text
    book = load_workbook(io.BytesIO(xlsx.read_bytes()), read_only=True)
    cells = [str(c) for sheet in book for row in sheet.iter_rows(values_only=True)
             for c in row if c is not None]
    assert "No statement of conformity because" in cells
    assert any("none is listed, so the uncertainty holds no standard" in c for c in cells)


def test_a_specimen_with_no_standard_listed_is_a_test_report(tmp_path, capsys):
    """The bundled example's details without their standards: a specimen titled "Test report"
    (检测报告 in Chinese), its reason stated."""
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    details["standards"] = []
    for language, title, other in (("en", "Test report", "Calibration certificate"),
                                   ("zh", "检测报告", "校准证书")):
        meta, pdf = tmp_path / f"meta_{language}.json", tmp_path / f"t_{language}.pdf"
        meta.write_text(json.dumps({**details, "language": language}), encoding="utf-8")
        code = main(["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"),
                     "--metadata", str(meta), "--certificate", str(pdf)])
        assert code == 0, capsys.readouterr().err
        head = pdf_text(pdf.read_bytes())[:200]  # the title, before the first heading
        assert title in head and other not in head, language


def test_the_refusals_and_the_draft_banner_name_a_test_report_as_one(tmp_path, capsys):
    """Assessment 73 L2: ``--dcc`` with a specimen and no standard listed refused with "the
    certificate is a DRAFT" beside a PDF issued as "SPECIMEN … Test report"; a draft test
    report's banner read "Missing: certificate number" beside its "Report number". Each now
    names the document it is: a specimen test report's incomplete details, a draft test
    report, and its "report number"."""
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    details["standards"] = []
    meta = tmp_path / "specimen.json"
    meta.write_text(json.dumps({**details, "language": "en"}), encoding="utf-8")
    code = main(["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"),
                 "--metadata", str(meta), "--certificate", str(tmp_path / "s.pdf"),
                 "--dcc", str(tmp_path / "s.xml")])
    said = " ".join(capsys.readouterr())
    assert code != 0 and not (tmp_path / "s.xml").exists()
    assert "the certificate is a DRAFT" not in said and "neither the certificate" not in said
    assert "specimen test report" in said and "neither the test report nor its DCC" in said
    draft = {k: v for k, v in details.items() if k not in ("example", "certificate_number")}
    meta = tmp_path / "draft.json"
    meta.write_text(json.dumps({**draft, "language": "en"}), encoding="utf-8")
    pdf = tmp_path / "d.pdf"
    code = main(["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"),
                 "--metadata", str(meta), "--certificate", str(pdf), "--dcc",
                 str(tmp_path / "d.xml")])
    said = " ".join(capsys.readouterr())
    assert code != 0 and "the test report is a DRAFT (report number" in said, said
    code = main(["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"),
                 "--metadata", str(meta), "--certificate", str(pdf)])
    assert code == 0, capsys.readouterr().err
    text = pdf_text(pdf.read_bytes())
    assert "DRAFT — not valid as a test report. Missing: report number" in text
    assert "certificate number" not in text


@pytest.mark.parametrize("language", ["en", "zh", "zh+en"])
def test_a_test_reports_workbook_names_its_details_sheet_report(tmp_path, capsys, language):
    """Assessment 73 L4: a test report's XLSX kept its details on a sheet named
    *Certificate*; it is named *Report* (the sheets keep their names in every language),
    and a calibration certificate's keeps *Certificate*. ``register verify`` reads either."""
    from app.writers.results_export import issue_stated

    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    for standards, sheet, other in (([], "Report", "Certificate"),
                                    (details["standards"], "Certificate", "Report")):
        meta, book = tmp_path / "meta.json", tmp_path / f"r_{sheet}.xlsx"
        meta.write_text(json.dumps({**details, "standards": standards, "language": language}),
                        encoding="utf-8")
        code = main(["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"),
                     "--metadata", str(meta), "--results", str(book)])
        assert code == 0, capsys.readouterr().err
        names = load_workbook(book, read_only=True).sheetnames
        assert sheet in names and other not in names, names
        assert issue_stated(book.read_bytes()) == {"number": "", "pdf_sha256": "",
                                                   "dcc_sha256": ""}
