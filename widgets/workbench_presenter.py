"""The presenter every workbench shares: owns the readings, runs the analysis on
every edit and pushes the result to its passive view."""

from __future__ import annotations

import logging
from pathlib import Path
from typing import Any

from PySide6.QtCore import QObject, QRunnable, QThreadPool, QTimer, Signal
from PySide6.QtGui import QUndoStack
from PySide6.QtWidgets import QHeaderView

from models.analysis_kind import AnalysisKind
from models.project import WorkbenchState
from models.readings import ParsedReadings, ReadingsSheet
from models.tabular_import import map_columns, read_table
from widgets.readings_table_model import ReadingsTableModel
from widgets.workbench_view import WorkbenchView

log = logging.getLogger(__name__)

SAMPLES_DIR = Path(__file__).resolve().parent.parent / "resources" / "samples"

# Analyses of more used rows than this run on a worker thread.
THREAD_THRESHOLD_ROWS = 20_000


class _TaskSignals(QObject):
    finished = Signal(int, object, str)


class _AnalysisTask(QRunnable):
    def __init__(self, kind: AnalysisKind, parsed: ParsedReadings, settings: dict[str, Any],
                 generation: int, signals: _TaskSignals) -> None:
        super().__init__()
        self._args = (kind, parsed, settings, generation, signals)

    def run(self) -> None:
        kind, parsed, settings, generation, signals = self._args
        result, error = _run_analysis(kind, parsed, settings)
        signals.finished.emit(generation, result, error)


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
        self._signals = _TaskSignals()
        self._signals.finished.connect(self._on_task_finished)
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
        self.table_model.replace_all(rows, f"Import {Path(path).name}")
        self.refresh()

    def load_sample(self) -> None:
        self.import_file(SAMPLES_DIR / self.kind.sample_file)
        self.undo_stack.clear()
        self.mark_saved()

    # -- analysis -----------------------------------------------------------
    def schedule_refresh(self) -> None:
        self._timer.start()

    def refresh(self) -> None:
        """Parse the readings and analyse them now (or on a worker for large runs)."""
        self._timer.stop()
        self._generation += 1
        parsed = self.sheet.parse()
        self.parsed = parsed
        if parsed.n > THREAD_THRESHOLD_ROWS:
            self.view.set_summary(f"Analysing {parsed.n} readings …")
            QThreadPool.globalInstance().start(
                _AnalysisTask(self.kind, parsed, dict(self._settings), self._generation,
                              self._signals))
            return
        result, error = _run_analysis(self.kind, parsed, dict(self._settings))
        self._finish(result, error)

    def _on_task_finished(self, generation: int, result: Any, error: str) -> None:
        if generation == self._generation:  # a newer edit supersedes this result
            self._finish(result, error)

    def _finish(self, result: Any, error: str) -> None:
        parsed = self.parsed
        assert parsed is not None
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
