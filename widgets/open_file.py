"""The window's "open" file dialog, no larger than the screen it opens on.

Where the platform has a file dialog of its own (Windows, macOS, a Linux desktop whose Qt
platform theme offers GTK's or the desktop portal's) that one is used, as the static
QFileDialog functions did: the system sizes it to its screen and the user knows it. Where it
has none (X11 or Wayland without such a theme, as on a bare laptop install) Qt shows its own
dialog, which made itself 634×410 at 200 % on a 1280×720 laptop (640×360 logical: OK and
Cancel below the screen's edge); that one is given the size it asks for, at most the
screen's (:func:`widgets.screen_fit.fit_to_screen`) — the size is ignored by a native one."""

from __future__ import annotations

from PySide6.QtWidgets import QDialog, QFileDialog, QWidget

from widgets.screen_fit import fit_to_screen

__all__ = ["ask_open_file", "open_file_dialog"]


def open_file_dialog(parent: QWidget | None, title: str, folder: str,
                     filters: str) -> QFileDialog:
    """The dialog :func:`ask_open_file` shows: an existing file to open, sized to the screen."""
    dialog = QFileDialog(parent, title, folder, filters)
    dialog.setFileMode(QFileDialog.FileMode.ExistingFile)
    dialog.setAcceptMode(QFileDialog.AcceptMode.AcceptOpen)
    wanted = dialog.sizeHint()
    fit_to_screen(dialog, wanted.width(), wanted.height())
    return dialog


def ask_open_file(parent: QWidget | None, title: str, folder: str, filters: str) -> str:
    """The file chosen to open, "" when cancelled (QFileDialog.getOpenFileName's first half)."""
    dialog = open_file_dialog(parent, title, folder, filters)
    try:
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return ""
        chosen = dialog.selectedFiles()
        return chosen[0] if chosen else ""
    finally:
        dialog.deleteLater()  # not kept as one more child of ``parent`` for each file opened
