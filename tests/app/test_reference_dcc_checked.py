"""A polygon's or a standard's DCC is checked as a whole before anything of it is taken
(dccin74): the item it calibrates is the standard it is read for (F1), a configured trust
is not bypassed by removing the signature (F2), its dates (F5, F6), its coverage factor
with its probability (F8), and values no polygon has are the DCC's, said so (F9).

Every DCC here is AngleBench's own — the cross-calibration sample's, a 12-face polygon
P12-7 calibrated 2026-11-20 — altered in the test with lxml: its polygon result given the
24 deviations of the polygon sample's column (read from the CSV here), its serial, dates,
k, p or a face's value changed."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest
from lxml import etree

from app.main import main
from tests import dcc_documents as t

pytestmark = pytest.mark.slow  # the cross-calibration sample is issued once (conftest)

NS = {"dcc": "https://ptb.de/dcc", "si": "https://ptb.de/si"}
SAMPLE_DETAILS = "certificate_polygon.json"  # lists polygon P24-3, calibration 2026-11-20


@pytest.fixture(scope="module")
def issued_polygon(issued_samples) -> Path:
    code, said, _, xml, _, _ = issued_samples["crosscal"]
    assert code == 0, said
    return xml


def _sample_deviations(samples_dir: Path) -> dict[int, float]:
    with open(samples_dir / "polygon_sample.csv", encoding="utf-8") as handle:
        return {int(r["position"]): float(r["polygon_dev_arcsec"]) for r in csv.DictReader(handle)}


def polygon_dcc(base: Path, out: Path, deviations: dict[int, float], *, u=None, k="2",
                p="0.9545", serial: str | None = None, end_date: str | None = None,
                period: str | None = None, alone: bool = False) -> Path:
    """``base`` (AngleBench's DCC of a polygon) with its polygon result giving
    ``deviations`` with U ``u`` (one per face, default 0.10″), k and p, and the other
    changes asked for (``alone``: its other results removed), written to ``out``."""
    tree = etree.parse(str(base))
    n = len(deviations)
    result = tree.find(".//dcc:result[@refType='anglebench_polygonFaceDeviations']", NS)
    for other in list(result.getparent()) if alone else ():
        if other is not result:
            result.getparent().remove(other)
    index = result.find(".//dcc:quantity[@refType='anglebench_faceIndex']", NS)
    index.find(".//si:valueXMLList", NS).text = " ".join(str(i) for i in range(1, n + 1))
    face = result.find(".//dcc:quantity[@refType='anglebench_faceDeviation']", NS)
    face.find(".//si:valueXMLList", NS).text = " ".join(repr(deviations[i])
                                                        for i in range(1, n + 1))
    face.find(".//si:valueExpandedMUXMLList", NS).text = " ".join(
        str(x) for x in (u or [0.10] * n))
    face.find(".//si:coverageFactorXMLList", NS).text = k
    face.find(".//si:coverageProbabilityXMLList", NS).text = p
    if serial is not None:
        tree.find(".//dcc:items/dcc:item/dcc:identifications/dcc:identification/dcc:value",
                  NS).text = serial
    if end_date is not None:
        tree.find(".//dcc:coreData/dcc:endPerformanceDate", NS).text = end_date
    if period is not None:
        validity = tree.find(".//dcc:statement[@refType='anglebench_validity']", NS)
        element = etree.Element(f"{{{NS['dcc']}}}period")
        element.text = period
        validity.insert(0, element)
    tree.write(str(out), xml_declaration=True, encoding="UTF-8")
    return out


def _analyze(capsys, samples_dir, dcc, details=None, *extra) -> tuple[int, str, str]:
    code = main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--metadata",
                 str(details or samples_dir / SAMPLE_DETAILS), "--reference-dcc", str(dcc),
                 "--json", *map(str, extra)])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_another_polygons_dcc_is_refused_naming_both(issued_polygon, samples_dir, tmp_path,
                                                     capsys):
    """F1: the DCC of polygon P12-7 (its deviations 3″ off the sample's) for the details'
    P24-3 was taken: the certificate printed P24-3 with the other's number and errors."""
    deviations = _sample_deviations(samples_dir)
    other = {i: v + (3.0 if i % 2 else -3.0) for i, v in deviations.items()}
    dcc = polygon_dcc(issued_polygon, tmp_path / "other.xml", other)
    pdf = tmp_path / "c.pdf"
    code, _, err = _analyze(capsys, samples_dir, dcc, None, "--certificate", pdf)
    assert code == 2, err
    assert "serial P12-7" in err and "serial P24-3" in err and "another item's" in err, err
    assert not pdf.exists()
    same = polygon_dcc(issued_polygon, tmp_path / "same.xml", deviations, serial="P24-3")
    code, _, err = _analyze(capsys, samples_dir, same)
    assert code == 0, err
    # details that name no serial yet take the DCC's, and say so
    details = tmp_path / "no_serial.json"
    text = (samples_dir / SAMPLE_DETAILS).read_text(encoding="utf-8")
    details.write_text(text.replace('"P24-3"', '""'), encoding="utf-8")
    code, _, err = _analyze(capsys, samples_dir, dcc, details)
    assert code == 0, err
    assert "P12-7 is taken from certificate" in err, err


def test_an_unsigned_dcc_is_refused_where_a_trusted_certificate_is_set(
        issued_polygon, samples_dir, tmp_path, capsys, monkeypatch):
    """F2: with the lab's trusted certificate configured, a DCC whose signature was removed
    (then altered) was read in silence."""
    _, cert = t.self_signed(tmp_path)
    trusted = tmp_path / "trusted.pem"
    trusted.write_bytes(cert)
    monkeypatch.setenv("ANGLEBENCH_DCC_TRUSTED_CERTIFICATE", str(trusted))
    dcc = polygon_dcc(issued_polygon, tmp_path / "unsigned.xml",
                      _sample_deviations(samples_dir), serial="P24-3")
    code, _, err = _analyze(capsys, samples_dir, dcc)
    assert code == 2 and "signature missing" in err, err
    monkeypatch.delenv("ANGLEBENCH_DCC_TRUSTED_CERTIFICATE")
    code, _, err = _analyze(capsys, samples_dir, dcc)
    assert code == 0, err


def test_the_labs_own_signing_certificate_demands_no_signature_of_a_dcc_read(
        issued_polygon, samples_dir, tmp_path, capsys, monkeypatch):
    """A lab that signs its own DCCs (ANGLEBENCH_DCC_SIGNING_CERTIFICATE) still reads a supplier's unsigned
    DCC (a signature is optional in DCC 3.3.0): only a trusted certificate named for the DCCs
    read demands one (the lab's signing certificate counted as that, and every unsigned DCC
    was refused with no way to read it)."""
    _, cert = t.self_signed(tmp_path)
    own = tmp_path / "lab.pem"
    own.write_bytes(cert)
    monkeypatch.delenv("ANGLEBENCH_DCC_TRUSTED_CERTIFICATE", raising=False)
    monkeypatch.setenv("ANGLEBENCH_DCC_SIGNING_CERTIFICATE", str(own))
    dcc = polygon_dcc(issued_polygon, tmp_path / "unsigned.xml",
                      _sample_deviations(samples_dir), serial="P24-3")
    code, _, err = _analyze(capsys, samples_dir, dcc)
    assert code == 0, err


def test_calibration_dates_are_checked(issued_polygon, samples_dir, tmp_path, capsys):
    """F6: a calibration dated after the measurement (2026-11-20) was taken; one 25 years
    old was said only as 'states no due date (no validity statement)' — of a DCC that
    states its validity. F5: a validity period past the year 9999 crashed."""
    deviations = _sample_deviations(samples_dir)
    future = polygon_dcc(issued_polygon, tmp_path / "future.xml", deviations, serial="P24-3",
                         end_date="2030-06-01")
    code, _, err = _analyze(capsys, samples_dir, future)
    assert code == 2 and "calibrated on 2030-06-01, after the measurement on 2026-11-20" in err
    old = polygon_dcc(issued_polygon, tmp_path / "old.xml", deviations, serial="P24-3",
                      end_date="2001-01-05")
    code, _, err = _analyze(capsys, samples_dir, old)
    assert code == 0, err
    # 2001-01-05 to 2026-11-20: 9450 days
    assert f"calibrated 2001-01-05, {9450 / 365.25:.1f} years before the measurement" in err
    assert "no validity statement" not in err and "its validity statement gives no due" in err
    huge = polygon_dcc(issued_polygon, tmp_path / "huge.xml", deviations, serial="P24-3",
                       period="P9999Y")
    code, _, err = _analyze(capsys, samples_dir, huge)
    assert code == 2 and "P9999Y" in err and "after the year 9999" in err, err


@pytest.mark.parametrize("k, p, said", [
    ("0.5", "0.9545", "k = 0.5 is below 1"),
    ("2", "0.6827", "k = 2 and the coverage probability p = 0.6827 contradict"),
    ("2", "0.5", "k = 2 and the coverage probability p = 0.5 contradict"),
    ("1", "0.9545", "k = 1 and the coverage probability p = 0.9545 contradict")])
def test_coverage_factors_that_make_no_sense_are_refused(issued_polygon, samples_dir,
                                                         tmp_path, capsys, k, p, said):
    """F8: k = 0.5 doubled the certificate's U; k = 2 with p = 0.68 was printed as U95."""
    dcc = polygon_dcc(issued_polygon, tmp_path / "k.xml", _sample_deviations(samples_dir),
                      serial="P24-3", k=k, p=p)
    code, _, err = _analyze(capsys, samples_dir, dcc)
    assert code == 2 and said in err and "k.xml: " in err, err  # the DCC named


@pytest.mark.parametrize("p, basis", [("0.9545", "U95"), ("0.95", "U95"), ("0.90", "u")])
def test_the_label_follows_the_stated_probability(issued_polygon, samples_dir, tmp_path, p,
                                                  basis):
    """F8: U with k = 2 was listed as U95 whatever p the DCC stated; k = 2 with p = 0.90
    (few degrees of freedom) is no 95 % interval: listed as U/k with its k."""
    from models.dcc.reader import polygon_standard, read_polygon_dcc

    dcc = polygon_dcc(issued_polygon, tmp_path / "p.xml", _sample_deviations(samples_dir),
                      u=[0.2] * 24, serial="P24-3", p=p)
    standard = polygon_standard(read_polygon_dcc(dcc, measurement_date="2026-11-20"))
    assert standard["basis"] == basis and standard["coverage_factor"] == 2.0
    assert standard["uncertainty"] == pytest.approx(0.2 if basis == "U95" else 0.1)


@pytest.mark.parametrize("face, value, u, said", [
    (5, 3_600_000.0, None, "face 5: the deviation 3.6e+06″ is beyond ±3600″"),
    (24, None, 5000.0, "face 24: the expanded uncertainty 5000″ is beyond ±3600″"),
    (0, None, 0.0, "the expanded uncertainty is 0 on every face")])
def test_impossible_values_are_the_dccs(issued_polygon, samples_dir, tmp_path, capsys, face,
                                        value, u, said):
    """F9: a face deviation of 1000° was refused as 'polygon_sample.csv: row 5 …', the
    readings blamed; F4: U 5000″ or 0 on every face was refused as the details'."""
    deviations = _sample_deviations(samples_dir)
    us = [0.10] * len(deviations)
    if value is not None:
        deviations[face] = value
    if u is not None:
        us = [u] * len(us) if face == 0 else [*us[:face - 1], u, *us[face:]]
    dcc = polygon_dcc(issued_polygon, tmp_path / "bad.xml", deviations, u=us, serial="P24-3")
    code, _, err = _analyze(capsys, samples_dir, dcc)
    assert code == 2, err
    assert "bad.xml" in err and said in err and "polygon_sample.csv" not in err, err


def test_a_statistic_of_the_errors_is_not_the_error(issued_polygon, tmp_path):
    """F7: beside an 'Errors' result (U 0.3″), a result named 'Standard deviation of the
    error (repeatability)' (U 2.0″) gave the standard's U: the words 'standard deviation'
    cut out, 'of the error' was taken for an error. The DCC's refTypes are removed, so its
    names alone say what each result is."""
    from models.dcc.reader import read_standard_dcc

    tree = etree.parse(str(issued_polygon))
    results = tree.find(".//dcc:measurementResult/dcc:results", NS)
    polygon = results.find("dcc:result[@refType='anglebench_polygonFaceDeviations']", NS)
    for result in list(results):
        if result is not polygon:
            results.remove(result)
    statistic = etree.fromstring(etree.tostring(polygon))
    results.append(statistic)
    for result, name, u in ((polygon, "Errors", 0.3),
                            (statistic, "Standard deviation of the error (repeatability)", 2.0)):
        for content in result.findall("dcc:name/dcc:content", NS):
            content.text = name
        face = result.find(".//dcc:quantity[@refType='anglebench_faceDeviation']", NS)
        for content in face.findall("dcc:name/dcc:content", NS):
            content.text = name
        mu = face.find(".//si:valueExpandedMUXMLList", NS)
        mu.text = " ".join([str(u)] * len(mu.text.split()))
        face.find(".//si:coverageFactorXMLList", NS).text = "2"
    for element in tree.getroot().iter():
        element.attrib.pop("refType", None)
    path = tmp_path / "statistic.xml"
    tree.write(str(path), xml_declaration=True, encoding="UTF-8")
    got = read_standard_dcc(path, measurement_date="2026-11-20")
    assert got.uncertainty == pytest.approx(0.3) and got.coverage_factor == 2.0
