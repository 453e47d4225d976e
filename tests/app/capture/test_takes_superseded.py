"""Review 62 F1, row 17: a take at the wrong face (encoder 90° for face 3, the
autocollimator at 1.51″), its cells cleared (Delete, "Clear cells") and the reading taken
again into the same row. The older take kept the row: the certificate printed "reading of
row 17 edited after capture: 300.00002 → —" (the readout's) and the window marked AC x and
AC y orange ("1.51 → 1.90") until the next change, although every cell held what the
instruments sent.

Now the newer take supersedes the older one of its instrument in the row (the raw record
keeps both, the older marked with the newer's key): the row is said once, "captured again",
never "edited", by the one function the window's marks and the certificate both use — at
every moment, the take's own sheet change included. Cells cleared and not taken again are
said cleared. Through the real window: the autocollimator and readout simulators, the
entry plan, the table's Clear cells, Edit › Undo and Redo."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QItemSelectionModel

from tests.app.capture.test_takes_undone import FAST, X, Y, _said, _type
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds

AGAIN = ("reading of row {row} captured again, superseding an earlier take (both kept in the "
         "instrument output)")


def _clear(bench, row: int, keys: list[str]) -> None:
    """The cells selected and the table's Clear cells (Delete)."""
    table, model = bench.view.table, bench.table_model
    columns = [c.key for c in model.sheet.columns]
    selection = table.selectionModel()
    selection.clearSelection()
    for key in keys:
        selection.select(model.index(row, columns.index(key)),
                         QItemSelectionModel.SelectionFlag.Select)
    table.clear_action.trigger()


def _wait_for(qtbot, link, values) -> None:
    qtbot.waitUntil(lambda: link.latest is not None and link.usable and all(
        abs(a - b) < 1e-4 for a, b in zip(link.latest.values, values, strict=False)),
        timeout=5000)


@pytest.fixture
def planned(window):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": 12, "plan_sets": 2})
    bench.undo_stack.clear()
    yield bench
    window.capture_panel.close()


def test_a_row_cleared_and_taken_again_is_said_captured_again_never_edited(window, qtbot,
                                                                          planned):
    bench, model = planned, planned.table_model
    columns = [c.key for c in model.sheet.columns]
    panel = window.capture_panel
    undo, redo = window.menus.undo_action, window.menus.redo_action
    # the window's marks at each sheet change, after the window has set them (its handler
    # was connected first): the take's own change included
    marks: list[dict] = []
    model.sheet_changed.connect(lambda: marks.append(dict(model.edited_cells)))

    def said():
        return _said(window, bench)

    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(0.00004,)]) as ro:
        panel.connect_to("autocollimator", ac.port, **FAST)
        panel.connect_to("readout", ro.port, slot=1, **FAST)
        readout = panel.links[1]
        readout.column.setCurrentIndex(readout.column.findData("encoder_deg"))
        for face, (encoder, x, y) in enumerate([(0.00004, 0.5, 0.25), (30.00001, 0.75, 0.5),
                                                 (90.00002, 1.51, 0.25)]):  # face 4's
            ac.positions[0], ro.positions[0] = (x, y), (encoder,)
            _wait_for(qtbot, panel.links[0], (x, y))
            _wait_for(qtbot, readout, (encoder,))
            assert panel.take_reading() == f"row {face + 1}"
        assert said() == [] and model.edited_cells == {}
        row = 2
        assert (model.sheet.text(row, columns.index("encoder_deg")),
                model.sheet.text(row, columns.index(X))) == ("90.00002", "1.51")

        # the wrong take's reading cells cleared: a change of captured readings, said so
        # (was: "edited after capture: 1.51 → —")
        _clear(bench, row, ["encoder_deg", X, Y])
        cleared = ["reading of row 3 cleared after capture: 1.51",
                   "reading of row 3 cleared after capture: 0.25",
                   "reading of row 3 cleared after capture: 90.00002"]  # the readout's cell
        assert said() == cleared
        # the readout's encoder cell marked too (day review 64 P3: it was never marked)
        assert set(model.edited_cells) == {(row, columns.index(X)), (row, columns.index(Y)),
                                           (row, columns.index("encoder_deg"))}
        assert model.edited_cells[(row, columns.index(X))] == cleared[0]

        # taken again at face 3: the plan sends it back to row 3
        ac.positions[0], ro.positions[0] = (1.9, 0.5), (60.00001,)
        _wait_for(qtbot, panel.links[0], (1.9, 0.5))
        _wait_for(qtbot, readout, (60.00001,))
        marks.clear()
        assert panel.take_reading() == "row 3"
        assert (model.sheet.text(row, columns.index("encoder_deg")),
                model.sheet.text(row, columns.index(X))) == ("60.00001", "1.90")
        # was, until the next change: AC x and AC y orange, "edited after capture: 1.51 →
        # 1.90"; and on the certificate "reading of row 3 edited after capture: 90.00002 → —"
        assert marks and all(m == {} for m in marks), marks
        assert said() == [AGAIN.format(row=3)]
        sessions = {s["instrument"]: s for s in panel.raw_sessions("polygon")}
        for instrument in ("autocollimator", "readout"):
            session = sessions[instrument]
            takes = session["takes"]
            assert [t[0] for t in takes] == [0, 1, -1, 2], instrument
            newer = [instrument, session["port"], session["started_utc"], *takes[3][1:]]
            assert takes[2][3] == newer  # the older take: superseded, by the newer's key

        # Edit › Undo of the take (the plan's pre-fill of the next row first): the older take
        # has the row again, its cells cleared; Redo: captured again
        while model.sheet.text(row, columns.index(X)):
            undo.trigger()
        assert said() == cleared
        assert set(model.edited_cells) == {(row, columns.index(X)), (row, columns.index(Y)),
                                           (row, columns.index("encoder_deg"))}
        assert [t for s in panel.raw_sessions("polygon") for t in s["takes"] if len(t) > 3] == []
        assert [t[0] for s in panel.raw_sessions("polygon") for t in s["takes"]] == \
            [0, 1, 2, -1] * 2
        while redo.isEnabled():
            redo.trigger()
        assert said() == [AGAIN.format(row=3)] and model.edited_cells == {}

        # the newer reading edited afterwards is an edit, said beside the retake
        _type(bench, row, X, "1.95")
        assert said() == [AGAIN.format(row=3),
                          "reading of row 3 edited after capture: 1.9 → 1.95"]
        assert set(model.edited_cells) == {(row, columns.index(X))}
        undo.trigger()
        panel.disconnect_instrument()
    assert said() == [AGAIN.format(row=3)] and model.edited_cells == {}


def test_the_certificate_of_a_row_taken_again_says_captured_again_once(
        window, qtbot, samples_dir, tmp_path):
    """The polygon sample's last row: taken at the wrong place, cleared, taken again as
    the sample has it. The certificate prints the capture's SHA-256 and "reading of row 9
    captured again …" once, and no "edited after capture" (was: "reading of row 9 edited
    after capture: <the wrong x> → <the sample's x>" and its y, or "→ —")."""
    import hashlib
    import json
    import subprocess

    from app.certificate_issue import issue_certificate
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.register.store import Register

    bench = _show(window, "polygon")
    model, kind = bench.table_model, bench.kind
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    last = len(rows) - 1
    x, y = float(rows[last][3]), float(rows[last][4])
    blank = [list(r) for r in rows]
    blank[last][3:5] = ["", ""]
    model.replace_all(blank, "sample")
    panel = window.capture_panel
    bench.view.table.setCurrentIndex(model.index(last, 0))
    with AutocollimatorSimulator("pty", positions=[(x + 30.0, y - 2.0)]) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        _wait_for(qtbot, panel.links[0], (x + 30.0, y - 2.0))
        assert panel.take_reading() == f"row {last + 1}"
        _clear(bench, last, [X, Y])
        sim.positions[0] = (x, y)
        _wait_for(qtbot, panel.links[0], (x, y))
        bench.view.table.setCurrentIndex(model.index(last, 0))
        assert panel.take_reading() == f"row {last + 1}"
        panel.disconnect_instrument()
    sheet = [[bench.sheet.text(r, c) for c in range(len(rows[0]))]
             for r in range(bench.sheet.row_count)]
    assert [float(v) for v in sheet[last][3:5]] == [x, y]
    sessions = panel.raw_sessions("polygon")
    assert [t[0] for t in sessions[0]["takes"]] == [-1, last]
    assert _said(window, bench) == [AGAIN.format(row=last + 1)]
    result = kind.analyze(ReadingsSheet(kind.columns, sheet).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": ""})
    with Register(f"sqlite:///{tmp_path / 'register.sqlite'}") as register:
        record = issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                   kind.checked_settings({}), sheet, "retaken.anglebench.json",
                                   str(tmp_path / "retaken.pdf"), raw_capture=sessions)
    text = " ".join(subprocess.run(["pdftotext", str(tmp_path / "retaken.pdf"), "-"],
                                   capture_output=True, text=True, check=True).stdout.split())
    kept = json.loads(record.project_json)["raw_capture"]["polygon"]
    digest = hashlib.sha256(json.dumps(kept["sessions"], ensure_ascii=False,
                                       separators=(",", ":")).encode()).hexdigest()
    assert record.raw_sha256 == digest and digest in text.replace(" ", "")
    # the heading beside it, 采集后变动 / Changes after capture (it said "Edited after
    # capture"), may fall inside the wrapped line in the text pdftotext gives
    assert text.count("采集后变动") == text.count("Changes after capture") == 1
    lines = text.replace("采集后变动 ", "").replace("Changes after capture ", "")
    assert lines.count(AGAIN.format(row=last + 1)) == 1, text
    assert "edited" not in text.lower() and "→ —" not in text
    assert kept["sessions"][0]["takes"][0][3][3:] == kept["sessions"][0]["takes"][1][1:]


def test_a_take_and_the_plans_pre_fill_of_the_next_row_are_one_undo_step(window, qtbot,
                                                                          planned):
    """rev62day F15: after a take the first Ctrl+Z undid "Entry plan: set 1: face 2 of 12"
    (the next row's pre-fill), only the second the take. One Edit › Undo now takes the
    reading back, pre-fill included; Redo puts both back."""
    bench, model = planned, planned.table_model
    columns = [c.key for c in model.sheet.columns]
    panel = window.capture_panel
    undo, redo = window.menus.undo_action, window.menus.redo_action

    def rows():
        return [[model.sheet.text(r, c) for c in range(len(columns))]
                for r in range(model.sheet.row_count)]

    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac:
        panel.connect_to("autocollimator", ac.port, **FAST)
        _wait_for(qtbot, panel.links[0], (0.5, 0.25))
        before, steps = rows(), bench.undo_stack.count()
        assert panel.take_reading() == "row 1"
        taken = rows()
        assert taken[0][columns.index(X)] == "0.50"
        assert len(taken) == 2 and any(taken[1])  # the next point pre-filled in row 2
        assert bench.undo_stack.count() == steps + 1
        assert undo.text().endswith("Take reading (row 1)")
        undo.trigger()
        assert rows() == before and [t[0] for s in panel.raw_sessions("polygon")
                                     for t in s["takes"]] == [-1]
        redo.trigger()
        assert rows() == taken and _said(window, bench) == []
        panel.disconnect_instrument()
