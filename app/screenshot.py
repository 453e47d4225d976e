"""``anglebench --screenshot DIR``: each workbench with its sample, rendered offscreen."""

from __future__ import annotations

import tempfile
from pathlib import Path

from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication

from app.main_window import MainWindow
from models.recovery import RecoveryStore


def write_screenshots(folder: str | Path, size: tuple[int, int] = (1400, 900)) -> list[Path]:
    out_dir = Path(folder)
    out_dir.mkdir(parents=True, exist_ok=True)
    app = QApplication.instance() or QApplication(["anglebench"])
    with tempfile.TemporaryDirectory() as scratch:
        settings = QSettings(str(Path(scratch) / "settings.ini"), QSettings.Format.IniFormat)
        window = MainWindow(settings=settings, recovery=RecoveryStore(scratch))
        window.load_all_samples()
        window.resize(*size)
        window.show()
        paths = []
        for index, presenter in enumerate(window.presenters):
            window.tabs.setCurrentIndex(index)
            presenter.refresh()
            app.processEvents()  # one-off render, not an event loop
            path = out_dir / f"{presenter.kind.key}.png"
            window.grab().save(str(path))
            paths.append(path)
        window.recovery.discard()
        window.close()
    return paths
