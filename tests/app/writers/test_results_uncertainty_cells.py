"""--results as numbers (issue 39): a figure with a symmetric U ("25.01\", U = ±1.35\"", or its
U on a line of its own, "0.407\"\\n±0.094\"") is split into number cells like an asymmetric one,
and the Certificate sheet states the decided value's interval and the decision's risk."""

from __future__ import annotations

import io
from dataclasses import replace

import pytest
from openpyxl import load_workbook

from app.writers.results_export import results_xlsx_bytes, split_figures
from models.certificate.document import Table
from tests.app.writers.test_certificate_export import META, _analysed


@pytest.mark.parametrize(("text", "numbers"), [
    ("25.01\", U = ±1.35\"", (25.01, 1.35, 1.35)),
    ("0.407\"\n±0.094\"", (0.407, 0.094, 0.094)),
    ("0.41\"\n−0.12\"/+0.14\"", (0.41, 0.12, 0.14)),
    ("-3.2\", U = ±0.81\"", (-3.2, 0.81, 0.81)),
])
def test_a_figure_with_its_u_is_three_numbers(text, numbers):
    assert split_figures(text) == (numbers, "\"", "U−/U+")


def test_xlsx_holds_value_and_u_as_numbers_and_the_decision_figures():
    kind, result = _analysed("theodolite")
    doc = kind.certificate_document(result, META)
    table = Table("Statistics", ("Quantity", "Value", ""),
                  [("A", "25.01\", U = ±1.35\"", ""), ("Decided", "0.407\"\n±0.094\"", ""),
                   ("B", "0.41\"\n−0.12\"/+0.14\"", "")])
    book = load_workbook(io.BytesIO(results_xlsx_bytes(replace(doc, statistics=table))))
    rows = [list(r) for r in book["Statistics"].iter_rows(values_only=True)]
    assert rows[0][:4] == ["Quantity", "Value (\")", "Value (U−) (\")", "Value (U+) (\")"]
    assert rows[1][1:4] == [25.01, 1.35, 1.35]
    assert rows[2][1:4] == [0.407, 0.094, 0.094]
    assert rows[3][1:4] == [0.41, 0.12, 0.14]
    certificate = {r[0]: r[1] for r in book["Certificate"].iter_rows(values_only=True)}
    c = doc.conformity
    assert certificate["Decided value: interval low (\")"] == pytest.approx(c.interval_low)
    assert certificate["Decided value: interval high (\")"] == pytest.approx(c.interval_high)
    assert certificate["Decided value: coverage probability (%)"] == pytest.approx(95.45, abs=0.01)
    risk = certificate["Probability of a wrong decision (%)"]  # "< 0.01" as the PDF's
    assert risk == "< 0.01" or 0.01 <= risk <= 100
