"""A tolerance stated in another unit is quoted as the customer stated it on every workbench
(assessment 72 M1: the fringe, cross-calibration and polygon restated it converted,
"±0.515662″" for 2.5 µrad, "±0.41253″" for 2 µrad), with its value in the decision's unit
beside it, which is the T decided with, so that the decision redone from the printed
figures and that T gives the printed verdict (M2: 7.0297 µrad printed "(1.45″)" beside a
conditional pass that 0.95″ + 0.50″ ≤ 1.45″ contradicts).

Expected figures from the units' definitions (π rad = 648 000″) and ILAC-G8's rule redone
from the printed digits; nothing imported from the code checked."""

from __future__ import annotations

import contextlib
import io
import json
import math
import re
import subprocess
from decimal import Decimal
from pathlib import Path

import pytest

from app.main import main
from tests.ilac_verdict import ilac_verdict

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
URAD_PER_ARCSEC = math.pi / 648000.0 * 1e6
FULL = ["--phase-reference-u", "0.01", "--adc-lsb-mv", "0.3", "--adc-offset-u-mv", "0.5",
        "--adc-gain-u-pct", "0.05", "--adc-linearity-mv", "0.5"]


def _text(path: Path) -> str:
    out = subprocess.run(["pdftotext", "-layout", str(path), "-"], capture_output=True,
                         text=True, check=True).stdout
    return re.sub(r"\s+", " ", out)


def _issue(tmp_path: Path, workbench: str, extra: list[str], details: dict) -> str:
    base = json.loads((SAMPLES / f"certificate_{workbench}.json").read_text("utf-8"))
    base.update(details)
    meta, pdf = tmp_path / "meta.json", tmp_path / f"{workbench}.pdf"
    meta.write_text(json.dumps(base), "utf-8")
    said = io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(said):
        assert main(["analyze", workbench, str(SAMPLES / f"{workbench}_sample.csv"), *extra,
                     "--metadata", str(meta), "--certificate", str(pdf)]) == 0, said.getvalue()
    return _text(pdf)


def _six(urad: float) -> str:
    """The arcsecond value of ``urad`` to six significant digits, as a reader writes it, its
    trailing zeros kept (assessment 73 L1: "0.41253″" read as a five-digit figure)."""
    value = Decimal(repr(urad / URAD_PER_ARCSEC))
    return str(value.quantize(Decimal(1).scaleb(value.adjusted() - 5)))


VERDICTS = {"(pass)": "pass", "(fail)": "fail", "Conditional pass": "conditional pass",
            "Conditional fail": "conditional fail"}


def _printed_verdict(text: str) -> str:
    found = re.search(r"\(pass\)|\(fail\)|Conditional pass|Conditional fail", text)
    assert found, text
    return VERDICTS[found[0]]


PHASE = {"description": "Phase reference (sampling clock)", "serial": "PR-1",
         "certificate_no": "CAL-2026-31", "uncertainty": 0.01, "uncertainty_unit": "arcsec",
         "basis": "U95", "role": "reference"}
ADC = {"description": "Data acquisition (16-bit ADC)", "serial": "DAQ-5",
       "certificate_no": "CAL-2026-33", "uncertainty": 0.02, "uncertainty_unit": "arcsec",
       "basis": "U95"}


@pytest.mark.parametrize(("workbench", "extra", "details", "urad"), [
    ("fringe", FULL, {"tolerance": 2.5, "tolerance_unit": "urad", "decision_rule": "guarded",
                      "standards": [PHASE, ADC]}, 2.5),
    ("crosscal", ["--cmc-arcsec", "0.1"], {"tolerance": 2.0, "tolerance_unit": "urad",
                                           "decision_rule": "guarded"}, 2.0),
])
def test_the_specification_is_quoted_as_stated_with_the_t_decided(tmp_path, workbench, extra,
                                                                   details, urad):
    text = _issue(tmp_path, workbench, extra, details)
    t = _six(urad)
    # as typed in the details: a JSON 2.0 keeps its decimal (ASTM E29's place, merge of e29)
    stated = f"{json.dumps(details['tolerance'])} µrad ({t}\")"
    assert f"tolerance ±{stated}" in text  # the front page
    assert f"specification ±{stated}" in text  # the statement
    assert f"±{t}\"" not in text  # never the conversion alone
    assert _printed_verdict(text[text.index("Statement of conformity"):]) in VERDICTS.values()


def test_the_polygon_grade_is_quoted_as_the_customer_stated_it(tmp_path):
    text = _issue(tmp_path, "polygon", ["--grade", "4"],
                  {"tolerance": 0.5555556, "tolerance_unit": "mdeg", "item_grade": "grade 4"})
    assert "tolerance ±0.5555556 mdeg (2.00000\")" in text and "tolerance ±2\"" not in text


def test_a_converted_t_near_the_limit_redecides_to_the_verdict_printed(tmp_path):
    """7.0297 µrad = 1.449983″ against the theodolite sample's 0.95″ (U −0.94″/+0.50″)."""
    text = _issue(tmp_path, "theodolite", [],
                  {"tolerance": 7.0297, "tolerance_unit": "urad", "decision_rule": "guarded"})
    t = _six(7.0297)
    assert t == "1.44998"
    assert f"±7.0297 µrad ({t}\")" in text
    # (a page may break inside the statement: its foot between "U =" and the figures)
    found = re.search(r"error: ([\d.]+)\".*?\(U =.*?−([\d.]+)\"/\+([\d.]+)\"", text)
    assert found, text
    value, minus, plus = (Decimal(found[i]) for i in (1, 2, 3))
    statement = text[text.index("Statement of conformity"):]
    assert _printed_verdict(statement) == ilac_verdict("guarded", value, minus, plus, Decimal(t))
