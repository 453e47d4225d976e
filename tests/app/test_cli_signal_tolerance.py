"""``anglebench analyze fringe`` with --signal-preset and --interpolator-table (#45)."""

from __future__ import annotations

import json

import pytest

from app.main import main
from models.fringe.signal_tolerance import LAB_DEFAULTS_KEY
from tests.fringe_signal_simulator import Head, equal_phase


def run_cli(capsys, *args):
    code = main(["analyze", *args, "--language", "en"])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


@pytest.fixture
def record(tmp_path):
    """A 1 Vpp head at the band's upper edge for A (1.2 Vpp), B at 1.0 Vpp, 4° quadrature."""
    theta = equal_phase(16, 64)
    u_a, u_b = Head(peak_a=0.6, peak_b=0.5, quadrature_deg=4.0, offset_a=0.01,
                    harmonics={3: (0.0, 0.0)}).signals(theta)
    path = tmp_path / "head.csv"
    path.write_text("u_sin,u_cos\n" + "\n".join(f"{a:.12f},{b:.12f}" for a, b in zip(u_a, u_b,
                                                                                    strict=True)))
    return path


def test_preset_judgement_in_json_and_summary(capsys, record):
    code, out, err = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64",
                             "--json", "--signal-preset", "heidenhain_1vpp")
    assert code == 0, err
    data = json.loads(out)
    tol = data["signal_tolerance"]
    assert tol["preset"] == "heidenhain_1vpp" and tol["guard_band"] is None
    q = tol["quantities"]
    assert q["amplitude_a"]["value"] == pytest.approx(1.2, abs=1e-6)
    assert q["amplitude_a"]["state"] == "inside"  # on the edge (to the 12 digits written)
    assert q["amplitude_ratio"]["value"] == pytest.approx(1.0 / 1.2, abs=1e-6)
    assert q["phase_deviation"]["value"] == pytest.approx(4.0, abs=1e-6)
    assert q["offset_a"]["value"] == pytest.approx(100 * 0.01 / 1.2, abs=1e-6)
    assert len(data["signal_quality"]) == 16 and data["signal_quality"][0]["states"]
    code, out, err = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64",
                             "--signal-preset", "heidenhain_1vpp")
    assert "amplitude_a = 1.2 Vpp: inside (band 0.6 … 1.2)" in out
    assert "not a statement of conformity" in out


def test_fringe_json_has_signal_quality_without_a_preset(capsys, record):
    code, out, _ = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64",
                           "--json")
    data = json.loads(out)
    assert code == 0 and "signal_tolerance" not in data
    assert data["signal_quality_units"]["offset_a"] == "V"
    assert data["signal_quality"][0]["offset_a"] == pytest.approx(0.01, abs=1e-9)


def test_lab_presets_file(capsys, record, tmp_path):
    lab = tmp_path / "lab.json"
    lab.write_text(json.dumps({LAB_DEFAULTS_KEY: [
        {"key": "ours", "name": "our mounting band", "interface": "1Vpp", "source": "lab rule",
         "bands": [{"quantity": "amplitude_a", "unit": "Vpp", "inside": [0.9, 1.1],
                    "outer": [0.6, 1.2]}]}]}))
    code, out, err = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64",
                             "--json", "--signal-presets", str(lab), "--signal-preset", "ours")
    assert code == 0, err
    assert json.loads(out)["signal_tolerance"]["quantities"]["amplitude_a"]["state"] == "outer"


def test_interpolator_table_written_and_in_json(capsys, record, tmp_path):
    out_hex = tmp_path / "lut.hex"
    code, out, err = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64",
                             "--json", "--interpolator-table", str(out_hex),
                             "--table-entries", "64", "--table-bits", "8",
                             "--table-interpolation", "linear")
    assert code == 0, err
    table = json.loads(out)["interpolator_table"]
    assert table["entries"] == 64 and len(table["codes"]) == 64
    assert table["predicted_residual"]["max_abs_arcsec"] < \
        table["error_without_table"]["max_abs_arcsec"] / 10
    assert out_hex.read_text().endswith(":00000001FF\n")
    assert "Interpolator table (generic, 64 entries of 8 bits" in err


def test_interpolator_table_refused_names_what_would(capsys, record, tmp_path):
    out_h = tmp_path / "lut.h"
    code, _, err = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64",
                           "--interpolator-table", str(out_h), "--table-entries", "64",
                           "--table-bits", "4", "--table-max-residual", "0.01")
    assert code == 2 and not out_h.exists()
    assert "no table" in err and "would reach it" in err and "arcsec" in err


@pytest.mark.parametrize("extra, words", [
    (["--signal-preset", "nope"], "no signal tolerance preset 'nope'"),
    (["--interpolator-table", "x.bin"], "write .csv, .h or .hex"),
    (["--table-bits", "8"], "give --interpolator-table"),
    (["--interpolator-table", "x.h", "--table-chip", "ic-tw8", "--table-entries", "128"],
     "takes entries 64"),
    (["--signal-scale", "-1", "--signal-preset", "heidenhain_1vpp"], "positive"),
])
def test_bad_options_refused(capsys, record, extra, words):
    code, _, err = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64", *extra)
    assert code == 2 and words in err


def test_options_are_fringes_and_the_output_guard_holds(capsys, record, samples_dir):
    code, _, err = run_cli(capsys, "theodolite", str(samples_dir / "theodolite_sample.csv"),
                           "--signal-preset", "heidenhain_1vpp")
    assert code == 2 and "applies to fringe" in err
    before = record.read_bytes()
    code, _, err = run_cli(capsys, "fringe", str(record), "--samples-per-period", "64",
                           "--interpolator-table", str(record.with_suffix(".csv")))
    assert code == 2 and record.read_bytes() == before
