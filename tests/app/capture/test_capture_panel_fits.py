"""#41: the capture panel docks (left, right, bottom; remembered) and never widens the
window past its screen. Before, Instrument › Connect… made the window 1484 px wide on a
1280 px screen (Connect, auto-take, Window and Dwell cut off at the right edge)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSettings, Qt

from tests.capture_panel_probe import docked_probed

pytestmark = pytest.mark.slow  # a window in a process of its own, on a screen of 1280×720



def test_every_control_in_sight_at_1280x720_docked_anywhere(tmp_path_factory):
    found = docked_probed(tmp_path_factory)["panel"]
    assert {f["area"] for f in found} == {"right", "left", "bottom"}
    assert len(found) == 3 * 5  # every workbench at every side
    for seen in found:
        x, y, w, h = seen["frame"]
        ax, ay, aw, ah = seen["available"]
        where = f"{seen['workbench']} with the panel at the {seen['area']}"
        assert (aw, ah) == (1280, 720)
        assert x >= ax and x + w <= ax + aw and y + h <= ay + ah, f"{where}: {w}×{h}"
        assert seen["dock"].lower().startswith(seen["area"]), where
        assert not seen["hidden"], f"{where}: " + "; ".join(seen["hidden"])
        # the readings table and one plot stay in sight beside it
        assert min(seen["table"]) >= 60 and seen["plot"] and min(seen["plot"]) >= 60, where
        if seen["area"] != "bottom":
            assert seen["table"][1] >= 250 and seen["plot"][1] >= 250, where
        else:  # a low panel, its parts side by side: the plot keeps ~200 px (#41)
            assert seen["plot"][1] >= 200 and seen["table"][1] >= 150, where
            assert seen["panel"][1] <= 200 and seen["panel"][0] >= 1200, where


def test_where_the_panel_is_docked_is_remembered(qtbot, tmp_path):
    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    path = str(tmp_path / "settings.ini")
    first = MainWindow(settings=QSettings(path, QSettings.Format.IniFormat),
                       recovery=RecoveryStore(tmp_path / "recovery"))
    qtbot.addWidget(first)
    first.show()
    first.addDockWidget(Qt.DockWidgetArea.LeftDockWidgetArea, first.capture_panel)
    first.capture_panel.show()
    first.close()
    second = MainWindow(settings=QSettings(path, QSettings.Format.IniFormat),
                        recovery=RecoveryStore(tmp_path / "recovery"))
    qtbot.addWidget(second)
    second.show()
    assert second.dockWidgetArea(second.capture_panel) == Qt.DockWidgetArea.LeftDockWidgetArea
    assert second.capture_panel.isVisible()
    allowed = second.capture_panel.allowedAreas()
    for area in (Qt.DockWidgetArea.LeftDockWidgetArea, Qt.DockWidgetArea.RightDockWidgetArea,
                 Qt.DockWidgetArea.BottomDockWidgetArea):
        assert allowed & area
    second.close()
