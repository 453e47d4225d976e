"""The results workbook's verdict in Chinese is the certificate's word (assessment 72 L1): 合格
for a pass, as the PDF's statement and the workbook's other verdicts (有条件合格, 不合格) say
it, not 通过 (a check passed); above the English on a bilingual certificate."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import openpyxl
import pytest

from app.main import main

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"


@pytest.mark.parametrize(("language", "expected"), [("zh", "合格"), ("zh+en", "合格\npass"),
                                                    ("en", "pass")])
def test_a_pass_is_he_ge_in_chinese(tmp_path, language, expected):
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    details.update({"language": language, "tolerance": 3.0, "tolerance_unit": "arcsec",
                    "decision_rule": "guarded"})
    meta, book = tmp_path / "meta.json", tmp_path / "r.xlsx"
    meta.write_text(json.dumps(details), "utf-8")
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", "theodolite", str(SAMPLES / "theodolite_sample.csv"),
                     "--metadata", str(meta), "--results", str(book)]) == 0
    rows = list(openpyxl.load_workbook(book)["Certificate"].iter_rows(values_only=True))
    verdicts = [row[1] for row in rows if row and row[0] and "Verdict" in row[0] or
                row and row[0] and str(row[0]).startswith("结论")]
    assert verdicts == [expected]
