"""What the cross-calibration sends to the polygon workbench (File › Send as reference) and
writes to its face-deviation file carries the U from face 1 that its certificate states with
the same certificate details: the comparators' (autocollimator's) stated calibration U in.

Before, both took U without the certificate details: for the bundled sample 0.028″ sent
against 0.050″ certified, so a polygon certificate made with the sent reference stated a U
too small. Without details that list a comparator with a stated U, the U sent or written is
the readings' own (what the certificate states with those details) and says, in the standard's
name, the window's message and the file's header, that it leaves the comparators' calibration
out.

The expected U are the CLI's JSON "U from face 1" (with --metadata, the certificate's) and
the certificate's own column, never the function under test.
"""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.registry import KINDS
from tests.printed_u import u_beside

pytestmark = pytest.mark.slow  # the window, the CLI and a certificate

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
READINGS = SAMPLES / "crosscal_sample.csv"
KIND = KINDS["crosscal"]
WITHOUT = ("without the comparators' calibration U: not stated in the cross-calibration's "
           "certificate details")
INCLUDED = "# the comparators' stated calibration U included, as on the cross-calibration's certificate"


def _details(**changes) -> dict:
    data = json.loads((SAMPLES / "certificate_crosscal.json").read_text(encoding="utf-8"))
    data.update(example=False, language="en", **changes)
    return data


def _main(args: list[str]) -> tuple[str, str]:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue(), told.getvalue()


def _json(*extra: str) -> dict:
    text = _main(["analyze", "crosscal", str(READINGS), "--json", *extra])[0]
    return json.loads(text[text.index("{"):])


def _file_u(path: Path) -> tuple[list[str], np.ndarray]:
    text = path.read_text(encoding="utf-8")
    header = [line for line in text.splitlines() if line.startswith("#")]
    u = np.array([float(line.split(",")[2]) for line in text.splitlines() if line[:1].isdigit()])
    return header, u


@pytest.fixture(scope="module")
def certified(tmp_path_factory):
    """The sample's U from face 1 as the certificate states it with the sample's details (an
    autocollimator, U95 = 0.1″ per reading) and without any, from the CLI's JSON; the
    certificate's printed column; the files --table writes with and without --metadata."""
    out = tmp_path_factory.mktemp("xcalsend")
    meta = out / "meta.json"
    meta.write_text(json.dumps(_details()), encoding="utf-8")
    with_u = _json("--metadata", str(meta))
    bare = _json()
    _main(["analyze", "crosscal", str(READINGS), "--metadata", str(meta), "--table",
           str(out / "with.csv")])
    told = _main(["analyze", "crosscal", str(READINGS), "--table", str(out / "without.csv")])[1]
    document = KIND.certificate_document(KIND.analyze(*_parsed()), CertificateMetadata.from_dict(
        _details()), "crosscal_sample.csv", KIND.default_settings)
    column = [str(h) for h in document.results.header].index("U from face 1 (\")")
    printed = [float(row[column]) if any(c.isdigit() for c in str(row[column])) else 0.0
               for row in document.results.rows]
    return {"out": out, "u": np.asarray(with_u["polygon_deviation_U_from_face1_arcsec"]),
            "bare": np.asarray(bare["polygon_deviation_U_from_face1_arcsec"]),
            "d1": np.asarray(with_u["polygon_deviation_from_face1_arcsec"]),
            "k": with_u["coverage_factor"], "printed": np.asarray(printed), "told": told}


def _parsed():
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table

    rows = map_columns(read_table(READINGS), KIND.columns)
    return ReadingsSheet(KIND.columns, rows).parse(), KIND.default_settings


def test_the_sample_certifies_a_u_from_face1_with_the_autocollimators_u(certified):
    # what the tests rely on: the comparator's U is a large part of the certified U
    u, bare, k = certified["u"], certified["bare"], certified["k"]
    assert u[0] == 0.0 and bare[0] == 0.0
    assert 0.045 < u.max() < 0.055 and 0.02 < bare.max() < 0.035
    # the certificate prints the JSON's figures (two significant digits, rounded up, as
    # printed beside each figure: issue 39)
    d1 = certified["d1"]
    assert [f"{p:.3f}" for p in certified["printed"][1:]] == [
        u_beside(x, w) for x, w in zip(d1[1:], u[1:], strict=True)]
    # independently: the comparator's share is u_c·|G_i − G_1| through the design (its U
    # 0.1″ stated as "U95", k = 2: models/uncertainty/budget.py BASIS_DIVISORS)
    result = KIND.analyze(*_parsed())
    g = np.asarray(result.solution.gain, dtype=float)[result.faces:]
    through = np.sqrt(np.sum((g - g[0]) ** 2, axis=1))
    np.testing.assert_allclose(np.sqrt(u**2 - bare**2) / k, 0.1 / 2.0 * through,
                               rtol=1e-9, atol=1e-12)


def test_the_face_deviation_file_states_the_certificates_u_with_the_details(certified):
    header, u = _file_u(certified["out"] / "with.csv")
    np.testing.assert_allclose(u, np.round(certified["u"], 4), atol=1e-12)
    assert f"# U (k = {certified['k']:.2f}) from face 1 up to {certified['u'].max():.4f} arcsec: " \
           "enter it as the polygon standard's U stated from face 1" in header
    assert INCLUDED in header and not any("without" in line for line in header)
    # without --metadata: the readings' own U, said to leave the comparators out
    header, u = _file_u(certified["out"] / "without.csv")
    np.testing.assert_allclose(u, np.round(certified["bare"], 4), atol=1e-12)
    assert f"# {WITHOUT}" in header and INCLUDED not in header
    assert f"(from face 1, with U; {WITHOUT}) written to" in certified["told"]
    # the polygon workbench still reads both
    from models.polygon.certificate_reader import read_polygon_certificate

    for name in ("with.csv", "without.csv"):
        assert read_polygon_certificate(certified["out"] / name) == pytest.approx(
            {i + 1: round(x, 4) for i, x in enumerate(certified["d1"])}, abs=1e-12)


def _sent_standard(window, qtbot=None):
    """The polygon's standard stated from face 1, as its certificate details hold it and,
    given ``qtbot``, as the polygon's certificate dialog shows it in its standards table."""
    (standard,) = [s for s in window.certificates.details("polygon").standards
                   if s.applies_to == "from face 1"]
    if qtbot is not None:
        from widgets.certificate_dialog import _STANDARD_COLUMNS, CertificateDialog

        dialog = CertificateDialog(window.certificates.details("polygon"), window)
        qtbot.addWidget(dialog)
        table = dialog.standards
        cells = [{key: (table.item(r, c).text() if table.item(r, c) else "")
                  for c, key in enumerate(_STANDARD_COLUMNS)} for r in range(table.rowCount())]
        (shown,) = [row for row in cells if row["description"] == standard.description]
        assert float(shown["uncertainty"]) == standard.uncertainty
    return standard


def _send(window):
    from app.reference_sender import send_reference

    crosscal = window.presenter("crosscal")
    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    assert send_reference(window), window.told
    return window.presenter("polygon")


def test_the_window_sends_the_certified_u_from_face1(window, certified, tmp_path, qtbot):
    """The crosscal sample in the window with the sample's certificate details: the polygon
    workbench's reference column is d_i − d_1 and its standard's u the largest certified U
    from face 1 over k (0.050″ / k, not the 0.028″ / k sent before); the file saved from the
    window states the certified U."""
    crosscal = window.presenter("crosscal")
    crosscal.load_sample()
    window.certificates.store_details("crosscal", CertificateMetadata.from_dict(_details()))
    polygon = _send(window)
    n, k = crosscal.result.faces, certified["k"]
    column = polygon.sheet.column_index("polygon_dev_arcsec")
    got = np.array([float(polygon.sheet.text(r, column)) for r in range(n)])
    np.testing.assert_allclose(got, certified["d1"], atol=1e-6)
    standard = _sent_standard(window, qtbot)
    assert standard.basis == "u" and standard.uncertainty_unit == "arcsec"
    assert standard.uncertainty == pytest.approx(certified["u"].max() / k, abs=1e-6)
    assert standard.uncertainty > 1.5 * certified["bare"].max() / k
    assert f"{certified['u'].max():.4f}\" (k = {k:.2f})" in standard.description
    assert "without" not in standard.description
    assert "without" not in window.statusBar().currentMessage()
    # the face-deviation file saved from the window: the same U
    path = tmp_path / "faces.csv"
    assert crosscal.save_polygon_reference(str(path))
    header, u = _file_u(path)
    np.testing.assert_allclose(u, np.round(certified["u"], 4), atol=1e-12)
    assert INCLUDED in header


def test_lab_defaults_listing_the_autocollimator_are_the_certificates_too(window, certified):
    """No details typed for the cross-calibration yet: its certificate would start from the
    lab's defaults, the autocollimator with its U among them, and so does what is sent."""
    crosscal = window.presenter("crosscal")
    crosscal.load_sample()
    window.certificates.save_lab_defaults({"lab_name": "Lab",
                                           "standards": _details()["standards"]}, "crosscal")
    assert window.certificates.stored_details("crosscal") is None
    _send(window)
    standard = _sent_standard(window)
    assert standard.uncertainty == pytest.approx(certified["u"].max() / certified["k"],
                                                 abs=1e-6)


@pytest.mark.parametrize("standards", [None, [{"description": "Autocollimator AC-17",
                                               "serial": "AC-17"}]],
                         ids=["no details", "autocollimator without U"])
def test_without_a_comparators_u_what_is_sent_and_written_says_so(window, certified, tmp_path,
                                                                   standards, qtbot):
    """No details, or an autocollimator listed without its U: the certificate states the
    readings' own U from face 1, and so do the reference and the file, each saying that it
    leaves the comparators' calibration out (the standard's name on the polygon certificate,
    the window's message, the file's header and the status after saving)."""
    crosscal = window.presenter("crosscal")
    crosscal.load_sample()
    if standards is not None:
        details = CertificateMetadata.from_dict(_details(standards=standards))
        window.certificates.store_details("crosscal", details)
        # the certificate with these details states the readings' own U: nothing smaller sent
        stated = KIND.certified_json(crosscal.result, details, crosscal.result_settings)
        np.testing.assert_allclose(stated["polygon_deviation_U_from_face1_arcsec"],
                                   certified["bare"], rtol=1e-12)
    _send(window)
    standard = _sent_standard(window, qtbot)
    assert standard.uncertainty == pytest.approx(certified["bare"].max() / certified["k"],
                                                 abs=1e-6)
    assert standard.description.endswith(
        f"largest U of d_i − d_1 {certified['bare'].max():.4f}\" (k = {certified['k']:.2f}), "
        "without the comparators' calibration U: not stated")
    assert window.statusBar().currentMessage().endswith(f"restores the column; {WITHOUT}")
    path = tmp_path / "faces.csv"
    assert crosscal.save_polygon_reference(str(path))
    header, u = _file_u(path)
    np.testing.assert_allclose(u, np.round(certified["bare"], 4), atol=1e-12)
    assert f"# {WITHOUT}" in header
    assert WITHOUT in window.statusBar().currentMessage()


def test_a_cmc_and_no_comparators_u_are_both_named_within_a_standards_name(window, certified):
    """With the polygon's CMC 0.1″ set and no comparator's U: each U from face 1 but the
    first raised to the CMC, the name says both within the 200 characters a standard's name
    holds (a longer one made the polygon's stored details drop every standard unseen)."""
    crosscal = window.presenter("crosscal")
    crosscal.load_sample()
    crosscal.set_settings({**crosscal.settings, "cmc_arcsec": 0.1})
    _send(window)  # (the result is analysed again with the CMC before it is sent)
    standard = _sent_standard(window)
    assert standard.uncertainty == pytest.approx(0.1 / certified["k"], abs=1e-6)
    assert standard.description == (
        f"Polygon, 12 faces, cross-calibrated (closure principle); largest U of d_i − d_1 "
        f"0.1000\" (k = {certified['k']:.2f}), each ≥ the laboratory's CMC 0.1\", without the "
        "comparators' calibration U: not stated")


def test_a_standards_name_too_long_is_refused_not_dropped_unseen(window, monkeypatch):
    """A sent standard whose name the details cannot hold is told and nothing changes (the
    polygon's own standards and reference column kept), never stored to be dropped on
    reading back with every other standard."""
    from models.crosscal import analysis

    crosscal, polygon = window.presenter("crosscal"), window.presenter("polygon")
    crosscal.load_sample()
    window.certificates.store_details("polygon", CertificateMetadata.from_dict({
        "standards": [{"description": "Autocollimator", "uncertainty_arcsec": 0.1,
                       "basis": "U95"}]}))
    long = analysis.polygon_reference

    def too_long(result, *details):
        import dataclasses

        return dataclasses.replace(long(result, *details), standard_name="x" * 201)

    monkeypatch.setattr(type(KIND), "sent_reference", staticmethod(too_long))
    from app.reference_sender import send_reference

    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    assert not send_reference(window)
    assert "201 characters" in window.told[-1]
    assert [s.description for s in window.certificates.details("polygon").standards] == [
        "Autocollimator"]
    column = polygon.sheet.column_index("polygon_dev_arcsec")
    assert not any(polygon.sheet.text(r, column) for r in range(polygon.sheet.row_count))
