"""contract75 F13: an absurd encoder cell (1e308) was printed as a 309-digit number in the
polygon's refusal; it is said in scientific form, the refusal one line naming the row."""

from __future__ import annotations

import csv

from app.main import main


def test_a_polygon_encoder_cell_of_1e308_is_said_in_scientific_form(tmp_path, samples_dir,
                                                                    capsys):
    with (samples_dir / "polygon_sample.csv").open(encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    column = rows[0].index("encoder_deg")
    rows[5][column] = "1e308"
    path = tmp_path / "huge.csv"
    with path.open("w", newline="", encoding="utf-8") as handle:
        csv.writer(handle).writerows(rows)
    assert main(["analyze", "polygon", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "huge.csv" in err
    assert "1e+308" in err and "0" * 30 not in err, err
