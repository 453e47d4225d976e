"""The laboratory's CMC holds the coverage intervals of the ISO 230-2 / VDI/DGQ 3441 figures
too (ILAC-P14:09/2020 5.4: no U stated below the CMC), in every output of one issue.

A positioning test (a rotary axis, the standard test cycle simulated from first principles
in tests/reversal_simulator.py: 12 targets, 5 runs, repeatability 0.04″) and a theodolite
run with passes (tests/theodolite_passes_simulator.py: 5 passes each way, pointing 0.05″)
give every figure an interval a few tenths of an arcsecond wide; issued with a CMC of 2″
above every half-width, each figure's interval is value ± CMC at least (its lower end not
below 0 where the figure cannot be negative) in the JSON, each object says which half-width
was raised, the certificate's scope statement names the figures, and the PDF's figures table,
the XLSX's Statistics sheet and the DCC state the same ends. Without a CMC the intervals are
the readings' own, unmarked.
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
from openpyxl import load_workbook

from app.main import main
from models.dcc import vocabulary as v
from tests.pdf_text import pdf_text as _pdf_text
from tests.reversal_simulator import readings_rows
from tests.theodolite_passes_simulator import passes_record

pytestmark = pytest.mark.slow  # certificates, DCCs and the JSON of two workbenches

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
NS = {"dcc": v.DCC_NAMESPACE, "si": v.SI_NAMESPACE}
CMC = 2.0
#: figures that may be negative (B̄): the others' lower end is not below 0
SIGNED = {"B_mean"}


def _main(args: list[str]) -> str:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


def _json(args: list[str]) -> dict:
    text = _main([*args, "--json", "--language", "en"])
    return json.loads(text[text.index("{"):])


def _issue(out: Path, kind: str, readings: Path, details: dict, cmc_flag: str) -> dict:
    meta = out / f"{kind}.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    common = ["analyze", kind, str(readings), "--metadata", str(meta)]
    plain = _json(common)
    held = _json([*common, cmc_flag, f"{CMC:g}"])
    _main([*common, cmc_flag, f"{CMC:g}", "--language", "en", "--certificate",
           str(out / f"{kind}.pdf"), "--dcc", str(out / f"{kind}.xml"), "--results",
           str(out / f"{kind}.xlsx")])
    return {"plain": plain, "held": held, "pdf": _pdf_text((out / f"{kind}.pdf").read_bytes()),
            "dcc": etree.parse(str(out / f"{kind}.xml")),
            "xlsx": load_workbook(out / f"{kind}.xlsx")}


@pytest.fixture(scope="module")
def issued(tmp_path_factory):
    out = tmp_path_factory.mktemp("cmc_figures")
    mp = pytest.MonkeyPatch()
    mp.setenv("ANGLEBENCH_REGISTER", str(out / "register.sqlite"))
    rng = np.random.default_rng(20261206)
    try:
        # positioning: an even reversal of 0.5″ (± 0.1″) over 12 targets, 5 runs each way
        # (repeatability 0.04″: P's interval holds the band μ ± (|β|/2 + 3σ̄) each target's
        # own 5 runs allow, and at 0.05″ it was 2.2″ wide, above the CMC)
        reversal = 0.5 + 0.1 * rng.standard_normal(12)
        rows = readings_rows(reversal, 0.04, 5, rng)
        positioning = out / "positioning.csv"
        positioning.write_text("target,run,direction,deviation\n" + "".join(
            ",".join(row[:4]) + "\n" for row in rows), encoding="utf-8")
        details = json.loads((SAMPLES / "certificate_positioning.json").read_text(
            encoding="utf-8"))
        details.update(example=False, certificate_number="AB-2026-0901")
        details["standards"][0].update(uncertainty=0.02)
        found = {"positioning": _issue(out, "positioning", positioning, details, "--cmc")}
        # theodolite: 5 passes each way, pointing 0.05″, a reversal of 0.3″ (R's interval
        # holds the largest σ a θ's own passes allow: with 3 passes and 0.1″ it was 3.6″
        # wide, above the CMC)
        theodolite = out / "theodolite.csv"
        passes_record(theodolite, rng, 5, 0.05, 0.3)
        details = json.loads((SAMPLES / "certificate_theodolite.json").read_text(
            encoding="utf-8"))
        details.update(example=False, certificate_number="AB-2026-0902", approver="Dr. Li")
        details["standards"][0].update(uncertainty=0.05)  # u per reading: the pointing noise
        found["theodolite"] = _issue(out, "theodolite", theodolite, details, "--cmc-arcsec")
    finally:
        mp.undo()
    return found


def _printed(figure: dict) -> str:
    """An interval's ends as printed to the decimal of U = 2.0″ (GUM 7.2.6): each rounded
    outwards from the JSON's (the lower down, the upper up: the printed interval holds the
    computed one)."""
    low = math.floor(round(figure["interval_low"] * 10, 9)) / 10 + 0.0
    high = math.ceil(round(figure["interval_high"] * 10, 9)) / 10 + 0.0
    return f"{low:.1f}\" … {high:.1f}\""


def _figures(data: dict) -> dict[str, dict]:
    out = dict(data["iso230_2_figures"])
    out.update(data.get("vdi3441_figures", {}))
    return {k: f for k, f in out.items() if f["interval_low"] is not None}


@pytest.mark.parametrize("kind", ["positioning", "theodolite"])
def test_every_figures_interval_is_held_to_the_cmc_in_the_json(issued, kind):
    plain, held = _figures(issued[kind]["plain"]), _figures(issued[kind]["held"])
    assert len(held) >= (10 if kind == "positioning" else 6)
    assert held.keys() == plain.keys()
    for key, before in plain.items():
        after = held[key]
        value = before["value"]
        # the readings' own half-widths are below the CMC (the case of the issue)
        assert before["interval_high"] - before["interval_low"] < CMC, key
        assert after["value"] == value, key
        assert after["coverage_probability"] == before["coverage_probability"], key
        assert after["interval_high"] == pytest.approx(value + CMC, abs=1e-12), key
        low = value - CMC if key in SIGNED else max(value - CMC, 0.0)
        assert after["interval_low"] == pytest.approx(low, abs=1e-12), key
        assert after["interval_low"] <= before["interval_low"], key
        assert after["raised_to_cmc"] == {"low": True, "high": True}, key
        assert "raised_to_cmc" not in before, key  # without a CMC nothing is said


@pytest.mark.parametrize("kind", ["positioning", "theodolite"])
def test_the_certificate_names_the_figures_raised_and_prints_their_intervals(issued, kind):
    pdf = issued[kind]["pdf"]
    held = _figures(issued[kind]["held"])
    statement = re.search(r"The coverage interval of (.+?) is held to it as well", pdf)
    assert statement, pdf[pdf.find("calibration and measurement capability"):][:600]
    named = {name.strip() for name in statement.group(1).split(",")}
    assert named == set(held), named ^ set(held)
    # the figures table prints each interval held, to the decimal of U = 2.0″
    for key, figure in held.items():
        printed = _printed(figure)
        assert printed in pdf, (key, printed)


def _dcc_figures(dcc) -> dict[str, dict | str]:
    """The statistics table's rows in the DCC: a figure with its interval as a dcc:list
    (value, intervalMin, intervalMax, p: the positioning's), another row as its English
    text (the theodolite's "1.0\" — coverage interval 0.0\" … 3.0\" (92.00 %)")."""
    out: dict[str, dict | str] = {}
    for result in dcc.xpath(f".//dcc:result[@refType='{v.REFTYPE_SUMMARY}']", namespaces=NS):
        for lst in result.xpath(".//dcc:list", namespaces=NS):
            out[lst.findtext("dcc:name/dcc:content", namespaces=NS)] = {
                q.findtext("dcc:name/dcc:content", namespaces=NS):
                    float(q.findtext(".//si:value", namespaces=NS))
                for q in lst.findall("dcc:quantity", namespaces=NS)}
        for q in result.xpath(".//dcc:quantity[dcc:noQuantity]", namespaces=NS):
            out[q.findtext("dcc:name/dcc:content", namespaces=NS)] = q.findtext(
                "dcc:noQuantity/dcc:content[@lang='en']", namespaces=NS)
    return out


@pytest.mark.parametrize("kind", ["positioning", "theodolite"])
def test_the_dcc_and_the_xlsx_state_the_same_intervals_as_the_json(issued, kind):
    held = _figures(issued[kind]["held"])
    stated = _dcc_figures(issued[kind]["dcc"])
    # the DCC's statements carry the certificate's, naming the figures raised
    assert b"is held to it as well" in etree.tostring(issued[kind]["dcc"])
    sheet = issued[kind]["xlsx"]["Statistics"]
    cells = [" ".join(str(c) for c in row if c is not None)
             for row in sheet.iter_rows(values_only=True)]
    for key, figure in held.items():
        match = [said for name, said in stated.items()
                 if re.match(rf"^(ISO 230-2 )?{re.escape(key)}(:|$)", name)]
        assert len(match) == 1, (key, sorted(stated))
        # the ends to the decimal of U = 2.0″ as printed (GUM 7.2.6)
        printed = _printed(figure)
        if isinstance(match[0], dict):  # at full precision, held to the CMC
            assert match[0]["intervalMax"] >= match[0]["value"] + CMC - 1e-9, key
            assert match[0]["intervalMin"] == pytest.approx(figure["interval_low"], abs=1e-9)
            assert match[0]["intervalMax"] == pytest.approx(figure["interval_high"], abs=1e-9)
        else:
            assert printed in match[0], (key, match[0])
        row = [c for c in cells if re.match(rf"^(ISO 230-2 )?{re.escape(key)}(:| )", c)]
        assert len(row) == 1, (key, cells)
        # the ends as numbers (positioning) or in the row's text (theodolite), as printed
        numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?", row[0])]
        for end in (figure["interval_low"], figure["interval_high"]):
            assert any(abs(x - end) < 0.1 + 1e-9 for x in numbers), (key, end, row[0])
