"""The window a technician uses all day (#19, first part): the keyboard switches
workbenches and redoes, a dropped file is imported and said so, a name typed without an
extension gets the chosen type's, a bad cell's tooltip names the header on screen, the
spectrum's bars rise with the harmonic's size."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QMimeData, QPointF, QSettings, Qt, QUrl
from PySide6.QtGui import QDropEvent
from PySide6.QtWidgets import QFileDialog, QMessageBox

from app.main_window import MainWindow, with_chosen_suffix
from models.project.recovery import RecoveryStore


@pytest.fixture
def window(qtbot, tmp_path):
    w = MainWindow(settings=QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat),
                   recovery=RecoveryStore(tmp_path / "recovery"))
    w.told = []
    w.tell = lambda title, text: w.told.append(text)
    w.ask = lambda *a: QMessageBox.StandardButton.Discard
    qtbot.addWidget(w)
    w.show()
    return w


def test_ctrl_pgdown_and_ctrl_tab_switch_workbenches_even_from_the_table(window, qtbot):
    window.presenters[0].view.table.setFocus()
    qtbot.keyClick(window.presenters[0].view.table, Qt.Key.Key_PageDown,
                   Qt.KeyboardModifier.ControlModifier)
    assert window.tabs.currentIndex() == 1
    qtbot.keyClick(window.current.view.table, Qt.Key.Key_PageUp,
                   Qt.KeyboardModifier.ControlModifier)
    assert window.tabs.currentIndex() == 0
    window.switch_tab(-1)
    assert window.tabs.currentIndex() == window.tabs.count() - 1


def test_ctrl_shift_z_redoes(window, qtbot):
    window.load_all_samples()
    presenter = window.current
    presenter.table_model.set_cells([(0, 0, "-19.5")])
    presenter.undo_stack.undo()
    assert presenter.sheet.text(0, 0) == "-20"
    qtbot.keyClick(presenter.view.table, Qt.Key.Key_Z,
                   Qt.KeyboardModifier.ControlModifier | Qt.KeyboardModifier.ShiftModifier)
    assert presenter.sheet.text(0, 0) == "-19.5"


def drop(window, path) -> None:
    mime = QMimeData()
    mime.setUrls([QUrl.fromLocalFile(str(path))])
    event = QDropEvent(QPointF(10, 10), Qt.DropAction.CopyAction, mime,
                       Qt.MouseButton.LeftButton, Qt.KeyboardModifier.NoModifier)
    window.dropEvent(event)


def test_a_dropped_csv_is_imported_and_said_so(window, samples_dir):
    window.tabs.setCurrentIndex(1)
    window.statusBar().showMessage("an old error", 15000)
    drop(window, samples_dir / "polygon_sample.csv")
    assert window.presenter("polygon").sheet.row_count == 50
    assert window.statusBar().currentMessage().startswith("Imported polygon_sample.csv: 50 row")
    drop(window, samples_dir / "fringe_sample.png")  # not a readings file: ignored
    assert window.told == []


def test_the_chosen_file_type_gives_a_name_its_extension(window, monkeypatch, tmp_path):
    assert with_chosen_suffix("/x/out", "Excel workbook (*.xlsx)") == "/x/out.xlsx"
    assert with_chosen_suffix("/x/out.csv", "Excel workbook (*.xlsx)") == "/x/out.csv"
    assert with_chosen_suffix("", "CSV (*.csv)") == ""
    window.load_all_samples()
    monkeypatch.setattr(QFileDialog, "getSaveFileName",
                        lambda *a, **k: (str(tmp_path / "results"), "Excel workbook (*.xlsx)"))
    assert window.export_results()
    assert (tmp_path / "results.xlsx").read_bytes()[:2] == b"PK"  # a workbook, not a CSV


def test_a_bad_cell_names_the_header_on_screen(window):
    presenter = window.presenter("theodolite")
    presenter.table_model.set_cells([(0, 2, "abc")])
    tip = presenter.table_model.data(presenter.table_model.index(0, 2),
                                     Qt.ItemDataRole.ToolTipRole)
    assert tip.startswith("Row 1, E / V [deg] (elevation_deg):")


def test_spectrum_bars_rise_with_the_harmonic(window):
    window.load_all_samples()
    fringe = window.presenter("fringe")
    fringe.refresh()
    bars = fringe.view.plots.sin_bars.opts
    heights = np.asarray(bars["height"])
    amplitudes = [fringe.result.sin_fit.amplitude[k] for k in fringe.result.sin_fit.orders]
    assert np.all(heights > 0)
    assert list(np.argsort(heights)) == list(np.argsort(amplitudes))
    np.testing.assert_allclose(bars["y0"] + heights, np.log10(amplitudes))
