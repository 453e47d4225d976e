"""live81: two things the polygon window said wrong on a live bench day (readings typed as
the run goes, an entry plan of sets with two readings a face).

1. Readings typed before the polygon's certificate was loaded (its face deviations not in
   the table): the readings box was titled "Readings — 0 used" beside a table full of
   readings, which a technician reads as "my readings were thrown away". They are kept and
   wait for the face deviations, as the pane says once; the title says so too.
2. A set complete but for its closure's second reading: the progress line said "point 13:
   1 of 2 readings" (the 13th point counted among the readings) where the plan above it
   said "next: set 1: closure on face 1, reading 2 of 2". It names the closure as the plan
   does, in a forward set and in the reverse set 2.

Through the real window: the readings typed in the table's editor, Return after each."""

from __future__ import annotations

import pytest

from tests.app.capture.window_steps import polygon_bench
from tests.app.table_typing import type_and_return

pytestmark = pytest.mark.slow  # a window, a few dozen readings typed

FACES = 6
#: the polygon's face deviations from its certificate (″), faces 1 … 6
DEVIATIONS = [0.0, 0.12, -0.08, 0.05, 0.2, -0.15]
MISSING = ("the polygon's face deviations are missing: load its certificate (“Load polygon "
           "certificate…”, at the end of the set-up) or type them in the polygon dev [\"] column. "
           "A blank one is not taken as 0; the readings are kept.")


def _encoder(face: int, reading: int, set_: int) -> str:
    """The encoder at ``face`` (60° a face from 10°), its readings 0.4″ apart, a set 0.7″
    from the other."""
    return f"{10.0 + 60.0 * (face - 1) + ((reading - 1) * 0.4 + set_ * 0.7) / 3600.0:.6f}"


def _ac_x(face: int, reading: int, set_: int) -> str:
    return f"{0.3 * ((face * 7) % 5 - 2) + 0.05 * (reading - 1) + 0.03 * set_:.2f}"




def _take(qtbot, bench, face: int, reading: int, set_: int) -> int:
    """One reading typed where the plan sends it (the row Return left the cursor on): the
    autocollimator's x, then the encoder. Its row."""
    table = bench.view.table
    index = table.currentIndex()
    row = index.row() if index.isValid() else 0
    if row < bench.sheet.row_count:  # a planned row: its face filled by the plan
        assert bench.sheet.text(row, bench.sheet.column_index("position")) in ("", str(face))
    type_and_return(qtbot, table, row, bench.sheet.column_index("ac_x_arcsec"),
                     _ac_x(face, reading, set_))
    type_and_return(qtbot, table, row, bench.sheet.column_index("encoder_deg"),
                     _encoder(face, reading, set_))
    return row


def _analysed(qtbot, bench) -> None:
    qtbot.waitUntil(lambda: not bench.analysis_pending, timeout=20000)


@pytest.fixture
def bench(window):
    yield from polygon_bench(window, faces=FACES, plan_sets=2, readings_per_point=2)


def _certificate(tmp_path) -> str:
    path = tmp_path / "polygon6_certificate.csv"
    path.write_text("position,deviation_arcsec\n" + "".join(
        f"{face},{value:g}\n" for face, value in enumerate(DEVIATIONS, start=1)))
    return str(path)


def test_readings_typed_before_the_certificate_say_they_wait_for_it(bench, window, qtbot,
                                                                      tmp_path):
    window.show()  # the table's editor opens in a shown window
    view = bench.view
    for face in (1, 2, 3):
        for reading in (1, 2):
            _take(qtbot, bench, face, reading, 1)
    _analysed(qtbot, bench)
    assert bench.result is None
    assert view.summary.toPlainText() == f"No result: {MISSING}"
    # main: "Readings — 0 used" beside six readings
    assert view.readings_label.text() == "Readings — 6 taken, waiting for the face deviations"
    assert view.next_label.text() == "next: set 1: face 4 of 6, reading 1 of 2 (6/28)"

    # a reading typed wrong is a bad cell, and not among those waiting
    table = view.table
    type_and_return(qtbot, table, 2, bench.sheet.column_index("ac_x_arcsec"), "0,3x")
    _analysed(qtbot, bench)
    assert view.readings_label.text() == \
        "Readings — 5 taken, waiting for the face deviations, 1 bad cell(s)"
    assert view.warnings.text() == ("⚠ 1 cell(s) cannot be read (row 3); those rows are left "
                                    "out. Point at a red cell to see why.")
    type_and_return(qtbot, table, 2, bench.sheet.column_index("ac_x_arcsec"), _ac_x(2, 1, 1))
    _analysed(qtbot, bench)
    assert view.readings_label.text() == "Readings — 6 taken, waiting for the face deviations"

    # the certificate loaded: the deviations in, the readings counted as before
    assert bench.load_certificate(_certificate(tmp_path)) == 7  # and the planned row's
    bench.refresh()
    _analysed(qtbot, bench)
    assert "face deviations" not in view.readings_label.text()
    assert view.readings_label.text() == "Readings — 6 used"


def test_the_closure_short_of_its_second_reading_is_named_as_the_plan_names_it(
        bench, window, qtbot, tmp_path):
    bench.load_certificate(_certificate(tmp_path))  # before the run: kept by face
    window.show()
    view = bench.view
    summary = view.summary
    forward, reverse = list(range(1, FACES + 1)), [1, *range(FACES, 1, -1)]
    for face in forward:
        for reading in (1, 2):
            _take(qtbot, bench, face, reading, 1)
    row = _take(qtbot, bench, 1, 1, 1)  # the closure's first reading
    _analysed(qtbot, bench)
    assert row == 2 * FACES
    assert view.next_label.text() == "next: set 1: closure on face 1, reading 2 of 2 (13/28)"
    # main: "In progress: point 7: 1 of 2 readings (rows 13–13) …"
    assert summary.toPlainText().startswith(
        "In progress: set 1: closure on face 1: reading 1 of 2 (rows 13–13); its readings "
        "enter no figure until it is complete")
    assert "point 7" not in summary.toPlainText() + view.warnings.text()
    # its closure is being read, not missing (main: "⚠ Set 1: no closure reading (the row
    # back on its start face): drift not checked." beside it)
    assert "no closure reading" not in view.warnings.text()
    assert "⚠ In progress: set 1: closure on face 1: reading 1 of 2" in view.warnings.text()
    assert str(bench.result.incomplete.text()) == "set 1: closure on face 1: reading 1 of 2"
    assert bench.result.mean_corrected_arcsec.size == FACES  # set 1's faces keep their result
    assert view.readings_label.text() == "Readings — 13 taken, 12 used"

    _take(qtbot, bench, 1, 2, 1)  # the closure's second reading: set 1 complete
    _analysed(qtbot, bench)
    assert bench.result.incomplete is None
    assert not summary.toPlainText().startswith("In progress")
    assert view.readings_label.text() == "Readings — 14 used"

    # set 2, the reverse set (1, 6, 5 … 2, then 1 again), likewise
    for face in reverse:
        for reading in (1, 2):
            _take(qtbot, bench, face, reading, 2)
    _take(qtbot, bench, 1, 1, 2)
    _analysed(qtbot, bench)
    assert view.next_label.text() == "next: set 2: closure on face 1, reading 2 of 2 (27/28)"
    assert summary.toPlainText().startswith(
        "In progress: set 2: closure on face 1: reading 1 of 2 (rows 27–27)")
    assert "no closure reading" not in view.warnings.text()
    assert bench.result.incomplete.as_dict()["point"] == {
        "name": "set 2: closure on face 1", "readings": 1, "expected": 2}
    assert view.readings_label.text() == "Readings — 27 taken, 26 used"
