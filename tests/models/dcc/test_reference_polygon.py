"""An encoder's DCC is no polygon's certificate. The polygon workbench (an encoder tested
against a reference polygon) restates its reference polygon's face deviations, as that
polygon's certificate states them, in the face-deviation form; up to 0.8.11 under the
refType of a *calibrated* polygon (``anglebench_polygonFaceDeviations``), so the polygon
reader, given an encoder's DCC by mistake, took the reference's deviations and U under the
encoder's certificate number and dates — and a later certificate cited the encoder's
certificate as the polygon's calibration. Now the reference has its own refType, and an
encoder's DCC (0.8.11's too, told by that result's name or by the polygon encoder test it
belongs to) is refused, naming the polygon's own certificate as the DCC lists it."""

from __future__ import annotations

from pathlib import Path

import pytest

from models.dcc.reader import DccError, read_polygon_dcc, read_standard_dcc
from tests import dcc_documents as t

SCHEMA = t.SHARED_DCC
#: the polygon workbench's sample DCC as 0.8.11 (git 888d633) wrote it, its PDF left out:
#: certificate SPECIMEN-45AF2B79 of an encoder, its reference polygon NIM-2026-0871
#: (24 faces, U95 0.2" per face from face 1)
WRITTEN_0_8_11 = Path(__file__).resolve().parent / "written_0_8_11" / "polygon.xml"
OLD = "anglebench_polygonFaceDeviations"
NEW = "anglebench_referencePolygonFaceDeviations"
EN_NAME = "Reference polygon face deviations (from face 1, as its certificate states them)"
ZH_NAME = "参考多面棱体各面偏差（相对第 1 面，按其校准证书给出）"


def _write(tmp_path, data: bytes, name: str = "dcc.xml") -> Path:
    path = tmp_path / name
    path.write_bytes(data)
    return path


def _named(result_name: str = "", lang: str = "en", measurement: str = "",
           standards: tuple[tuple[str, str, str], ...] = ()):
    """A root_extra: the polygon result renamed (in ``lang``), the measurement renamed, and
    ``standards`` (name, certificate number, stated U's name) listed before the results."""
    def change(root):
        result = root.find(f".//{t.d('result')}")
        if result_name:
            content = result.find(f"{t.d('name')}/{t.d('content')}")
            content.text, content.attrib["lang"] = result_name, lang
        record = root.find(f".//{t.d('measurementResult')}")
        if measurement:
            record.find(f"{t.d('name')}/{t.d('content')}").text = measurement
        if standards:
            equipments = t.etree.Element(t.d("measuringEquipments"))
            record.find(t.d("results")).addprevious(equipments)
            for name, number, stated in standards:
                equipment = t.sub(equipments, t.d("measuringEquipment"))
                t.text(equipment, t.d("name"), name)
                certificate = t.sub(equipment, t.d("certificate"))
                t.text(certificate, t.d("referral"), "Calibration certificate")
                t.sub(certificate, t.d("referralID"), number)
                t.sub(certificate, t.d("procedure"), "certificate number")
                t.sub(certificate, t.d("value"), number)
                quantities = t.sub(equipment, t.d("measuringEquipmentQuantities"))
                quantity = t.sub(quantities, t.d("measuringEquipmentQuantity"))
                t.text(quantity, t.d("name"), stated)
                real = t.sub(quantity, t.s("real"))
                t.sub(real, t.s("value"), "0")
                t.sub(real, t.s("unit"), r"\arcsecond")
    return change


def test_an_encoders_dcc_written_by_0_8_11_is_refused_naming_the_polygons_certificate():
    """0.8.11 read it as certificate SPECIMEN-45AF2B79 of a 24-face polygon, U 0.2″."""
    with pytest.raises(DccError) as refused:
        read_polygon_dcc(WRITTEN_0_8_11, SCHEMA, faces=24)
    said = str(refused.value)
    assert said == (
        f"{WRITTEN_0_8_11}: certificate SPECIMEN-45AF2B79 calibrates an encoder against a "
        "reference polygon, not the polygon: the face deviations in it are the reference "
        "polygon's, restated from its own certificate NIM-2026-0871 (as this DCC lists the "
        "standard); read that certificate's DCC as the polygon's")
    # the autocollimator listed beside it (NIM-2026-0212) is not named as the polygon's
    assert "NIM-2026-0212" not in said


@pytest.mark.parametrize("reftype, result_name, lang, measurement", [
    (NEW, "", "en", ""),  # written from now on: its own refType
    (OLD, EN_NAME, "en", ""),  # 0.8.11 and before: the name AngleBench gave it
    (OLD, ZH_NAME, "zh", ""),  # … in any language
    (OLD, "", "en", "Polygon encoder test"),  # … or the measurement it belongs to
    (OLD, "", "en", "多面棱体编码器检测"),
], ids=["new refType", "0.8.11 en name", "0.8.11 zh name", "encoder test", "encoder test zh"])
def test_a_reference_polygons_result_is_never_read_as_the_polygon(tmp_path, reftype,
                                                                  result_name, lang,
                                                                  measurement):
    data = t.document("ENC-7", results=t.polygon_results(result_reftype=reftype),
                      root_extra=_named(result_name, lang, measurement))
    t.assert_valid(data)
    with pytest.raises(DccError, match="certificate ENC-7 calibrates an encoder against a "
                                       "reference polygon, not the polygon") as refused:
        read_polygon_dcc(_write(tmp_path, data), SCHEMA)
    assert "restated from its own certificate, which this DCC does not name" in str(
        refused.value)


def test_the_polygons_certificate_is_the_standard_listed_for_it(tmp_path):
    """The standard stated per face from face 1 (the one the reference's U comes from), else
    the one whose name names a polygon; never the autocollimator."""
    autocollimator = ("Autocollimator", "AC-1", "expanded uncertainty U (k = 2) per reading")
    stated = t.document("ENC-8", results=t.polygon_results(result_reftype=NEW),
                        root_extra=_named(standards=(autocollimator, (
                            "P24-3", "POLY-24", "expanded uncertainty U (k = 2) per face, "
                                                "stated from face 1"))))
    named = t.document("ENC-9", results=t.polygon_results(result_reftype=NEW),
                       root_extra=_named(standards=(autocollimator, (
                           "24-face polygon", "POLY-25", "expanded uncertainty U (k = 2) per "
                                                         "reading"))))
    for data, number in ((stated, "POLY-24"), (named, "POLY-25")):
        t.assert_valid(data)
        with pytest.raises(DccError) as refused:
            read_polygon_dcc(_write(tmp_path, data), SCHEMA)
        said = str(refused.value)
        assert f"restated from its own certificate {number} (as this DCC lists" in said
        assert "AC-1" not in said


def test_a_calibrated_polygon_another_lab_calls_a_reference_polygon_is_read(tmp_path):
    """Only AngleBench's own name (or its encoder test) marks the old refType as a
    reference: a polygon calibrated elsewhere and named so by its laboratory is read."""
    errors = t.polygon_errors(12, seed=4)
    data = t.document("PTB-2026-0099", results=t.polygon_results(errors, u_arcsec=0.1),
                      root_extra=_named("Reference polygon PG-12: face deviations"))
    read = read_polygon_dcc(_write(tmp_path, data), SCHEMA)
    assert read.certificate_id == "PTB-2026-0099" and read.faces == 12
    assert read.deviations[5] == pytest.approx(errors[4]) and read.largest_u == 0.1


def _with_measured_values(reftype: str):
    """Beside the reference polygon's face deviations (U 0.2″, k = 2), the item's measured
    values with U 0.05″ (k = 2), marked basic_measuredValue."""
    def fill(results):
        t.polygon_results(u_arcsec=0.2, result_reftype=reftype)(results)
        result = t.sub(results, t.d("result"))
        t.text(result, t.d("name"), "Indicated angles")
        t.real_list(t.sub(result, t.d("data")), [10.0, 20.0, 30.0], r"\arcsecond",
                    u=[0.05] * 3, reftype="basic_measuredValue", name="Angle")
    return fill


@pytest.mark.parametrize("reftype, name", [(NEW, ""), (OLD, EN_NAME)],
                         ids=["new refType", "0.8.11"])
def test_a_standards_u_is_never_the_reference_polygons(tmp_path, reftype, name):
    """Read as a standard's certificate, the reference polygon's face deviations are not the
    standard's (0.8.11 took them before measured values: 0.2″, the reference's U)."""
    data = t.document("ENC-10", results=_with_measured_values(reftype),
                      root_extra=_named(name))
    t.assert_valid(data)
    got = read_standard_dcc(_write(tmp_path, data), SCHEMA)
    assert got.uncertainty == 0.05 and got.coverage_factor == 2.0
    assert "“Indicated angles › Angle”" in got.notes[-1]
    assert f"not used: {name or 'Face deviations'}" in got.notes[-1]


def test_an_encoders_dcc_of_0_8_11_read_as_a_standard_gives_its_corrected_errors_u():
    """The encoder's own errors' U (the corrected error's, U/k the largest), as before; the
    reference polygon's face deviations named as not used."""
    got = read_standard_dcc(WRITTEN_0_8_11, SCHEMA)
    assert got.certificate_id == "SPECIMEN-45AF2B79"
    assert got.uncertainty == 0.415796487499 and got.coverage_factor == 2.00007922229
    assert got.notes[-1].split("not used: ")[1] == (
        "Reference polygon face deviations (from face 1, as its certificate states them), "
        "Set-up parameters identified")
