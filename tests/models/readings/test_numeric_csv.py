"""The fast reader of all-numeric files (#15) gives exactly the readings the tolerant
reader gives, whenever it answers; on anything but plain numbers it leaves the file to
the tolerant reader, which then says what is wrong and where."""

from __future__ import annotations

import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.readings.numeric_csv import read_numeric
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

FRINGE, THEODOLITE = KINDS["fringe"].columns, KINDS["theodolite"].columns


def tolerant(path: Path, columns):
    return ReadingsSheet(columns, map_columns(read_table(path), columns)).parse()


def same(a, b) -> None:
    assert a.values.keys() == b.values.keys()
    for key in a.values:
        if a.values[key].dtype == object:
            assert list(a.values[key]) == list(b.values[key])
        else:
            np.testing.assert_array_equal(a.values[key], b.values[key])
    np.testing.assert_array_equal(a.row_index, b.row_index)
    assert a.errors == b.errors == []


@st.composite
def numeric_files(draw):
    kind = draw(st.sampled_from(["fringe", "theodolite"]))
    keys = (["u_sin", "u_cos"] + draw(st.sampled_from([[], ["theta_deg"]])) if kind == "fringe"
            else ["theta_deg", "azimuth_deg", "elevation_deg"] + draw(
                st.sampled_from([[], ["run"]])))
    keys = draw(st.permutations(keys))
    n = draw(st.integers(1, 40))
    delimiter = draw(st.sampled_from([",", "\t", ";"]))
    decimals = draw(st.integers(0, 7))
    number = st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False)
    lines = [draw(st.sampled_from([[], ["Test of encoder 42"], ["Lab", "2026-11-27"]]))]
    lines = [delimiter.join(cells) for cells in lines if cells] + [delimiter.join(keys)]
    for _ in range(n):
        cells = [str(draw(st.integers(1, 9))) if key == "run" else
                 f"{draw(number):.{decimals}f}" for key in keys]
        lines.append(delimiter.join(cells))
    ending = draw(st.sampled_from(["\n", "\r\n"]))
    return kind, ending.join(lines) + draw(st.sampled_from(["", ending]))


@pytest.mark.slow
@settings(max_examples=120, deadline=None)
@given(numeric_files())
def test_the_fast_reader_reads_what_the_tolerant_reader_reads(case):
    kind, text = case
    columns = FRINGE if kind == "fringe" else THEODOLITE
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "readings.csv"
        path.write_text(text, encoding="utf-8")
        fast = read_numeric(path, columns)
        assert fast is not None, text[:200]
        same(fast, tolerant(path, columns))


@pytest.mark.parametrize("body, why", [
    ("0.1,0.2\n\n0.3,0.4\n", "a blank line keeps its place in a signal"),
    ("0.1,0.2\nnan,0.4\n", "nan is not a reading"),
    ("0.1,0.2\n1_0,0.4\n", "python reads 1_0 as 10"),
    ("0.1,0.2\n0.3,abc\n", "text"),
    ("0.1,0.2\n0.3\n", "a short row"),
    ("0.1,0.2\n0.3,0.4 # note\n", "a comment sign"),
    ("0.1,0.2\n\"0.3\",0.4\n", "a quote"),
    ("0.1,0.2\n０.3,0.4\n", "full-width digits"),
])
def test_anything_but_plain_numbers_goes_to_the_tolerant_reader(tmp_path, body, why):
    path = tmp_path / "signals.csv"
    path.write_text("u_sin,u_cos\n" + body, encoding="utf-8")
    assert read_numeric(path, FRINGE) is None, why


def test_a_header_on_the_last_line_is_left_to_the_tolerant_reader(tmp_path):
    """Found by the CLI fuzz test: rows of numbers, then the header as the file's last line."""
    path = tmp_path / "upside_down.csv"
    path.write_text("a,b\n0.1,0.2\nu_sin,u_cos\n", encoding="utf-8")  # "a,b" reads as a header
    assert read_numeric(path, FRINGE) is None


def test_what_is_not_a_readings_file_is_left_to_the_tolerant_reader(tmp_path):
    assert read_numeric(tmp_path / "missing.csv", FRINGE) is None
    (tmp_path / "x.xlsx").write_bytes(b"PK")
    assert read_numeric(tmp_path / "x.xlsx", FRINGE) is None
    (tmp_path / "gbk.csv").write_bytes("转角,方位\n1,2\n".encode("gbk"))
    assert read_numeric(tmp_path / "gbk.csv", THEODOLITE) is None  # no elevation column
    (tmp_path / "dms.csv").write_text("theta_deg,azimuth_deg,elevation_deg\n0,1°2'3\",0\n",
                                      encoding="utf-8")
    assert read_numeric(tmp_path / "dms.csv", THEODOLITE) is None


def test_a_chinese_header_and_a_title_block_read_fast(tmp_path):
    path = tmp_path / "theodolite.csv"
    path.write_text("经纬仪测量 2026-11-27\n转角θ/°,方位角A,俯仰角E\n-20,-19.88,-1.58\n0,0,0.04\n"
                    "20,20.08,1.62\n", encoding="utf-8")
    fast = read_numeric(path, THEODOLITE)
    assert fast is not None and fast.n == 3
    same(fast, tolerant(path, THEODOLITE))
    np.testing.assert_array_equal(fast["azimuth_deg"], [-19.88, 0.0, 20.08])
