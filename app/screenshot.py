"""``anglebench --screenshot DIR``: each workbench with its sample, rendered offscreen, the
certificate dialog, and the Live signals window as first opened, with the demonstration
head's figures."""

from __future__ import annotations

import json
import os
import tempfile
import time
from pathlib import Path

from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication

from app.main_window import LANGUAGE_SETTING, MainWindow
from models.certificate.metadata import CertificateMetadata
from models.project.recovery import RecoveryStore
from widgets.certificate_dialog import CertificateDialog


def _example_metadata() -> CertificateMetadata:
    return CertificateMetadata.from_dict({
        "certificate_number": "AB-2026-0042", "lab_name": "精密角度计量实验室 Precision Angle Lab",
        "customer_name": "Changchun Optics Ltd.", "item_description": "Limited-rotation axis",
        "item_serial": "LRA-0815", "calibration_date": "2026-11-20", "operator": "Wang",
        "standards": [{"description": "Autocollimating theodolite", "certificate_no": "NIM-1187",
                       "uncertainty": 0.5, "basis": "U95"}]})


def offscreen_platform(size: tuple[int, int], folder: Path) -> str:
    """``QT_QPA_PLATFORM`` for the screenshots: Qt's offscreen platform with one screen of
    ``size`` logical px (the window's, device px × ``QT_SCALE_FACTOR``), described in a file
    written to ``folder``, so that a window fitted to its screen takes the size it takes on
    such a screen. Qt's own offscreen screen is 800×800 px: at 200 % the Live signals window
    was fitted to 392×368 px, widened to its least width, and laid out as no window on a
    screen of the window's size is (day review 68 F10). Plain ``offscreen`` where the file's
    name cannot be given (a ":" in it, which separates the platform's options)."""
    try:
        scale = float(os.environ.get("QT_SCALE_FACTOR") or 1.0)
    except ValueError:  # Qt ignores it too
        scale = 1.0
    if not (0.1 <= scale <= 10.0):
        scale = 1.0
    width, height = (max(1, round(v * scale)) for v in size)
    path = folder / "offscreen-screen.json"
    if ":" in str(path):
        return "offscreen"
    path.write_text(json.dumps({"screens": [{
        "name": "AngleBench", "x": 0, "y": 0, "width": width, "height": height,
        "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]}), encoding="utf-8")
    return f"offscreen:configfile={path}"


def write_screenshots(folder: str | Path, size: tuple[int, int] = (1400, 900),
                      language: str = "en") -> list[Path]:
    out_dir = Path(folder)
    out_dir.mkdir(parents=True, exist_ok=True)
    app = QApplication.instance() or QApplication(["anglebench"])
    with tempfile.TemporaryDirectory() as scratch:
        settings = QSettings(str(Path(scratch) / "settings.ini"), QSettings.Format.IniFormat)
        settings.setValue(LANGUAGE_SETTING, language)
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
        # at the size it opens at on this screen (it fits itself to it), not a fixed
        # 1100×760 that a 1280×720 screen cannot hold
        dialog = CertificateDialog(_example_metadata(), window)
        dialog.show()
        app.processEvents()
        path = out_dir / "certificate_dialog.png"
        dialog.grab().save(str(path))
        paths.append(path)
        dialog.close()
        paths += _live_signals(window, out_dir)
        window.projects.recovery.discard()
        window.close()
    return paths


def _live_signals(window, out_dir: Path) -> list[Path]:
    """The Live signals window opened from Instrument › Live signals… at the size it takes on
    this screen the first time, the demonstration head streaming until its figures are
    shown (at most 15 s), never resized: what a technician sees first (day review 67 F8:
    its x axis titles were cut on the first open only)."""
    from app.capture.signal_live import open_live_signals
    from models.workbench import JudgesSignals

    app = QApplication.instance()
    if app is None or not open_live_signals(window):
        return []
    panel = next(p.view.live_signals for p in window.presenters
                 if isinstance(p.kind, JudgesSignals))
    try:
        panel.start_demonstration()
        deadline = time.monotonic() + 15
        while panel.samples < 2000 and time.monotonic() < deadline:
            app.processEvents()
            time.sleep(0.02)
        for _ in range(10):  # the status line and the plots laid out after the figures
            app.processEvents()
            time.sleep(0.02)
        path = out_dir / "live_signals.png"
        panel.grab().save(str(path))
    finally:
        panel.disconnect_stream()
        panel.close()
    return [path]
