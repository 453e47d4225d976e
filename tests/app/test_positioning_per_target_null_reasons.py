"""Every null figure of the positioning JSON says why beside it, per target too: in a run in
both directions, a target approached one way only has no B_i, M_i, R_i (nor a mean, s and ±2s
band that way), one approached once in a direction no s that way and no R_i. 0.8.22 gave
``B_i_reason`` … only for a run in one direction: null beside null at such targets.

The record is simulated here: an axis with a once-a-turn error of 6″ and a twice-a-turn one
of 2″, a backlash of 1.5″, 5 runs each way at 13 targets with 0.4″ of noise, rounded to
0.01″; at 90 the backward approaches were not made, at 180 only the first run's, at 270 only
the first run's forward one."""

from __future__ import annotations

import contextlib
import io
import json
import re
from pathlib import Path

import numpy as np

from app.main import main

SETTINGS = ["--misalignment-u", "0.2", "--reference-resolution", "0.1", "--temperature-u", "0.2"]
TARGETS = np.arange(0, 361, 30)
NO_BACKWARD, ONE_BACKWARD, ONE_FORWARD = 90, 180, 270


def _kept(target: int, run: int, sign: str) -> bool:
    if sign == "-":
        return target != NO_BACKWARD and (target != ONE_BACKWARD or run == 1)
    return target != ONE_FORWARD or run == 1


def _record(path: Path) -> None:
    rng = np.random.default_rng(74)
    rows = ["target,run,direction,deviation"]
    for run in range(1, 6):
        for sign, order in (("+", TARGETS), ("-", TARGETS[::-1])):
            for t in order:
                true = (6.0 * np.sin(np.radians(t) + 0.3) + 2.0 * np.cos(2 * np.radians(t))
                        + (0.75 if sign == "+" else -0.75))
                if _kept(int(t), run, sign):
                    rows.append(f"{t},{run},{sign},{round(true + rng.normal(0, 0.4), 2)}")
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")


def _named(reason: str | None) -> set[float]:
    """The targets a reason names ("null at target(s) 90, 180: …; null at target(s) …")."""
    out: set[float] = set()
    for group in re.findall(r"null at target\(s\) ([^:]+):", reason or ""):
        out |= {float(t) for t in group.split(", ")}
    return out


def test_every_null_per_target_figure_of_a_run_in_both_directions_says_why(tmp_path):
    record = tmp_path / "both.csv"
    _record(record)
    said = io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", "positioning", str(record), *SETTINGS, "--json"]) == 0
    per_target = json.loads(said.getvalue())["per_target"]
    # which targets each figure cannot have, from the record's own design
    expected = {"mean_up": set(), "mean_down": {NO_BACKWARD},
                "s_up": {ONE_FORWARD}, "s_down": {NO_BACKWARD, ONE_BACKWARD},
                "band_2s_up": {ONE_FORWARD}, "band_2s_down": {NO_BACKWARD, ONE_BACKWARD},
                "B_i": {NO_BACKWARD}, "M_i": {NO_BACKWARD},
                "R_i": {NO_BACKWARD, ONE_BACKWARD, ONE_FORWARD}}
    targets = per_target["target"]
    for key, missing in expected.items():
        nulls = {t for t, v in zip(targets, per_target[key], strict=True) if v is None}
        assert nulls == missing, (key, nulls)
        reason = per_target[f"{key}_reason"]
        assert (reason is None) == (not missing), (key, reason)
        assert _named(reason) == missing, (key, reason)
    assert "both approach directions" in per_target["B_i_reason"]
    assert "↓" in per_target["mean_down_reason"]
    assert "only once in the ↓ direction" in per_target["s_down_reason"]
    assert "only once in a direction" in per_target["R_i_reason"]
