"""Positioning in one approach direction (assessment 72 M6): VDI/DGQ 3441's P and U_max (and
ISO 230-2's figures of both directions) are not evaluated, and the JSON's ``interval_reason``
and the results workbook's *Statistics* row say why (0.8.20: null beside null, "not
evaluated | —", the reason only in the PDF's and the DCC's remark).

The record is simulated here: an axis with a once-a-turn error of 6″ and a twice-a-turn one
of 2″, 5 runs approached from below at 13 targets, each reading with 0.5″ of noise,
rounded to 0.01″."""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

import numpy as np
import openpyxl

from app.main import main

SETTINGS = ["--misalignment-u", "0.2", "--reference-resolution", "0.1", "--temperature-u", "0.2"]


def _record(path: Path) -> None:
    rng = np.random.default_rng(72)
    targets = np.arange(0, 361, 30)
    rows = ["target,run,direction,deviation"]
    for run in range(1, 6):
        for t in targets:
            true = 6.0 * np.sin(np.radians(t) + 0.3) + 2.0 * np.cos(2 * np.radians(t))
            rows.append(f"{t},{run},+,{round(true + rng.normal(0, 0.5), 2)}")
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")


def test_one_direction_says_why_p_and_u_are_not_evaluated(tmp_path):
    record, book = tmp_path / "up.csv", tmp_path / "up.xlsx"
    _record(record)
    said = io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", "positioning", str(record), *SETTINGS, "--json",
                     "--results", str(book)]) == 0
    data = json.loads(said.getvalue())
    for key in ("P", "U_max"):
        figure = data["vdi3441_figures"][key]
        assert figure["value"] is None
        assert "both approach directions" in (figure["interval_reason"] or ""), (key, figure)
    for key in ("A", "E", "M", "R", "B"):
        figure = data["iso230_2_figures"][key]
        assert figure["value"] is None and figure["interval_reason"], (key, figure)
    # a figure of one direction keeps its value and no reason
    assert data["iso230_2_figures"]["E_up"]["value"] is not None
    assert data["iso230_2_figures"]["E_up"]["interval_reason"] is None
    rows = [row for row in openpyxl.load_workbook(book)["Statistics"].iter_rows(values_only=True)
            if row and isinstance(row[0], str) and row[0].startswith(("P:", "U_max:"))]
    assert len(rows) == 2, rows
    for row in rows:
        assert any("both approach directions" in str(cell) for cell in row), row


def test_every_null_figure_of_one_direction_says_why(tmp_path):
    """Assessment 73 M3: A↓, E↓ and R↓ (the direction not measured) and the per-target B_i,
    M_i and R_i (both directions) were null with no reason; every null figure now has one
    beside it (``interval_reason``; per target ``B_i_reason`` …), and every figure given
    has none."""
    record = tmp_path / "up.csv"
    _record(record)
    said = io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(io.StringIO()):
        assert main(["analyze", "positioning", str(record), *SETTINGS, "--json"]) == 0
    data = json.loads(said.getvalue())
    for group in ("iso230_2_figures", "vdi3441_figures"):
        for key, figure in data[group].items():
            if figure["value"] is None:
                assert figure["interval_reason"], (group, key, figure)
    for key in ("A_down", "E_down", "R_down"):
        assert "↓" in data["iso230_2_figures"][key]["interval_reason"], key
    per_target = data["per_target"]
    for key in ("B_i", "M_i", "R_i"):
        assert per_target[key] is None or all(v is None for v in per_target[key])
        assert "both approach directions" in (per_target[f"{key}_reason"] or ""), key
