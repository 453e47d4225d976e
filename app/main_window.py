"""Main window: one tab per workbench, composed with the presenters that decide — the
project's (files, recent files, autosave, recovery: app/project_presenter.py) and the
certificates' (app/certificate_presenter.py) — their window sides (app/project_dialogs.py,
app/certificate_dialogs.py) and the menus (app/main_menus.py). The window itself keeps
its state between runs, the language and angle unit, importing, printing, the register
and sending a run to the positioning workbench."""

from __future__ import annotations

import contextlib
import logging
from pathlib import Path

import numpy as np
import pyqtgraph as pg
import scipy
from PySide6 import __version__ as pyside_version
from PySide6.QtCore import QByteArray, QSettings, Qt, qVersion
from PySide6.QtGui import QCloseEvent, QUndoGroup
from PySide6.QtWidgets import (
    QApplication,
    QDialog,
    QLabel,
    QMainWindow,
    QMessageBox,
    QTabWidget,
    QWidget,
)

from app.certificate_dialogs import CertificateDialogs
from app.certificate_issue import readings_stated
from app.certificate_presenter import CertificatePresenter
from app.main_menus import MainMenus
from app.project_dialogs import ProjectDialogs
from app.project_presenter import ProjectPresenter, default_recovery_store
from app.reference_sender import (
    check_sent_references,
    sent_reference_source,
    watch_sent_references,
)
from app.run_overlay_actions import RunOverlayActions
from models import __version__
from models.certificate.readings_origin import (
    TYPED,
    ReadingsStatement,
    SentFrom,
    captured_rows,
    source_stated,
)
from models.display_units import ANGLE_UNITS, AngleUnit
from models.project.recovery import RecoveryStore
from models.readings.tabular_import import TableImportError
from models.registry import KINDS, presenter_class
from models.workbench import AcceptsRuns, JudgesSignals, SendsRuns
from widgets.fonts import ensure_cjk_font
from widgets.i18n import (
    declared,
    explained,
    install_language,
    on_language_change,
    resolve_language,
    tr,
    translated,
)
from widgets.open_file import ask_open_file
from widgets.screen_fit import fit_to_screen
from widgets.status_line import StatusLine
from widgets.text_dialog import TextDialog
from widgets.workbench_presenter import SAMPLES_DIR, WorkbenchPresenter

log = logging.getLogger(__name__)

LANGUAGE_SETTING = "ui/language"  # "system", "en" or "zh_CN" (widgets/i18n.py)
ANGLE_UNIT_SETTING = "display/angle_unit"  # the unit results are read in, for every workbench


def default_presenters() -> list[WorkbenchPresenter]:
    """One presenter per registered workbench, in the registry's order."""
    return [presenter_class(kind)() for kind in KINDS.values()]


class _SheetRows:
    """A sheet's rows as a sequence of lists of text, read when asked (not copied)."""

    def __init__(self, sheet) -> None:
        self.sheet = sheet

    def __len__(self) -> int:
        return self.sheet.row_count

    def __getitem__(self, row: int) -> list[str]:
        return [self.sheet.text(row, c) for c in range(self.sheet.column_count)]


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
        self.certificates.open_project_path = lambda: self.projects.path
        self.projects.refuse_issued = self.certificates.refuse_issued  # issued files (rev64 F1)
        # the details an issue stored in the project: said so on closing (gui78)
        self.certificates.details_issued = self.projects.details_issued
        self.imported_files: list[str] = []  # inputs: no export may replace them
        self.certificates.inputs = lambda: list(self.imported_files)
        # the test plans are saved with the lab defaults; a new project starts with them
        self.certificates.workbench_settings = lambda key: self.presenter(key).settings
        self.projects.new_settings = self.certificates.test_plan
        # a pending Amend…/Replace… ends when another project is opened (rev62 F1)
        self.projects.project_replaced = self.certificates.end_revision
        # … and is shown until it is issued or ended: in the title and the status bar (rev62 F3)
        self.projects.title_note = self.certificates.pending_words
        self.certificates.revision_changed = self._show_revision
        # the plots' tolerance band and U band: from the details the certificate would use
        for presenter in self.presenters:
            presenter.certificate_details = (
                lambda key=presenter.kind.key: self.certificates.stored_details(key))
        # the details change no figure of the result, only the bands drawn with it: redrawn,
        # not analysed again (a new analysis would leave the result not yet current and hold
        # back the next export while capturing or on a large sheet)
        self.certificates.details_changed = lambda key: self.presenter(key).schedule_redraw()
        # a reference sent from one workbench to another is said when its source changes
        watch_sent_references(self)
        self.certificates.lab_defaults_changed = lambda: [
            p.schedule_redraw() for p in self.presenters]  # every workbench's details change
        for presenter in self.presenters:  # a polygon read from its DCC joins the standards
            if hasattr(presenter, "dcc_schema_dir"):  # a DCC read is validated against it
                presenter.dcc_schema_dir = self._dcc_schema_dir
            if hasattr(presenter, "dcc_register_url"):  # the lab's own DCC checked against it
                presenter.dcc_register_url = self.certificates.register_url
            if hasattr(presenter, "dcc_trusted_certificate"):  # its signature checked against it
                presenter.dcc_trusted_certificate = (
                    lambda: self.certificates.dcc_signing_paths()[2])
            if hasattr(presenter, "issue_details"):  # what it writes as its certificate states
                presenter.issue_details = (
                    lambda key=presenter.kind.key: self.certificates.issue_details(key))
            if hasattr(presenter, "reference_standard_found"):
                presenter.reference_standard_found = (
                    lambda reference, key=presenter.kind.key: (
                        self.certificates.add_polygon_standard(key, reference)))
            if hasattr(presenter, "reference_standard_checked"):  # before the DCC is applied
                presenter.reference_standard_checked = (
                    lambda reference, key=presenter.kind.key: (
                        self.certificates.polygon_standard_placed(key, reference)[1]))
        for presenter in self.presenters:  # the table exports spare them too
            presenter.protected_outputs = self.certificates.protected
            presenter.refuse_issued = self.certificates.refuse_issued  # issued files (rev63 F6)
        ensure_cjk_font()  # Chinese names and readings are never boxes
        self.language = install_language(str(self.qsettings.value(LANGUAGE_SETTING, "system")))
        self.certificates.default_language = "zh" if self.language == "zh_CN" else "en"
        self._setup_ui()
        self.run_overlays = RunOverlayActions(self)
        self.menus = MainMenus(self)
        self.menus.check(self.menus.language_actions,
                         str(self.qsettings.value(LANGUAGE_SETTING, "system")))
        saved = str(self.qsettings.value(ANGLE_UNIT_SETTING, "arcsec"))
        self.set_angle_unit(ANGLE_UNITS.get(saved, ANGLE_UNITS["arcsec"]))
        on_language_change(self, self._retranslate)
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
            presenter.imported.connect(
                lambda path, rows, p=presenter: self._on_imported(path, rows, p))
        self.tabs.currentChanged.connect(self._on_tab_changed)
        self.setAcceptDrops(True)
        self._on_tab_changed(0)
        self.setCentralWidget(self.tabs)
        # its message said again in the new language after a switch (widgets/status_line.py)
        self.setStatusBar(StatusLine(self))
        self.statusBar().showMessage(tr("Ready"))
        # the pending Amend…/Replace…, in sight until it is issued or ended (rev62 F3)
        self.revision_label = QLabel()
        self.revision_label.setObjectName("pending_revision")
        self.revision_label.setStyleSheet(
            "QLabel { background: #fff3c4; color: #5a4500; padding: 1px 6px; "
            "border: 1px solid #d9b600; border-radius: 3px; font-weight: bold; }")
        self.revision_label.hide()
        self.statusBar().addPermanentWidget(self.revision_label)
        fit_to_screen(self, 1400, 900)
        # readings from the instruments (#34): the panel, hidden until Instrument › Connect…
        from app.capture.panel import CapturePanel

        self.capture_panel = CapturePanel(self)
        self.addDockWidget(Qt.DockWidgetArea.RightDockWidgetArea, self.capture_panel)
        self.capture_panel.hide()
        # its raw frames go with the project
        self.projects.raw_capture = self.capture_panel.raw_capture
        self.projects.load_raw_capture = self._load_raw_capture
        # the live signals of a read head being mounted (#45): stream, demonstration, takes
        from app.capture.signal_live import attach_live_signals

        attach_live_signals(self)
        # a captured reading edited in the sheet since is marked there (issue 40)
        self._captured_values: dict = {}
        from models.capture.take_rows import TakeRows

        for presenter in self.presenters:
            # the takes follow their rows: inserted, deleted, replaced (review 61 F5)
            presenter.table_model.take_rows = TakeRows(
                lambda k=presenter.kind.key: self.capture_panel.takes_of(k))
            presenter.table_model.sheet_changed.connect(
                lambda p=presenter: self.mark_edited_readings(p))
            # the sheet replaced (an import, a sample, File › New or Open): the take note
            # and a status message about its rows go with the rows (day review 64 P7)
            presenter.table_model.modelReset.connect(
                lambda p=presenter: self._sheet_replaced(p))

    def _sheet_replaced(self, presenter) -> None:
        self.capture_panel.sheet_replaced(presenter.kind.key)
        bar = self.statusBar()
        if isinstance(bar, StatusLine):
            bar.forget(presenter.view)

    def _load_raw_capture(self, raw: dict) -> None:
        self.capture_panel.load_raw_capture(raw)
        for presenter in self.presenters:
            self.mark_edited_readings(presenter)

    def mark_edited_readings(self, presenter) -> None:
        """Mark the cells of ``presenter``'s captured readings that differ now from what the
        instrument's frames give (app/certificate_issue.py says the same on the
        certificate)."""
        from app.certificate_issue import readings_edited_after_capture

        panel = getattr(self, "capture_panel", None)
        sessions = panel.raw_sessions(presenter.kind.key) if panel is not None else []
        if not sessions and not presenter.table_model.edited_cells:
            return
        sheet = presenter.sheet
        keys = [c.key for c in sheet.columns]
        edits = readings_edited_after_capture(presenter.kind, presenter.settings,
                                              _SheetRows(sheet), sessions,
                                              self._captured_values)
        presenter.table_model.set_edited_cells({  # a deleted row's reading is in no cell
            (e.row, keys.index(e.column)): e.text() for e in edits
            if e.in_sheet and e.column in keys})

    def set_language(self, choice: str) -> None:
        """The window in English or Chinese (or the system's language), at once: every text
        is set again and each result redrawn; readings, undo history and plots stay."""
        self.menus.check(self.menus.language_actions, choice)
        self.qsettings.setValue(LANGUAGE_SETTING, choice)
        self.language = resolve_language(choice)  # before the texts are set again in it
        self.certificates.default_language = "zh" if self.language == "zh_CN" else "en"
        install_language(choice)

    def _retranslate(self) -> None:
        self.menus.update_undo_actions()
        # the status line says its message again itself ("Ready" too: --language is set
        # after the window is made), widgets/status_line.py
        if self.manual is not None and self.manual.isVisible():  # the page in the new language
            self.manual.show_page(self.current.kind.key, self.language)
        for index, presenter in enumerate(self.presenters):
            self.tabs.setTabText(index, declared(presenter.kind.title))
        self._show_revision()

    def _show_revision(self) -> None:
        """The pending amendment or replacement in the title and the status bar."""
        words = self.certificates.pending_words()
        label = getattr(self, "revision_label", None)
        if label is not None:
            pending = self.certificates.pending
            label.setText(words)
            label.setToolTip(tr(
                "The next certificate exported from the {workbench} workbench issues this; "
                "it ends when issued, or when another project is opened.").format(
                    workbench=declared(KINDS[pending.workbench].title))
                if pending is not None and pending.workbench in KINDS else "")
            label.setVisible(bool(words))
        self.projects.update_title()

    def set_angle_unit(self, unit: AngleUnit) -> None:
        """Results in ``unit`` on every workbench (redrawn, not re-analysed); remembered."""
        self.menus.check(self.menus.angle_unit_actions, unit.key)
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
        TextDialog(tr("AngleBench — quick guide"), tr(
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
            "import it."), self).exec()

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
            # a message about another workbench's readings is that workbench's
            bar = self.statusBar()
            if isinstance(bar, StatusLine):
                bar.show_workbench(self.presenters[index].view)

    def show_workbench_status(self, presenter, text: str, timeout: int) -> None:
        """A message about ``presenter``'s readings: shown while its tab is in front (put
        aside on another tab's, widgets/status_line.py), gone when its sheet is replaced."""
        bar = self.statusBar()
        if isinstance(bar, StatusLine):
            bar.show_about(text, timeout, presenter.view)
            if presenter is not self.current:  # read in while another tab is in front
                bar.show_workbench(self.current.view)
        else:
            bar.showMessage(text, timeout)

    # -- dialogs (tests replace these) --------------------------------------------
    def tell(self, title: str, text: str) -> None:
        self.statusBar().showMessage(text, 15000)
        QMessageBox.warning(self, title, text)

    def ask(self, title: str, text: str, buttons, default):
        return QMessageBox.question(self, title, text, buttons, default)

    def import_dialog(self) -> None:
        path = ask_open_file(
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
        self.show_workbench_status(
            presenter, tr("Imported {path} (Edit › Undo restores the old readings)").format(
                path=path), 8000)
        return True

    def _on_import_failed(self, message: str) -> None:
        self.tell(tr("Cannot import"), message)

    def _on_imported(self, path: str, rows: int, presenter=None) -> None:
        """Say that it worked (and replace an earlier error at once), as a message of the
        workbench it was imported into (``presenter``; None: the one in front)."""
        if path not in self.imported_files:
            self.imported_files.append(path)
        self.show_workbench_status(
            presenter or self.current,
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
        self.current.import_file(SAMPLES_DIR / self.current.kind.sample_file, sample=True)

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
                        + self._source_shown())
        self.statusBar().showMessage(tr("Printed"), 5000)

    def _dcc_schema_dir(self) -> str:
        """The DCC schema folder set (the environment's, else the certificate details'):
        a DCC read in (a polygon's) is validated against it; "" none."""
        from app.dcc_issue import dcc_schema_dir

        return dcc_schema_dir(configured=self.certificates.dcc_options()[1])

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
        target = next((p for p in self.presenters if isinstance(p.kind, AcceptsRuns)), None)
        if target is None or source is target or not isinstance(source.kind, SendsRuns):
            self.tell(tr("Cannot send"), tr("{workbench} has nothing to send to the "
                                            "positioning workbench.").format(
                workbench=declared(source.kind.title)))
            return False
        if not self.result_is_current(source, sending=True):
            return False
        if source.result is None:
            problem = (translated(source.problem) if source.problem else
                       tr("no readings have been analysed yet"))
            self.tell(tr("Nothing to send"), tr("{workbench}: {problem}.").format(
                workbench=declared(source.kind.title), problem=problem))
            return False
        rows = source.kind.run_rows(source.result)
        # the positioning certificate says where these readings came from: the sending
        # workbench and its own "Readings:" line (day review 66: "readings typed in
        # AngleBench" was said of them)
        # (day review 67 F3: and what that line was made of, which a project file keeps, so
        # that a certificate words it in its own language after the project is opened again)
        sent = SentFrom(source.kind.title, self._readings_line(source), self._statement(source))
        target.table_model.replace_all(rows, f"From {source.kind.title}", checked=True,
                                       origin=sent)
        target.set_settings(target.kind.settings_for_runs(target.settings))
        target.refresh()
        self.tabs.setCurrentIndex(self.presenters.index(target))
        self.statusBar().showMessage(
            tr("{workbench}: {rows} readings sent (deviation = −corrected error); Edit › Undo "
               "restores the positioning readings").format(workbench=declared(source.kind.title),
                                                           rows=len(rows)), 8000)
        return True

    def load_all_samples(self) -> None:
        for presenter in self.presenters:
            presenter.load_sample()
        self.projects.update_title()
        self.statusBar().showMessage(tr("Bundled samples loaded in every workbench"), 8000)

    # -- certificates: the CertificatePresenter decides, its CertificateDialogs show ----
    def _current_result(self):
        """The result of the workbench in front, when it is the analysis of the readings
        and settings it holds now (an edit still waiting is analysed first); None, told
        why, otherwise: a certificate is never issued from a result older than the
        readings it records, nor results exported from one (#39)."""
        presenter = self.current
        if not self.result_is_current(presenter):
            return None
        if presenter.result is None:
            problem = (translated(presenter.problem) if presenter.problem else
                       tr("no readings have been analysed yet"))
            self.tell(tr("Nothing to export"), tr("{workbench}: {problem}.").format(
                workbench=declared(presenter.kind.title), problem=problem))
            return None
        return presenter.result

    def result_is_current(self, presenter, sending: bool = False) -> bool:
        """Whether ``presenter``'s result is the analysis of the readings and settings it
        holds now (an edit still waiting is analysed first); told why not: nothing is
        exported, nor sent to another workbench, from a result older than its readings."""
        if presenter.analyse_if_due():
            return True
        if sending:
            text = (tr("The readings are still being read from the file; send again when "
                       "their result is shown.") if presenter.reading_file else
                    tr("The latest readings are still being analysed; send again when their "
                       "result is shown."))
            self.tell(tr("Not sent yet"), text)
            return False
        text = (tr("The readings are still being read from the file; export again when "
                   "their result is shown.") if presenter.reading_file else
                tr("The latest readings are still being analysed; export again when their "
                   "result is shown."))
        self.tell(tr("Not exported yet"), text)
        return False

    def _source_name(self, presenter=None) -> str:
        """The certificate's source of the readings of ``presenter`` (the one in front when
        None): the project's file; else the file they were imported from or the bundled
        sample (day review 65 F4: "readings typed in AngleBench" was said of them), pasted
        or sent from another workbench, and the rows pasted (day review 66); else, a
        certificate's project from the register, its readings' source as it named it;
        else typed. A project saved under a name is named, with where its readings came
        from when that is known (day review 67: saved, opened again or recovered after a
        crash, they were the project's, or typed)."""
        return source_stated(self._statement(presenter or self.current, captured=False))

    def _statement(self, presenter, captured: bool = True) -> ReadingsStatement:
        """What the "Readings:" line of ``presenter``'s readings is made of (models/
        certificate/readings_origin.ReadingsStatement): where the sheet's rows came from,
        the project file they are in and whether they were changed since it was saved or
        recovered (day review 67 F4: the file was named as the source of readings it does
        not hold), and (``captured``) the analysed rows taken from the instruments."""
        origin, edited, pasted, count = presenter.table_model.readings_origin()
        project = self.projects.path.name if self.projects.path else ""
        taken: tuple[int, ...] = ()
        if captured:
            key = presenter.kind.key
            taken = tuple(captured_rows(self.capture_panel.raw_sessions(key),
                                        presenter.result_state().rows, key))
        return ReadingsStatement(origin, edited, tuple(pasted), count, taken, project,
                                 bool(project) and presenter.readings_unsaved(),
                                 "" if project else self.projects.readings_source or "")

    def _readings_line(self, presenter) -> str:
        """The "Readings:" line a certificate of ``presenter``'s analysed readings would
        print: their source and the rows captured from the instruments."""
        key = presenter.kind.key
        return readings_stated(key, self._source_name(presenter), presenter.result_state().rows,
                               self.capture_panel.raw_sessions(key), presenter.kind.columns,
                               presenter.result)[0]

    def _source_shown(self) -> str:
        """:meth:`_source_name` in the window's language."""
        source = self._source_name()
        return tr("readings typed in AngleBench") if source == TYPED else translated(source)

    def export_certificate(self) -> bool:
        # the readings and settings the result was analysed from, not the sheet's and the
        # form's: the certificate states what it computed with, and the register records
        # the readings that give its figures
        result = self._current_result()
        if result is None or not self._sent_reference_current():
            return False
        analysed = self.current.result_state()
        issued = self.certificates.export_certificate(
            self.current.kind, result, analysed.settings, self._source_name(),
            analysed.rows, self.capture_panel.raw_sessions(self.current.kind.key))
        # the register window open beside shows the record issued (rev62 F11: only once
        # closed and opened again)
        if issued and getattr(self, "register_window", None) is not None \
                and self.register_window.isVisible():
            self.register_presenter.refresh(self.register_presenter.search)
        return issued

    def _sent_reference_current(self) -> bool:
        """Whether the reference the workbench in front holds, sent from another workbench
        (File › Send as reference), is what its source would send now; told why not. No
        certificate is issued on a stale reference column (day review 64 P2): the
        technician sends it again (the notice's *Send again*) or loads the reference's own
        certificate, and exports then."""
        source = sent_reference_source(self, self.current)
        if source is None:
            return True
        if not self.result_is_current(source):  # an edit there still being analysed
            return False
        check_sent_references(self)
        notice = self.current.view.reference_notice
        if not notice.stale:
            return True
        self.tell(tr("Reference not current"), tr(
            "{workbench}: no certificate is issued on this reference column. {notice}").format(
            workbench=declared(self.current.kind.title), notice=notice.label.text()))
        return False

    def export_results(self) -> bool:
        result = self._current_result()
        if result is None:
            return False
        # the readings the result was analysed from, and the instrument's sessions behind
        # them: the results say which rows were captured (day review 64 P8)
        return self.certificates.export_results(
            self.current.kind, result, self.current.result_settings, self._source_name(),
            self.current.angle_unit, self.current.result_state().rows,
            self.capture_panel.raw_sessions(self.current.kind.key))

    def closeEvent(self, event: QCloseEvent) -> None:  # noqa: N802
        for presenter in self.presenters:  # a value still being typed is work to keep
            table = getattr(getattr(presenter, "view", None), "table", None)
            if hasattr(table, "enter_typed"):
                table.enter_typed()
        try:
            let_go = self.projects.confirm_discard()
        except Exception as exc:  # noqa: BLE001 - the close event comes accepted: an exception
            # here closed the window with the work in no file
            log.exception("closing: the unsaved work could not be saved")
            self.tell(tr("Cannot save"), tr("The project could not be saved ({reason}). The "
                                             "window stays open with your readings.")
                      .format(reason=explained(exc) or type(exc).__name__))
            let_go = False
        if not let_go:
            event.ignore()
            return
        self.capture_panel.remember_open()
        self.qsettings.setValue("window/geometry", self.saveGeometry())
        self.qsettings.setValue("window/state", self.saveState())
        self.qsettings.setValue("window/tab", self.tabs.currentIndex())
        self.capture_panel.disconnect_instrument()
        for presenter in self.presenters:
            if isinstance(presenter.kind, JudgesSignals):  # its view_needs: the panel
                presenter.view.live_signals.disconnect_stream()
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
        # the instrument panel open only on the workbenches it was open on, not every tab
        self.capture_panel.restore_open()

    def show_about(self) -> None:
        QMessageBox.about(
            self, tr("About AngleBench"),
            f"<b>AngleBench {__version__}</b><br>" + tr("Angle metrology workbench.") + "<br><br>"
            f"Qt {qVersion()}, PySide6 {pyside_version}, pyqtgraph {pg.__version__}, "
            f"numpy {np.__version__}, scipy {scipy.__version__}")

