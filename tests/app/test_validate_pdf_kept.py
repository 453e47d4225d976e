"""``validate --pdf`` never replaces a file that is no PDF (contract75 F5: a copy of the
polygon readings named as --pdf became the validation report, exit 0), as
``analyze --certificate`` refuses the same target; and --help states the --trials bound
the command enforces (contract75 F13)."""

from __future__ import annotations

from pathlib import Path

import pytest

from app.main import main

SAMPLES = Path(__file__).resolve().parents[2] / "resources" / "samples"


def test_a_readings_csv_named_as_pdf_is_refused_and_kept(tmp_path, capsys):
    victim = tmp_path / "victim_readings.csv"
    readings = (SAMPLES / "polygon_sample.csv").read_bytes()
    victim.write_bytes(readings)
    assert main(["validate", "--pdf", str(victim), "--trials", "100", "--language", "en"]) == 2
    captured = capsys.readouterr()
    assert captured.err.strip().splitlines() == [
        f"anglebench validate: --pdf {victim} exists and is not a PDF: it would be replaced "
        "with no way back; nothing was written: choose another name"]
    assert captured.out == ""  # refused before any case ran
    assert victim.read_bytes() == readings
    assert sorted(p.name for p in tmp_path.iterdir()) == ["victim_readings.csv"]


def test_analyze_certificate_refuses_the_same_target(tmp_path, capsys):
    victim = tmp_path / "victim_readings.csv"
    victim.write_bytes((SAMPLES / "polygon_sample.csv").read_bytes())
    assert main(["analyze", "polygon", str(SAMPLES / "polygon_sample.csv"), "--certificate",
                 str(victim), "--language", "en"]) == 2
    assert "exists and is not a PDF: it would be replaced with no way back" in \
        capsys.readouterr().err


def test_help_states_the_trials_bound(capsys):
    with pytest.raises(SystemExit):
        main(["validate", "--help", "--language", "en"])
    help_text = " ".join(capsys.readouterr().out.split())
    assert "100 to 100000 (default 200)" in help_text
    assert main(["validate", "--trials", "5", "--language", "en"]) == 2
    assert "--trials must be 100 to 100000" in capsys.readouterr().err
