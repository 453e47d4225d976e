"""The cross-calibration certificate of a polygon states the sign it tabulates (review 61, F3).

Its results are the face deviations d_i = the face's angle − its nominal. A polygon is a
material measure: it indicates its nominal angle (VIM 3.6), so d_i is actual −
indicated, the negative of an error of indication. The certificate printed the other
workbenches' "error = indicated − reference" above them (PDF, XLSX, DCC) and the JSON named
only that convention; the numbers are right (they feed the polygon workbench as dev_i in
b_i = (i−1)·360°/n + dev_i, SPEC.md §2) and stay: the exception is stated, as positioning
states its own.
"""

from __future__ import annotations

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.messages import translator
from models.readings.sheet import ReadingsSheet
from models.registry import KINDS
from tests.crosscal_simulator import Bench

KIND = KINDS["crosscal"]


def _analyze(item: str):
    n = 12
    dev = np.zeros(n)
    dev[1], dev[7] = 1.5, -0.9  # face 2 stands 1.5" beyond its nominal, face 8 0.9" short
    rows = Bench(n, {1: (2.0, 0.3), 3: (0.5, 2.0)}, dev,
                 rng=np.random.default_rng(3)).rows(range(n))
    text = [[str(j), str(i), f"{a:.9f}", f"{x:.6f}", ""] for j, i, a, x, *_ in rows]
    parsed = ReadingsSheet(KIND.columns, text).parse()
    return KIND.analyze(parsed, {**KIND.default_settings, "certificate_of": item}), dev


@pytest.mark.slow
def test_the_polygons_certificate_states_actual_minus_nominal_and_tabulates_it():
    result, dev = _analyze("polygon")
    document = KIND.certificate(result, CertificateMetadata(tolerance=2.0))
    # the figures: the true deviations about their mean, signed actual − nominal
    expected = dev - dev.mean()
    d = dict(document.point_columns)["deviation_arcsec"]
    np.testing.assert_allclose(d, expected, atol=0.01)
    assert d[1] == pytest.approx(1.5 - dev.mean(), abs=0.01) and d[1] > 0
    # the convention stated over them says so, and is not the error of indication's
    said = str(document.sign_convention)
    assert "actual − nominal" in said
    assert "the negative of an error of indication" in said
    assert "error = indicated − reference" not in said
    assert translator("zh_CN")(said) != said, "the convention has its Chinese"
    # the JSON names the polygon's sign beside the encoder's
    data = KIND.to_json(result)
    assert data["polygon_deviation_sign_convention"] == "actual_minus_nominal"
    assert data["sign_convention"] == "indicated_minus_reference"  # the encoder's error


@pytest.mark.slow
def test_the_encoders_certificate_keeps_the_error_of_indication():
    result, _ = _analyze("encoder")
    document = KIND.certificate(result, CertificateMetadata(tolerance=5.0))
    assert str(document.sign_convention) == ("error = indicated − reference (VIM); "
                                             "correction = −error")
