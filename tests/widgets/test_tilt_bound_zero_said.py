"""The tilt bound's field says what 0 is: since 0.8.22 a bound of 0 (an axis, or a polygon on
the shaft, with no tilt at all, which no set-up achieves) is refused where the readings do not
identify the tilt; the field at 0 read "none" and its tooltip said nothing of 0, as if 0 were
"no bound" and taken. Now the field at 0 and its tooltip say it is no tilt and refused there
(theodolite, polygon, cross-calibration), and the command line's table of settings too; the
cross-calibration's readings without vertical readings show the refusal they announce.

The readings are tests/crosscal_simulator.py's bench (numpy only): nothing from models/."""

from __future__ import annotations

import contextlib
import io

import pytest

from app.main import main
from models.registry import KINDS
from tests.app.test_crosscal_tilt_bound import MOUNTINGS, _bench, _file
from widgets.settings_form import SettingsForm


def _tilt_bound(key: str):
    return next(p for p in KINDS[key].parameters if p.key == "tilt_bound_arcsec")


@pytest.mark.parametrize("key", ["theodolite", "polygon", "crosscal"])
def test_the_field_at_zero_says_no_tilt_refused_where_not_identified(qtbot, key):
    form = SettingsForm()
    qtbot.addWidget(form)
    field = form.add_parameter(_tilt_bound(key))
    field.setValue(0.0)
    shown = field.text()
    assert "no tilt" in shown and "refused" in shown, shown
    said = " ".join(field.toolTip().split())
    assert "; 0: " in said, said
    zero = said.split("; 0: ", 1)[1]
    assert "no tilt at all" in zero and "refused where" in zero, zero
    field.setValue(60.0)  # a bound stated: the figure, no words
    assert "refused" not in field.text()


def test_the_command_lines_table_says_so():
    from app.docs_tables import settings_tables

    rows = [line for line in settings_tables().splitlines() if "`--tilt-bound-arcsec`" in line]
    assert len(rows) == 3
    for row in rows:
        assert "0: no tilt (refused where not identified)" in row, row
        assert "0: none |" not in row


def test_what_the_crosscal_field_announces_at_zero_is_what_the_readings_get(tmp_path):
    path = _file(tmp_path, _bench(1, 0.0).rows(MOUNTINGS, vertical=True))
    told = io.StringIO()
    with contextlib.redirect_stdout(told), contextlib.redirect_stderr(told):
        code = main(["analyze", "crosscal", str(path), "--tilt-bound-arcsec", "0",
                     "--language", "en"])
    assert code != 0 and "tilt bound of 0" in told.getvalue(), told.getvalue()
