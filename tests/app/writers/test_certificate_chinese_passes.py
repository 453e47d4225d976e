"""A Chinese certificate of a theodolite run with repeated passes, a theodolite standard
stated per reading, a tolerance and the laboratory's CMC: the texts only such a run prints
(the ISO 230-2 figures' and the decided half range's method statements, the circle part the
readings do not exclude, the figures held to the CMC) are Chinese too.

The sample certificates (test_certificate_chinese.py) are of one pass and no CMC: an
assessor found these statements printed in English on 0.8.15's first build (their texts had
not been translated), which no sample showed."""

from __future__ import annotations

import contextlib
import io
import json
import re
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from models.registry import KINDS
from tests.app.writers.test_certificate_chinese import SYMBOLS, WORD
from tests.pdf_text import pdf_text
from tests.theodolite_passes_simulator import passes_record

pytestmark = pytest.mark.slow  # one certificate with the figures' bootstrap

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"


def test_a_chinese_certificate_of_passes_held_to_the_cmc_has_no_english_of_ours(
        tmp_path, monkeypatch):
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    readings = tmp_path / "passes.csv"
    # 3 passes each way, pointing 0.25″, a reversal of 0.3″: the theodolite stated at 0.5″
    # per reading, so a circle part is not excluded and the half range is united with E/2
    passes_record(readings, np.random.default_rng(66), 3, 0.25, 0.3)
    details = json.loads((SAMPLES / "certificate_theodolite.json").read_text("utf-8"))
    details.update(example=False, certificate_number="AB-2026-0966", approver="Dr. Li",
                   tolerance=3, tolerance_unit="arcsec", decision_rule="guarded",
                   language="zh")
    details["standards"][0].update(uncertainty=0.5, uncertainty_unit="arcsec", basis="u")
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(details, ensure_ascii=False), encoding="utf-8")
    pdf = tmp_path / "certificate.pdf"
    said = io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(said):
        code = main(["analyze", "theodolite", str(readings), "--metadata", str(meta),
                     "--cmc-arcsec", "1.5", "--certificate", str(pdf), "--language", "en"])
    assert code == 0, said.getvalue()
    chinese = pdf_text(pdf.read_bytes())
    # a command quoted to be typed and a module's path stay as written
    chinese = re.sub(r"“anglebench[^”]*”|\S*/\S*", " ", chinese)
    theirs = " ".join(str(v) for v in [*details.values(), *details["standards"][0].values(),
                                        KINDS["theodolite"].method_reference, readings.name])
    english = sorted(w for w in set(WORD.findall(chinese)) - SYMBOLS if w not in theirs)
    assert english == [], english
    # the statements this run prints and a sample's does not are there, in Chinese
    assert "CMC" in chinese and "符合性声明" in chinese
