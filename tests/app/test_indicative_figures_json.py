"""The summary figures the JSON states as plain numbers, with no interval, say why beside
them (audit 68 finding 4): the cross-calibration's ``encoder_figures_arcsec`` (JJF 1115,
ISO 230-2 of the encoder, the mountings taken as runs) and the polygon's ``iso230_arcsec``,
as other figures stated without an interval do (``reversal_figures_reason``); the keys keep
their meaning (plain numbers, issue #39)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from app.main import main

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"


@pytest.mark.parametrize(("kind", "sample", "key", "more"), [
    ("crosscal", "crosscal_sample.csv", "encoder_figures_arcsec", ("--certificate-of", "encoder")),
    ("crosscal", "crosscal_sample.csv", "encoder_figures_arcsec", ()),
    ("polygon", "polygon_sample.csv", "iso230_arcsec", ()),
])
def test_summary_figures_without_interval_say_why(kind, sample, key, more, capsys):
    assert main(["analyze", kind, str(SAMPLES / sample), "--json", *more]) == 0
    data = json.loads(capsys.readouterr().out)
    figures = data[key]
    # the key's meaning kept: each figure a plain number
    assert figures and all(isinstance(v, float) for v in figures.values()), figures
    assert any(math.isfinite(v) for v in figures.values())
    reason = data[f"{key}_reason"]
    assert isinstance(reason, str) and reason.startswith("indicative: no coverage interval"), reason
