"""One U per point in every document (assessment 72 H1): the U a certificate's results table
prints beside a point is that point's U in the JSON rounded up to two significant digits
(GUM 7.2.6) — the figure the XLSX, the DCC, the "largest U" sentence, the CMC remark and
the budget give — not a U re-measured from the rounded value to the computed interval's end
(0.8.20 printed 0.43″ at polygon positions 8 and 9 beside "U = 0.42″, the largest", 2.6″
in 25 of 26 positioning cells beside "U = 2.5″, the CMC"). The theodolite's table prints
one U, the largest, rounded up, as before.

A decision on a point uses that same printed U: the positioning sample with a CMC of 2.5″
and T = ±12.85″ (guarded) prints |e| = 10.3″ and U = 2.5″ at target 60° ↓, the XLSX's
*Results* row 10.33 ± 2.5; redone from either document's figures the verdict is a pass
(0.8.20 printed 2.6″ and "conditional pass", which the XLSX's figures contradict).

The expected U is worked out here from the JSON's unrounded U with decimals, by the
definition (two significant digits after rounding up), not by the code checked.
"""

from __future__ import annotations

import contextlib
import io
import json
import math
import re
import subprocess
from decimal import ROUND_CEILING, Decimal
from pathlib import Path

import openpyxl

from app.main import main

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"


def _main(args: list[str]) -> str:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


def _rounded_up(u: float) -> str:
    """U to two significant digits, rounded up (0.4198 → 0.42, 0.0996 → 0.10, 2.5 → 2.5)."""
    exact = Decimal(repr(u))
    d = 1 - math.floor(math.log10(u))
    shown = exact.quantize(Decimal(1).scaleb(-d), ROUND_CEILING)
    if shown >= Decimal(10) ** (2 - d):  # carried into a third digit
        d -= 1
        shown = exact.quantize(Decimal(1).scaleb(-d), ROUND_CEILING)
    return f"{shown:.{max(d, 0)}f}"


def _layout(pdf: Path) -> list[str]:
    return subprocess.run(["pdftotext", "-layout", str(pdf), "-"], capture_output=True,
                          text=True, check=True).stdout.splitlines()


def _raw(pdf: Path) -> list[str]:
    """The text in content order (pdftotext -raw): the draft's watermark, drawn over the
    table's last rows, splits them into columns under -layout."""
    return subprocess.run(["pdftotext", "-raw", str(pdf), "-"], capture_output=True,
                          text=True, check=True).stdout.splitlines()


def _issue(tmp_path: Path, workbench: str, extra: list[str], metadata: dict | None = None):
    pdf, data = tmp_path / f"{workbench}.pdf", tmp_path / f"{workbench}.json"
    args = ["analyze", workbench, str(SAMPLES / f"{workbench}_sample.csv"), *extra]
    if metadata is not None:
        meta = tmp_path / f"{workbench}_meta.json"
        meta.write_text(json.dumps(metadata), encoding="utf-8")
        args += ["--metadata", str(meta)]
    _main([*args, "--certificate", str(pdf)])
    data.write_text(_main([*args, "--json"]), encoding="utf-8")
    return _layout(pdf), json.loads(data.read_text(encoding="utf-8"))


NUMBER = r"[-+]?\d+\.\d+"


def test_polygon_table_u_is_the_json_u_rounded_up(tmp_path):
    _, data = _issue(tmp_path, "polygon", [])
    lines = _raw(tmp_path / "polygon.pdf")
    u = data["expanded_uncertainty_mean_corrected_error_arcsec"]
    row = re.compile(rf"^\s*(\d+)\s+\d+\.\d+\s+{NUMBER}\s+{NUMBER}\s+{NUMBER}\s+(\d+\.\d+)\s*$")
    printed = {int(m[1]): m[2] for m in map(row.match, lines) if m}
    assert len(printed) == len(u), printed
    assert printed == {i + 1: _rounded_up(x) for i, x in enumerate(u)}


def test_crosscal_table_u_is_the_json_u_rounded_up(tmp_path):
    lines, data = _issue(tmp_path, "crosscal", [])
    u, u1 = data["polygon_deviation_U_arcsec"], data["polygon_deviation_U_from_face1_arcsec"]
    row = re.compile(rf"^\s*(\d+)\s+\d+\.\d+\s+{NUMBER}\s+(\d+\.\d+)\s+{NUMBER}(?:\s+(\d+\.\d+))?\s*$")
    rows = {int(m[1]): (m[2], m[3]) for m in map(row.match, lines) if m}
    assert len(rows) == len(u), rows
    for face, (shown, shown1) in rows.items():
        assert shown == _rounded_up(u[face - 1]), (face, shown, u[face - 1])
        if u1[face - 1] > 0:
            assert shown1 == _rounded_up(u1[face - 1]), (face, shown1, u1[face - 1])


FRINGE = ["--phase-reference-u", "0.01", "--adc-lsb-mv", "0.3", "--adc-offset-u-mv", "0.5",
          "--adc-gain-u-pct", "0.05", "--adc-linearity-mv", "0.5"]


def test_fringe_table_u_is_the_json_u_rounded_up(tmp_path):
    """The fringe sample with every input stated (0.8.20: 134 of its 512 rows printed a U
    one digit above the JSON's rounded up, 0.029″ beside "U = 0.028″, the largest")."""
    details = json.loads((SAMPLES / "certificate_fringe.json").read_text(encoding="utf-8"))
    lines, data = _issue(tmp_path, "fringe", FRINGE, details)
    u = data["expanded_uncertainty_raw_error_arcsec"]
    row = re.compile(rf"^\s*(\d+)\s+\d+\.\d+\s+{NUMBER}\s+{NUMBER}\s+{NUMBER}\s+(\d+\.\d+)\s*$")
    printed = {int(m[1]): m[2] for m in map(row.match, lines) if m}
    assert len(printed) == len(u), len(printed)
    assert printed == {i + 1: _rounded_up(x) for i, x in enumerate(u)}


POSITIONING = ["--misalignment-u", "0.2", "--reference-resolution", "0.1",
               "--temperature-u", "0.2", "--cmc", "2.5"]


def _verdict(e: float, u: float, t: float) -> str:
    """The guarded (non-binary) rule on |e|, U and T as a reader applies it."""
    e = abs(e)
    if e + u <= t + 1e-12:
        return "pass"
    if e <= t:
        return "conditional pass"
    return "conditional fail" if e - u <= t else "fail"


def test_positioning_cmc_table_u_and_the_verdict_agree_with_the_xlsx(tmp_path):
    metadata = {"example": True, "certificate_number": "AB-2026-0043",
                "lab_name": "Precision Angle Lab", "customer_name": "Changchun Photonics Ltd.",
                "item_description": "Rotary table, C axis", "item_serial": "RT-400-0117",
                "tolerance": 12.85, "tolerance_unit": "arcsec", "calibration_date": "2026-11-20",
                "issue_date": "2026-11-24", "operator": "Wang", "approver": "Dr. Li",
                "decision_rule": "guarded", "decision_quantity": "points", "language": "en",
                "standards": [{"description": "Laser rotary calibrator", "serial": "XR20-0815",
                               "certificate_no": "NIM-2026-1033", "uncertainty": 1.0,
                               "uncertainty_unit": "arcsec", "basis": "U95",
                               "applies_to": "angle"}]}
    lines, data = _issue(tmp_path, "positioning", POSITIONING, metadata)
    targets = data["per_target"]
    expected = sorted({_rounded_up(x) for x in targets["expanded_uncertainty_mean_up"]
                       + targets["expanded_uncertainty_mean_down"]})
    assert expected == ["2.5"]  # every U held at the CMC
    row = re.compile(rf"^\s*(\d+)\s+{NUMBER}\s+(\d+\.?\d*)\s+(\d+\.\d+)\s+{NUMBER}\s+(\d+\.?\d*)"
                     rf"\s+(\d+\.\d+)\s+{NUMBER}\s+{NUMBER}\s*$")
    cells = [(m[3], m[5]) for m in map(row.match, lines) if m]
    assert len(cells) == len(targets["mean_up"]), lines
    assert {c for pair in cells for c in pair} == {"2.5"}
    text = " ".join(" ".join(lines).split())
    stated = re.search(r'\|e\| = ([\d.]+)", U = ([\d.]+)"\. (.*?)\((pass|conditional pass|'
                       r'conditional fail|fail)\)', text)
    said = re.search(r"(Conditional pass|Conditional fail|\(pass\)|\(fail\))", text[stated.start():])
    printed_verdict = said[1].strip("()").lower()
    assert _verdict(float(stated[1]), float(stated[2]), 12.85) == printed_verdict
    # the same point's figures in the results workbook give the same verdict
    book = tmp_path / "positioning.xlsx"
    _main(["analyze", "positioning", str(SAMPLES / "positioning_sample.csv"), *POSITIONING,
           "--metadata", str(tmp_path / "positioning_meta.json"), "--results", str(book)])
    sheet = openpyxl.load_workbook(book)["Results"]
    rows = [r for r in sheet.iter_rows(values_only=True) if r and r[0] == 60 and r[1] == -1]
    assert rows, "no row for target 60° ↓"
    e, u = float(rows[0][2]), float(rows[0][5])
    assert _verdict(e, u, 12.85) == printed_verdict == "pass"
