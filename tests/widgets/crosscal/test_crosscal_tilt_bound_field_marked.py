"""A zero tilt bound in the cross-calibration window where no mounting has vertical
readings (a polygon seated with no tilt at all, which the readings cannot show): no result,
the bound's field marked, the readings and settings as typed; a bound stated unmarks it and
gives the result. The readings are the command line test's bench (its own 3-D simulation,
nothing from models/)."""

from __future__ import annotations

import pytest

from models.readings.tabular_import import map_columns, read_table
from tests.app.test_crosscal_tilt_bound import MOUNTINGS, _bench, _file

pytestmark = pytest.mark.slow  # a window


def test_a_zero_bound_marks_its_field_and_keeps_the_readings(window, qtbot, tmp_path):
    presenter = window.presenter("crosscal")
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    path = _file(tmp_path, _bench(1, 0.0).rows(MOUNTINGS, vertical=True))
    presenter.table_model.replace_all(map_columns(read_table(path), presenter.kind.columns))
    form = presenter.view.settings
    form.field("ac_scale_pct").setValue(0.1)  # another setting typed: kept
    field = form.field("tilt_bound_arcsec")
    field.setValue(0.0)
    presenter.refresh()
    assert presenter.result is None
    assert "tilt bound of 0" in presenter.problem and "0, 1, 5" in presenter.problem
    assert form.marked() == "tilt_bound_arcsec" and field.styleSheet()
    assert not any(form.field(k).styleSheet() for k in form.values() if k != "tilt_bound_arcsec")
    # nothing lost: the readings and the settings as typed
    assert presenter.sheet.row_count >= 3 * 13
    assert presenter.settings["tilt_bound_arcsec"] == 0.0 and field.value() == 0.0
    assert presenter.settings["ac_scale_pct"] == pytest.approx(0.1)
    field.setValue(30.0)
    presenter.refresh()
    assert presenter.result is not None, presenter.problem
    assert presenter.result.tilt_bound_arcsec == 30.0
    assert form.marked() == "" and not field.styleSheet()
