"""Pasting a run and importing the files labs have: a header row is left out (and read for
the column order), Ctrl+A then paste replaces the sheet, a shorter run pasted over a longer
one asks instead of mixing them; headers in Chinese, with units, below a title block."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.readings.headers import match_header, normalise_header
from models.readings.paste import plan_paste
from models.readings.tabular_import import TableImportError, map_columns, read_table
from models.registry import KINDS
from widgets.theodolite.presenter import TheodolitePresenter

THEODOLITE = KINDS["theodolite"].columns


@pytest.mark.parametrize("header, expected", [
    (["theta_deg", "azimuth_deg", "elevation_deg"], [0, 1, 2]),
    (["转角θ/°", "方位角A", "俯仰角E"], [0, 1, 2]),
    (["E (deg)", "θ [deg]", "A(″)"], [1, 2, 0]),
    (["Azimuth", "Elevation", "Theta"], [2, 0, 1]),
    (["水平角", "天顶距", "转角"], [2, 0, 1]),
])
def test_headers_as_labs_write_them(header, expected):
    assert match_header(header, THEODOLITE)[:3] == expected


def test_normalising_takes_units_off():
    assert normalise_header("转角θ/°") == "转角θ"
    assert normalise_header("A(″)") == "a" and normalise_header("theta_deg") == "theta"


@settings(max_examples=60, deadline=None)
@given(st.permutations(["theta_deg", "azimuth_deg", "elevation_deg", "run", "direction"]))
def test_any_column_order_is_read_back(order):
    positions = match_header(order, THEODOLITE)
    assert [order[p] for p in positions] == [c.key for c in THEODOLITE]


def test_a_gbk_file_with_a_title_block_and_chinese_headers(tmp_path, samples_dir):
    sample = (samples_dir / "theodolite_sample.csv").read_text(encoding="utf-8").splitlines()
    text = "\n".join(["精密角度计量实验室 转台校准记录", "日期,2026-11-20", "",
                      "转角θ/°,方位角A,俯仰角E", *sample[1:]]) + "\n"
    path = tmp_path / "gbk.csv"
    path.write_bytes(text.encode("gbk"))
    table = read_table(path)
    rows = map_columns(table, THEODOLITE)
    expected = map_columns(read_table(samples_dir / "theodolite_sample.csv"), THEODOLITE)
    assert rows == expected
    assert table.line_numbers[0] == 5  # messages still name the file's rows


def test_a_file_naming_no_column_is_refused_with_its_header(tmp_path):
    path = tmp_path / "x.csv"
    path.write_text("foo,bar,baz\n1,2,3\n", encoding="utf-8")
    with pytest.raises(TableImportError, match="no column 'theta_deg'.*header is foo,bar,baz"):
        map_columns(read_table(path), THEODOLITE)


def test_plan_takes_a_header_off_and_maps_it():
    grid = [["A", "θ", "E"], ["1.0", "1", "0.1"], ["2.0", "2", "0.2"]]
    plan = plan_paste(grid, THEODOLITE, filled_rows=0, top=0, left=0, whole_sheet=False)
    assert plan.header == ["A", "θ", "E"] and plan.mapped
    assert plan.rows[0][:3] == ["1", "1.0", "0.1"]
    plain = plan_paste(grid[1:], THEODOLITE, 0, 0, 0, False)
    assert plain.header is None and plain.rows == grid[1:]


@pytest.fixture
def presenter(qtbot, samples_dir):
    p = TheodolitePresenter()
    qtbot.addWidget(p.view)
    p.load_sample()
    return p


def run_text(n: int, offset: float = 0.0) -> str:
    theta = np.linspace(-10, 10, n)
    return "\n".join(f"{t:g}\t{t + offset:.6f}\t0.1" for t in theta)


@pytest.mark.slow
def test_ctrl_a_then_paste_replaces_the_sheet(presenter, qtbot):
    table = presenter.view.table
    assert presenter.sheet.row_count >= 41
    table.selectAll()
    assert table.paste_text(run_text(15)) == "replace"
    presenter.refresh()
    assert presenter.parsed.n == 15
    presenter.undo_stack.undo()  # one step brings the sample back
    presenter.refresh()
    assert presenter.parsed.n == 41


def test_a_shorter_run_over_a_longer_one_asks(presenter):
    table = presenter.view.table
    table.setCurrentIndex(presenter.table_model.index(0, 0))
    table.ask_paste = lambda block, left: ""  # cancelled: nothing changes
    assert table.paste_text(run_text(15)) == ""
    assert presenter.sheet.text(0, 0) == "-20"
    table.ask_paste = lambda block, left: "overwrite" if (block, left) == (15, 26) else "?"
    assert table.paste_text(run_text(15)) == "overwrite"
    assert presenter.sheet.text(0, 0) == "-10"
    table.ask_paste = lambda block, left: "replace"
    assert table.paste_text(run_text(15)) == "replace"
    presenter.refresh()
    assert presenter.parsed.n == 15


@pytest.mark.slow
def test_a_pasted_header_row_is_left_out_not_red(presenter):
    table = presenter.view.table
    last = presenter.sheet.row_count  # the blank row after the run: append a run there
    table.setCurrentIndex(presenter.table_model.index(last, 0))
    text = "θ\tA\tE\n" + run_text(3, 0.001)
    assert table.paste_text(text) == "cells"
    presenter.refresh()
    assert presenter.parsed.errors == [] and presenter.parsed.n == 44


def test_cli_columns_maps_headers_it_does_not_know(tmp_path, samples_dir, capsys):
    from app.main import main

    lines = (samples_dir / "theodolite_sample.csv").read_text(encoding="utf-8").splitlines()
    path = tmp_path / "de.csv"
    path.write_text("\n".join(["Winkel,Hz,Vert", *lines[1:]]) + "\n", encoding="utf-8")
    assert main(["analyze", "theodolite", str(path)]) == 2
    assert "no column 'theta_deg'" in capsys.readouterr().err
    assert main(["analyze", "theodolite", str(path), "--columns",
                 "theta_deg=Winkel,azimuth_deg=Hz,elevation_deg=Vert"]) == 0
    assert main(["analyze", "theodolite", str(path), "--columns", "theta_deg=Wnkl"]) == 2
    assert "the file has no header 'Wnkl'" in capsys.readouterr().err


@pytest.mark.slow
def test_the_window_asks_for_a_mapping_once_and_remembers_it(qtbot, tmp_path, samples_dir,
                                                            monkeypatch):
    from PySide6.QtCore import QSettings
    from PySide6.QtWidgets import QDialog

    from widgets.column_mapping_dialog import ColumnMappingDialog

    QSettings.setDefaultFormat(QSettings.Format.IniFormat)
    QSettings.setPath(QSettings.Format.IniFormat, QSettings.Scope.UserScope, str(tmp_path))
    lines = (samples_dir / "theodolite_sample.csv").read_text(encoding="utf-8").splitlines()
    path = tmp_path / "de.csv"
    path.write_text("\n".join(["Winkel,Hz,Vert", *lines[1:]]) + "\n", encoding="utf-8")
    asked = []

    def choose(dialog):
        asked.append(dialog)
        assert not dialog.buttons.button(dialog.buttons.StandardButton.Ok).isEnabled()
        dialog.choices["theta_deg"].setCurrentIndex(1)  # Winkel
        dialog.choices["elevation_deg"].setCurrentIndex(3)  # Vert
        assert dialog.preview.item(0, 0).text() == "-20"
        assert dialog.buttons.button(dialog.buttons.StandardButton.Ok).isEnabled()
        return QDialog.DialogCode.Accepted

    monkeypatch.setattr(ColumnMappingDialog, "exec", choose)
    p = TheodolitePresenter()
    qtbot.addWidget(p.view)
    p.import_file(path)
    assert p.sheet.row_count == 41 and len(asked) == 1
    p.import_file(path)  # the same headers again: the remembered mapping, no question
    assert len(asked) == 1 and p.sheet.text(0, 1) == "-19°52'57.0\""
    monkeypatch.setattr(ColumnMappingDialog, "exec", lambda d: QDialog.DialogCode.Rejected)
    other = tmp_path / "other.csv"
    other.write_text("a1,b1,c1\n1,2,3\n", encoding="utf-8")
    with pytest.raises(TableImportError, match="no column 'theta_deg'"):
        p.import_file(other)  # cancelled: the error stands, the readings stay
    assert p.sheet.row_count == 41


def test_a_first_row_of_mistyped_readings_is_kept_not_taken_for_a_header():
    grid = [["1.5.5", "2°61'", "x1"], ["1.0", "1", "0.1"], ["2.0", "2", "0.2"]]
    plan = plan_paste(grid, THEODOLITE, filled_rows=0, top=0, left=0, whole_sheet=False)
    assert plan.header is None and plan.rows[0] == ["1.5.5", "2°61'", "x1"]
    words = [["Winkel", "Hz", "Vert"], ["1.0", "1", "0.1"]]
    plan = plan_paste(words, THEODOLITE, 0, 0, 0, False)
    assert plan.header == ["Winkel", "Hz", "Vert"] and not plan.mapped  # only Hz is known:
    assert plan.rows == [["1.0", "1", "0.1"]]  # pasted where it lands, Winkel's cells kept


def test_a_paste_over_the_whole_sheet_goes_from_the_first_column_and_says_its_columns():
    """Day review 65 F1: every row selected, the cursor in the elevation column (left 2):
    the block goes from θ; a 4-wide block's 4th column and beyond is known as dropped."""
    grid = [["-20", "1.0", "2.0", "x"], ["-19", "1.1", "2.1", "y"]]
    plan = plan_paste(grid, THEODOLITE, filled_rows=5, top=3, left=2, whole_sheet=True)
    assert plan.replace_sheet and plan.left == 0
    assert plan.filled == (0, 1, 2, 3) and plan.dropped == ()
    wide = [r + ["", "z", "w"] for r in grid]  # 7 wide on the theodolite's 5 columns
    plan = plan_paste(wide, THEODOLITE, filled_rows=5, top=3, left=2, whole_sheet=True)
    assert plan.filled == (0, 1, 2, 3, 4) and plan.dropped == (5, 6)
    at_cursor = plan_paste(grid, THEODOLITE, filled_rows=5, top=3, left=2, whole_sheet=False)
    assert at_cursor.left == 2 and at_cursor.filled == (2, 3, 4) and at_cursor.dropped == (3,)
