"""Review 62 F4: a take undone (Edit › Undo of the take, or of the import the take went into)
kept its row, so a reading typed there by hand later was printed on the certificate "edited
after capture", with the undone take's values. The take and its cells are one undo step
now: the undo leaves no cell claiming the take, the redo puts it back.

Through the real window: the autocollimator simulator over a pty, the panel's Take reading,
Edit › Undo and Redo, cells typed as the table's editor types them. Then a property: random
insert, delete, type, take, undo and redo against a model of which row holds which take,
kept apart from the code (snapshots of the rows for undo and redo)."""

from __future__ import annotations

import random

import pytest

from app.certificate_issue import readings_edited_after_capture
from app.main_window import _SheetRows
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, TheodoliteSimulator

pytestmark = pytest.mark.slow  # a window and an instrument for seconds

FAST = {"silence_s": 0.3, "retries": 4, "retry_pause_s": 0.05}
X, Y = "ac_x_arcsec", "ac_y_arcsec"


def _said(window, bench) -> list[str]:
    return [str(e.text()) for e in readings_edited_after_capture(
        bench.kind, bench.settings, _SheetRows(bench.sheet),
        window.capture_panel.raw_sessions(bench.kind.key))]


def _take(window, qtbot, bench, row: int) -> int:
    """The panel's Take reading with the cursor in ``row``; the row it went to (0-based)."""
    panel = window.capture_panel
    qtbot.waitUntil(lambda: panel.take_button.isEnabled() and not panel.used_again(),
                    timeout=5000)
    bench.view.table.setCurrentIndex(bench.table_model.index(row, 0))
    done = panel.take_reading()
    assert done.startswith("row ")
    return int(done[4:]) - 1


def _type(bench, row: int, column: str, text: str) -> None:
    """A cell typed in the table (its editor commits through setData)."""
    model = bench.table_model
    keys = [c.key for c in model.sheet.columns]
    assert model.setData(model.index(row, keys.index(column)), text)


def _cells(bench, row: int) -> tuple[str, str]:
    sheet = bench.sheet
    keys = [c.key for c in sheet.columns]
    return sheet.text(row, keys.index(X)), sheet.text(row, keys.index(Y))


@pytest.fixture
def polygon(window):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.undo_stack.clear()
    yield bench
    window.capture_panel.close()


def test_a_reading_typed_where_a_take_was_undone_is_not_printed_as_captured(window, qtbot,
                                                                            polygon):
    bench, model = polygon, polygon.table_model
    undo, redo = window.menus.undo_action, window.menus.redo_action
    panel = window.capture_panel
    for row, (x, y) in enumerate([("99", "9"), ("12.5", "-3.25"), ("21.56", "1"), ("7.25", "0.5")]):
        _type(bench, row, "position", str(row + 1))
        _type(bench, row, X, x)
        _type(bench, row, Y, y)
    with AutocollimatorSimulator("pty", positions=[(33.33, 2.22)], sigma=0.0) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        assert _take(window, qtbot, bench, 4) == 4  # row 5
        panel.disconnect_instrument()
    assert _cells(bench, 4) == ("33.33", "2.22")
    assert [t[0] for t in panel.raw_sessions("polygon")[0]["takes"]] == [4]
    assert _said(window, bench) == []

    undo.trigger()  # Ctrl+Z of the take: its cells and the take
    assert bench.sheet.row_count == 4
    # was: "reading of row 5 edited after capture: 33.33 → —"
    assert _said(window, bench) == [] and model.edited_cells == {}
    assert [t[0] for t in panel.raw_sessions("polygon")[0]["takes"]] == [-1]

    redo.trigger()  # the take back, in its row
    assert _cells(bench, 4) == ("33.33", "2.22")
    assert [t[0] for t in panel.raw_sessions("polygon")[0]["takes"]] == [4]
    _type(bench, 4, X, "33.4")  # a real edit of the captured reading is said
    assert _said(window, bench) == ["reading of row 5 edited after capture: 33.33 → 33.4"]
    assert set(model.edited_cells) == {(4, 3)}
    undo.trigger()  # the edit
    undo.trigger()  # the take
    assert _said(window, bench) == []

    # the technician types row 5 by hand: never captured, never said so
    for column, text in (("position", "5"), (X, "40.00"), (Y, "3.00")):
        _type(bench, 4, column, text)
    assert _cells(bench, 4) == ("40.00", "3.00")
    # was: "reading of row 5 edited after capture: 33.33 → 40.00" and "2.22 → 3.00"
    assert _said(window, bench) == [] and model.edited_cells == {}
    # and the project saved keeps the frames, its take claiming no row
    assert [t[0] for t in panel.raw_capture()["polygon"][0]["takes"]] == [-1]


def test_undoing_the_import_a_take_went_into_gives_the_typed_sheet_back_unclaimed(
        window, qtbot, polygon):
    bench, model = polygon, polygon.table_model
    undo, redo = window.menus.undo_action, window.menus.redo_action
    panel = window.capture_panel
    for row, (x, y) in enumerate([("5.5", "1"), ("6.5", "2"), ("8.75", "3")]):
        _type(bench, row, "position", str(row + 1))
        _type(bench, row, X, x)
        _type(bench, row, Y, y)
    model.replace_all([["1", "0", "0", "", ""], ["2", "45", "0", "", ""],
                       ["3", "90", "0", "", ""]], "Import plan.csv")
    with AutocollimatorSimulator("pty", positions=[(7.25, 0.5)], sigma=0.0) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        assert _take(window, qtbot, bench, 2) == 2  # row 3 of the imported sheet
        panel.disconnect_instrument()
    assert _cells(bench, 2) == ("7.25", "0.50")
    assert _said(window, bench) == []

    undo.trigger()  # the take
    undo.trigger()  # the import: the typed sheet is back
    assert _cells(bench, 2) == ("8.75", "3")
    # was: "reading of row 3 edited after capture: 7.25 → 8.75" and "0.5 → 3"
    assert _said(window, bench) == [] and model.edited_cells == {}

    redo.trigger()  # the import
    redo.trigger()  # the take, in row 3 of the imported sheet again
    assert _cells(bench, 2) == ("7.25", "0.50")
    assert [t[0] for t in panel.raw_sessions("polygon")[0]["takes"]] == [2]
    _type(bench, 2, Y, "0.75")
    assert _said(window, bench) == ["reading of row 3 edited after capture: 0.5 → 0.75"]


def test_the_certificate_of_a_sheet_typed_where_a_take_was_undone_says_no_edit(
        window, qtbot, polygon, samples_dir, tmp_path):
    """The polygon sample's last row: a take into it (the autocollimator a little off),
    Edit › Undo, the row typed by hand. The certificate issued from the window's sheet and
    raw capture prints the capture's SHA-256 and no "edited after capture" (was: "reading of
    row 9 edited after capture: <the take's x> → <the typed x>")."""
    import hashlib
    import json
    import subprocess

    from app.certificate_issue import issue_certificate
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.register.store import Register

    bench, model = polygon, polygon.table_model
    kind = bench.kind
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    model.replace_all([list(r) for r in rows[:-1]], "sample")
    last = len(rows) - 1
    x, y = float(rows[last][3]), float(rows[last][4])
    panel = window.capture_panel
    with AutocollimatorSimulator("pty", positions=[(x + 1.5, y - 0.75)], sigma=0.0) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        assert _take(window, qtbot, bench, last) == last
        panel.disconnect_instrument()
    window.menus.undo_action.trigger()
    for column, key in enumerate(c.key for c in kind.columns):
        if column < len(rows[last]) and rows[last][column]:
            _type(bench, last, key, rows[last][column])
    typed = [[bench.sheet.text(r, c) for c in range(len(rows[0]))]
             for r in range(bench.sheet.row_count)]
    assert typed == [list(r[:len(rows[0])]) for r in rows]
    sessions = panel.raw_sessions("polygon")
    result = kind.analyze(ReadingsSheet(kind.columns, typed).parse(), kind.checked_settings({}))
    data = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    data.update({"certificate_number": ""})
    with Register(f"sqlite:///{tmp_path / 'register.sqlite'}") as register:
        record = issue_certificate(register, kind, result, CertificateMetadata.from_dict(data),
                                   kind.checked_settings({}), typed, "typed.anglebench.json",
                                   str(tmp_path / "typed.pdf"), raw_capture=sessions)
    text = " ".join(subprocess.run(["pdftotext", str(tmp_path / "typed.pdf"), "-"],
                                   capture_output=True, text=True, check=True).stdout.split())
    kept = json.loads(record.project_json)["raw_capture"]["polygon"]
    digest = hashlib.sha256(json.dumps(kept["sessions"], ensure_ascii=False,
                                       separators=(",", ":")).encode()).hexdigest()
    assert record.raw_sha256 == digest and digest in text.replace(" ", "")
    assert "after capture" not in text
    assert [t[0] for s in sessions for t in s["takes"]] == [-1]  # the frames kept, unclaimed


def test_a_captured_azimuth_typed_a_whole_turn_away_is_marked_and_said(window, qtbot):
    """Review 62 M3: a captured angle typed 360° away was "as captured" (compared on the
    circle). The number on the certificate changed: it is an edit."""
    bench = _show(window, "theodolite")
    model = bench.table_model
    keys = [c.key for c in model.sheet.columns]
    column = keys.index("azimuth_deg")
    panel = window.capture_panel
    row = model.sheet.row_count
    bench.view.table.setCurrentIndex(model.index(row, 0))
    with TheodoliteSimulator("pty", positions=[(123.4567, 87.6543)]) as sim:
        panel.connect_to("theodolite", sim.port, **FAST)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=3000)
        assert panel.take_reading() == f"row {row + 1}"
        panel.disconnect_instrument()
    azimuth = model.sheet.text(row, column)
    assert float(azimuth) == pytest.approx(123.4567, abs=1e-4) and _said(window, bench) == []
    turned = "483" + azimuth[3:]  # + 360°
    _type(bench, row, "azimuth_deg", turned)
    (said,) = readings_edited_after_capture(bench.kind, bench.settings, _SheetRows(bench.sheet),
                                            panel.raw_sessions("theodolite"))
    assert (said.row, said.column, said.now) == (row, "azimuth_deg", turned)
    assert float(said.captured) == pytest.approx(float(azimuth), abs=0.051 / 3600)
    assert set(model.edited_cells) == {(row, column)}
    _type(bench, row, "azimuth_deg", azimuth)  # put back: as captured
    assert _said(window, bench) == [] and model.edited_cells == {}
    window.capture_panel.close()


# -- the property ---------------------------------------------------------------------------

class _Model:
    """Which row holds which take, kept apart from the code: each state the rows (the takes
    that claim each, oldest first, and its x and y), the takes whose rows were deleted, the
    takes superseded by a newer one into their row, as (older, newer) (review 62 F1), and
    the step that made it; undo and redo step through the states, as the undo stack does
    through the commands. Beside the states, the row each undone take was in (``ghosts``),
    moved by every step, its undo and redo, as rows move: a take into that row supersedes
    the undone take as it does a cleared one (both said "captured again")."""

    def __init__(self, rows: int) -> None:
        self.states = [([((), "", "") for _ in range(rows)], (), (), ())]
        self.at = 0
        self.values: list[tuple[str, str]] = []  # per take (in the order taken): its x, y
        self.ghosts: dict[int, int] = {}  # an undone take: the row it was in, moved since

    @property
    def rows(self):
        return self.states[self.at][0]

    @property
    def deleted(self):
        return self.states[self.at][1]

    @property
    def superseded(self):
        return self.states[self.at][2]

    def push(self, rows, deleted=None, superseded=None, step=()) -> None:
        del self.states[self.at + 1:]
        self.states.append((rows, self.deleted if deleted is None else deleted,
                            self.superseded if superseded is None else superseded, step))
        self.at += 1
        self._ghosts_forward(step)

    def _ghosts_forward(self, step) -> None:
        """The undone takes' rows after ``step`` (made or redone)."""
        if not step:
            return
        if step[0] == "insert":
            at, count = step[1:]
            self.ghosts = {t: g + count if g >= at else g for t, g in self.ghosts.items()}
        elif step[0] == "delete":
            gone = step[1]
            self.ghosts = {t: g - sum(r < g for r in gone) for t, g in self.ghosts.items()
                           if g not in gone}
        elif step[0] == "replace":
            self.ghosts = {}
        elif step[0] == "take":
            for old in step[3]:
                del self.ghosts[old]

    def _ghosts_back(self, step) -> None:
        """The undone takes' rows after the undo of ``step``."""
        if not step:
            return
        if step[0] == "insert":
            at, count = step[1:]
            self.ghosts = {t: g - count if g >= at + count else g
                           for t, g in self.ghosts.items() if not at <= g < at + count}
        elif step[0] == "delete":
            for r in sorted(step[1]):
                self.ghosts = {t: g + 1 if g >= r else g for t, g in self.ghosts.items()}
        elif step[0] == "replace":
            self.ghosts = {}
        elif step[0] == "take":
            row, new, olds = step[1:]
            self.ghosts.update({t: row for t in (new, *olds)})

    def insert(self, at: int, count: int) -> None:
        self.push(self.rows[:at] + [((), "", "")] * count + self.rows[at:],
                  step=("insert", at, count))

    def delete(self, gone: list[int]) -> None:
        claims = tuple(t for r in gone for t in self.rows[r][0])
        self.push([row for r, row in enumerate(self.rows) if r not in gone],
                  tuple(sorted(self.deleted + claims)), step=("delete", tuple(gone)))

    def replace(self, count: int) -> None:
        claims = tuple(t for row in self.rows for t in row[0])
        self.push([((), "", "")] * count, tuple(sorted(self.deleted + claims)),
                  step=("replace",))

    def type(self, row: int, x: str, y: str) -> None:
        rows = list(self.rows)
        rows[row] = (rows[row][0], x, y)
        self.push(rows)

    def clear(self, row: int) -> None:
        rows = list(self.rows)
        rows[row] = (rows[row][0], "", "")
        self.push(rows)

    def take(self, row: int, x: str, y: str) -> None:
        """A take into ``row``: it supersedes the takes that claimed it (cleared since) and
        the takes undone of it."""
        rows = list(self.rows) + ([((), "", "")] if row == len(self.rows) else [])
        assert rows[row][1:] == ("", ""), "a take goes to a row whose reading is blank"
        new = len(self.values)
        ghosts = tuple(sorted(t for t, g in self.ghosts.items() if g == row))
        superseded = self.superseded + tuple((old, new) for old in rows[row][0] + ghosts)
        rows[row] = ((new,), x, y)
        self.values.append((x, y))
        self.push(rows, superseded=superseded, step=("take", row, new, ghosts))

    def undo(self) -> None:
        if self.at > 0:
            self._ghosts_back(self.states[self.at][3])
            self.at -= 1

    def redo(self) -> None:
        if self.at < len(self.states) - 1:
            self.at += 1
            self._ghosts_forward(self.states[self.at][3])

    def take_rows(self) -> list[str]:
        """Per take: its row, 'deleted', 'superseded by N' or 'undone' (in no state before
        this one)."""
        where = {t: r for r, (claims, _, _) in enumerate(self.rows) for t in claims}
        by = dict(self.superseded)
        return [str(where[t]) if t in where else "deleted" if t in self.deleted
                else f"superseded by {by[t]}" if t in by else "undone"
                for t in range(len(self.values))]

    def again(self) -> list[int]:
        """The rows whose take superseded an earlier one (said once each, captured again)."""
        newer = {new for _, new in self.superseded}
        return [r for r, (claims, _, _) in enumerate(self.rows) if claims and claims[-1] in newer]

    def edited(self) -> set[tuple[int, str]]:
        """(row, column) of each captured reading the row holds no more (its latest take's):
        edited, or cleared."""
        out = set()
        for r, (claims, x, y) in enumerate(self.rows):
            if claims:
                tx, ty = self.values[claims[-1]]
                out |= {(r, key) for key, now, then in ((X, x, tx), (Y, y, ty))
                        if float(now or "nan") != float(then)}
        return out


def _stored_rows(takes) -> list[str]:
    """Per stored take, as :meth:`_Model.take_rows` says it (the newer by its index)."""
    takes = list(takes)
    index = {(t[1], t[2]): i for i, t in enumerate(takes)}
    return [str(t[0]) if t[0] >= 0 else "deleted" if t[0] <= -2
            else f"superseded by {index[tuple(t[3][3:])]}" if len(t) > 3 else "undone"
            for t in takes]


def _clear(bench, row: int) -> None:
    """Row ``row``'s x and y selected and the table's Clear cells (Delete)."""
    from PySide6.QtCore import QItemSelectionModel

    table, model = bench.view.table, bench.table_model
    selection = table.selectionModel()
    selection.clearSelection()
    for column in (3, 4):
        selection.select(model.index(row, column), QItemSelectionModel.SelectionFlag.Select)
    table.clear_action.trigger()


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_random_rows_takes_undo_and_redo_keep_each_take_in_the_cell_that_holds_it(
        window, qtbot, polygon, seed):
    bench, model = polygon, polygon.table_model
    undo, redo = window.menus.undo_action, window.menus.redo_action
    panel = window.capture_panel
    rnd = random.Random(seed)
    for row in range(4):  # typed by hand
        _type(bench, row, X, f"{500 + row}.5")
        _type(bench, row, Y, f"{600 + row}.5")
    bench.undo_stack.clear()
    ideal = _Model(0)
    ideal.states = [([((), f"{500 + r}.5", f"{600 + r}.5") for r in range(4)], (), (), ())]
    log: list[str] = []
    undone = edits = retaken = 0  # steps with a take undone, a reading edited, a row retaken
    with AutocollimatorSimulator("pty", positions=[(3.25, -1.5)], sigma=2.0) as sim:
        panel.connect_to("autocollimator", sim.port, **FAST)
        for _ in range(50):
            rows = bench.sheet.row_count
            op = rnd.choice(["take", "take", "take", "undo", "undo", "undo", "redo", "redo",
                             "insert", "delete", "type", "import", "clear", "retake",
                             "retake"])
            held = [r for r, row in enumerate(ideal.rows) if row[0] and any(row[1:])]
            if op == "take":
                at = _take(window, qtbot, bench, rnd.randrange(0, rows + 1))
                ideal.take(at, *_cells(bench, at))
                log.append(f"take→{at}")
            elif op == "undo" and undo.isEnabled():
                undo.trigger()
                ideal.undo()
                log.append("undo")
            elif op == "redo" and redo.isEnabled():
                redo.trigger()
                ideal.redo()
                log.append("redo")
            elif op in ("clear", "retake") and held:  # review 62 F1: Delete, then F9 again
                row = rnd.choice(held)
                _clear(bench, row)
                ideal.clear(row)
                log.append(f"clear {row}")
                if op == "retake":
                    # the cursor's row, blank again (or a row above still waiting for
                    # its reading: the panel's next point)
                    at = _take(window, qtbot, bench, row)
                    ideal.take(at, *_cells(bench, at))
                    log.append(f"take→{at}")
            elif op == "insert":
                at, count = rnd.randrange(0, rows + 1), rnd.randint(1, 2)
                model.insert_rows(at, count)
                ideal.insert(at, count)
                log.append(f"insert {at}+{count}")
            elif op == "delete" and rows:
                gone = sorted(rnd.sample(range(rows), k=min(rows, rnd.randint(1, 2))))
                model.remove_rows(gone)
                ideal.delete(gone)
                log.append(f"delete {gone}")
            elif op == "type" and rows:
                held = [r for r, row in enumerate(ideal.rows) if row[0]]  # a captured one, often
                row = rnd.choice(held) if held and rnd.random() < 0.6 else rnd.randrange(rows)
                x, y = f"{rnd.randint(700, 999)}.25", f"{rnd.randint(700, 999)}.75"
                _type(bench, row, X, x)
                _type(bench, row, Y, y)
                ideal.type(row, x, ideal.rows[row][2])  # two cells typed: two undo steps
                ideal.type(row, x, y)
                log.append(f"type {row}")
            elif op == "import":  # a file's plan replaces the sheet
                count = rnd.randint(2, 4)
                model.replace_all([[str(r + 1), "", "", "", ""] for r in range(count)],
                                  "Import plan.csv")
                ideal.replace(count)
                log.append(f"import {count}")
            else:
                continue
            assert [t[1:] for t in ideal.rows] == [_cells(bench, r)
                                                   for r in range(bench.sheet.row_count)], log
            sessions = panel.raw_sessions("polygon")
            assert _stored_rows(t for s in sessions for t in s["takes"]) == ideal.take_rows(), log
            said = readings_edited_after_capture(bench.kind, bench.settings,
                                                 _SheetRows(bench.sheet), sessions)
            assert {(e.row, e.column) for e in said if e.what in ("edited", "cleared")} == \
                ideal.edited(), log
            assert all(e.what == "cleared" for e in said
                       if e.in_sheet and not _cells(bench, e.row)[e.column == Y]), log
            # a row captured again is said once, never an edit of the superseded take
            assert [e.row for e in said if e.what == "again"] == ideal.again(), log
            assert sum(e.what == "deleted" for e in said) == len(ideal.deleted), log
            undone += "undone" in ideal.take_rows()
            edits += bool(ideal.edited())
            retaken += bool(ideal.again())
            assert {(r, c) for r, c in model.edited_cells} == {
                (r, 3 if key == X else 4) for r, key in ideal.edited()}, log
        panel.disconnect_instrument()
    assert undone and edits and retaken, log  # the sequence did what the test is about
