"""Main window: one tab per workbench, the File/Edit/Help menus, project files,
autosave and crash recovery, persisted window state and recent files."""

from __future__ import annotations

import contextlib
from pathlib import Path

import numpy as np
import pyqtgraph as pg
import scipy
from PySide6 import __version__ as pyside_version
from PySide6.QtCore import QByteArray, QSettings, Qt, qVersion
from PySide6.QtGui import QAction, QActionGroup, QCloseEvent, QKeySequence, QUndoGroup
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QFileDialog,
    QMainWindow,
    QMenu,
    QMessageBox,
    QTabWidget,
    QWidget,
)

from app.certificate_dialogs import CertificateDialogs
from app.certificate_presenter import CertificatePresenter
from app.project_dialogs import ProjectDialogs
from app.project_presenter import ProjectPresenter, default_recovery_store
from app.run_overlay_actions import RunOverlayActions
from models import __version__
from models.display_units import ANGLE_UNITS, AngleUnit
from models.project.recovery import RecoveryStore
from models.readings.tabular_import import TableImportError
from models.registry import KINDS, presenter_class
from widgets.fonts import ensure_cjk_font
from widgets.i18n import (
    LANGUAGES,
    Tr,
    declared,
    explained,
    install_language,
    live,
    on_language_change,
    resolve_language,
    tr,
)
from widgets.screen_fit import fit_to_screen
from widgets.shortcuts import key_sequences
from widgets.workbench_presenter import SAMPLES_DIR, WorkbenchPresenter

LANGUAGE_SETTING = "ui/language"  # "system", "en" or "zh_CN" (widgets/i18n.py)
ANGLE_UNIT_SETTING = "display/angle_unit"  # the unit results are read in, for every workbench


def default_presenters() -> list[WorkbenchPresenter]:
    """One presenter per registered workbench, in the registry's order."""
    return [presenter_class(kind)() for kind in KINDS.values()]


class MainWindow(QMainWindow):
    """Holds the workbench presenters; all dialogs go through ``ask``/``tell`` so tests can
    answer them."""

    def __init__(self, settings: QSettings | None = None, recovery: RecoveryStore | None = None,
                 presenters: list[WorkbenchPresenter] | None = None, parent=None) -> None:
        super().__init__(parent)
        self.qsettings = settings or QSettings("AngleBench", "AngleBench")
        self.presenters = presenters or default_presenters()
        self.projects = ProjectPresenter(ProjectDialogs(self), self.presenters,
                                         recovery or default_recovery_store(), self.qsettings,
                                         lambda: self.current, self)
        self.manual = None  # the manual's window, made when first asked for (F1)
        self.certificates = CertificatePresenter(CertificateDialogs(self), self.qsettings,
                                                 lambda: self.projects.metadata,
                                                 lambda: self.current.mark_modified())
        ensure_cjk_font()  # Chinese names and readings are never boxes
        self.language = install_language(str(self.qsettings.value(LANGUAGE_SETTING, "system")))
        self.certificates.default_language = "zh" if self.language == "zh_CN" else "en"
        self._setup_ui()
        self._setup_menus()
        on_language_change(self, self._retranslate)
        self.tabs.currentChanged.connect(self._on_tab_changed_send)
        self._on_tab_changed_send(self.tabs.currentIndex())
        self._restore_window_state()
        self.projects.start()

    # -- construction ---------------------------------------------------------
    def _setup_ui(self) -> None:
        self.tabs = QTabWidget()
        self.undo_group = QUndoGroup(self)
        for presenter in self.presenters:
            self.tabs.addTab(presenter.view, declared(presenter.kind.title))
            self.undo_group.addStack(presenter.undo_stack)
            presenter.import_failed.connect(self._on_import_failed)
            presenter.imported.connect(self._on_imported)
        self.tabs.currentChanged.connect(self._on_tab_changed)
        self.setAcceptDrops(True)
        self._on_tab_changed(0)
        self.setCentralWidget(self.tabs)
        self.statusBar().showMessage(tr("Ready"))
        fit_to_screen(self, 1400, 900)

    def _menu(self, parent, title: Tr) -> QMenu:
        menu = parent.addMenu(title)
        live(menu.setTitle, title)
        return menu

    def _action(self, menu, text: Tr, slot, shortcut=None, tip: Tr | str = "") -> QAction:
        action = QAction(text, self)
        live(action.setText, text)
        if shortcut is not None:
            action.setShortcuts(key_sequences(shortcut))
        if isinstance(tip, Tr):
            live(action.setStatusTip, tip)
        action.triggered.connect(slot)
        menu.addAction(action)
        return action

    def _setup_menus(self) -> None:
        file_menu = self._menu(self.menuBar(), tr("&File"))
        self.new_action = self._action(file_menu, tr("&New"), self.projects.new_project,
                                       QKeySequence.StandardKey.New)
        self.open_action = self._action(file_menu, tr("&Open…"), self.projects.open_project_dialog,
                                        QKeySequence.StandardKey.Open)
        self.recent_menu = self._menu(file_menu, tr("Open &recent"))
        self.save_action = self._action(file_menu, tr("&Save"), self.projects.save,
                                        QKeySequence.StandardKey.Save)
        self.save_as_action = self._action(file_menu, tr("Save &as…"), self.projects.save_as,
                                           QKeySequence.StandardKey.SaveAs)
        file_menu.addSeparator()
        self.import_action = self._action(file_menu, tr("&Import CSV/XLSX…"), self.import_dialog,
                                          QKeySequence("Ctrl+Shift+I"),
                                          tr("Replace the current workbench's readings with a "
                                             "file's"))
        self.sample_action = self._action(file_menu, tr("Load bundled &sample"), self.load_sample)
        self.export_action = self._action(
            file_menu, tr("&Export certificate…"), self.export_certificate, QKeySequence("Ctrl+E"),
            tr("Write the current workbench's test certificate (PDF)"))
        self.export_results_action = self._action(
            file_menu, tr("Export &results (CSV/XLSX)…"), self.export_results,
            tip=tr("Write every point's raw, correction, corrected error and U"))
        self.register_action = self._action(
            file_menu, tr("Certificate re&gister…"), self.show_register,
            tip=tr("Every issued certificate: search, verify a PDF, amend, an instrument's "
                   "history"))
        self.send_action = self._action(
            file_menu, tr("Send to &positioning"), self.send_to_positioning,
            tip=tr("Judge this run to ISO 230-2 / VDI 3441 in the positioning workbench (its "
                   "readings are replaced; Edit > Undo there restores them)"))
        self.run_overlays = RunOverlayActions(self)
        self.overlay_action = self._action(
            file_menu, tr("O&verlay a run…"), lambda: self.run_overlays.overlay_file(),
            tip=tr("Draw another run of this workbench against today's: a readings or project "
                   "file (before/after compensation …)"))
        self.overlay_record_action = self._action(
            file_menu, tr("Overlay a certificate from the register…"),
            lambda: self.run_overlays.overlay_record(),
            tip=tr("Draw this instrument's earlier certificate against today's run"))
        self.remove_overlay_action = self._action(
            file_menu, tr("Remove the overlaid run"), lambda: self.run_overlays.remove())
        file_menu.addSeparator()
        self.print_action = self._action(
            file_menu, tr("&Print…"), self.print_dialog, QKeySequence.StandardKey.Print,
            tr("Print the current workbench's result and plot (the certificate is the PDF)"))
        file_menu.addSeparator()
        self._action(file_menu, tr("&Quit"), self.close, QKeySequence.StandardKey.Quit)

        edit_menu = self._menu(self.menuBar(), tr("&Edit"))
        # our own actions, not QUndoGroup's: theirs keep the prefix of the language they
        # were made in ("Undo Paste 3 rows" stays English in a Chinese window)
        undo = QAction(self)
        undo.triggered.connect(self.undo_group.undo)
        undo.setShortcuts(key_sequences(QKeySequence.StandardKey.Undo))
        redo = QAction(self)
        redo.triggered.connect(self.undo_group.redo)
        redo.setShortcuts(key_sequences(QKeySequence.StandardKey.Redo, "Ctrl+Shift+Z", "Ctrl+Y"))
        edit_menu.addAction(undo)
        edit_menu.addAction(redo)
        self.undo_action, self.redo_action = undo, redo
        for signal in (self.undo_group.undoTextChanged, self.undo_group.redoTextChanged,
                       self.undo_group.canUndoChanged, self.undo_group.canRedoChanged,
                       self.undo_group.activeStackChanged):
            signal.connect(self._update_undo_actions)
        self._update_undo_actions()
        edit_menu.addSeparator()
        self._action(edit_menu, tr("&Copy"), lambda: self.current.view.table.copy_selection())
        self._action(edit_menu, tr("&Paste"), lambda: self.current.view.table.paste())
        self._action(edit_menu, tr("&Insert row"), lambda: self.current.view.table.insert_row())
        self._action(edit_menu, tr("&Delete rows"), lambda: self.current.view.table.delete_rows())

        view_menu = self._menu(self.menuBar(), tr("&View"))
        for text, keys, step in ((tr("&Next workbench"), ("Ctrl+PgDown", "Ctrl+Tab"), 1),
                                 (tr("&Previous workbench"), ("Ctrl+PgUp", "Ctrl+Shift+Tab"),
                                  -1)):
            action = self._action(view_menu, text, lambda _=False, s=step: self.switch_tab(s))
            action.setShortcuts(key_sequences(*keys))
            action.setShortcutContext(Qt.ShortcutContext.ApplicationShortcut)
        focus = self._action(view_menu, tr("Next &pane (table, set-up, result, plots)"),
                             self.focus_next_pane, QKeySequence("F6"))
        focus.setShortcutContext(Qt.ShortcutContext.ApplicationShortcut)
        units_menu = self._menu(view_menu, tr("Angle &unit of results"))
        self.angle_unit_actions = QActionGroup(self)
        for unit in ANGLE_UNITS.values():
            action = self._action(units_menu, declared(unit.name),
                                  lambda _=False, u=unit: self.set_angle_unit(u),
                                  tip=tr("Plots, figures, texts and exported results in this "
                                         "unit (certificates keep the unit of the evaluation)"))
            action.setCheckable(True)
            action.setData(unit.key)
            self.angle_unit_actions.addAction(action)
        saved = str(self.qsettings.value(ANGLE_UNIT_SETTING, "arcsec"))
        self.set_angle_unit(ANGLE_UNITS.get(saved, ANGLE_UNITS["arcsec"]))

        language_menu = self._menu(view_menu, tr("&Language"))
        self.language_actions = QActionGroup(self)
        chosen = str(self.qsettings.value(LANGUAGE_SETTING, "system"))
        for key, name in LANGUAGES.items():
            action = self._action(language_menu, tr(name) if key == "system" else Tr(name, name),
                                  lambda _=False, k=key: self.set_language(k))
            action.setCheckable(True)
            action.setChecked(key == chosen)
            action.setData(key)
            self.language_actions.addAction(action)

        # readings from the instruments (#34): the panel, hidden until Connect…
        from app.capture.panel import CapturePanel

        self.capture_panel = CapturePanel(self)
        self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.capture_panel)
        self.capture_panel.hide()
        instrument_menu = self._menu(self.menuBar(), tr("&Instrument"))
        self.connect_instrument_action = self._action(
            instrument_menu, tr("&Connect…"),
            lambda: (self.capture_panel.show(), self.capture_panel.connect_dialog()))
        help_menu = self._menu(self.menuBar(), tr("&Help"))
        self._action(help_menu, tr("&Manual (this workbench)"), self.show_manual,
                     QKeySequence.StandardKey.HelpContents,
                     tip=tr("What to measure, how to set up, every setting and plot"))
        self._action(help_menu, tr("&Quick guide"), self.show_guide)
        self._action(help_menu, tr("&About AngleBench"), self.show_about)

    def set_language(self, choice: str) -> None:
        """The window in English or Chinese (or the system's language), at once: every text
        is set again and each result redrawn; readings, undo history and plots stay."""
        for action in self.language_actions.actions():
            action.setChecked(action.data() == choice)
        self.qsettings.setValue(LANGUAGE_SETTING, choice)
        self.language = resolve_language(choice)  # before the texts are set again in it
        self.certificates.default_language = "zh" if self.language == "zh_CN" else "en"
        install_language(choice)

    def _update_undo_actions(self, *_args) -> None:
        group = self.undo_group
        what = group.undoText()
        self.undo_action.setText(tr("&Undo {what}").format(what=what) if what else tr("&Undo"))
        self.undo_action.setEnabled(group.canUndo())
        what = group.redoText()
        self.redo_action.setText(tr("&Redo {what}").format(what=what) if what else tr("&Redo"))
        self.redo_action.setEnabled(group.canRedo())

    def _retranslate(self) -> None:
        self._update_undo_actions()
        if self.manual is not None and self.manual.isVisible():  # the page in the new language
            self.manual.show_page(self.current.kind.key, self.language)
        for index, presenter in enumerate(self.presenters):
            self.tabs.setTabText(index, declared(presenter.kind.title))
        self.projects.update_title()

    def set_angle_unit(self, unit: AngleUnit) -> None:
        """Results in ``unit`` on every workbench (redrawn, not re-analysed); remembered."""
        for action in self.angle_unit_actions.actions():
            action.setChecked(action.data() == unit.key)
        for presenter in self.presenters:
            presenter.set_angle_unit(unit)
        self.qsettings.setValue(ANGLE_UNIT_SETTING, unit.key)

    def focus_next_pane(self) -> None:
        """F6: the readings table, the set-up, the result, the plots, and round again."""
        view = self.current.view
        panes = [view.table, view.settings, view.summary, view.plot_tabs]
        here = QApplication.focusWidget()
        index = next((i for i, pane in enumerate(panes)
                      if here is not None and (here is pane or pane.isAncestorOf(here))), -1)
        target = panes[(index + 1) % len(panes)]
        first = target.focusWidget() if target is view.settings else None
        fields = [w for w in target.findChildren(QWidget)
                  if w.focusPolicy() != Qt.FocusPolicy.NoFocus] if target is view.settings else []
        (first or (fields[0] if fields else target)).setFocus(Qt.FocusReason.ShortcutFocusReason)

    def show_manual(self) -> None:
        """F1: the bundled manual at the page of the workbench in front."""
        if self.manual is None:
            from widgets.manual_window import ManualWindow

            self.manual = ManualWindow(self)  # a window of its own, closed with this one
        self.manual.show_page(self.current.kind.key, self.language)

    def show_guide(self) -> None:
        QMessageBox.information(self, tr("AngleBench — quick guide"), tr(
            "Type or paste the readings on the left (Return goes to the next row's first "
            "reading; a nominal step fills θ, face or target). The result, its warnings and the "
            "plots follow every edit.\n\n"
            "Keys: Ctrl+PgDn / Ctrl+PgUp or Ctrl+Tab switch workbenches; F6 moves between "
            "table, set-up, result and plots; Ctrl+Z / Ctrl+Shift+Z undo and redo; Ctrl+E "
            "exports the certificate; F1 opens the manual; right-click a plot to copy or save "
            "its image.\n\n"
            "Errors are errors of indication (indicated − reference); the positioning workbench "
            "keeps ISO 230-2's actual − target. Certificates are numbered and recorded by the "
            "register (File › Certificate register). Drop a CSV or XLSX on the window to "
            "import it."))

    def switch_tab(self, step: int) -> None:
        self.tabs.setCurrentIndex((self.tabs.currentIndex() + step) % self.tabs.count())

    @property
    def current(self) -> WorkbenchPresenter:
        return self.presenters[self.tabs.currentIndex()]

    def presenter(self, key: str) -> WorkbenchPresenter:
        return next(p for p in self.presenters if p.kind.key == key)

    def _on_tab_changed(self, index: int) -> None:
        if 0 <= index < len(self.presenters):
            self.undo_group.setActiveStack(self.presenters[index].undo_stack)

    # -- dialogs (tests replace these) --------------------------------------------
    def tell(self, title: str, text: str) -> None:
        self.statusBar().showMessage(text, 15000)
        QMessageBox.warning(self, title, text)

    def ask(self, title: str, text: str, buttons, default):
        return QMessageBox.question(self, title, text, buttons, default)

    def import_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(
            self, tr("Import readings into {workbench}").format(
                workbench=declared(self.current.kind.title)), self.projects.last_dir(),
            tr("Readings (*.csv *.txt *.xlsx *.xlsm);;All files (*)"))
        if path:
            self.current.start_import(path)  # large files are read off the GUI thread

    def import_file(self, path: str | Path, key: str | None = None) -> bool:
        presenter = self.presenter(key) if key else self.current
        try:
            presenter.import_file(path)
        except TableImportError as exc:
            self.tell(tr("Cannot import"), explained(exc))
            return False
        self.statusBar().showMessage(
            tr("Imported {path} (Edit › Undo restores the old readings)").format(path=path), 8000)
        return True

    def _on_import_failed(self, message: str) -> None:
        self.tell(tr("Cannot import"), message)

    def _on_imported(self, path: str, rows: int) -> None:
        """Say that it worked (and replace an earlier error at once)."""
        self.statusBar().showMessage(
            tr("Imported {name}: {rows} row(s) (Edit › Undo restores the previous readings)")
            .format(name=Path(path).name, rows=rows), 8000)

    # -- dropping files on the window (the project presenter decides) ---------------
    def _dropped_paths(self, mime) -> list[str]:
        return self.projects.droppable([u.toLocalFile() for u in mime.urls() if u.isLocalFile()])

    def dragEnterEvent(self, event) -> None:  # noqa: N802 - Qt's name
        if event.mimeData().hasUrls() and self._dropped_paths(event.mimeData()):
            event.acceptProposedAction()

    def dropEvent(self, event) -> None:  # noqa: N802 - Qt's name
        paths = self._dropped_paths(event.mimeData())
        if paths:
            event.acceptProposedAction()
            self.projects.drop(paths[0])

    def load_sample(self) -> None:
        """Replace the current workbench's readings with its sample (one undo step)."""
        self.current.import_file(SAMPLES_DIR / self.current.kind.sample_file)

    def print_dialog(self) -> bool:
        from PySide6.QtPrintSupport import QPrintDialog, QPrinter

        printer = QPrinter(QPrinter.PrinterMode.HighResolution)
        dialog = QPrintDialog(printer, self)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return False
        self.print_to(printer)
        return True

    def print_to(self, printer) -> None:
        from widgets.print_view import print_workbench

        print_workbench(self.current.view, printer,
                        f"{declared(self.current.kind.title)} — "
                        + (self.projects.path.name if self.projects.path
                           else tr("readings typed in AngleBench")))
        self.statusBar().showMessage(tr("Printed"), 5000)

    def show_register(self) -> None:
        from app.register_presenter import RegisterPresenter
        from widgets.register_window import RegisterWindow

        if getattr(self, "register_window", None) is None:
            self.register_window = RegisterWindow(self)
            self.register_presenter = RegisterPresenter(self.register_window, self.certificates,
                                                        self.projects.open_project_state)
            self.register_window.subscribe(self.register_presenter)
            # the statuses, revisions and headings in the language chosen later too
            on_language_change(self.register_window, self.register_presenter.refresh)
        self.register_presenter.refresh()
        self.register_window.show()
        self.register_window.raise_()

    def send_to_positioning(self) -> bool:
        """The current run, as readings of the positioning workbench (one undo step there)."""
        source = self.current
        target = next((p for p in self.presenters if p.kind.key == "positioning"), None)
        if target is None or source is target or source.kind.positioning_rows is None:
            self.tell(tr("Cannot send"), tr("{workbench} has nothing to send to the "
                                            "positioning workbench.").format(
                workbench=declared(source.kind.title)))
            return False
        if source.result is None:
            problem = source.problem or tr("no readings have been analysed yet")
            self.tell(tr("Nothing to send"), f"{declared(source.kind.title)}: {problem}.")
            return False
        rows = source.kind.positioning_rows(source.result)
        target.table_model.replace_all(rows, f"From {source.kind.title}", checked=True)
        target.set_settings({**target.settings, "target_unit": "deg", "deviation_unit": "arcsec"})
        target.refresh()
        self.tabs.setCurrentIndex(self.presenters.index(target))
        self.statusBar().showMessage(
            tr("{workbench}: {rows} readings sent (deviation = −corrected error); Edit › Undo "
               "restores the positioning readings").format(workbench=declared(source.kind.title),
                                                           rows=len(rows)), 8000)
        return True

    def _on_tab_changed_send(self, index: int) -> None:
        presenter = self.presenters[index] if 0 <= index < len(self.presenters) else None
        self.send_action.setEnabled(presenter is not None
                                    and presenter.kind.positioning_rows is not None)

    def load_all_samples(self) -> None:
        for presenter in self.presenters:
            presenter.load_sample()
        self.projects.update_title()
        self.statusBar().showMessage(tr("Bundled samples loaded in every workbench"), 8000)

    # -- certificates: the CertificatePresenter decides, its CertificateDialogs show ----
    def _current_result(self):
        presenter = self.current
        if presenter.result is None:
            problem = presenter.problem or tr("no readings have been analysed yet")
            self.tell(tr("Nothing to export"), f"{declared(presenter.kind.title)}: {problem}.")
            return None
        return presenter.result

    def _source_name(self) -> str:
        return self.projects.path.name if self.projects.path else "readings typed in AngleBench"

    def export_certificate(self) -> bool:
        result = self._current_result()
        return result is not None and self.certificates.export_certificate(
            self.current.kind, result, self.current.settings, self._source_name(),
            self.current.state().rows)

    def export_results(self) -> bool:
        result = self._current_result()
        return result is not None and self.certificates.export_results(
            self.current.kind, result, self.current.settings, self._source_name(),
            self.current.angle_unit)

    def closeEvent(self, event: QCloseEvent) -> None:  # noqa: N802
        if not self.projects.confirm_discard():
            event.ignore()
            return
        self.qsettings.setValue("window/geometry", self.saveGeometry())
        self.qsettings.setValue("window/state", self.saveState())
        self.qsettings.setValue("window/tab", self.tabs.currentIndex())
        self.capture_panel.disconnect_instrument()
        self.projects.close()
        event.accept()

    # -- settings -----------------------------------------------------------------
    def _restore_window_state(self) -> None:
        geometry = self.qsettings.value("window/geometry")
        if isinstance(geometry, QByteArray):
            self.restoreGeometry(geometry)
        state = self.qsettings.value("window/state")
        if isinstance(state, QByteArray):
            self.restoreState(state)
        tab = self.qsettings.value("window/tab", 0)
        with contextlib.suppress(TypeError, ValueError):
            self.tabs.setCurrentIndex(int(tab))

    def show_about(self) -> None:
        QMessageBox.about(
            self, tr("About AngleBench"),
            f"<b>AngleBench {__version__}</b><br>" + tr("Angle metrology workbench.") + "<br><br>"
            f"Qt {qVersion()}, PySide6 {pyside_version}, pyqtgraph {pg.__version__}, "
            f"numpy {np.__version__}, scipy {scipy.__version__}")

