"""What U lacks is said with the budget, and the JSON lists it (review 61, F6).

The fringe's test report said under traceability that the phase reference and the ADC have
no stated uncertainty, while its budget (one row, "Signal noise") and its U stood as if
complete, and the JSON gave ``"uncertainty_inputs_not_stated": []``. GUM 7.2.7: the
components of U are listed; the ones left out are named where U is. The positioning
certificate said it among its statements; now every certificate says it under the budget,
once, in PDF, XLSX and DCC.
"""

from __future__ import annotations

import io
import json
import re
from dataclasses import replace
from pathlib import Path

import pytest
from pypdf import PdfReader

from app.writers.certificate_pdf import certificate_pdf_bytes
from app.writers.results_export import _metadata_rows
from models.certificate.metadata import CertificateMetadata
from models.certificate.uncertainty_json import workbench_uncertainty_json
from models.messages import translator
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
LINE = ("Inputs not stated, so not in U: Phase reference, ADC quantisation, ADC offset, ADC gain "
        "ratio, ADC linearity. U covers only the inputs in the budget.")


def _details(key: str) -> CertificateMetadata:
    data = json.loads((SAMPLES / f"certificate_{key}.json").read_text("utf-8"))
    return CertificateMetadata.from_dict({**data, "example": False})


def _analysed(key: str, **settings):
    kind = KINDS[key]
    table = read_table(SAMPLES / kind.sample_file)
    parsed = ReadingsSheet(kind.columns, map_columns(table, kind.columns)).parse()
    chosen = kind.settings_with_defaults(settings)
    return kind, kind.analyze(parsed, chosen), chosen


def _flat(pdf: bytes) -> str:
    text = "\n".join(p.extract_text() for p in PdfReader(io.BytesIO(pdf)).pages)
    return re.sub(r"\s+", " ", text)


def _section(flat: str, start: str, end: str) -> str:
    return flat[flat.index(start):flat.index(end, flat.index(start))]


@pytest.mark.slow
def test_the_fringe_names_what_u_lacks_under_its_budget_and_in_the_json():
    kind, result, settings = _analysed("fringe")
    meta = _details("fringe")
    document = kind.certificate_document(result, meta, kind.sample_file, settings=settings)
    assert [c.name for c in document.budget.components] == ["Signal noise"]
    flat = _flat(certificate_pdf_bytes(document))
    budget = _section(flat, "Measurement uncertainty", "Statement of conformity")
    assert LINE in budget
    assert flat.count("Inputs not stated, so not in U") == 1
    data = workbench_uncertainty_json(kind, result, meta, settings)
    assert data["uncertainty_inputs_not_stated"] == [
        "Phase reference", "ADC quantisation", "ADC offset", "ADC gain ratio", "ADC linearity"]
    rows = dict(_metadata_rows(document))
    assert str(rows["Inputs not stated, so not in U"]) == LINE
    zh = replace(meta, language="zh")
    chinese = _flat(certificate_pdf_bytes(kind.certificate_document(result, zh, settings=settings)))
    words = translator("zh_CN")
    assert "未给出、因而未计入 U 的输入量：" in chinese
    assert f"{words('Phase reference')}、{words('ADC quantisation')}" in chinese


@pytest.mark.slow
def test_a_stated_adc_figure_enters_the_budget_and_leaves_the_list():
    kind, result, settings = _analysed("fringe", adc_offset_u_mv=0.5, adc_gain_u_pct=0.1)
    meta = _details("fringe")
    document = kind.certificate_document(result, meta, settings=settings)
    names = [c.name for c in document.budget.components]
    assert "ADC offset" in names and "ADC gain ratio" in names
    assert document.not_in_u == ("Phase reference", "ADC quantisation", "ADC linearity")
    assert workbench_uncertainty_json(kind, result, meta, settings)[
        "uncertainty_inputs_not_stated"] == ["Phase reference", "ADC quantisation",
                                             "ADC linearity"]


@pytest.mark.slow
def test_positioning_says_it_once_under_the_budget():
    kind, result, settings = _analysed("positioning")
    document = kind.certificate_document(result, _details("positioning"), settings=settings)
    flat = _flat(certificate_pdf_bytes(document))
    line = ("Inputs not stated, so not in U: Misalignment of the reference, Resolution of the "
            "reference, Temperature. U covers only the inputs in the budget.")
    assert line in _section(flat, "Measurement uncertainty", "Statement of conformity")
    assert flat.count("Inputs not stated, so not in U") == 1
