"""What the DCC's uncertainties are, machine-readably (assessment of 0.8.10, F4, F11, F14,
F15): the budget's u_c and U each under their own refType, U with its k and p; a reference
standard's stated uncertainty in D-SI form (U with k and p, u, or a maximum permissible
error as an interval), named in each language; the raw error's U one rule on every
workbench, said beside it; no "-0"; one coverage probability; the command line's polygon
summary not passing for the certificate's decision.

Every figure checked here is recomputed from what the test reads itself (the JSON, the
readings' own budget table in the DCC, math.erf), not from the writer's code.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest
from lxml import etree
from scipy import stats

from app.main import main
from models.dcc import vocabulary as v
from models.dcc.reader import read_polygon_dcc, read_standard_dcc
from tests.app.test_dcc_out import CASES, NS, SCHEMA, _curve, _issue
from tests.app.writers.test_certificate_chinese import SYMBOLS, WORD

pytestmark = pytest.mark.slow  # each case prints a certificate

#: k = 2's coverage probability for a normal distribution, as the DCC writes it (12 digits)
P_K2 = float(f"{math.erf(2.0 / math.sqrt(2.0)):.12g}")
WRITTEN_0_8_10 = Path(__file__).resolve().parents[1] / "models" / "dcc" / "written_0_8_10"


def _details(samples: Path, out: Path) -> Path:
    """The polygon's sample details with the autocollimator stated as a maximum permissible
    error ±0.3" for any angle between two readings."""
    data = json.loads((samples / "certificate_polygon.json").read_text("utf-8"))
    data["standards"][1].update(uncertainty=0.3, basis="MPE", applies_to="angle")
    path = out / "certificate_polygon_mpe.json"
    path.write_text(json.dumps(data, ensure_ascii=False), "utf-8")
    return path


@pytest.fixture(scope="module")
def issued(tmp_path_factory, issued_samples):
    """theodolite, polygon, fringe, positioning and a polygon with an MPE: (DCC tree, JSON,
    DCC path, what the command line said). The four samples as issued once a run for every
    DCC test (tests/conftest.py's ``issued_samples``); the polygon with an MPE issued here."""
    from tests.conftest import SAMPLES

    results = {}
    for case in ("theodolite", "polygon", "fringe", "positioning"):
        code, said, _, xml, _, data = issued_samples[case]
        assert code == 0, said
        results[case] = (etree.parse(str(xml)).getroot(), data, xml, said)
    out = tmp_path_factory.mktemp("dcc_semantics")
    mp = pytest.MonkeyPatch()
    mp.setenv("ANGLEBENCH_REGISTER", str(out / "register.sqlite"))

    class Capture:
        def readouterr(self):
            return type("C", (), {"out": "", "err": ""})()

    try:
        details = _details(SAMPLES, out)
        kind, readings, meta, options = CASES["polygon"]
        where = out / "polygon_mpe"
        where.mkdir()
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer), contextlib.redirect_stderr(buffer):
            code, _, _, xml = _issue("polygon", where, Capture(), SAMPLES, details=details)
        said = buffer.getvalue()
        assert code == 0, said
        buffer = io.StringIO()
        with contextlib.redirect_stdout(buffer):
            main(["analyze", kind, str(SAMPLES / readings), "--json", "--metadata",
                  str(details), *options])
        results["polygon_mpe"] = (etree.parse(str(xml)).getroot(), json.loads(buffer.getvalue()),
                                  xml, said)
    finally:
        mp.undo()
    return results


def _value(q) -> float:
    return float(q.findtext("si:real/si:value", namespaces=NS))


def _names(q) -> dict[str | None, str]:
    return {c.get("lang"): c.text for c in q.iterfind("dcc:name/dcc:content", NS)}


# -- F4: the budget's u_c and U ---------------------------------------------------------
def test_the_budgets_u_c_and_u_have_their_own_reftypes_and_u_its_k_and_p(issued):
    """u_c was tagged anglebench_expandedUncertainty like U (a consumer filtering on the
    refType got two "expanded" values); U's k was in no element."""
    for case in ("theodolite", "polygon", "fringe", "positioning"):
        tree = issued[case][0]
        budget = tree.find(f".//dcc:result[@refType='{v.REFTYPE_BUDGET}']", NS)
        assert budget is not None, case

        def one(ref: str, case=case, budget=budget) -> float:
            found = budget.findall(f".//dcc:quantity[@refType='{ref}']", NS)
            assert len(found) == 1, (case, ref, len(found))
            return _value(found[0])

        u_c = one("anglebench_combinedStandardUncertainty")
        big_u = one("anglebench_expandedUncertainty")
        k = one("anglebench_coverageFactor")
        p = one("anglebench_coverageProbability")
        assert big_u == pytest.approx(k * u_c, rel=1e-10), case
        assert p == P_K2, case
    # the theodolite's from its JSON: the budget is at the point of the largest U
    data = issued["theodolite"][1]
    big_us = np.asarray(data["expanded_uncertainty_corrected_error_arcsec"], float)
    ks = np.broadcast_to(np.asarray(data["coverage_factor_corrected_error_arcsec"], float),
                         big_us.shape)
    i = int(np.argmax(big_us))
    budget = issued["theodolite"][0].find(f".//dcc:result[@refType='{v.REFTYPE_BUDGET}']", NS)
    figures = {q.get("refType"): _value(q) for q in budget.iterfind(".//dcc:quantity", NS)
               if q.get("refType") != "anglebench_budgetComponent"}
    assert figures["anglebench_expandedUncertainty"] == pytest.approx(big_us[i], rel=1e-10)
    assert figures["anglebench_coverageFactor"] == pytest.approx(ks[i], rel=1e-10)
    assert figures["anglebench_combinedStandardUncertainty"] == pytest.approx(
        big_us[i] / ks[i], rel=1e-10)  # 0.718"


# -- F4, F14: the standards' stated uncertainties -----------------------------------------
def _standards(tree) -> list:
    return tree.findall(f".//dcc:measuringEquipmentQuantity[@refType='{v.REFTYPE_STANDARD_U}']",
                        NS)


def test_a_standards_stated_uncertainty_is_d_si_with_its_k_named_in_each_language(issued):
    """Up to 0.8.10: the figure alone as a value (no k), the theodolite's standard
    uncertainty u under a refType "…ExpandedUncertainty", named "(u, per reading)" and in
    Chinese "（u，每 reading）"."""
    # theodolite: u = 0.5" per reading (certificate_theodolite.json)
    (q,) = _standards(issued["theodolite"][0])
    assert _names(q) == {"en": "standard uncertainty u per reading", "zh": "每个读数的标准不确定度 u"}
    assert _value(q) == 0.0 and q.findtext("si:real/si:unit", namespaces=NS) == r"\arcsecond"
    mu = q.find("si:real/si:measurementUncertaintyUnivariate", NS)
    assert [_local(e.tag) for e in mu] == ["standardMU"]
    assert float(mu.findtext("si:standardMU/si:valueStandardMU", namespaces=NS)) == 0.5
    # polygon: U95 0.2" per face from face 1, the autocollimator's U95 0.1" per reading
    polygon, autocollimator = _standards(issued["polygon"][0])
    assert _names(polygon) == {"en": "expanded uncertainty U (k = 2) per face, stated from face 1",
                               "zh": "每个面，以第 1 面为基准给出的扩展不确定度 U（k = 2）"}
    assert _names(autocollimator) == {"en": "expanded uncertainty U (k = 2) per reading",
                                      "zh": "每个读数的扩展不确定度 U（k = 2）"}
    for q, big_u in ((polygon, 0.2), (autocollimator, 0.1)):
        assert _value(q) == 0.0
        e = q.find("si:real/si:measurementUncertaintyUnivariate/si:expandedMU", NS)
        assert float(e.findtext("si:valueExpandedMU", namespaces=NS)) == big_u
        assert float(e.findtext("si:coverageFactor", namespaces=NS)) == 2.0
        assert float(e.findtext("si:coverageProbability", namespaces=NS)) == P_K2
    # an MPE ±0.3" for any angle between two readings: −0.3 … +0.3, p = 1, u = a/√3
    _, mpe = _standards(issued["polygon_mpe"][0])
    assert _names(mpe) == {"en": "maximum permissible error ±a per angle between two readings",
                           "zh": "每个角度（任意两个读数之间）的最大允许误差 ±a"}
    e = mpe.find("si:real/si:measurementUncertaintyUnivariate/si:coverageIntervalMU", NS)
    assert [float(e.findtext(f"si:{x}", namespaces=NS))
            for x in ("intervalMin", "intervalMax", "coverageProbability")] == [-0.3, 0.3, 1.0]
    assert float(e.findtext("si:valueStandardMU", namespaces=NS)) == pytest.approx(
        0.3 / math.sqrt(3.0), rel=1e-11)
    assert e.findtext("si:distribution", namespaces=NS) == "rectangular"
    # no English word of ours in any standard's Chinese name
    for case, (tree, *_) in issued.items():
        for q in _standards(tree):
            assert not set(WORD.findall(_names(q)["zh"])) - SYMBOLS, (case, _names(q))


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def test_a_standards_dcc_read_back_gives_its_results_u_not_a_standard_it_used(issued, tmp_path):
    """The standards' U is now si:expandedMU inside measuringEquipments: reading a DCC as a
    standard's certificate takes the largest U of its results only, never the U of a
    standard that calibrated it (here set to 50")."""
    xml = issued["polygon"][2]
    before = read_standard_dcc(xml, SCHEMA)
    tree = etree.parse(str(xml))
    value = tree.find(f".//dcc:measuringEquipmentQuantity[@refType='{v.REFTYPE_STANDARD_U}']"
                      "//si:valueExpandedMU", NS)
    value.text = "50"
    changed = tmp_path / "polygon_with_a_50_arcsec_standard.xml"
    tree.write(str(changed), xml_declaration=True, encoding="UTF-8")
    after = read_standard_dcc(changed, SCHEMA)
    assert after.uncertainty == before.uncertainty
    assert after.coverage_factor == before.coverage_factor


def test_dccs_written_by_0_8_10_are_still_read():
    """The reader's forms are unchanged: a 0.8.10 cross-calibration DCC gives its polygon,
    a 0.8.10 theodolite DCC its id and U (embedded PDFs left out of the stored copies)."""
    polygon = read_polygon_dcc(WRITTEN_0_8_10 / "crosscal.xml", SCHEMA)
    assert polygon.faces == 12 and polygon.certificate_id == "AB-2026-0008"
    assert polygon.deviations[1] == 0.0 and polygon.deviations[2] == pytest.approx(0.230039367414)
    assert polygon.expanded_uncertainty[2] == pytest.approx(0.0467585686758)
    standard = read_standard_dcc(WRITTEN_0_8_10 / "theodolite.xml", SCHEMA)
    assert standard.certificate_id == "AB-2026-0002"
    # the largest U/k of its errors (the corrected error's first point, U/k 0.7182"), not
    # of its set-up parameters (the tilt direction α's 59", k = 2.07, taken up to 0.8.11)
    assert standard.uncertainty == 1.4364763721 and standard.coverage_factor == 2.00006199355
    assert "not used: Set-up parameters identified" in standard.notes[-1]


# -- F11: the raw error's U, one rule ----------------------------------------------------
_NOTE = ("U of the raw error: the certificate's budget without the inputs of the correction "
         "that the raw error is before (")
_SET_UP = ("Pyramidal correction (ψ, ω)", "Pyramidal tilt, not identified (bound)",
           "Autocollimator roll ρ (cross-talk ρ·(y − y_z))")


def _raw_description(tree, column: str) -> str:
    q = next(q for q in tree.iterfind(".//dcc:result[@refType='anglebench_curve']"
                                      "//dcc:quantity", NS)
             if q.findtext("dcc:name/dcc:content[last()]", namespaces=NS) == column)
    found = q.find("dcc:description/dcc:content[@lang='en']", NS)
    return "" if found is None else found.text


def test_the_raw_errors_u_is_one_rule_said_in_every_dcc_and_the_jsons(issued):
    """Theodolite and fringe stated the raw error's U (the budget without the set-up model,
    without the compensation's model) with no word of it; the polygon said its own."""
    for case, column, inputs in (("theodolite", "raw_error_arcsec", ("Set-up model ζ (ψ, α, β)",)),
                                 ("fringe", "raw_error_arcsec",
                                  ("Fitted model (correction table)",)),
                                 ("polygon", "raw_error_arcsec", _SET_UP)):
        text = _raw_description(issued[case][0], column)
        assert text.startswith(_NOTE), (case, text)
        assert all(f"“{name}”" in text for name in inputs), (case, text)
    for case in ("theodolite", "fringe"):  # the DCC's U and k are the JSON's
        tree, data, *_ = issued[case]
        raw = _curve(tree)["raw_error_arcsec"]
        assert raw["U"] == pytest.approx(data["expanded_uncertainty_raw_error_arcsec"], rel=1e-10)
        assert raw["k"] == pytest.approx(np.broadcast_to(
            data["coverage_factor_raw_error_arcsec"], raw["k"].shape), rel=1e-10)


def _budget_rows(tree) -> list[tuple[str, float, float]]:
    """(name, c·u, ν) of each input of the DCC's budget table."""
    budget = tree.find(f".//dcc:result[@refType='{v.REFTYPE_BUDGET}']", NS)
    rows = []
    for q in budget.iterfind(".//dcc:quantity[@refType='anglebench_budgetComponent']", NS):
        dof = re.search(r"dof (\S+)$", q.findtext("dcc:description/dcc:content", namespaces=NS))
        rows.append((_names(q)["en"], _value(q), float(dof.group(1))))
    return rows


def test_the_polygons_raw_error_u_leaves_out_every_input_of_the_set_up(issued):
    """The polygon's raw error (before the pyramidal correction) had the autocollimator's
    roll in its U, an input of the set-up's error that the correction removes (as the
    theodolite's raw error has no set-up model input): its u_c recomputed at the budget's
    point from the DCC's own budget table, without the set-up's inputs."""
    tree = issued["polygon"][0]
    curve = _curve(tree)
    raw, corrected = curve["raw_error_arcsec"], curve["corrected_error_arcsec"]
    i = int(np.argmax(corrected["U"]))  # the budget's point
    rows = _budget_rows(tree)
    kept = [(c, nu) for name, c, nu in rows if name not in _SET_UP]
    roll = [c for name, c, _ in rows if name == _SET_UP[2]]
    assert roll and roll[0] > 0.05  # the sample's roll bound (1′, not measured) counts here
    u_c = math.sqrt(sum(c * c for c, _ in kept))
    assert raw["U"][i] / raw["k"][i] == pytest.approx(u_c, rel=1e-9)  # 0.169"
    # k for ν_eff of the inputs kept (of the order of 10⁴ here: k within 2.0000…2.001)
    nu = min((nu for _, nu in kept), default=math.inf)
    assert 2.0 <= raw["k"][i] <= stats.t.ppf(0.5 * (1.0 + P_K2), nu)
    assert raw["U"][i] < corrected["U"][i] - 0.01


# -- F15 ---------------------------------------------------------------------------------
def test_no_minus_zero_and_one_coverage_probability(issued):
    """The theodolite's raw error at its reference point was written "-0"; the positioning
    figures' intervals read their p off the printed "95.45 %" (0.9545) beside 0.954499736104
    everywhere else."""
    tree = issued["theodolite"][0]
    words = [w for e in tree.iter(f"{{{v.SI_NAMESPACE}}}*") if e.text for w in e.text.split()]
    assert "-0" not in words and "0" in words
    tree = issued["positioning"][0]
    stated = [_value(q) for q in tree.iterfind(
        ".//dcc:quantity[@refType='anglebench_coverageProbability']", NS)]
    stated += [float(e.text) for e in tree.iter(f"{{{v.SI_NAMESPACE}}}coverageProbability",
                                                f"{{{v.SI_NAMESPACE}}}coverageProbabilityXMLList")]
    assert 0.9545 not in stated and stated.count(P_K2) >= 6
    for name in ("R: ", "B: ", "Ps_max: ", "U_max: "):
        lst = next(lst for lst in tree.iterfind(".//dcc:list[@refType='anglebench_summaryFigure']",
                                                NS)
                   if lst.findtext("dcc:name/dcc:content", namespaces=NS).startswith(name))
        p = lst.find("dcc:quantity[@refType='anglebench_coverageProbability']", NS)
        assert _value(p) == P_K2, name


def test_the_polygon_summary_says_its_grade_check_is_not_the_certificates_decision(issued):
    """"ω = 120.0° ± 0.00°" (a u of zero) and "accuracy ±1" met (rule: half the
    peak-to-peak ≤ accuracy)" under a certificate decided by the guarded rule."""
    said, data = issued["polygon"][3], issued["polygon"][1]
    assert not re.search(r"± 0\.0*[\"°]", said) and "accuracy ±1\" met" not in said
    line = next(x for x in said.splitlines() if x.startswith("Corrected error"))
    assert line.endswith("half the peak-to-peak is within the grade's ±1\", U left out — not a "
                         "statement of conformity (a certificate decides with U, by the rule in "
                         "its details)")
    first = next(x for x in said.splitlines() if x.startswith("  set 1 "))
    found = re.search(r"ψ = (\S+)\" ± (\S+)\", ω = (\S+)° ± (\S+)° \(u, k = 1\)", first)
    assert found, first
    for value, u, exact in ((found[1], found[2], data["pyramidal_tilt_arcsec"]),
                            (found[3], found[4], data["pyramidal_direction_deg"])):
        decimals = len(u.partition(".")[2])
        assert float(u) > 0 and 10 <= float(u) * 10**decimals < 100  # two significant digits
        assert value == f"{float(np.ravel(exact)[0]):.{decimals}f}"


# -- F14: no English of ours in the Chinese ----------------------------------------------
def _typed_words(samples: Path) -> set[str]:
    """The words the laboratory typed in the sample details (names, grades, addresses): a
    DCC gives them as typed, in each language."""
    words: set[str] = set()
    for path in samples.glob("certificate_*.json"):
        stack = [json.loads(path.read_text("utf-8"))]
        while stack:
            item = stack.pop()
            if isinstance(item, dict):
                stack.extend(item.values())
            elif isinstance(item, list):
                stack.extend(item)
            elif isinstance(item, str):
                words |= set(WORD.findall(item))
    return words


def test_every_chinese_text_of_a_dcc_is_chinese_but_for_what_was_typed(issued):
    """"给定的不确定度（U95，每 from face 1）" (a key put into a sentence untranslated), the
    budget's point "position 9" and the settings "faces n: from the readings; …" in English
    only: every dcc:content in Chinese holds no English word but the laboratory's own
    (its details), symbols and element names. The DCC's texts take their Chinese from
    resources/translations (the window's catalogue)."""
    from tests.conftest import SAMPLES

    allowed = SYMBOLS | _typed_words(SAMPLES) | {
        "PDF", "SPECIMEN", "measuringEquipments", "Tian",  # a format, a number, a name, a cite
        "commit", "local", "changes"}  # the software's source: "commit 65fbc7d1… + local changes"
    for case, (tree, *_) in issued.items():
        for content in tree.iter(f"{{{v.DCC_NAMESPACE}}}content"):
            if content.get("lang") == "zh":
                words = set(WORD.findall(content.text or "")) - allowed
                assert not words, (case, content.getparent().tag, content.text[:120], words)


def test_the_budgets_point_and_the_settings_are_in_each_language(issued):
    tree = issued["polygon"][0]
    corrected = _curve(tree)["corrected_error_arcsec"]
    position = int(np.argmax(corrected["U"])) + 1  # the budget's point: the largest U
    budget = tree.find(f".//dcc:result[@refType='{v.REFTYPE_BUDGET}']", NS)
    said = {c.get("lang"): c.text for c in budget.iterfind("dcc:description/dcc:content", NS)}
    assert said == {"en": f"position {position}", "zh": f"第 {position} 位置"}
    method = tree.find(".//dcc:usedMethod", NS)
    said = {c.get("lang"): c.text for c in method.iterfind("dcc:description/dcc:content", NS)}
    assert said["en"].startswith("faces n: from the readings; encoder grade: grade 3: ±1\"; "
                                 "closure limits grades 1–7 (\"): 0.125, 0.25")
    assert said["zh"].startswith("面数 n: 由读数确定; 编码器等级: 3 级：±1\"; ")
    assert "(\"): 0.125, 0.25" in said["zh"] and "closure" not in said["zh"]
