"""A particle swarm's fit makes no certificate, no U and no decision (assessment 76 H1).

The bundled sample fitted with ``--method pso`` (AB-2026-0023): the Method said "fitted by
linear least squares", R² printed "nan", each harmonic's phase "amplitude not significant (A1
≤ U)" beside A1 = 3.745 V with no U at all, and the decided half range 0.420″ (0.406 …
0.434″, an interval of the least squares' covariance) decided "pass" against ±0.45″ where
the least squares of the same readings, 600 times better on the swarm's own cost, decided
"fail". Decided: the swarm is the paper's method kept for comparison; it has no covariance,
so no certificate (PDF, DCC, results) is made of it, refused before the details with the
reason and how far its residual is from the least squares'; its JSON states no U, no
interval and no verdict, with that reason; its R² is the fit's own; its Method says it.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata, MetadataError
from models.certificate.uncertainty_json import workbench_uncertainty_json
from models.fringe.analysis import FRINGE
from models.fringe.report import _parameter_rows, fringe_certificate, method_text
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table

SETTINGS = {"lines_per_rev": 16384, "phase_reference_u": 0.05, "adc_lsb_mv": 0.1,
            "adc_offset_u_mv": 0.2, "adc_gain_u_pct": 0.05, "adc_linearity_mv": 0.3}
# the assessor's T = ±0.45": least squares fails, the swarm passed
# (the assessor's meta/f_t045.json: the phase reference listed with u 0.001" per sample)
DETAILS = {"tolerance": 0.45, "tolerance_unit": "arcsec", "decision_rule": "guarded",
           "standards": [{"description": "Phase reference (sampling clock)",
                          "certificate_no": "NIM-2026-0500", "uncertainty": 0.001,
                          "uncertainty_unit": "arcsec", "basis": "u", "role": "reference"},
                         {"description": "Data acquisition (16-bit ADC)",
                          "certificate_no": "CAL-2026-33", "role": "adc"}]}
METADATA = CertificateMetadata.from_dict(DETAILS)


def _analysed(samples_dir, method: str):
    rows = map_columns(read_table(samples_dir / FRINGE.sample_file), FRINGE.columns)
    return FRINGE.analyze(ReadingsSheet(FRINGE.columns, rows).parse(),
                          {**SETTINGS, "method": method})


@pytest.fixture(scope="module")
def pso(request):
    from tests.conftest import SAMPLES

    return _analysed(SAMPLES, "pso")


def test_the_swarms_r_squared_is_its_fits_own_not_nan(pso):
    for fit, u in ((pso.sin_fit, pso.u_sin), (pso.cos_fit, pso.u_cos)):
        resid = u - (fit.offset + sum(fit.amplitude[k] * np.sin(k * pso.theta_rad + fit.phase[k])
                                      for k in fit.orders))
        expected = 1.0 - np.sum(resid**2) / np.sum((u - u.mean()) ** 2)
        assert fit.r_squared == pytest.approx(expected, rel=1e-12)
        assert 0.99 < fit.r_squared < 1.0
    assert "nan" not in FRINGE.summary(pso).lower()


def test_the_method_says_the_swarm_identified_the_parameters(pso, samples_dir):
    said = str(method_text(pso))
    assert "particle swarm" in said and "linear least squares, which" in said
    assert "fitted by linear least squares" not in said
    lsq = str(method_text(_analysed(samples_dir, "lsq")))
    assert "fitted by linear least squares" in lsq


def test_no_certificate_of_a_swarms_fit_says_how_far_it_is_from_least_squares(pso):
    refusal = str(FRINGE.certificate_refusal(pso))
    # the whole record's residual RMS: the swarm's 64 mV and 6.58 mV, least squares' 1.98
    assert "64 mV (sin) and 6.58 mV (cos), is 23 times" in refusal
    assert "(1.98 and 1.98 mV)" in refusal
    with pytest.raises(MetadataError, match="identified by particle swarm"):
        fringe_certificate(pso, METADATA)


def test_least_squares_is_not_refused(samples_dir):
    lsq = _analysed(samples_dir, "lsq")
    assert FRINGE.certificate_refusal(lsq) == ""
    assert fringe_certificate(lsq, METADATA).conformity.verdict == "fail"


def test_the_swarms_json_states_no_u_no_interval_and_no_verdict(pso):
    out = workbench_uncertainty_json(FRINGE, pso, METADATA, {**SETTINGS, "method": "pso"})
    decided = out["decided_quantity"]
    assert decided["verdict"] is None and decided.get("probability_conforming") is None
    assert decided["interval_low"] is None and decided["interval_high"] is None
    assert decided["coverage_probability"] is None
    assert "identified by particle swarm" in decided["reason"]
    assert decided["value"] == pytest.approx(0.42016, abs=1e-5)  # as measured, said so
    assert "identified by particle swarm" in out["uncertainty_withheld"]
    params = FRINGE.certified_json(pso, METADATA)
    assert params["sin_params"]["expanded_uncertainty_A0"] is None  # ADC's share alone, was
    assert "particle swarm" in params["parameters_uncertainty_withheld"]


def test_no_significance_is_said_of_an_amplitude_without_a_u(samples_dir):
    lsq = _analysed(samples_dir, "lsq")
    lsq.sin_fit.u_amplitude[3] = math.nan  # an amplitude whose U is not determined
    lsq.__dict__.pop("_parameter_uncertainty", None)
    rows = {str(name): (value, u) for name, value, u in _parameter_rows(lsq)}
    value, u = rows["sin: c3"]
    assert u == "—" and "rad" in value
    assert not any("not significant" in str(cell) for row in rows.values() for cell in row
                   if "A3" in str(cell))


def test_the_command_line_writes_no_certificate_of_a_swarms_fit(tmp_path, samples_dir,
                                                               capsys):
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(DETAILS))
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "c.xlsx"
    code = main(["analyze", "fringe", str(samples_dir / FRINGE.sample_file), "--metadata",
                 str(meta), "--certificate", str(pdf), "--results", str(xlsx),
                 "--lines-per-rev", "16384", "--method", "pso"])
    assert code == 2
    assert not pdf.exists() and not xlsx.exists()
    assert "identified by particle swarm" in capsys.readouterr().err


def test_the_window_says_why_before_the_details_dialog(pso):
    from unittest import mock

    from app.certificate_presenter import CertificatePresenter, CertificateView

    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, mock.MagicMock(), dict, lambda: None)
    assert not presenter.export_certificate(FRINGE, pso, {**SETTINGS, "method": "pso"},
                                            "fringe_sample.csv")
    view.edit_certificate_details.assert_not_called()
    view.choose_save_path.assert_not_called()
    title, text = view.tell.call_args.args
    assert text.startswith("No certificate: the signals were identified by particle swarm")
