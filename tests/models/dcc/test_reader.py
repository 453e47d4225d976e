"""DCC in: a polygon's and a standard's digital calibration certificate, written by hand per
PTB's schema (tests/dcc_documents.py), read back as numbers; every refusal; hostile XML."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.dcc.reader import (
    DccError,
    angle_factor,
    embedded_pdfs,
    parse_decimal_list,
    polygon_standard,
    read_polygon_dcc,
    read_standard_dcc,
    replace_face_deviations,
)
from models.dcc.signature import sign
from tests import dcc_documents as t

SCHEMA = t.SHARED_DCC


def write(tmp_path, data: bytes, name: str = "poly.xml"):
    path = tmp_path / name
    path.write_bytes(data)
    return path


@pytest.mark.parametrize("unit", [r"\arcsecond", r"\arcminute", r"\degree", r"\radian",
                                  r"\micro\radian"])
def test_a_polygon_dcc_gives_each_face_and_its_u_in_arcseconds(tmp_path, unit):
    errors = t.polygon_errors(12, seed=3)
    data = t.document("PTB-2026-0042", results=t.polygon_results(errors, unit=unit, u_arcsec=0.12),
                      statements=t.validity(date="2027-03-10"))
    t.assert_valid(data)
    ref = read_polygon_dcc(write(tmp_path, data), SCHEMA, measurement_date="2026-11-20",
                           faces=12)
    assert ref.faces == 12 and ref.certificate_id == "PTB-2026-0042"
    assert ref.calibration_date == "2026-03-10" and ref.due_date == "2027-03-10"
    for face, error in enumerate(errors, 1):
        assert ref.deviations[face] == pytest.approx(error, abs=1e-9)
        assert ref.expanded_uncertainty[face] == pytest.approx(0.12, rel=1e-12)
    assert ref.coverage_factor == 2.0 and ref.coverage_probability == 0.95
    assert abs(sum(ref.deviations.values())) < 1e-9  # the faces close the circle
    assert ref.notes == ()


def test_the_due_date_from_a_validity_period_and_none_stated(tmp_path):
    data = t.document(statements=t.validity(period="P2Y"), end_date="2024-02-29")
    ref = read_polygon_dcc(write(tmp_path, data), SCHEMA)
    assert ref.due_date == "2026-02-28"  # 29 February plus two years
    bare = read_polygon_dcc(write(tmp_path, t.document(), "bare.xml"), SCHEMA,
                            measurement_date="2030-01-01")
    assert bare.due_date == "" and "states no due date" in bare.notes[0]


def test_an_expired_calibration_is_refused(tmp_path):
    data = t.document("PTB-7", statements=t.validity(date="2026-06-30"))
    with pytest.raises(DccError, match=r"PTB-7 was due for recalibration on 2026-06-30, before "
                                       r"the measurement on 2026-07-01"):
        read_polygon_dcc(write(tmp_path, data), SCHEMA, measurement_date="2026-07-01")
    assert read_polygon_dcc(write(tmp_path, data), SCHEMA,
                            measurement_date="2026-06-30").due_date == "2026-06-30"


@pytest.mark.parametrize("unit", [r"\metre", r"\second", r"\one", r"\kilo\radian"])
def test_a_unit_that_is_no_angle_is_refused_by_name(tmp_path, unit):
    data = t.document(results=t.polygon_results(unit=unit))
    t.assert_valid(data)
    with pytest.raises(DccError, match=f"the unit {unit.replace(chr(92), chr(92) * 2)} is not "
                                       "an angle"):
        read_polygon_dcc(write(tmp_path, data), SCHEMA)


def test_a_face_count_that_disagrees_is_refused(tmp_path):
    path = write(tmp_path, t.document("PTB-9"))
    with pytest.raises(DccError, match="PTB-9 gives 12 faces, the readings have 24"):
        read_polygon_dcc(path, SCHEMA, faces=24)
    gapped = t.document(results=t.polygon_results(indices=[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 13]))
    with pytest.raises(DccError, match="face indices are not 1 to 12"):
        read_polygon_dcc(write(tmp_path, gapped, "g.xml"), SCHEMA)


def test_no_polygon_result_and_no_uncertainty_are_refused(tmp_path):
    other = t.document(results=t.polygon_results(result_reftype="basic_measuredValue"))
    with pytest.raises(DccError, match="no polygon result found"):
        read_polygon_dcc(write(tmp_path, other), SCHEMA)
    bare = t.document(results=t.polygon_results(with_u=False))
    with pytest.raises(DccError, match="carry no expanded uncertainty"):
        read_polygon_dcc(write(tmp_path, bare, "b.xml"), SCHEMA)


def test_a_document_failing_the_schema_is_refused_only_with_a_schema_folder(tmp_path):
    def extra(root):  # an element dcc.xsd does not allow at the root
        t.sub(root, t.d("unexpected"), "x")
    path = write(tmp_path, t.document(root_extra=extra))
    with pytest.raises(DccError, match=r"not a valid DCC 3.3.0 document .*unexpected"):
        read_polygon_dcc(path, SCHEMA)
    assert read_polygon_dcc(path).faces == 12  # no folder set: read as it is


def test_a_signed_dcc_is_read_and_a_changed_one_refused(tmp_path):
    key, cert = t.self_signed(tmp_path)
    signed = sign(t.document("PTB-S1", statements=t.validity(date="2099-01-01")), key, cert)
    t.assert_valid(signed)  # the ds:Signature sits where dcc.xsd allows it
    ref = read_polygon_dcc(write(tmp_path, signed), SCHEMA, trusted_cert=cert)
    assert ref.signer == "CN=Test lab DCC signing" and ref.notes == ()
    untrusted = read_polygon_dcc(write(tmp_path, signed), SCHEMA)
    assert "not checked against a trusted certificate" in untrusted.notes[0]
    changed = signed.replace(b"PTB-S1", b"PTB-S2")
    with pytest.raises(DccError, match="the signature does not verify: .*; it is not read"):
        read_polygon_dcc(write(tmp_path, changed, "c.xml"), SCHEMA)
    _, other = t.self_signed(tmp_path, "Someone else")
    # intact, but signed by another than the one trusted: said so, not "does not verify"
    with pytest.raises(DccError, match=r"signed by CN=Test lab DCC signing, which the trusted "
                       r"certificate \(CN=Someone else\) does not vouch for: the document is "
                       r"unchanged since it was signed, but not by the signer trusted; it is "
                       r"not read"):
        read_polygon_dcc(write(tmp_path, signed, "o.xml"), SCHEMA, trusted_cert=other)
    with pytest.raises(DccError, match="the signature does not verify: .*; it is not read"):
        read_polygon_dcc(write(tmp_path, changed, "oc.xml"), SCHEMA, trusted_cert=other)


def test_hostile_xml_reads_no_file_and_expands_no_entity(tmp_path):
    secret = tmp_path / "secret.txt"
    secret.write_text("TOP-SECRET-VALUE")
    xxe = (f'<?xml version="1.0"?><!DOCTYPE d [<!ENTITY x SYSTEM "file://{secret}">]>'
           '<dcc:digitalCalibrationCertificate xmlns:dcc="https://ptb.de/dcc" '
           'schemaVersion="3.3.0"><dcc:administrativeData><dcc:coreData>'
           '<dcc:uniqueIdentifier>&x;</dcc:uniqueIdentifier></dcc:coreData>'
           '</dcc:administrativeData></dcc:digitalCalibrationCertificate>').encode()
    laughs = ('<?xml version="1.0"?><!DOCTYPE l [<!ENTITY a "aaaaaaaaaa">'
              + "".join(f'<!ENTITY {c} "{("&" + p + ";") * 10}">'
                        for p, c in zip("abcdefgh", "bcdefghi", strict=True))
              + ']><dcc:digitalCalibrationCertificate xmlns:dcc="https://ptb.de/dcc">&i;'
              '</dcc:digitalCalibrationCertificate>').encode()
    for name, data in (("xxe.xml", xxe), ("laughs.xml", laughs)):
        with pytest.raises(DccError) as caught:
            read_polygon_dcc(write(tmp_path, data, name), SCHEMA)
        assert "TOP-SECRET" not in str(caught.value)
        assert "declares a DTD" in str(caught.value) or "not an XML document" in str(caught.value)
    with pytest.raises(DccError, match="not an XML document"):
        read_polygon_dcc(write(tmp_path, b"\x00\x01 not xml", "bin.xml"))
    with pytest.raises(DccError, match="not a digital calibration certificate"):
        read_polygon_dcc(write(tmp_path, b"<html/>", "h.xml"))


def test_a_standards_dcc_gives_its_id_u_and_due_date(tmp_path):
    data = t.document("NIM-2026-A17", results=t.standard_results(
        [0.1, -0.2, 0.05], r"\micro\radian", [0.3, 0.5, 0.4], k=2.0),
        statements=t.validity(date="2027-01-31", reftype="basic_validity"))
    t.assert_valid(data)
    got = read_standard_dcc(write(tmp_path, data), SCHEMA, measurement_date="2026-12-01")
    assert got.certificate_id == "NIM-2026-A17" and got.due_date == "2027-01-31"
    assert got.unit == "arcsec" and got.uncertainty == pytest.approx(0.5 * 0.648 / math.pi)
    assert got.as_standard() == {"certificate_no": "NIM-2026-A17", "due_date": "2027-01-31",
                                 "uncertainty": got.uncertainty, "basis": "U95",
                                 "uncertainty_unit": "arcsec", "applies_to": "reading"}
    k3 = t.document("K3", results=t.standard_results([1.0], r"\micro\metre", [0.6], k=3.0,
                                                     p=0.997))
    got = read_standard_dcc(write(tmp_path, k3, "k3.xml"), SCHEMA)
    assert got.unit == "um" and got.as_standard()["basis"] == "u"
    assert got.as_standard()["uncertainty"] == pytest.approx(0.2)  # U/k exactly
    volts = t.document("V1", results=t.standard_results([1.0], r"\volt", [0.1]))
    with pytest.raises(DccError, match=r"in \\volt: neither an angle nor a length"):
        read_standard_dcc(write(tmp_path, volts, "v.xml"), SCHEMA)


def test_the_readings_deviation_column_is_replaced_and_a_difference_said(tmp_path):
    ref = read_polygon_dcc(write(tmp_path, t.document(
        results=t.polygon_results([0.5, -0.25, 0.0, -0.25])), "four.xml"))
    rows = [["1", "0", "", "1"], ["2", "90", "", "2"], ["3", "180", "", "3"],
            ["4", "270", "", "4"], ["1", "360", "", "1"]]
    out, differed = replace_face_deviations(rows, 0, 2, ref)
    assert [r[2] for r in out] == ["0.500000", "-0.250000", "0.000000", "-0.250000", "0.500000"]
    assert not differed and rows[0][2] == ""  # the input is not changed
    typed = [r[:2] + ["0.5"] + r[3:] for r in rows]
    assert replace_face_deviations(typed, 0, 2, ref)[1]  # 0.5 typed where -0.25 is certified
    with pytest.raises(DccError, match="measures face 5"):
        replace_face_deviations(rows + [["5", "0", "", "0"]], 0, 2, ref)
    with pytest.raises(DccError, match="faces up to 3"):
        replace_face_deviations(rows[:3], 0, 2, ref)
    standard = polygon_standard(ref)
    assert standard["uncertainty"] == 0.15 and standard["basis"] == "U95"


def test_the_embedded_pdf_is_returned_byte_for_byte():
    pdf = bytes(range(256)) * 7
    assert embedded_pdfs(t.document(pdf=pdf)) == [pdf]
    assert embedded_pdfs(t.document()) == []


@settings(max_examples=60, deadline=None)
@given(st.lists(st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False), min_size=1,
                max_size=30))
def test_decimal_lists_round_trip(values):
    assert parse_decimal_list(" ".join(repr(v) for v in values), "x") == values


@settings(max_examples=60, deadline=None)
@given(st.floats(-1e4, 1e4, allow_nan=False),
       st.sampled_from([r"\arcsecond", r"\arcminute", r"\degree", r"\radian", r"\milli\radian",
                        r"\micro\radian"]))
def test_unit_conversion_is_exact(arcsec, unit):
    per = {r"\arcsecond": 1.0, r"\arcminute": 60.0, r"\degree": 3600.0,
           r"\radian": 206264.80624709636, r"\milli\radian": 206.26480624709636,
           r"\micro\radian": 0.20626480624709636}[unit]
    assert angle_factor(unit) == pytest.approx(per, rel=1e-15)
    assert (arcsec / per) * angle_factor(unit) == pytest.approx(arcsec, rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("word", ["1,5", "0x10", "nan", "inf", "1e999", "--1", ""])
def test_a_bad_decimal_is_named(word):
    if not word:
        assert parse_decimal_list("  ", "x") == []
        return
    with pytest.raises(DccError, match="entry 2"):
        parse_decimal_list(f"1.0 {word}", "x")


def test_a_schema_folder_that_cannot_be_used_is_named(tmp_path):
    path = write(tmp_path, t.document())
    with pytest.raises(DccError, match="dcc.xsd is missing"):
        read_polygon_dcc(path, tmp_path / "no-schemas")


@settings(max_examples=25, deadline=None)
@given(st.integers(3, 72), st.integers(0, 10_000),
       st.sampled_from([r"\arcsecond", r"\arcminute", r"\degree", r"\radian", r"\micro\radian"]),
       st.floats(0.01, 2.0), st.sampled_from([1.96, 2.0, 2.5, 3.0]))
def test_any_polygon_written_in_any_angle_unit_reads_back(faces, seed, unit, u, k):
    """A polygon of any face count, its deviations written by another lab in any angle
    unit, reads back face by face in arcseconds with its U and k."""
    import tempfile
    from pathlib import Path

    errors = t.polygon_errors(faces, seed=seed, spread_arcsec=1.5)
    data = t.document(results=t.polygon_results(errors, unit=unit, u_arcsec=u, k=k))
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "p.xml"
        path.write_bytes(data)
        ref = read_polygon_dcc(path, faces=faces)
    assert ref.faces == faces and ref.coverage_factor == k
    for face, error in enumerate(errors, 1):
        assert ref.deviations[face] == pytest.approx(error, rel=1e-12, abs=1e-12)
        assert ref.expanded_uncertainty[face] == pytest.approx(u, rel=1e-12)
    standard = polygon_standard(ref)
    assert standard["uncertainty"] * (1.0 if k == 2.0 else k) == pytest.approx(u, rel=1e-12)


@settings(max_examples=40, deadline=None)
@given(st.permutations(range(1, 13)), st.lists(st.sampled_from(["", "0", "9.9", "x"]),
                                                min_size=12, max_size=12))
def test_every_face_gets_its_own_deviation_whatever_the_order(tmp_path_factory, order, before):
    ref = read_polygon_dcc(write(tmp_path_factory.mktemp("p"), t.document()))
    rows = [[str(face), "0", typed, "0"] for face, typed in zip(order, before, strict=True)]
    out, differed = replace_face_deviations(rows, 0, 2, ref)
    for row in out:
        assert float(row[2]) == pytest.approx(ref.deviations[int(row[0])], abs=5e-7)
    typed_other = [b == "x" or (b != "" and abs(float(b) - ref.deviations[face]) > 5e-4)
                   for face, b in zip(order, before, strict=True)]
    assert differed == any(typed_other)


def test_a_file_too_large_is_refused_before_it_is_read(tmp_path, monkeypatch):
    """dccin74 F10: the 64 MB limit was checked after the whole file was read."""
    from pathlib import Path

    big = tmp_path / "big.xml"
    with open(big, "wb") as handle:  # sparse: 65 MB that take no disk
        handle.truncate(65 * 1024 * 1024)

    def never(self):
        raise AssertionError(f"{self} read in full")

    monkeypatch.setattr(Path, "read_bytes", never)
    with pytest.raises(DccError, match="65 MB: too large"):
        read_standard_dcc(big)


@pytest.mark.parametrize("k, p", [(2.0, 0.9545), (1.96, 0.95), (2.0, 0.95), (2.02298, 0.9545),
                                  (2.52, 0.95), (1.0, 0.6827), (3.0, 0.9973), (1.7320508, 1.0)])
def test_a_coverage_factor_that_goes_with_its_probability_is_read(tmp_path, k, p):
    """dccin74 F8's check refuses only what contradicts: k from the normal distribution's
    (1.96 for 95 %) to Student's t with few degrees of freedom (2.52: ν = 6), a bounded
    distribution's √3 at p = 1."""
    data = t.document("K", results=t.polygon_results(t.polygon_errors(12, seed=1),
                                                     u_arcsec=0.1, k=k, p=p))
    got = read_polygon_dcc(write(tmp_path, data), measurement_date="2026-11-20")
    assert (got.coverage_factor, got.coverage_probability) == (k, p)
