"""The window a technician uses all day (#19, first part): the keyboard switches
workbenches and redoes, a dropped file is imported and said so, a name typed without an
extension gets the chosen type's, a bad cell's tooltip names the header on screen, the
spectrum's bars rise with the harmonic's size."""

from __future__ import annotations

import numpy as np
import pytest
from PySide6.QtCore import QMimeData, QPointF, Qt, QUrl
from PySide6.QtGui import QDropEvent

from widgets import save_file
from widgets.save_file import with_filter_suffix

pytestmark = pytest.mark.slow  # every test here takes more than 0.4 s (a window, a certificate, a program)


@pytest.fixture(scope="module")
def _window_of_the_module(qapp, tmp_path_factory):
    """One shown window (focus and key presses need a visible window) for the cases below,
    each of which starts from it as :func:`window` leaves it: a window each took ~0.45 s of
    CPU."""
    from tests.conftest import window_of_a_module

    for shown in window_of_a_module(tmp_path_factory.mktemp("window_of_the_module")):
        shown.show()
        shown.size_when_made = shown.size()
        yield shown


@pytest.fixture
def window(_window_of_the_module, qtbot):
    """:func:`_window_of_the_module` as a fresh one is, but for the analyses of the empty
    sheets File › New makes (a fresh window has analysed nothing yet; no case here asks
    before it loads or types): every sheet empty, the set-ups the lab's defaults, no project
    file, no nominal step, no undo history, in English, the first workbench in front, its
    first size, no manual open, nothing told yet."""
    from PySide6.QtCore import QCoreApplication, QEvent
    from PySide6.QtWidgets import QApplication

    shown = _window_of_the_module
    if shown.language != "en":
        shown.set_language("en")
    shown.projects.new_project()
    for presenter in shown.presenters:
        presenter.view.step.setValue(0.0)
        presenter.undo_stack.clear()
    if shown.manual is not None:
        shown.manual.close()
        shown.manual.deleteLater()
        shown.manual = None
        QCoreApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)
    shown.resize(shown.size_when_made)
    shown.tabs.setCurrentIndex(0)
    shown.statusBar().clearMessage()
    shown.told.clear()
    # the active window again, as a window just shown is (its shortcuts need it): a manual or
    # another case's window shown since took that from it
    shown.activateWindow()
    qtbot.waitUntil(lambda: QApplication.activeWindow() is shown, timeout=2000)
    return shown


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
    both = "CSV (*.csv);;Excel workbook (*.xlsx)"
    assert with_filter_suffix("/x/out", "Excel workbook (*.xlsx)", both) == "/x/out.xlsx"
    assert with_filter_suffix("/x/out.csv", "Excel workbook (*.xlsx)", both) == "/x/out.csv"
    assert with_filter_suffix("", "CSV (*.csv)", both) == ""
    window.load_all_samples()
    monkeypatch.setattr(save_file, "choose_save_file",
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
    window.presenter("fringe").load_sample()  # the workbench looked at
    fringe = window.presenter("fringe")
    fringe.refresh()
    bars = fringe.view.plots.sin_bars.opts
    heights = np.asarray(bars["height"])
    amplitudes = [fringe.result.sin_fit.amplitude[k] for k in fringe.result.sin_fit.orders]
    assert np.all(heights > 0)
    assert list(np.argsort(heights)) == list(np.argsort(amplitudes))
    np.testing.assert_allclose(bars["y0"] + heights, np.log10(amplitudes))


def test_results_read_at_a_glance(window):
    """The verdict in one line on top, every warning in its strip, the figures in a table,
    and the result box resizable against the plots."""
    window.load_all_samples()
    polygon = window.presenter("polygon")
    view = polygon.view
    assert view.verdict.text().startswith("Grade 3 (±1\") met")
    assert "above the 270\" allowed — re-seat the polygon" in view.verdict.text()
    assert view.warnings.text().count("⚠") == len(polygon.result.warnings)
    names = [view.figures.item(r, 0).text() for r in range(view.figures.rowCount())]
    assert names == ["corrected peak-to-peak (\")", "pyramidal tilt ψ (\")"]
    # as the certificate prints it: to its U's decimal (0.98, not 0.9835)
    assert view.figures.item(0, 1).text() == f"{polygon.result.stats.peak_to_peak:.2f}"
    before, plots = view.result_splitter.sizes()
    view.result_splitter.setSizes([before + 150, plots - 150])
    assert view.result_splitter.sizes()[0] > before  # the technician gave it more room
    positioning = window.presenter("positioning").view
    # A to 0.1″ beside its interval 18.0 … 34.7″ (each target's own bounds, at the whole tail:
    # 0.8.18), R to 0.1″ beside 4.6 … 19.8″ (0.8.19; to 1″ beside 3 … 28″ before)
    assert positioning.verdict.text().startswith("ISO 230-2:2014: A = 22.4\", R = 10.1\"")
    window.presenter("theodolite").table_model.set_cells([(r, 0, "") for r in range(41)])
    window.presenter("theodolite").refresh()
    assert window.presenter("theodolite").view.verdict.text().startswith("No result")
    assert window.presenter("theodolite").view.figures.rowCount() == 0


def test_every_plot_copies_and_saves_its_image_by_name(window, qtbot):
    import pyqtgraph as pg
    from PySide6.QtWidgets import QApplication

    from widgets.plot_image import image_file_name

    window.presenter("polygon").load_sample()  # the workbench looked at
    view = window.presenter("polygon").view
    error_plot = view.plot_widget(0)
    menu = next(i for i in error_plot.graphics.scene().items() if isinstance(i, pg.ViewBox)).getMenu(None)
    actions = {a.text(): a for a in menu.actions()}
    assert "Copy image" in actions and "Save image…" in actions
    QApplication.clipboard().clear()
    actions["Copy image"].trigger()
    image = QApplication.clipboard().image()
    assert image.width() > 200 and image.height() > 200
    assert image_file_name("Polygon encoder test Error over the circle") == \
        "polygon-encoder-test-error-over-the-circle.png"


def test_instrument_style_entry_fills_theta_and_moves_to_the_next_reading(window, qtbot):
    presenter = window.presenter("theodolite")
    view, table = presenter.view, presenter.view.table
    assert (table.nominal_column, table.entry_column) == (0, 1)
    view.step.setValue(2.0)
    for r, (theta, az, el) in enumerate([("-4", "-4.0001", "0.1"), ("", "-1.9999", "0.2")]):
        if theta:
            table.setCurrentIndex(presenter.table_model.index(r, 0))
            qtbot.keyClick(table, Qt.Key.Key_F2)
            qtbot.keyClicks(table.focusWidget(), theta)
            qtbot.keyClick(table.focusWidget(), Qt.Key.Key_Tab)
        for text in (az, el):
            qtbot.keyClick(table, Qt.Key.Key_F2)
            qtbot.keyClicks(table.focusWidget(), text)
            qtbot.keyClick(table.focusWidget(),
                           Qt.Key.Key_Tab if text == az else Qt.Key.Key_Return)
        # Return (Qt commits it queued): one row down, at the first reading; θ from the step
        qtbot.waitUntil(lambda r=r: table.currentIndex().row() == r + 1, timeout=2000)
        assert table.currentIndex().column() == 1
    assert [presenter.sheet.text(r, 0) for r in range(3)] == ["-4", "-2", "0"]
    assert presenter.sheet.text(1, 1) == "-1.9999"
    presenter.refresh()
    # the last row holds θ = 0 from the step and waits for its reading: it is the next one
    # (#41 review: "next" said the row after it while a take filled it)
    assert presenter.sheet.text(2, 1) == ""
    assert view.next_label.text() == f"next: row {presenter.sheet.row_count}"
    assert not window.presenter("fringe").view.step.isVisibleTo(window.presenter("fringe").view)


@pytest.mark.parametrize("key", ["theodolite", "polygon", "positioning"])
def test_return_without_a_step_goes_to_the_next_rows_first_column(window, qtbot, key):
    """No nominal step: the technician types θ, the face or the target too, so Return
    lands on it (#31: it landed on A, the encoder or the deviation, and a typed run
    shifted every row by one column)."""
    presenter = window.presenter(key)
    window.tabs.setCurrentIndex(window.presenters.index(presenter))
    table = presenter.view.table
    assert presenter.view.step.value() == 0
    table.setCurrentIndex(presenter.table_model.index(0, 0))
    for column in range(2):
        qtbot.keyClick(table, Qt.Key.Key_F2)
        qtbot.keyClicks(table.focusWidget(), "1")
        qtbot.keyClick(table.focusWidget(), Qt.Key.Key_Tab if column == 0 else Qt.Key.Key_Return)
    qtbot.waitUntil(lambda: table.currentIndex().row() == 1, timeout=2000)
    assert table.currentIndex().column() == 0


def test_f6_walks_the_panes_and_f1_opens_the_manual(window, qtbot, monkeypatch):
    from PySide6.QtWidgets import QApplication

    view = window.current.view
    view.table.setFocus()
    qtbot.waitUntil(lambda: QApplication.focusWidget() is view.table)
    visited = []
    for _ in range(4):
        window.focus_next_pane()
        here = QApplication.focusWidget()
        visited.append(next(name for name, pane in (("table", view.table),
                                                     ("set-up", view.settings),
                                                     ("result", view.summary),
                                                     ("plots", view.plot_tabs))
                            if here is pane or pane.isAncestorOf(here)))
    assert visited == ["set-up", "result", "plots", "table"]
    shown = []
    from widgets.text_dialog import TextDialog  # the guide scrolls on a small screen (fit74)

    monkeypatch.setattr(TextDialog, "exec", lambda dialog: shown.append(dialog.text.text()) or 0)
    help_action = next(a for a in window.menuBar().actions() if a.text() == "&Help").menu()
    guide = next(a for a in help_action.actions() if a.text() == "&Quick guide")
    guide.trigger()
    assert "Ctrl+PgDn" in shown[0]
    manual = next(a for a in help_action.actions() if a.text().startswith("&Manual"))
    assert manual.shortcut().toString() == "F1"
    window.tabs.setCurrentIndex(1)
    qtbot.keyClick(window.current.view.table, Qt.Key.Key_F1)
    qtbot.waitUntil(lambda: window.manual is not None and window.manual.isVisible())
    assert window.manual.browser.source().fileName() == "polygon.html"
    assert "Vertical readings / tilt" in window.manual.browser.toPlainText()
    window.tabs.setCurrentIndex(2)
    manual.trigger()
    assert window.manual.browser.source().fileName() == "fringe.html"


def test_the_manual_explains_every_setting_and_every_plot_of_each_workbench(window):
    """A page per workbench naming each of its settings and plot tabs as the window shows
    them, so a setting or plot added without its explanation fails here."""
    import html
    import re
    from pathlib import PurePosixPath

    from app.manual_pages import render
    from widgets.manual_window import manual_page

    for presenter in window.presenters:
        page = manual_page(presenter.kind.key)
        assert page.name == f"{presenter.kind.key}.html"
        source = PurePosixPath(f"docs/user-guide/{presenter.kind.key}.md")  # the one source
        assert page.read_text("utf-8") == render(source), f"{page.name}: run `make docs`"
        text = html.unescape(re.sub(r"<[^>]+>", "", render(source)))
        tabs = presenter.view.plot_tabs
        for name in [tabs.tabText(i) for i in range(tabs.count())] + \
                [p.label for p in presenter.kind.parameters]:
            assert name in text, f"{page.name} does not explain {name!r}"


def test_the_chinese_manual_explains_every_setting_and_plot_as_the_window_names_them(window):
    """In Chinese, F1 opens the Chinese page, which names each setting and plot tab as the
    Chinese window shows them."""
    import html
    import re
    from pathlib import PurePosixPath

    from PySide6.QtWidgets import QLabel

    from app.manual_pages import render
    from widgets.manual_window import manual_page

    window.set_language("zh_CN")
    try:
        for presenter in window.presenters:
            page = manual_page(presenter.kind.key, "zh_CN")
            assert page.name == f"{presenter.kind.key}.zh_CN.html"
            source = PurePosixPath(f"docs/zh_CN/user-guide/{presenter.kind.key}.md")
            assert page.read_text("utf-8") == render(source), f"{page.name}: run `make docs`"
            text = html.unescape(re.sub(r"<[^>]+>", "", render(source)))
            tabs = presenter.view.plot_tabs
            labels = [label.text() for label in presenter.view.settings.findChildren(QLabel)
                      if label.buddy() is not None]
            assert len(labels) == len(presenter.kind.parameters)
            for name in [tabs.tabText(i) for i in range(tabs.count())] + labels:
                assert name in text, f"{page.name} does not explain {name!r}"
        window.show_manual()
        assert window.manual.browser.source().fileName() == \
            f"{window.current.kind.key}.zh_CN.html"
        window.set_language("en")  # the open manual follows
        assert window.manual.browser.source().fileName() == f"{window.current.kind.key}.html"
    finally:
        window.set_language("en")


def test_plots_keep_their_height_and_scroll_when_the_window_is_small(window, qtbot):
    from PySide6.QtWidgets import QScrollArea

    window.load_all_samples()
    view = window.presenter("theodolite").view
    assert isinstance(view.plot_tabs.widget(0), QScrollArea)
    error_plot = view.plot_widget(0)
    assert error_plot.minimumHeight() == 3 * view.PANEL_MIN_HEIGHT  # three panels
    window.resize(900, 420)  # as small as 200 % scale makes a laptop screen
    qtbot.wait(50)
    assert error_plot.height() >= 3 * view.PANEL_MIN_HEIGHT


def test_print_puts_the_result_and_plot_on_a_page(window, tmp_path):
    from pypdf import PdfReader
    from PySide6.QtPrintSupport import QPrinter

    window.load_all_samples()
    window.tabs.setCurrentIndex(1)
    printer = QPrinter(QPrinter.PrinterMode.HighResolution)
    printer.setOutputFormat(QPrinter.OutputFormat.PdfFormat)
    printer.setOutputFileName(str(tmp_path / "print.pdf"))
    window.print_to(printer)
    reader = PdfReader(tmp_path / "print.pdf")
    text = " ".join(reader.pages[0].extract_text().split())
    assert len(reader.pages) == 1 and "Grade 3" in text and "Polygon encoder test" in text
    assert reader.pages[0].images  # the plot
    assert window.menus.print_action.shortcut().toString() == "Ctrl+P"


@pytest.fixture
def own_window(qtbot, tmp_path):
    """A shown window of the test's own (settings and autosaves in its folder)."""
    from tests.conftest import answered_window, delete_window

    made = answered_window(tmp_path)
    qtbot.addWidget(made)
    made.show()
    yield made
    delete_window(made)


def test_results_are_read_in_the_unit_chosen_once(own_window, monkeypatch, tmp_path):
    """View › Angle unit: every workbench's plots, figures, verdict and exported results
    change unit together, with the unit in every title, and the choice is remembered (a
    window of its own: the unit chosen is remembered in its settings)."""
    from app.main_window import MainWindow
    from models.project.recovery import RecoveryStore

    window = own_window
    window.load_all_samples()
    theodolite, polygon = window.presenter("theodolite"), window.presenter("polygon")
    plot = theodolite.view.error_plot
    before = plot.corrected_curve.getData()[1].copy()
    monkeypatch.setattr(save_file, "choose_save_file",
                        lambda *a, **k: (str(tmp_path / "arcsec.csv"), "CSV (*.csv)"))
    assert window.export_results()
    urad = next(a for a in window.menus.angle_unit_actions.actions() if a.data() == "urad")
    urad.trigger()
    assert urad.isChecked()
    np.testing.assert_allclose(plot.corrected_curve.getData()[1], before * 4.8481368, rtol=1e-7)
    assert plot.main_plot.getAxis("left").labelText == "raw error (µrad)"
    assert plot.corrected_plot.getAxis("left").labelText == "corrected (µrad)"
    assert plot.residual_plot.getAxis("left").labelText == "E residual (µrad)"
    assert "µrad" in theodolite.view.verdict.text() and "\"" not in theodolite.view.verdict.text()
    names = [polygon.view.figures.item(r, 0).text() for r in range(polygon.view.figures.rowCount())]
    assert names == ["corrected peak-to-peak (µrad)", "pyramidal tilt ψ (µrad)"]
    assert float(polygon.view.figures.item(0, 1).text()) == pytest.approx(
        polygon.result.stats.peak_to_peak * 4.8481368, rel=1e-3)
    assert polygon.view.tilt_plot.plot.getAxis("left").labelText.endswith("(µrad)")
    per_target = window.presenter("positioning").view.per_target
    assert per_target.horizontalHeaderItem(1).text() == "x̄↑ (µrad)"
    monkeypatch.setattr(save_file, "choose_save_file",
                        lambda *a, **k: (str(tmp_path / "urad.csv"), "CSV (*.csv)"))
    assert window.export_results()
    arcsec_rows = (tmp_path / "arcsec.csv").read_text("utf-8-sig").splitlines()
    urad_rows = (tmp_path / "urad.csv").read_text("utf-8-sig").splitlines()
    assert "corrected_error_urad" in urad_rows[0] and "urad" not in arcsec_rows[0]
    for head, a, u in zip(arcsec_rows[0].split(","), arcsec_rows[1].split(","),
                          urad_rows[1].split(","), strict=True):
        factor = 4.8481368 if head.endswith("_arcsec") else 1.0
        # each file's figures to its own unit's printed decimals + 3 (0.8.14): equal within
        # half a last digit of each
        # (a figure whose rounded digits end in zeros is written shorter: at least 3 decimals)
        def half_step(text: str) -> float:
            return 0.5 * 10.0 ** -max(len(text.partition(".")[2]), 3)
        assert float(u or "nan") == pytest.approx(
            float(a or "nan") * factor, rel=1e-7,
            abs=half_step(u) + factor * half_step(a) + 1e-12, nan_ok=True)
    again = MainWindow(settings=window.qsettings, recovery=RecoveryStore(tmp_path / "r2"))
    try:
        assert all(p.angle_unit.key == "urad" for p in again.presenters)
    finally:
        again.close()
        again.deleteLater()
