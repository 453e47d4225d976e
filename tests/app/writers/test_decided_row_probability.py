"""The decided quantity's row in the certificate's statistics carries its own interval's
coverage probability (audit 68 finding 2: positioning's and the theodolite's decided
"6.0″ −1.1″/+1.0″" at 92.5 % sat above "Expanded uncertainty U (p = 95.45 %)" with no
probability of its own). The probability looked for is the JSON's
``decided_quantity.coverage_probability``; the certificate is read back with pdftotext, in
English, Chinese and both. The theodolite's passes are simulated from first principles
(tests/repeatability_rig.py)."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.repeatability_rig import theodolite_passes_csv

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
ROW_NAMES = ("Decided quantity", "判定的量")


def _percent(p: float) -> str:
    """0.925 → "92.5", 0.9545 → "95.45": a probability as a percentage, no trailing zero."""
    return f"{100.0 * p:.2f}".rstrip("0").rstrip(".")


def _readings(kind: str, tmp_path: Path) -> Path:
    if kind == "positioning":
        return SAMPLES / "positioning_sample.csv"
    text, _ = theodolite_passes_csv("varying", 13, 3, 0.3, np.random.default_rng(6801))
    path = tmp_path / "passes.csv"
    path.write_text(text, encoding="utf-8")
    return path


def _metadata(kind: str, language: str, tmp_path: Path) -> Path:
    details = json.loads((SAMPLES / f"certificate_{kind}.json").read_text("utf-8"))
    details.pop("certificate_number", None)  # the register allocates one
    details.update(language=language, decision_quantity="half_range", tolerance=15.0)
    path = tmp_path / f"meta_{language}.json"
    path.write_text(json.dumps(details), encoding="utf-8")
    return path


def _decided_rows(text: str) -> list[str]:
    """The statistics table's decided-quantity rows (not the footnote "[1] Decided …", nor
    the statement of conformity's "Decided quantity: …"). On a bilingual certificate the
    row's name is in Chinese above its English (zh81), the figures on the lines between:
    the row is those lines, from its Chinese name to its English one."""
    out = []
    lines = [line.strip() for line in text.splitlines()]
    named = [i for i, s in enumerate(lines)
             if s.startswith(ROW_NAMES) and not s.startswith(tuple(f"{n}:" for n in ROW_NAMES))
             and not s.startswith(tuple(f"{n}：" for n in ROW_NAMES))]
    taken: set[int] = set()
    for i in named:
        if i in taken:
            continue
        english = next((j for j in named if i < j <= i + 4 and lines[i].startswith(ROW_NAMES[1])
                        and lines[j].startswith(ROW_NAMES[0])), None)
        if english is None:
            out.append(lines[i])
        else:
            out.append(" ".join(lines[i:english + 1]))
            taken.add(english)
    return out


@pytest.mark.parametrize("kind", ["positioning", "theodolite"])
@pytest.mark.parametrize("language", ["en", "zh", "zh+en"])
def test_decided_row_prints_its_own_coverage_probability(kind, language, tmp_path, capsys):
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    csv, meta = _readings(kind, tmp_path), _metadata(kind, language, tmp_path)
    pdf = tmp_path / "c.pdf"
    # the certificate and the JSON of one analysis (the JSON that of --json alone)
    assert main(["analyze", kind, str(csv), "--metadata", str(meta), "--json",
                 "--certificate", str(pdf)]) == 0
    out = capsys.readouterr().out
    decided = json.loads(out[out.index("{"):])["decided_quantity"]
    p = decided["coverage_probability"]
    assert p is not None and decided["interval_low"] is not None
    text = subprocess.run(["pdftotext", "-layout", "-enc", "UTF-8", str(pdf), "-"],
                          capture_output=True, text=True, encoding="utf-8", check=True).stdout
    rows = _decided_rows(text)
    assert rows, text
    assert all(f"{_percent(p)} %" in row for row in rows), (p, rows)
