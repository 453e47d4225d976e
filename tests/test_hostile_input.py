"""The inputs a fuzzing round and a day of hostile files found: each is refused with
one line naming the file and what is wrong, or read as it should be — never a
traceback, a hang, an absurd figure at exit 0, or an input overwritten."""

from __future__ import annotations

import json
import time

import pytest

from app.main import main
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import TableImportError, read_table
from models.theodolite.analysis import THEODOLITE

THEODOLITE_ROWS = "\n".join(f"{t},{t + 0.001 * t},{0.1 + 0.001 * t}" for t in range(-20, 21, 2))


def run(capsys, *args) -> tuple[int, str, str]:
    code = main(["analyze", *args])
    out, err = capsys.readouterr()
    return code, out, err


def refused(capsys, *args) -> str:
    code, _, err = run(capsys, *args)
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1, err
    assert "Traceback" not in err
    return err


def test_cr_only_line_endings_read_like_any_file(tmp_path, capsys):
    path = tmp_path / "mac.csv"
    path.write_bytes(("theta_deg,azimuth_deg,elevation_deg\r" + THEODOLITE_ROWS.replace("\n", "\r")
                      + "\r").encode())
    code, out, err = run(capsys, "theodolite", str(path), "--json")
    assert code == 0, err and len(json.loads(out)["theta_deg"]) == 21


@pytest.mark.parametrize("content, message", [
    ("theta_deg,azimuth_deg,elevation_deg\n1,\"2\n", "a quote is not closed"),
    ("theta_deg,azimuth_deg,elevation_deg\n1," + "9" * 5000 + ",3\n", "a cell of 5000 characters"),
    ("theta_deg,azimuth_deg,elevation_deg\n1,2,\"a\rb\"\n", "row 2, column 'elevation_deg'"),
    ("theta_deg,azimuth_deg,elevation_deg\n1_0,2,3\n2,3,4\n3,4,5\n4,5,6\n", "'1_0' is not"),
])
def test_damaged_csv_is_one_line(tmp_path, capsys, content, message):
    path = tmp_path / "bad.csv"
    path.write_bytes(content.encode())
    assert message in refused(capsys, "theodolite", str(path))


def test_underscore_number_is_refused_on_both_paths():
    rows = [["1_0", "2", "3"]] + [[str(i), str(i), "0.1"] for i in range(1, 6)]
    parsed = ReadingsSheet(THEODOLITE.columns, rows).parse()
    assert parsed.errors and "'1_0' is not" in parsed.errors[0].reason
    fast = ReadingsSheet(THEODOLITE.columns, [["1_0", "2", "3"]] * 5000).parse()
    assert fast.n == 0 and len(fast.errors) == 5000


def test_xlsx_declaring_a_million_rows_is_read_in_moments(tmp_path):
    import openpyxl

    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["theta_deg", "azimuth_deg", "elevation_deg"])
    for i in range(5):
        sheet.append([i, i, 0.1])
    sheet["XFD1048576"] = "x"  # one far cell: the sheet claims A1:XFD1048576
    path = tmp_path / "bomb.xlsx"
    book.save(path)
    start = time.perf_counter()
    with pytest.raises(TableImportError, match="more than 10000 empty rows after row 6"):
        read_table(path)
    assert time.perf_counter() - start < 5.0


def test_xlsx_that_expands_beyond_any_readings_file_is_refused_unread(tmp_path, monkeypatch):
    import openpyxl

    from models.readings import tabular_import

    book = openpyxl.Workbook()
    for i in range(200):
        book.active.append([i, i, 0.1])
    path = tmp_path / "big.xlsx"
    book.save(path)
    monkeypatch.setattr(tabular_import, "MAX_XLSX_EXPANDED_BYTES", 1000)
    with pytest.raises(TableImportError, match="expands to"):
        read_table(path)


@pytest.mark.parametrize("metadata, message", [
    ('{"temperature_c": ' + "9" * 401 + "}", "'temperature_c'"),
    ("[" * 100_000 + "]" * 100_000, "nested too deep"),
    ('["a list"]', "must be a JSON object"),
    ('{"standards": [{"uncertainty_arcsec": 1e300}]}', "must be 0 to 3600"),
    ('{"item_resolution_arcsec": -5}', "must be 0 to 3600"),
    ('{"customer_name": {"a": 1}}', "must be text"),
])
def test_hostile_metadata_is_one_line(tmp_path, capsys, samples_dir, metadata, message):
    meta = tmp_path / "meta.json"
    meta.write_text(metadata)
    err = refused(capsys, "theodolite", str(samples_dir / "theodolite_sample.csv"),
                  "--certificate", str(tmp_path / "c.pdf"), "--metadata", str(meta))
    assert message in err


@pytest.mark.parametrize("flag", ["--results", "--certificate"])
def test_an_output_never_overwrites_the_input(tmp_path, capsys, samples_dir, flag):
    path = tmp_path / "in.csv"
    path.write_bytes((samples_dir / "theodolite_sample.csv").read_bytes())
    before = path.read_bytes()
    err = refused(capsys, "theodolite", str(path), flag, str(tmp_path / "." / "in.csv"))
    assert "is an input" in err and path.read_bytes() == before


def test_control_character_in_the_file_name_still_exports_xlsx(tmp_path, capsys, samples_dir):
    path = tmp_path / "run\x07one.csv"
    path.write_bytes((samples_dir / "theodolite_sample.csv").read_bytes())
    code, _, err = run(capsys, "theodolite", str(path), "--results", str(tmp_path / "r.xlsx"))
    assert code == 0, err


@pytest.mark.parametrize("rows, message", [
    ("\n".join(["5,5,0.1"] * 10), "all θ are equal"),
    ("1e308,1,0.1\n2,2,0.1\n3,3,0.1\n4,4,0.1\n5,5,0.1", "'theta_deg': 1e+308°"),
    ("1,1,114\n2,2,0.1\n3,3,0.1\n4,4,0.1\n5,5,0.1", "'elevation_deg': 114°"),
    ("1,1,-297\n2,2,0.1\n3,3,0.1\n4,4,0.1\n5,5,0.1", "'elevation_deg': -297°"),
    ("1,1,0.1\n1.00001,1,0.1\n1.00002,1,0.1\n1.00003,1,0.1", "too little rotation"),
])
def test_theodolite_readings_that_identify_nothing_are_refused(tmp_path, capsys, rows, message):
    path = tmp_path / "run.csv"
    path.write_text("theta_deg,azimuth_deg,elevation_deg\n" + rows + "\n")
    assert message in refused(capsys, "theodolite", str(path))


@pytest.mark.parametrize("kind, args, message", [
    ("theodolite", ["--grade", "3"], "--grade applies to polygon, not theodolite"),
    ("theodolite", ["--reference-row", "-5"], "reference_row must be 0 or 1 to 1e+07, not -5"),
    ("polygon", ["--samples-per-period", "64"], "--samples-per-period applies to fringe"),
    ("fringe", ["--lines-per-rev", "0"], "lines_per_rev must be"),
])
def test_inapplicable_or_out_of_range_options_are_refused(capsys, samples_dir, kind, args, message):
    from models.registry import KINDS

    err = refused(capsys, kind, str(samples_dir / KINDS[kind].sample_file), *args)
    assert message in err


@pytest.mark.parametrize("settings, message", [
    ({"lut_size": 100_000_000}, "lut_size must be 8 to 65536"),
    ({"samples_per_period": "64"}, "samples_per_period must be a number"),
])
def test_fringe_settings_from_a_project_file_are_checked(settings, message):
    from models.analysis_kind import SettingsError
    from models.fringe.analysis import FRINGE

    with pytest.raises(SettingsError, match=message):
        FRINGE.analyze(ReadingsSheet(FRINGE.columns, [["0", "1"]] * 40).parse(), settings)


@pytest.mark.parametrize("settings, message", [
    ({"faces": 1_000_000_000}, r"faces must be 0 or 3 to 360, not 1e\+09"),
    ({"closure_limits_arcsec": [0.1, 0.2]}, "must be text"),
    ({"grade": "3"}, "grade must be one of 1, 2, 3"),
])
def test_polygon_settings_from_a_project_file_are_checked(samples_dir, settings, message):
    from models.analysis_kind import SettingsError
    from models.polygon.analysis import POLYGON
    from models.readings.tabular_import import map_columns

    rows = map_columns(read_table(samples_dir / POLYGON.sample_file), POLYGON.columns)
    with pytest.raises(SettingsError, match=message):
        POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), settings)
