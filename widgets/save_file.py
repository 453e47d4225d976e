"""The window's "save as" file dialog: the name it returns is the name written.

A name typed without its extension ("run3") gets the extension of the chosen file type
("run3.anglebench.json"). The file dialog asked whether to replace "run3", not the longer
name, so when the longer name is a file already there it is asked again here; "No" opens
the dialog again (as the dialog's own question does).

The dialog is no larger than the screen it opens on, as the "open" one
(widgets/open_file.py): Qt's own dialog was 634×410 at 200 % on a 1280×720 laptop (640×360
logical), Save and Cancel below the screen's edge; a native one sizes itself."""

from __future__ import annotations

import re
from collections.abc import Callable
from pathlib import Path

from PySide6.QtWidgets import QDialog, QFileDialog, QMessageBox, QWidget

from widgets.i18n import tr
from widgets.screen_fit import fit_to_screen

__all__ = ["ask_save_file", "choose_save_file", "confirm_replace", "filter_suffixes",
           "save_file_dialog", "with_filter_suffix"]

_PATTERN = re.compile(r"\*(\.[\w.]+)")


def filter_suffixes(file_filter: str) -> list[str]:
    """The extensions named by a filter ("CSV (*.csv);;C header (*.h)": .csv, .h), in order."""
    return _PATTERN.findall(file_filter or "")


def with_filter_suffix(path: str, chosen_filter: str, filters: str = "") -> str:
    """``path`` as it is written: a name that does not end in an extension of the dialog's
    file types (``filters``, and the chosen one) gets the first extension of the chosen type
    (of the first type when the dialog did not say which was chosen); "All files (*)" adds
    none. "out" → "out.xlsx" for "Excel workbook (*.xlsx)"; "run3.v2" →
    "run3.v2.anglebench.json" for "AngleBench project (*.anglebench.json *.json)"."""
    if not path:
        return path
    known = filter_suffixes(filters) + filter_suffixes(chosen_filter)
    if any(path.lower().endswith(s.lower()) for s in known):
        return path
    chosen = filter_suffixes(chosen_filter) if chosen_filter else filter_suffixes(
        (filters or "").split(";;")[0])
    return path + chosen[0] if chosen else path


def confirm_replace(parent: QWidget | None, path: str, ask: Callable | None = None) -> bool:
    """Yes: replace the file ``path`` (asked as the file dialog asks, default No), through
    ``ask(title, text, buttons, default)`` (the main window's, which tests answer) or a
    message box of ``parent``'s."""
    ask = ask or (lambda *question: QMessageBox.question(parent, *question))
    answer = ask(
        tr("Replace the file?"),
        tr("{name} already exists in {folder}.\n\nReplace it?").format(
            name=Path(path).name, folder=str(Path(path).parent)),
        QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
        QMessageBox.StandardButton.No)
    return answer == QMessageBox.StandardButton.Yes


def save_file_dialog(parent: QWidget | None, title: str, suggested: str,
                     filters: str) -> QFileDialog:
    """The dialog :func:`choose_save_file` shows, as QFileDialog.getSaveFileName builds it:
    in the folder of ``suggested`` (a folder, a file's path or a bare name; the last folder
    used when it names none there), its name selected, the first of ``filters`` chosen, the
    dialog's own "replace?" question kept; sized to the screen."""
    dialog = QFileDialog(parent, title, suggested, filters)
    dialog.setFileMode(QFileDialog.FileMode.AnyFile)
    dialog.setSupportedSchemes(["file"])
    dialog.setAcceptMode(QFileDialog.AcceptMode.AcceptSave)
    wanted = dialog.sizeHint()
    fit_to_screen(dialog, wanted.width(), wanted.height())
    return dialog


def choose_save_file(parent: QWidget | None, title: str, suggested: str,
                     filters: str) -> tuple[str, str]:
    """The name given in the dialog and the file type chosen there, ("", "") when cancelled
    (what QFileDialog.getSaveFileName returned)."""
    dialog = save_file_dialog(parent, title, suggested, filters)
    try:
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return "", ""
        chosen = dialog.selectedFiles()
        return (chosen[0] if chosen else ""), dialog.selectedNameFilter()
    finally:
        dialog.deleteLater()  # not kept as one more child of ``parent`` for each save


def ask_save_file(parent: QWidget | None, title: str, suggested: str, filters: str,
                  ask: Callable | None = None) -> str:
    """The file dialog (:func:`choose_save_file`), then the name with its extension
    (:func:`with_filter_suffix`); "" when cancelled. When the extension added names a file
    already there, it is asked (:func:`confirm_replace`, through ``ask`` when given) whether
    to replace it: the dialog asked about the name typed, not this one. No: the dialog again,
    with the name."""
    while True:
        typed, chosen = choose_save_file(parent, title, suggested, filters)
        if not typed:
            return ""
        path = with_filter_suffix(typed, chosen, filters)
        if path == typed or not Path(path).exists() or confirm_replace(parent, path, ask):
            return path
        suggested = path
