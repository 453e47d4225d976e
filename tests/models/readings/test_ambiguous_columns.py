"""Contract review 75 F6: a file with two columns of one header (ac_x_arcsec twice,
azimuth_deg twice) was analysed with the first and no word, and a column mapping giving one
header to two keys was not refused. Now: exit 2 and one line naming the header and both
column positions, in every workbench (the reader is shared), and the window's import the
same refusal (it reads through map_columns)."""

from __future__ import annotations

import pytest

from app.main import main
from models.polygon.analysis import POLYGON
from models.readings.tabular_import import TableImportError, map_columns, read_table
from models.theodolite.analysis import THEODOLITE


def _write(path, lines: list[str]):
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def _polygon_with_two_ac_x(tmp_path, samples_dir):
    lines = (samples_dir / "polygon_sample.csv").read_text(encoding="utf-8-sig").splitlines()
    out = [lines[0] + ",ac_x_arcsec"]
    # the second column differs from the first (a wrong copy): which is meant is not clear
    out += [line + ",0" for line in lines[1:] if line.strip()]
    return _write(tmp_path / "two_ac_x.csv", out)


def test_two_columns_of_one_header_are_refused_naming_both(tmp_path, samples_dir, capsys):
    path = _polygon_with_two_ac_x(tmp_path, samples_dir)
    assert main(["analyze", "polygon", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"{path}: the header names columns 4 and 8 alike ('ac_x_arcsec', "
                   "ac_x_arcsec): which holds the readings is not clear; rename or delete one"]
    with pytest.raises(TableImportError, match="columns 4 and 8 alike"):
        map_columns(read_table(path), POLYGON.columns)  # the window's import too


def test_two_headers_alike_after_normalising_are_refused(tmp_path, capsys):
    path = _write(tmp_path / "t.csv", ["theta_deg,azimuth_deg,elevation_deg,Azimuth (deg)",
                                       "0,10,90,11", "90,100,90,101", "180,190,90,191",
                                       "270,280,90,281"])
    assert main(["analyze", "theodolite", str(path), "--json"]) == 2
    captured = capsys.readouterr()
    assert captured.out == ""
    assert captured.err.strip() == (
        f"{path}: the header names columns 2 and 4 alike ('azimuth_deg', azimuth_deg): which "
        "holds the readings is not clear; rename or delete one")


def test_a_duplicate_column_no_workbench_reads_is_no_matter(tmp_path):
    path = _write(tmp_path / "t.csv", ["theta_deg,azimuth_deg,elevation_deg,note,note",
                                       "0,10,90,a,b", "90,100,90,c,d"])
    assert map_columns(read_table(path), THEODOLITE.columns)[1][:3] == ["90", "100", "90"]


def test_one_header_mapped_to_two_keys_is_refused(samples_dir, capsys):
    sample = samples_dir / "theodolite_sample.csv"
    assert main(["analyze", "theodolite", str(sample), "--columns",
                 "azimuth_deg=azimuth_deg,elevation_deg=azimuth_deg"]) == 2
    assert capsys.readouterr().err.strip() == (
        f"{sample}: column mapping gives the header 'azimuth_deg' to both azimuth_deg and "
        "elevation_deg: one column holds one quantity; map each to its own header")


def test_a_mapping_onto_a_column_another_key_has_is_refused(samples_dir, capsys):
    sample = samples_dir / "theodolite_sample.csv"
    assert main(["analyze", "theodolite", str(sample), "--columns",
                 "elevation_deg=azimuth_deg"]) == 2
    assert capsys.readouterr().err.strip() == (
        f"{sample}: column 2 ('azimuth_deg') is taken for both azimuth_deg and elevation_deg: "
        "one column holds one quantity; map each to its own header")
