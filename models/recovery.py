"""Crash recovery: the autosaved copy of unsaved work, offered on the next start."""

from __future__ import annotations

import contextlib
import time
from pathlib import Path

from models.project import Project, ProjectFileError, load_project, save_project

__all__ = ["RecoveryStore"]


class RecoveryStore:
    """One recovery file in ``folder``. The app writes it while work is unsaved,
    and removes it on a clean exit; if it is still there at start-up, the last
    session ended without saving (a crash, a power cut) and it is offered back.
    """

    FILE_NAME = "recovery.anglebench.json"

    def __init__(self, folder: str | Path) -> None:
        self.folder = Path(folder)
        self.path = self.folder / self.FILE_NAME

    def write(self, project: Project) -> None:
        self.folder.mkdir(parents=True, exist_ok=True)
        project.metadata = dict(project.metadata)
        project.metadata["autosaved_at"] = time.strftime("%Y-%m-%d %H:%M:%S")
        save_project(self.path, project)

    def exists(self) -> bool:
        return self.path.is_file()

    def load(self) -> Project:
        """Read the recovery file. A damaged one is kept aside (renamed), not deleted."""
        try:
            return load_project(self.path)
        except ProjectFileError:
            with contextlib.suppress(OSError):
                self.path.replace(self.path.with_suffix(".damaged.json"))
            raise

    def discard(self) -> None:
        with contextlib.suppress(FileNotFoundError):
            self.path.unlink()
