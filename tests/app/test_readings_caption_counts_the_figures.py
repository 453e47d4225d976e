"""Day review 74 F9: the readings caption said "Readings — 7 used" while run 2 was in
progress and its 3 readings entered no figure (the summary said so). It now counts what
the figures use: "7 taken, 4 used" while a run is in progress, "8 used" once it is
complete. The readings are an axis simulated here: a periodic error plus a small scatter
per approach, in arcseconds."""

from __future__ import annotations

import math
import random

from tests.app.capture.window_steps import show_workbench as _show


def _approaches(targets, runs):
    """(target, run, direction, deviation) of ISO 230-2's linear cycle, one direction."""
    rng = random.Random(74)
    return [[f"{t:g}", str(run), "+",
             f"{3.0 * math.sin(math.radians(t)) + rng.gauss(0.0, 0.4):.2f}"]
            for run in range(1, runs + 1) for t in targets]


def _caption(window, qtbot, rows):
    bench = _show(window, "positioning")
    bench.set_settings({**bench.settings, "plan_runs": 0})
    bench.table_model.replace_all([list(r) for r in rows], "typed")
    with qtbot.waitSignal(bench.analysed, timeout=5000):
        bench.refresh()
    return bench, bench.view.readings_label.text()


def test_a_run_in_progress_is_counted_as_taken_not_used(window, qtbot):
    rows = _approaches([0, 15, 30, 45], 2)
    bench, caption = _caption(window, qtbot, rows[:7])
    assert bench.result is not None and bench.result.incomplete is not None
    assert caption.startswith("Readings — 7 taken, 4 used"), caption
    bench, caption = _caption(window, qtbot, rows)
    assert bench.result is not None and bench.result.incomplete is None
    assert caption.startswith("Readings — 8 used"), caption
