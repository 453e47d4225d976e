"""The fringe certificate's parameters table and per-sample columns say what each figure is
(review 61, F9 and F10): the fit's R² and residual RMS are not printed under the U header,
and the results export gives each error its own U."""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

import numpy as np
import pytest
from openpyxl import load_workbook
from scipy import stats

from app.writers.results_export import results_xlsx_bytes
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

SAMPLE = Path(__file__).resolve().parents[3] / "resources" / "samples" / "fringe_sample.csv"
META = CertificateMetadata.from_dict({
    "certificate_number": "AB-1", "lab_name": "Lab", "tolerance_arcsec": 0.5,
    "calibration_date": "2026-11-20"})


@pytest.fixture(scope="module")
def analysed():
    kind = KINDS["fringe"]
    rows = map_columns(read_table(SAMPLE), kind.columns)
    settings = kind.settings_with_defaults({})
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    return kind, result, kind.certificate_document(result, META, SAMPLE.name, settings)


def _signals():
    with open(SAMPLE, encoding="utf-8") as handle:
        rows = list(csv.DictReader(handle))
    return {key: np.array([float(r[key]) for r in rows]) for key in ("u_sin", "u_cos",
                                                                       "theta_deg")}


def test_r_squared_and_residual_rms_are_values_not_under_the_u_header(analysed):
    """F9: 'sin: R², residual RMS | 0.99999945 | 1.98 mV' put the RMS in the column headed
    'U (k = 2.00, ν = 505)', read as the U of R². Each is now a value of its own row, its U
    cell empty; both recomputed here from the sample's signals and the fitted model."""
    _kind, result, document = analysed
    header = document.parameters.header
    assert str(header[2]).startswith("U (k = ")
    rows = {str(r[0]): r for r in document.parameters.rows}
    signals = _signals()
    theta = np.radians(signals["theta_deg"])
    for channel, fit, y in (("sin", result.sin_fit, signals["u_sin"]),
                            ("cos", result.cos_fit, signals["u_cos"])):
        model = fit.offset + sum(fit.amplitude[k] * np.sin(k * theta + fit.phase[k])
                                 for k in fit.orders)
        residual = y - model
        r2 = 1.0 - float(residual @ residual) / float(((y - y.mean()) ** 2).sum())
        rms_mv = 1e3 * math.sqrt(float(np.mean(residual ** 2)))
        r2_row, rms_row = rows[f"{channel}: R² of the fit"], rows[f"{channel}: residual RMS of the fit"]
        assert r2_row[1] == f"{r2:.8f}" and r2_row[2] == ""
        assert rms_row[1] == f"{rms_mv:.3g} mV" and rms_row[2] == ""
        assert f"{channel}: R², residual RMS" not in rows
    for row in document.parameters.rows:  # nothing in the U column is a figure without U
        assert "R²" not in str(row[0]) or row[2] == ""
