"""One cell typed wrong, or a wrong option, in a record that is otherwise complete (contract
review 75 F2, F3, F8): the command exits 2 with one line naming the file, the row and the
cell, and prints no result; before, each exited 0 with figures from the bad data.

F2: the fringe sample with θ = 1e308, or θ = 12°30'15.5" between 28.125° and 33.75°, on its
line 7 (compensated 0.451" and 4.351" printed for 0.038"). F3: the fringe sample without its
θ column and N = 63 for its 64 samples a period (10.66" as found printed for 0.991"). F8: the
positioning sample with target 150 of run 1 typed 12°30'15.5" (a 14th target, run 5 "in
progress", 26 readings dropped, A and R not evaluated).
"""

from __future__ import annotations

import pytest

from app.main import main
from tests.app.test_cli_incomplete import _rows, _write


def _refused(capsys, *argv):
    code = main(["analyze", *argv])
    captured = capsys.readouterr()
    assert code == 2, captured.out
    assert captured.out == ""  # no figure from bad data
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in captured.err, captured.err
    return lines[0]


@pytest.mark.parametrize("typed", ["1e308", "12°30'15.5\""])
def test_a_theta_cell_typed_wrong_is_refused_naming_its_row(capsys, tmp_path, samples_dir,
                                                            typed):
    header, rows = _rows(samples_dir / "fringe_sample.csv")
    assert header[2] == "theta_deg" and rows[5][2] == "28.1250"
    rows[5][2] = typed  # line 7 of the file, the sixth sample
    path = _write(tmp_path / "fringe_typo.csv", header, rows)
    line = _refused(capsys, "fringe", path)
    assert line.startswith(f"{path}: row ") and "column 'theta_deg'" in line
    row = int(line.split(": row ")[1].split(",")[0])
    assert row in (6, 7)  # the sheet's row or the file's line (review 75 F7 decides which)
    assert ("beyond ±1e+09°" in line) if typed == "1e308" else \
        ("θ = 12.5043° is not the phase of its signals" in line)


def test_the_untouched_fringe_sample_still_gives_its_figures(capsys, samples_dir):
    assert main(["analyze", "fringe", str(samples_dir / "fringe_sample.csv")]) == 0
    out = capsys.readouterr().out
    assert "peak-to-peak 0.991\"" in out and "peak-to-peak 0.038\"" in out


def test_a_wrong_samples_per_period_is_refused_and_the_right_one_analysed(capsys, tmp_path,
                                                                        samples_dir):
    header, rows = _rows(samples_dir / "fringe_sample.csv")
    path = _write(tmp_path / "fringe_notheta.csv", header[:2], [r[:2] for r in rows])
    line = _refused(capsys, "fringe", path, "--samples-per-period", "63")
    assert line.startswith(f"{path}: the signals do not follow N = 63 samples per period")
    assert "they show 64 samples a period" in line
    assert main(["analyze", "fringe", path, "--samples-per-period", "64"]) == 0
    out = capsys.readouterr().out
    assert "peak-to-peak 0.991\"" in out and "peak-to-peak 0.038\"" in out


def test_a_mistyped_target_in_a_complete_positioning_file_is_refused(capsys, tmp_path,
                                                                     samples_dir):
    header, rows = _rows(samples_dir / "positioning_sample.csv")
    assert rows[5][:3] == ["150", "1", "+"]
    rows[5][0] = "12°30'15.5\""  # line 7 of the file
    path = _write(tmp_path / "positioning_typo.csv", header, rows)
    line = _refused(capsys, "positioning", path)
    assert line.startswith(f"{path}: row ")
    assert int(line.split(": row ")[1].split(":")[0]) in (6, 7)
    assert ("target 12.5043 is read in run 1 only, while target 150 has no reading in that "
            "direction in run 1, which the other runs read") in line
    assert "in progress" not in line  # run 5 is complete: it is not left out


@pytest.mark.parametrize("case", ["last run complete", "last run in progress", "no run column"])
def test_a_mistyped_target_elsewhere_is_refused_naming_its_row(capsys, tmp_path, samples_dir,
                                                               case):
    header, rows = _rows(samples_dir / "positioning_sample.csv")
    if case == "no run column":  # the k-th approach to a target is run k
        header, rows = [header[0], *header[2:]], [[r[0], *r[2:]] for r in rows]
        at = 5
    else:
        at = 108  # run 5, + at 120
        assert rows[at][:3] == ["120", "5", "+"]
        rows = rows if case == "last run complete" else rows[:115]
    rows[at][0] = "155"
    path = _write(tmp_path / "positioning_typo.csv", header, rows)
    line = _refused(capsys, "positioning", path)
    assert line.startswith(f"{path}: row ") and "is read in run " in line
    assert "target 150 has no reading" in line if case == "no run column" else \
        "target 120 has no reading in that direction in run 5" in line
    assert int(line.split(": row ")[1].split(":")[0]) in (at + 1, at + 2)


@pytest.mark.parametrize("order, last_row", [
    ("linear", 14), ("linear", 40), ("linear", 59), ("linear", 110), ("linear", 129),
    ("pilgrim step", 34), ("pilgrim step", 59), ("pilgrim step", 110), ("pilgrim step", 121)])
def test_a_positioning_run_in_progress_is_still_one(capsys, tmp_path, samples_dir, last_row,
                                                    order):
    """A run short of its last targets has not reached them yet, nor has the pilgrim step's
    last target its later runs: such targets are read in one run only, and are no typos."""
    header, rows = _rows(samples_dir / "positioning_sample.csv")
    if order == "pilgrim step":  # every approach of a target in turn
        rows = sorted(rows, key=lambda r: (float(r[0]), int(r[1]), r[2] != "+"))
    path = _write(tmp_path / "positioning_progress.csv", header, rows[:last_row])
    assert main(["analyze", "positioning", path]) == 0, capsys.readouterr().err
    out = capsys.readouterr().out
    if order == "linear" and last_row > 26:  # (run 1 alone is no run in progress)
        assert "In progress: run" in out
    elif order == "pilgrim step" and last_row % 10:
        assert "In progress: target" in out


def test_a_target_approached_once_with_no_reading_missing_is_no_typo(capsys, tmp_path):
    """Run 1 reads 0, 10 and 20; run 2 only 0 and 20: no target of run 1 is missing where
    10 was read, so 10 is a target approached once (its U not determined), not a typo."""
    path = tmp_path / "log.csv"
    path.write_text("target,run,direction,deviation\n0,1,+,1.0\n0,2,+,1.2\n10,1,+,2.0\n"
                    "20,1,+,2.5\n20,2,+,2.4\n", encoding="utf-8")
    assert main(["analyze", "positioning", str(path)]) == 0
    assert "3 targets 0…20°, 5 readings" in capsys.readouterr().out
