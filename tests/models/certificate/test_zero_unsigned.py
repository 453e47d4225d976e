"""One sign convention for a zero in every column of a results table: a figure that rounds to
zero is printed without a sign, "0.0", neither "-0.0" (which the PDF already printed "0.0")
nor "+0.0" (assessment 76 L6: "0.0" at θ = −2° but "+0.0" at the reference point)."""

from __future__ import annotations

import re

import pytest

from tests.models.certificate.test_certificate_statements import _sample
from tests.models.certificate.test_certificate_uncertainty import META

pytestmark = pytest.mark.slow

SIGNED_ZERO = re.compile(r"^[-+−]0(\.0+)?$")


def test_the_theodolite_results_table_prints_every_zero_unsigned():
    kind, result = _sample("theodolite")
    table = kind.certificate_document(result, META).results
    col = {h: i for i, h in enumerate(table.header)}
    cells = [str(cell) for row in table.rows for cell in row]
    assert not [c for c in cells if SIGNED_ZERO.match(c)]
    reference = table.rows[result.reference_index]
    # the reference point: raw, correction and corrected error all zero by definition
    assert [reference[col[name]] for name in ("Raw error (\")", "Correction (\")",
                                              "Corrected error (\")")] == ["0.0"] * 3
    # θ = −2°: a corrected error of −0.027″, printed as the reference point's zero is
    minus_two = next(row for row in table.rows if row[0] == "-2.0000")
    assert result.corrected_error_arcsec[list(result.theta_deg).index(-2.0)] < 0
    assert minus_two[col["Corrected error (\")"]] == "0.0"
