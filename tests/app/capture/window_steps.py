"""Steps the capture tests take in the main window, written once."""

from __future__ import annotations


def show_workbench(window, key):
    """Bring workbench ``key``'s tab to the front, as a click on its tab does; its presenter."""
    window.tabs.setCurrentIndex(window.presenters.index(window.presenter(key)))
    return window.presenter(key)


def planned_positioning(window, targets="0:15:3"):
    """The positioning tab shown with an empty sheet and a plan of one run up ``targets``
    (degrees, deviations in arcseconds): a take fills the next planned row."""
    bench = show_workbench(window, "positioning")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "plan_runs": 1, "plan_targets": targets,
                        "plan_directions": "up", "target_unit": "deg",
                        "deviation_unit": "arcsec"})
    return bench
