"""Contract review 75 F7: one numbering of rows a command. A bad cell was named by the
file's line (header = row 1) and the checks made after parsing by that line − 1 (the
window's sheet row): a technician sent to "row 29" checked the wrong reading. The command
line now names the file's line in every message (and takes it for --reference-row); the
JSON's incomplete.first_row/last_row keep their meaning (the sheet's rows) beside
first_line/last_line. One mapping (app.cli.by_file_line), every workbench."""

from __future__ import annotations

import csv
import io
import json

import pytest

from app.main import main


def _table(path) -> list[list[str]]:
    with open(path, encoding="utf-8-sig", newline="") as handle:
        return list(csv.reader(handle))


def _write(path, table: list[list[str]], above: list[str] = ()):
    out = io.StringIO()
    for line in above:
        out.write(line + "\n")
    csv.writer(out, lineterminator="\n").writerows(table)
    path.write_text(out.getvalue(), encoding="utf-8")
    return path


def _err(capsys, *args) -> str:
    assert main(["analyze", *map(str, args)]) == 2
    captured = capsys.readouterr()
    lines = captured.err.strip().splitlines()
    assert len(lines) == 1 and captured.out == ""
    return lines[0]


@pytest.mark.parametrize("kind, column, extra", [
    ("polygon", "ac_x_arcsec", ()),
    ("fringe", "u_sin", ("--lines-per-rev", "16384", "--samples-per-period", "64")),
    ("crosscal", "encoder_deg", ()),
    ("positioning", "target", ()),
])
def test_a_check_after_parsing_names_the_files_line(kind, column, extra, samples_dir,
                                                    tmp_path, capsys):
    table = _table(samples_dir / f"{kind}_sample.csv")
    c = table[0].index(column)
    table[6][c] = "1e+308"  # line 7 of the file (the header is line 1)
    err = _err(capsys, kind, _write(tmp_path / "huge.csv", table), *extra)
    assert ": row 7" in err and "row 6" not in err, err
    # a cell that does not parse at the same line is named alike
    table[6][c] = "abc"
    err = _err(capsys, kind, _write(tmp_path / "text.csv", table), *extra)
    assert ": row 7, column" in err, err


def test_a_title_above_the_header_is_counted(samples_dir, tmp_path, capsys):
    table = _table(samples_dir / "polygon_sample.csv")
    table[6][table[0].index("ac_x_arcsec")] = "1e+308"  # 2 lines below: line 9
    path = _write(tmp_path / "titled.csv", table, above=["Polygon test, bench 2", ""])
    err = _err(capsys, "polygon", path)
    assert err == (f"{path}: row 9, column 'ac_x_arcsec': 1e+308\" is beyond ±3600\" and "
                   "cannot be a reading of a polygon test")


def test_the_theodolite_names_the_line_of_its_largest_residual(samples_dir, tmp_path, capsys):
    table = _table(samples_dir / "theodolite_sample.csv")
    table[29][2] = "-7"  # line 30: an elevation no set-up explains
    err = _err(capsys, "theodolite", _write(tmp_path / "bad_e.csv", table))
    assert "is at row 30:" in err, err


def test_reference_row_is_the_files_line(samples_dir, capsys):
    sample = samples_dir / "theodolite_sample.csv"
    last_line = len(_table(sample))  # the header is line 1: the last reading's line
    assert main(["analyze", "theodolite", str(sample), "--json", "--reference-row",
                 str(last_line)]) == 0, capsys.readouterr().err
    capsys.readouterr()
    err = _err(capsys, "theodolite", sample, "--reference-row", "1")  # the header's line
    assert err.endswith("reference row 1 is blank, unreadable or missing")


def test_a_set_in_progress_names_the_files_lines_and_the_json_keeps_its_rows(samples_dir,
                                                                             tmp_path, capsys):
    table = _table(samples_dir / "polygon_sample.csv")
    path = _write(tmp_path / "partial.csv", table[:29])  # set 2: lines 27–29, 3 of 24 faces
    assert main(["analyze", "polygon", str(path)]) == 0
    assert "In progress: set 2: 3 of 24 faces (rows 27–29)" in capsys.readouterr().out
    assert main(["analyze", "polygon", str(path), "--json"]) == 0
    incomplete = json.loads(capsys.readouterr().out)["incomplete"]
    assert (incomplete["first_row"], incomplete["last_row"]) == (26, 28)  # the sheet's rows
    assert (incomplete["first_line"], incomplete["last_line"]) == (27, 29)
