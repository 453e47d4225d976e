"""row81: a reading typed by hand, between its first cell and its second (the polygon's
autocollimator x, then its encoder; the theodolite's A, then E), was a fault: "Readings — 9
used, 1 bad cell(s)", "⚠ 1 cell(s) cannot be read (row 10) …", the blank encoder cell red,
while the plan's "next:" line had moved on. On every reading typed.

The last row with a reading, some of its reading cells typed and the others blank, is a
reading in progress: its blank cells wait (not red, not counted bad), the complete rows keep
their result and curves, the progress line says the row is in progress (as a unit in progress
is said), and a certificate waits for it. A cell typed wrong in that row, or a reading cell
left blank in any other row, is still a bad cell.

Through the real window: the cells typed in the table's editor, Return after each."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import Qt

from tests.app.capture.window_steps import polygon_bench, show_workbench
from tests.app.table_typing import clear_and_return, type_and_return
from tests.app.test_polygon_live_day import _ac_x, _certificate, _encoder

pytestmark = pytest.mark.slow  # a window, a few dozen cells typed

FACES = 6
BACKGROUND, TOOLTIP = Qt.ItemDataRole.BackgroundRole, Qt.ItemDataRole.ToolTipRole


def _analysed(qtbot, bench) -> None:
    qtbot.waitUntil(lambda: not bench.analysis_pending, timeout=20000)


def _cell(bench, row: int, key: str, role):
    model = bench.table_model
    return model.data(model.index(row, bench.sheet.column_index(key)), role)


def _red(bench, row: int, key: str) -> bool:
    from widgets.readings_table_model import INVALID_BRUSH

    return _cell(bench, row, key, BACKGROUND) == INVALID_BRUSH


@pytest.fixture
def polygon(window):
    yield from polygon_bench(window, faces=FACES, plan_sets=2)




def _next_row(bench) -> int:
    index = bench.view.table.currentIndex()
    return index.row() if index.isValid() else 0


def _take(qtbot, bench, face: int, set_: int) -> int:
    """One polygon reading typed where the plan sends it: the autocollimator's x, then the
    encoder. Its row."""
    row = _next_row(bench)
    table = bench.view.table
    type_and_return(qtbot, table, row, bench.sheet.column_index("ac_x_arcsec"),
                     _ac_x(face, 1, set_))
    type_and_return(qtbot, table, row, bench.sheet.column_index("encoder_deg"),
                     _encoder(face, 1, set_))
    return row


def test_a_polygon_reading_half_typed_is_in_progress(polygon, window, qtbot, tmp_path):
    bench, view = polygon, polygon.view
    bench.load_certificate(_certificate(tmp_path))
    window.show()  # the table's editor opens in a shown window
    for face in [*range(1, FACES + 1), 1]:  # set 1 and its closure
        _take(qtbot, bench, face, 1)
    for face in (1, 6):  # set 2 (reverse): its first two faces
        _take(qtbot, bench, face, 2)
    _analysed(qtbot, bench)
    assert view.readings_label.text() == "Readings — 9 taken, 7 used"
    assert str(bench.result.incomplete.text()) == "set 2: 2 of 6 faces"
    raw = [np.array(a) for a in view.error_plot.raw_curve.getData()]
    corrected = [np.array(a) for a in view.error_plot.corrected_curve.getData()]
    assert raw[0].size == FACES

    # face 5 of set 2: its autocollimator x typed, not yet its encoder
    row = _next_row(bench)
    assert row == 9
    type_and_return(qtbot, view.table, row, bench.sheet.column_index("ac_x_arcsec"),
                     _ac_x(5, 1, 2))
    _analysed(qtbot, bench)
    assert view.next_label.text() == "next: set 2: face 4 of 6 (10/14)"  # moved on
    # main: "Readings — 9 used, 1 bad cell(s)" and "⚠ 1 cell(s) cannot be read (row 10) …"
    assert view.readings_label.text() == "Readings — 10 taken, 7 used"
    assert "cannot be read" not in view.warnings.text()
    progress = ("In progress: set 2: 2 of 6 faces, row 10: encoder a [deg] not typed yet "
                "(rows 8–10); its readings enter no figure until it is complete, and a "
                "certificate waits for it.")
    assert view.summary.toPlainText().startswith(progress)
    assert view.warnings.text().endswith("⚠ " + progress)
    assert not _red(bench, row, "encoder_deg") and _cell(bench, row, "encoder_deg", TOOLTIP) \
        is None
    assert bench.result.incomplete.typing.row == row
    # set 1's result and curves stay as they were
    for curve, before in ((view.error_plot.raw_curve, raw),
                          (view.error_plot.corrected_curve, corrected)):
        for got, was in zip(curve.getData(), before, strict=True):
            np.testing.assert_array_equal(got, was)
    # a certificate waits for it, before any dialog
    window.told.clear()
    assert not window.export_certificate()
    assert window.told == [
        "No certificate: set 2: 2 of 6 faces, row 10: encoder a [deg] not typed yet is not "
        "complete. A certificate needs every set, mounting or run complete; finish it, or "
        "delete its rows to certify the complete ones."]

    # a text that cannot be read is bad even in the last row
    type_and_return(qtbot, view.table, row, bench.sheet.column_index("encoder_deg"), "130,0x")
    _analysed(qtbot, bench)
    assert view.readings_label.text() == "Readings — 9 taken, 7 used, 1 bad cell(s)"
    assert view.warnings.text().startswith("⚠ 1 cell(s) cannot be read (row 10)")
    assert _red(bench, row, "encoder_deg")
    assert bench.result.incomplete.typing is None

    # the encoder typed: the reading is complete, set 2 counts it
    type_and_return(qtbot, view.table, row, bench.sheet.column_index("encoder_deg"),
                     _encoder(5, 1, 2))
    _analysed(qtbot, bench)
    assert view.readings_label.text() == "Readings — 10 taken, 7 used"
    assert str(bench.result.incomplete.text()) == "set 2: 3 of 6 faces"
    assert "cannot be read" not in view.warnings.text()

    # a reading cell left blank in any other row is still a bad cell
    clear_and_return(qtbot, view.table, 2, bench.sheet.column_index("encoder_deg"))
    _analysed(qtbot, bench)
    assert view.warnings.text().startswith("⚠ 1 cell(s) cannot be read (row 3)")
    assert view.readings_label.text().endswith(", 1 bad cell(s)")
    assert _red(bench, 2, "encoder_deg")


THETAS = [-20, -19, -18, -17, -16, -15, -14, -13, -12, -11]


@pytest.fixture
def theodolite(window):
    presenter = show_workbench(window, "theodolite")
    presenter.table_model.replace_all([], "empty")
    presenter.undo_stack.clear()
    yield presenter


def test_a_theodolite_reading_half_typed_is_in_progress(theodolite, window, qtbot,
                                                        samples_dir):
    from tests.app.test_cli_incomplete import _rows

    bench, view = theodolite, theodolite.view
    table = view.table
    _, rows = _rows(samples_dir / "theodolite_sample.csv")
    window.show()
    columns = [bench.sheet.column_index(k) for k in ("theta_deg", "azimuth_deg",
                                                       "elevation_deg")]
    for r, cells in enumerate(rows[:9]):
        for column, text in zip(columns, cells, strict=True):
            type_and_return(qtbot, table, r, column, text)
    _analysed(qtbot, bench)
    assert bench.result is not None and bench.result.incomplete is None
    assert view.readings_label.text() == "Readings — 9 used"
    corrected = [np.array(a) for a in view.error_plot.corrected_curve.getData()]
    assert corrected[0].size == 9

    # θ and A of the 10th row typed, not yet E
    for column, text in zip(columns[:2], rows[9][:2], strict=True):
        type_and_return(qtbot, table, 9, column, text)
    _analysed(qtbot, bench)
    # main: "Readings — 9 used, 1 bad cell(s)", "⚠ 1 cell(s) cannot be read (row 10) …"
    assert view.readings_label.text() == "Readings — 10 taken, 9 used"
    assert "cannot be read" not in view.warnings.text()
    progress = ("In progress: row 10: E / V [deg] not typed yet (rows 10–10); its readings "
                "enter no figure until it is complete, and a certificate waits for it.")
    assert view.summary.toPlainText().startswith(progress)
    assert "⚠ " + progress in view.warnings.text()
    assert not _red(bench, 9, "elevation_deg")
    for got, was in zip(view.error_plot.corrected_curve.getData(), corrected, strict=True):
        np.testing.assert_array_equal(got, was)
    window.told.clear()
    assert not window.export_certificate()
    assert window.told and window.told[0].startswith(
        "No certificate: row 10: E / V [deg] not typed yet is not complete.")

    # E typed: ten readings, nothing in progress
    type_and_return(qtbot, table, 9, columns[2], rows[9][2])
    _analysed(qtbot, bench)
    assert view.readings_label.text() == "Readings — 10 used"
    assert bench.result.incomplete is None
    assert view.error_plot.corrected_curve.getData()[0].size == 10

    # a reading cell blank in a row that is not the last: a bad cell
    clear_and_return(qtbot, table, 4, columns[1])
    _analysed(qtbot, bench)
    assert view.readings_label.text() == "Readings — 9 used, 1 bad cell(s)"
    assert view.warnings.text().startswith("⚠ 1 cell(s) cannot be read (row 5)")
    assert _red(bench, 4, "azimuth_deg")


def test_a_closure_half_typed_is_not_said_missing(polygon, window, qtbot, tmp_path):
    """Set 1 read, its closure's x typed (not yet its encoder): the closure is being read,
    not "no closure reading (the row back on its start face)" beside its progress line."""
    bench, view = polygon, polygon.view
    bench.load_certificate(_certificate(tmp_path))
    window.show()
    for face in range(1, FACES + 1):
        _take(qtbot, bench, face, 1)
    _analysed(qtbot, bench)
    unread = "⚠ Set 1: no closure reading (the row back on its start face): drift not checked."
    assert unread in view.warnings.text()  # not typed: missing
    type_and_return(qtbot, view.table, FACES, bench.sheet.column_index("ac_x_arcsec"),
                     _ac_x(1, 1, 1))
    _analysed(qtbot, bench)
    assert view.next_label.text() == "next: set 2: face 1 of 6 (7/14)"
    assert view.summary.toPlainText().startswith(
        "In progress: row 7: encoder a [deg] not typed yet (rows 7–7)")
    assert "no closure reading" not in view.warnings.text()
    assert "cannot be read" not in view.warnings.text()
    assert view.readings_label.text() == "Readings — 7 taken, 6 used"
    assert bench.result.mean_corrected_arcsec.size == FACES


def test_on_a_worker_too(theodolite, qtbot, samples_dir):
    """While readings are captured the analysis runs on a worker: the row being typed is in
    progress there as well (it is found on the GUI thread, with the sheet it analyses)."""
    from tests.app.test_cli_incomplete import _rows

    bench = theodolite
    _, rows = _rows(samples_dir / "theodolite_sample.csv")
    bench.set_capturing(True)
    try:
        bench.table_model.replace_all([[*r, "", ""] for r in rows[:9]] +
                                      [[*rows[9][:2], "", "", ""]])
        bench.refresh()
        assert bench.analysis_pending  # on the worker
        _analysed(qtbot, bench)
    finally:
        bench.set_capturing(False)
    assert bench.result is not None and bench.result.incomplete.typing.row == 9
    assert bench.view.readings_label.text() == "Readings — 10 taken, 9 used"
    assert "cannot be read" not in bench.view.warnings.text()
    assert not _red(bench, 9, "elevation_deg")


def test_half_typed_before_the_face_deviations(window, qtbot):
    """Readings typed before the polygon's certificate (its deviations awaited, live81), two
    a face: the next reading half-typed is taken and waits with the others, not a bad cell
    (its blank deviation cell waits as every row's does)."""
    from tests.app.test_polygon_live_day import _take as _take_of

    bench = next(polygon_bench(window, faces=FACES, plan_sets=2, readings_per_point=2))
    view = bench.view
    window.show()
    for face in (1, 2, 3):
        for reading in (1, 2):
            _take_of(qtbot, bench, face, reading, 1)
    row = _next_row(bench)
    type_and_return(qtbot, view.table, row, bench.sheet.column_index("ac_x_arcsec"),
                     _ac_x(4, 1, 1))
    _analysed(qtbot, bench)
    # main: "Readings — 6 taken, waiting for the face deviations, 1 bad cell(s)"
    assert view.readings_label.text() == "Readings — 7 taken, waiting for the face deviations"
    assert "cannot be read" not in view.warnings.text()
    assert not _red(bench, row, "encoder_deg")
    assert view.next_label.text() == "next: set 1: face 4 of 6, reading 2 of 2 (7/28)"
    window.capture_panel.close()
