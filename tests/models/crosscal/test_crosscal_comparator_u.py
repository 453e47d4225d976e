"""The comparator's stated U in the cross-calibration's results (#39, #43): the budget takes
each comparator's calibration as an input of every reading, through the design. The
values from face 1 (and the encoder's from step 0) carry it too, and the JSON's U is the
certificate's whenever the details list a comparator.

The check is physical: the independent bench (tests/crosscal_simulator.py) reads each face
with a comparator whose indication is off by an independent error of the stated standard
uncertainty at each reading; the spread of the results over many such benches is what the
U says."""

from __future__ import annotations

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.crosscal.report import comparator_u_arcsec, crosscal_budget
from models.crosscal.solve import solve_crosscal
from models.readings.sheet import ReadingsSheet
from models.registry import KINDS
from tests.crosscal_simulator import Bench

KIND = KINDS["crosscal"]
HARMONICS = {1: (2.0, 0.3), 2: (1.0, 1.1), 3: (0.5, 2.0)}
U95 = 0.1  # the comparator's stated U (k = 2) per reading, ″


def _details(u95: float | None = U95) -> CertificateMetadata:
    standards = [] if u95 is None else [{
        "description": "Photoelectric autocollimator", "serial": "AC-1",
        "certificate_no": "NIM-1", "uncertainty_arcsec": u95, "basis": "U95"}]
    return CertificateMetadata.from_dict({"certificate_number": "X", "lab_name": "L",
                                          "standards": standards})


def _rows(n: int):
    dev = np.random.default_rng(905).normal(0.0, 1.5, n)
    return Bench(n, HARMONICS, dev, rng=np.random.default_rng(5), noise_arcsec=0.0).rows(range(n))


def _analyze(rows):
    """No scale error stated; no vertical readings, so the tilt bound is the default's (a
    bound of 0 where the tilt is not identified is refused): the comparator's share is
    taken as a difference of squares, which that row, the same on both sides, leaves out."""
    text = [[str(j), str(i), f"{a:.9f}", f"{x:.6f}", ""] for j, i, a, x in rows]
    parsed = ReadingsSheet(KIND.columns, text).parse()
    return KIND.analyze(parsed, {**KIND.default_settings, "ac_scale_pct": 0.0})


def test_a_comparators_reading_errors_spread_the_results_as_its_stated_u_says():
    n, trials = 8, 400
    rows = _rows(n)
    j, i, a, c = (np.array(col) for col in list(zip(*rows, strict=True))[:4])
    rng = np.random.default_rng(11)
    u_reading = U95 / 2.0
    from_face1, about_mean = [], []
    for _ in range(trials):  # the comparator off by an independent error at each reading
        s = solve_crosscal(j, i, a, c + rng.normal(0.0, u_reading, c.size), faces=n)
        d = s.polygon_deviation_arcsec
        from_face1.append(d - d[0])
        about_mean.append(d)
    result = _analyze(rows)
    details = _details()
    spread1 = np.std(np.array(from_face1), axis=0, ddof=1)
    spread = np.std(np.array(about_mean), axis=0, ddof=1)
    # the certificate's U from face 1 less the bench's own: the comparator's share
    k = result.solution.coverage_factor
    share1 = np.sqrt(result.polygon_u_from_face1_arcsec(details) ** 2
                     - result.polygon_u_from_face1_arcsec() ** 2) / k
    assert share1[0] == 0.0 and spread1[0] == 0.0
    np.testing.assert_allclose(share1[1:], spread1[1:], rtol=0.15)  # 400 trials: ±7 % (2σ)
    # about the mean: the budget's comparator row is the same spread
    row = next(c for c in crosscal_budget(result, details).components
               if "Comparator" in str(c.name))
    np.testing.assert_allclose(np.asarray(row.value) / row.divisor, spread, rtol=0.15)
    n2 = 2 * n
    np.testing.assert_allclose(comparator_u_arcsec(result, details)[n:n2], spread, rtol=0.15)


def test_without_a_comparator_listed_nothing_is_added():
    result = _analyze(_rows(8))
    np.testing.assert_array_equal(result.polygon_u_from_face1_arcsec(_details(None)),
                                  result.polygon_u_from_face1_arcsec())
    np.testing.assert_array_equal(result.encoder_u_from_step0_arcsec(_details(None)),
                                  result.encoder_u_from_step0_arcsec())


@pytest.mark.parametrize("u95", [None, U95])
def test_the_jsons_u_is_the_certificates_with_or_without_a_comparator(u95):
    from models.certificate.uncertainty_json import workbench_uncertainty_json

    result = _analyze(_rows(8))
    details = _details(u95)
    data = workbench_uncertainty_json(KIND, result, details)
    document = KIND.certificate(result, details)
    columns = dict(document.point_columns)
    np.testing.assert_allclose(data["expanded_uncertainty_polygon_deviation_arcsec"],
                               columns["expanded_uncertainty_arcsec"], rtol=1e-12)
    np.testing.assert_allclose(data["expanded_uncertainty_polygon_deviation_from_face1_arcsec"],
                               columns["expanded_uncertainty_from_face1_arcsec"], rtol=1e-12)
    encoder = KIND.certificate(__import__("dataclasses").replace(result, certificate_of="encoder"),
                               details)
    np.testing.assert_allclose(data["expanded_uncertainty_encoder_error_arcsec"],
                               dict(encoder.point_columns)["expanded_uncertainty_arcsec"],
                               rtol=1e-12)
    if u95 is not None:  # the comparator is in: more than the bench's own
        assert np.all(np.asarray(data["expanded_uncertainty_polygon_deviation_arcsec"])
                      > np.asarray(result.expanded_u_arcsec[1]) * 1.1)


def test_the_u_arrays_of_before_39_are_the_certificates_with_the_details():
    """encoder_error_U_arcsec, polygon_deviation_U_arcsec (and from face 1) keep their
    meaning — the U of those values — and with the details given they are the certificate's,
    equal to the expanded_uncertainty_* beside them."""
    from models.certificate.uncertainty_json import certified_json, workbench_uncertainty_json

    result = _analyze(_rows(8))
    details = _details()
    data = {**KIND.to_json(result), **workbench_uncertainty_json(KIND, result, details),
            **certified_json(KIND, result, details)}
    for old, new in (("encoder_error_U_arcsec", "expanded_uncertainty_encoder_error_arcsec"),
                     ("polygon_deviation_U_arcsec", "expanded_uncertainty_polygon_deviation_arcsec"),
                     ("polygon_deviation_U_from_face1_arcsec",
                      "expanded_uncertainty_polygon_deviation_from_face1_arcsec")):
        np.testing.assert_allclose(data[old], data[new], rtol=1e-12)
    assert np.max(data["polygon_deviation_U_arcsec"]) > 1.1 * np.max(KIND.to_json(result)[
        "polygon_deviation_U_arcsec"])


def test_with_no_comparator_listed_u_is_incomplete_and_no_conformity_is_stated():
    """Assessment 73 M2: the comparator's calibration is an input of every reading whether or
    not a standard is listed. With ``"standards": []`` 0.8.21 dropped its budget row (the
    larger part of U here), stated a pass on the smaller U and titled the document a
    calibration certificate. Now the input is named as not stated (JSON and certificate), no
    statement of conformity is made (verdict null, with the reason), and the document is a
    test report. The simulated bench's comparator spreads the results as the row says (the
    test above), so the row left out is a real part of U: here it exceeds the rest."""
    from models.certificate.uncertainty_json import workbench_uncertainty_json

    result = _analyze(_rows(8))
    stated = {"tolerance": 10.0, "tolerance_unit": "arcsec", "decision_rule": "simple"}
    with_ac = CertificateMetadata.from_dict({**_details().to_dict(), **stated})
    without = CertificateMetadata.from_dict({**_details(None).to_dict(), **stated})
    row = next(c for c in crosscal_budget(result, with_ac).components
               if "Comparator" in str(c.name))
    assert np.max(np.asarray(row.value) / row.divisor) > np.max(result.solution
                                                               .polygon_deviation_u_arcsec)
    listed = KIND.certificate_document(result, with_ac)
    assert listed.conformity.verdict == "pass" and not listed.is_test_report
    document = KIND.certificate_document(result, without)
    assert document.conformity.verdict == "not assessed"
    assert "Comparator calibration" in str(document.conformity.reason)
    assert document.is_test_report and any("Comparator calibration" in str(n)
                                           for n in document.not_in_u)
    data = workbench_uncertainty_json(KIND, result, without)
    assert data["decided_quantity"]["verdict"] is None
    assert "Comparator calibration" in data["decided_quantity"]["reason"]
    assert any("Comparator calibration" in n for n in data["uncertainty_inputs_not_stated"])
    assert workbench_uncertainty_json(KIND, result, with_ac)["uncertainty_inputs_not_stated"] == []


def test_the_comparator_is_never_said_to_be_outside_the_uncertainty():
    """Assessment 73 M2: "The autocollimator is a comparator only" beside a budget whose
    largest row is its calibration read as a contradiction; the statement says its
    calibration is an input of the uncertainty, with a comparator listed or not."""
    result = _analyze(_rows(8))
    for details in (_details(), _details(None)):
        said = " ".join(str(s) for s in KIND.certificate_document(result, details).statements)
        assert "comparator only" not in said
        assert "its calibration (the uncertainty its certificate states) is an input" in said
