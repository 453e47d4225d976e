"""row81: a file whose last row holds part of a reading (saved between typing the
autocollimator's x and the encoder) is a run in progress on the command line too, as a point
short of its n readings is (test_cli_short_last_point.py): the complete rows' figures, the
row said in progress, a certificate waits for it. On main the row was taken for a row
waiting for its reading and left out without a word: the summary and the JSON said nothing
in progress, and a certificate was issued without it.

A reading cell blank in any other row, or a cell typed wrong in the last, is still refused."""

from __future__ import annotations

import pytest

from app.main import main
from tests.app.test_cli_incomplete import _json, _rows, _units, _write

pytestmark = pytest.mark.slow  # each workbench's analysis, a few times


def _blank(row: list[str], column: int) -> list[str]:
    return [("" if i == column else cell) for i, cell in enumerate(row)]


def test_a_polygon_files_last_row_half_typed_is_in_progress(capsys, samples_dir, tmp_path):
    header, rows = _rows(samples_dir / "polygon_sample.csv")
    sets = _units(rows, header.index("set"))
    encoder = header.index("encoder_deg")
    alone = _json(capsys, "polygon", _write(tmp_path / "a.csv", header, sets[0]))
    path = _write(tmp_path / "b.csv", header, [*sets[0], _blank(sets[1][0], encoder)])
    partial = _json(capsys, "polygon", path)
    assert alone.pop("incomplete") is None
    got = partial.pop("incomplete")
    line = len(sets[0]) + 2  # the header line 1
    assert got["text"] == f"row {line}: encoder a [deg] not typed yet"
    assert (got["unit"], got["first_row"], got["last_row"]) == ("row", line - 1, line - 1)
    assert (got["first_line"], got["last_line"]) == (line, line)
    assert got["typing"] == {"row": line - 1, "line": line, "blank": ["encoder_deg"]}
    assert partial == alone  # set 1's figures, the row in none
    assert main(["analyze", "polygon", path]) == 0
    assert (f"In progress: row {line}: encoder a [deg] not typed yet (rows {line}–{line}); "
            "its readings enter no figure") in capsys.readouterr().out
    pdf = tmp_path / "c.pdf"
    assert main(["analyze", "polygon", path, "--certificate", str(pdf)]) == 2
    assert (f"no certificate was written: row {line}: encoder a [deg] not typed yet is not "
            "complete; a certificate waits for it") in capsys.readouterr().err
    assert not pdf.exists()

    # within a set in progress: said after it
    got = _json(capsys, "polygon", _write(tmp_path / "d.csv", header, [
        *sets[0], *sets[1][:3], _blank(sets[1][3], encoder)]))["incomplete"]
    assert got["text"] == f"set 2: 3 of 24 faces, row {line + 3}: encoder a [deg] not typed yet"
    assert (got["first_line"], got["last_line"]) == (line, line + 3)


def test_a_half_typed_row_elsewhere_or_a_cell_typed_wrong_is_refused(capsys, samples_dir,
                                                                     tmp_path):
    header, rows = _rows(samples_dir / "polygon_sample.csv")
    sets = _units(rows, header.index("set"))
    encoder = header.index("encoder_deg")
    middle = [*sets[0][:5], _blank(sets[0][5], encoder), *sets[0][6:]]
    assert main(["analyze", "polygon", _write(tmp_path / "m.csv", header, middle)]) == 2
    assert "row 7, column 'encoder_deg': empty; a value is needed here" in \
        capsys.readouterr().err
    wrong = [*sets[0], [*sets[1][0][:encoder], "12x", *sets[1][0][encoder + 1:]]]
    assert main(["analyze", "polygon", _write(tmp_path / "w.csv", header, wrong)]) == 2
    assert f"row {len(sets[0]) + 2}, column 'encoder_deg'" in capsys.readouterr().err


def test_a_theodolite_files_last_row_half_typed_is_in_progress(capsys, samples_dir, tmp_path):
    header, rows = _rows(samples_dir / "theodolite_sample.csv")
    alone = _json(capsys, "theodolite", _write(tmp_path / "a.csv", header, rows[:9]))
    partial = _json(capsys, "theodolite", _write(tmp_path / "b.csv", header,
                                                 [*rows[:9], _blank(rows[9], 2)]))
    got = partial.pop("incomplete")
    alone.pop("incomplete")
    assert got["text"] == "row 11: E / V [deg] not typed yet"
    assert partial == alone
