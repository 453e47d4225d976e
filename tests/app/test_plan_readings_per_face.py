"""plan80: a polygon entry plan of sets with two readings per face (the setting *readings per
point*) had one row per face: the second reading of face 1 was typed into face 2's planned
row and every later reading one face early; the averaging then refused the sheet ("position
differs"), the technician's session spoiled. The plan now gives each face as many rows as
readings per face, and its next point says which reading of the face it is.

Through the real window: the readings typed in the table's editor, Return after each."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QLineEdit

from tests.app.capture.window_steps import show_workbench as _show

pytestmark = pytest.mark.slow  # a window, 24 readings typed

FACES = 12
#: the polygon's face deviations from its certificate (″), faces 1 … 12
DEVIATIONS = [0.0, 0.12, -0.08, 0.05, 0.2, -0.15, 0.03, -0.04, 0.1, -0.11, 0.07, -0.02]


def _encoder(face: int, reading: int) -> str:
    """The encoder at ``face`` (30° a face from 10°), its two readings 0.4″ apart."""
    return f"{10.0 + 30.0 * (face - 1) + (reading - 1) * 0.4 / 3600.0:.6f}"


def _ac_x(face: int, reading: int) -> str:
    return f"{0.3 * ((face * 7) % 5 - 2) + 0.05 * (reading - 1):.2f}"


def _type_and_return(qtbot, table, row: int, column: int, text: str) -> None:
    """``text`` typed into cell (row, column) through the table's editor, then Return."""
    index = table.model().index(row, column)
    table.setCurrentIndex(index)
    table.edit(index)
    editors = [w for w in table.viewport().findChildren(QLineEdit) if w.isVisible()]
    assert len(editors) == 1
    editors[0].selectAll()
    qtbot.keyClicks(editors[0], text)
    qtbot.keyClick(editors[0], Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.model().data(table.model().index(row, column)) == text)


def _cursor_row(table) -> int:
    index = table.currentIndex()
    return index.row() if index.isValid() else 0


@pytest.fixture
def bench(window, tmp_path):
    presenter = _show(window, "polygon")
    presenter.table_model.replace_all([], "empty")
    presenter.set_settings({**presenter.settings, "faces": FACES, "plan_sets": 1,
                            "readings_per_point": 2})
    certificate = tmp_path / "polygon12_certificate.csv"
    certificate.write_text("position,deviation_arcsec\n" + "".join(
        f"{face},{value:g}\n" for face, value in enumerate(DEVIATIONS, start=1)))
    presenter.load_certificate(str(certificate))  # before the run: kept by face
    presenter.undo_stack.clear()
    window.show()  # the table's editor opens in a shown window
    return presenter


def _column(bench, key: str) -> int:
    return bench.sheet.column_index(key)


def test_typed_readings_of_twelve_faces_twice_each_land_on_their_faces(bench, qtbot):
    table = bench.view.table
    encoder, ac_x = _column(bench, "encoder_deg"), _column(bench, "ac_x_arcsec")
    captions = {}
    for face in range(1, FACES + 1):
        for reading in (1, 2):
            row = _cursor_row(table)  # where Return sent the cursor: the plan's next row
            captions[(face, reading)] = bench._next_text()
            _type_and_return(qtbot, table, row, ac_x, _ac_x(face, reading))
            _type_and_return(qtbot, table, row, encoder, _encoder(face, reading))
    sheet = bench.sheet
    used = [r for r in range(sheet.row_count) if sheet.text(r, encoder).strip()]
    assert len(used) == 2 * FACES
    faces = [sheet.text(r, _column(bench, "position")) for r in used]
    assert faces == [str(f) for f in range(1, FACES + 1) for _ in (1, 2)]
    assert {sheet.text(r, _column(bench, "set")) for r in used} == {"1"}
    # each row got its own face's deviation from the certificate
    assert [float(sheet.text(r, _column(bench, "polygon_dev_arcsec"))) for r in used] == \
        pytest.approx([d for d in DEVIATIONS for _ in (1, 2)])
    # the next point names the reading of the face
    assert captions[(1, 1)] == "next: set 1: face 1 of 12, reading 1 of 2 (0/26)"
    assert captions[(3, 2)] == "next: set 1: face 3 of 12, reading 2 of 2 (5/26)"
    assert bench._next_text() == "next: set 1: closure on face 1, reading 1 of 2 (24/26)"
    # the closure's two readings: the analysis averages every face's two, no refusal
    for reading in (1, 2):
        row = _cursor_row(table)
        _type_and_return(qtbot, table, row, ac_x, _ac_x(1, reading))
        _type_and_return(qtbot, table, row, encoder, _encoder(1, reading))
    assert bench.plan_placement() is None
    qtbot.waitUntil(lambda: not bench.analysis_pending and bench.parsed is not None
                    and bench.parsed.n == 26, timeout=10000)
    assert not bench.parsed.errors
    assert bench.problem == ""
    assert bench.result is not None and bench.result.repeats.n == 2
    assert bench.result.repeats.rows.shape == (FACES + 1, 2)
