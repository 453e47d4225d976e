"""Assessment 73 M4 and M6 through the command line, on a positioning axis decided point by
point under simple acceptance (the bundled sample, T = ±10.4″ as in the assessment):

* M6: the probabilities are Boole bounds over the points. The JSON keeps its figures and
  says they are bounds (``decision_risk_is_bound``); the results workbook gives them as
  bounds ("≤", "≥", never "< 0.01" of a lower bound of 0) and says how they are stated;
  the statement prints "at most" a figure no smaller than the JSON's.
* M4: the JSON states the tolerance as the customer typed it (``tolerance_stated``: its
  number, the places typed, the text and the unit) beside the converted ``tolerance``, so
  that the JSON alone redoes the decision: here T typed "50.420" µrad for errors in ″.

The conversion is done here from the unit's definition (1 rad = 648000/π ″)."""

from __future__ import annotations

import contextlib
import io
import json
import math
import re

import pytest
from openpyxl import load_workbook

from app.main import main

pytestmark = pytest.mark.slow  # a positioning analysis with its results workbook

IN = ["--misalignment-u", "0.2", "--reference-resolution", "0.1", "--temperature-u", "0.2"]


def _run(args):
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


def _details(samples_dir, tmp_path, **changes):
    data = json.loads((samples_dir / "certificate_positioning.json").read_text("utf-8"))
    data.update(decision_rule="simple", decision_quantity="points", **changes)
    path = tmp_path / "details.json"
    path.write_text(json.dumps(data), "utf-8")
    return str(path)


def test_the_points_bound_is_said_to_be_one_in_the_json_and_the_workbook(samples_dir, tmp_path):
    details = _details(samples_dir, tmp_path, tolerance=10.4, tolerance_unit="arcsec")
    book = tmp_path / "r.xlsx"
    out = _run(["analyze", "positioning", str(samples_dir / "positioning_sample.csv"), *IN,
                "--json", "--metadata", details, "--results", str(book)])
    decided = json.loads(out)["decided_quantity"]
    assert decided["verdict"] in ("pass", "fail") and decided["decision_risk_is_bound"] is True
    risk, conforming = decided["decision_risk"], decided["probability_conforming"]
    rows = {r[0]: r[1] for r in load_workbook(book)["Certificate"].iter_rows(values_only=True)}
    wrong, conform = rows["Probability of a wrong decision (%)"], rows["Probability of conformity (%)"]
    assert isinstance(wrong, str) and wrong.startswith("≤ ")
    assert float(wrong[2:]) >= 100 * risk - 1e-9
    passed = decided["verdict"] == "pass"
    assert isinstance(conform, str) and conform.startswith("≥ " if passed else "≤ ")
    assert (float(conform[2:]) <= 100 * conforming + 1e-9 if passed
            else float(conform[2:]) >= 100 * conforming - 1e-9)
    assert "bounds" in str(rows["Probabilities stated as"])
    statement = str(rows["Conformity"])
    assert "100.00 %" not in statement
    found = re.search(r"at this decision: at most ([0-9.]+) %", statement)
    assert (found and float(found.group(1)) >= 100 * risk - 1e-9) or (
        "not bounded by this method" in statement and risk > 0.9999)


def test_the_json_states_the_tolerance_as_typed(samples_dir, tmp_path):
    details = _details(samples_dir, tmp_path, tolerance="50.420", tolerance_unit="urad")
    out = _run(["analyze", "positioning", str(samples_dir / "positioning_sample.csv"), *IN,
                "--json", "--metadata", details])
    decided = json.loads(out)["decided_quantity"]
    stated = decided["tolerance_stated"]
    assert stated == {"value": 50.42, "decimals": 3, "text": "50.420", "unit": "urad"}
    arcsec = 50.42 * 0.648 / math.pi
    assert decided["unit"] == "arcsec" and decided["tolerance"] == float(f"{arcsec:.6g}")
