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


def polygon_bench(window, **settings):
    """The polygon tab shown with an empty sheet and ``settings`` (faces, plan_sets,
    readings_per_point …), nothing to undo; the capture panel closed afterwards (a fixture's
    body: ``yield from polygon_bench(window, faces=12)``)."""
    presenter = show_workbench(window, "polygon")
    presenter.table_model.replace_all([], "empty")
    presenter.set_settings({**presenter.settings, **settings})
    presenter.undo_stack.clear()
    yield presenter
    window.capture_panel.close()


def captured_rows(presenter, keys=("position", "encoder_deg", "ac_x_arcsec")) -> list[tuple]:
    """The cells ``keys`` of every row that holds an autocollimator x, as the table shows them."""
    sheet = presenter.table_model.sheet
    columns = [c.key for c in sheet.columns]
    return [tuple(sheet.text(r, columns.index(k)) for k in keys)
            for r in range(sheet.row_count) if sheet.text(r, columns.index("ac_x_arcsec"))]
