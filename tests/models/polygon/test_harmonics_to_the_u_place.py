"""Assessment 78 L6: the polygon's 1st and 2nd harmonic amplitudes were printed to 0.001″
("0.362″ / 0.157″") beside the certificate's U = 0.42″: digits the data do not support
(the amplitudes are indicative, no U of their own). They are printed to the decimal of the
certificate's largest U, two significant digits (GUM 7.2.6): "0.36″ / 0.16″"."""

from __future__ import annotations

import re

import numpy as np

from models.uncertainty.rounding import significant_decimals
from tests.models.certificate.test_certificate_statements import _sample
from tests.models.certificate.test_printed_rounding import _bundled


def test_the_harmonics_are_printed_to_the_place_of_the_certificates_u():
    kind, result = _sample("polygon")
    document = kind.certificate_document(result, _bundled("polygon"))
    row = next(r for r in document.statistics.rows if str(r[0]) == "Harmonics 1st / 2nd")
    found = re.fullmatch(r"(\d+)\.(\d+)\" / (\d+)\.(\d+)\"", str(row[1]))
    assert found, row
    u = np.asarray(document.budget.expanded, dtype=float)
    d = significant_decimals(float(np.max(u[np.isfinite(u) & (u > 0)])))
    assert d == 2  # the sample's U, 0.42″
    assert len(found.group(2)) == len(found.group(4)) == d
    h = result.harmonics.amplitude
    assert str(row[1]) == f"{h[1]:.{d}f}\" / {h[2]:.{d}f}\""
    assert str(row[1]) == "0.36\" / 0.16\""  # the assessor's certificate: 0.362″ / 0.157″
