"""A cross-calibration's U stated from face 1 and from step 0 is held to the laboratory's CMC
of its quantity (ILAC-P14 5.4), as its U about the mean is, except at the reference point
itself (zero by definition); every output that states it says the same figures.

The sample's U from face 1 is 0.046″ … 0.050″ and from step 0 0.041″ …; with the polygon's
CMC 0.10″ and the encoder's 0.07″ (two values, so the JSON's laboratory_cmc cannot confuse
them) every one of them but the reference's is raised. The expected U are recomputed here
from the same readings analysed without a CMC.
"""

from __future__ import annotations

import contextlib
import io
import json
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from lxml import etree
from openpyxl import load_workbook

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.dcc import vocabulary as v
from models.dcc.schema import validate
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from tests.printed_u import u_beside

pytestmark = pytest.mark.slow  # certificates, DCCs, XLSX and the JSON

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
READINGS = SAMPLES / "crosscal_sample.csv"
NS = {"dcc": v.DCC_NAMESPACE, "si": v.SI_NAMESPACE}
CMC_POLYGON, CMC_ENCODER = 0.10, 0.07
CMC_ARGS = ("--cmc-arcsec", f"{CMC_POLYGON:g}", "--cmc-encoder-arcsec", f"{CMC_ENCODER:g}")
SCHEMA = next((p / "shared" / "dcc" for p in ROOT.parents
               if (p / "shared" / "dcc" / "dcc.xsd").is_file()), None)
KIND = KINDS["crosscal"]


def _details(out: Path, sample: str, **changes) -> Path:
    details = json.loads((SAMPLES / sample).read_text(encoding="utf-8"))
    details.update(example=False, language="en", **changes)
    path = out / f"meta{len(list(out.glob('meta*')))}.json"
    path.write_text(json.dumps(details), encoding="utf-8")
    return path


def _main(args: list[str]) -> str:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


def _json(meta: Path, *extra: str) -> dict:
    text = _main(["analyze", "crosscal", str(READINGS), "--metadata", str(meta), "--json",
                  *extra])
    return json.loads(text[text.index("{"):])


def _pdf_text(path: Path) -> str:
    if shutil.which("pdftotext"):
        return subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True,
                              check=True, text=True).stdout
    from pypdf import PdfReader

    return "\n".join(p.extract_text() for p in PdfReader(path).pages)


def _analysed(**settings):
    rows = map_columns(read_table(READINGS), KIND.columns)
    parsed = ReadingsSheet(KIND.columns, rows).parse()
    full = {**KIND.default_settings, **settings}
    return KIND.analyze(parsed, full), full


def _metadata(sample: str) -> CertificateMetadata:
    return CertificateMetadata.from_dict(json.loads((SAMPLES / sample).read_text(
        encoding="utf-8")))


def _floored(computed, cmc: float) -> tuple[np.ndarray, np.ndarray]:
    """(U, raised): each U but the first (the reference's, zero) at least the CMC."""
    computed = np.asarray(computed, dtype=float)
    raised = (np.arange(computed.size) > 0) & (computed < cmc)
    return np.where(raised, cmc, computed), raised


@pytest.fixture(scope="module")
def issued(tmp_path_factory):
    out = tmp_path_factory.mktemp("xcalcmc")
    mp = pytest.MonkeyPatch()
    try:
        polygon = _details(out, "certificate_crosscal.json")
        encoder = _details(out, "certificate_crosscal_encoder.json")
        mp.setenv("ANGLEBENCH_REGISTER", str(out / "polygon.sqlite"))
        plain = _json(polygon)
        held = _json(polygon, *CMC_ARGS)
        _main(["analyze", "crosscal", str(READINGS), "--metadata", str(polygon), *CMC_ARGS,
               "--certificate", str(out / "p.pdf"), "--dcc", str(out / "p.xml"),
               "--results", str(out / "p.xlsx"), "--table", str(out / "p.csv")])
        mp.setenv("ANGLEBENCH_REGISTER", str(out / "plain.sqlite"))
        _main(["analyze", "crosscal", str(READINGS), "--metadata", str(polygon),
               "--certificate", str(out / "plain.pdf")])
        mp.setenv("ANGLEBENCH_REGISTER", str(out / "encoder.sqlite"))
        _main(["analyze", "crosscal", str(READINGS), "--metadata", str(encoder), *CMC_ARGS,
               "--certificate-of", "encoder", "--certificate", str(out / "e.pdf"),
               "--dcc", str(out / "e.xml")])
    finally:
        mp.undo()
    plain_result, _ = _analysed()  # no CMC: the U these readings give
    return {"out": out, "plain": plain, "held": held,
            "u_face1": np.asarray(plain["polygon_deviation_U_from_face1_arcsec"]),
            "u_step0": plain_result.encoder_u_from_step0_arcsec(
                _metadata("certificate_crosscal_encoder.json")),
            "k": plain["coverage_factor"]}


def test_the_sample_is_below_both_cmcs(issued):
    # what the test relies on: every U from the reference but its own is below its CMC
    assert issued["u_face1"][0] == 0.0 and np.min(issued["u_face1"][1:]) > 0.04
    assert np.max(issued["u_face1"]) < CMC_POLYGON
    assert issued["u_step0"][0] == 0.0 and np.max(issued["u_step0"]) < CMC_ENCODER


def test_the_json_states_u_from_face1_held_to_the_cmc_and_flags_it(issued):
    plain, held = issued["plain"], issued["held"]
    expected, raised = _floored(issued["u_face1"], CMC_POLYGON)
    assert raised.sum() == 11 and not raised[0]
    for key in ("polygon_deviation_U_from_face1_arcsec",
                "expanded_uncertainty_polygon_deviation_from_face1_arcsec"):
        assert held[key] == pytest.approx(list(expected), abs=1e-15), key
    assert held["uncertainty_raised_to_cmc_polygon_deviation_from_face1_arcsec"] == list(raised)
    # k stays the solution's, the values themselves do not move
    assert held["coverage_factor_polygon_deviation_from_face1_arcsec"] == plain["coverage_factor"]
    assert held["polygon_deviation_from_face1_arcsec"] == plain["polygon_deviation_from_face1_arcsec"]
    cmc = held["laboratory_cmc"]
    assert (cmc["setting"], cmc["value"]) == ("cmc_arcsec", CMC_POLYGON)
    assert cmc["arrays"] == ["polygon_deviation_arcsec", "polygon_deviation_from_face1_arcsec"]
    assert cmc["other_quantities"][0]["arrays"] == ["encoder_error_arcsec",
                                                    "encoder_error_from_step0_arcsec"]


def test_without_a_cmc_the_u_from_face1_is_what_the_readings_give(issued, tmp_path):
    plain = issued["plain"]
    assert "laboratory_cmc" not in plain
    assert not [key for key in plain if key.startswith("uncertainty_raised_to_cmc_")]
    assert plain["expanded_uncertainty_polygon_deviation_from_face1_arcsec"] == \
        plain["polygon_deviation_U_from_face1_arcsec"]
    # the certificate's column as before: 2 significant digits of the readings' own U, as
    # printed beside its figure (rounded up; issue 39)
    text = _pdf_text(issued["out"] / "plain.pdf")
    rows = re.findall(r"^\s*(\d+)\s+\d+\.0000\s+[+-]\d\.\d+\s+0\.\d+\s+[+-]\d\.\d{3}\s+(0\.\d+)\s*$",
                      text, re.M)
    d1 = plain["polygon_deviation_from_face1_arcsec"]
    assert [u for _, u in rows] == [u_beside(x, u) for x, u in
                                    zip(d1[1:], issued["u_face1"][1:], strict=True)]
    assert "holds the U stated from face 1" not in text


def test_the_certificate_prints_u_from_face1_held_to_the_cmc(issued):
    text = _pdf_text(issued["out"] / "p.pdf")
    # the results table: face, nominal, deviation, U, from face 1, U from face 1; each figure
    # from face 1 to its U's decimal (0.10″: 2 decimals), face 1 the reference point
    # (each U the CMC's 0.10″ as printed beside its figure: rounded up, the figure ± U
    # holding the computed interval, so 0.10″ or 0.11″; issue 39)
    rows = re.findall(r"^\s*(\d+)\s+(\d+\.0000)\s+([+-]\d\.\d\d)\s+(0\.1\d)\s+([+-]\d\.\d+)\s+"
                      r"(0\.\d+)\s*$", text, re.M)
    d1 = np.asarray(issued["plain"]["polygon_deviation_from_face1_arcsec"])
    deviation = np.asarray(issued["plain"]["polygon_deviation_arcsec"])
    assert [r[0] for r in rows] == [str(i) for i in range(2, 13)]
    assert [r[5] for r in rows] == [u_beside(x, CMC_POLYGON) for x in d1[1:]]
    assert [r[3] for r in rows] == [u_beside(x, CMC_POLYGON) for x in deviation[1:]]
    assert [r[4] for r in rows] == [f"{x:+.2f}" for x in d1[1:]]
    # face 1 from face 1: zero, unsigned (assessment 76 L6)
    assert re.search(r"^\s*1\s+0\.0000\s+[+-]\d\.\d\d\s+0\.1\d\s+0\.00\s*$", text, re.M)
    flat = " ".join(text.split())
    assert flat.count("reference point, by") == 1  # face 1's U (the layout wraps it)
    assert "U(x_j − x_i), is at most 0.10\"." in flat  # two significant digits (GUM 7.2.6)
    assert ("The laboratory's CMC for this quantity, U = 0.1\", holds the U stated from face 1 "
            "and the U of the difference of any two too: from face 1, at 11 of the 11 other "
            f"points the U these readings give (down to {np.min(issued['u_face1'][1:]):.2g}\") "
            "is below it, so it is stated as the CMC, with the same coverage factor k "
            "(ILAC-P14 5.4).") in flat


def test_the_certificate_document_of_the_encoder_holds_u_from_step0(issued):
    result, settings = _analysed(certificate_of="encoder", cmc_arcsec=CMC_POLYGON,
                                 cmc_encoder_arcsec=CMC_ENCODER)
    metadata = _metadata("certificate_crosscal_encoder.json")
    document = KIND.certificate_document(result, metadata, "crosscal_sample.csv", settings)
    columns = dict(document.point_columns)
    expected, raised = _floored(issued["u_step0"], CMC_ENCODER)
    assert raised.sum() == 11
    np.testing.assert_array_equal(columns["expanded_uncertainty_from_step0_arcsec"], expected)
    table = document.results
    last = [row[-1] for row in table.rows]
    from_step0 = columns["error_from_step0_arcsec"]
    assert last[1:] == [u_beside(x, CMC_ENCODER) for x in from_step0[1:]]
    assert "reference point" in str(last[0])
    # and the PDF issued with the same settings prints them
    flat = " ".join(_pdf_text(issued["out"] / "e.pdf").split())
    assert "holds the U stated from step 0 and the U of the difference of any two too: from " \
           "step 0, at 11 of the 11 other points" in flat


def _marked(dcc: bytes) -> dict[str, tuple[list[bool], float, np.ndarray, np.ndarray]]:
    """Each quantity with CMC marks: (marks, the CMC, its U, its k), by its key (the column's,
    or the shared form's refType)."""
    root = etree.fromstring(dcc)
    out = {}
    for q in root.xpath(".//dcc:quantity[dcc:measurementMetaData/dcc:metaData"
                        f"[@refType='{v.REFTYPE_U_RAISED_TO_CMC}']]", namespaces=NS):
        names = q.xpath("dcc:name/dcc:content[not(@lang)]/text()", namespaces=NS)
        key = names[0] if names else q.get("refType")
        meta = q.find("dcc:measurementMetaData/dcc:metaData", NS)
        marks = [x == "true" for x in meta.findtext("dcc:validXMLList", namespaces=NS).split()]
        u = np.array(q.findtext(".//si:valueExpandedMUXMLList", namespaces=NS).split(), float)
        k = np.array(q.findtext(".//si:coverageFactorXMLList", namespaces=NS).split(), float)
        out[key] = (marks, float(meta.findtext(".//si:value", namespaces=NS)), u, k)
    return out


def test_the_dcc_states_u_from_face1_held_its_shared_form_too_each_point_marked(issued):
    xml = (issued["out"] / "p.xml").read_bytes()
    if SCHEMA is not None:
        assert validate(xml, SCHEMA) == []
    expected, raised = _floored(issued["u_face1"], CMC_POLYGON)
    marked = _marked(xml)
    shared = next(key for key in marked if v.REFTYPE_FACE_DEVIATION in key)
    assert set(marked) == {"deviation_arcsec", "deviation_from_face1_arcsec", shared}
    for key in ("deviation_from_face1_arcsec", shared):
        marks, cmc, u, k = marked[key]
        assert marks == list(raised) and cmc == CMC_POLYGON, key
        np.testing.assert_allclose(u, expected, rtol=1e-11, atol=0.0, err_msg=key)
        # k is the solution's at every point (not that of a point of the budget about the
        # mean whose U is the same CMC)
        np.testing.assert_allclose(k, issued["k"], rtol=1e-10, err_msg=key)
    # the deviations about the mean: every point raised, each keeps its own k (the JSON's)
    marks, _, u, k = marked["deviation_arcsec"]
    assert all(marks) and np.all(u == CMC_POLYGON)
    np.testing.assert_allclose(
        k, issued["held"]["coverage_factor_polygon_deviation_arcsec"], rtol=1e-10)
    assert np.ptp(k) > 1e-5  # (they differ from point to point)
    # the polygon workbench reads the shared form as the polygon's certificate: the same U
    from models.dcc.reader import read_polygon_dcc

    reference = read_polygon_dcc(issued["out"] / "p.xml", None)
    np.testing.assert_allclose(list(reference.expanded_uncertainty.values()), expected,
                               rtol=1e-11)


def test_the_encoders_dcc_states_u_from_step0_held_and_marked(issued):
    xml = (issued["out"] / "e.xml").read_bytes()
    if SCHEMA is not None:
        assert validate(xml, SCHEMA) == []
    expected, raised = _floored(issued["u_step0"], CMC_ENCODER)
    marks, cmc, u, k = _marked(xml)["error_from_step0_arcsec"]
    assert marks == list(raised) and cmc == CMC_ENCODER
    np.testing.assert_allclose(u, expected, rtol=1e-11, atol=0.0)
    np.testing.assert_allclose(k, issued["k"], rtol=1e-10)


def test_the_xlsx_and_the_face_deviation_file_state_the_same_u(issued):
    expected, _ = _floored(issued["u_face1"], CMC_POLYGON)
    sheet = load_workbook(issued["out"] / "p.xlsx")["Results"]
    rows = list(sheet.iter_rows(values_only=True))
    column = rows[0].index("expanded_uncertainty_from_face1_arcsec")
    assert [r[column] for r in rows[1:13]] == pytest.approx(list(expected), abs=1e-15)
    text = (issued["out"] / "p.csv").read_text(encoding="utf-8")
    lines = [line.split(",") for line in text.splitlines() if line[:1].isdigit()]
    assert [line[2] for line in lines] == [f"{u:.4f}" for u in expected]  # --metadata's
    assert "from face 1 up to 0.1000 arcsec" in text
    assert "# each U held to the laboratory's CMC for face deviations, 0.1 arcsec, except at " \
           "face 1 (zero by definition)" in text
    # the polygon workbench reads it
    from models.polygon.certificate_reader import read_polygon_certificate

    d1 = issued["plain"]["polygon_deviation_from_face1_arcsec"]
    assert read_polygon_certificate(issued["out"] / "p.csv") == pytest.approx(
        {i + 1: round(x, 4) for i, x in enumerate(d1)}, abs=1e-12)


def test_the_reference_sent_to_the_polygon_workbench_holds_its_u_to_the_cmc(issued):
    result, _ = _analysed(cmc_arcsec=CMC_POLYGON, cmc_encoder_arcsec=CMC_ENCODER)
    # with the certificate details, as the window sends it (tests/app/test_crosscal_sent_u.py)
    sent = KIND.sent_reference(result, _metadata("certificate_crosscal.json"))
    expected, _ = _floored(issued["u_face1"], CMC_POLYGON)
    assert list(sent.expanded_uncertainty) == list(range(1, 13))
    np.testing.assert_allclose(list(sent.expanded_uncertainty.values()), expected, rtol=1e-12)
    assert sent.coverage_factor == issued["k"]
    assert sent.largest_standard_uncertainty == pytest.approx(CMC_POLYGON / issued["k"])
    assert sent.standard_name.endswith(
        f"the largest U of d_i − d_1 over the faces, 0.1000\" (k = {issued['k']:.2f}), each at "
        "least the laboratory's CMC 0.1\"")
    # without a CMC: the U these readings and details give, named as before
    plain, _ = _analysed()
    sent = KIND.sent_reference(plain, _metadata("certificate_crosscal.json"))
    np.testing.assert_allclose(list(sent.expanded_uncertainty.values()),
                               issued["u_face1"], rtol=1e-12)
    assert sent.standard_name.endswith(f"over the faces, {np.max(issued['u_face1']):.4f}\" "
                                       f"(k = {issued['k']:.2f})")


def test_a_cmc_within_the_u_from_face1_raises_only_the_points_below_it(issued):
    computed = issued["u_face1"]
    cmc = float(np.median(computed[1:]))
    result, _ = _analysed(cmc_arcsec=cmc)
    held = result.u_from_first("polygon", _metadata("certificate_crosscal.json"))
    expected, raised = _floored(computed, cmc)
    assert 0 < raised.sum() < 11
    np.testing.assert_array_equal(held.below_floor, raised)
    np.testing.assert_allclose(held.expanded, expected, rtol=1e-12)
    # the encoder's from step 0 is the encoder's CMC's, not the polygon's
    np.testing.assert_allclose(result.encoder_u_from_step0_arcsec(), _analysed()[0]
                               .encoder_u_from_step0_arcsec(), rtol=0.0, atol=0.0)
