"""Audit 73 finding 1 in the window: a theodolite run whose elevations do not identify the
axis tilt, with the tilt bound set to 0 (a set-up with no tilt at all, which the readings
cannot show), gets no result; the bound's field is marked and the readings and settings
stay as typed; a bound stated unmarks it and gives the result. The readings are the command
line test's rig (its own 3-D simulation, nothing from models/)."""

from __future__ import annotations

import pytest

from models.readings.tabular_import import map_columns, read_table
from tests.app.test_tilt_bound_zero_refused import SIGMA, _theodolite_rows

pytestmark = pytest.mark.slow  # a window


def test_a_zero_bound_marks_its_field_and_keeps_the_readings(window, qtbot, tmp_path):
    presenter = window.presenter("theodolite")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    path = tmp_path / "run.csv"
    path.write_text("theta_deg,azimuth_deg,elevation_deg\n" + "".join(_theodolite_rows(0.1)),
                    encoding="utf-8")
    presenter.table_model.replace_all(map_columns(read_table(path), presenter.kind.columns))
    form = presenter.view.settings
    form.field("accuracy_arcsec").setValue(SIGMA)
    field = form.field("tilt_bound_arcsec")
    field.setValue(0.0)
    presenter.refresh()
    assert presenter.result is None
    assert "tilt bound of 0" in presenter.problem
    assert form.marked() == "tilt_bound_arcsec" and field.styleSheet()
    assert not any(form.field(k).styleSheet() for k in form.values() if k != "tilt_bound_arcsec")
    # nothing lost: the readings and the settings as typed
    assert presenter.sheet.row_count >= 9
    assert presenter.settings["tilt_bound_arcsec"] == 0.0 and field.value() == 0.0
    assert presenter.settings["accuracy_arcsec"] == pytest.approx(SIGMA)
    field.setValue(120.0)
    presenter.refresh()
    assert presenter.result is not None, presenter.problem
    assert form.marked() == "" and not field.styleSheet()
