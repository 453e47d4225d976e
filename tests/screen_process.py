"""What the screen probes share (tests/small_screen_probe.py, tests/dialog_fit_probe.py): the
test side runs a probe in a process of its own on an offscreen screen of a given size and
scale (:func:`run_on_screen`); the probe side opens the window on the bundled samples in a
scratch folder, in the language asked for (:func:`open_window`), and closes it without a
trace (:func:`close_window`)."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def run_on_screen(probe: str, tmp_path: Path, width: int, height: int, scale: str,
                  language: str | list[str]) -> dict:
    """Run the module ``probe`` (``python -m``) on a ``width``×``height`` offscreen screen at
    QT_SCALE_FACTOR ``scale`` with the window in ``language`` (a probe that takes several
    languages, one window after another in its one process, is given a list); its last line
    of output, JSON."""
    config = tmp_path / "screen.json"
    config.write_text(json.dumps({"screens": [{
        "name": "laptop", "x": 0, "y": 0, "width": width, "height": height,
        "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]}))
    env = {**os.environ, "QT_QPA_PLATFORM": f"offscreen:configfile={config}",
           "QT_SCALE_FACTOR": scale, "PYTHONPATH": str(ROOT), "HOME": str(tmp_path),
           "XDG_CONFIG_HOME": str(tmp_path / "config"), "XDG_DATA_HOME": str(tmp_path / "data")}
    languages = [language] if isinstance(language, str) else language
    run = subprocess.run([sys.executable, "-m", probe, *languages], env=env,
                         capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-3000:]
    return json.loads(run.stdout.strip().splitlines()[-1])


#: every screen the fit tests probe (tests/widgets/test_dialogs_fit.py, test_small_screens.py):
#: (width, height, QT_SCALE_FACTOR) → the languages asked of it
PROBED_SCREENS = {(1280, 720, "1"): ("en",), (2560, 1600, "2"): ("zh_CN",),
                  (1280, 720, "2"): ("en", "zh_CN")}


def screen_probed(tmp_path_factory, width: int, height: int, scale: str) -> dict:
    """What tests/dialog_fit_probe.py found on that screen (:data:`PROBED_SCREENS`), ``{language:
    {"dialogs": ..., "window and certificate dialog": ...}}``: one process a screen, a window
    in each language after another, probed once a run for every test and worker that reads it
    (tests.conftest.once_a_run; a probe process is ~3.5 s of CPU, ~1.5 s of it starting, and
    the window on the samples ~1 s)."""
    from tests.conftest import once_a_run

    languages = list(PROBED_SCREENS[width, height, scale])
    name = f"screen-probe-{width}x{height}-{scale}-{'-'.join(languages)}"
    return once_a_run(tmp_path_factory, name, lambda folder: run_on_screen(
        "tests.dialog_fit_probe", folder, width, height, scale, languages))


def open_window(prefix: str, language: str | None = None):
    """The main window on every bundled sample, shown, with its settings and recovery in a
    scratch folder of its own and in ``language`` (by default the probe's first argument, en
    without one)."""
    from PySide6.QtCore import QSettings

    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    scratch = Path(tempfile.mkdtemp(prefix=prefix))
    settings = QSettings(str(scratch / "settings.ini"), QSettings.Format.IniFormat)
    if language is None:
        language = sys.argv[1] if len(sys.argv) > 1 else "en"
    settings.setValue("ui/language", language)
    window = MainWindow(settings=settings, recovery=RecoveryStore(scratch / "recovery"))
    window.load_all_samples()
    window.show()
    return window


def close_window(window, found: dict | None) -> None:
    """Close ``window``, leaving no recovery behind, and print ``found`` as the probe's JSON
    (a probe of several windows prints once, after the last: ``found`` None before)."""
    window.projects.recovery.discard()
    window.close()
    if found is not None:
        sys.stdout.write(json.dumps(found) + "\n")
