"""The presenter every workbench shares: owns the readings, runs the analysis on
every edit and pushes the result to its passive view."""

from __future__ import annotations

import gc
import logging
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
from PySide6.QtCore import QCoreApplication, QObject, QRunnable, QTimer, Signal
from PySide6.QtGui import QUndoStack

from models.cancellation import AnalysisCancelled, cancellable, checkpoint
from models.capture.take_cells import waiting_row
from models.certificate.readings_origin import ImportedFrom, sheet_source
from models.certificate.stored_origin import origin_record, stored_origin
from models.display_units import (
    ANGLE_UNITS,
    AngleUnit,
    decimals_in_unit,
    figure_in_unit,
    figures_in_unit,
    header_in_unit,
    in_unit,
)
from models.messages import reason_of
from models.project.file import WorkbenchState, file_sha256
from models.readings.entry_plan import EntryPlan, Placement
from models.readings.incomplete import (
    RowInProgress,
    row_in_progress,
    typing_row,
    without_waiting_rows,
)
from models.readings.numeric_csv import read_numeric
from models.readings.sheet import NumericRows, ParsedReadings, ReadingsSheet
from models.readings.tabular_import import (
    MissingColumnError,
    TableImportError,
    map_columns,
    read_table,
)
from models.workbench import IssuesCertificates, ShowsHeadline, Workbench
from widgets.i18n import (
    Said,
    application_language,
    declared,
    explained,
    joined,
    on_language_change,
    tr,
    translated,
)
from widgets.readings_table_model import ReadingsTableModel
from widgets.table_commands import SettingsCommand
from widgets.workbench_view import WorkbenchView
from widgets.workers import Workers, application_workers, emit_if_alive

log = logging.getLogger(__name__)

SAMPLES_DIR = Path(__file__).resolve().parent.parent / "resources" / "samples"

# Sheets of more rows than this are parsed and analysed on a worker thread.
THREAD_THRESHOLD_ROWS = 20_000
LIVE_COLUMN_FIT_ROWS = 200  # up to this many rows the columns resize with every edit
# Files larger than this are read on a worker thread.
THREAD_THRESHOLD_BYTES = 1_000_000
# a file read on the GUI thread above this size may take half a second (the 216 kB
# interferometer sample: 0.38 s to read and analyse): the busy bar is shown first (#31)
PROGRESS_BYTES = 100_000
# the entry plan follows sheets up to this many rows (a test typed or captured point by point)
PLAN_ROWS = 5_000


class _TaskSignals(QObject):
    """Owned by the presenter; workers emit through it back to the GUI thread."""

    # the error as an object: a Message keeps its template (typed str, Qt gave back its
    # English: "无结果：0 usable readings…" while capturing, #41)
    finished = Signal(int, object, object)
    cancelled = Signal(int)  # an analysis superseded by newer readings stopped early
    imported = Signal(object, str, str, int, str)  # rows, path, error, generation, SHA-256


class _AnalysisTask(QRunnable):
    """Parse and analyse a large sheet on a worker thread (``sheet``: a snapshot, which the
    GUI thread's edits do not reach; it goes back with the result)."""

    def __init__(self, kind: Workbench, sheet: ReadingsSheet, settings: dict[str, Any],
                 generation: int, signals: _TaskSignals, prepare, current, workers: Workers,
                 reading_keys: tuple[str, ...] = (), planned: int | None = None,
                 details: Any = None, typing: tuple[int | None, tuple[str, ...]] = (None, ())
                 ) -> None:
        super().__init__()
        self._args = (kind, sheet, settings, generation, signals, prepare, current, workers,
                      reading_keys, planned, details, typing)

    def run(self) -> None:
        (kind, sheet, settings, generation, signals, prepare, current, workers, reading_keys,
         planned, details, (typing_row, blank_too)) = self._args
        # a newer edit (come while this waited in the queue or ran) cancels this analysis at
        # its next checkpoint: the newer one has its thread and the interpreter to itself
        try:
            with (workers.gui_thread_first(), workers.analysis_running(),
                  cancellable(lambda: generation != current())):
                checkpoint()
                parsed = sheet.parse()
                typing = None
                if reading_keys:
                    # the rows at the end waiting for their reading, as in the GUI thread's
                    # analysis (#62 review F8: while capturing, the plan's pre-filled row was
                    # "3 cell(s) cannot be read"), and the row being typed (row81)
                    parsed = _without_waiting_rows(parsed, sheet, reading_keys, planned)
                    parsed, typing = row_in_progress(parsed, typing_row, reading_keys,
                                                     kind.columns, blank_too, sheet.text)
                result, error, refused = _run_analysis(kind, parsed, settings, typing)
                checkpoint()
                display = _prepare_display(prepare, result)
                checkpoint()
                # the figures as the certificate prints them, here too: its coverage
                # intervals are a bootstrap (the GUI thread paused 0.2-0.3 s for each take)
                shown = _shown_on_worker(kind, result, details, settings)
        except AnalysisCancelled:
            emit_if_alive(signals.cancelled, generation)
            return
        emit_if_alive(signals.finished, generation,
                      (parsed, result, display, settings, sheet, shown, refused, typing), error)


def _without_waiting_rows(parsed: ParsedReadings, sheet: ReadingsSheet,
                          reading_keys: tuple[str, ...],
                          planned: int | None = None) -> ParsedReadings:
    """``parsed`` less the rows at the end of ``sheet`` waiting for their reading, and the
    row the entry plan sends the next reading to (``planned``) wherever it is
    (models/readings/incomplete.py), their reading cells' text blank."""
    keys = [c.key for c in sheet.columns]
    columns = [keys.index(k) for k in reading_keys if k in keys]
    if isinstance(sheet.rows, NumericRows) or not columns:
        return without_waiting_rows(parsed, reading_keys, planned=planned)[0]

    def blank_reading(row: int) -> bool:
        return all(not sheet.text(row, c).strip() for c in columns)

    return without_waiting_rows(parsed, reading_keys, blank_reading, planned)[0]


class AwaitedColumn(NamedTuple):
    """A column the analysis waits for (:meth:`WorkbenchPresenter.awaited_column`): its
    ``key``, the sentence that says why there is no result and where its values come from
    (translated), and the readings' caption's few words of what the readings wait for
    ("waiting for the face deviations", translated)."""

    key: str
    reason: str
    waiting: str


@dataclass(frozen=True)
class ShownAsPrinted:
    """What the window shows of ``result`` as its certificate prints it: the summary, the
    verdict and the headline figures ({name: text}), rounded as the certificate made with
    ``details`` (None: none yet) and the result's ``settings`` rounds them (the kind's
    printed_rounding, review 62 F2). Made with the result where it was analysed (on the
    worker for a large sheet or a take), and kept: a new language or unit shows it again."""

    result: Any
    details: Any
    settings: dict[str, Any]
    summary: Any
    verdict: Any
    printed: dict[str, str]
    #: the kind's printed_rounding of the result (None: the kind has none), which the
    #: plot's readout under the cursor follows
    rounding: Any = None
    #: the statement of conformity as the certificate made with ``details`` states it
    #: (its Conformity, or why no certificate can be made; None where no tolerance is set),
    #: shown by :func:`conformity_text`
    conformity: Any = None

    def of(self, result: Any, details: Any, settings: dict[str, Any]) -> bool:
        """Whether this is what ``result`` with ``details`` and ``settings`` shows."""
        return self.result is result and self.details == details and self.settings == settings


def shown_as_printed(kind: Workbench, result: Any, details: Any,
                     settings: dict[str, Any]) -> ShownAsPrinted:
    """:class:`ShownAsPrinted` of ``result`` (models only: safe on a worker thread). The
    certificate's rounding may be costly (the positioning's coverage intervals with the
    reference standards' U are a bootstrap, the cross-calibration's budgets): computed
    once here, never again on the GUI thread for the same result and details."""
    from models.certificate.metadata import CertificateMetadata

    printed_as = kind.printed_rounding(
        result, details if details is not None else CertificateMetadata(), settings)
    rounded = {} if printed_as is None else {"printed": printed_as}
    summary = kind.summary(result, **rounded)
    verdict = kind.verdict(result, **rounded) if isinstance(kind, ShowsHeadline) else ""
    return ShownAsPrinted(result, details, dict(settings), summary, verdict,
                          kind.printed_headline(result, printed_as), printed_as,
                          _conformity(kind, result, details, settings))


def _conformity(kind: Workbench, result: Any, details: Any, settings: dict[str, Any]) -> Any:
    """The certificate's :class:`~models.uncertainty.conformity.Conformity` where the details
    set a tolerance (why none, where the certificate cannot be made with them), None
    elsewhere (the window showed only the tolerance band; pass or fail was seen in an
    issued PDF only: day 65, F8)."""
    if details is None or getattr(details, "tolerance", None) is None \
            or not isinstance(kind, IssuesCertificates):
        return None
    try:
        return kind.certificate_document(result, details, "", settings).conformity
    except (ValueError, ArithmeticError) as exc:  # the certificate could not be made: why
        log.debug("no statement of conformity shown: %s", exc)
        return reason_of(exc)


def conformity_text(conformity: Any) -> str:
    """The statement of conformity in the window's language, short, as the result summary
    shows it: the verdict, the decision rule and the decided value with its interval; or
    "no statement" and why (the certificate's full statement: :func:`conformity_statement`)."""
    from models.certificate.document import printed_decided_figures
    from models.quantity import unit
    from models.uncertainty.conformity import DECISION_RULE_NAMES, VERDICT_WORDS
    from models.uncertainty.rounding import fixed_places, interval_decimals

    if conformity is None:
        return ""
    if isinstance(conformity, str):  # no certificate can be made with these details
        return tr("No statement of conformity: {reason}.").format(reason=translated(conformity))
    name = DECISION_RULE_NAMES.get(conformity.rule_key, "")
    rule = tr(name) if name else translated(conformity.rule)
    if conformity.verdict not in VERDICT_WORDS["en"]:
        text = tr("Conformity: no statement ({rule}): {reason}.").format(
            rule=rule, reason=translated(conformity.reason or conformity.statement))
    else:
        text = tr("Conformity: {verdict} ({rule}).").format(
            verdict=certificate_verdict(conformity.verdict), rule=rule)
    value, upper, lower = conformity.value, conformity.expanded, conformity.expanded_lower
    lower = lower if np.isfinite(lower) else upper
    # the figures the certificate prints (the value ± its printed U the interval's ends:
    # assessment 76 M1, where the window said [780, 1220] nm beside the certificate's
    # 770 nm … 1230 nm), else the interval rounded to its half-width's decimal
    shown = printed_decided_figures(conformity, "", conformity.unit)
    if shown is not None:
        written = unit(conformity.unit).written()
        text = _then(text, tr("Decided value {value}, interval [{low}, {high}]{unit}.").format(
            value=f"{shown['value']}{written}", low=shown["low"], high=shown["high"],
            unit=written))
    elif np.isfinite(value) and np.isfinite(upper) and np.isfinite(lower):
        low, high = value - lower, value + upper
        d = interval_decimals(low, high)
        written = unit(conformity.unit).written()
        text = _then(text, tr("Decided value {value}, interval [{low}, {high}]{unit}.").format(
            value=f"{fixed_places(value, d)}{written}", low=fixed_places(low, d),
            high=fixed_places(high, d),
            unit=written))
    return text


def certificate_verdict(verdict: str) -> Said:
    """``verdict`` ("pass", "conditional pass" …) in the window's language as the
    certificate's statement of conformity words it (models.uncertainty.conformity
    .VERDICT_WORDS: 合格 in Chinese, as the certificate, its XLSX and its DCC say it, not the
    validation report's 通过 of a check passed: assessment 78 M1), said again in the language
    then installed."""
    from models.uncertainty.conformity import VERDICT_WORDS

    def now() -> str:
        chinese = (QCoreApplication.instance() is not None
                   and application_language().code == "zh_CN")
        return VERDICT_WORDS["zh" if chinese else "en"][verdict]

    return Said(now(), now)


def _then(first: str, second: str) -> str:
    """Two sentences one after the other as the window's language joins them (the models'
    join, models.messages.JOINS: in Chinese no space after "。"; a plain " " left
    "符合性：合格（…）。 判定值 …", cert77)."""
    return tr("{first} {second}").format(first=first, second=second)


def conformity_statement(conformity: Any) -> str:
    """The certificate's whole statement of conformity (the verdict line's tooltip)."""
    if conformity is None or isinstance(conformity, str):
        return ""
    return translated(conformity.statement)


def _shown_on_worker(kind: Workbench, result: Any, details: Any,
                     settings: dict[str, Any]) -> ShownAsPrinted | None:
    """:func:`shown_as_printed` on a worker; None (the GUI thread then makes it) where there
    is no result or making it failed (logged: a failure must not leave the window busy)."""
    if result is None:
        return None
    try:
        return shown_as_printed(kind, result, details, settings)
    except Exception:  # noqa: BLE001 - the GUI thread makes it again, and says what fails
        log.exception("the figures as printed failed on the worker")
        return None


def _prepare_display(prepare, result: Any) -> Any:
    """The presenter's plot arrays for ``result`` (numpy only, safe on a worker thread)."""
    if result is None:
        return None
    try:
        return prepare(result)
    except Exception:  # noqa: BLE001 - the plots then compute what they need themselves
        log.exception("preparing the plots failed")
        return None


class _ImportTask(QRunnable):
    """Read and map a large file on a worker thread."""

    def __init__(self, kind: Workbench, path: str, signals: _TaskSignals,
                 generation: int, workers: Workers) -> None:
        super().__init__()
        self._args = (kind, path, signals, generation, workers)

    def run(self) -> None:
        kind, path, signals, generation, workers = self._args
        digest = _file_digest(path)
        # Millions of new row lists would trigger full cyclic-GC passes that hold the GIL
        # for up to half a second each and stall the window; rows of strings hold no
        # cycles, so the collector rests while they are built.
        with workers.cyclic_gc_paused(), workers.gui_thread_first(), workers.analysis_running():
            # a record of plain numbers stays numbers (a column store): a million readings
            # are read in a fraction of a second and never become a million text rows
            parsed = read_numeric(path, kind.columns)
            if parsed is not None:
                emit_if_alive(signals.imported, NumericRows(kind.columns, parsed.values,
                                                            parsed.n), path, "", generation,
                              digest)
                return
            try:
                rows = map_columns(read_table(path), kind.columns)
            except MissingColumnError as exc:  # mapped on the GUI thread, with the user
                emit_if_alive(signals.imported, exc, path, explained(exc), generation, digest)
                return
            except TableImportError as exc:
                emit_if_alive(signals.imported, None, path, explained(exc),
                              generation, digest)
                return
            gc.freeze()  # keep the new rows out of later full passes too
        emit_if_alive(signals.imported, rows, path, "", generation, digest)


def _file_digest(path: str | Path) -> str:
    """SHA-256 of the file being imported ("" when it cannot be read: the import says why)."""
    try:
        return file_sha256(path)
    except OSError:
        return ""


def _sheet_state(sheet: ReadingsSheet, settings: dict[str, Any], deep: bool) -> WorkbenchState:
    """``sheet``'s rows (less blank rows at the end) and ``settings``, copied: each row
    (``deep``) or only the list of rows."""
    if isinstance(sheet.rows, NumericRows):  # a record of numbers: read as text
        return WorkbenchState(sheet.copy_rows() if deep else  # when written
                              sheet.rows.snapshot(), dict(settings))
    rows = sheet.copy_rows() if deep else list(sheet.rows)
    while rows and not any(c.strip() for c in rows[-1]):
        rows.pop()
    return WorkbenchState(rows, dict(settings))


def _run_analysis(kind: Workbench, parsed: ParsedReadings, settings: dict[str, Any],
                  typing: RowInProgress | None = None) -> tuple[Any, str, str]:
    """The result, or why there is none; and the key of the setting the readings refuse
    (a tilt bound of 0 where they do not identify the tilt: its field is marked), "" when
    no one setting is to blame. ``typing``: the row a reading is being typed into, part of
    the run in progress (Workbench.analyze_as_far_as_it_goes)."""
    try:
        # a run in progress: the complete units analysed, the last one's progress shown
        return kind.analyze_as_far_as_it_goes(parsed, settings, typing), "", ""
    except AnalysisCancelled:
        raise
    except ValueError as exc:  # bad input: a message for the technician
        return None, reason_of(exc), str(getattr(exc, "key", "") or "")
    except Exception as exc:  # noqa: BLE001 - a bug must not take the typed readings with it
        log.exception("analysis failed")
        return None, f"internal error while analysing ({type(exc).__name__}: {exc})", ""


class WorkbenchPresenter(QObject):
    """Base presenter. Subclasses build their view's fields and draw results.

    ``result`` holds the last analysis result (``None`` when the readings
    cannot be analysed; ``problem`` then says why).
    """

    modified_changed = Signal(bool)
    analysed = Signal()
    import_failed = Signal(str)
    imported = Signal(str, int)  # file, rows read

    #: the view a presenter makes when none is given (a test gives a mock)
    view_class: type[WorkbenchView] | None = None

    def __init__(self, kind: Workbench, view: WorkbenchView | None = None, parent=None) -> None:
        if view is None:
            view = self.view_class()
        # lives as long as its view (a mock view in a test is no QObject)
        super().__init__(parent if parent is not None else
                         (view if issubclass(type(view), QObject) else None))
        self.kind = kind
        self.view = view
        #: the files no export of this workbench may replace (the main window sets it: the
        #: register and its journals, the open project, the readings files imported)
        self.protected_outputs = list
        #: raises OutputRefused when a path is a file the register issued (a certificate's
        #: PDF, DCC or results file; the main window sets it: app/issued_outputs.py)
        self.refuse_issued: Callable[[str], None] = lambda _path: None
        self.workers = application_workers()  # the application's thread pool
        self.sheet = ReadingsSheet(kind.columns)
        self.undo_stack = QUndoStack(self)
        self.table_model = ReadingsTableModel(self.sheet, self.undo_stack, self)
        keys = [c.key for c in kind.columns]
        self.table_model.reading_columns = tuple(keys.index(k) for k in self._reading_keys()
                                                 if k in keys)
        self.table_model.planned_row = self.planned_row
        self.table_model.typing_row = self.typing_row
        self.view.attach_table_model(self.table_model)
        if hasattr(getattr(self.view, "table", None), "own_layout"):  # a mock view has none
            self.view.table.own_layout = kind.rows_from_table
            self.view.table.plan_return = self.plan_return
            self.view.table.plan_typed = self.plan_typed
            self.view.table.plan_paste = self.plan_paste
        self._settings: dict[str, Any] = kind.settings_with_defaults(None)
        self._settings_modified = False
        #: by column index: the figure its blank cells show (Workbench.shown_in_blank, with
        #: the settings of now) and what to say of it
        self._shown_in_blank: dict[int, tuple[Callable[[Callable[[str], str]], str | None],
                                              str]] = {}
        self.table_model.shown_in_blank = self._blank_cell_shown
        self._settings_shown_in_blank()
        #: the rows were changed in a window after the project file was last saved, before
        #: this one took them (recovered from its autosave: :meth:`readings_unsaved`)
        self.recovered_unsaved = False
        self.result: Any = None
        # the settings ``result`` was analysed with: a certificate of it states and computes
        # with these, not the form's (edited since, their analysis still to come)
        self.result_settings: dict[str, Any] = dict(self._settings)
        # the readings ``result`` was analysed from (a snapshot later edits do not reach):
        # a certificate records these with its figures, never the sheet's rows of the moment
        self.result_sheet: ReadingsSheet = self.sheet.snapshot()
        self.display: Any = None  # prepare_display(result)
        self.shown: ShownAsPrinted | None = None  # the texts of ``result`` as printed
        self.parsed: ParsedReadings | None = None
        #: the row a reading is being typed into when ``parsed`` was analysed (None: none)
        self.typing: RowInProgress | None = None
        self.problem = ""
        self.refused_setting = ""  # the setting whose field the readings refuse (key)
        self.plan_problem = ""  # why the entry plan set cannot be made ("" when it can)
        # the certificate details this workbench's certificate would be made with (the
        # window sets it; None: none): the plots' tolerance and U bands come from them
        self.certificate_details: Callable[[], Any] = lambda: None
        self.angle_unit: AngleUnit = ANGLE_UNITS["arcsec"]  # what results are shown in
        self._generation = 0  # one more for every analysis started (``refresh``)
        self._shown_generation = 0  # the analysis whose result is shown (``result``)
        self._import_generation = 0  # a newer import, or an opened project, drops older imports
        self._import_pending = False
        self._signals = _TaskSignals(self)
        self._signals.finished.connect(self._on_task_finished)
        self.cancelled_analyses = 0  # superseded while running, stopped at a checkpoint
        self._signals.cancelled.connect(self._on_task_cancelled)
        self._signals.imported.connect(self._on_import_finished)
        self.busy = False
        #: readings are coming from an instrument (the capture panel says): each take is
        #: analysed off the GUI thread and the columns are not re-measured (the panel widens
        #: the ones it fills), so the window never pauses for a take (#41)
        self.capturing = False
        #: the row the capture sends the next take to (the capture panel's, while its
        #: instruments are connected to this workbench; None: none): without an entry plan,
        #: it waits for its reading as the plan's row does (day review 64 P4)
        self.take_row: Callable[[], int] | None = None
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(0)
        self._timer.timeout.connect(self.refresh)
        self._redraw_timer = QTimer(self)  # the result drawn again, not analysed again
        self._redraw_timer.setSingleShot(True)
        self._redraw_timer.setInterval(0)
        self._redraw_timer.timeout.connect(self._redraw)
        self.build_settings()
        self.view.set_settings(self._settings)
        self._setting_units_shown()
        keys = [c.key for c in kind.columns]
        nominal = keys.index(kind.nominal_column) if kind.nominal_column in keys else None
        self.view.set_entry_columns(nominal, keys.index(kind.entry_column)
                                    if kind.entry_column in keys else 0,
                                    kind.columns[nominal].title if nominal is not None else "")
        self.table_model.sheet_changed.connect(self.schedule_refresh)
        self.undo_stack.cleanChanged.connect(self._on_clean_changed)
        self.view.subscribe(self)
        on_language_change(self, self._redraw)

    # -- subclass hooks ---------------------------------------------------
    def output_refused(self, path: str, title: str) -> bool:
        """Whether the export to ``path`` is refused (told, nothing written): it is the
        register, the open project or an input (models/project/output_guard.py), or a file
        the register issued (rev63 F6: a table replaced an issued results file, which the
        CLI's ``--table`` refuses)."""
        from models.project.output_guard import OutputRefused, check_output

        try:
            check_output(path, self.protected_outputs())
            self.refuse_issued(path)
        except OutputRefused as exc:
            self.view.tell(title, explained(exc))
            return True
        return False

    def save_image(self, path: str, data: bytes) -> bool:
        """A plot's "Save image…" (widgets/plot_image.py): refused like any export of the
        workbench (:meth:`output_refused`: the register, the open project, an input, a file
        the register issued), else written atomically. rev64: it was written in place, so a
        ``.png`` link or hard link to an issued PDF, XLSX or DCC replaced the issued file."""
        from models.project.atomic_write import write_bytes_atomic

        title = tr("Cannot save the image")
        if self.output_refused(path, title):
            return False
        try:
            write_bytes_atomic(path, data)
        except OSError as exc:
            self.view.tell(title, explained(exc))
            return False
        return True

    def build_settings(self) -> None:
        """The set-up fields, one per declared setting of the kind."""
        for parameter in self.kind.parameters:
            self.view.add_setting(parameter)

    def prepare_display(self, result: Any) -> Any:
        """Heavy plot arrays for ``result`` (decimation, model curves): pure numpy, run on
        the worker thread with a large analysis; ``self.display`` holds it in show_result."""
        return None

    def show_result(self, result: Any) -> None:
        """Draw a fresh result in the view."""

    def clear_result(self) -> None:
        """Empty the plots (the readings cannot be analysed)."""

    # -- the unit results are shown in -----------------------------------
    def set_angle_unit(self, unit: AngleUnit) -> None:
        """Show the result in ``unit`` (redrawn, not re-analysed)."""
        if unit == self.angle_unit:
            return
        self.angle_unit = unit
        self._redraw()

    def schedule_redraw(self) -> None:
        """Draw the result again soon (the certificate details changed: the plots'
        tolerance and U bands follow them); the result itself stays, nothing is analysed."""
        self._redraw_timer.start()

    def _redraw(self) -> None:
        """The result shown again (a new language or unit), not analysed again."""
        if self.parsed is not None:
            self._finish(self.parsed, self.result, self.problem, self.display,
                         refused=self.refused_setting, typing=self.typing)

    def in_unit(self, *figures):
        """The declared plots with their angles in the chosen unit (``None``, a plot with
        nothing to draw, stays ``None``)."""
        return tuple(None if f is None else figure_in_unit(f, self.angle_unit)
                     for f in figures)

    def tolerance_bands(self, result: Any) -> tuple[float | None, dict[str, Any], str]:
        """(T, {array name: U per point}, decision quantity) as the certificate would use
        them: T from the certificate details (in the errors' unit), U from the workbench's
        budgets for the JSON's ``expanded_uncertainty_*``
        (models/certificate/uncertainty_json.py); (None, {}, "") when no tolerance is set
        or the details cannot give one."""
        meta = self.certificate_details()
        if meta is None or getattr(meta, "tolerance", None) is None:
            return None, {}, ""
        budgets_of = getattr(self.kind, "uncertainty_budgets", None)
        if budgets_of is None:
            return None, {}, ""
        try:
            # with the settings the result was analysed with, as its certificate's budget
            budgets = budgets_of(result, meta, self.result_settings)
            unit = next((b.unit.key for b in budgets.values() if hasattr(b, "unit")), None)
            tolerance = meta.tolerance_in(unit or self.kind.error_unit(self.result_settings))
        except (ValueError, ArithmeticError) as exc:
            log.debug("no tolerance band: %s", exc)
            return None, {}, ""
        return tolerance, {name: getattr(b, "expanded", None) for name, b in budgets.items()}, \
            str(getattr(meta, "decision_quantity", "half_range"))

    def shown_as_printed(self, result: Any, made: ShownAsPrinted | None = None
                         ) -> ShownAsPrinted:
        """The summary, verdict and figures of ``result`` as its certificate prints them,
        with the details it would be made with now (none yet: the inputs the readings
        give): ``made`` (the worker's) or the last ones shown where they are of this result,
        these details and the result's settings; else made here, on the GUI thread (a
        sheet analysed here, or new certificate details)."""
        details = self.printed_details()
        for shown in (made, self.shown):
            if shown is not None and shown.of(result, details, self.result_settings):
                break
        else:
            shown = shown_as_printed(self.kind, result, details, self.result_settings)
        self.shown = shown
        return shown

    def printed_details(self) -> Any:
        """The certificate details the window's figures are rounded with: those its
        certificate would be made with now (None: none yet)."""
        return self.certificate_details()

    def printed_rounding(self, result: Any) -> Any:
        """How the certificate of ``result`` rounds (the kind's printed_rounding with
        :meth:`printed_details`; None: the kind has none)."""
        return self.shown_as_printed(result).rounding

    def _show_readout_decimals(self, printed_as: Any) -> None:
        """The error plot's readout under the cursor to the decimals the certificate prints
        the errors to (a kind whose printed rounding is one decimal, in arcseconds), in the
        unit shown; else the plot's own (the data's)."""
        plot = getattr(self.view, "error_plot", None)
        if plot is None or not hasattr(plot, "set_readout_decimals"):
            return
        printed = isinstance(printed_as, int) and not isinstance(printed_as, bool)
        plot.set_readout_decimals(decimals_in_unit(printed_as, self.angle_unit)
                                  if printed else None)

    def in_unit_text(self, text: str) -> str:
        """A model's text in the chosen unit (converted from its figures), then in the
        window's language."""
        return translated(in_unit(text, self.angle_unit))

    # -- state ------------------------------------------------------------
    @property
    def settings(self) -> dict[str, Any]:
        return dict(self._settings)

    def set_settings(self, settings: dict[str, Any]) -> None:
        self._settings = self.kind.settings_with_defaults(settings)
        self.view.set_settings(self._settings)
        self._readings_per_point()
        self._settings_shown_in_blank()
        self.table_model.forget_waiting()  # the plan's row waiting may be another
        self._settings_modified = True
        self._emit_modified()
        self.schedule_refresh()

    def settings_edited(self) -> None:
        """The user changed a set-up field: one undo step (Edit › Undo puts it back)."""
        old = dict(self._settings)
        new = {**old, **self.view.settings_values()}
        if new == old:
            return
        changed = [k for k in new if new[k] != old.get(k)]
        label = tr("Set-up: {names}").format(names=", ".join(
            self._setting_label(k) for k in changed[:3]) + (" …" if len(changed) > 3 else ""))
        self.undo_stack.push(SettingsCommand(self._apply_edited_settings, old, new, label))

    def _setting_label(self, key: str) -> str:
        parameter = next((p for p in self.kind.parameters if p.key == key), None)
        return declared(parameter.label) if parameter is not None else key

    def _apply_edited_settings(self, settings: dict[str, Any]) -> None:
        """The set-up of an undo step, shown and analysed (the fields set without signals)."""
        if settings != self.view.settings_values():
            self.view.set_settings(settings)
        self._settings = dict(settings)
        self._readings_per_point()
        self._settings_shown_in_blank()
        self.table_model.forget_waiting()  # the plan's row waiting may be another
        self._settings_modified = True
        self._emit_modified()
        self.schedule_refresh()

    def _settings_shown_in_blank(self) -> None:
        """The figures blank cells show (positioning's deviation from the measured
        position: gui77, the deviation column stayed empty while a live run's measured
        filled), worked out with the settings of now, and the table repainted; the units
        the settings give columns in their headers."""
        keys = [c.key for c in self.kind.columns]
        self._shown_in_blank = {keys.index(key): shown for key, shown in
                                self.kind.shown_in_blank(self._settings).items() if key in keys}
        self.table_model.shown_columns = tuple(sorted(self._shown_in_blank))
        self.table_model.shown_changed()
        # … and the units the settings give columns, in their headers (live78)
        self.table_model.set_header_units({
            keys.index(key): unit for key, unit in self.kind.column_units(self._settings).items()
            if key in keys})
        self._setting_units_shown()

    def _setting_units_shown(self) -> None:
        """The units the settings give other settings, beside their fields (positioning's
        budget inputs in the deviations' unit: leftovers 79)."""
        self.view.set_setting_units(dict(self.kind.setting_units(self._settings)))

    def _blank_cell_shown(self, r: int, c: int) -> tuple[str, str] | None:
        """The figure blank cell (r, c) shows and what to say of it (None: none)."""
        shown = self._shown_in_blank.get(c)
        if shown is None:
            return None
        sheet = self.sheet
        columns = {col.key: i for i, col in enumerate(sheet.columns)}
        figure = shown[0](lambda key: sheet.text(r, columns[key]) if key in columns else "")
        return None if figure is None else (figure, shown[1])

    def _readings_per_point(self) -> None:
        """Typed entry fills a point's nominal n times when n readings make a point."""
        self.view.set_readings_per_point(max(1, int(self._settings.get("readings_per_point", 1)
                                                    or 1)))

    @property
    def is_modified(self) -> bool:
        return self._settings_modified or not self.undo_stack.isClean()

    def mark_modified(self) -> None:
        """Count the current state as unsaved (e.g. work recovered after a crash)."""
        self._settings_modified = True
        self._emit_modified()

    def mark_saved(self) -> None:
        self._settings_modified = False
        self.recovered_unsaved = False
        self.undo_stack.setClean()
        self._emit_modified()

    def readings_unsaved(self) -> bool:
        """Whether the rows may differ from the project file's as it was last saved or
        opened: a step between the saved one and now changed rows (a change of settings
        does not), the saved step is out of reach of the undo history, or the rows were
        recovered changed (:attr:`recovered_unsaved`). Day review 67 F4: the certificate
        named the file as the source of readings it did not hold."""
        if self.recovered_unsaved:
            return True
        stack = self.undo_stack
        clean, now = stack.cleanIndex(), stack.index()
        if clean < 0:
            return True
        for i in range(min(clean, now), max(clean, now)):
            step = stack.command(i)
            commands = [step.child(j) for j in range(step.childCount())] or [step]
            if any(not isinstance(command, SettingsCommand) for command in commands):
                return True
        return False

    def _on_clean_changed(self, _clean: bool) -> None:
        self._emit_modified()

    def _emit_modified(self) -> None:
        self.modified_changed.emit(self.is_modified)

    def state(self, deep: bool = True) -> WorkbenchState:
        """The readings, settings and where the readings came from. ``deep=False`` copies
        only the list of rows (a million rows' copies would stall the window); the rows are
        shared, which later edits do not reach (an edit replaces a row:
        ReadingsSheet.snapshot)."""
        state = _sheet_state(self.sheet, self._settings, deep)
        state.origin = origin_record(*self.table_model.origin_since())
        state.marks = self.table_model.mark_records()  # the cells' marks (gui77)
        return state

    def result_state(self) -> WorkbenchState:
        """The readings and settings ``result`` was analysed from (copied): what a
        certificate of it records, whatever the sheet and the form hold now."""
        return _sheet_state(self.result_sheet, self.result_settings, True)

    def load_state(self, state: WorkbenchState, project: str = "") -> None:
        """Replace readings and settings (a project was opened: ``project`` its file's name,
        "" none or an untitled one's autosave); clears the undo history. The readings'
        origin is the one the project kept; one it did not keep, of rows, is "from project
        NAME" (models/certificate/stored_origin.py), never typed."""
        self._supersede_imports()
        self._settings = self.kind.settings_with_defaults(state.settings)
        self.view.set_settings(self._settings)
        self.table_model.apply_replace(state.rows)
        self.table_model.set_mark_records(state.marks)  # the cells' marks it kept
        self.table_model.forget_origin()
        if state.origin is not None or state.rows:
            opened = stored_origin(state.origin, project)
            self.table_model.set_opened_origin(opened.origin, opened.edited, opened.pasted)
        self.undo_stack.clear()
        self.mark_saved()
        self.refresh()

    def readings_source(self, project: str = "") -> str | None:
        """Where the sheet's readings came from when it is a file imported (or the bundled
        sample: day review 65 F4), pasted, or sent from another workbench, with the rows
        pasted since (day review 66), or a project that did not say (day review 67), as a
        certificate says it (None: typed, or the project's: ``project`` the name of the
        file the window has them in)."""
        return sheet_source(*self.table_model.readings_origin(), project=project)

    def import_file(self, path: str | Path, sample: bool = False) -> None:
        """Replace the readings with a CSV/XLSX file's (undoable). Raises TableImportError.
        Headers that name no column are mapped by the user (the view asks). ``sample``: the
        file is the workbench's bundled sample (what a certificate then names)."""
        digest = _file_digest(path)
        table = read_table(path)
        try:
            rows = map_columns(table, self.kind.columns)
        except MissingColumnError as exc:
            rows = self._rows_by_mapping(exc)
            if rows is None:
                raise
        self.table_model.replace_all(rows, tr("Import {name}").format(name=Path(path).name),
                                     checked=True,
                                     origin=ImportedFrom(Path(path).name, digest, sample))
        self.imported.emit(str(path), len(rows))
        self._fit_columns()
        self.refresh()

    def start_import(self, path: str | Path) -> None:
        """Import a file, on a worker thread when it is large; errors go to ``import_failed``."""
        path = str(path)
        try:
            # a workbook can expand far beyond its size on disk: always off the GUI thread
            size = Path(path).stat().st_size
            large = (size > THREAD_THRESHOLD_BYTES
                     or Path(path).suffix.lower() in (".xlsx", ".xlsm"))
        except OSError:
            size, large = 0, False
        self._supersede_imports()
        if not large:
            shown = size > PROGRESS_BYTES and self.view.show_reading(
                tr("Reading {name} …").format(name=Path(path).name))
            try:
                self.import_file(path)
            except TableImportError as exc:
                self.import_failed.emit(explained(exc))
            finally:
                if shown:
                    self.view.show_reading("")
            return
        self._import_pending = True
        self._set_busy(True, tr("Reading {name} …").format(name=Path(path).name))
        self.workers.start(_ImportTask(self.kind, path, self._signals, self._import_generation,
                                       self.workers))

    def _rows_by_mapping(self, exc: MissingColumnError) -> list[list[str]] | None:
        """The rows with the column mapping the view gives (remembered or asked); None when
        the user gives none. Raises TableImportError for a mapping the file cannot take."""
        table = exc.table
        own = self.kind.rows_from_table(table)  # the workbench's own layout, taken as it is
        if own is not None:
            return own
        mapping = self.view.ask_column_mapping(self.kind.columns, list(table.header or []),
                                               table.rows[:8], explained(exc))
        if not mapping:
            return None
        return map_columns(table, self.kind.columns, mapping)

    def _supersede_imports(self) -> None:
        """Whatever import is still reading will be dropped when it lands."""
        self._import_generation += 1
        if self._import_pending:
            self._import_pending = False
            self._set_busy(False)

    def _on_import_finished(self, rows, path: str, error: str, generation: int,
                            digest: str = "") -> None:
        if generation != self._import_generation:
            return  # superseded: a newer import or an opened project is what the user wants
        self._import_pending = False
        if isinstance(rows, MissingColumnError):  # the headers need the user's mapping
            try:
                rows = self._rows_by_mapping(rows)
            except TableImportError as exc:
                rows, error = None, explained(exc)
        if rows is None or len(rows) <= THREAD_THRESHOLD_ROWS:
            self._set_busy(False)  # a large sheet stays "busy" into its analysis: no
            #                        repaint of the old plots in between
        if rows is None:
            self.import_failed.emit(error)
            return
        self.table_model.replace_all(rows, tr("Import {name}").format(name=Path(path).name),
                                     checked=True, origin=ImportedFrom(Path(path).name, digest))
        self.imported.emit(str(path), len(rows))
        self._fit_columns()
        # queued behind the table's own relayout: started now, the analysis worker would
        # compete with it for the GIL and the relayout of a million rows would stall
        self.schedule_refresh()

    def _fit_columns(self) -> None:
        self.view.fit_columns(self.sheet.row_count, LIVE_COLUMN_FIT_ROWS, THREAD_THRESHOLD_ROWS)

    def _set_busy(self, busy: bool, text: str = "") -> None:
        self.busy = busy
        self.view.set_busy(busy)
        if busy and text:
            self.view.set_summary(text)

    def load_sample(self) -> None:
        self.import_file(SAMPLES_DIR / self.kind.sample_file, sample=True)
        self.undo_stack.clear()
        self.mark_saved()

    # -- the entry plan: entry follows the run ----------------------------------
    def entry_plan(self) -> EntryPlan | None:
        """The plan the settings give (None: none set, or it cannot be made: plan_problem)."""
        try:
            plan = self.kind.entry_plan(self._settings)
        except ValueError as exc:
            self.plan_problem = reason_of(exc)
            return None
        self.plan_problem = ""
        return plan

    def _plan_rows(self, plan: EntryPlan) -> tuple[list[dict[str, str]], list[str]] | None:
        if isinstance(self.sheet.rows, NumericRows) or self.sheet.row_count > PLAN_ROWS:
            return None
        keys = [c.key for c in self.kind.columns]
        return [{k: self.sheet.text(r, c) for c, k in enumerate(keys)}
                for r in range(self.sheet.row_count)], keys

    def _reading_keys(self) -> tuple[str, ...]:
        return self.kind.plan_reading_keys or ((self.kind.entry_column,)
                                               if self.kind.entry_column else ())

    def plan_return(self, row: int, blank_before: bool = True) -> int | None:
        """Return after an edit of ``row`` with a plan set: the row's plan cells filled when
        it is the row the plan pointed at, empty before this reading (``blank_before``: the
        table's, as the editor opened), and its reading came without them — said on the
        status line; the next point's plan cells put in the row it goes to (one undo step
        each); the row the next reading goes to, None without a plan.

        A reading typed into any other row without the plan's cells (a correction of a
        pasted row) gets none: day review 65 F2 stamped the plan's next θ on it, a wrong θ
        said nowhere, while the plan's own row for that θ stayed empty."""
        plan = self.entry_plan()
        if plan is None:
            return None
        got = self._plan_rows(plan)
        if got is None:
            return None
        rows, keys = got
        reading = self._reading_keys()
        changes = self._typed_row_plan_cells(plan, rows, keys, row, blank_before)
        place = plan.placement(rows, reading)
        if place is None:
            if changes:
                self.table_model.set_cells(changes, tr("Entry plan"))
            if blank_before and 0 <= row < len(rows) and \
                    any(rows[row].get(k, "").strip() for k in reading):
                beyond = self.after_plan_end(row)
                if beyond:
                    self._say(beyond)
            return None
        if place.row >= len(rows):
            rows.append({k: "" for k in keys})
        changes += [(place.row, keys.index(k), v) for k, v in place.cells.items()
                    if not rows[place.row].get(k, "").strip()]
        if changes:
            self.table_model.set_cells(changes, tr("Entry plan: {point}").format(
                point=translated(place.point.label)))
        return place.row

    def _typed_row_plan_cells(self, plan: EntryPlan, rows: list[dict[str, str]],
                              keys: list[str], row: int,
                              blank_before: bool) -> list[tuple[int, int, str]]:
        """The plan's cells of ``row`` (``rows`` updated with them, said on the status line)
        when it is the row the plan pointed at, empty before this reading, and its reading
        came without them; [] otherwise."""
        reading = self._reading_keys()
        if not (blank_before and 0 <= row < len(rows)
                and any(rows[row].get(k, "").strip() for k in reading)
                and not any(rows[row].get(k, "").strip() for k in plan.points[0].cells)
                and self._plan_pointed_at(plan, rows, row)):
            return []
        point = plan.next_point(rows, reading)
        if point is None:
            return []
        rows[row].update(point.cells)
        self._say(tr("Row {row}: {point}, from the entry plan").format(
            row=row + 1, point=translated(point.label)))
        return [(row, keys.index(k), v) for k, v in point.cells.items()]

    def plan_typed(self, row: int, blank_before: bool = True) -> None:
        """A reading typed into ``row`` and left by Tab, a click or another cell (not
        Return): the row's plan cells filled as Return fills them (:meth:`plan_return`),
        the cursor left where the user put it and the next row not pre-filled. live78: the
        theodolite's first row typed A, Tab, E, Tab kept no θ; the block pasted below it
        then took the plan's θ from −20° on, each row one θ early — a result from shifted
        θ, said only as "Rows 2–5: θ = −20° … θ = 10°, from the entry plan"."""
        plan = self.entry_plan()
        got = None if plan is None else self._plan_rows(plan)
        if plan is None or got is None:
            return
        rows, keys = got
        changes = self._typed_row_plan_cells(plan, rows, keys, row, blank_before)
        if changes:
            self.table_model.set_cells(changes, tr("Entry plan"))

    def after_plan_end(self, row: int) -> str:
        """What to say of a reading taken into ``row`` (typed into a new row, or captured)
        when the entry plan was complete without it: the plan's end, in the plan's words,
        and that the reading is kept; "" when the plan had a point for it, or there is no
        plan. Day review 66: a reading after "Entry plan complete" was taken without a
        word."""
        plan = self.entry_plan()
        got = None if plan is None else self._plan_rows(plan)
        if plan is None or got is None:
            return ""
        rows, keys = got
        without = [dict(r) for r in rows]
        if 0 <= row < len(without):
            without[row] = dict.fromkeys(keys, "")
        if plan.placement(without, self._reading_keys()) is not None:
            return ""
        planned = translated(plan.next_text(without, self._reading_keys()))
        # a cell the analysis needs and only the plan fills (positioning's target): the
        # row is left out of the analysis until it is typed (day review live76 F6: row 17
        # taken after the plan's end, no word of it left out, the report counted it)
        cells = rows[row] if 0 <= row < len(rows) else {}
        filled_by_plan = {k for point in plan.points for k in point.cells}
        needed = [c for c in self.kind.columns if c.required and c.key in filled_by_plan
                  and not str(cells.get(c.key, "")).strip()]
        if needed:
            return tr("Row {row}: taken after the end of the entry plan ({plan}); the reading "
                      "is kept but left out of the analysis until its {columns} is typed"
                      ).format(row=row + 1, plan=planned, columns=joined(
                          ", ", [declared(c.title) for c in needed]))
        return tr("Row {row}: taken after the end of the entry plan ({plan}); the reading is "
                  "kept, as a point the plan does not have").format(row=row + 1, plan=planned)

    def _plan_pointed_at(self, plan: EntryPlan, rows: list[dict[str, str]], row: int) -> bool:
        """Whether ``row`` is the row the plan sent the next reading to before that row was
        filled (the plan's placement with the row emptied)."""
        before = [dict(r) for r in rows]
        before[row] = {k: "" for k in before[row]}
        place = plan.placement(before, self._reading_keys())
        return place is not None and place.row == row

    def _say(self, text: str) -> None:
        """``text`` on the status line, as the table's messages about its rows."""
        notice = getattr(getattr(self.view, "table", None), "notice", None)
        if notice is not None and hasattr(notice, "emit"):
            notice.emit(text)

    def plan_paste(self, top: int, count: int) -> Callable[[], str] | None:
        """A block of ``count`` rows about to be pasted from row ``top``, with a plan set:
        what, once pasted, gives its rows the plan's cells (θ, run, direction; target …)
        — when the block lands on the row the plan points at, each of its rows that was
        empty (or that row) and holds a reading without the plan's cells gets the plan's
        next point, points already in the sheet skipped — and returns what to say of it
        ("" when nothing was filled). None without a plan, or when the block lands
        elsewhere: rows the plan was not pointing at get nothing from it (as a typed edit,
        :meth:`plan_return`). Day review 65 F3: pasted rows got nothing, the plan did not
        advance, and later takes were labelled with θ already in the sheet."""
        place = self.plan_placement()
        if place is None or place.row != top:
            return None
        sheet = self.sheet
        candidates = [r for r in range(top, top + count)
                      if r == top or r >= sheet.row_count or sheet.is_blank_row(r)]

        def fill() -> str:
            plan = self.entry_plan()
            got = None if plan is None else self._plan_rows(plan)
            if plan is None or got is None:
                return ""
            rows, keys = got
            points = plan.fill(rows, self._reading_keys(), candidates)
            if not points:
                return ""
            changes = [(r, keys.index(k), v) for r, point in points
                       for k, v in point.cells.items() if not rows[r].get(k, "").strip()]
            self.table_model.set_cells(changes, tr("Entry plan"))
            (first, start), (last, end) = points[0], points[-1]
            if first == last:
                return tr("Row {row}: {point}, from the entry plan").format(
                    row=first + 1, point=translated(start.label))
            return tr("Rows {first}–{last}: {start} … {end}, from the entry plan").format(
                first=first + 1, last=last + 1, start=translated(start.label),
                end=translated(end.label))
        return fill

    def plan_placement(self) -> Placement | None:
        """Where the plan's next point goes (its row, ``len(rows)`` for a new one, and the
        plan's cells for it), without changing the table; None without a plan (or when the
        table is too large for one, or the plan is complete)."""
        plan = self.entry_plan()
        got = None if plan is None else self._plan_rows(plan)
        if got is None:
            return None
        return plan.placement(got[0], self._reading_keys())

    def plan_complete(self) -> int:
        """The number of the entry plan's points when every one has its reading (the plan
        complete); 0 without a plan or while it has points to go."""
        plan = self.entry_plan()
        got = None if plan is None else self._plan_rows(plan)
        if got is None or plan.placement(got[0], self._reading_keys()) is not None:
            return 0
        return len(plan.points)

    def waiting_row(self) -> int | None:
        """Without a plan, the row that waits for the next reading: the first of the rows at
        the end with their point (θ, target) but no reading (models/capture/take_cells.py
        waiting_row); None when there is none."""
        sheet = self.sheet
        if isinstance(sheet.rows, NumericRows) or sheet.row_count > PLAN_ROWS:
            return None
        keys = [c.key for c in sheet.columns]
        reading = [keys.index(k) for k in self._reading_keys() if k in keys]
        return waiting_row(sheet.row_count, len(keys), reading, sheet.text)

    def planned_row(self) -> int | None:
        """The row of the table the entry plan sends the next reading to — a row pre-filled
        with the next point, or one in the middle whose reading was cleared (a take thrown
        away) — that waits for its reading as the rows at the end do: never a bad row.
        Without a plan, the row the capture sends the next take to (:attr:`take_row`, the
        row its guidance names: one cleared in the middle too, day review 64 P4). None
        without either, when the plan is complete or the next point is a new row."""
        place = self.plan_placement()
        if place is not None:
            row: int | None = place.row
        elif self.take_row is not None and self.sheet.row_count <= PLAN_ROWS:
            row = self.take_row()
        else:
            row = None
        return row if row is not None and row < self.sheet.row_count else None

    def typing_row(self) -> int | None:
        """The row a reading is being typed into by hand (row81): the last row with a
        reading (models/readings/incomplete.py typing_row; with an entry plan, the row the
        plan sent the reading to: the rows after it are its next points, pre-filled), some
        of its reading cells typed, a reading cell that needs a value still blank, every
        other cell readable (a column the analysis waits for may be blank too). Its blank
        reading cells wait (not red, not bad cells) and the row is said in progress; a
        reading left half-typed in any other row is a bad row. None: no such row."""
        sheet = self.sheet
        if isinstance(sheet.rows, NumericRows) or sheet.row_count > PLAN_ROWS:
            return None
        keys = [c.key for c in sheet.columns]
        reading = [keys.index(k) for k in self._reading_keys() if k in keys]
        last = typing_row(sheet.row_count, reading,
                          [sheet.columns[c].required for c in reading], sheet.text)
        return last if last is not None and self._only_readings_blank(last, reading) else None

    def _only_readings_blank(self, row: int, reading: list[int]) -> bool:
        """Every cell of ``row`` reads, but its blank reading cells (and the blank cells of
        a column the analysis waits for)."""
        sheet = self.sheet
        allowed = set(reading) | {sheet.column_index(k) for k in self._blank_too(sheet)}
        for c in range(sheet.column_count):
            if c in allowed and not sheet.text(row, c).strip():
                continue
            if sheet.cell_error(row, c) is not None:
                return False
        return True

    def _blank_too(self, sheet: ReadingsSheet) -> tuple[str, ...]:
        """The column the analysis waits for (:meth:`awaited_column`), whose blank cells a
        row being typed may have too."""
        if isinstance(sheet.rows, NumericRows):
            return ()
        awaited = self.awaited_column(sheet)
        return () if awaited is None else (awaited.key,)

    def _without_waiting_rows(self, parsed: ParsedReadings,
                              sheet: ReadingsSheet | None = None,
                              planned: int | None = None) -> ParsedReadings:
        """The readings less the rows at the end that wait for their reading (the plan's or
        the nominal step's cells filled, no reading yet), and the plan's row ``planned``
        waiting for the next one: a row waiting is not a bad row."""
        return _without_waiting_rows(parsed, self.sheet if sheet is None else sheet,
                                     self._reading_keys(), planned)

    # -- analysis -----------------------------------------------------------
    def schedule_refresh(self) -> None:
        self._timer.start()

    def set_capturing(self, on: bool) -> None:
        """Readings from an instrument start (analysis off the GUI thread, columns widened
        by the capture only) or stop (the columns fitted to their contents again)."""
        if on == self.capturing:
            return
        self.capturing = on
        if on:
            self.view.hold_columns()
        else:
            self._fit_columns()

    def refresh(self) -> None:
        """Parse the readings and analyse them now (on a worker for large sheets, and while
        capturing)."""
        self._timer.stop()
        if not self.capturing:
            self._fit_columns()
        self._generation += 1
        # the readings as they are now: the analysis parses these, wherever it runs, and
        # they stay with its result (edits made while a worker analyses never reach them)
        sheet = self.sheet.snapshot()
        planned = self.planned_row()  # the plan's row waiting in the middle (cleared)
        typing = self.typing_row(), self._blank_too(sheet)  # a reading being typed (row81)
        if sheet.row_count > THREAD_THRESHOLD_ROWS or self.capturing:
            if not self.capturing:
                self._set_busy(True, tr("Analysing {rows} readings …").format(
                    rows=sheet.row_count))
            self.workers.start(
                _AnalysisTask(self.kind, sheet, dict(self._settings), self._generation,
                              self._signals, self.prepare_display, lambda: self._generation,
                              self.workers,
                              self._reading_keys() if sheet.row_count <= PLAN_ROWS else (),
                              planned, self.printed_details(), typing))
            return
        parsed = self._without_waiting_rows(sheet.parse(), sheet, planned)
        parsed, in_progress = row_in_progress(parsed, typing[0], self._reading_keys(),
                                              self.kind.columns, typing[1], sheet.text)
        settings = dict(self._settings)
        result, error, refused = _run_analysis(self.kind, parsed, settings, in_progress)
        self._shown_generation = self._generation
        self.result_settings, self.result_sheet = settings, sheet
        self._finish(parsed, result, error, _prepare_display(self.prepare_display, result),
                     refused=refused, typing=in_progress)

    @property
    def analysis_pending(self) -> bool:
        """Whether the readings or settings changed after the analysis of the result shown
        began: an edit waits for its analysis (the 0-ms timer), or a newer analysis still
        runs on a worker. ``result`` is then not the analysis of what the sheet and the
        form hold now."""
        return self._timer.isActive() or self._shown_generation != self._generation

    @property
    def reading_file(self) -> bool:
        """A file is being read on a worker; its readings replace the sheet's when read."""
        return self._import_pending

    def analyse_if_due(self) -> bool:
        """An edit still waiting for its analysis is analysed now (on a worker where the
        sheet is large or readings are being captured: then not yet done). True when the
        result shown is the analysis of the current readings and settings and no file is
        being read into the sheet: what a certificate of it may be issued from."""
        if self._timer.isActive():
            self.refresh()
        return not self.analysis_pending and not self._import_pending

    def _on_task_cancelled(self, _generation: int) -> None:
        self.cancelled_analyses += 1

    def _on_task_finished(self, generation: int, payload: Any, error: str) -> None:
        if generation == self._generation:  # a newer edit supersedes this result
            if not self._import_pending:  # a file being read keeps the window busy
                self._set_busy(False)
            parsed, result, display, settings, sheet, shown, refused, typing = payload
            self._shown_generation = generation
            self.result_settings, self.result_sheet = settings, sheet
            self._finish(parsed, result, error, display, shown, refused, typing)

    def _next_text(self) -> str:
        """"next: target 120°, run 3 ↓" with a plan; "next: row 57" without."""
        plan = self.entry_plan()
        got = None if plan is None else self._plan_rows(plan)
        if got is None:
            waiting = self.waiting_row()  # the row a take fills (app/capture/panel.py)
            row = waiting if waiting is not None else self.sheet.row_count
            return tr("next: row {row}").format(row=row + 1)
        text = translated(plan.next_text(got[0], self._reading_keys()))
        done, total = plan.progress(got[0], self._reading_keys())
        return f"{text} ({done}/{total})"

    def _waiting_in_the_middle(self, parsed: ParsedReadings) -> int | None:
        """The row the next reading goes to (:meth:`planned_row`) when it is one in the
        middle whose reading was cleared, left out of ``parsed`` while rows after it are in:
        said in the result strip, as the reason it is not in the result (day review 64 P4).
        None otherwise (the rows at the end waiting are the usual next points)."""
        row = self.planned_row()
        if row is None or parsed.n == 0:
            return None
        rows = np.asarray(parsed.row_index)
        if (rows == row).any() or not (rows > row).any():
            return None
        columns = self.table_model.reading_columns
        if not columns or any(self.sheet.text(row, c).strip() for c in columns):
            return None
        return row

    @staticmethod
    def _readings_count(parsed: ParsedReadings, result: Any,
                        awaiting: tuple[int, str] | None = None, typing: bool = False) -> str:
        """"Readings — 7 used", or with a run in progress "Readings — 7 taken, 4 used": the
        figures' readings counted, not those of the run whose readings enter no figure yet
        (day review 74 F9: "7 used" while the summary said run 2's 3 enter no figure).
        ``awaiting``: the rows whose only want is the column the analysis waits for
        (:meth:`awaited_column`) and what they wait for: "Readings — 24 taken, waiting for
        the face deviations" (live81: "0 used" beside a table full of readings read as
        "my readings were thrown away"). ``typing``: a row a reading is being typed into,
        taken and in no figure yet (row81)."""
        typed = int(typing)
        if awaiting is not None and awaiting[0]:
            return tr("Readings — {taken} taken, {waiting}").format(
                taken=parsed.n + awaiting[0] + typed, waiting=awaiting[1])
        incomplete = getattr(result, "incomplete", None)
        waiting = len(incomplete.rows) if incomplete is not None else 0
        # and the readings the analysis left out (positioning's far beyond the limit: live76 F7)
        waiting += len(getattr(result, "left_out", ()) or ())
        if waiting or typed:
            return tr("Readings — {taken} taken, {used} used").format(
                taken=parsed.n + typed, used=parsed.n - waiting)
        return tr("Readings — {used} used").format(used=parsed.n)

    def awaited_column(self, sheet: ReadingsSheet) -> AwaitedColumn | None:
        """A column the analysis cannot go without that no row of ``sheet`` has filled yet,
        with the one sentence (translated) that says what it waits for and where it comes
        from: its blank cells are then not bad cells (not red, not counted as such) and the
        sentence is the reason there is no result (the polygon's face deviations before its
        certificate is loaded: plan80). None (the default): every blank cell of a column
        that needs a value is a bad cell."""
        return None

    def _awaited(self, parsed: ParsedReadings, error: str,
                 result: Any) -> tuple[list[Any], str, tuple[int, str] | None]:
        """The bad cells of ``parsed`` less the blank ones of the column the analysis waits
        for (:meth:`awaited_column`), marked so in the table; ``error``, with no result
        the sentence that says what it waits for; and (the rows that want nothing but that
        column, what they wait for), for the readings' caption (None: none awaited)."""
        sheet = self.result_sheet
        awaited = None if isinstance(sheet.rows, NumericRows) else self.awaited_column(sheet)
        self.table_model.set_awaited_columns(
            {} if awaited is None else {sheet.column_index(awaited.key): awaited.reason})
        if awaited is None:
            return list(parsed.errors), error, None

        def blank_awaited(e: Any) -> bool:
            return e.column_key == awaited.key and not str(e.text).strip()

        errors = [e for e in parsed.errors if not blank_awaited(e)]
        wanting = {e.row for e in parsed.errors if blank_awaited(e)} - {e.row for e in errors}
        return (errors, (awaited.reason if result is None else error),
                (len(wanting), awaited.waiting))

    def _finish(self, parsed: ParsedReadings, result: Any, error: str, display: Any = None,
                shown: ShownAsPrinted | None = None, refused: str = "",
                typing: RowInProgress | None = None) -> None:
        # the blank cells of a column the analysis waits for: one sentence, not bad cells
        bad_cells, error, awaiting = self._awaited(parsed, error, result)
        self.parsed = parsed
        self.typing = typing  # the row a reading is being typed into (row81)
        self.display = display
        self.result = result
        self.problem = error
        # the setting the readings refuse, its field marked until the next analysis (the
        # readings and the other settings stay as typed: the reason stands in the pane)
        self.refused_setting = refused
        self.view.mark_setting(refused)
        input_warnings = []
        if bad_cells:
            rows = sorted({e.row + 1 for e in bad_cells})
            listed = ", ".join(map(str, rows[:8])) + (" …" if len(rows) > 8 else "")
            input_warnings.append(
                tr("{cells} cell(s) cannot be read (row {rows}); those rows are left out. Point "
                   "at a red cell to see why.").format(cells=len(bad_cells), rows=listed))
        waiting = self._waiting_in_the_middle(parsed)
        if waiting is not None:
            input_warnings.append(tr("The next reading goes to row {row}: row {row} waits for "
                                     "its reading and is left out until then.").format(
                                         row=waiting + 1))
        next_text = self._next_text()
        if self.plan_problem:
            input_warnings.append(tr("Entry plan: {reason}").format(
                reason=translated(self.plan_problem)))
        self.view.set_readings_caption(self._readings_count(parsed, result, awaiting,
                                                            typing is not None) + (
                tr(", {cells} bad cell(s)").format(cells=len(bad_cells))
                                             if bad_cells else ""))
        self.view.set_next_row(next_text)
        if result is None:
            self.shown = None  # (a million-sample result is not kept for nothing)
            self.clear_result()
            error = self.in_unit_text(error)
            no_result = tr("No result: {reason}").format(reason=error) if error else ""
            self.view.set_summary(no_result or tr("No readings yet."))
            # the reason once, in the pane: the bold line above it says only that there is
            # none (day review 67 F5: the same long sentence stood in both)
            self.view.set_verdict(tr("No result (the reason is below)") if error else "")
            self.view.set_figures({})
            self.view.set_warnings(input_warnings)
        else:
            def unit_text(text: str) -> str:  # in the window's language, then its unit
                return self.in_unit_text(text)

            incomplete = getattr(result, "incomplete", None)
            progress = (unit_text(incomplete.progress()) + "\n") if incomplete else ""
            # the figures the certificate prints, as it prints them (F2 of review 62)
            shown = self.shown_as_printed(result, shown)
            self._show_readout_decimals(shown.rounding)
            self.view.set_summary(progress + unit_text(shown.summary))
            verdict = unit_text(shown.verdict) if isinstance(self.kind, ShowsHeadline) else ""
            # the certificate's statement, before issuing; a reason the verdict already
            # gives (no U whatever the details: the kind's verdict says why) not said twice
            if shown.conformity is not None and not (
                    isinstance(shown.conformity, str) and translated(shown.conformity) in verdict):
                verdict = "\n".join(t for t in (verdict, conformity_text(shown.conformity)) if t)
            self.view.set_verdict(verdict, conformity_statement(shown.conformity))
            printed = {}  # by the name shown; a figure shown in another unit: its value
            for name, text in shown.printed.items():
                header, factor = header_in_unit(name, self.angle_unit)
                if factor == 1.0:
                    printed[header] = text
            self.view.set_figures(figures_in_unit(self.kind.headline_figures(result),
                                                  self.angle_unit), printed)
            self.view.set_warnings(input_warnings + [unit_text(w) for w in
                                                     getattr(result, "warnings", [])]
                                   + ([unit_text(incomplete.progress())] if incomplete else []))
            self.show_result(result)
        self.analysed.emit()
