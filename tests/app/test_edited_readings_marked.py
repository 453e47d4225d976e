"""A captured reading edited in the sheet is marked in the readings table (issue 40 item
11): its cell drawn apart, its tooltip saying from what to what; put back, the mark goes."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSettings, Qt
from PySide6.QtWidgets import QMessageBox

from app.main_window import MainWindow
from models.capture.raw_record import session_json
from models.project.recovery import RecoveryStore
from widgets.readings_table_model import EDITED_BRUSH

pytestmark = pytest.mark.slow  # a window


def test_an_edited_captured_reading_is_marked_in_the_table(qtbot, tmp_path):
    settings = QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat)
    window = MainWindow(settings=settings, recovery=RecoveryStore(tmp_path / "recovery"))
    window.ask = lambda *a: QMessageBox.StandardButton.Yes
    qtbot.addWidget(window)
    bench = window.presenter("polygon")
    bench.table_model.set_cells([(0, 0, "1"), (0, 1, "0"), (0, 2, "0"), (0, 3, "12.5"),
                                 (0, 4, "-3.25"), (2, 0, "3"), (2, 1, "60"), (2, 2, "0"),
                                 (2, 3, "21.56"), (2, 4, "1")])
    frames = [(0.0, b"3 003 12.500 -3.250", True), (0.1, b"3 003 21.560 1.000", True)]
    window.projects.load_raw_capture({"polygon": [session_json(
        "autocollimator", "/dev/ttyUSB0", 9600, "2026-12-02T01:02:03+00:00", frames,
        [[0, 0, 0], [2, 1, 1]])]})
    model = bench.table_model
    assert model.edited_cells == {}
    model.set_cells([(2, 3, "26.56")])
    assert set(model.edited_cells) == {(2, 3)}
    index = model.index(2, 3)
    assert model.data(index, Qt.ItemDataRole.BackgroundRole) == EDITED_BRUSH
    assert model.data(index, Qt.ItemDataRole.ToolTipRole) == \
        "reading of row 3 edited after capture: 21.56 → 26.56"
    assert model.data(model.index(0, 3), Qt.ItemDataRole.BackgroundRole) is None
    model.set_cells([(2, 3, "21.560")])  # put back: as captured
    assert model.edited_cells == {}
    window.capture_panel.close()
