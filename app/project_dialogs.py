"""The window's side of the project presenter (app/project_presenter.py): its file dialogs
and questions, the title, the recent files menu, the status bar.

Questions and messages go through the window's ``ask`` and ``tell`` so tests can answer
them."""

from __future__ import annotations

from typing import Any

from PySide6.QtWidgets import QLabel, QMessageBox

from widgets.i18n import tr
from widgets.open_file import ask_open_file
from widgets.save_file import ask_save_file

__all__ = ["ProjectDialogs"]


class ProjectDialogs:
    """:class:`app.project_presenter.ProjectView` for ``window`` (the main window; its
    ``projects`` is the presenter, its ``menus.recent_menu`` lists the recent files)."""

    def __init__(self, window: Any) -> None:
        self.window = window

    def ask_open_path(self, folder: str) -> str:
        return ask_open_file(self.window, tr("Open project"), folder,
                             tr("AngleBench project (*.anglebench.json *.json)"))

    def ask_save_path(self, folder: str) -> str:
        """The name the project is written to: "run3" is run3.anglebench.json, asked about
        when that file is there (the file dialog asked about "run3")."""
        return ask_save_file(self.window, tr("Save project"), folder,
                             tr("AngleBench project (*.anglebench.json *.json)"), self.window.ask)

    def ask_save_changes(self, question: str = "") -> bool | None:
        answer = self.window.ask(
            tr("Unsaved changes"), question or tr("Save the changes to the project first?"),
            QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Discard
            | QMessageBox.StandardButton.Cancel, QMessageBox.StandardButton.Save)
        if answer == QMessageBox.StandardButton.Save:
            return True
        return False if answer == QMessageBox.StandardButton.Discard else None

    def ask_recover(self, name: str, when: str) -> bool:
        answer = self.window.ask(
            tr("Recover unsaved work"),
            tr("AngleBench did not close normally. Restore the unsaved readings of {name}, "
               "autosaved {when}?").format(name=name, when=when),
            QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
            QMessageBox.StandardButton.Yes)
        return answer == QMessageBox.StandardButton.Yes

    def ask_overwrite_changed(self, name: str) -> bool | None:
        answer = self.window.ask(
            tr("Project changed on disk"),
            tr("{name} was changed on disk since this window opened or saved it (by another "
               "window, a colleague or a program): saving replaces those changes.\n\n"
               "Yes: replace it with this window's project. No: save this window's project "
               "under another name. Cancel: do not save.").format(name=name),
            QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No
            | QMessageBox.StandardButton.Cancel, QMessageBox.StandardButton.No)
        if answer == QMessageBox.StandardButton.Yes:
            return True
        return False if answer == QMessageBox.StandardButton.No else None

    def tell(self, title: str, text: str) -> None:
        self.window.tell(title, text)

    def show_status(self, text: str, milliseconds: int) -> None:
        self.window.statusBar().showMessage(text, milliseconds)

    def show_autosave_problem(self, text: str) -> None:
        """A red warning in the status bar, beside any message, until ``text`` is empty."""
        label = getattr(self.window, "autosave_warning", None)
        if label is None:
            label = QLabel()
            label.setStyleSheet("color: #b00020; font-weight: bold;")
            label.setWordWrap(False)
            self.window.statusBar().addPermanentWidget(label)
            self.window.autosave_warning = label
        label.setText(text)
        label.setToolTip(text)
        label.setVisible(bool(text))

    def show_title(self, title: str) -> None:
        self.window.setWindowTitle(title)

    def show_recent(self, paths: list[str]) -> None:
        menu = self.window.menus.recent_menu
        menu.clear()
        for path in paths:
            action = menu.addAction(path)
            action.triggered.connect(lambda _checked=False, p=path: self.window.projects.open_project(p))
        menu.setEnabled(bool(paths))

    def show_workbench(self, key: str) -> None:
        self.window.tabs.setCurrentIndex(next(i for i, p in enumerate(self.window.presenters)
                                              if p.kind.key == key))
