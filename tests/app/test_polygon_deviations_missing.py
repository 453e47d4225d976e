"""plan80: rows captured before the polygon's certificate was loaded (its face deviations
not in the table) all showed as bad cells — "Readings — 0 used, 24 bad cell(s)", every
row's deviation cell red, "24 cell(s) cannot be read … Point at a red cell", and "No
result: 0 usable readings" — as if the technician had typed 24 cells wrong.

The deviations are needed (SPEC §2: b_i = (i − 1)·360°/n + dev_i; a blank one taken as 0
would take the polygon as perfect and put its face deviations into the encoder's errors on
the certificate), so the window says ONE thing: they are missing, where they come from. A
cell that IS typed wrong stays red; once the certificate is loaded, the result comes."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from tests.app.capture.window_steps import show_workbench as _show
from widgets.readings_table_model import INVALID_BRUSH, LEFT_OUT_BRUSH

pytestmark = pytest.mark.slow  # a window

MISSING = ("the polygon's face deviations are missing: load its certificate (“Load polygon "
           "certificate…”, at the end of the set-up) or type them in the polygon dev [\"] column. "
           "A blank one is not taken as 0; the readings are kept.")
DEVIATIONS = [0.0, 0.12, -0.08, 0.05, 0.2, -0.15, 0.03, -0.04, 0.1, -0.11, 0.07, -0.02]


@pytest.fixture
def bench(window):
    """12 faces twice each, as captured (face, set, direction, encoder, AC x, AC y), the
    deviation column blank: no certificate loaded."""
    presenter = _show(window, "polygon")
    presenter.set_settings({**presenter.settings, "faces": 12, "plan_sets": 1,
                            "readings_per_point": 2})
    keys = [c.key for c in presenter.sheet.columns]
    rows = []
    for k, face in enumerate(f for f in range(1, 13) for _ in (1, 2)):
        row = dict.fromkeys(keys, "")
        row.update(position=str(face), set="1", direction="+",
                   encoder_deg=f"{10 + 30 * (face - 1) + (k % 2) * 1e-4:.6f}",
                   ac_x_arcsec=f"{0.3 * ((face * 7) % 5 - 2) + 0.05 * (k % 2):.2f}",
                   ac_y_arcsec=f"{-3.2 + 0.01 * face:.2f}")
        rows.append([row[key] for key in keys])
    presenter.table_model.replace_all(rows, "captured")
    presenter.refresh()
    return presenter


def _marks(bench, key: str) -> list[tuple[object, object]]:
    """(background, tooltip) of column ``key``'s cells, row by row."""
    model = bench.table_model
    c = bench.sheet.column_index(key)
    return [(model.data(model.index(r, c), Qt.ItemDataRole.BackgroundRole),
             model.data(model.index(r, c), Qt.ItemDataRole.ToolTipRole))
            for r in range(bench.sheet.row_count)]


def test_blank_deviations_are_said_once_not_marked_bad_in_every_row(bench, tmp_path):
    view = bench.view
    assert bench.result is None
    assert view.summary.toPlainText() == f"No result: {MISSING}"
    # no "24 bad cell(s)"; and not "0 used" beside 24 readings (live81)
    assert view.readings_label.text() == "Readings — 24 taken, waiting for the face deviations"
    assert view.warnings.text() == ""  # no "24 cell(s) cannot be read … red cell"
    assert _marks(bench, "polygon_dev_arcsec") == [(LEFT_OUT_BRUSH, MISSING)] * 24
    dev = bench.sheet.column_index("polygon_dev_arcsec")
    assert all(bench.table_model.cell_error(r, dev) is None for r in range(24))
    assert all(brush is None for brush, _ in _marks(bench, "encoder_deg"))

    # a cell typed wrong is still marked, and counted, as typed wrong
    model = bench.table_model
    ac_x = bench.sheet.column_index("ac_x_arcsec")
    model.setData(model.index(4, ac_x), "0,3x")
    bench.refresh()
    assert _marks(bench, "ac_x_arcsec")[4][0] == INVALID_BRUSH
    assert view.readings_label.text() == \
        "Readings — 23 taken, waiting for the face deviations, 1 bad cell(s)"
    assert view.warnings.text() == ("⚠ 1 cell(s) cannot be read (row 5); those rows are left "
                                    "out. Point at a red cell to see why.")
    assert view.summary.toPlainText() == f"No result: {MISSING}"
    # … and so is a deviation typed wrong, the blank ones still waiting for the certificate
    model.setData(model.index(4, ac_x), "0.30")
    model.setData(model.index(6, dev), "0.1.2")
    bench.refresh()
    marks = _marks(bench, "polygon_dev_arcsec")
    assert marks[6][0] == INVALID_BRUSH and "0.1.2" not in MISSING
    assert marks[:6] == [(LEFT_OUT_BRUSH, MISSING)] * 6
    assert view.readings_label.text() == \
        "Readings — 23 taken, waiting for the face deviations, 1 bad cell(s)"
    model.setData(model.index(6, dev), "")

    # the certificate loaded: every row gets its face's deviation, and the result comes
    certificate = tmp_path / "polygon12_certificate.csv"
    certificate.write_text("position,deviation_arcsec\n" + "".join(
        f"{face},{value:g}\n" for face, value in enumerate(DEVIATIONS, start=1)))
    assert bench.load_certificate(str(certificate)) == 24
    bench.refresh()
    assert bench.result is not None and bench.problem == ""
    assert view.readings_label.text().startswith("Readings — 24 used")
    assert all(brush is None for brush, _ in _marks(bench, "polygon_dev_arcsec"))


def test_the_chinese_sentence_names_the_column_as_the_table_heads_it(bench, window):
    """gui80: the Chinese sentence said "或在 polygon dev 列中键入" — an English column name
    the Chinese table has not (its header is "棱体偏差 [\"]"): it names the header shown."""
    window.set_language("zh_CN")
    bench.refresh()
    model = bench.table_model
    dev = bench.sheet.column_index("polygon_dev_arcsec")
    header = model.headerData(dev, Qt.Orientation.Horizontal)
    assert header == '棱体偏差 ["]'
    said = bench.view.summary.toPlainText()
    assert f"{header} 列" in said, said
    assert "polygon dev" not in said
    assert _marks(bench, "polygon_dev_arcsec")[0][1] == said.split("：", 1)[1]
