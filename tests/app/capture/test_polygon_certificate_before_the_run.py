"""A polygon certificate loaded before a live run (live78): with the table empty it changed
no cell and was dropped without a word; every face taken then had no deviation, each row
was red ("cannot be read"), and the run showed "0 usable readings" and no faces on the plot
to its end. Its deviations are now kept by face: each take fills its face's deviation, the
faces of set 1 are plotted as they come, and the status line says the certificate waits
for the faces. Another project (File › New) forgets them. Through the window: the
autocollimator and readout simulators, the polygon's entry plan, the certificate's CSV."""

from __future__ import annotations

import pytest

from tests.app.capture.test_capture_marks import _connect, _take_at
from tests.app.capture.test_polygon_first_faces_plotted import FACES, _errors
from tests.app.capture.window_steps import show_workbench as _show
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator

pytestmark = pytest.mark.slow  # a window and two instruments for seconds


@pytest.fixture
def certificate(tmp_path):
    """The polygon's 12 face deviations (″): FACES' for faces 1–4, then 0.05 · face."""
    path = tmp_path / "polygon_certificate.csv"
    deviations = [f[3] for f in FACES] + [0.05 * face for face in range(5, 13)]
    path.write_text("position,deviation_arcsec\n" + "".join(
        f"{face},{value:g}\n" for face, value in enumerate(deviations, start=1)))
    return path


def test_a_certificate_loaded_before_the_run_fills_each_face_taken(window, qtbot,
                                                                    certificate):
    bench = _show(window, "polygon")
    bench.table_model.replace_all([], "empty")
    bench.set_settings({**bench.settings, "faces": 12, "plan_sets": 2})
    model, view, panel = bench.table_model, bench.view, window.capture_panel
    dev = [c.key for c in model.sheet.columns].index("polygon_dev_arcsec")
    assert bench.load_certificate(str(certificate)) == 0  # no row yet: no cell changed
    said = window.statusBar().currentMessage()
    with AutocollimatorSimulator("pty", positions=[(0.5, 0.25)]) as ac, \
            ReadoutSimulator("pty", positions=[(10.0,)]) as ro:
        _connect(panel, ac, ro)
        for face, (encoder, x, y, deviation) in enumerate(FACES):
            assert _take_at(qtbot, panel, ac, ro, encoder, x, y) == f"row {face + 1}"
            assert float(model.sheet.text(face, dev)) == pytest.approx(deviation)
            qtbot.waitUntil(lambda f=face: not bench.analysis_pending and bench.parsed is not None
                            and bench.parsed.n == f + 1, timeout=5000)
            assert not bench.parsed.errors  # no red row
            xs, ys = view.error_plot.raw_curve.getData()
            assert xs is not None and len(xs) == face + 1, (face, xs)
            assert ys == pytest.approx(_errors(face + 1), abs=1e-6)
        panel.disconnect_instrument()
    assert said == ("polygon_certificate.csv: 12 face(s) have no row yet (1–12); their "
                    "deviations are filled in as each face is taken or typed")
    assert bench.face_deviations[12] == "0.6"
    window.menus.new_action.trigger()  # another project: another polygon, perhaps
    assert bench.face_deviations == {}


def test_a_certificate_loaded_over_the_whole_table_says_nothing_more(window, certificate):
    """Every face in the table: the column filled, no word on the status line."""
    bench = _show(window, "polygon")
    keys = [c.key for c in bench.sheet.columns]
    rows = []
    for face in range(1, 13):
        row = [""] * len(keys)
        row[keys.index("position")] = str(face)
        rows.append(row)
    bench.table_model.replace_all(rows, "faces")
    window.statusBar().clearMessage()
    assert bench.load_certificate(str(certificate)) == 12
    assert bench.sheet.text(11, keys.index("polygon_dev_arcsec")) == "0.6"
    assert window.statusBar().currentMessage() == ""
