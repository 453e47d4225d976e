"""gui80: with n readings per point the positioning summary counted the averaged points as
readings ("3 readings" beside the table's caption "6 used"); it says the readings and the
points they make."""

from __future__ import annotations

from app.main import main
from tests.app.test_cli_incomplete import _rows, _write


def test_the_summary_counts_the_readings_and_the_points_they_make(capsys, samples_dir,
                                                                   tmp_path):
    header, rows = _rows(samples_dir / "positioning_sample.csv")
    twice = _write(tmp_path / "twice.csv", header, [r for row in rows for r in (row, row)])
    assert main(["analyze", "positioning", twice, "--readings-per-point", "2"]) == 0
    out = capsys.readouterr().out
    assert f", {2 * len(rows)} readings ({len(rows)} points of 2), " in out, out
    assert main(["analyze", "positioning", str(samples_dir / "positioning_sample.csv")]) == 0
    assert f", {len(rows)} readings, " in capsys.readouterr().out
