"""Main window: one tab per workbench, the File/Edit/Help menus, project files,
autosave and crash recovery, persisted window state and recent files."""

from __future__ import annotations

import contextlib
import logging
import os
import re
import threading
import time
from pathlib import Path

import numpy as np
import pyqtgraph as pg
import scipy
from PySide6 import __version__ as pyside_version
from PySide6.QtCore import QByteArray, QSettings, QStandardPaths, Qt, QTimer, qVersion
from PySide6.QtGui import QAction, QActionGroup, QCloseEvent, QKeySequence, QUndoGroup
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QFileDialog,
    QInputDialog,
    QMainWindow,
    QMenu,
    QMessageBox,
    QTabWidget,
    QWidget,
)

from app.certificate_presenter import CertificatePresenter
from app.run_overlay_actions import RunOverlayActions
from models import __version__
from models.certificate.metadata import CertificateMetadata
from models.display_units import ANGLE_UNITS, AngleUnit
from models.project.file import (
    Project,
    ProjectFileError,
    WorkbenchState,
    check_project,
    load_project,
    project_from_json,
    save_project,
)
from models.project.recovery import RecoveryStore
from models.readings.tabular_import import TableImportError
from models.registry import KINDS, presenter_class
from models.workbench import AcceptsRuns, SendsRuns
from widgets.certificate_dialog import CertificateDialog
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
from widgets.workers import cyclic_gc_paused, gui_thread_first, wait_while_analysing

log = logging.getLogger(__name__)

LANGUAGE_SETTING = "ui/language"  # "system", "en" or "zh_CN" (widgets/i18n.py)
AUTOSAVE_DELAY_MS = 3_000  # an edit is autosaved this soon (at most every 3 s while typing)
AUTOSAVE_THREAD_ROWS = 50_000  # sheets larger than this are autosaved off the GUI thread …
AUTOSAVE_DELAY_LARGE_MS = 20_000  # … and less often
MAX_RECENT = 8
ANGLE_UNIT_SETTING = "display/angle_unit"  # the unit results are read in, for every workbench


def with_chosen_suffix(path: str, chosen_filter: str) -> str:
    """A name typed without an extension gets the one of the file type chosen in the dialog
    ("Excel workbook (*.xlsx)" writes out.xlsx, not a CSV named "out")."""
    if not path or Path(path).suffix:
        return path
    match = re.search(r"\*(\.[A-Za-z0-9]+)", chosen_filter or "")
    return path + match.group(1) if match else path


def default_presenters() -> list[WorkbenchPresenter]:
    """One presenter per registered workbench, in the registry's order."""
    return [presenter_class(kind)() for kind in KINDS.values()]


def default_recovery_store() -> RecoveryStore:
    folder = os.environ.get("ANGLEBENCH_DATA_DIR") or QStandardPaths.writableLocation(
        QStandardPaths.StandardLocation.AppDataLocation)
    return RecoveryStore(Path(folder or Path.home() / ".anglebench"))


class MainWindow(QMainWindow):
    """Holds the workbench presenters; all dialogs go through ``ask``/``tell`` so tests can
    answer them."""

    def __init__(self, settings: QSettings | None = None, recovery: RecoveryStore | None = None,
                 presenters: list[WorkbenchPresenter] | None = None, parent=None) -> None:
        super().__init__(parent)
        self.qsettings = settings or QSettings("AngleBench", "AngleBench")
        self.recovery = recovery or default_recovery_store()
        self.presenters = presenters or default_presenters()
        self.project_path: Path | None = None
        self.project_metadata: dict = {}
        self.manual = None  # the manual's window, made when first asked for (F1)
        self.certificates = CertificatePresenter(self, self.qsettings, lambda: self.project_metadata,
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
        self.autosave_timer = QTimer(self)
        self.autosave_timer.setSingleShot(True)
        self.autosave_timer.setInterval(AUTOSAVE_DELAY_MS)
        self.autosave_timer.timeout.connect(self._autosave_when_due)
        self._unsaved_since = 0.0  # time.monotonic() of the first edit not yet autosaved
        self._autosave_thread: threading.Thread | None = None
        for presenter in self.presenters:
            presenter.undo_stack.indexChanged.connect(self._schedule_autosave)
            presenter.modified_changed.connect(self._schedule_autosave)
        try:
            self.recovery.claim()
        except OSError as exc:
            self.statusBar().showMessage(tr("Autosave is off: {reason}").format(reason=exc), 15000)
        self._update_title()

    # -- construction ---------------------------------------------------------
    def _setup_ui(self) -> None:
        self.tabs = QTabWidget()
        self.undo_group = QUndoGroup(self)
        for presenter in self.presenters:
            self.tabs.addTab(presenter.view, declared(presenter.kind.title))
            self.undo_group.addStack(presenter.undo_stack)
            presenter.import_failed.connect(self._on_import_failed)
            presenter.imported.connect(self._on_imported)
            presenter.modified_changed.connect(self._on_modified_changed)
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
        self.new_action = self._action(file_menu, tr("&New"), self.new_project, QKeySequence.StandardKey.New)
        self.open_action = self._action(file_menu, tr("&Open…"), self.open_project_dialog,
                                        QKeySequence.StandardKey.Open)
        self.recent_menu = self._menu(file_menu, tr("Open &recent"))
        self.save_action = self._action(file_menu, tr("&Save"), self.save, QKeySequence.StandardKey.Save)
        self.save_as_action = self._action(file_menu, tr("Save &as…"), self.save_as,
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
        self._refresh_recent_menu()

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
        self._update_title()

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

    # -- project ----------------------------------------------------------------
    @property
    def is_modified(self) -> bool:
        return any(p.is_modified for p in self.presenters)

    def project(self) -> Project:
        return Project({p.kind.key: p.state() for p in self.presenters}, dict(self.project_metadata))

    def apply_project(self, project: Project) -> None:
        for presenter in self.presenters:
            presenter.load_state(project.workbenches.get(presenter.kind.key, WorkbenchState()))
        self.project_metadata = dict(project.metadata)
        self.project_metadata.pop("autosaved_at", None)
        self.project_metadata.pop("project_path", None)

    def _on_modified_changed(self, _modified: bool) -> None:
        self._update_title()

    def _update_title(self) -> None:
        name = self.project_path.name if self.project_path else tr("untitled")
        self.setWindowTitle(f"AngleBench {__version__} — {name}{' *' if self.is_modified else ''}")

    def _confirm_discard(self) -> bool:
        if not self.is_modified:
            return True
        answer = self.ask(tr("Unsaved readings"), tr("Save the changes to the project first?"),
                          QMessageBox.StandardButton.Save | QMessageBox.StandardButton.Discard
                          | QMessageBox.StandardButton.Cancel, QMessageBox.StandardButton.Save)
        if answer == QMessageBox.StandardButton.Save:
            return self.save()
        return answer == QMessageBox.StandardButton.Discard

    def new_project(self) -> None:
        if not self._confirm_discard():
            return
        self.apply_project(Project())
        self.project_path = None
        self._update_title()

    def open_project_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, tr("Open project"), self._last_dir(),
                                              tr("AngleBench project (*.anglebench.json *.json)"))
        if path:
            self.open_project(path)

    def open_project(self, path: str | Path) -> bool:
        """Open a project; a damaged or newer file leaves the current work untouched."""
        if not self._confirm_discard():
            return False
        try:
            project = load_project(path)
            check_project(project, {p.kind.key: p.kind for p in self.presenters}, str(path))
        except ProjectFileError as exc:
            self.tell(tr("Cannot open project"),
                      tr("{reason}. Your current work is as it was.").format(reason=exc))
            return False
        self.apply_project(project)
        self.project_path = Path(path)
        self._add_recent(self.project_path)
        self._update_title()
        self.statusBar().showMessage(tr("Opened {path}").format(path=path), 5000)
        return True

    def save(self) -> bool:
        if self.project_path is None:
            return self.save_as()
        return self.save_to(self.project_path)

    def save_as(self) -> bool:
        path, _ = QFileDialog.getSaveFileName(self, tr("Save project"), self._last_dir(),
                                              tr("AngleBench project (*.anglebench.json *.json)"))
        if not path:
            return False
        if not path.endswith(".json"):
            path += ".anglebench.json"
        return self.save_to(path)

    def save_to(self, path: str | Path) -> bool:
        try:
            save_project(path, self.project())
        except OSError as exc:
            self.tell(tr("Cannot save"), tr("{path}: {reason}. Your readings are still here.")
                      .format(path=path, reason=exc.strerror or exc))
            return False
        self.project_path = Path(path)
        for presenter in self.presenters:
            presenter.mark_saved()
        self.recovery.discard()
        self._add_recent(self.project_path)
        self._update_title()
        self.statusBar().showMessage(tr("Saved {path}").format(path=path), 5000)
        return True

    def import_dialog(self) -> None:
        path, _ = QFileDialog.getOpenFileName(
            self, tr("Import readings into {workbench}").format(
                workbench=declared(self.current.kind.title)), self._last_dir(),
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

    # -- dropping files on the window -------------------------------------------------
    DROPPABLE = (".csv", ".txt", ".tsv", ".xlsx", ".xlsm", ".json")

    def _dropped_paths(self, mime) -> list[str]:
        return [u.toLocalFile() for u in mime.urls()
                if u.isLocalFile() and u.toLocalFile().lower().endswith(self.DROPPABLE)]

    def dragEnterEvent(self, event) -> None:  # noqa: N802 - Qt's name
        if event.mimeData().hasUrls() and self._dropped_paths(event.mimeData()):
            event.acceptProposedAction()

    def dropEvent(self, event) -> None:  # noqa: N802 - Qt's name
        """A readings file goes into the current workbench (one undo step); a project file
        opens (asking about unsaved work)."""
        paths = self._dropped_paths(event.mimeData())
        if not paths:
            return
        event.acceptProposedAction()
        path = paths[0]
        if path.lower().endswith(".json"):
            self.open_project(path)
        else:
            self.current.start_import(path)

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
                        + (self.project_path.name if self.project_path
                           else tr("readings typed in AngleBench")))
        self.statusBar().showMessage(tr("Printed"), 5000)

    def show_register(self) -> None:
        from app.register_presenter import RegisterPresenter
        from widgets.register_window import RegisterWindow

        if getattr(self, "register_window", None) is None:
            self.register_window = RegisterWindow(self)
            self.register_presenter = RegisterPresenter(self.register_window, self.certificates,
                                                        self.open_project_state)
            self.register_window.subscribe(self.register_presenter)
            # the statuses, revisions and headings in the language chosen later too
            on_language_change(self.register_window, self.register_presenter.refresh)
        self.register_presenter.refresh()
        self.register_window.show()
        self.register_window.raise_()

    def open_project_state(self, project_json: str, workbench: str) -> bool:
        """Load the project behind a certificate (asking about unsaved work first) and show its
        workbench; the project is untitled (saving it asks for a name)."""
        if not self._confirm_discard():
            return False
        try:
            project = project_from_json(project_json, "the register's record")
            check_project(project, {p.kind.key: p.kind for p in self.presenters},
                          "the register's record")
        except ProjectFileError as exc:
            self.tell(tr("Cannot open"), explained(exc))
            return False
        self.apply_project(project)
        self.project_path = None
        self.tabs.setCurrentIndex(next(i for i, p in enumerate(self.presenters)
                                       if p.kind.key == workbench))
        self._update_title()
        return True

    def send_to_positioning(self) -> bool:
        """The current run, as readings of the positioning workbench (one undo step there)."""
        source = self.current
        target = next((p for p in self.presenters if isinstance(p.kind, AcceptsRuns)), None)
        if target is None or source is target or not isinstance(source.kind, SendsRuns):
            self.tell(tr("Cannot send"), tr("{workbench} has nothing to send to the "
                                            "positioning workbench.").format(
                workbench=declared(source.kind.title)))
            return False
        if source.result is None:
            problem = source.problem or tr("no readings have been analysed yet")
            self.tell(tr("Nothing to send"), f"{declared(source.kind.title)}: {problem}.")
            return False
        rows = source.kind.run_rows(source.result)
        target.table_model.replace_all(rows, f"From {source.kind.title}", checked=True)
        target.set_settings(target.kind.settings_for_runs(target.settings))
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
                                    and isinstance(presenter.kind, SendsRuns))

    def load_all_samples(self) -> None:
        for presenter in self.presenters:
            presenter.load_sample()
        self._update_title()
        self.statusBar().showMessage(tr("Bundled samples loaded in every workbench"), 8000)

    # -- certificates -----------------------------------------------------------------
    # -- certificates: the CertificatePresenter decides, the window shows ----------------
    def lab_defaults(self) -> dict:
        return self.certificates.lab_defaults()

    def save_lab_defaults(self, defaults: dict) -> None:
        self.certificates.save_lab_defaults(defaults)

    def certificate_metadata(self, key: str | None = None) -> CertificateMetadata:
        return self.certificates.details(key or self.current.kind.key)

    def store_certificate_metadata(self, meta: CertificateMetadata, key: str | None = None) -> None:
        self.certificates.store_details(key or self.current.kind.key, meta)

    def edit_certificate_metadata(self, meta: CertificateMetadata) -> CertificateMetadata | None:
        return self.certificates.edit_details(meta)

    def edit_certificate_details(self, meta: CertificateMetadata, problems: dict[str, str],
                                 raw: dict) -> CertificateMetadata | None:
        """The certificate dialog (the presenter's view call)."""
        dialog = CertificateDialog(meta, self)
        dialog.lab_defaults_saved.connect(self.save_lab_defaults)
        if problems:  # a stored detail that no longer reads: shown as stored, marked
            dialog.show_problems(problems, raw)
        if dialog.exec() != QDialog.DialogCode.Accepted:
            return None
        return dialog.metadata()

    def confirm_draft(self, missing: list[str]) -> bool:
        answer = self.ask(
            tr("Export a draft?"),
            tr("These details are missing: {missing}. The PDF will be marked DRAFT, is not a "
               "certificate, and nothing is recorded in the register. Export the draft anyway?")
            .format(missing=", ".join(tr(m) for m in missing)),
            QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
            QMessageBox.StandardButton.No)
        return answer == QMessageBox.StandardButton.Yes

    def confirm_implausible(self, reason: str) -> bool:
        answer = self.ask(
            tr("Certify these figures?"),
            tr("{reason}\n\nIssue a certificate on this result anyway? Only if you have "
               "checked the readings and the figures are right.").format(reason=reason),
            QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
            QMessageBox.StandardButton.No)
        return answer == QMessageBox.StandardButton.Yes

    def ask_change_note(self, revision) -> str:
        question = (tr("This certificate replaces {number}. What changed, and why? (printed on "
                       "the certificate; ISO/IEC 17025 7.8.8)") if revision.replacement else
                    tr("This certificate amends {number}. What changed, and why? (printed on "
                       "the certificate; ISO/IEC 17025 7.8.8)"))
        text, ok = QInputDialog.getMultiLineText(self, tr("What changed"),
                                                 question.format(number=revision.number))
        return text if ok else ""

    def choose_save_path(self, title: str, suggested: str, file_filter: str) -> str:
        path, chosen = QFileDialog.getSaveFileName(self, title,
                                                   str(Path(self._last_dir()) / suggested),
                                                   file_filter)
        return with_chosen_suffix(path, chosen)

    def show_status(self, text: str, milliseconds: int) -> None:
        self.statusBar().showMessage(text, milliseconds)

    def wait_cursor(self, on: bool) -> None:
        if on:
            QApplication.setOverrideCursor(Qt.CursorShape.WaitCursor)
        else:
            QApplication.restoreOverrideCursor()

    def _current_result(self):
        presenter = self.current
        if presenter.result is None:
            problem = presenter.problem or tr("no readings have been analysed yet")
            self.tell(tr("Nothing to export"), f"{declared(presenter.kind.title)}: {problem}.")
            return None
        return presenter.result

    def _source_name(self) -> str:
        return self.project_path.name if self.project_path else "readings typed in AngleBench"

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

    # -- autosave and recovery ------------------------------------------------------
    def _rows(self) -> int:
        return sum(p.sheet.row_count for p in self.presenters)

    def _schedule_autosave(self, *_args) -> None:
        """An edit: autosave a few seconds from now (not later while typing goes on)."""
        if not self.autosave_timer.isActive():
            self._unsaved_since = time.monotonic()
            self.autosave_timer.start(self._autosave_delay_ms())

    def _autosave_delay_ms(self) -> int:
        return AUTOSAVE_DELAY_LARGE_MS if self._rows() > AUTOSAVE_THREAD_ROWS else AUTOSAVE_DELAY_MS

    def _autosave_when_due(self) -> None:
        """The timer's end: autosave, unless the sheets grew large since it was started (a
        file read after a setting changed); a large one waits its own longer delay, from
        the same first edit (why: BENCHMARKS.md, Notes)."""
        waited_ms = (time.monotonic() - self._unsaved_since) * 1000.0
        due_ms = self._autosave_delay_ms()
        if waited_ms < due_ms - 1.0:
            self.autosave_timer.start(int(due_ms - waited_ms) + 1)
            return
        self.autosave()

    def autosave(self) -> None:
        if not self.is_modified:
            return
        if self._rows() > AUTOSAVE_THREAD_ROWS:
            project = Project({p.kind.key: p.state(deep=False) for p in self.presenters},
                              dict(self.project_metadata))
            if self._autosave_thread is not None and self._autosave_thread.is_alive():
                self.autosave_timer.start()  # the last one is still writing: try again soon
                return
            self._autosave_thread = threading.Thread(
                target=self._write_recovery_in_background, args=(project,), daemon=True)
            self._autosave_thread.start()
        else:
            self._write_recovery(self.project())

    def _write_recovery_in_background(self, project: Project) -> None:
        # the window keeps the interpreter every 0.1 ms; a million new strings would start
        # full cyclic-GC passes that hold it for a few hundred ms (strings hold no cycles)
        with gui_thread_first(), cyclic_gc_paused():
            self._write_recovery(project, wait_while_analysing)

    def _write_recovery(self, project: Project, between_blocks=None) -> None:
        try:
            self.recovery.write(project, self.project_path, between_blocks)
        except OSError as exc:
            log.warning("autosave failed: %s", exc)

    def offer_recovery(self) -> bool:
        """If a window ended without saving, offer its autosaved work (newest first);
        another running window's autosave is never offered."""
        orphans = self.recovery.orphans()
        if not orphans:
            return False
        path = orphans[0]
        try:
            project = self.recovery.load(path)
        except ProjectFileError as exc:
            self.tell(tr("Cannot recover"),
                      tr("{reason} (the file was kept aside as damaged)").format(reason=exc))
            return False
        when = project.metadata.get("autosaved_at") or tr("an unknown time")
        source = project.metadata.get("project_path") or ""
        name = Path(source).name if source else tr("an untitled project")
        answer = self.ask(
            tr("Recover unsaved work"),
            tr("AngleBench did not close normally. Restore the unsaved readings of {name}, "
               "autosaved {when}?").format(name=name, when=when),
            QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
            QMessageBox.StandardButton.Yes)
        if answer != QMessageBox.StandardButton.Yes:
            kept = self.recovery.set_aside(path, "declined")
            self.statusBar().showMessage(tr("The autosave was kept aside: {path}").format(
                path=kept), 15000)
            return False
        self.apply_project(project)
        self.project_path = Path(source) if source else None
        for presenter in self.presenters:  # recovered work is unsaved work
            presenter.mark_modified()
        self.recovery.adopt(path)
        self.autosave()  # now this window's own autosave
        self._update_title()
        return True

    def closeEvent(self, event: QCloseEvent) -> None:  # noqa: N802
        if not self._confirm_discard():
            event.ignore()
            return
        self.qsettings.setValue("window/geometry", self.saveGeometry())
        self.qsettings.setValue("window/state", self.saveState())
        self.qsettings.setValue("window/tab", self.tabs.currentIndex())
        self.autosave_timer.stop()
        self.capture_panel.disconnect_instrument()
        if self._autosave_thread is not None:
            self._autosave_thread.join(timeout=30)
        self.recovery.release()
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

    def recent_files(self) -> list[str]:
        value = self.qsettings.value("recent_files", [])
        if isinstance(value, str):
            value = [value]
        return [str(v) for v in (value or [])]

    def _add_recent(self, path: Path) -> None:
        files = [str(path)] + [f for f in self.recent_files() if f != str(path)]
        self.qsettings.setValue("recent_files", files[:MAX_RECENT])
        self._refresh_recent_menu()

    def _refresh_recent_menu(self) -> None:
        self.recent_menu.clear()
        for path in self.recent_files():
            action = self.recent_menu.addAction(path)
            action.triggered.connect(lambda _checked=False, p=path: self.open_project(p))
        self.recent_menu.setEnabled(bool(self.recent_files()))

    def _last_dir(self) -> str:
        recent = self.recent_files()
        return str(Path(recent[0]).parent) if recent else str(Path.home())

    def show_about(self) -> None:
        QMessageBox.about(
            self, tr("About AngleBench"),
            f"<b>AngleBench {__version__}</b><br>" + tr("Angle metrology workbench.") + "<br><br>"
            f"Qt {qVersion()}, PySide6 {pyside_version}, pyqtgraph {pg.__version__}, "
            f"numpy {np.__version__}, scipy {scipy.__version__}")

