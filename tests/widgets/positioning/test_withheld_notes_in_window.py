"""Leftovers 79, item 1, in the window: the results beside a two-run record's "R = 7″" say,
in the certificate's words, that its interval is withheld, why, and the place it is rounded
to; they said why only. The axis is simulated from first principles
(tests/repeatability_rig.py)."""

from __future__ import annotations

import re

import numpy as np

from tests.models.positioning.test_withheld_figures_printed import _axis


def test_the_results_say_the_place_a_withheld_figure_is_rounded_to(window, qtbot, tmp_path):
    rows, _ = _axis(np.random.default_rng(6805))
    csv = tmp_path / "two_runs.csv"
    csv.write_text("target,run,direction,deviation\n" + "".join(
        f"{a},{r},{d},{x}\n" for a, r, d, x, _ in rows), encoding="utf-8")
    presenter = window.presenter("positioning")
    presenter.import_file(csv)
    qtbot.waitUntil(lambda: presenter.result is not None and not presenter.analysis_pending,
                    timeout=60000)
    shown = presenter.view.summary.toPlainText()
    r = re.search(r"ISO 230-2: A = \S+, R = (\d+)\"", shown)
    assert r, shown
    assert r.group(1) == "7", shown  # R 6.54″ of this axis, to its withheld interval's 1″
    assert ("measure at least 3 runs each way; R is printed rounded to 1\", the last place of "
            "that interval's half-width to two significant digits (GUM 7.2.6): the two runs "
            "do not give it more closely.") in shown, shown
