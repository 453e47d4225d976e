"""#41: the test plan is saved with the lab defaults, per workbench (positioning's plan
settings and the others' ``plan_…``), and a new project (File › New, or the window
opened anew) starts with them; the other settings start from their defaults."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QSettings

pytestmark = pytest.mark.slow  # two windows

PLAN = {"plan_runs": 3, "plan_targets": "0:45:5", "plan_directions": "up",
        "plan_order": "pilgrim"}


def _save_lab_defaults(window, key):
    meta = window.certificates.details(key)  # the dialog asks for the details first
    window.certificates.save_lab_defaults(meta.lab_defaults())


def test_the_test_plan_is_saved_with_the_lab_defaults(window, tmp_path):
    positioning = window.presenter("positioning")
    theodolite = window.presenter("theodolite")
    positioning.set_settings({**positioning.settings, **PLAN, "deviation_unit": "um"})
    theodolite.set_settings({**theodolite.settings, "plan_passes": 2,
                             "plan_thetas": "-10:5:5"})
    _save_lab_defaults(window, "positioning")
    _save_lab_defaults(window, "theodolite")
    assert window.certificates.test_plan("positioning") == PLAN
    assert window.certificates.test_plan("theodolite")["plan_passes"] == 2
    assert window.certificates.test_plan("polygon") == {}

    # File › New: the plans, not the other settings
    positioning.set_settings({**positioning.settings, "plan_runs": 0})
    window.projects.new_project()
    settings = positioning.settings
    assert {k: settings[k] for k in PLAN} == PLAN
    assert settings["deviation_unit"] == positioning.kind.settings_with_defaults({})[
        "deviation_unit"]
    plan = positioning.entry_plan()
    assert plan is not None and len(plan) == 3 * 5  # 5 targets × 3 runs, one direction
    assert plan.points[1].cells == {"target": "0", "run": "2", "direction": "+"}  # pilgrim
    assert theodolite.settings["plan_thetas"] == "-10:5:5"
    assert window.presenter("polygon").settings["plan_sets"] == 0  # none saved: default
    assert not window.projects.is_modified

    # a window opened anew (another day at the bench) starts with them too
    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    again = MainWindow(settings=QSettings(str(tmp_path / "settings.ini"),
                                          QSettings.Format.IniFormat),
                       recovery=RecoveryStore(tmp_path / "recovery2"))
    try:
        got = again.presenter("positioning").settings
        assert {k: got[k] for k in PLAN} == PLAN
        assert again.presenter("positioning").entry_plan() is not None
        assert not again.projects.is_modified
    finally:
        again.projects.close()
        again.deleteLater()
