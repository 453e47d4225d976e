"""#41: a take follows the entry plan. With a positioning test plan (3 targets × 2 runs,
bidirectional) every take goes to the plan's next point, fills target, run and direction
beside the reading, never writes over a filled row (wherever the cursor sits), and the log
the takes make is one the analysis accepts, with the deviations the axis really had.
The readout is the protocol simulator on TCP; the axis is simulated here (its actual angle
at each commanded target: a pitch error and a backlash)."""

from __future__ import annotations

import math

import pytest

from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and an instrument: more than 0.4 s

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}
PLAN = {"plan_runs": 2, "plan_targets": "0:30:3", "plan_directions": "both",
        "plan_order": "linear", "target_unit": "deg", "deviation_unit": "arcsec"}


def _axis_error_arcsec(target_deg: float, direction: str, run: int) -> float:
    """The axis' positioning error at a commanded target: a pitch error, a backlash of
    ±4″ and a run-to-run shift of 0.5″ (what the reference readout sees)."""
    return 25.0 * math.sin(math.radians(3.0 * target_deg)) \
        + (4.0 if direction == "+" else -4.0) + 0.5 * (run - 1)


def test_takes_follow_the_positioning_plan(window, qtbot):
    presenter = _show(window, "positioning")
    model = presenter.table_model
    keys = [c.key for c in model.sheet.columns]
    model.replace_all([], "empty")
    presenter.set_settings(PLAN)
    panel = window.capture_panel
    truth = {}
    with ReadoutSimulator("tcp", positions=[(0.0,)]) as readout:
        panel.connect_to("readout", readout.port, **FAST)
        link = panel.links[0]
        link.column.setCurrentIndex(link.column.findData("measured"))
        assert link.column.currentData() == "measured"
        for k in range(12):
            place = presenter.plan_placement()
            assert place is not None, k
            target, run, direction = (place.cells[n] for n in ("target", "run", "direction"))
            actual = float(target) + _axis_error_arcsec(float(target), direction,
                                                        int(run)) / 3600.0
            readout.positions[0] = (actual,)
            qtbot.waitUntil(lambda a=actual: link.latest is not None and link.usable
                            and abs(link.latest.values[0] - a) < 6e-6, timeout=3000)
            if k == 4:  # the cursor on a filled row: the take still goes to the plan's point
                presenter.view.table.setCurrentIndex(model.index(1, keys.index("measured")))
                before = [model.sheet.text(1, c) for c in range(len(keys))]
            assert panel.take_reading() == f"row {place.row + 1}"
            if k == 4:
                assert [model.sheet.text(1, c) for c in range(len(keys))] == before
            row = place.row
            assert [model.sheet.text(row, keys.index(n)) for n in ("target", "run",
                                                                  "direction")] == \
                [target, run, direction]
            truth[row] = _axis_error_arcsec(float(target), direction, int(run))
        assert presenter.plan_placement() is None  # the plan is complete
        panel.disconnect_instrument()
    assert model.sheet.row_count == 12
    # the linear cycle: run 1 ↑ 0, 30, 60; ↓ 60, 30, 0; run 2 …
    assert [model.sheet.text(r, keys.index("target")) for r in range(6)] == \
        ["0", "30", "60", "60", "30", "0"]
    assert [model.sheet.text(r, keys.index("direction")) for r in range(6)] == \
        ["+", "+", "+", "-", "-", "-"]
    assert {model.sheet.text(r, keys.index("run")) for r in range(6, 12)} == {"2"}
    presenter.refresh()
    assert presenter.problem == "", presenter.problem
    result = presenter.result
    assert result is not None and result.incomplete is None
    assert len(result.deviations) == 12
    for row, deviation in zip(result.rows, result.deviations, strict=True):
        # the readout sends 5 decimals of a degree: 0.018″ at most
        assert deviation == pytest.approx(truth[int(row)], abs=0.02)
