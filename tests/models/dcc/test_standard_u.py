"""A standard's U from another maker's DCC (written by hand per PTB's schema,
tests/dcc_documents.py): the U of the quantity the standard provides — its errors marked by
PTB's refType, else named as errors, else its measured values — never a fitted set-up
parameter's, a standard deviation's or a reference value's; said which, and what was not
used; a DCC that marks nothing keeps the largest of all and says so. Each expected U is the
figure written into the file, converted here."""

from __future__ import annotations

import math

import pytest

from models.dcc.reader import DccError, read_standard_dcc
from tests import dcc_documents as t

SCHEMA = t.SHARED_DCC
URAD = 0.648 / math.pi  # arcseconds per microradian, written out


def _result(name: str, *quantities):
    """A filler of one dcc:result named ``name`` holding ``quantities``: (name, values,
    unit, U, k, refType) each."""
    def fill(results):
        result = t.sub(results, t.d("result"))
        t.text(result, t.d("name"), name)
        data = t.sub(result, t.d("data"))
        for q_name, values, unit, u, k, reftype in quantities:
            t.real_list(data, values, unit, u=u, k=k, reftype=reftype, name=q_name)
    return fill


def _results(*fillers):
    def fill(results):
        for f in fillers:
            f(results)
    return fill


def _read(tmp_path, name: str, *fillers):
    data = t.document("LAB-2026-7", results=_results(*fillers),
                      statements=t.validity(date="2027-06-30"))
    t.assert_valid(data)
    path = tmp_path / f"{name}.xml"
    path.write_bytes(data)
    return read_standard_dcc(path, SCHEMA)


#: an autocollimator calibrated by another laboratory: errors of indication with U 0.12"
#: (k = 2) at most, beside an alignment tilt identified with U 40 µrad (8.25")
ERRORS = ("Error of indication", [0.05, -0.08, 0.11], r"\arcsecond", [0.10, 0.12, 0.11], 2.0,
          "basic_measurementError")
TILT = ("Alignment tilt", [12.0], r"\micro\radian", [40.0], 2.0, "")


def test_the_errors_marked_by_their_reftype_not_a_set_up_tilt(tmp_path):
    got = _read(tmp_path, "marked", _result("Calibration results", ERRORS),
                _result("Alignment of the set-up", TILT))
    assert got.uncertainty == pytest.approx(0.12, rel=1e-12) and got.coverage_factor == 2.0
    assert got.unit == "arcsec" and got.as_standard()["uncertainty"] == pytest.approx(0.12)
    assert got.notes[-1].endswith(
        "U is that of “Calibration results › Error of indication”, the largest of its "
        "results that are measurement errors or deviations; not used: Alignment of the set-up")


def test_errors_named_as_such_when_nothing_carries_a_reftype(tmp_path):
    """No refType anywhere: the names tell (English, German, Chinese); a standard deviation
    is a statistic of the readings, not an error."""
    for i, (error_name, other_name) in enumerate((("Error of indication", "Axis tilt"),
                                                  ("Messabweichung", "Standardabweichung"),
                                                  ("示值误差", "标准偏差"))):
        got = _read(tmp_path, f"named{i}",
                    _result("Results", (error_name, [0.1, -0.1], r"\arcsecond", [0.2, 0.25],
                                        2.0, ""),
                            (other_name, [0.3], r"\arcsecond", [3.0], 2.0, "")))
        assert got.uncertainty == pytest.approx(0.25, rel=1e-12), error_name
        assert f"“Results › {error_name}”" in got.notes[-1]
        assert f"not used: Results › {other_name}" in got.notes[-1]


def test_measured_values_when_no_error_and_never_a_reference_value(tmp_path):
    """An angle gauge's measured angle (basic_measuredValue, U 0.3" at k = 2.5): its U/k;
    the calibrating laboratory's reference value with a larger U is not the gauge's."""
    got = _read(tmp_path, "measured", _result(
        "Angle gauge", ("Measured angle", [10.0, 30.0], r"\degree",
                        [0.3 / 3600.0, 0.2 / 3600.0], 2.5, "basic_measuredValue"),
        ("Reference angle", [10.0, 30.0], r"\degree", [1.0 / 3600.0] * 2, 2.0,
         "basic_referenceValue")))
    assert got.uncertainty == pytest.approx(0.3, rel=1e-9) and got.coverage_factor == 2.5
    assert got.as_standard() == {"certificate_no": "LAB-2026-7", "due_date": "2027-06-30",
                                 "uncertainty": pytest.approx(0.12, rel=1e-9), "basis": "u",
                                 "uncertainty_unit": "arcsec", "applies_to": "reading"}
    assert "results that are measured values; not used: Angle gauge › Reference angle" in (
        got.notes[-1])


def test_nothing_told_apart_keeps_the_largest_of_all_and_says_so(tmp_path):
    got = _read(tmp_path, "unmarked", _result("Table 1", ("A", [0.1], r"\arcsecond", [0.2],
                                                          2.0, "")),
                _result("Table 2", ("B", [5.0], r"\micro\radian", [4.0], 2.0, "")))
    assert got.uncertainty == pytest.approx(4.0 * URAD, rel=1e-12)
    assert "none of its results is marked as a measurement error, a deviation or a measured " \
           "value" in got.notes[-1]
    assert "that of “Table 2 › B”; check that it is the uncertainty of what the standard " \
           "provides" in got.notes[-1]


def test_set_up_parameters_only_leave_the_u_empty_and_say_why(tmp_path):
    got = _read(tmp_path, "setup", _result(
        "Set-up parameters identified", ("Axis tilt ψ", [0.01], r"\degree", [0.00175], 2.07,
                                         "anglebench_setupParameter")))
    # emptied, never left to the certificate the row held before
    assert got.uncertainty is None and got.as_standard()["uncertainty"] == ""
    assert got.notes[-1].endswith(
        "none of its results with an uncertainty is a measurement error, a deviation or a "
        "measured value of the standard (only Set-up parameters identified): the standard's U "
        "is left empty")


def test_errors_in_volts_are_refused_not_replaced_by_a_tilts_angle(tmp_path):
    with pytest.raises(DccError, match=r"in \\volt: neither an angle nor a length"):
        _read(tmp_path, "volts",
              _result("Results", ("Error", [0.001], r"\volt", [0.0002], 2.0,
                                  "basic_measurementError")),
              _result("Alignment of the set-up", TILT))


def test_a_polygon_in_anglebench_vocabulary_gives_its_largest_face_u(tmp_path):
    """Another laboratory's polygon DCC in the face-deviation vocabulary only: the largest
    face U, as the polygon reader's (tests/app/test_standard_dcc_u: AngleBench's own)."""
    from models.dcc.reader import polygon_standard, read_polygon_dcc

    data = t.document("PTB-2026-0042", results=t.polygon_results(
        t.polygon_errors(12), u_arcsec=0.15, k=2.0), statements=t.validity(date="2027-06-30"))
    path = tmp_path / "polygon.xml"
    path.write_bytes(data)
    got = read_standard_dcc(path, SCHEMA)
    assert got.as_standard()["uncertainty"] == polygon_standard(
        read_polygon_dcc(path, SCHEMA))["uncertainty"] == pytest.approx(0.15, rel=1e-12)
    assert "results that are a polygon's face deviations" in got.notes[-1]
