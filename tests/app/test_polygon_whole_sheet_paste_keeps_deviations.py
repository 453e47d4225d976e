"""Leftovers 79, item 6: a polygon certificate loaded (its deviations kept by face,
``certificate_by_face``), a full set of readings pasted over the whole sheet (Ctrl+A,
Ctrl+V) got none of them: rows with their face and readings and no deviation, red, no result
— while rows typed or pasted over part of the sheet get their face's deviation
(PolygonPresenter._deviation_cells, gui78). A paste that replaces the sheet brings them the
same way, in the same undo step."""

from __future__ import annotations

import pytest
from PySide6.QtWidgets import QAbstractItemView

from tests.app.test_polygon_certificate_kept_by_face import (
    DEVIATIONS,
    ENCODER,
    _col,
    _empty_polygon,
    polygon_certificate_file,
)


@pytest.fixture
def certificate(tmp_path):
    return polygon_certificate_file(tmp_path)


def _block(header: bool, deviations: dict[int, str] | None = None) -> str:
    """Faces 1…6 with their readings, tab-separated as a spreadsheet copies them; with
    ``header`` the keys named (no deviation column), else every column of the sheet with
    the deviation blank (``deviations``: those given)."""
    given = deviations or {}
    if header:
        lines = ["position\tencoder_deg\tac_x_arcsec\tac_y_arcsec"]
        lines += [f"{face}\t{ENCODER[face - 1]}\t0.5\t1.0" for face in range(1, 7)]
    else:
        lines = [f"{face}\t{ENCODER[face - 1]}\t{given.get(face, '')}\t0.5\t1.0"
                 for face in range(1, 7)]
    return "\n".join(lines)


def _paste_over_all(bench, qtbot, text: str) -> str:
    table = bench.view.table
    table.setSelectionMode(QAbstractItemView.SelectionMode.ExtendedSelection)
    table.selectAll()
    return table.paste_text(text)


@pytest.mark.parametrize("header", [True, False])
def test_a_paste_over_the_whole_sheet_gets_the_kept_deviations(window, qtbot, certificate,
                                                               header):
    bench = _empty_polygon(window)
    assert bench.load_certificate(str(certificate)) == 0  # no row yet: kept by face
    dev = _col(bench, "polygon_dev_arcsec")
    # two rows typed first, so that the paste replaces a sheet (Ctrl+A over them)
    for row, face in enumerate((1, 2)):
        bench.table_model.set_cells([(row, _col(bench, "position"), str(face)),
                                     (row, _col(bench, "encoder_deg"), f"{ENCODER[row]}")])
    assert [bench.sheet.text(r, dev) for r in range(2)] == ["0.1", "0.2"]
    steps = bench.undo_stack.count()
    said: list[str] = []
    bench.view.table.notice.connect(lambda text: said.append(str(text)))
    assert _paste_over_all(bench, qtbot, _block(header)) == "replace"
    assert bench.sheet.row_count == 6
    assert [bench.sheet.text(r, dev) for r in range(6)] == [f"{d:g}" for d in DEVIATIONS]
    assert bench.sheet.text(5, _col(bench, "ac_x_arcsec")) == "0.5"
    qtbot.waitUntil(lambda: not bench.analysis_pending and bench.parsed is not None,
                    timeout=10000)
    assert bench.parsed.n == 6 and not bench.parsed.errors  # no red row
    if header:  # what the paste did with the columns: the deviation not said left empty
        assert said == ['Pasted into pos, encoder a [deg], AC x ["], AC y ["]; set, '
                        'dir [+/−] left empty'], said
    # one step: undone, the two typed rows are back as they were
    assert bench.undo_stack.count() == steps + 1
    bench.undo_stack.undo()
    assert bench.sheet.row_count == 2
    assert [bench.sheet.text(r, dev) for r in range(2)] == ["0.1", "0.2"]


def test_a_deviation_pasted_with_the_readings_is_kept_as_pasted(window, qtbot, certificate):
    bench = _empty_polygon(window)
    bench.load_certificate(str(certificate))
    dev = _col(bench, "polygon_dev_arcsec")
    for row, face in enumerate((1, 2)):
        bench.table_model.set_cells([(row, _col(bench, "position"), str(face)),
                                     (row, _col(bench, "encoder_deg"), f"{ENCODER[row]}")])
    # face 3's deviation pasted with it (another certificate's figure): the paste's, not
    # the one kept; the others the kept ones
    assert _paste_over_all(bench, qtbot, _block(False, {3: "0.31"})) == "replace"
    assert [bench.sheet.text(r, dev) for r in range(6)] == ["0.1", "0.2", "0.31", "0", "-0.2",
                                                            "-0.1"]


def test_without_a_certificate_kept_a_paste_is_left_as_pasted(window, qtbot):
    bench = _empty_polygon(window)
    for row, face in enumerate((1, 2)):
        bench.table_model.set_cells([(row, _col(bench, "position"), str(face)),
                                     (row, _col(bench, "encoder_deg"), f"{ENCODER[row]}")])
    assert _paste_over_all(bench, qtbot, _block(True)) == "replace"
    assert [bench.sheet.text(r, _col(bench, "polygon_dev_arcsec")) for r in range(6)] == \
        [""] * 6

