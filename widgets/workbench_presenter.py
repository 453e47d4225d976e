"""The presenter every workbench shares: owns the readings, runs the analysis on
every edit and pushes the result to its passive view."""

from __future__ import annotations

import contextlib
import gc
import logging
from pathlib import Path
from typing import Any

from PySide6.QtCore import QObject, QRunnable, QThreadPool, QTimer, Signal
from PySide6.QtGui import QUndoStack
from PySide6.QtWidgets import QHeaderView

from models.analysis_kind import AnalysisKind
from models.project import WorkbenchState
from models.readings import ParsedReadings, ReadingsSheet
from models.tabular_import import TableImportError, map_columns, read_table
from widgets.readings_table_model import ReadingsTableModel
from widgets.workbench_view import WorkbenchView

log = logging.getLogger(__name__)

SAMPLES_DIR = Path(__file__).resolve().parent.parent / "resources" / "samples"

# Sheets of more rows than this are parsed and analysed on a worker thread.
THREAD_THRESHOLD_ROWS = 20_000
# Files larger than this are read on a worker thread.
THREAD_THRESHOLD_BYTES = 1_000_000


class _TaskSignals(QObject):
    """Owned by the presenter; workers emit through it back to the GUI thread."""

    finished = Signal(int, object, str)
    imported = Signal(object, str, str)


class _AnalysisTask(QRunnable):
    """Parse and analyse a large sheet on a worker thread."""

    def __init__(self, kind: AnalysisKind, sheet: ReadingsSheet, settings: dict[str, Any],
                 generation: int, signals: _TaskSignals) -> None:
        super().__init__()
        self._args = (kind, sheet, settings, generation, signals)

    def run(self) -> None:
        kind, sheet, settings, generation, signals = self._args
        parsed = sheet.parse()
        result, error = _run_analysis(kind, parsed, settings)
        _emit_if_alive(signals.finished, generation, (parsed, result), error)


class _ImportTask(QRunnable):
    """Read and map a large file on a worker thread."""

    def __init__(self, kind: AnalysisKind, path: str, signals: _TaskSignals) -> None:
        super().__init__()
        self._args = (kind, path, signals)

    def run(self) -> None:
        kind, path, signals = self._args
        # Millions of new row lists would trigger full cyclic-GC passes that hold the GIL
        # for up to half a second each and stall the window; rows of strings hold no
        # cycles, so the collector rests while they are built.
        with _cyclic_gc_paused():
            try:
                rows = map_columns(read_table(path), kind.columns)
            except TableImportError as exc:
                _emit_if_alive(signals.imported, None, path, str(exc))
                return
            gc.freeze()  # keep the new rows out of later full passes too
        _emit_if_alive(signals.imported, rows, path, "")


def _emit_if_alive(signal, *args) -> None:
    """Deliver a worker's result; if its workbench was closed meanwhile, drop it."""
    with contextlib.suppress(RuntimeError):
        signal.emit(*args)


@contextlib.contextmanager
def _cyclic_gc_paused():
    was_enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was_enabled:
            gc.enable()


def _run_analysis(kind: AnalysisKind, parsed: ParsedReadings,
                  settings: dict[str, Any]) -> tuple[Any, str]:
    try:
        return kind.analyze(parsed, settings), ""
    except ValueError as exc:  # bad input: a message for the technician
        return None, str(exc)
    except Exception as exc:  # noqa: BLE001 - a bug must not take the typed readings with it
        log.exception("analysis failed")
        return None, f"internal error while analysing ({type(exc).__name__}: {exc})"


class WorkbenchPresenter(QObject):
    """Base presenter. Subclasses build their view's fields and draw results.

    ``result`` holds the last analysis result (``None`` when the readings
    cannot be analysed; ``problem`` then says why).
    """

    modified_changed = Signal(bool)
    analysed = Signal()
    import_failed = Signal(str)

    def __init__(self, kind: AnalysisKind, view: WorkbenchView, parent=None) -> None:
        super().__init__(parent if parent is not None else view)  # lives as long as its view
        self.kind = kind
        self.view = view
        self.sheet = ReadingsSheet(kind.columns)
        self.undo_stack = QUndoStack(self)
        self.table_model = ReadingsTableModel(self.sheet, self.undo_stack, self)
        self.view.table.setModel(self.table_model)
        header = self.view.table.horizontalHeader()
        header.setSectionResizeMode(QHeaderView.ResizeMode.ResizeToContents)
        header.setStretchLastSection(True)
        self._settings: dict[str, Any] = kind.settings_with_defaults(None)
        self._settings_modified = False
        self.result: Any = None
        self.parsed: ParsedReadings | None = None
        self.problem = ""
        self._generation = 0
        self._signals = _TaskSignals(self)
        self._signals.finished.connect(self._on_task_finished)
        self._signals.imported.connect(self._on_import_finished)
        self.busy = False
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(0)
        self._timer.timeout.connect(self.refresh)
        self.build_settings()
        self.view.settings.set_values(self._settings)
        self.table_model.sheet_changed.connect(self.schedule_refresh)
        self.view.settings.changed.connect(self._on_settings_edited)
        self.undo_stack.cleanChanged.connect(self._on_clean_changed)

    # -- subclass hooks ---------------------------------------------------
    def build_settings(self) -> None:
        """Add the set-up fields to ``self.view.settings``."""

    def show_result(self, result: Any) -> None:
        """Draw a fresh result in the view."""

    def clear_result(self) -> None:
        """Empty the plots (the readings cannot be analysed)."""

    # -- state ------------------------------------------------------------
    @property
    def settings(self) -> dict[str, Any]:
        return dict(self._settings)

    def set_settings(self, settings: dict[str, Any]) -> None:
        self._settings = self.kind.settings_with_defaults(settings)
        self.view.settings.set_values(self._settings)
        self._settings_modified = True
        self._emit_modified()
        self.schedule_refresh()

    def _on_settings_edited(self) -> None:
        self._settings.update(self.view.settings.values())
        self._settings_modified = True
        self._emit_modified()
        self.schedule_refresh()

    @property
    def is_modified(self) -> bool:
        return self._settings_modified or not self.undo_stack.isClean()

    def mark_modified(self) -> None:
        """Count the current state as unsaved (e.g. work recovered after a crash)."""
        self._settings_modified = True
        self._emit_modified()

    def mark_saved(self) -> None:
        self._settings_modified = False
        self.undo_stack.setClean()
        self._emit_modified()

    def _on_clean_changed(self, _clean: bool) -> None:
        self._emit_modified()

    def _emit_modified(self) -> None:
        self.modified_changed.emit(self.is_modified)

    def state(self) -> WorkbenchState:
        rows = self.sheet.copy_rows()
        while rows and not any(c.strip() for c in rows[-1]):
            rows.pop()
        return WorkbenchState(rows, dict(self._settings))

    def load_state(self, state: WorkbenchState) -> None:
        """Replace readings and settings (a project was opened); clears the undo history."""
        self._settings = self.kind.settings_with_defaults(state.settings)
        self.view.settings.set_values(self._settings)
        self.table_model.apply_replace(state.rows)
        self.undo_stack.clear()
        self.mark_saved()
        self.refresh()

    def import_file(self, path: str | Path) -> None:
        """Replace the readings with a CSV/XLSX file's (undoable). Raises TableImportError."""
        rows = map_columns(read_table(path), self.kind.columns)
        self.table_model.replace_all(rows, f"Import {Path(path).name}", checked=True)
        self._fit_columns()
        self.refresh()

    def start_import(self, path: str | Path) -> None:
        """Import a file, on a worker thread when it is large; errors go to ``import_failed``."""
        path = str(path)
        try:
            large = Path(path).stat().st_size > THREAD_THRESHOLD_BYTES
        except OSError:
            large = False
        if not large:
            try:
                self.import_file(path)
            except TableImportError as exc:
                self.import_failed.emit(str(exc))
            return
        self._set_busy(True, f"Reading {Path(path).name} …")
        QThreadPool.globalInstance().start(_ImportTask(self.kind, path, self._signals))

    def _on_import_finished(self, rows, path: str, error: str) -> None:
        self._set_busy(False)
        if rows is None:
            self.import_failed.emit(error)
            return
        self.table_model.replace_all(rows, f"Import {Path(path).name}", checked=True)
        self._fit_columns()
        self.refresh()

    def _fit_columns(self) -> None:
        """Size columns to their contents, except for huge sheets where that scan stalls."""
        header = self.view.table.horizontalHeader()
        mode = (QHeaderView.ResizeMode.Interactive if self.sheet.row_count > THREAD_THRESHOLD_ROWS
                else QHeaderView.ResizeMode.ResizeToContents)
        if header.sectionResizeMode(0) != mode:
            header.setSectionResizeMode(mode)

    def _set_busy(self, busy: bool, text: str = "") -> None:
        self.busy = busy
        self.view.set_busy(busy)
        if busy and text:
            self.view.set_summary(text)

    def load_sample(self) -> None:
        self.import_file(SAMPLES_DIR / self.kind.sample_file)
        self.undo_stack.clear()
        self.mark_saved()

    # -- analysis -----------------------------------------------------------
    def schedule_refresh(self) -> None:
        self._timer.start()

    def refresh(self) -> None:
        """Parse the readings and analyse them now (on a worker for large sheets)."""
        self._timer.stop()
        self._generation += 1
        if self.sheet.row_count > THREAD_THRESHOLD_ROWS:
            self._set_busy(True, f"Analysing {self.sheet.row_count} readings …")
            QThreadPool.globalInstance().start(
                _AnalysisTask(self.kind, self.sheet, dict(self._settings), self._generation,
                              self._signals))
            return
        parsed = self.sheet.parse()
        result, error = _run_analysis(self.kind, parsed, dict(self._settings))
        self._finish(parsed, result, error)

    def _on_task_finished(self, generation: int, payload: Any, error: str) -> None:
        if generation == self._generation:  # a newer edit supersedes this result
            self._set_busy(False)
            parsed, result = payload
            self._finish(parsed, result, error)

    def _finish(self, parsed: ParsedReadings, result: Any, error: str) -> None:
        self.parsed = parsed
        self.result = result
        self.problem = error
        input_warnings = []
        if parsed.errors:
            rows = sorted({e.row + 1 for e in parsed.errors})
            shown = ", ".join(map(str, rows[:8])) + (" …" if len(rows) > 8 else "")
            input_warnings.append(
                f"{len(parsed.errors)} cell(s) cannot be read (row {shown}); those rows are "
                "left out. Point at a red cell to see why.")
        self.view.set_readings_caption(
            f"Readings — {parsed.n} used" + (f", {len(parsed.errors)} bad cell(s)"
                                             if parsed.errors else ""))
        if result is None:
            self.clear_result()
            self.view.set_summary(f"No result: {error}" if error else "No readings yet.")
            self.view.set_warnings(input_warnings)
        else:
            self.view.set_summary(self.kind.summary(result))
            self.view.set_warnings(input_warnings + list(getattr(result, "warnings", [])))
            self.show_result(result)
        self.analysed.emit()
