"""Two runs leave each target's σ one degree of freedom: the intervals of R, R↑, R↓,
Ps_max, and of A, A↑, A↓ and P (made of μ ± 2σ, ± 1.5σ, since 0.8.17 from each target's own
bounds), would reach tens of times their value (audit 68 finding 3: a theodolite's R of 3.13″
in 0.86″ … 225″), so the JSON states the figures as measured with no interval and says why
(``interval_reason``); three runs (ν = 2) keep their intervals. The axis is simulated from
first principles (tests/repeatability_rig.py: each reading the target's true mean, ± half
a reversal, plus normal noise of its own σ)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.repeatability_rig import positioning_test

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
REPEATABILITY = ("R", "R_up", "R_down")
BANDS = ("A", "A_up", "A_down")


def _csv(runs: int, tmp_path: Path, seed: int = 6803) -> Path:
    m = 12
    readings, _ = positioning_test("varying", m, runs, 0.6, np.random.default_rng(seed))
    targets = np.arange(m) * 30.0
    lines = ["target,run,direction,deviation"]
    for run in range(runs):
        for name, sign, order in (("up", "+", range(m)), ("down", "-", reversed(range(m)))):
            lines += [f"{targets[i]:g},{run + 1},{sign},{readings[name][run, i]:.4f}"
                      for i in order]
    path = tmp_path / f"runs{runs}.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _json(csv: Path, capsys, *more: str) -> dict:
    assert main(["analyze", "positioning", str(csv), "--json", *more]) == 0
    return json.loads(capsys.readouterr().out)


def _metadata(tmp_path: Path) -> Path:
    details = json.loads((SAMPLES / "certificate_positioning.json").read_text("utf-8"))
    details.pop("certificate_number", None)
    path = tmp_path / "meta.json"
    path.write_text(json.dumps(details), encoding="utf-8")
    return path


@pytest.mark.parametrize("with_certificate_details", [False, True])
def test_two_runs_withhold_the_repeatability_intervals_with_the_reason(
        with_certificate_details, tmp_path, capsys):
    more = ("--metadata", str(_metadata(tmp_path))) if with_certificate_details else ()
    data = _json(_csv(2, tmp_path), capsys, *more)
    iso, vdi = data["iso230_2_figures"], data["vdi3441_figures"]
    for key, figure in [*((k, iso[k]) for k in (*REPEATABILITY, *BANDS)),
                        ("Ps_max", vdi["Ps_max"]), ("P", vdi["P"])]:
        assert figure["value"] is not None and figure["value"] > 0, key  # still as measured
        assert figure["interval_low"] is None and figure["interval_high"] is None, key
        assert figure["coverage_probability"] is None, key
        reason = figure["interval_reason"]
        assert "one degree of freedom" in reason and "at least 3 runs" in reason, reason
        # the interval it would have been is quoted: its upper end far above the value
        high = float(reason.split(" … ")[1].split('"')[0])
        assert high > (5 if key in (*REPEATABILITY, "Ps_max") else 2) * figure["value"], (key,
                                                                                        reason)
    # the figures of the means keep theirs
    for key in ("E", "M", "B"):
        assert iso[key]["interval_low"] is not None and iso[key]["interval_reason"] is None


def test_three_runs_keep_the_repeatability_intervals(tmp_path, capsys):
    data = _json(_csv(3, tmp_path), capsys)
    for key in (*REPEATABILITY, *BANDS):
        figure = data["iso230_2_figures"][key]
        assert figure["interval_low"] is not None and figure["interval_high"] is not None, key
        assert figure["interval_reason"] is None, key


def test_two_runs_summary_says_why_R_has_no_interval(tmp_path, capsys):
    assert main(["analyze", "positioning", str(_csv(2, tmp_path)), "--language", "en"]) == 0
    out = capsys.readouterr().out
    intervals = next(line for line in out.splitlines() if line.startswith("Coverage intervals"))
    assert "R_up " not in intervals and "E " in intervals
    for key in (*REPEATABILITY, "Ps_max", *BANDS, "P"):
        assert f"No coverage interval is given for {key}: two runs" in out, out
