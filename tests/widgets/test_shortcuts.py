"""No key does two things (#31): each platform's standard bindings expanded (Qt's table in
qplatformtheme.cpp: what Ctrl+Y, Ctrl+Shift+Z… mean on Windows, macOS, KDE, GNOME and
plain X11), no action carries a sequence twice and no two actions of the window share
one. Before #31 Redo added Ctrl+Shift+Z, X11's own Redo, a second time: Qt then runs
neither ("Ambiguous shortcut overload")."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QAction, QKeySequence

from widgets import shortcuts

K = QKeySequence.StandardKey
# the bindings of the standard keys the window uses, per platform (Ctrl is ⌘ on macOS)
PLATFORMS = {
    "Windows": {K.Undo: ["Ctrl+Z", "Alt+Backspace"],
                K.Redo: ["Ctrl+Y", "Ctrl+Shift+Z", "Alt+Shift+Backspace"],
                K.New: ["Ctrl+N"], K.Open: ["Ctrl+O"], K.Save: ["Ctrl+S"], K.SaveAs: [],
                K.Print: ["Ctrl+P"], K.Quit: [], K.HelpContents: ["F1"],
                K.Copy: ["Ctrl+C", "Ctrl+Ins"], K.Paste: ["Ctrl+V", "Shift+Ins"],
                K.Delete: ["Del"]},
    "macOS": {K.Undo: ["Ctrl+Z"], K.Redo: ["Ctrl+Shift+Z"], K.New: ["Ctrl+N"],
              K.Open: ["Ctrl+O"], K.Save: ["Ctrl+S"], K.SaveAs: ["Ctrl+Shift+S"],
              K.Print: ["Ctrl+P"], K.Quit: ["Ctrl+Q"], K.HelpContents: ["Ctrl+?"],
              K.Copy: ["Ctrl+C"], K.Paste: ["Ctrl+V"], K.Delete: ["Del", "Meta+D", "Backspace"]},
    "KDE": {K.Undo: ["Ctrl+Z", "F14"], K.Redo: ["Ctrl+Shift+Z", "Ctrl+Y"], K.New: ["Ctrl+N"],
            K.Open: ["Ctrl+O"], K.Save: ["Ctrl+S"], K.SaveAs: ["Ctrl+Shift+S"],
            K.Print: ["Ctrl+P"], K.Quit: ["Ctrl+Q"], K.HelpContents: ["F1"],
            K.Copy: ["Ctrl+C", "Ctrl+Ins", "F16"], K.Paste: ["Ctrl+V", "Shift+Ins", "F18"],
            K.Delete: ["Del"]},
    "GNOME / X11": {K.Undo: ["Ctrl+Z", "F14"], K.Redo: ["Ctrl+Shift+Z"], K.New: ["Ctrl+N"],
                    K.Open: ["Ctrl+O"], K.Save: ["Ctrl+S"], K.SaveAs: ["Ctrl+Shift+S"],
                    K.Print: ["Ctrl+P"], K.Quit: ["Ctrl+Q"], K.HelpContents: ["F1"],
                    K.Copy: ["Ctrl+C", "Ctrl+Ins", "F16"], K.Paste: ["Ctrl+V", "Shift+Ins", "F18"],
                    K.Delete: ["Del"]},
}


def _clashes(actions: list[QAction]) -> list[str]:
    seen: dict[str, str] = {}
    found = []
    for action in actions:
        keys = [k.toString() for k in action.shortcuts()]
        name = action.text().replace("&", "") or action.objectName() or repr(action)
        if len(keys) != len(set(keys)):
            found.append(f"{name} carries {keys}")
        for key in set(keys):
            if key in seen:
                found.append(f"{key}: {seen[key]} and {name}")
            seen[key] = name
    return found


@pytest.mark.slow
@pytest.mark.parametrize("platform", PLATFORMS)
def test_no_key_sequence_is_bound_twice(platform, monkeypatch, qtbot, tmp_path):
    from PySide6.QtCore import QSettings

    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    table = PLATFORMS[platform]
    monkeypatch.setattr(shortcuts, "platform_bindings",
                        lambda key: [QKeySequence(s) for s in table[key]])
    window = MainWindow(settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat),
                        recovery=RecoveryStore(tmp_path / "recovery"))
    qtbot.addWidget(window)
    mine = [a for a in window.findChildren(QAction) if a.shortcuts()
            and not any(p.view.table is a.parent() for p in window.presenters)]
    redo = [k.toString() for k in window.menus.redo_action.shortcuts()]
    assert "Ctrl+Shift+Z" in redo and "Ctrl+Y" in redo  # the keys the quick guide names
    for presenter in window.presenters:  # the table's keys act where the table has focus
        table_actions = [a for a in presenter.view.table.actions() if a.shortcuts()]
        assert all(a.shortcutContext() == Qt.ShortcutContext.WidgetWithChildrenShortcut
                   for a in table_actions)
        assert not _clashes(mine + table_actions), _clashes(mine + table_actions)
    window.projects.recovery.discard()


def test_the_platforms_own_bindings_are_expanded_once():
    sequences = shortcuts.key_sequences(K.Redo, "Ctrl+Shift+Z", "Ctrl+Y")
    strings = [s.toString() for s in sequences]
    assert len(strings) == len(set(strings))
    assert {"Ctrl+Shift+Z", "Ctrl+Y"} <= set(strings)
    assert [s.toString() for s in QKeySequence.keyBindings(K.Redo)] == strings[:len(
        QKeySequence.keyBindings(K.Redo))]
