"""Entry follows the run: a positioning test plan fills target, run and direction as the
deviations are typed, says what comes next, and the analysis never refuses the log (#41)."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLineEdit

from widgets.positioning.presenter import PositioningPresenter

PLAN = {"plan_runs": 2, "plan_targets": "0:30:4", "plan_directions": "both",
        "plan_order": "linear"}


def _truth(target: float, direction: str) -> float:
    """The axis' deviation at a target (a pitch error and a backlash of 1.2″)."""
    return 2.0 * np.sin(np.radians(target)) + (0.6 if direction == "+" else -0.6)


def _cells(presenter, row):
    return [presenter.sheet.text(row, c) for c in range(3)]


@pytest.mark.slow
def test_the_plan_fills_target_run_and_direction_as_deviations_arrive(presenter_and_view):
    presenter, view = presenter_and_view
    presenter.set_settings(PLAN)
    presenter.refresh()
    assert view.set_next_row.call_args.args[0] == "next: target 0°, run 1 ↑ (0/16)"
    deviation = presenter.sheet.column_index("deviation")
    row = 0
    for k in range(16):
        # the technician types only the deviation, in the row the plan gave, and presses Return
        target = float(presenter.sheet.text(row, 0) or 0.0) if row < presenter.sheet.row_count \
            else 0.0
        direction = presenter.sheet.text(row, 2) if row < presenter.sheet.row_count else "+"
        if row >= presenter.sheet.row_count:
            presenter.table_model.insert_rows(row)
        presenter.table_model.set_cells([(row, deviation,
                                          f"{_truth(target, direction or '+'):.3f}")])
        following = presenter.plan_return(row)
        presenter.refresh()
        if k:  # one reading is one target: from the second on, never "no run number …"
            assert presenter.problem == "", presenter.problem
        if k == 10:  # run 1 complete, run 2 ↑ at 0, 30 and 60: a run in progress
            assert str(presenter.result.incomplete.text()) == "run 2: 3 of 8 readings"
            assert view.set_next_row.call_args.args[0] == "next: target 90°, run 2 ↑ (11/16)"
            # its readings drawn as taken beside the runs, in no figure
            readings = view.show_figures.call_args.args[2]
            taken = readings.series[-1]
            assert taken.label == "in progress (as taken)"
            np.testing.assert_allclose(taken.x, [0, 30, 60])
            np.testing.assert_allclose(taken.y, [_truth(t, "+") for t in (0, 30, 60)],
                                       atol=1e-3)
        if following is None:
            break
        row = following
    assert k == 15
    assert [_cells(presenter, r) for r in (0, 3, 4, 7, 8, 15)] == [
        ["0", "1", "+"], ["90", "1", "+"], ["90", "1", "-"], ["0", "1", "-"],
        ["0", "2", "+"], ["0", "2", "-"]]
    result = presenter.result
    assert result.incomplete is None and result.least_runs == {"up": 2, "down": 2}
    np.testing.assert_allclose(result.iso.forward.mean,
                               [_truth(t, "+") for t in (0, 30, 60, 90)], atol=1e-3)
    assert view.set_next_row.call_args.args[0] == "plan complete (16 points) (16/16)"


def test_a_row_waiting_for_its_reading_is_no_bad_row(presenter_and_view):
    """The nominal step's (or the plan's) next row holds only its target: left out, not a
    refusal ("row 56: neither a deviation nor …" was shown after every Return)."""
    presenter, view = presenter_and_view
    rows = [[f"{t}", "1", "+", "0.5", ""] for t in (0, 30, 60)] + [["90", "", "", "", ""]]
    presenter.table_model.replace_all(rows)
    presenter.refresh()
    assert presenter.problem == "" and presenter.result is not None
    assert presenter.parsed.n == 3


def test_a_plan_that_cannot_be_made_is_said(presenter_and_view):
    presenter, view = presenter_and_view
    presenter.set_settings({"plan_runs": 2, "plan_targets": "0:30"})
    presenter.refresh()
    assert presenter.plan_problem.startswith("test plan targets '0:30'")
    assert any("Entry plan: test plan targets" in w for w in view.set_warnings.call_args.args[0])


@pytest.mark.slow
def test_typing_deviations_and_return_follows_the_plan(qtbot):
    presenter = PositioningPresenter()
    qtbot.addWidget(presenter.view)
    presenter.view.show()
    presenter.set_settings({**PLAN, "plan_runs": 1, "plan_targets": "0, 45, 90"})
    table = presenter.view.table
    deviation = presenter.sheet.column_index("deviation")
    for k in range(6):
        row = table.currentIndex().row() if k else 0
        index = table.model().index(row, deviation)
        table.setCurrentIndex(index)
        table.edit(index)
        editor = next(w for w in table.viewport().findChildren(QLineEdit) if w.isVisible())
        qtbot.keyClicks(editor, f"0.{k + 1}")
        qtbot.keyClick(editor, Qt.Key.Key_Return)
        qtbot.waitUntil(lambda r=row, k=k: presenter.sheet.row_count > r and
                        presenter.sheet.text(r, deviation) == f"0.{k + 1}")
    qtbot.waitUntil(lambda: presenter.result is not None and presenter.result.deviations.size == 6)
    assert [_cells(presenter, r) for r in range(6)] == [
        ["0", "1", "+"], ["45", "1", "+"], ["90", "1", "+"], ["90", "1", "-"], ["45", "1", "-"],
        ["0", "1", "-"]]
