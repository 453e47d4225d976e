"""The cross-calibration's JSON states the encoder's errors from step 0 (E_k − E_0, the
certificate's "From step 0" column) with their U and k beside them, as #39's rule has it for
every reported error array (the polygon's from face 1 had theirs; the encoder's had none):
``encoder_error_from_step0_arcsec``, ``expanded_uncertainty_encoder_error_from_step0_arcsec``
and ``coverage_factor_encoder_error_from_step0_arcsec``, the figures the certificate prints
with the same details (the comparators' stated U in). The keys there before keep theirs."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import numpy as np

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
READINGS = SAMPLES / "crosscal_sample.csv"
DETAILS = SAMPLES / "certificate_crosscal_encoder.json"
KIND = KINDS["crosscal"]


def _json() -> dict:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(["analyze", "crosscal", str(READINGS), "--metadata", str(DETAILS),
                     "--json"]) == 0, told.getvalue()
    text = said.getvalue()
    return json.loads(text[text.index("{"):])


def test_encoder_errors_from_step0_with_their_u_as_the_certificate_states_them():
    data = _json()
    e = np.asarray(data["encoder_error_arcsec"], dtype=float)
    from_step0 = np.asarray(data["encoder_error_from_step0_arcsec"], dtype=float)
    np.testing.assert_allclose(from_step0, e - e[0], atol=1e-12)
    assert from_step0[0] == 0.0
    u = np.asarray(data["expanded_uncertainty_encoder_error_from_step0_arcsec"], dtype=float)
    k = data["coverage_factor_encoder_error_from_step0_arcsec"]
    assert u.shape == e.shape and u[0] == 0.0 and np.all(u[1:] > 0)
    assert k == data["coverage_factor"]
    # the certificate's "U from step 0" column with the same details
    rows = map_columns(read_table(READINGS), KIND.columns)
    settings = {**KIND.default_settings, "certificate_of": "encoder"}
    result = KIND.analyze(ReadingsSheet(KIND.columns, rows).parse(), settings)
    meta = CertificateMetadata.from_dict(json.loads(DETAILS.read_text(encoding="utf-8")))
    assert meta.standards  # the comparators' stated U enter it
    document = KIND.certificate(result, meta, settings=settings)
    columns = dict(document.point_columns)
    np.testing.assert_allclose(u, columns["expanded_uncertainty_from_step0_arcsec"], rtol=1e-12)
    np.testing.assert_allclose(from_step0, columns["error_from_step0_arcsec"], atol=1e-12)
    # the comparators' U is in: more than the readings' own from step 0
    assert np.all(u[1:] > np.asarray(result.encoder_u_from_step0_arcsec(), dtype=float)[1:])
    # the keys there before keep their meaning: about the mean, the polygon's from face 1
    assert data["encoder_error_reference"] == "mean"
    d = np.asarray(data["polygon_deviation_arcsec"], dtype=float)
    np.testing.assert_allclose(data["polygon_deviation_from_face1_arcsec"], d - d[0], atol=1e-12)
    assert len(data["expanded_uncertainty_encoder_error_arcsec"]) == e.size
