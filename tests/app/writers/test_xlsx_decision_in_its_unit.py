"""A results workbook in another unit than the certificate's states the certificate's one
verdict on figures that give it (assessment 72 H2): its *Conformity* and *Zones* texts are
those of the unit the decision was made in, so that the value, U₋, U₊ and T printed there,
re-decided under the rule, give the *Verdict* beside them, and each zone limit is T ∓ the
U printed in that text.

0.8.20 re-rounded the texts in the sheet's unit: the theodolite sample against ±1.445″
(guarded) read "4.6 µrad (U = −4.6/+2.4 µrad) … conditional pass … ±1.445″ (7.01 µrad)",
which those figures pass (4.6 + 2.4 ≤ 7.01), with zones 4.58 µrad beside 7.01 − 2.4; the
positioning sample decided in µrad against ±15.4 µrad, its workbook in arcseconds, read
"|e| = 2.1″, U = 1.1″ … (pass)" beside 15.4 µrad (3.18″), a conditional pass on them.

The checks redo the ILAC-G8 decision here from the printed digits (decimals), importing
nothing that makes them.
"""

from __future__ import annotations

import contextlib
import io
import json
import re
from decimal import Decimal
from pathlib import Path

import openpyxl

from app.main import main

ROOT = Path(__file__).resolve().parents[3]
SAMPLES = ROOT / "resources" / "samples"
NUMBER = r"(\d+(?:\.\d+)?)"
UNIT = r'(?:"| µrad)'


def _issue(tmp_path: Path, workbench: str, extra: list[str], details: dict) -> dict:
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps({"example": True, "lab_name": "Angle Lab",
                                "customer_name": "Customer", "item_description": "Axis",
                                "item_serial": "S-1", "calibration_date": "2026-11-20",
                                "operator": "Wang", "approver": "Li", "language": "en",
                                **details}), encoding="utf-8")
    book = tmp_path / "results.xlsx"
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(["analyze", workbench, str(SAMPLES / f"{workbench}_sample.csv"), *extra,
                     "--metadata", str(meta), "--results", str(book)]) == 0, told.getvalue()
    sheet = openpyxl.load_workbook(book)["Certificate"]
    return {row[0]: row[1] for row in sheet.iter_rows(values_only=True) if row and row[0]}


def _ilac(value: Decimal, minus: Decimal, plus: Decimal, t: Decimal) -> str:
    if value + plus <= t:
        return "pass"
    if value <= t:
        return "conditional pass"
    return "conditional fail" if value - minus <= t else "fail"


STANDARD = {"description": "Autocollimating theodolite", "serial": "T-4411",
            "certificate_no": "NIM-2026-1187", "uncertainty": 0.5, "uncertainty_unit": "arcsec",
            "basis": "u"}


def test_theodolite_workbook_in_urad_redecides_to_its_verdict(tmp_path):
    rows = _issue(tmp_path, "theodolite", ["--unit", "urad"],
                  {"tolerance": 1.445, "tolerance_unit": "arcsec", "decision_rule": "guarded",
                   "standards": [STANDARD]})
    text = rows["Conformity"]
    found = re.search(r"error: " + NUMBER + UNIT + r".*?\(U = (?:±" + NUMBER + UNIT + "|−"
                      + NUMBER + UNIT + r"/\+" + NUMBER + UNIT + r").*?±" + NUMBER + UNIT, text)
    assert found, text
    value = Decimal(found[1])
    minus, plus = Decimal(found[2] or found[3]), Decimal(found[2] or found[4])
    t = Decimal(found[5])
    assert rows["Verdict"] == _ilac(value, minus, plus, t) == "conditional pass", text
    zones = rows["Zones"]
    low = re.search(r"pass ≤ " + NUMBER + UNIT + r" \(T − U₊, U₊ = " + NUMBER, zones)
    high = re.search(r"conditional fail ≤ " + NUMBER + UNIT + r" \(T \+ U₋, U₋ = " + NUMBER, zones)
    assert low and high, zones
    assert Decimal(low[2]) == plus and Decimal(high[2]) == minus
    step = Decimal(1).scaleb(-max(len(low[1].partition(".")[2]), 0))
    assert Decimal(low[1]) <= t - plus < Decimal(low[1]) + step
    assert Decimal(high[1]) <= t + minus < Decimal(high[1]) + step


def test_positioning_decided_in_urad_workbook_in_arcsec_redecides_to_its_verdict(tmp_path):
    rows = _issue(tmp_path, "positioning",
                  ["--misalignment-u", "0.2", "--reference-resolution", "0.1",
                   "--temperature-u", "0.2", "--deviation-unit", "urad"],
                  {"tolerance": 15.4, "tolerance_unit": "urad", "decision_rule": "guarded",
                   "decision_quantity": "points",
                   "standards": [{**STANDARD, "uncertainty": 1.0, "basis": "U95",
                                  "applies_to": "angle"}]})
    text = rows["Conformity"]
    found = re.search(r"±" + NUMBER + UNIT + r".*?\|e\| = " + NUMBER + UNIT + ", U = "
                      + NUMBER + UNIT, text)
    assert found, text
    t, value, u = (Decimal(found[i]) for i in (1, 2, 3))
    assert rows["Verdict"] == _ilac(value, u, u, t), text
    zones = rows["Zones"]
    low = re.search(r"pass ≤ " + NUMBER + UNIT + r" \(T − w\)", zones)
    assert low, zones
    step = Decimal(1).scaleb(-len(low[1].partition(".")[2]))
    assert Decimal(low[1]) <= t - u < Decimal(low[1]) + step, (zones, t, u)
