"""A reading taken into a column kept in D°M′S″ form is what the instrument said until the
cell is changed.

A readout's reading (the encoder, θ, a position) went into a D°M′S″ column as D°M′S″, and the
certificate said "reading of row 4 edited or cleared after capture: no cell of the row holds
90.00012 now" although nobody had touched it: the check read the cells with ``float``, which
reads no D°M′S″ (models/capture/edits.py). A cell is read now as the analysis reads its
column (an angle column by the angle parser) and holds the reading within half the step the
take wrote it to; a cell changed by 1″, or cleared, is still said.

Through the real window: the readout and theodolite simulators over a pty, the panel's Take
reading, the cells typed in the table's editor and cleared by its Clear cells, and the
certificate issued from the window's sheet and raw capture."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt

from models.readings.angles import parse_angle_deg
from tests.app.capture.test_takes_superseded import AGAIN, _clear
from tests.app.capture.test_takes_undone import FAST, _said
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import ReadoutSimulator, TheodoliteSimulator

pytestmark = pytest.mark.slow  # a window and an instrument for seconds

#: the rows before the take, the column kept in D°M′S″
TYPED = ["0°00'00.000\"", "30°00'00.036\"", "60°00'00.072\""]
#: the readout's reading (its line "+90.00012 deg") and the cell the take writes of it
READING, CELL = 90.00012, "90°00'00.432\""
#: what is said of it: the cell the take wrote, checked as any captured cell, the reading
#: beside a D°M′S″ cell in D°M′S″ (was "edited or cleared after capture: no cell of the row
#: holds 90.00012 now", day review 64 P3)
EDITED = "reading of row 4 edited after capture: {} → {}"
CLEARED = "reading of row 4 cleared after capture: {}"


def _type_in_editor(window, qtbot, bench, row: int, key: str, text: str) -> None:
    """The cell double-clicked, its editor's text selected and ``text`` typed over it,
    Return."""
    table, model = bench.view.table, bench.table_model
    # the analysis of the last change finished first (its marks repainted over an open
    # editor once put the cell's text back into it; no longer:
    # tests/widgets/test_typing_survives_repaints.py)
    with qtbot.waitSignal(bench.analysed, timeout=10000):
        bench.refresh()
    index = model.index(row, [c.key for c in model.sheet.columns].index(key))
    table.scrollTo(index)
    where = table.visualRect(index).center()
    qtbot.mouseClick(table.viewport(), Qt.MouseButton.LeftButton, pos=where)
    qtbot.mouseDClick(table.viewport(), Qt.MouseButton.LeftButton, pos=where)
    qtbot.waitUntil(lambda: table._typing_delegate.editor is not None, timeout=3000)
    editor = table._typing_delegate.editor
    qtbot.waitUntil(editor.hasFocus, timeout=3000)
    editor.selectAll()
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: model.sheet.text(row, index.column()) == text, timeout=3000)


def _typed_rows(bench, column: str, texts: list[str]) -> None:
    """Rows whose ``column`` holds ``texts`` (a position's target beside it), one more
    waiting for its reading."""
    keys = [c.key for c in bench.table_model.sheet.columns]
    rows = []
    for i, text in enumerate([*texts, ""]):
        row = [""] * len(keys)
        row[keys.index(column)] = text
        if "target" in keys:  # positioning: the target the position was taken at
            row[keys.index("target")] = f"{30 * i}"
        rows.append(row)
    bench.table_model.replace_all(rows, "typed")
    bench.undo_stack.clear()


def _take_readout(window, qtbot, bench, row: int, column: str, value: float) -> None:
    """The readout at ``value`` into ``column`` ("Readout into"), the cursor in ``row``."""
    model, panel = bench.table_model, window.capture_panel
    keys = [c.key for c in model.sheet.columns]
    bench.view.table.setCurrentIndex(model.index(row, keys.index(column)))
    with ReadoutSimulator("pty", positions=[(value,)]) as ro:
        panel.connect_to("readout", ro.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData(column))
        qtbot.waitUntil(lambda: link.latest is not None and link.usable
                        and abs(link.latest.values[0] - value) < 1e-6, timeout=5000)
        assert panel.take_reading() == f"row {row + 1}"
        panel.disconnect_instrument()


@pytest.mark.parametrize("workbench,column", [
    ("polygon", "encoder_deg"), ("theodolite", "theta_deg"), ("positioning", "measured"),
    ("crosscal", "encoder_deg"), ("fringe", "theta_deg")])
def test_a_readouts_reading_in_a_dms_column_is_no_edit_until_the_cell_changes(
        window, qtbot, workbench, column):
    window.show()
    bench = _show(window, workbench)
    keys = [c.key for c in bench.table_model.sheet.columns]
    _typed_rows(bench, column, TYPED)
    _take_readout(window, qtbot, bench, 3, column, READING)
    assert bench.sheet.text(3, keys.index(column)) == CELL  # in the column's form
    # was: "reading of row 4 edited or cleared after capture: no cell of the row holds
    # 90.00012 now" (float() reads no D°M′S″)
    assert _said(window, bench) == []
    # the cell changed by 1″: said
    _type_in_editor(window, qtbot, bench, 3, column, "90°00'01.432\"")
    assert _said(window, bench) == [EDITED.format(CELL, "90°00'01.432\"")]
    # typed back as the take wrote it, in another spelling the analysis reads: as captured
    _type_in_editor(window, qtbot, bench, 3, column, "90 00 00.432")
    assert _said(window, bench) == []
    # cleared: said
    _clear(bench, 3, [column])
    assert bench.sheet.text(3, keys.index(column)) == ""
    # said as the column writes it (was "cleared after capture: 90.00012")
    assert _said(window, bench) == [CLEARED.format(CELL)]
    window.capture_panel.close()


def test_a_theodolites_dms_cells_hold_its_reading_to_the_step_they_show(window, qtbot):
    """The theodolite (0.1″) into A and E kept in D°M′S″: a cell written to 0.1″ holds the
    reading within 0.05″ (30.0001234° is 30°00′00.444″, written 30°00′00.4″); 1″ more, or
    the cell cleared, is an edit, marked in the table and said — the captured reading in
    D°M′S″ beside a D°M′S″ cell."""
    from widgets.readings_table_model import EDITED_BRUSH

    window.show()
    bench = _show(window, "theodolite")
    model = bench.table_model
    keys = [c.key for c in model.sheet.columns]
    rows = [[f"{10 * i}°00'00.0\"", f"{10 * i}°00'01.0\"", "2°00'02.0\"", "", ""]
            for i in range(3)]
    model.replace_all([*rows, ["30°00'00.0\"", "", "", "", ""]], "typed")
    panel = window.capture_panel
    bench.view.table.setCurrentIndex(model.index(3, 0))
    with TheodoliteSimulator("pty", positions=[(30.0001234, 87.6543)]) as sim:
        panel.connect_to("theodolite", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        assert panel.take_reading() == "row 4"
        panel.disconnect_instrument()
    azimuth, elevation = (model.sheet.text(3, keys.index(k)) for k in ("azimuth_deg",
                                                                        "elevation_deg"))
    assert (azimuth, elevation) == ("30°00'00.4\"", "2°20'44.5\"")  # E = 90° − V
    assert _said(window, bench) == [] and model.edited_cells == {}
    _type_in_editor(window, qtbot, bench, 3, "azimuth_deg", "30°00'01.4\"")
    # the captured reading said as the take wrote it beside the cell (was "30.000123398 →
    # 30°00'01.4\"")
    assert _said(window, bench) == [
        "reading of row 4 edited after capture: 30°00'00.4\" → 30°00'01.4\""]
    index = model.index(3, keys.index("azimuth_deg"))
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is EDITED_BRUSH
    _type_in_editor(window, qtbot, bench, 3, "azimuth_deg", azimuth)  # put back
    assert _said(window, bench) == [] and model.edited_cells == {}
    _clear(bench, 3, ["elevation_deg"])
    (said,) = _said(window, bench)
    # in D°M′S″ to the 0.1″ the take wrote, as the column has it (was "2.3457…")
    assert said == "reading of row 4 cleared after capture: 2°20'44.5\""
    assert set(model.edited_cells) == {(3, keys.index("elevation_deg"))}
    window.capture_panel.close()


def _issued_text(kind, bench, sessions, samples_dir, tmp_path, name: str) -> str:
    """The certificate issued from the window's sheet and raw capture, as pdftotext reads it."""
    import json
    import subprocess

    from app.certificate_issue import issue_certificate
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.register.store import Register

    sheet = [[bench.sheet.text(r, c) for c in range(len(kind.columns))]
             for r in range(bench.sheet.row_count)]
    result = kind.analyze(ReadingsSheet(kind.columns, sheet).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": ""})
    with Register(f"sqlite:///{tmp_path / f'{name}.sqlite'}") as register:
        issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                          kind.checked_settings({}), sheet, f"{name}.anglebench.json",
                          str(tmp_path / f"{name}.pdf"), raw_capture=sessions)
    return " ".join(subprocess.run(["pdftotext", str(tmp_path / f"{name}.pdf"), "-"],
                                   capture_output=True, text=True, check=True).stdout.split())


def test_the_certificate_of_an_encoder_read_into_dms_says_no_change(window, qtbot,
                                                                     samples_dir, tmp_path):
    """The polygon sample (its encoder in D°M′S″), its last encoder reading taken from the
    readout. The certificate said under "Changes after capture": "reading of row 50 edited
    or cleared after capture: no cell of the row holds 123.39568 now"; it says no change
    now, and says the change once the cell is 1″ off."""
    from models.readings.tabular_import import map_columns, read_table

    window.show()
    bench = _show(window, "polygon")
    kind = bench.kind
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    last, encoder = len(rows) - 1, kind.columns.index(
        next(c for c in kind.columns if c.key == "encoder_deg"))
    typed = rows[last][encoder]
    assert typed == "123°23'44.43\""
    value = round(parse_angle_deg(typed), 5)  # as the readout sends it: 123.39568
    blank = [list(r) for r in rows]
    blank[last][encoder] = ""
    bench.table_model.replace_all(blank, "sample")
    _take_readout(window, qtbot, bench, last, "encoder_deg", value)
    assert bench.sheet.text(last, encoder) == "123°23'44.448\""
    sessions = window.capture_panel.raw_sessions("polygon")
    text = _issued_text(kind, bench, sessions, samples_dir, tmp_path, "untouched")
    # was: "Changes after capture" and "reading of row 50 edited or cleared after capture"
    assert "Changes after capture" not in text and "采集后变动" not in text
    assert "after capture" not in text
    # the encoder cell 1″ off: the change is on the certificate
    _type_in_editor(window, qtbot, bench, last, "encoder_deg", "123°23'45.448\"")
    text = _issued_text(kind, bench, sessions, samples_dir, tmp_path, "edited")
    assert text.count("Changes after capture") == 1
    said = EDITED.replace("row 4", f"row {last + 1}").format("123°23'44.448\"",
                                                             "123°23'45.448\"")
    assert said in text.replace("采集后变动 ", "").replace("Changes after capture ", "")
    assert AGAIN.format(row=last + 1) not in text
    window.capture_panel.close()


@pytest.mark.parametrize("workbench,column", [("polygon", "encoder_deg"),
                                               ("positioning", "measured")])
def test_a_readouts_cell_edited_or_cleared_is_marked_in_the_table(window, qtbot, workbench,
                                                                  column):
    """The readout's cell ("Readout into: encoder a"), untouched: no mark; 1″ off, then
    cleared: orange, with the same tooltip as any captured cell. Was never marked (day review
    64 P3): the take's reading was recorded with no column ("a cell chosen at the time") and
    the window's marks keep only edits of a column, while the certificate said the change."""
    from widgets.readings_table_model import EDITED_BRUSH

    window.show()
    bench = _show(window, workbench)
    model = bench.table_model
    keys = [c.key for c in model.sheet.columns]
    _typed_rows(bench, column, TYPED)
    _take_readout(window, qtbot, bench, 3, column, READING)
    index = model.index(3, keys.index(column))
    assert model.sheet.text(3, index.column()) == CELL
    assert model.edited_cells == {}
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is not EDITED_BRUSH
    # 1″ more, typed in the cell's editor: orange, the change in its tooltip
    _type_in_editor(window, qtbot, bench, 3, column, "90°00'01.432\"")
    edited = EDITED.format(CELL, "90°00'01.432\"")
    qtbot.waitUntil(lambda: set(model.edited_cells) == {(3, index.column())}, timeout=3000)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is EDITED_BRUSH
    assert edited in model.data(index, Qt.ItemDataRole.ToolTipRole)
    # typed back as captured: no mark
    _type_in_editor(window, qtbot, bench, 3, column, CELL)
    qtbot.waitUntil(lambda: model.edited_cells == {}, timeout=3000)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is not EDITED_BRUSH
    # cleared with the table's Clear cells: orange, said cleared
    _clear(bench, 3, [column])
    qtbot.waitUntil(lambda: set(model.edited_cells) == {(3, index.column())}, timeout=3000)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) is EDITED_BRUSH
    # the tooltip says the reading in D°M′S″, as the column has it (was "90.00012")
    assert CLEARED.format(CELL) in model.data(index, Qt.ItemDataRole.ToolTipRole)
    window.capture_panel.close()
