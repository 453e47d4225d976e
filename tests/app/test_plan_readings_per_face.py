"""plan80: a polygon entry plan of sets with two readings per face (the setting *readings per
point*) had one row per face: the second reading of face 1 was typed into face 2's planned
row and every later reading one face early; the averaging then refused the sheet ("position
differs"), the technician's session spoiled. The plan now gives each face as many rows as
readings per face, and its next point says which reading of the face it is.

Through the real window: the readings typed in the table's editor, Return after each."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.app.table_typing import type_and_return

#: two polygon projects with an entry plan saved by main before plan80, and what its window
#: said of them (tests/fixtures/plan80/written_by_main.py)
WRITTEN_BY_MAIN = Path(__file__).resolve().parents[1] / "fixtures" / "plan80"

pytestmark = pytest.mark.slow  # a window, 24 readings typed

FACES = 12
#: the polygon's face deviations from its certificate (″), faces 1 … 12
DEVIATIONS = [0.0, 0.12, -0.08, 0.05, 0.2, -0.15, 0.03, -0.04, 0.1, -0.11, 0.07, -0.02]


def _encoder(face: int, reading: int) -> str:
    """The encoder at ``face`` (30° a face from 10°), its two readings 0.4″ apart."""
    return f"{10.0 + 30.0 * (face - 1) + (reading - 1) * 0.4 / 3600.0:.6f}"


def _ac_x(face: int, reading: int) -> str:
    return f"{0.3 * ((face * 7) % 5 - 2) + 0.05 * (reading - 1):.2f}"




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
            type_and_return(qtbot, table, row, ac_x, _ac_x(face, reading))
            type_and_return(qtbot, table, row, encoder, _encoder(face, reading))
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
        type_and_return(qtbot, table, row, ac_x, _ac_x(1, reading))
        type_and_return(qtbot, table, row, encoder, _encoder(1, reading))
    assert bench.plan_placement() is None
    qtbot.waitUntil(lambda: not bench.analysis_pending and bench.parsed is not None
                    and bench.parsed.n == 26, timeout=10000)
    assert not bench.parsed.errors
    assert bench.problem == ""
    assert bench.result is not None and bench.result.repeats.n == 2
    assert bench.result.repeats.rows.shape == (FACES + 1, 2)


def _table(bench) -> list[dict[str, str]]:
    sheet = bench.sheet
    keys = [c.key for c in sheet.columns]
    return [{k: sheet.text(r, c) for c, k in enumerate(keys)} for r in range(sheet.row_count)]


def _opened(window, name: str):
    path = WRITTEN_BY_MAIN / name
    assert window.projects.open_project(path)
    bench = _show(window, "polygon")
    saved = json.loads(path.read_text(encoding="utf-8"))["workbenches"]["polygon"]
    # opened as saved: the settings, the cells as typed, nothing changed by the opening
    assert {k: bench.settings[k] for k in saved["settings"]} == saved["settings"]
    assert [[r[c.key] for c in bench.sheet.columns] for r in _table(bench)] == saved["rows"]
    assert not window.projects.is_modified
    return bench


def test_projects_saved_before_keep_their_plan_and_figures(window, qtbot):
    said = json.loads((WRITTEN_BY_MAIN / "said_by_main.json").read_text(encoding="utf-8"))
    # one reading a face: the plan is the one main had, at the same point
    bench = _opened(window, "polygon_plan_one_reading.anglebench.json")
    plan = bench.entry_plan()
    assert [dict(p.cells) for p in plan.points] == said["one_reading"]["cells"]
    assert str(plan.next_text(_table(bench), bench.kind.plan_reading_keys)) == \
        said["one_reading"]["next"] == "next: set 1: face 8 of 12"
    assert list(plan.progress(_table(bench), bench.kind.plan_reading_keys)) == \
        said["one_reading"]["progress"]
    # two readings a face (the faces typed by hand on main, its plan could not take them):
    # the same figures; the plan now counts both readings of every face
    bench = _opened(window, "polygon_plan_two_readings.anglebench.json")
    assert bench.settings["readings_per_point"] == 2 and bench.settings["plan_sets"] == 1
    qtbot.waitUntil(lambda: not bench.analysis_pending and bench.result is not None,
                    timeout=10000)
    assert list(bench.result.mean_corrected_arcsec) == pytest.approx(
        said["two_readings"]["mean_corrected_arcsec"], abs=1e-12)
    plan = bench.entry_plan()
    assert said["two_readings"]["progress"] == [13, 13]  # main: a row a face, 13 of 26 taken
    assert plan.progress(_table(bench), bench.kind.plan_reading_keys) == (26, 26)
    assert str(plan.next_text(_table(bench), bench.kind.plan_reading_keys)) == \
        "plan complete (26 points)"
