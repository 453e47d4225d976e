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


SHEET_STEP = 0.5e-6 + 1e-12  # the sheet's rounding of a U printed to 0.001"


def _column(book, name):
    rows = list(book["Results"].iter_rows(values_only=True))
    at = list(rows[0]).index(name)
    return np.array([r[at] for r in rows[1:]], dtype=float)


def test_the_results_export_gives_each_error_its_own_u(analysed):
    """F10: the XLSX had one column 'expanded_uncertainty_arcsec' after the compensated
    error, holding the as-found (raw) error's U. Each error now has its U, named for it; the
    compensated error's is recombined here from its budget's inputs (GUM 5.1.2, ν_eff by
    Welch–Satterthwaite truncated, Student's t) and differs from the raw one's (sample 1:
    0.0135623" against 0.0134714", the JSON's figures). The sheet writes them to its
    resolution, three decimals beyond the printed 0.013" (models/certificate/
    export_resolution.py): to 0.5e-6"."""
    from models.fringe.report import fringe_budget

    kind, result, document = analysed
    book = load_workbook(io.BytesIO(results_xlsx_bytes(document)))
    header = list(next(book["Results"].iter_rows(values_only=True)))
    assert "expanded_uncertainty_arcsec" not in header
    assert header[-2:] == ["expanded_uncertainty_raw_error_arcsec",
                           "expanded_uncertainty_compensated_error_arcsec"]
    raw_u = _column(book, "expanded_uncertainty_raw_error_arcsec")
    comp_u = _column(book, "expanded_uncertainty_compensated_error_arcsec")
    for budget, shown in ((fringe_budget(result, META, as_found=True), raw_u),
                          (fringe_budget(result, META), comp_u)):
        cu = [np.broadcast_to(np.asarray(c.value, float) / c.divisor
                              * np.abs(np.asarray(c.sensitivity, float)), shown.shape)
              for c in budget.components]
        u_c = np.sqrt(sum(x ** 2 for x in cu))
        nu = u_c ** 4 / sum(x ** 4 / c.dof for x, c in zip(cu, budget.components, strict=True))
        # (ν = 505 − 6e-14 for one input of 505 degrees: an integer but for rounding)
        k = stats.t.ppf(0.5 * (1 + META.coverage_probability), np.floor(nu + 1e-9))
        assert shown == pytest.approx(k * u_c, abs=SHEET_STEP)
    assert raw_u[0] == pytest.approx(0.0134714, abs=SHEET_STEP)
    assert comp_u[0] == pytest.approx(0.0135623, abs=SHEET_STEP)
    assert np.all(comp_u > raw_u)  # the fitted model's input is added
    # the same figures as the budgets the JSON's and the DCC's arrays come from
    budgets = kind.uncertainty_budgets(result, META)
    assert raw_u == pytest.approx(budgets["raw_error_arcsec"].expanded, abs=SHEET_STEP)
    assert comp_u == pytest.approx(budgets["compensated_error_arcsec"].expanded, abs=SHEET_STEP)


def test_as_left_the_raw_errors_u_is_still_its_own(analysed):
    """As left (the table loaded), the certificate's U column is the compensated error's;
    the single exported column then held that U and the DCC paired it with the raw error.
    Each error keeps its own U, as the budgets give them."""
    import dataclasses

    from models.fringe.report import fringe_budget

    kind, result, _document = analysed
    meta = dataclasses.replace(META, as_left_table_sha256=result.table.sha256)
    columns = dict(kind.certificate_document(result, meta, SAMPLE.name).point_columns)
    assert columns["expanded_uncertainty_raw_error_arcsec"] == pytest.approx(
        fringe_budget(result, meta, as_found=True).expanded, rel=1e-12)
    assert columns["expanded_uncertainty_compensated_error_arcsec"] == pytest.approx(
        fringe_budget(result, meta).expanded, rel=1e-12)
