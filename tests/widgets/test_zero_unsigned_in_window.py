"""A zero is printed unsigned in the window as on the certificate (models/uncertainty/
rounding.fixed_places; assessment 76 L6: "0.0" at θ = −2° and "+0.0" at the reference
point): the positioning per-target table without a certificate's cells (its figures to
0.001), a printed figure converted to another unit, and the plot's cursor readout."""

from __future__ import annotations

import numpy as np
import pytest

from models.display_units import ANGLE_UNITS, table_in_unit
from models.positioning.analysis import POSITIONING
from models.readings.sheet import ReadingsSheet
from widgets.error_plot import ErrorPlot


def _result_with_zero_at_target_0():
    rng = np.random.default_rng(1)
    rows = []
    for run in range(1, 6):
        for direction, targets in (("+", (0, 30, 60)), ("-", (60, 30, 0))):
            for target in targets:
                deviation = 0.0 if target == 0 else rng.normal(0.0, 1.0)
                rows.append([str(target), str(run), direction, f"{deviation:.2f}", ""])
    return POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(),
                               POSITIONING.settings_with_defaults(None))


def test_the_per_target_tables_zero_has_no_sign():
    """Without the certificate's cells (no budget: the figures to 0.001) the mean deviation
    0 at target 0 read "+0.000" where the certificate prints "0.00"; the others keep their
    sign."""
    header, rows = _result_with_zero_at_target_0().per_target_table(None)
    first = dict(zip(header, rows[0], strict=True))
    assert first["target (°)"] == "0"
    assert [first[k] for k in ('x̄↑ (")', 'x̄↓ (")', 'B_i (")', 'M_i (")')] == ["0.000"] * 4
    signed = [dict(zip(header, row, strict=True))['x̄↑ (")'] for row in rows[1:]]
    assert all(text[0] in "+-" for text in signed), signed


@pytest.mark.parametrize("text, unit, shown", [("+0.0", "mdeg", "0.00"),
                                               ("-0.00", "urad", "0.00"),
                                               ("+0.36", "mdeg", "+0.100")])
def test_a_printed_zero_converted_stays_unsigned(text, unit, shown):
    _, rows = table_in_unit(('x (")',), [(text,)], ANGLE_UNITS[unit])
    assert rows[0][0] == shown


def test_the_cursor_readout_prints_zero_unsigned(qtbot):
    plot = ErrorPlot()
    qtbot.addWidget(plot)
    plot.resize(600, 500)
    plot.show()
    x = np.linspace(-20.0, 20.0, 41)
    plot.set_curves(x, 0.0 * x, -0.0 * x, 0.0 * x)
    plot._on_mouse_moved(plot.main_plot.sceneBoundingRect().center())
    text = plot.readout.text()
    assert "@" in text and "+0.0" not in text and "-0.0" not in text, text
    assert " 0.0" in text, text
