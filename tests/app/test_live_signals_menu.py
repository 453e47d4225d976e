"""Instrument › Live signals… opens the fringe workbench's live window (besides its tab),
and the presets edited there are stored with the window's lab defaults (the certificate
presenter's, the certificate's own lab details kept)."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QDialogButtonBox

from models.fringe.signal_tolerance import LAB_DEFAULTS_KEY


@pytest.mark.slow
def test_the_instrument_menu_opens_the_live_window_and_presets_go_with_the_lab_defaults(
        window, qtbot):
    window.certificates.save_lab_defaults_entry("lab_name", "Our lab")
    window.tabs.setCurrentIndex(0)
    assert window.menus.live_signals_action.isEnabled()
    window.menus.live_signals_action.trigger()
    fringe = window.presenters[window.tabs.currentIndex()]
    assert fringe.kind.key == "fringe"
    panel = fringe.view.live_signals
    assert panel.isVisible()
    dialog = panel.edit_presets()
    qtbot.mouseClick(dialog.add_button, Qt.MouseButton.LeftButton)
    dialog.name.selectAll()
    qtbot.keyClicks(dialog.name, "Bench 3 heads")
    for column, text in ((1, "Vpp"), (2, "0.8"), (3, "1.2")):
        dialog.table.item(0, column).setData(Qt.ItemDataRole.EditRole, text)
    qtbot.mouseClick(dialog.buttons.button(QDialogButtonBox.StandardButton.Save),
                     Qt.MouseButton.LeftButton)
    stored = window.certificates.lab_defaults()
    assert stored["lab_name"] == "Our lab"
    assert [p["name"] for p in stored[LAB_DEFAULTS_KEY]] == ["Bench 3 heads"]
    assert panel.current_preset.name == "Bench 3 heads"
    panel.close()
