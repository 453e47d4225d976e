"""An absurd figure in a message is written in scientific form (contract75 F13: an encoder
cell of 1e308 in a cross-calibration file was printed as a 309-digit number)."""

from __future__ import annotations

from pathlib import Path

from app.main import main
from models.number_text import fixed

SAMPLE = Path(__file__).resolve().parents[2] / "resources" / "samples" / "crosscal_sample.csv"


def test_fixed_keeps_a_reading_s_decimals_and_writes_an_absurd_one_short():
    assert fixed(359.99994, 4) == "359.9999"
    assert fixed(12.5, 4) == "12.5000" and fixed(-0.25, 3, sign=True) == "-0.250"
    assert fixed(0.25, 3, sign=True) == "+0.250"
    assert fixed(1e308, 4) == "1e+308" and fixed(-2.5e12, 4) == "-2.5e+12"
    assert fixed(999_999_999.0, 1) == "999999999.0"


def test_a_cross_calibration_encoder_cell_of_1e308_is_said_in_a_short_line(tmp_path, capsys):
    lines = SAMPLE.read_text(encoding="utf-8").splitlines()
    header = lines[0].split(",")
    column = header.index("encoder_deg")
    cells = lines[5].split(",")
    cells[column] = "1e308"
    lines[5] = ",".join(cells)
    bad = tmp_path / "crosscal_huge.csv"
    bad.write_text("\n".join(lines) + "\n", encoding="utf-8")
    assert main(["analyze", "crosscal", str(bad), "--language", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and len(err[0]) < 300, err
    assert f"{bad}: row " in err[0] and "column 'encoder_deg': 1e+308°" in err[0]
