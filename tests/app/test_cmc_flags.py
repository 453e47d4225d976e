"""Where the laboratory's CMC raised a U, every output says so (the stop-61 notes N3, N4).

The theodolite sample with CMC 1.42″ sits across its budget: the raw error's U (1.41″) is
below it at every point but the reference, the corrected error's (up to 1.44″) at some. The
JSON flags each point's U raised (``uncertainty_raised_to_cmc_<name>``), names the CMC
(``laboratory_cmc``) and which half-width of the decided interval it raised; the DCC marks the
same points (a dcc:metaData's validXMLList on each quantity whose U the CMC holds). The flags
are checked against the U the same readings give without a CMC. And a calibration issued as
separate from a current certificate says so in its DCC (a statement naming it) and its XLSX.
"""

from __future__ import annotations

import contextlib
import io
import json
import re
from pathlib import Path

import numpy as np
import pytest
from lxml import etree
from openpyxl import load_workbook

from app.main import main
from models.dcc import vocabulary as v
from models.dcc.schema import validate
from tests.own_readings import own_readings

pytestmark = pytest.mark.slow  # certificates, DCCs and the JSON

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
NS = {"dcc": v.DCC_NAMESPACE, "si": v.SI_NAMESPACE}
CMC, T = 1.42, 3.0
SCHEMA = next((p / "shared" / "dcc" for p in ROOT.parents
               if (p / "shared" / "dcc" / "dcc.xsd").is_file()), None)


def _details(out: Path, **changes) -> Path:
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text(encoding="utf-8"))
    details.update(example=False, approver="Dr. Li", tolerance=T, decision_rule="guarded",
                   **changes)
    path = out / f"meta{len(list(out.glob('meta*')))}.json"
    path.write_text(json.dumps(details), encoding="utf-8")
    return path


def _main(args: list[str]) -> str:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


def _issue(args: list[str]) -> str:
    """What an issue says (on stdout or stderr)."""
    said = io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(said):
        assert main(args) == 0, said.getvalue()
    return said.getvalue()


def _json(kind: str, readings: Path, meta: Path, *extra: str) -> dict:
    text = _main(["analyze", kind, str(readings), "--metadata", str(meta), "--json", *extra])
    return json.loads(text[text.index("{"):])


@pytest.fixture(scope="module")
def theodolite(tmp_path_factory):
    out = tmp_path_factory.mktemp("cmcflags")
    mp = pytest.MonkeyPatch()
    mp.setenv("ANGLEBENCH_REGISTER", str(out / "register.sqlite"))
    try:
        meta = _details(out)
        readings = SAMPLES / "theodolite_sample.csv"
        plain = _json("theodolite", readings, meta)
        held = _json("theodolite", readings, meta, "--cmc-arcsec", f"{CMC:g}")
        points = _json("theodolite", readings, _details(out, decision_quantity="points"),
                       "--cmc-arcsec", f"{CMC:g}")
        points_plain = _json("theodolite", readings,
                             _details(out, decision_quantity="points"))
        _main(["analyze", "theodolite", str(readings), "--metadata", str(meta), "--cmc-arcsec",
               f"{CMC:g}", "--certificate", str(out / "c.pdf"), "--dcc", str(out / "c.xml")])
    finally:
        mp.undo()
    return {"plain": plain, "held": held, "points": points, "points_plain": points_plain,
            "dcc": (out / "c.xml").read_bytes()}


NAMES = ("raw_error_arcsec", "corrected_error_arcsec")


def test_each_points_u_raised_to_the_cmc_is_flagged_in_the_json(theodolite):
    plain, held = theodolite["plain"], theodolite["held"]
    for name in NAMES:
        computed = np.asarray(plain[f"expanded_uncertainty_{name}"])
        flags = np.asarray(held[f"uncertainty_raised_to_cmc_{name}"])
        assert flags.dtype == bool and flags.size == computed.size
        # raised exactly where the budget gives less than the CMC (not at the reference
        # point, whose error and U are zero by definition), and U there is the CMC
        assert np.array_equal(flags, (computed < CMC) & (computed > 0)), name
        assert np.array_equal(np.asarray(held[f"expanded_uncertainty_{name}"]),
                              np.where(flags, CMC, computed)), name
    raw = np.asarray(held["uncertainty_raised_to_cmc_raw_error_arcsec"])
    corrected = np.asarray(held["uncertainty_raised_to_cmc_corrected_error_arcsec"])
    assert raw.sum() == 40 and 0 < corrected.sum() < 40  # both kinds of point present
    # the model's U is not held to the CMC (a fit, not an error stated): all false
    assert not any(held["uncertainty_raised_to_cmc_model_error_arcsec"])
    # the existing keys keep their meaning: the same k, the same decided value
    for name in NAMES:
        assert held[f"coverage_factor_{name}"] == plain[f"coverage_factor_{name}"]
    assert held["decided_quantity"]["value"] == plain["decided_quantity"]["value"]
    assert held["laboratory_cmc"] == {"value": CMC, "unit": "arcsec", "quantity": "axis error",
                                      "setting": "cmc_arcsec", "arrays": list(NAMES)}


def test_without_a_cmc_nothing_is_said_of_one(theodolite):
    plain = theodolite["plain"]
    assert "laboratory_cmc" not in plain
    assert not [key for key in plain if key.startswith("uncertainty_raised_to_cmc_")]
    assert "raised_to_cmc" not in plain["decided_quantity"]


def test_the_decided_intervals_half_widths_raised_are_flagged(theodolite):
    plain, held = theodolite["plain"]["decided_quantity"], theodolite["held"]["decided_quantity"]
    x = plain["value"]
    low, high = x - plain["interval_low"], plain["interval_high"] - x
    # the sample's own interval: above the CMC on neither side (0.00 … 2.1″ about 0.95″)
    assert held["raised_to_cmc"] == {"low": low < CMC, "high": high < CMC}
    assert held["raised_to_cmc"]["high"] is True
    assert held["interval_high"] == pytest.approx(x + max(high, CMC), abs=1e-12)
    # every point deciding: the deciding point's U is both half-widths
    points, points_plain = theodolite["points"], theodolite["points_plain"]
    u_plain = (points_plain["decided_quantity"]["interval_high"]
               - points_plain["decided_quantity"]["value"])
    raised = u_plain < CMC
    assert points["decided_quantity"]["raised_to_cmc"] == {"low": raised, "high": raised}


def test_the_dcc_marks_the_same_points_with_the_cmc(theodolite):
    if SCHEMA is not None:
        assert validate(theodolite["dcc"], SCHEMA) == []
    dcc = etree.fromstring(theodolite["dcc"])
    held = theodolite["held"]
    marked = {}
    for q in dcc.xpath(".//dcc:quantity[dcc:measurementMetaData/dcc:metaData"
                       f"[@refType='{v.REFTYPE_U_RAISED_TO_CMC}']]", namespaces=NS):
        key = q.xpath("dcc:name/dcc:content[not(@lang)]/text()", namespaces=NS)[0]
        meta = q.find("dcc:measurementMetaData/dcc:metaData", NS)
        marked[key] = [x == "true" for x in meta.findtext("dcc:validXMLList", namespaces=NS)
                       .split()]
        assert float(meta.findtext(".//si:value", namespaces=NS)) == CMC
        assert meta.findtext(".//si:unit", namespaces=NS) == r"\arcsecond"
        said = meta.findtext("dcc:declaration/dcc:content[@lang='en']", namespaces=NS)
        assert f"U = 1.42\" holds this quantity's U. At the {sum(marked[key])} of the 41 " \
               "points marked true" in said
        # U and k beside it: U is the CMC where marked, k the point's coverage factor
        u = np.array(q.findtext(".//si:valueExpandedMUXMLList", namespaces=NS).split(), float)
        assert np.all(u[np.array(marked[key])] == CMC)
    assert set(marked) == set(NAMES)  # the model's U is not the CMC's: not marked
    for name in NAMES:
        assert marked[name] == held[f"uncertainty_raised_to_cmc_{name}"], name


def test_a_separate_calibration_is_a_dcc_statement_and_xlsx_rows(tmp_path):
    mp = pytest.MonkeyPatch()
    mp.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    readings = SAMPLES / "theodolite_sample.csv"
    meta = _details(tmp_path, certificate_number="", language="zh+en")
    try:
        first = _issue(["analyze", "theodolite", str(readings), "--metadata", str(meta),
                        "--certificate", str(tmp_path / "a.pdf")])
        # as left after the adjustment: readings of its own (the same readings and details
        # are the first calibration issued again, refused: register79)
        as_left = own_readings(readings, "as left", tmp_path / "as_left")
        _main(["analyze", "theodolite", str(as_left), "--metadata", str(meta),
               "--certificate", str(tmp_path / "b.pdf"), "--dcc", str(tmp_path / "b.xml"),
               "--results", str(tmp_path / "b.xlsx"),
               "--separate-calibration", "as left after the adjustment"])
    finally:
        mp.undo()
    number = re.search(r"[A-Z]+-\d{4}-\d{4}", first).group(0)  # the register's number
    xml = (tmp_path / "b.xml").read_bytes()
    if SCHEMA is not None:
        assert validate(xml, SCHEMA) == []
    dcc = etree.fromstring(xml)
    (st,) = dcc.xpath(".//dcc:statements/dcc:statement"
                      f"[@refType='{v.REFTYPE_SEPARATE_CALIBRATION}']", namespaces=NS)
    assert st.xpath("dcc:reference/text()", namespaces=NS) == [number]
    en = st.findtext("dcc:declaration/dcc:content[@lang='en']", namespaces=NS)
    zh = st.findtext("dcc:declaration/dcc:content[@lang='zh']", namespaces=NS)
    assert en == (f"A calibration of its own, separate from certificate {number} of the same "
                  "item and date of calibration, which stays valid: as left after the "
                  f"adjustment; readings changed from those of {number}: row(s) 1–41 (41 rows "
                  "there, 41 here)")
    assert f"证书 {number}" in zh and "仍然有效" in zh
    assert dcc.xpath(".//dcc:coreData/dcc:reportAmendedSubstituted", namespaces=NS) == []
    sheet = load_workbook(tmp_path / "b.xlsx")["Certificate"]
    rows = {row[0]: row[1] for row in sheet.iter_rows(values_only=True) if row and row[0]}
    # a bilingual certificate's labels: the Chinese, a space, the English
    assert rows["独立校准，有别于以下证书（仍然有效） Separate calibration from certificate(s), "
                "which stay valid"] == number
    # why, and what it changes against the other (its readings: readings of its own)
    assert rows["作为独立校准的理由 Why it is a calibration of its own"] == (
        f"as left after the adjustment；读数与 {number} 的不同：第 1–41 行（那里 41 行，这里 41 行）\n"
        f"as left after the adjustment; readings changed from those of {number}: row(s) 1–41 "
        "(41 rows there, 41 here)")


def test_the_polygons_per_set_arrays_flag_their_own_points(tmp_path):
    """The polygon's arrays of every set (a budget per set, concatenated) carry the flags of
    each set's own budget; the pyramidal correction's own U is not held to the CMC."""
    cmc = 0.3
    meta = SAMPLES / "certificate_polygon.json"
    readings = SAMPLES / "polygon_sample.csv"
    plain = _json("polygon", readings, meta)
    held = _json("polygon", readings, meta, "--cmc-arcsec", f"{cmc:g}")
    for name in ("error_arcsec", "corrected_error_arcsec", "mean_corrected_error_arcsec"):
        computed = np.asarray(plain[f"expanded_uncertainty_{name}"])
        flags = np.asarray(held[f"uncertainty_raised_to_cmc_{name}"])
        assert np.array_equal(flags, (computed < cmc) & (computed > 0)), name
        assert flags.any(), name
        assert np.array_equal(np.asarray(held[f"expanded_uncertainty_{name}"]),
                              np.where(flags, cmc, computed)), name
    assert not any(held["uncertainty_raised_to_cmc_pyramidal_error_arcsec"])
    assert held["laboratory_cmc"]["arrays"] == ["error_arcsec", "corrected_error_arcsec",
                                                "mean_corrected_error_arcsec"]
