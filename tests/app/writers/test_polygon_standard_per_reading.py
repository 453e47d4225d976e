"""Leftovers 79, item 5: the polygon budget named a reference standard's figure "U95 per
face or reading" where the standards table beside it says "per reading": one figure, two
words. The figure is the one the standard's certificate states for each reading made with it
(the metadata's ``applies_to`` "reading"; a polygon's reading is a face's deviation, an
autocollimator's its horizontal reading at the face), entering the budget as one error per
face and one at the zero face (models/polygon/report.py): both say "per reading"."""

from __future__ import annotations

import re

from app.writers.certificate_pdf.traceability import _standards_table
from tests.models.certificate.test_certificate_statements import _sample
from tests.models.certificate.test_printed_rounding import _bundled


def _per(text: str) -> str:
    found = re.search(r"\(k = 2\) per (.+?)(?:, certificate|\)|$)", text)
    assert found, text
    return found.group(1)


def test_the_budget_and_the_standards_table_say_per_reading_alike():
    kind, result = _sample("polygon")
    document = kind.certificate_document(result, _bundled("polygon"))
    table = {str(row[0]): _per(str(row[3])) for row in _standards_table(document).rows}
    assert table == {"24-face polygon (deviations from face 1)": "face, stated from face 1",
                     "Photoelectric autocollimator": "reading"}
    budget = {str(c.name): _per(str(c.note)) for c in document.budget.components
              if str(c.name).startswith(tuple(table))}
    # the autocollimator's, its own and at the zero face, as the table says it
    assert budget == {"24-face polygon (deviations from face 1)": "face, stated from face 1",
                      "Photoelectric autocollimator": "reading",
                      "Photoelectric autocollimator, at the zero face": "reading"}, budget
    assert "face or reading" not in " ".join(str(c.note) for c in document.budget.components)
