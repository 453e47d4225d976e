"""The readings table driven like a user: type, paste, undo, delete; plots follow."""

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication
from PySide6.QtWidgets import QLineEdit

from models.theodolite.model import SetupParameters, simulate_readings
from widgets.readings_table_model import INVALID_BRUSH
from widgets.theodolite.presenter import TheodolitePresenter


@pytest.fixture
def bench(qtbot):
    presenter = TheodolitePresenter()
    qtbot.addWidget(presenter.view)
    presenter.view.show()
    return presenter


def run_rows(noise=0.0, seed=0):
    theta = np.arange(-10.0, 11.0, 2.0)
    truth = 0.6 * np.sin(np.radians(theta) * 20)
    az, el = simulate_readings(theta, SetupParameters(3.0, 45.0, 2.0), truth, noise,
                               np.random.default_rng(seed))
    return theta, truth, [[f"{t:g}", f"{a:.9f}", f"{e:.9f}"] for t, a, e in zip(theta, az, el, strict=True)]


def type_cell(qtbot, view, row, column, text):
    index = view.model().index(row, column)
    view.setCurrentIndex(index)
    view.edit(index)
    editors = [w for w in view.viewport().findChildren(QLineEdit) if w.isVisible()]
    assert len(editors) == 1
    editors[0].selectAll()
    qtbot.keyClicks(editors[0], text)
    qtbot.keyClick(editors[0], Qt.Key.Key_Return)
    # the delegate commits on Return through a queued call: let the event loop run
    qtbot.waitUntil(lambda: view.model().data(view.model().index(row, column)) == text)


@pytest.mark.slow
def test_typing_readings_updates_corrected_curve(qtbot, bench):
    theta, truth, rows = run_rows()
    table = bench.view.table
    for r, row in enumerate(rows):
        for c, text in enumerate(row):
            type_cell(qtbot, table, r, c, text)
    qtbot.waitUntil(lambda: bench.result is not None and bench.result.theta_deg.size == 11)
    x, y = bench.view.error_plot.corrected_curve.getData()
    np.testing.assert_allclose(x, theta)
    np.testing.assert_allclose(y, truth, atol=1e-4)
    assert bench.sheet.row_count == 11


@pytest.mark.slow
def test_paste_block_then_undo_redo(qtbot, bench):
    theta, _, rows = run_rows(noise=0.2)
    QGuiApplication.clipboard().setText("\n".join("\t".join(r) for r in rows))
    bench.view.table.setCurrentIndex(bench.table_model.index(0, 0))
    bench.view.table.paste_action.trigger()
    qtbot.waitUntil(lambda: bench.result is not None)
    assert bench.sheet.row_count == 11
    assert bench.undo_stack.count() == 1  # one paste, one undo step
    bench.undo_stack.undo()
    qtbot.waitUntil(lambda: bench.result is None)
    assert bench.sheet.row_count == 0
    x, _ = bench.view.error_plot.corrected_curve.getData()
    assert x is None or len(x) == 0
    bench.undo_stack.redo()
    qtbot.waitUntil(lambda: bench.result is not None)
    assert bench.sheet.text(10, 0) == "10"


@pytest.mark.slow
def test_invalid_cell_is_marked_and_the_rest_keeps_working(qtbot, bench):
    _, _, rows = run_rows()
    bench.table_model.replace_all(rows)
    type_cell(qtbot, bench.view.table, 3, 1, "1°61'00\"")
    qtbot.waitUntil(lambda: bench.parsed is not None and len(bench.parsed.errors) == 1)
    model = bench.table_model
    index = model.index(3, 1)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) == INVALID_BRUSH
    assert "minutes 61 out of range" in model.data(index, Qt.ItemDataRole.ToolTipRole)
    assert model.data(index) == "1°61'00\""  # what was typed stays
    assert bench.result is not None and bench.result.theta_deg.size == 10
    assert "cannot be read (row 4)" in bench.view.warnings.text()


@pytest.mark.slow
def test_insert_and_delete_rows_are_undoable(qtbot, bench):
    _, _, rows = run_rows()
    bench.table_model.replace_all(rows)
    table = bench.view.table
    table.setCurrentIndex(bench.table_model.index(2, 0))
    table.insert_action.trigger()
    assert bench.sheet.row_count == 12 and bench.sheet.is_blank_row(2)
    table.selectRow(0)
    table.delete_rows_action.trigger()
    assert bench.sheet.row_count == 11 and bench.sheet.text(0, 0) == "-8"
    bench.undo_stack.undo()
    bench.undo_stack.undo()
    assert bench.sheet.copy_rows() == [r + ["", ""] for r in rows]


@pytest.mark.slow
def test_copy_selection_as_tab_separated(qtbot, bench):
    _, _, rows = run_rows()
    bench.table_model.replace_all(rows)
    table = bench.view.table
    table.selectRow(1)
    table.copy_action.trigger()
    assert QGuiApplication.clipboard().text() == "\t".join(rows[1] + ["", ""])


@pytest.mark.slow
def test_clear_cells_with_delete_key(qtbot, bench):
    _, _, rows = run_rows()
    bench.table_model.replace_all(rows)
    table = bench.view.table
    table.setCurrentIndex(bench.table_model.index(0, 2))
    table.clear_action.trigger()
    assert bench.sheet.text(0, 2) == ""
    bench.undo_stack.undo()
    assert bench.sheet.text(0, 2) == rows[0][2]


@pytest.mark.slow
def test_settings_change_reanalyses(qtbot, bench):
    _, _, rows = run_rows()
    bench.table_model.replace_all(rows)
    qtbot.waitUntil(lambda: bench.result is not None)
    combo = bench.view.settings.field("method")
    combo.setCurrentIndex(combo.findData("azimuth"))
    qtbot.waitUntil(lambda: bench.result.identification.method == "azimuth")
    assert "absorbed" in bench.view.warnings.text()
    assert bench.is_modified


@pytest.mark.slow
def test_simulation_panel_reproduces_fig3_family(qtbot, bench):
    sim = bench.view.simulation
    sim.sweep_values.setText("-2, 0, 2")
    sim.update_curves()
    spans = [np.ptp(c.getData()[1]) for c in sim.top_curves[:3]]
    assert spans[0] < spans[1] < spans[2]  # Fig 3: the span grows with β at α = 45°
    x, y = sim.top_curves[2].getData()  # β = 2°
    assert y.max() == pytest.approx(187.9, abs=0.1)
