"""Audit 72 finding 5 through the command line: a positioning axis's decided half range
against a tolerance stated three places finer than its U's digit, under simple acceptance.
The verdict is the one ASTM E29 §6.4 gives (the value rounded to T's last place, to the
nearest, a lone 5 to even), and the JSON, the certificate's PDF, its DCC and the results
XLSX state the same verdict and the same figure compared with T.

The record is simulated here (numpy only); E29's rounding is done here with decimal, from
the JSON's exact value; T is chosen from that value so that the value printed at U's digit
and E29's rounding of it fall on either side of T (0.8.20 gave the other verdict)."""

from __future__ import annotations

import contextlib
import io
import json
import math
import shutil
import subprocess
from decimal import ROUND_HALF_EVEN, Decimal
from pathlib import Path

import numpy as np
import pytest
from lxml import etree
from openpyxl import load_workbook

from app.main import main

pytestmark = pytest.mark.slow  # a positioning certificate with its DCC and XLSX

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
TARGETS_MM = np.array([0.0, 31.7, 58.2, 96.4, 127.9, 161.3, 188.6, 224.1, 259.8, 300.0])


def _main(args: list[str]) -> str:
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(args) == 0, said.getvalue() + told.getvalue()
    return said.getvalue()


def _record(path: Path, rng: np.random.Generator, scale: float) -> None:
    """An axis sent to each target in 5 runs up and down: a scale error of ``scale`` µm/mm,
    a slow wave of ±1.5 µm, a reversal of ±0.4 µm and a repeatability of 0.6 µm."""
    x = (TARGETS_MM - TARGETS_MM[0]) / (TARGETS_MM[-1] - TARGETS_MM[0])
    curve = scale * TARGETS_MM + 1.5 * np.sin(2 * math.pi * 0.8 * x + 0.4)
    rows = []
    for run in range(1, 6):
        for sign, d, order in (("+", 1.0, range(TARGETS_MM.size)),
                               ("-", -1.0, range(TARGETS_MM.size - 1, -1, -1))):
            for i in order:
                rows.append(f"{TARGETS_MM[i]:.3f},{run},{sign},"
                            f"{curve[i] + d * 0.4 + 0.6 * rng.standard_normal():.4f}\n")
    path.write_text("target,run,direction,deviation\n" + "".join(rows), encoding="utf-8")


def _u_decimals(u: float) -> int:
    """GUM 7.2.6: the decimal of U's second significant digit, U rounded up."""
    d = 1 - math.floor(math.log10(u))
    return d - 1 if math.ceil(u * 10 ** d - 1e-9) >= 100 else d


def _e29(value: float, places: int) -> Decimal:
    return Decimal(repr(value)).quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_EVEN)


@pytest.mark.parametrize("direction", ["value above its printed figure: a fail 0.8.20 passed",
                                       "value below its printed figure: a pass 0.8.20 failed"])
def test_every_output_states_the_e29_verdict_and_figure(tmp_path, monkeypatch, direction):
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    readings = tmp_path / "axis.csv"
    above = direction.startswith("value above")
    options = ["--target-unit", "mm", "--deviation-unit", "um", "--misalignment-u", "0.1",
               "--reference-resolution", "0.01", "--temperature-u", "0.2", "--language", "en"]
    details = json.loads((SAMPLES / "certificate_positioning.json").read_text("utf-8"))
    details.update(example=False, certificate_number="AB-2026-0729", approver="Dr. Li",
                   item_serial="LS-0729", decision_rule="simple",
                   decision_quantity="half_range", tolerance_unit="um",
                   standards=[{"description": "laser interferometer", "serial": "LI-1",
                               "certificate_no": "C-77", "uncertainty": 1.0,
                               "uncertainty_unit": "um", "basis": "U95",
                               "applies_to": "reading"}])
    meta = tmp_path / "details.json"

    def run(tolerance: str, *more: str) -> dict:
        # the tolerance written as the lab types it, its digits as they stand
        text = json.dumps({**details, "tolerance": 0.0}).replace(
            '"tolerance": 0.0', f'"tolerance": {tolerance}')
        meta.write_text(text, "utf-8")
        said = _main(["analyze", "positioning", str(readings), "--metadata", str(meta),
                      *options, *more])
        return json.loads(said[said.index("{"):]) if not more or "--json" in more else {}

    for scale in np.arange(0.040, 0.060, 0.001):  # the first axis whose value lies so
        _record(readings, np.random.default_rng(20261206), float(scale))
        first = run("1000", "--json")["decided_quantity"]
        value = float(first["value"])
        u = max(first["interval_high"] - value, value - first["interval_low"])
        d = _u_decimals(u)
        printed = _e29(value, d)  # the value at U's digit
        places = d + 3
        e29 = _e29(value, places)
        if (printed < e29) == above and e29 != printed:
            break
    else:
        pytest.fail("no simulated axis gave the case")
    assert e29 != printed and abs(Decimal(repr(value)) - printed) < Decimal(1).scaleb(-d) / 2
    step = Decimal(1).scaleb(-places)
    # T between the printed value and E29's figure: 0.8.20 decided on the printed one
    t = e29 - step if printed < e29 else e29
    t_text = f"{t:.{places}f}"
    if t_text.endswith("0"):  # a trailing zero typed: its place still counts
        assert Decimal(t_text).as_tuple().exponent == -places
    expected = "pass" if e29 <= t else "fail"
    assert expected != ("pass" if printed <= t else "fail")
    assert u < float(t)

    decided = run(t_text, "--json")["decided_quantity"]
    assert decided["verdict"] == expected
    assert Decimal(repr(decided["compared_with_tolerance"]["value"])) == e29
    assert decided["compared_with_tolerance"]["decimals"] == places

    out = tmp_path / "cert"
    out.mkdir()
    run(t_text, "--certificate", str(out / "c.pdf"), "--dcc", str(out / "c.xml"),
        "--results", str(out / "c.xlsx"))
    figure = f"Compared with T: {e29:.{places}f} µm"
    tree = etree.fromstring((out / "c.xml").read_bytes())
    dcc = "".join(tree.itertext())
    assert figure in dcc and f"±{t_text} µm" in dcc
    conformity = [el.text for el in tree.iter() if etree.QName(el).localname == "conformity"]
    assert conformity == [expected]
    book = load_workbook(out / "c.xlsx")
    cells = " ".join(str(c) for row in book["Certificate"].iter_rows(values_only=True)
                     for c in row if c is not None)
    assert figure in cells
    if shutil.which("pdftotext") is not None:
        text = subprocess.run(["pdftotext", "-enc", "UTF-8", str(out / "c.pdf"), "-"],
                              capture_output=True, text=True, check=True).stdout
        flat = " ".join(text.split())
        assert figure in flat and f"({expected})" in flat
