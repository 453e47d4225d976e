"""Readings typed from a noise-free signal: the fit's scatter cannot show a rounding that
the fitted harmonics take up whole (sin and cos typed to four decimals at N = 8: the
rounding of ±0.70710678 to ±0.7071 is (sin θ + sin 3θ)/√2 times itself, so the residuals
are 10⁻¹⁷ V and the summary printed "A1 = 0.999995204977007668 ± 0.000000000000000020 V").
The last digit typed is a resolution of its own, ±δ/2 rectangular a reading (δ = 0.0001 V
here), and with the readings of a phase alike in every period the fit's coefficients carry
it averaged over the N phases, not the n readings: an amplitude's standard uncertainty is
at least δ/√12·√(2/N), which the summary and the JSON print; with an ADC LSB stated, that is
the resolution instead.

The record is written here from the signal's own formula (nothing from models/).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

from app.main import main

PER_PERIOD, PERIODS, STEP_V = 8, 3, 0.0001


def _typed(tmp_path: Path) -> Path:
    """sin θ and cos θ at N equal steps over whole periods, typed to four decimals."""
    rows = ["u_sin,u_cos"]
    for i in range(PER_PERIOD * PERIODS):
        theta = 2 * math.pi * i / PER_PERIOD
        rows.append(f"{math.sin(theta):.4f},{math.cos(theta):.4f}")
    path = tmp_path / "typed.csv"
    path.write_text("\n".join(rows) + "\n", encoding="utf-8")
    return path


def _run(tmp_path: Path, capsys, *more: str) -> str:
    code = main(["analyze", "fringe", str(_typed(tmp_path)), "--lines-per-rev", "16384",
                 "--samples-per-period", str(PER_PERIOD), "--max-order", "3",
                 "--language", "en", *more])
    out = capsys.readouterr()
    assert code == 0, out.err
    return out.out


def _least_u(step_v: float) -> float:
    """An amplitude's standard uncertainty from the rounding alone, the same at a phase in
    every period: δ/√12 a phase, over N phases."""
    return step_v / math.sqrt(12.0) * math.sqrt(2.0 / PER_PERIOD)


def test_the_summary_prints_each_amplitudes_u_at_the_typed_digit(tmp_path, capsys):
    said = _run(tmp_path, capsys)
    for channel in ("A", "B"):
        line = next(line for line in said.splitlines() if f"{channel}1 = " in line)
        u_text = re.search(rf"{channel}1 = [\d.]+ ± ([\d.]+) V", line).group(1)
        assert len(u_text.split(".")[1]) <= 7, line  # (was 18 decimals)
        assert float(u_text) >= 0.99 * _least_u(STEP_V), line


def test_the_json_states_the_typed_resolution_in_every_amplitudes_u(tmp_path, capsys):
    data = json.loads(_run(tmp_path, capsys, "--json"))
    k = data["parameters_coverage_factor"]
    for channel in ("sin", "cos"):
        params = data[f"{channel}_params"]
        for order in (1, 3):
            assert params[f"expanded_uncertainty_A{order}"] >= 0.99 * k * _least_u(STEP_V)
        assert params["expanded_uncertainty_A0"] >= (
            0.99 * k * STEP_V / math.sqrt(12.0) / math.sqrt(PER_PERIOD))


def test_an_adc_lsb_stated_is_the_resolution_instead(tmp_path, capsys):
    lsb_mv = 1.0  # ten times the typed digit
    data = json.loads(_run(tmp_path, capsys, "--json", "--adc-lsb-mv", str(lsb_mv)))
    k = data["parameters_coverage_factor"]
    for channel in ("sin", "cos"):
        assert data[f"{channel}_params"]["expanded_uncertainty_A1"] >= (
            0.99 * k * _least_u(lsb_mv * 1e-3))
