"""A polygon live run shows the faces read so far while set 1 is read (gui77, live76 F11:
the main plot said "No data" until set 1 closed, though a technician judges the set-up from
the first faces). Each face's raw error against the set's first reading — the encoder's
step less 30° and the face's deviation, less the autocollimator's change — is on the error
plot and beside the sets as the takes arrive; with the faces not set, the autocollimator's
x at each encoder reading. Through the window: the autocollimator and readout simulators,
the polygon's entry plan, the certificate's deviation typed per face as the day did."""

from __future__ import annotations

import numpy as np
import pytest

from tests.app.capture.test_capture_marks import _connect, _take_at
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds

#: per face of set 1: encoder (°), AC x and y (″), the polygon's deviation (″)
FACES = [(10.0, 0.5, 0.25, 0.10), (40.0004, 0.75, 0.5, 0.20), (70.0002, 1.25, 0.75, 0.30),
         (99.9999, -0.5, 1.0, 0.00)]


def _errors(n: int) -> list[float]:
    """eq 1 against face 1: (a − a₁ − (f − 1)·30°)·3600 − (dev − dev₁) − (x − x₁)."""
    a1, x1, _, d1 = FACES[0]
    return [((a - a1) - k * 30.0) * 3600.0 - (d - d1) - (x - x1)
            for k, (a, x, _, d) in enumerate(FACES[:n])]


@pytest.mark.parametrize("faces", [12, 0])
def test_the_faces_of_set_1_are_plotted_as_they_are_taken(window, qtbot, faces):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": faces, "plan_sets": 2 if faces else 0})
    model, view, panel = bench.table_model, bench.view, window.capture_panel
    keys = [c.key for c in model.sheet.columns]
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(10.0,)]) as ro:
        _connect(panel, ac, ro)
        for face, (encoder, x, y, deviation) in enumerate(FACES):
            assert _take_at(qtbot, panel, ac, ro, encoder, x, y) == f"row {face + 1}"
            if not faces:  # no plan: the face typed, as without one
                model.set_cells([(face, keys.index("position"), str(face + 1))])
            model.set_cells([(face, keys.index("polygon_dev_arcsec"), f"{deviation:.2f}")])
            qtbot.waitUntil(lambda f=face: not bench.analysis_pending and bench.parsed is not None
                            and bench.parsed.n == f + 1, timeout=5000)
            assert bench.result is None  # no set complete: no result yet
            xs, ys = view.error_plot.raw_curve.getData()
            assert xs is not None and len(xs) == face + 1, (face, xs)
            if faces:
                assert xs == pytest.approx(np.arange(face + 1) * 30.0)
                assert ys == pytest.approx(_errors(face + 1), abs=1e-6)
            else:
                assert xs == pytest.approx([f[0] for f in FACES[:face + 1]])
                assert ys == pytest.approx([f[1] for f in FACES[:face + 1]])
            (curve,) = [c for c in view.sets_plot.curves if c.getData()[0] is not None
                        and len(c.getData()[0])]  # beside the sets as well
            assert curve.getData()[1] == pytest.approx(ys)
        panel.disconnect_instrument()
    assert _errors(4) == pytest.approx([0.0, 1.09, -0.23, 0.74], abs=1e-6)


def test_no_faces_read_figure_once_set_1_has_closed():
    """Set 1 closed (or set 2 begun): the result, or the reason there is none, stands for
    it; the figure of "set 1 in progress" is not drawn."""
    from models.polygon.analysis import POLYGON
    from models.polygon.plots import faces_read_figure
    from models.readings.sheet import ReadingsSheet

    keys = [c.key for c in POLYGON.columns]

    def sheet(rows):
        return ReadingsSheet(POLYGON.columns, [[dict(r).get(k, "") for k in keys]
                                               for r in rows]).parse()

    rows = [{"position": str(f), "encoder_deg": f"{(f - 1) * 90.0 + 0.0001 * f:.4f}",
             "polygon_dev_arcsec": "0", "ac_x_arcsec": "0.5", "set": "1"} for f in (1, 2, 3)]
    figure = faces_read_figure(sheet(rows), {"faces": 4})
    assert figure is not None and list(figure.series[0].y) == pytest.approx([0.0, 0.36, 0.72])
    closed = rows + [{**rows[0], "position": "4", "encoder_deg": "270"}, rows[0]]
    assert faces_read_figure(sheet(closed), {"faces": 4}) is None
    assert faces_read_figure(sheet(rows[:1] + [{**rows[1], "set": "2"}]), {"faces": 4}) is None
