"""A theodolite run of two passes each way: each θ's σ has one degree of freedom, and the
intervals of R, R↑ and R↓ would reach tens of times their value (audit 68 finding 3: R =
3.13″ in 0.86″ … 225″, the truth 1.8″). The JSON states them as measured with no interval
and says why (``interval_reason``); three passes (ν = 2) keep theirs. The passes are
simulated from first principles (tests/repeatability_rig.py: a mirror on a tilted axis, read
with pointing noise)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.repeatability_rig import theodolite_passes_csv
from tests.theodolite_run_json import passes_summary

REPEATABILITY = ("R", "R_up", "R_down")
BANDS = ("A", "A_up", "A_down")  # μ ± 2σ from each θ's own bounds (0.8.17): alike


def _figures(passes: int, tmp_path: Path, capsys, *more: str) -> dict:
    text, _ = theodolite_passes_csv("varying", 13, passes, 0.3, np.random.default_rng(6804))
    csv = tmp_path / f"passes{passes}.csv"
    csv.write_text(text, encoding="utf-8")
    assert main(["analyze", "theodolite", str(csv), "--json", *more]) == 0
    return json.loads(capsys.readouterr().out)["iso230_2_figures"]


@pytest.mark.parametrize("more", [(), ("--accuracy-arcsec", "0.5")])
def test_two_passes_withhold_R_intervals_with_the_reason(more, tmp_path, capsys):
    figures = _figures(2, tmp_path, capsys, *more)
    for key in (*REPEATABILITY, *BANDS):
        figure = figures[key]
        assert figure["value"] is not None and figure["value"] > 0, key  # still as measured
        assert figure["interval_low"] is None and figure["interval_high"] is None, key
        assert figure["coverage_probability"] is None, key
        reason = figure["interval_reason"]
        assert "one degree of freedom" in reason and "at least 3 passes" in reason, reason
        high = float(reason.split(" … ")[1].split('"')[0])  # the interval withheld, quoted
        assert high > (5 if key in REPEATABILITY else 2) * figure["value"], (key, reason)
    for key in ("E", "M", "E_up"):
        assert figures[key]["interval_low"] is not None and figures[key]["interval_reason"] is None


def test_three_passes_keep_R_intervals(tmp_path, capsys):
    figures = _figures(3, tmp_path, capsys)
    for key in (*REPEATABILITY, *BANDS):
        assert figures[key]["interval_low"] is not None, key
        assert figures[key]["interval_reason"] is None, key


def test_two_passes_summary_says_why_R_has_no_interval(tmp_path, capsys):
    out = passes_summary(capsys, tmp_path, 2, 6804)
    intervals = next(line for line in out.splitlines() if line.startswith("Coverage intervals"))
    assert " R " not in intervals and "R_up " not in intervals and "E " in intervals
    for key in (*REPEATABILITY, *BANDS):
        assert f"No coverage interval is given for {key}: two passes" in out, out
