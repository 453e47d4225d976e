"""A reference standard's figure says what it is stated per, in the standards table as in
the budget (day review 69, finding 2): a theodolite whose T-4411 is stated for any angle
between two readings printed "0.5″ (standard uncertainty u)", the same words as one stated
per reading, and its budget took "u = 0.354″ per reading" with no word that 0.354″ is
0.5″/√2. Checked on printed certificates (pdftotext)."""

from __future__ import annotations

import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # theodolite certificates

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"


def _certificate(tmp_path: Path, capsys, applies_to: str) -> str:
    from app.main import main

    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    data = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    data.pop("certificate_number", None)
    data["language"] = "en"
    data["standards"] = [{**std, "applies_to": applies_to} for std in data["standards"]]
    meta = tmp_path / f"meta_{applies_to}.json"
    meta.write_text(json.dumps(data), encoding="utf-8")
    pdf = tmp_path / f"c_{applies_to}.pdf"
    code = main(["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"),
                 "--metadata", str(meta), "--certificate", str(pdf)])
    assert code == 0, capsys.readouterr().err
    return re.sub(r"\s+", " ", subprocess.run(
        ["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True, text=True,
        encoding="utf-8", check=True).stdout)


def test_a_standard_stated_per_angle_says_so_in_the_table_and_why_u_over_root_two(
        tmp_path, capsys):
    text = _certificate(tmp_path, capsys, "angle")
    table = text[text.index("Reference standards and traceability"):
                 text.index("Metrological traceability")]
    assert "(standard uncertainty u per angle between two readings)" in table, table
    u = 0.5  # the sample's T-4411, standard uncertainty
    said = (f"Autocollimating theodolite u = {u:.3f}\" per angle, u/√2 = "
            f"{u / math.sqrt(2):.3f}\" per reading")
    assert said in text, text[text.index("Reading error (pointing):"):][:900]
    # and the reason: an angle is the difference of two readings
    assert "since an angle is the difference of two readings" in text


def test_a_standard_stated_per_reading_says_so_in_the_table(tmp_path, capsys):
    text = _certificate(tmp_path, capsys, "reading")
    table = text[text.index("Reference standards and traceability"):
                 text.index("Metrological traceability")]
    assert "(standard uncertainty u per reading)" in table, table
    assert "per angle" not in text
