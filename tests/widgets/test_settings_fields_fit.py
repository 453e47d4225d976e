"""#41 (technician's review): every set-up field's text in sight at 1280×720 with the capture
panel docked. One long caption set the form's label column and left every field ~110 px: the
polygon's faces field read "rom the readings", its closure limits "0.125, 0.25, 0.5, 1, 2.5"."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # a window in a process of its own, on a screen of 1280×720

ROOT = Path(__file__).resolve().parents[2]


def test_every_settings_field_shows_its_whole_text_at_1280x720_panel_docked(tmp_path):
    config = tmp_path / "screen.json"
    config.write_text(json.dumps({"screens": [{
        "name": "laptop", "x": 0, "y": 0, "width": 1280, "height": 720,
        "logicalDpi": 96, "logicalBaseDpi": 96, "dpr": 1}]}))
    env = {**os.environ, "QT_QPA_PLATFORM": f"offscreen:configfile={config}",
           "PYTHONPATH": str(ROOT), "HOME": str(tmp_path),
           "XDG_CONFIG_HOME": str(tmp_path / "config"), "XDG_DATA_HOME": str(tmp_path / "data")}
    run = subprocess.run([sys.executable, "-m", "tests.settings_fields_probe"], env=env,
                         capture_output=True, text=True, timeout=600, cwd=tmp_path)
    assert run.returncode == 0, run.stderr[-3000:]
    found = json.loads(run.stdout.strip().splitlines()[-1])
    assert {f["area"] for f in found} == {"right", "left", "bottom"}
    assert {f["workbench"] for f in found} == {"theodolite", "polygon", "fringe",
                                               "positioning", "crosscal"}
    assert any(f["key"] == "closure_limits_arcsec" and f["text"] for f in found)
    clipped = [f"{f['workbench']} ({f['area']}): {f['key']} '{f['text']}' needs {f['needs']} px,"
               f" has {f['has']} px" for f in found if f["needs"] > f["has"]]
    assert not clipped, "; ".join(clipped)
    assert all(f["window"] <= 1280 for f in found)
