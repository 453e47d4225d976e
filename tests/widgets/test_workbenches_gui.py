"""Polygon and fringe workbenches driven through the GUI, and the screenshot command."""

import numpy as np
import pytest
from PySide6.QtCore import Qt
from PySide6.QtGui import QGuiApplication

from app.main import main
from widgets import save_file, workbench_presenter
from widgets.fringe.presenter import FringePresenter
from widgets.polygon.presenter import PolygonPresenter
from widgets.readings_table_model import MUTED_BRUSH


@pytest.fixture
def polygon(qtbot):
    presenter = PolygonPresenter()
    qtbot.addWidget(presenter.view)
    return presenter


@pytest.fixture
def fringe(qtbot):
    presenter = FringePresenter()
    qtbot.addWidget(presenter.view)
    return presenter


@pytest.mark.slow
def test_polygon_sample_plots_and_closure_row(qtbot, polygon):
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    x, corrected = polygon.view.error_plot.corrected_curve.getData()
    assert len(x) == 24
    np.testing.assert_allclose(corrected, polygon.result.mean_corrected_arcsec)
    assert polygon.table_model.highlight_rows == {24, 49}
    assert polygon.table_model.data(polygon.table_model.index(24, 0),
                                    Qt.ItemDataRole.BackgroundRole) == MUTED_BRUSH
    _, heights = polygon.view.harmonics.bars.opts["x"], polygon.view.harmonics.bars.opts["height"]
    assert heights[0] == pytest.approx(0.35, abs=0.05)  # eccentricity of the sample encoder


@pytest.mark.slow
def test_polygon_correction_curve_and_settings_through_the_form(qtbot, polygon):
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    result = polygon.result
    _, raw = polygon.view.error_plot.raw_curve.getData()
    _, correction = polygon.view.error_plot.model_curve.getData()
    _, corrected = polygon.view.error_plot.corrected_curve.getData()
    np.testing.assert_allclose(raw + correction, corrected, atol=1e-9)  # corrected = raw + correction
    mean_pyramidal = np.mean([s.pyramidal_error_arcsec for s in result.sets], axis=0)
    np.testing.assert_allclose(correction, -mean_pyramidal, atol=1e-9)
    assert "exceeds the 270\" allowed" in polygon.view.warnings.text()  # levelled, 1′ roll
    assert "autocollimator and rotary axis levelled" in polygon.view.summary.toPlainText()
    alignment = polygon.view.settings.field("ac_alignment")
    alignment.setCurrentIndex(alignment.findData("polygon"))  # seed 001's frame
    qtbot.waitUntil(lambda: polygon.result.ac_alignment == "polygon")
    assert "exceeds the 239\" allowed" in polygon.view.warnings.text()
    assert "the frame of Tian et al. 2015" in polygon.view.summary.toPlainText()
    zero = polygon.view.settings.field("zero_face")
    zero.setValue(5)
    qtbot.waitUntil(lambda: polygon.result.zero_face == 5)
    assert polygon.result.mean_corrected_arcsec[4] == pytest.approx(
        0.5 * (0.0 + polygon.result.sets[1].corrected_error_arcsec[4]))
    counting = polygon.view.settings.field("counting")
    counting.setCurrentIndex(counting.findData("against"))
    qtbot.waitUntil(lambda: polygon.result is None)  # the sample counts with the numbering
    # the likely cause first (#41: a partial set names the face numbering before a cell)
    said = polygon.view.summary.toPlainText()
    assert said.startswith("No result: The encoder readings of set 1 do not follow its face numbers")
    assert "row 2: encoder reading" in said
    assert "(counting against the face numbering" in polygon.view.summary.toPlainText()


@pytest.mark.slow
def test_polygon_failed_closure_shows_invalid(qtbot, polygon):
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    polygon.table_model.set_cells([(24, 3, "25.0")])  # closure reading far off
    qtbot.waitUntil(lambda: not polygon.result.valid)
    assert "RUN INVALID" in polygon.view.readings_label.text()
    assert "RUN INVALID" in polygon.view.summary.toPlainText()


@pytest.mark.slow
def test_fringe_paste_and_compensation(qtbot, fringe, samples_dir):
    lines = (samples_dir / "fringe_sample.csv").read_text().splitlines()[1:129]
    QGuiApplication.clipboard().setText("\n".join(line.replace(",", "\t") for line in lines))
    fringe.view.table.setCurrentIndex(fringe.table_model.index(0, 0))
    fringe.view.table.paste_action.trigger()
    qtbot.waitUntil(lambda: fringe.result is not None)
    _, raw = fringe.view.error_plot.raw_curve.getData()
    _, comp = fringe.view.error_plot.corrected_curve.getData()
    assert len(raw) == 128
    assert np.ptp(raw) > 0.9 and np.ptp(comp) < 0.1
    liss_x, _ = fringe.view.plots.liss_raw.getData()
    assert len(liss_x) == 128


@pytest.mark.slow
def test_interferometer_record_without_phase_reference(qtbot, fringe, samples_dir):
    lines = (samples_dir / "fringe_interferometer_sample.csv").read_text().splitlines()[1:3001]
    fringe.set_settings({"period_nm": 316.4})
    fringe.table_model.replace_all([line.split(",") for line in lines])
    fringe.refresh()
    qtbot.waitUntil(lambda: fringe.result is not None, timeout=10000)
    result = fringe.result
    assert result.phase_source == "estimated" and result.unit == "nm"
    assert "error, est. phase (nm)" in fringe.view.error_plot.main_plot.getAxis("left").labelText
    x, y = fringe.view.plots.liss_ellipse.getData()
    e = result.ellipse
    assert len(x) == 361 and np.max(y) == pytest.approx(e.offset_sin + e.amplitude_sin, rel=1e-3)
    assert "not observable without a phase reference" in fringe.view.warnings.text()
    assert "phase estimated from the signals" in fringe.view.summary.toPlainText()


@pytest.mark.slow
def test_large_fringe_run_is_analysed_off_the_gui_thread(qtbot, fringe, monkeypatch):
    monkeypatch.setattr(workbench_presenter, "THREAD_THRESHOLD_ROWS", 1000)
    theta = np.arange(64 * 40) * 2 * np.pi / 64
    rows = [[f"{3.7 * np.sin(t):.5f}", f"{3.7 * np.cos(t):.5f}"] for t in theta]
    fringe.table_model.replace_all(rows)
    fringe.refresh()
    assert fringe.result is None and "Analysing 2560 readings" in fringe.view.summary.toPlainText()
    qtbot.waitUntil(lambda: fringe.result is not None, timeout=10000)
    assert fringe.result.raw_error.size == 2560


@pytest.mark.slow
def test_edits_cancel_the_analysis_they_supersede(qtbot, fringe, monkeypatch):
    """Edits typed while a large record is analysed: the running analysis stops at its
    next checkpoint instead of finishing for nothing, and the result shown is the last
    edit's."""
    monkeypatch.setattr(workbench_presenter, "THREAD_THRESHOLD_ROWS", 1000)
    theta = np.arange(64 * 400) * 2 * np.pi / 64  # the phase estimated: seconds of work
    rows = [[f"{3.7 * np.sin(t):.5f}", f"{3.7 * np.cos(t) + 0.01:.5f}"] for t in theta]
    fringe.table_model.replace_all(rows)
    fringe.refresh()
    model = fringe.table_model
    for i in range(4):  # typed faster than the analysis runs
        model.setData(model.index(3, 0), f"{0.5 + 0.1 * i:.1f}")
        fringe.refresh()
    qtbot.waitUntil(lambda: fringe.result is not None and not fringe.busy, timeout=30000)
    assert fringe.result.u_sin[3] == pytest.approx(0.8)
    assert fringe.cancelled_analyses >= 3  # none of the superseded ones ran to its end
    assert fringe.cancelled_analyses <= 4


@pytest.mark.slow
def test_screenshot_command_writes_every_workbench(tmp_path, qapp):
    assert main(["--screenshot", str(tmp_path)]) == 0
    names = sorted(p.name for p in tmp_path.glob("*.png"))
    from models.registry import KINDS

    assert names == sorted(["certificate_dialog.png", "live_signals.png"]
                           + [f"{key}.png" for key in KINDS])
    assert all(p.stat().st_size > 20_000 for p in tmp_path.glob("*.png"))


@pytest.mark.slow
def test_polygon_certificate_fills_deviations_undoably(qtbot, polygon, tmp_path):
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    cert = tmp_path / "cert.csv"
    cert.write_text("position,deviation_arcsec\n" + "".join(f"{i},{0.01 * i:.2f}\n"
                                                              for i in range(1, 25)))
    before = polygon.sheet.copy_rows()
    assert polygon.load_certificate(str(cert)) == 50
    assert polygon.sheet.text(4, 2) == "0.05" and polygon.sheet.text(24, 2) == "0.01"
    polygon.undo_stack.undo()
    assert polygon.sheet.copy_rows() == before


@pytest.mark.slow
def test_polygon_certificate_missing_position(qtbot, polygon, tmp_path):
    from models.readings.tabular_import import TableImportError

    polygon.load_sample()
    cert = tmp_path / "short.csv"
    cert.write_text("1,0.1\n2,0.2\n")
    with pytest.raises(TableImportError, match="no deviation for position 3"):
        polygon.load_certificate(str(cert))


@pytest.mark.slow
def test_closure_limit_table_setting(qtbot, polygon):
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None and polygon.result.valid)
    polygon.set_settings({"closure_limits_arcsec": "0.1, 0.1, 0.1, 1, 2, 5, 15"})
    qtbot.waitUntil(lambda: not polygon.result.valid)  # sample closure 0.12" > 0.1"


@pytest.mark.slow
def test_what_if_starts_in_the_main_set_up_and_names_it_plainly(polygon):
    """#31: the What-if tab started in the paper's frame ("polygon's axis (seed 001's
    frame)") while the workbench starts levelled; its sweep menu cited "Fig 3" of no paper."""
    sim = polygon.view.simulation
    main = polygon.view.settings.field("ac_alignment")
    assert sim.form.values()["ac_alignment"] == main.currentData() == "levelled"
    alignment = sim.form.field("ac_alignment")
    texts = [alignment.itemText(i) for i in range(alignment.count())]
    assert texts == [main.itemText(i) for i in range(main.count())]
    assert texts[1] == "vertical along the polygon's axis (rolled with the tilt)"
    sweep = sim.form.field("sweep")
    assert not any("Fig" in sweep.itemText(i) for i in range(sweep.count()))
    assert "Fig. 3 of Tian et al. 2015" in sweep.toolTip()
    assert not any("seed" in text for text in texts + [main.toolTip()])


@pytest.mark.slow
def test_polygon_simulation_reproduces_fig3(qtbot, polygon):
    sim = polygon.view.simulation
    sim.form.set_values({"psi_arcsec": 600.0, "sweep": "omega_deg", "ac_alignment": "polygon"})
    sim.sweep_values.setText("0, 90")
    sim.update_curves()
    x, at_0 = sim.top_curves[0].getData()
    _, at_90 = sim.top_curves[1].getData()
    assert np.max(np.abs(at_90)) == pytest.approx(1.921, abs=0.001)  # ψ = 10', ω = 90°
    assert np.max(np.abs(at_0)) < np.max(np.abs(at_90))  # ω = 0° is the smallest (seed §3.3)
    sim.form.set_values({"ac_alignment": "levelled"})  # the polygon's own term only
    sim.update_curves()
    _, levelled = sim.top_curves[1].getData()
    assert np.ptp(levelled) == pytest.approx(600.0**2 / 206264.8 / 2, rel=1e-3)  # ψ²/2 rad


@pytest.mark.slow
def test_large_file_is_read_off_the_gui_thread(qtbot, fringe, tmp_path):
    theta = np.arange(64 * 1200) * 2 * np.pi / 64  # 76800 samples, about 1.4 MB
    path = tmp_path / "revolution.csv"
    np.savetxt(path, np.column_stack([3.77 * np.sin(theta + 0.03) + 0.08 * np.sin(3 * theta),
                                      3.73 * np.cos(theta)]),
               fmt="%.5f", delimiter=",", header="u_sin,u_cos", comments="")
    assert path.stat().st_size > workbench_presenter.THREAD_THRESHOLD_BYTES
    fringe.set_settings({"samples_per_period": 64})
    fringe.start_import(path)
    assert fringe.busy and fringe.view.busy.isVisibleTo(fringe.view)
    assert fringe.sheet.row_count == 0  # nothing replaced until the worker is done
    qtbot.waitUntil(lambda: fringe.result is not None and not fringe.busy, timeout=30000)
    assert fringe.sheet.row_count == 76800
    assert fringe.result.sin_fit.amplitude[3] == pytest.approx(0.08, abs=1e-4)
    assert fringe.result.sin_periods.shape == (1200, 7)
    fringe.undo_stack.undo()  # the import is one undo step
    qtbot.waitUntil(lambda: fringe.sheet.row_count == 0)


@pytest.mark.slow
def test_large_import_error_is_reported(qtbot, fringe, tmp_path):
    path = tmp_path / "bad.csv"
    path.write_text("foo,bar\n" + "1,2\n" * 300_000)
    with qtbot.waitSignal(fringe.import_failed, timeout=30000) as blocker:
        fringe.start_import(path)
    assert "no column 'u_sin'" in blocker.args[0]
    assert not fringe.busy


def _large_signal_file(tmp_path) -> object:
    theta = np.arange(64 * 1200) * 2 * np.pi / 64
    path = tmp_path / "revolution.csv"
    np.savetxt(path, np.column_stack([np.sin(theta), np.cos(theta)]), fmt="%.5f", delimiter=",",
               header="u_sin,u_cos", comments="")
    return path


def _the_worker_import_lands(qtbot, presenter):
    """Waits, on leaving the block, until the import read on a worker has landed in the GUI
    thread: its result is delivered to the presenter (which keeps or drops it) before this
    waiter's copy, both connections queued to the GUI thread in the order they were made
    (the tests waited 3 s, ~10 times the worker's read, for the same)."""
    return qtbot.waitSignal(presenter._signals.imported, timeout=30000)


@pytest.mark.slow
def test_the_last_import_asked_for_is_the_one_shown(qtbot, fringe, tmp_path, samples_dir):
    with _the_worker_import_lands(qtbot, fringe):
        fringe.start_import(_large_signal_file(tmp_path))  # read on a worker …
        fringe.start_import(samples_dir / "fringe_sample.csv")  # … then a small one at once
        assert fringe.sheet.row_count == 512 and not fringe.busy
    assert fringe.sheet.row_count == 512  # the large one landed and was dropped


@pytest.mark.slow
def test_opening_a_project_during_an_import_keeps_the_project(qtbot, fringe, tmp_path):
    from models.project.file import WorkbenchState

    with _the_worker_import_lands(qtbot, fringe):
        fringe.start_import(_large_signal_file(tmp_path))
        fringe.load_state(WorkbenchState([["0.1", "1.0"], ["0.9", "0.2"]], {}))
    assert fringe.sheet.copy_rows()[:2] == [["0.1", "1.0", ""], ["0.9", "0.2", ""]]
    assert fringe.sheet.row_count == 2 and not fringe.busy


@pytest.mark.slow
def test_polygon_headline_says_the_result_stands_and_what_the_tilt_asks(qtbot, polygon):
    """#31: "Grade 3 (±1″) met … tilt ψ = 480 exceeds 270" read as pass and fail at once.
    The tilt's error is removed from the figures (exact 3-D rotation), so the grade's
    verdict stands; the tilt above the allowed asks for a better seating next time."""
    polygon.load_sample()
    qtbot.waitUntil(lambda: polygon.result is not None)
    result = polygon.result
    assert result.sets[0].tilt.psi_arcsec > result.allowed_tilt_arcsec  # the sample: ~480″ > 270″
    headline = polygon.view.verdict.text()
    assert headline.startswith("Grade 3 (±1\") met: corrected error peak-to-peak")
    assert "exceeds" not in headline
    assert "the tilt's error is corrected in these figures" in headline
    assert (f"tilt ψ = {result.sets[0].tilt.psi_arcsec:.0f}\", above the "
            f"{result.allowed_tilt_arcsec:.0f}\" allowed — re-seat the polygon") in headline


@pytest.mark.slow
def test_fringe_table_export_to_an_unwritable_path_tells_the_user(qtbot, fringe, tmp_path,
                                                                   monkeypatch):
    """The export goes through the workbench's correction table, as on the command line: a
    folder that is not there is told, naming the file, and nothing is raised out of the
    button's slot; a good path writes the table and says so."""
    from PySide6.QtWidgets import QMessageBox

    told = []
    monkeypatch.setattr(QMessageBox, "warning", lambda _parent, title, text: told.append(
        (title, text)))
    fringe.load_sample()
    qtbot.waitUntil(lambda: fringe.result is not None)
    bad = tmp_path / "no such folder" / "table.csv"
    monkeypatch.setattr(save_file, "choose_save_file", lambda *_a, **_k: (str(bad), ""))
    qtbot.mouseClick(fringe.view.export_button, Qt.MouseButton.LeftButton)
    assert len(told) == 1
    title, text = told[0]
    assert title == "Cannot export the correction table"
    assert str(bad) in text and "does not exist" in text  # refused before writing (#61)
    assert not bad.parent.exists()
    good = tmp_path / "table.h"
    monkeypatch.setattr(save_file, "choose_save_file", lambda *_a, **_k: (str(good), ""))
    qtbot.mouseClick(fringe.view.export_button, Qt.MouseButton.LeftButton)
    assert len(told) == 1
    assert good.read_text().startswith("/* AngleBench fringe correction table")
    # said in the status bar, not written into the readings caption (#41)
    assert "Correction table, 1024 entries (C header) written" in fringe.view.last_status
    assert "written" not in fringe.view.readings_label.text()
