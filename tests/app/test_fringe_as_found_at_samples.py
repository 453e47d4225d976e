"""Where an order folds into a fitted one (N = 8, highest harmonic 3: order 5 into order 3),
the error *as found* is the readings' own at the 8 sampled phases only, as the compensated
error is (day review 69, finding 1): the Statistics row "Interpolation error as found …
peak-to-peak", the legend "before compensation" and the window's bold line gave the
sampled phases' peak-to-peak with no note, 26 % below the head's error over the whole
period, while the after side said "at the sampled phases only"; and the statement on the
table began "Conformity is judged on the interpolation error as found" where no conformity
is judged (the half range is withheld). Checked on the real window (qtbot) and on a printed
certificate (pdftotext).

The channels come from tests/fringe_channels.py (first principles), nothing from models/."""

from __future__ import annotations

import re

import numpy as np
import pytest

from tests.app.test_fringe_compensation_at_samples import (
    AT_SAMPLES,
    HEAD,
    LINES,
    OPTIONS,
    _certificate,
    _record,
)

pytestmark = pytest.mark.slow  # a window, and a fringe certificate

PERIOD_ARCSEC = 1296000.0 / LINES
SEED = 6901


def test_the_windows_line_and_legend_say_the_error_as_found_is_at_the_samples(
        window, qtbot, tmp_path):
    fringe = window.presenter("fringe")
    window.tabs.setCurrentIndex(window.presenters.index(fringe))
    fringe.import_file(_record(tmp_path, SEED))
    fringe.set_settings({**fringe._settings, **OPTIONS})
    qtbot.waitUntil(lambda: fringe.result is not None and not fringe.analysis_pending
                    and bool(fringe.result.folded_orders), timeout=60000)
    line = fringe.view.verdict.text()
    found = line[:line.index("after compensation")]
    assert "peak-to-peak " + AT_SAMPLES in found, line
    legend = [item[1].text for item in fringe.view.error_plot.legend.items]
    assert any("before compensation" in name and AT_SAMPLES in name for name in legend), legend


def test_the_certificate_qualifies_the_error_as_found_and_judges_nothing_on_it(
        tmp_path, capsys):
    text = _certificate(tmp_path, capsys, SEED, decision_quantity="half_range")
    # the row's columns interleave in pdftotext: its note begins after the peak-to-peak,
    # the range's figures may stand between its words
    row = re.search(r"Interpolation error as found .{0,120}?peak-to-peak ([\d.]+)\" "
                    r"\([\d.]+ % of a period\)(; at the [-+\d.\"… ]*sampled phases only: "
                    r"the error between them is not determined)?", text)
    assert row is not None, text
    assert row.group(2), row.group(0)
    # the figure is the sampled phases': below the whole period's true error
    assert float(row.group(1)) < np.ptp(HEAD.true_error_rad()) * PERIOD_ARCSEC / (2 * np.pi)
    assert "before compensation, " + AT_SAMPLES in text
    assert "Conformity is judged on the interpolation error as found" not in text
    assert "No conformity is judged on the interpolation error as found" in text
