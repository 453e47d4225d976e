"""Day 65, F10: the instrument panel takes room from the readings only where it is used.

Before, the window's saved state opened the panel on every workbench, with nothing
connected (~240 px at 100 %, 370 of 853 at 150 %): the theodolite's run and dir columns
behind a scroll bar, the set-up cut. Now it is open on the workbenches it was open on when
last left (or where an instrument is connected), closed elsewhere, and so at the next start.
And a fringe take's u sin/u cos (12 digits) were cut ("0.2659…") beside the panel: the
columns of a long sheet were measured for its first readings only, never again."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QMessageBox

from tests.app.capture.window_steps import show_workbench as _show

pytestmark = pytest.mark.slow  # windows: more than 0.4 s


def _window(path, qtbot):
    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    w = MainWindow(settings=QSettings(str(path / "settings.ini"), QSettings.Format.IniFormat),
                   recovery=RecoveryStore(path / "recovery"))
    w.ask = lambda *a: QMessageBox.StandardButton.Discard
    qtbot.addWidget(w)
    w.show()
    return w


def test_the_panel_is_open_only_on_the_workbench_it_was_opened_on(qtbot, tmp_path):
    window = _window(tmp_path, qtbot)
    panel = window.capture_panel
    _show(window, "theodolite")
    assert panel.isHidden()
    window.menus.show_panel_action.trigger()  # Instrument › Show the instrument panel
    assert panel.isVisible()
    _show(window, "fringe")  # nothing connected: the fringe's readings keep their width
    assert panel.isHidden()
    _show(window, "positioning")
    assert panel.isHidden()
    _show(window, "theodolite")
    assert panel.isVisible()
    _show(window, "fringe")
    window.close()
    # the next start, on the fringe workbench: closed there, open on the theodolite's
    again = _window(tmp_path, qtbot)
    assert again.current.kind.key == "fringe"
    assert again.capture_panel.isHidden()
    _show(again, "theodolite")
    assert again.capture_panel.isVisible()
    again.capture_panel.close()  # closed there by its title bar's button: so at the next start
    again.close()
    third = _window(tmp_path, qtbot)
    _show(third, "theodolite")
    assert third.capture_panel.isHidden()
    third.close()


def test_a_fringe_take_gets_columns_wide_enough_for_its_values(window, qtbot):
    fringe = _show(window, "fringe")
    fringe.load_sample()
    table = fringe.view.table
    keys = [c.key for c in fringe.table_model.sheet.columns]
    rng = np.random.default_rng(3)
    phase = np.linspace(0.0, 40.0 * np.pi, 2052)
    u_sin = 0.5 * np.sin(phase) + 1e-4 * rng.standard_normal(phase.size)
    u_cos = 0.5 * np.cos(phase) + 1e-4 * rng.standard_normal(phase.size)
    fringe.take_live_signals(u_sin, u_cos)  # what Live signals › Take sends
    metrics = table.fontMetrics()
    for key in ("u_sin", "u_cos"):
        column = keys.index(key)
        widest = max(metrics.horizontalAdvance(fringe.table_model.sheet.text(r, column))
                     for r in range(64))
        assert table.columnWidth(column) >= widest, key
