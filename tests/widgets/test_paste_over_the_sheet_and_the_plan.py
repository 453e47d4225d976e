"""Pasting as a technician does (Ctrl+A, Ctrl+V through the clipboard) and typing a
correction, with and without an entry plan (day review 65 F1–F3)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QLineEdit

from widgets.crosscal.presenter import CrossCalPresenter
from widgets.fringe.presenter import FringePresenter
from widgets.polygon.presenter import PolygonPresenter
from widgets.positioning.presenter import PositioningPresenter
from widgets.theodolite.presenter import TheodolitePresenter

PRESENTERS = [PositioningPresenter, PolygonPresenter, CrossCalPresenter, TheodolitePresenter,
              FringePresenter]


def _shown(qtbot, presenter):
    qtbot.addWidget(presenter.view)
    presenter.view.show()
    presenter.view.activateWindow()  # a shortcut (Ctrl+A, Ctrl+V) reaches an active window
    qtbot.waitActive(presenter.view)
    return presenter


def _rows(presenter) -> list[list[str]]:
    sheet = presenter.sheet
    return [[sheet.text(r, c) for c in range(sheet.column_count)]
            for r in range(sheet.row_count)]


def _click(qtbot, table, row: int, column: int) -> None:
    table.scrollTo(table.model().index(row, column))
    rect = table.visualRect(table.model().index(row, column))
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=rect.center())
    table.setFocus()  # the click's focus (the offscreen platform's click gives none)
    qtbot.waitUntil(table.hasFocus)
    assert (table.currentIndex().row(), table.currentIndex().column()) == (row, column)


def _select_all_and_paste(qtbot, table, text: str) -> None:
    QGuiApplication.clipboard().setText(text)
    qtbot.keyClick(table, Qt.Key.Key_A, Qt.KeyboardModifier.ControlModifier)
    qtbot.keyClick(table, Qt.Key.Key_V, Qt.KeyboardModifier.ControlModifier)


def _type(qtbot, table, row: int, column: int, text: str) -> None:
    _click(qtbot, table, row, column)
    qtbot.keyClick(table, Qt.Key.Key_F2)
    editor = next(w for w in table.viewport().findChildren(QLineEdit) if w.isVisible())
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.model().data(table.model().index(row, column)) == text)


# -- F1: a paste over the whole sheet goes from the first column --------------------------
@pytest.mark.slow
@pytest.mark.parametrize("make", PRESENTERS, ids=lambda p: p.__name__)
def test_the_sheet_pasted_over_itself_with_the_cursor_in_its_last_column_is_unchanged(
        qtbot, make):
    """Every workbench: its own rows copied without the header, the cursor in the last
    column, Ctrl+A and Ctrl+V: the same sheet (before: the block went to the cursor's
    column, every column left of it emptied and the block's other columns dropped)."""
    presenter = _shown(qtbot, make())
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.sheet.row_count > 3)
    before = _rows(presenter)
    width = presenter.sheet.column_count
    table = presenter.view.table
    _click(qtbot, table, 1, width - 1)
    steps = presenter.undo_stack.count()
    _select_all_and_paste(qtbot, table, "\n".join("\t".join(r) for r in before))
    assert presenter.undo_stack.count() == steps + 1  # pasted, replacing the sheet
    assert presenter.undo_stack.text(steps).endswith("replacing the sheet")
    assert _rows(presenter) == before


@pytest.mark.slow
def test_a_narrower_block_over_the_sheet_is_said_and_a_wider_one_s_columns_too(qtbot):
    """Positioning (target, run, direction, deviation, measured), the cursor on a deviation:
    a 4-column block over the whole sheet fills target … deviation and says measured is left
    empty; a 7-column block fills all five and says its columns 6–7 were left out."""
    presenter = _shown(qtbot, PositioningPresenter())
    presenter.load_sample()
    qtbot.waitUntil(lambda: presenter.sheet.row_count > 3)
    table = presenter.view.table
    deviation = presenter.sheet.column_index("deviation")
    _click(qtbot, table, 2, deviation)
    _select_all_and_paste(qtbot, table, "0\t1\t+\t0.5\n30\t1\t+\t0.7\n60\t1\t+\t0.9")
    assert _rows(presenter) == [["0", "1", "+", "0.5", ""], ["30", "1", "+", "0.7", ""],
                                ["60", "1", "+", "0.9", ""]]
    qtbot.waitUntil(lambda: "measured" in presenter.view.last_status)
    said = presenter.view.last_status
    # the headers as shown, with the set-up's units (live78)
    assert said.startswith('Pasted into target [deg], run, dir [+/−], deviation ["];')
    assert "measured [deg] left empty" in said
    _click(qtbot, table, 1, deviation)
    _select_all_and_paste(qtbot, table, "0\t1\t+\t0.5\t\tx\ty\n30\t1\t-\t0.7\t\tx\ty")
    assert _rows(presenter) == [["0", "1", "+", "0.5", ""], ["30", "1", "-", "0.7", ""]]
    qtbot.waitUntil(lambda: "left out" in presenter.view.last_status)
    assert "the block's column(s) 6–7 left out" in presenter.view.last_status


# -- F2, F3: the theodolite's entry plan, readings pasted and corrected ---------------------
THETAS = [-2, -1, 0, 1, 2]
A_E = {t: (f"{10 + t}.5", f"-0.{abs(t) + 1}") for t in THETAS}


@pytest.fixture
def theodolite_with_plan(qtbot):
    presenter = _shown(qtbot, TheodolitePresenter())
    presenter.set_settings({"plan_passes": 2, "plan_thetas": "-2:1:5"})
    return presenter


def _type_first_reading(qtbot, presenter):
    """Row 1's azimuth and elevation typed: the plan fills θ −2, pass 1 ↑ and goes on."""
    table = presenter.view.table
    azimuth = presenter.sheet.column_index("azimuth_deg")
    elevation = presenter.sheet.column_index("elevation_deg")
    _type(qtbot, table, 0, azimuth, A_E[-2][0])
    _type(qtbot, table, 0, elevation, A_E[-2][1])
    assert _rows(presenter)[0] == ["-2", A_E[-2][0], A_E[-2][1], "1", "+"]
    return table, azimuth


@pytest.mark.slow
def test_readings_pasted_at_the_plan_s_row_get_its_next_points_and_it_goes_on(
        qtbot, theodolite_with_plan):
    """F3: pass 1's other four A/E pasted at the row the plan points at get θ −1 … 2,
    pass 1 ↑ (one undo step with the paste, said), and the next point is pass 2's θ −2 in
    the row after them (before: θ empty and red, and the plan still said θ −1)."""
    presenter = theodolite_with_plan
    table, azimuth = _type_first_reading(qtbot, presenter)
    assert _rows(presenter)[1][0] == "-1"  # the plan's row, pre-filled
    QGuiApplication.clipboard().setText("\n".join(f"{A_E[t][0]}\t{A_E[t][1]}"
                                                  for t in THETAS[1:]))
    _click(qtbot, table, 1, azimuth)
    steps = presenter.undo_stack.count()
    qtbot.keyClick(table, Qt.Key.Key_V, Qt.KeyboardModifier.ControlModifier)
    assert _rows(presenter)[:5] == [[f"{t}", *A_E[t], "1", "+"] for t in THETAS]
    assert presenter.undo_stack.count() == steps + 1
    assert presenter.view.last_status == \
        "Rows 3–5: θ = 0°, pass 1 ↑ … θ = 2°, pass 1 ↑, from the entry plan"
    place = presenter.plan_placement()
    assert place is not None and place.row == 5
    assert dict(place.cells) == {"theta_deg": "-2", "run": "2", "direction": "+"}
    presenter.undo_stack.undo()  # the paste and the plan's cells go together
    assert [r[1] for r in _rows(presenter)[1:]] in ([], [""])


@pytest.mark.slow
def test_readings_pasted_with_their_theta_get_run_and_direction_and_the_plan_goes_on(
        qtbot, theodolite_with_plan):
    """F3 with θ in the block: θ, A and E of pass 1's other points pasted at the plan's row
    get run 1 and + (the points they hold, skipped by the plan), and the next point is pass
    2's θ −2 after them (before: their run and direction stayed empty, the plan said θ 0,
    pass 1 and would have labelled the next take so)."""
    presenter = theodolite_with_plan
    table, _ = _type_first_reading(qtbot, presenter)
    QGuiApplication.clipboard().setText("\n".join(f"{t}\t{A_E[t][0]}\t{A_E[t][1]}"
                                                  for t in THETAS[1:]))
    _click(qtbot, table, 1, 0)
    qtbot.keyClick(table, Qt.Key.Key_V, Qt.KeyboardModifier.ControlModifier)
    assert _rows(presenter)[:5] == [[f"{t}", *A_E[t], "1", "+"] for t in THETAS]
    place = presenter.plan_placement()
    assert place is not None and place.row == 5
    assert dict(place.cells) == {"theta_deg": "-2", "run": "2", "direction": "+"}


@pytest.mark.slow
def test_a_correction_typed_into_a_row_without_theta_gets_no_plan_theta(
        qtbot, theodolite_with_plan):
    """F2: a row pasted below the plan's rows (not at the row it points at) keeps its θ
    empty; correcting its elevation by typing gives it no θ, run or direction, and the
    plan still points at its own row (before: the plan's next θ −1 was stamped on it)."""
    presenter = theodolite_with_plan
    table, azimuth = _type_first_reading(qtbot, presenter)
    # the empty row the plan pointed at got its cells, and that was said
    assert presenter.view.last_status == "Row 1: θ = -2°, pass 1 ↑, from the entry plan"
    elevation = presenter.sheet.column_index("elevation_deg")
    QGuiApplication.clipboard().setText("\n".join(f"{A_E[t][0]}\t{A_E[t][1]}"
                                                  for t in THETAS[1:]))
    _click(qtbot, table, 2, azimuth)  # below the plan's row (row 2, θ −1, pre-filled)
    qtbot.keyClick(table, Qt.Key.Key_V, Qt.KeyboardModifier.ControlModifier)
    assert [r[0] for r in _rows(presenter)] == ["-2", "-1", "", "", "", ""]
    _type(qtbot, table, 4, elevation, "-0.25")
    assert _rows(presenter)[4] == ["", A_E[1][0], "-0.25", "", ""]
    place = presenter.plan_placement()
    assert place is not None and place.row == 1 and place.cells["theta_deg"] == "-1"


@pytest.mark.slow
def test_a_correction_in_the_last_row_pasted_before_the_plan_gets_no_plan_theta(qtbot):
    """F2 at the end of the sheet: three A/E pasted without θ, then the plan set; the last
    of them (the row after which the plan would go on) corrected by typing keeps θ, run and
    direction empty: it was no empty row the plan pointed at (before: θ −2, pass 1 ↑)."""
    presenter = _shown(qtbot, TheodolitePresenter())
    table = presenter.view.table
    azimuth = presenter.sheet.column_index("azimuth_deg")
    elevation = presenter.sheet.column_index("elevation_deg")
    QGuiApplication.clipboard().setText("\n".join(f"{A_E[t][0]}\t{A_E[t][1]}"
                                                  for t in THETAS[:3]))
    _click(qtbot, table, 0, azimuth)
    qtbot.keyClick(table, Qt.Key.Key_V, Qt.KeyboardModifier.ControlModifier)
    assert presenter.sheet.row_count == 3
    presenter.set_settings({"plan_passes": 2, "plan_thetas": "-2:1:5"})
    _type(qtbot, table, 2, elevation, "-0.35")
    assert _rows(presenter)[2] == ["", A_E[0][0], "-0.35", "", ""]


def _type_and_tab(qtbot, table, row: int, column: int, text: str) -> None:
    """``text`` typed into the cell and left with Tab, as in a spreadsheet (not Return)."""
    _click(qtbot, table, row, column)
    qtbot.keyClick(table, Qt.Key.Key_F2)
    editor = next(w for w in table.viewport().findChildren(QLineEdit) if w.isVisible())
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Tab)
    qtbot.waitUntil(lambda: table.model().data(table.model().index(row, column)) == text)


@pytest.mark.slow
def test_the_first_reading_left_with_tab_gets_its_theta_and_a_paste_below_goes_on(
        qtbot, theodolite_with_plan):
    """live78: row 1's A and E typed, each left with Tab (never Return), kept θ, run and
    direction empty (red); pass 1's other A/E pasted below then took θ −2 … 1 — each row
    one θ early, a result from shifted θ — said only as "Rows 2–5: θ = -2° … θ = 1°, from
    the entry plan". Now row 1 gets the plan's point as Return gives it, the cursor
    stays where Tab put it, and the paste goes on from θ −1."""
    presenter = theodolite_with_plan
    table = presenter.view.table
    azimuth = presenter.sheet.column_index("azimuth_deg")
    elevation = presenter.sheet.column_index("elevation_deg")
    _type_and_tab(qtbot, table, 0, azimuth, A_E[-2][0])
    assert _rows(presenter)[0] == ["-2", A_E[-2][0], "", "1", "+"]
    assert presenter.view.last_status == "Row 1: θ = -2°, pass 1 ↑, from the entry plan"
    assert (table.currentIndex().row(), table.currentIndex().column()) == (0, elevation)
    _type_and_tab(qtbot, table, 0, elevation, A_E[-2][1])
    assert _rows(presenter)[0] == ["-2", *A_E[-2], "1", "+"]
    QGuiApplication.clipboard().setText("\n".join(f"{A_E[t][0]}\t{A_E[t][1]}"
                                                  for t in THETAS[1:]))
    _click(qtbot, table, 1, azimuth)
    qtbot.keyClick(table, Qt.Key.Key_V, Qt.KeyboardModifier.ControlModifier)
    assert _rows(presenter)[:5] == [[f"{t}", *A_E[t], "1", "+"] for t in THETAS]
