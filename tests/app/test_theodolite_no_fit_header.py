"""The theodolite's set-up parameters where the elevations do not identify the tilt (every
elevation the same): no fit was made, so the table's U column is headed "U", not "U (k = …,
ν = …)", the k and ν of a fit (assessment 72 L7); with the tilt identified it keeps them."""

from __future__ import annotations

import contextlib
import csv
import io
import re
from pathlib import Path

from app.main import main
from tests.pdf_text import pdf_text

SAMPLE = Path(__file__).resolve().parents[2] / "resources" / "samples" / "theodolite_sample.csv"


def _issue(tmp_path: Path, record: Path) -> str:
    pdf = tmp_path / f"{record.stem}.pdf"
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", "theodolite", str(record), "--certificate", str(pdf)]) == 0
    return pdf_text(pdf.read_bytes())


def test_no_k_and_nu_where_no_fit_was_made(tmp_path):
    rows = list(csv.reader(SAMPLE.read_text("utf-8").splitlines()))
    level = tmp_path / "level.csv"
    with level.open("w", newline="", encoding="utf-8") as out:
        writer = csv.writer(out)
        writer.writerow(rows[0])
        for row in rows[1:]:
            writer.writerow([row[0], row[1], rows[1][2]])  # every elevation the first one
    text = _issue(tmp_path, level)
    assert "Set-up parameters: the tilt not identified" in text
    head = text[text.index("Set-up parameters: the tilt not identified"):][:120]
    assert re.search(r"Parameter Value U Axis tilt", head), head
    assert "U (k =" not in head
    identified = _issue(tmp_path, SAMPLE)
    assert re.search(r"Parameter Value U \(k = \d\.\d\d, ν = \d+\)", identified)
