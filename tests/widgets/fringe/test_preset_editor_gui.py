"""The signal tolerance presets edited as a technician would, from the live window's "Edit
presets…": typed into the table, saved with the lab defaults, there again when reopened;
a bad cell marked and Save refused without losing anything; Cancel discards; built-in
presets read-only."""

from __future__ import annotations

import json

import pytest
from PySide6.QtCore import Qt
from PySide6.QtWidgets import QAbstractItemView, QDialogButtonBox

from models.fringe.signal_tolerance import BUILTIN_PRESETS, LAB_DEFAULTS_KEY, load_presets
from widgets.fringe.presenter import FringePresenter


class LabDefaults:
    """The lab defaults as the certificate presenter keeps them: one JSON text."""

    def __init__(self, data: dict | None = None) -> None:
        self.text = json.dumps(data or {"lab_name": "Our lab"})
        self.saves = 0

    def get(self) -> dict:
        return json.loads(self.text)

    def save_entry(self, key, value) -> None:
        self.text = json.dumps({**self.get(), key: value})
        self.saves += 1


@pytest.fixture
def panel(qtbot):
    presenter = FringePresenter()
    qtbot.addWidget(presenter.view)
    panel = presenter.view.live_signals
    yield panel
    panel.disconnect_stream()


def attached(panel, lab: LabDefaults):
    panel.attach(lambda *_a: None, lab_defaults=lab.get, save_lab_defaults_entry=lab.save_entry)
    return panel


def type_cell(qtbot, dialog, row: int, column: int, text: str) -> None:
    """Select the cell, type over it as a user does, and press Enter."""
    table = dialog.table
    table.setCurrentCell(row, column)
    index = table.model().index(row, column)
    table.edit(index)  # as a double click or F2 does
    editor = table.indexWidget(index)
    assert editor is not None
    editor.selectAll()
    qtbot.keyClick(editor, Qt.Key.Key_Delete)
    qtbot.keyClicks(editor, text)
    qtbot.keyClick(editor, Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.indexWidget(index) is None, timeout=2000)  # Qt commits queued


def save(qtbot, dialog) -> None:
    qtbot.mouseClick(dialog.buttons.button(QDialogButtonBox.StandardButton.Save),
                     Qt.MouseButton.LeftButton)


def test_a_preset_typed_in_is_saved_with_the_lab_defaults_and_kept(panel, qtbot):
    lab = LabDefaults()
    attached(panel, lab)
    assert panel.edit_presets_button.isEnabled()
    qtbot.mouseClick(panel.edit_presets_button, Qt.MouseButton.LeftButton)
    dialog = panel.preset_editor
    assert dialog is not None and dialog.isVisible()
    qtbot.mouseClick(dialog.add_button, Qt.MouseButton.LeftButton)
    dialog.name.selectAll()
    qtbot.keyClicks(dialog.name, "Our ERA heads")
    dialog.source.setFocus()
    qtbot.keyClicks(dialog.source, "Our mounting instruction MI-7, rev. 3")
    type_cell(qtbot, dialog, 0, 1, "Vpp")
    type_cell(qtbot, dialog, 0, 2, "0.9")
    type_cell(qtbot, dialog, 0, 3, "1.1")
    type_cell(qtbot, dialog, 0, 4, "0.8")
    type_cell(qtbot, dialog, 0, 5, "1.2")
    qtbot.mouseClick(dialog.add_band_button, Qt.MouseButton.LeftButton)
    assert dialog.table.item(1, 0).data(Qt.ItemDataRole.EditRole) == "amplitude_b"
    type_cell(qtbot, dialog, 1, 1, "Vpp")
    type_cell(qtbot, dialog, 1, 2, "0.85")
    type_cell(qtbot, dialog, 1, 3, "1.15")
    assert dialog.marked() == {}
    save(qtbot, dialog)
    assert not dialog.isVisible() and lab.saves == 1
    # stored beside the other lab defaults, which are kept
    stored = lab.get()
    assert stored["lab_name"] == "Our lab"
    [own] = stored[LAB_DEFAULTS_KEY]
    assert own["name"] == "Our ERA heads" and own["interface"] == "1Vpp"
    assert own["source"] == "Our mounting instruction MI-7, rev. 3"
    assert own["bands"] == [
        {"quantity": "amplitude_a", "unit": "Vpp", "inside": [0.9, 1.1], "outer": [0.8, 1.2]},
        {"quantity": "amplitude_b", "unit": "Vpp", "inside": [0.85, 1.15], "outer": None}]
    # the window uses it now, and the bar shows its bands
    assert panel.current_preset.key == own["key"]
    assert panel.bars["amplitude_a"].band.outer == (0.8, 1.2)
    assert not panel.bars["phase_deviation"].isVisible()
    # reopened: the values are there as typed
    dialog = panel.edit_presets()
    row = next(i for i, e in enumerate(dialog.entries) if e["key"] == own["key"])
    dialog.list.setCurrentRow(row)
    assert dialog.name.text() == "Our ERA heads"
    assert [dialog.table.item(0, c).text() for c in range(1, 6)] == [
        "Vpp", "0.9", "1.1", "0.8", "1.2"]
    assert dialog.table.item(1, 4).text() == ""
    dialog.reject()


def test_a_bad_cell_is_marked_and_save_refused_without_losing_the_others(panel, qtbot):
    other = {"key": "lab_old", "name": "Kept", "interface": "11uApp",
             "bands": [{"quantity": "amplitude_a", "unit": "µApp", "inside": [8, 15]}]}
    lab = LabDefaults({LAB_DEFAULTS_KEY: [other]})
    dialog = attached(panel, lab).edit_presets()
    qtbot.mouseClick(dialog.add_button, Qt.MouseButton.LeftButton)
    type_cell(qtbot, dialog, 0, 2, "1.2")
    type_cell(qtbot, dialog, 0, 3, "0.6")  # low above high
    assert list(dialog.marked()) == [(0, 2)]
    assert "above its high" in dialog.marked()[(0, 2)]
    assert dialog.table.item(0, 2).background().color().name() == "#ffcdd2"
    type_cell(qtbot, dialog, 0, 2, "0,6")  # a decimal comma reads
    type_cell(qtbot, dialog, 0, 4, "0.7")  # outer low inside the inside band
    type_cell(qtbot, dialog, 0, 5, "1.3")
    assert list(dialog.marked()) == [(0, 4)]
    assert "contain the inside band" in dialog.marked()[(0, 4)]
    type_cell(qtbot, dialog, 0, 4, "abc")
    assert "'abc' is not a number" in dialog.marked()[(0, 4)]
    type_cell(qtbot, dialog, 0, 4, "")  # outer half given
    assert "both its low and its high" in dialog.marked()[(0, 4)]
    save(qtbot, dialog)  # refused: still open, nothing stored, the message says why
    assert dialog.isVisible() and lab.saves == 0
    assert "both its low and its high" in dialog.message.text()
    # another preset selected, then Save: the bad one is shown again with its cell marked
    dialog.list.setCurrentRow(0)
    save(qtbot, dialog)
    assert dialog.isVisible() and dialog.name.text() == "New preset"
    assert (0, 4) in dialog.marked()
    type_cell(qtbot, dialog, 0, 4, "0.5")
    save(qtbot, dialog)
    assert not dialog.isVisible()
    keys = [p["key"] for p in lab.get()[LAB_DEFAULTS_KEY]]
    assert "lab_old" in keys and len(keys) == 2


def test_cancel_discards_and_built_ins_are_read_only_copy_to_edit(panel, qtbot):
    lab = LabDefaults()
    dialog = attached(panel, lab).edit_presets()
    dialog.list.setCurrentRow(0)
    assert dialog.entries[0]["builtin"] and dialog.readonly_note.isVisible()
    assert dialog.table.editTriggers() == QAbstractItemView.EditTrigger.NoEditTriggers
    assert dialog.name.isReadOnly() and not dialog.delete_button.isEnabled()
    qtbot.mouseClick(dialog.copy_button, Qt.MouseButton.LeftButton)
    assert not dialog.readonly_note.isVisible() and not dialog.name.isReadOnly()
    assert dialog.name.text().endswith("(copy)")
    type_cell(qtbot, dialog, 0, 3, "1.0")
    qtbot.mouseClick(dialog.buttons.button(QDialogButtonBox.StandardButton.Cancel),
                     Qt.MouseButton.LeftButton)
    assert not dialog.isVisible() and lab.saves == 0
    assert [p.key for p in panel.presets] == [p.key for p in BUILTIN_PRESETS]
    # a copy saved: the built-in is unchanged, the copy has the edit
    dialog = panel.edit_presets()
    dialog.list.setCurrentRow(0)
    qtbot.mouseClick(dialog.copy_button, Qt.MouseButton.LeftButton)
    type_cell(qtbot, dialog, 0, 3, "1.0")
    dialog.name.selectAll()
    qtbot.keyClicks(dialog.name, "Tight 1 Vpp")
    save(qtbot, dialog)
    presets, problems = load_presets(lab.get())
    assert not problems and presets[0] == BUILTIN_PRESETS[0]
    copy = next(p for p in presets if p.name == "Tight 1 Vpp")
    assert copy.band("amplitude_a").inside == (0.6, 1.0)
    assert copy.band("offset_a").inside == pytest.approx(BUILTIN_PRESETS[0].band("offset_a")
                                                         .inside, rel=1e-9)
    assert copy.source == BUILTIN_PRESETS[0].source
    # deleted again
    dialog = panel.edit_presets()
    dialog.list.setCurrentRow(len(dialog.entries) - 1)
    qtbot.mouseClick(dialog.delete_button, Qt.MouseButton.LeftButton)
    save(qtbot, dialog)
    assert lab.get()[LAB_DEFAULTS_KEY] == []
    assert [p.key for p in panel.presets] == [p.key for p in BUILTIN_PRESETS]


def test_a_stored_preset_that_does_not_read_is_kept_when_others_are_saved(panel, qtbot):
    broken = {"key": "lab_broken", "interface": "1Vpp", "bands": "none"}
    lab = LabDefaults({LAB_DEFAULTS_KEY: [broken]})
    dialog = attached(panel, lab).edit_presets()
    qtbot.mouseClick(dialog.add_button, Qt.MouseButton.LeftButton)
    type_cell(qtbot, dialog, 0, 2, "0.5")
    type_cell(qtbot, dialog, 0, 3, "1.5")
    save(qtbot, dialog)
    stored = lab.get()[LAB_DEFAULTS_KEY]
    assert broken in stored and len(stored) == 2
