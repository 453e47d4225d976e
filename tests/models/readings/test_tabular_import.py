import pytest
from hypothesis import given
from hypothesis import strategies as st

from models.readings.sheet import Column, ColumnKind
from models.readings.tabular_import import TableImportError, map_columns, read_table, split_pasted_text

COLUMNS = [
    Column("theta_deg", "θ", "deg", ColumnKind.ANGLE_DEG),
    Column("azimuth_deg", "A", "deg", ColumnKind.ANGLE_DEG),
    Column("elevation_deg", "E", "deg", ColumnKind.ANGLE_DEG),
]


@pytest.mark.parametrize(
    "data",
    [
        b"theta_deg,azimuth_deg,elevation_deg\n0,0,1.5\n1,1.01,1.49\n",
        "\ufefftheta_deg,azimuth_deg,elevation_deg\r\n0,0,1.5\r\n1,1.01,1.49\r\n".encode(),
        b"theta_deg;azimuth_deg;elevation_deg\n0;0;1,5\n1;1,01;1,49\n",
        b"theta_deg\tazimuth_deg\televation_deg\n0\t0\t1.5\n1\t1.01\t1.49\n",
        "theta_deg,azimuth_deg,elevation_deg\n0,0,1.5\n1,1.01,1.49\n".encode("utf-16"),
    ],
)
def test_csv_variants(tmp_path, data):
    path = tmp_path / "run.csv"
    path.write_bytes(data)
    table = read_table(path)
    rows = map_columns(table, COLUMNS)
    assert rows == [["0", "0", "1.5"], ["1", "1.01", "1.49"]]
    assert table.line_numbers == [2, 3]


def test_gbk_with_chinese_header_titles(tmp_path):
    path = tmp_path / "gbk.csv"
    path.write_bytes("θ,A,E,备注\n0,0°00'00\",1.5,零位\n".encode("gb18030"))
    rows = map_columns(read_table(path), COLUMNS)
    assert rows == [["0", "0°00'00\"", "1.5"]]


def test_reordered_headers_and_missing_column(tmp_path):
    path = tmp_path / "r.csv"
    path.write_text("elevation_deg,theta_deg,azimuth_deg\n1.5,0,0\n")
    assert map_columns(read_table(path), COLUMNS) == [["0", "0", "1.5"]]
    path.write_text("theta_deg,elevation_deg\n0,1.5\n")
    with pytest.raises(TableImportError, match=r"r.csv: row 1 \(header\): no column 'azimuth_deg'"):
        map_columns(read_table(path), COLUMNS)


def test_headerless_file_is_positional(tmp_path):
    path = tmp_path / "h.csv"
    path.write_text("0,0,1.5\n1,1.01\n")
    assert map_columns(read_table(path), COLUMNS) == [["0", "0", "1.5"], ["1", "1.01", ""]]


def test_xlsx(tmp_path):
    openpyxl = pytest.importorskip("openpyxl")
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["theta_deg", "azimuth_deg", "elevation_deg"])
    sheet.append([0, 0.25, 1.5])
    sheet.append([1, "1°00'36\"", 1.49])
    book.save(tmp_path / "run.xlsx")
    rows = map_columns(read_table(tmp_path / "run.xlsx"), COLUMNS)
    assert rows == [["0", "0.25", "1.5"], ["1", "1°00'36\"", "1.49"]]


def test_unreadable_files(tmp_path):
    with pytest.raises(TableImportError, match="cannot read"):
        read_table(tmp_path / "missing.csv")
    (tmp_path / "bad.xlsx").write_bytes(b"not a zip")
    with pytest.raises(TableImportError, match="not a readable XLSX"):
        read_table(tmp_path / "bad.xlsx")
    (tmp_path / "empty.csv").write_text("\n\n")
    with pytest.raises(TableImportError, match="no rows"):
        read_table(tmp_path / "empty.csv")


cell = st.text(alphabet=st.characters(blacklist_characters="\t\r\n\"", blacklist_categories=("Cs",)),
               max_size=8)


@pytest.mark.slow
@given(st.lists(st.lists(cell, min_size=2, max_size=4), min_size=1, max_size=10))
def test_paste_round_trip_tab_separated(grid):
    width = max(len(r) for r in grid)
    grid = [r + [""] * (width - len(r)) for r in grid]
    if all(not any(c for c in r) for r in grid[-1:]):
        grid[-1][0] = "x"
    text = "\n".join("\t".join(r) for r in grid)
    assert split_pasted_text(text) == grid


def test_european_semicolon_file_with_dms_decimal_commas_reads_fully(tmp_path):
    """Issue 31 item 5: a semicolon file from a European spreadsheet, D°M'S" with a decimal
    comma in the seconds, decimal commas elsewhere: every cell read, none red."""
    from models.polygon.analysis import POLYGON
    from models.readings.sheet import ReadingsSheet

    lines = ["position;encoder_deg;polygon_dev_arcsec;ac_x_arcsec;ac_y_arcsec"]
    for face in range(1, 13):
        angle = 123.4 + 30 * (face - 1) + 0.5 / 3600 * face
        d, rest = divmod(angle * 3600, 3600)
        m, s = divmod(rest, 60)
        lines.append(f"{face};{int(d) % 360}°{int(m):02d}'{s:05.2f}\"".replace(".", ",")
                     + f";0,{face:02d};{face},5;-1,25")
    path = tmp_path / "eu.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    rows = map_columns(read_table(path), POLYGON.columns)
    parsed = ReadingsSheet(POLYGON.columns, rows).parse()
    assert parsed.errors == [] and parsed.n == 12
    assert parsed["encoder_deg"][1] == pytest.approx(153.4 + 1 / 3600, abs=0.006 / 3600)
    assert parsed["ac_x_arcsec"][0] == 1.5 and parsed["polygon_dev_arcsec"][11] == 0.12


def test_typed_and_pasted_dms_with_a_decimal_comma():
    from models.readings.sheet import ReadingsSheet

    pasted = split_pasted_text("138°24'05,15\"\n139°24'05,15\"\n")
    assert pasted == [["138°24'05,15\""], ["139°24'05,15\""]]
    tabbed = split_pasted_text("0\t138°24'05,15\"\t0°00'12,5\"\n")
    parsed = ReadingsSheet(COLUMNS, tabbed).parse()
    assert parsed.errors == []
    assert parsed["azimuth_deg"][0] == pytest.approx(138 + 24 / 60 + 5.15 / 3600, abs=1e-12)
    assert parsed["elevation_deg"][0] == pytest.approx(12.5 / 3600, abs=1e-12)


def test_xlsx_angles_stored_as_times_read_as_the_sheet_shows_them(tmp_path):
    import datetime

    import openpyxl

    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["theta_deg", "azimuth_deg", "elevation_deg"])
    sheet.append([1, datetime.time(6, 12, 30), datetime.timedelta(hours=138, minutes=24,
                                                                   seconds=5.15)])
    sheet["B2"].number_format = "h:mm:ss"
    sheet["C2"].number_format = "[h]:mm:ss.00"
    path = tmp_path / "times.xlsx"
    book.save(path)
    rows = map_columns(read_table(path), COLUMNS)
    from models.readings.angles import parse_angle_deg

    assert parse_angle_deg(rows[0][1]) == pytest.approx(6 + 12 / 60 + 30 / 3600, abs=1e-9)
    assert parse_angle_deg(rows[0][2]) == pytest.approx(138 + 24 / 60 + 5.15 / 3600, abs=1e-6)


def test_xlsx_formula_without_a_stored_value_reads_as_its_formula(tmp_path):
    """A formula cell never recalculated (a sheet written by a program) has no stored value:
    it reads as the formula — refused as an angle as the same cell in a CSV is — never as a
    blank cell that drops the reading."""
    import openpyxl

    book = openpyxl.Workbook()
    sheet = book.active
    sheet.append(["theta_deg", "azimuth_deg", "elevation_deg"])
    sheet.append([0, 0.25, 1.5])
    sheet.append([1, "=cmd|' /C calc'!A0", 1.49])
    book.save(tmp_path / "formula.xlsx")
    rows = map_columns(read_table(tmp_path / "formula.xlsx"), COLUMNS)
    assert rows == [["0", "0.25", "1.5"], ["1", "=cmd|' /C calc'!A0", "1.49"]]


def test_a_table_read_without_a_header_has_its_header_searched_not_a_type_error():
    """column_positions on a table whose header was not found (header None, a legal
    RawTable) looks for the header in its first rows, and names the missing column when
    there is none (it raised TypeError on None before mypy pointed at it, #44)."""
    from models.readings.tabular_import import MissingColumnError, RawTable, column_positions

    table = RawTable("t.csv", None, [["run 7", "", ""], ["E", "theta_deg", "A"],
                                     ["1.5", "0", "0.1"], ["1.49", "1", "1.01"]], [1, 2, 3, 4])
    assert column_positions(table, COLUMNS) == [1, 2, 0]
    assert table.header == ["E", "theta_deg", "A"]
    assert table.rows == [["1.5", "0", "0.1"], ["1.49", "1", "1.01"]]
    assert table.line_numbers == [3, 4]

    numbers = RawTable("n.csv", None, [["0", "0", "1.5"], ["1", "1.01", "1.49"]], [1, 2])
    with pytest.raises(MissingColumnError, match="no column 'theta_deg'"):
        column_positions(numbers, COLUMNS)
