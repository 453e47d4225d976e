"""Opens the window on the screen Qt was started with, shows the capture panel docked at
each side it can go (right, left, bottom) on every workbench, and prints, as JSON, the
window's frame, the screen's free area and every control of the panel that is not wholly
in sight, and at each step the set-up fields' room (tests/settings_fields_probe.py's
records): ``{"panel": [...], "fields": [...]}``. tests/app/capture/test_capture_panel_fits.py
and tests/widgets/test_settings_fields_fit.py read one run of it on a 1280×720 screen
(:func:`docked_probed`)."""

from __future__ import annotations

import json
import tempfile
from pathlib import Path

from PySide6.QtCore import QPoint, QRect, QSettings, Qt
from PySide6.QtWidgets import (
    QAbstractButton,
    QAbstractSpinBox,
    QApplication,
    QComboBox,
)

AREAS = {"right": Qt.DockWidgetArea.RightDockWidgetArea,
         "left": Qt.DockWidgetArea.LeftDockWidgetArea,
         "bottom": Qt.DockWidgetArea.BottomDockWidgetArea}


def run_at_1280x720(module: str, tmp_path) -> list[dict]:
    """Run the probe ``module`` (tests.…) in a process of its own on an offscreen screen of
    1280×720 with a scratch home; its JSON printed last."""
    import os
    import subprocess
    import sys

    root = Path(__file__).resolve().parents[1]
    config = tmp_path / "screen.json"
    config.write_text(json.dumps({"screens": [{
        "name": "laptop", "x": 0, "y": 0, "width": 1280, "height": 720,
        "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]}))
    env = {**os.environ, "QT_QPA_PLATFORM": f"offscreen:configfile={config}",
           "PYTHONPATH": str(root), "HOME": str(tmp_path),
           "XDG_CONFIG_HOME": str(tmp_path / "config"), "XDG_DATA_HOME": str(tmp_path / "data")}
    run = subprocess.run([sys.executable, "-m", module], env=env,
                         capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-3000:]
    return json.loads(run.stdout.strip().splitlines()[-1])


def settle(app) -> None:
    for _ in range(6):
        app.processEvents()


def each_docked_tab(prefix: str):
    """The window on a scratch profile with every sample loaded, the capture panel docked at
    each side it can go: yields (app, window, panel, side, presenter) with each workbench's
    tab shown in turn (the probes of the panel and of the set-up fields share it)."""
    app = QApplication.instance() or QApplication(["anglebench"])
    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    scratch = tempfile.mkdtemp(prefix=prefix)
    settings = QSettings(str(Path(scratch) / "settings.ini"), QSettings.Format.IniFormat)
    window = MainWindow(settings=settings, recovery=RecoveryStore(Path(scratch) / "recovery"))
    window.load_all_samples()
    window.show()
    settle(app)
    panel = window.capture_panel
    panel.show()
    for area_name, area in AREAS.items():
        window.addDockWidget(area, panel)
        panel.show()
        for index, presenter in enumerate(window.presenters):
            window.tabs.setCurrentIndex(index)
            settle(app)
            yield app, window, panel, area_name, presenter


def docked_probed(tmp_path_factory) -> dict:
    """This probe's records on a 1280×720 screen, ``{"panel": [...], "fields": [...]}`` (the
    second tests/settings_fields_probe.py's, made at the same steps), probed once a run for
    the capture panel's test and the set-up fields' test (tests.conftest.once_a_run: one
    process, one window on the samples and its 15 docked tabs, where each test made its own)."""
    from tests.conftest import once_a_run

    return once_a_run(tmp_path_factory, "docked-capture-panel-1280x720",
                      lambda folder: run_at_1280x720("tests.capture_panel_probe", folder))


def main() -> None:
    from tests.settings_fields_probe import fields_at

    found, fields = [], []
    for app, window, panel, area_name, presenter in each_docked_tab("anglebench-panel-"):
        frame = window.frameGeometry()
        screen = (window.screen() or app.primaryScreen()).availableGeometry()
        inside = window.rect()
        viewport = panel.scroll.viewport()
        seen = QRect(viewport.mapTo(window, QPoint(0, 0)), viewport.size())
        hidden = []
        for control in panel.findChildren(QAbstractButton) + panel.findChildren(
                QComboBox) + panel.findChildren(QAbstractSpinBox):
            if not control.isVisibleTo(panel) or control.parent() is panel:
                continue  # the column list shows for a readout only; the dock's own
            rect = QRect(control.mapTo(window, QPoint(0, 0)), control.size())
            if not (inside.contains(rect) and seen.contains(rect)):
                hidden.append(f"{control.objectName() or type(control).__name__} "
                              f"'{getattr(control, 'text', lambda: '')()}' at "
                              f"{rect.x()},{rect.y()} {rect.width()}×{rect.height()}")
        table = presenter.view.table
        plot = presenter.view.plot_tabs.currentWidget()
        found.append({"area": area_name, "workbench": presenter.kind.key,
                      "frame": [frame.x(), frame.y(), frame.width(), frame.height()],
                      "available": [screen.x(), screen.y(), screen.width(), screen.height()],
                      "hidden": hidden,
                      "dock": window.dockWidgetArea(panel).name,
                      "table": [table.width(), table.height()],
                      "panel": [panel.width(), panel.height()],
                      "plot": [plot.width(), plot.height()] if plot is not None else None})
        # the set-up fields' room at the same step (they only read the window, as this does)
        fields += fields_at(window, area_name, presenter)
    print(json.dumps({"panel": found, "fields": fields}))  # noqa: T201 - the probe's output


if __name__ == "__main__":
    main()
