"""Project control: the project file (new, open, save, save as, the recent files), a file
dropped on the window, the autosave of unsaved work (off the GUI thread for large sheets)
and the offer of the work a window left when it did not close normally.

A presenter with no widgets: it asks its view (the calls of :class:`ProjectView`) for a
file name or an answer, and to show the title, the recent files and messages; the
workbench presenters hold the readings and settings. Tested with a mock view, no window.
"""

from __future__ import annotations

import logging
import os
import threading
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any, Protocol

from PySide6.QtCore import QObject, QStandardPaths, QTimer, Signal

from models import __version__
from models.project.file import (
    READINGS_SOURCE,
    Project,
    ProjectFileError,
    WorkbenchState,
    check_project,
    file_sha256,
    load_project,
    project_from_json,
    project_to_json,
    save_project,
)
from models.project.recovery import RecoveryStore
from models.project.save_lock import STALE_SECONDS, LockInTheWay, ProjectFileBusy, SaveLock
from models.readings.sheet import NumericRows
from widgets.i18n import explained, tr, translated
from widgets.workbench_presenter import WorkbenchPresenter
from widgets.workers import application_workers

__all__ = ["ProjectPresenter", "ProjectView", "default_recovery_store"]

log = logging.getLogger(__name__)

AUTOSAVE_DELAY_MS = 3_000  # an edit is autosaved this soon (at most every 3 s while typing)
AUTOSAVE_THREAD_ROWS = 50_000  # sheets larger than this are autosaved off the GUI thread …
#: … and so is a raw capture of more frames than this (a day's capture, 2 M frames and
#: 66 MB, held the window 0.5 … 3 s at every autosave: #62 review F6); a few minutes of
#: frames write in the GUI thread in well under the 10 ms a repaint may wait
AUTOSAVE_THREAD_FRAMES = 20_000
AUTOSAVE_DELAY_LARGE_MS = 20_000  # … and less often
MAX_RECENT = 8
RECENT_FILES_KEY = "recent_files"
#: files that may be dropped on the window: readings, or a project (.json)
#: an autosave's detail: the keys of the workbenches whose rows were changed after the
#: project file was saved (the file is then not named as their source: day review 67 F4)
UNSAVED_READINGS = "unsaved_readings"
DROPPABLE = (".csv", ".txt", ".tsv", ".xlsx", ".xlsm", ".json")


def default_recovery_store() -> RecoveryStore:
    folder = os.environ.get("ANGLEBENCH_DATA_DIR") or QStandardPaths.writableLocation(
        QStandardPaths.StandardLocation.AppDataLocation)
    return RecoveryStore(Path(folder or Path.home() / ".anglebench"))



def _in_the_way(exc: LockInTheWay) -> str:
    """What stops every save of the project (a file at its lock's name) and what to do."""
    if exc.kind == "stale":
        return tr(
            "{lock} is the lock of a save that ended {minutes} minutes ago, but it belongs "
            "to user {owner} and cannot be removed from here ({error}). Nothing was "
            "written; your readings are still here. Ask {owner} or an administrator to "
            "delete {lock}, then save again, or save under another name (File › Save "
            "as).").format(lock=exc.path, minutes=int((exc.age or 0) // 60),
                            owner=exc.owner, error=exc.error)
    if exc.kind == "future":
        return tr(
            "{lock} is dated {date}, later than this computer's clock (a computer whose clock "
            "is ahead made it, or this clock was set back), so its age cannot be told. "
            "Nothing was written; your readings are still here. If no other window or "
            "computer is saving this project, delete {lock} and save again; otherwise save "
            "again in {minutes} minutes: a lock left unchanged that long is taken as left "
            "over.").format(lock=exc.path, minutes=int(STALE_SECONDS // 60),
                            date=time.strftime("%Y-%m-%d %H:%M:%S",
                                               time.localtime(exc.dated or 0)))
    kind = {"link": tr("a link"), "pipe": tr("a named pipe"),
            "folder": tr("a folder")}.get(exc.kind, tr("not a regular file"))
    return tr(
        "{lock} is in the way of the project's lock: it is {kind} (user {owner}), not a "
        "lock AngleBench made. Nothing was written; your readings are still here. Remove "
        "{lock}, then save again.").format(lock=exc.path, kind=kind, owner=exc.owner)

class ProjectView(Protocol):
    """What the project presenter asks of the window."""

    def ask_open_path(self, folder: str) -> str:
        """A project file to open (empty if cancelled)."""

    def ask_save_path(self, folder: str) -> str:
        """A file to save the project in (empty if cancelled)."""

    def ask_save_changes(self, question: str = "") -> bool | None:
        """Save the unsaved changes first? True: save, False: discard them, None: cancel."""

    def ask_recover(self, name: str, when: str) -> bool:
        """Restore the unsaved work of ``name``, autosaved ``when``?"""

    def ask_overwrite_changed(self, name: str) -> bool | None:
        """The project file ``name`` was changed on disk since this window opened or saved
        it: True: replace it; False: save under another name; None: cancel."""

    def tell(self, title: str, text: str) -> None: ...

    def show_status(self, text: str, milliseconds: int) -> None: ...

    def show_title(self, title: str) -> None: ...

    def show_recent(self, paths: list[str]) -> None:
        """The recent files, newest first (each one opens with ``open_project``)."""

    def show_workbench(self, key: str) -> None:
        """Bring the workbench ``key`` to the front."""

    def show_autosave_problem(self, text: str) -> None:
        """A warning that stays in sight until it is cleared (``text`` empty): the unsaved
        work is not being autosaved."""


class SettingsStore(Protocol):
    def value(self, key: str, default: Any = None) -> Any: ...

    def setValue(self, key: str, value: Any) -> None: ...  # noqa: N802 - QSettings' name


class ProjectPresenter(QObject):
    """The project of one window: ``presenters`` hold its workbenches, ``current`` gives
    the workbench in front (a readings file dropped goes there)."""

    #: an autosave ended: "" when it was written, else why it was not (emitted from the
    #: thread that wrote it; handled on the window's)
    autosave_finished = Signal(str)

    def __init__(self, view: ProjectView, presenters: Sequence[WorkbenchPresenter],
                 recovery: RecoveryStore, store: SettingsStore,
                 current: Callable[[], WorkbenchPresenter], parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.view = view
        self.presenters = list(presenters)
        self.recovery = recovery
        self.store = store
        self.current = current
        self.path: Path | None = None
        #: SHA-256 of ``path`` as this window last read or wrote it (None: not known): a
        #: save over a file changed since (another window, a colleague, a program) asks
        self.disk_sha256: str | None = None
        #: raises OutputRefused when a path is a file the register issued, a certificate's
        #: PDF, DCC or results file (the window sets it: app/issued_outputs.py)
        self.refuse_issued: Callable[[str], None] = lambda _path: None
        self.metadata: dict = {}
        #: by workbench, the certificates whose issue stored their details in the project
        #: since it was last saved, opened or begun (:meth:`details_issued`)
        self.issued_details: dict[str, list[str]] = {}
        #: the instruments' raw frames, saved and opened with the project (the window sets
        #: its capture panel's raw_capture and load_raw_capture)
        self.raw_capture: Callable[[], dict] = dict
        self.load_raw_capture: Callable[[dict], None] = lambda _raw: None
        #: a new project's settings of a workbench (the window sets it: the test plan saved
        #: with the lab defaults)
        self.new_settings: Callable[[str], dict] = lambda _key: {}
        #: another project was put in the window (New, Open, Recover, a register record):
        #: the window ends a pending Amend… or Replace… with it (rev62 F1)
        self.project_replaced: Callable[[], None] = lambda: None
        #: what the window is doing with this project, shown in its title ("" nothing: the
        #: window sets it to the pending Amend… or Replace…, rev62 F3)
        self.title_note: Callable[[], str] = lambda: ""
        #: where the readings of an untitled project came from, as the certificate it was
        #: issued with named them (the register's record; None: typed in the window)
        self.readings_source: str | None = None
        self.autosave_timer = QTimer(self)
        self.autosave_timer.setSingleShot(True)
        self.autosave_timer.setInterval(AUTOSAVE_DELAY_MS)
        self.autosave_timer.timeout.connect(self._autosave_when_due)
        self._unsaved_since = 0.0  # time.monotonic() of the first edit not yet autosaved
        self._autosave_thread: threading.Thread | None = None
        #: why the last autosave failed ("" when it did not): shown until a save succeeds
        self.autosave_problem = ""
        self.autosave_finished.connect(self._autosave_reported)
        for presenter in self.presenters:
            presenter.modified_changed.connect(self.update_title)
            presenter.undo_stack.indexChanged.connect(self._schedule_autosave)
            presenter.modified_changed.connect(self._schedule_autosave)
            table = getattr(getattr(presenter, "view", None), "table", None)
            typing = getattr(table, "typing", None)
            if typing is not None and hasattr(typing, "connect"):  # a value being typed
                typing.connect(self._schedule_autosave)

    def start(self) -> None:
        """This window's autosave claimed (told when it cannot be); title and recent files shown."""
        self.view.show_recent(self.recent_files())
        try:
            self.recovery.claim()
        except OSError as exc:
            self.view.show_status(tr("Autosave is off: {reason}").format(reason=exc), 15000)
        for presenter in self.presenters:  # the window opens on a new project
            saved = self.new_settings(presenter.kind.key)
            if saved and not presenter.is_modified and presenter.sheet.row_count == 0:
                presenter.load_state(WorkbenchState(settings={**presenter.settings, **saved}))
        self.update_title()

    def close(self) -> None:
        """The window closes: no more autosaves; the last one finished; the autosave let go."""
        self.autosave_timer.stop()
        if self._autosave_thread is not None:
            self._autosave_thread.join(timeout=30)
        self.recovery.release()

    # -- the project --------------------------------------------------------------
    @property
    def is_modified(self) -> bool:
        return any(p.is_modified for p in self.presenters)

    def project(self, raw: dict | None = None) -> Project:
        """The project as it is now (``raw``: the raw capture, when already taken)."""
        return Project({p.kind.key: p.state() for p in self.presenters}, dict(self.metadata),
                       self.raw_capture() if raw is None else raw)

    def apply_project(self, project: Project, name: str = "") -> None:
        """``project`` in the window; ``name``: its file's name ("" none, or an untitled
        project's autosave), what its readings are said to be from when it does not say
        where they came from (models/certificate/stored_origin.py)."""
        self.project_replaced()
        self.readings_source = None
        self.issued_details = {}
        # the details first: the workbenches' plots draw the tolerance they set
        self.metadata = dict(project.metadata)
        self.metadata.pop("autosaved_at", None)
        self.metadata.pop("project_path", None)
        self.metadata.pop("pending_edits", None)
        self.metadata.pop("project_sha256", None)
        self.metadata.pop(UNSAVED_READINGS, None)
        for presenter in self.presenters:
            presenter.load_state(project.workbenches.get(presenter.kind.key, WorkbenchState()),
                                 name)
        self.load_raw_capture(project.raw_capture)

    def update_title(self, *_args) -> None:
        name = self.path.name if self.path else tr("untitled")
        note = self.title_note()
        self.view.show_title(f"AngleBench {__version__} — {note + ' — ' if note else ''}"
                             f"{name}{' *' if self.is_modified else ''}")

    def confirm_discard(self, question: str = "") -> bool:
        """True when there is nothing unsaved, or the user saved it or lets it go;
        ``question``: what the window asks, naming what replaces the work (else its own:
        when all that differs from the file is the certificate details an issue stored,
        it says so, :meth:`issued_details_question`)."""
        if not self.is_modified:
            return True
        question = question or self.issued_details_question()
        answer = self.view.ask_save_changes(question) if question else \
            self.view.ask_save_changes()
        if answer:
            return self.save()
        return answer is False

    def details_issued(self, workbench: str, number: str) -> None:
        """Certificate ``number`` of ``workbench`` was issued with details that its issue
        stored in the project (the details dialog's, the number left out: the next
        certificate of the project starts from them), not yet in the project's file."""
        numbers = self.issued_details.setdefault(workbench, [])
        if number not in numbers:
            numbers.append(number)

    def issued_details_question(self) -> str:
        """What to ask before the work goes when the only difference between the project
        and its file is the certificate details issues stored (:meth:`details_issued`):
        which certificates, and that the register keeps them as issued; "" otherwise
        (the generic question). gui78 (live78 F9): "Unsaved changes — Save the changes to
        the project first?" right after an issue, though the user changed nothing after
        the save but the details typed for the certificate."""
        if not self.issued_details or self.path is None:
            return ""
        try:
            saved = load_project(self.path, {p.kind.key: p.kind for p in self.presenters})
        except (ProjectFileError, OSError, ValueError):
            return ""
        now = self.project()
        details = ("certificates", "certificates_last")
        now.metadata = {**{k: v for k, v in now.metadata.items() if k not in details},
                        **{k: v for k, v in saved.metadata.items() if k in details}}
        if project_to_json(now) != project_to_json(saved):
            return ""  # readings, settings or more changed too: the generic question
        numbers = [n for key in self.issued_details for n in self.issued_details[key]]
        return tr("Issuing {numbers} stored the certificate details entered for it in this "
                  "project; they are not yet saved in {file}. The register keeps them with "
                  "the certificate as issued; nothing else was changed since the project was "
                  "saved. Save the details in the project (the next certificate of this "
                  "project starts from them)?").format(numbers=", ".join(numbers),
                                                       file=self.path.name)

    def new_project(self) -> None:
        if not self.confirm_discard():
            return
        # the settings saved with the lab defaults (the test plans) are a new project's
        self.apply_project(Project(workbenches={
            p.kind.key: WorkbenchState(settings=dict(self.new_settings(p.kind.key)))
            for p in self.presenters}))
        self.path = None
        self.disk_sha256 = None
        self.update_title()

    def open_project_dialog(self) -> None:
        path = self.view.ask_open_path(self.last_dir())
        if path:
            self.open_project(path)

    def open_project(self, path: str | Path) -> bool:
        """Open a project; a damaged or newer file leaves the current work untouched."""
        if not self.confirm_discard():
            return False
        try:
            project = load_project(path, self._kinds())
            check_project(project, self._kinds(), str(path))
        except ProjectFileError as exc:
            self.view.tell(tr("Cannot open project"),
                           tr("{reason}. Your current work is as it was.").format(reason=explained(exc)))
            return False
        self.apply_project(project, Path(path).name)
        self.path = Path(path)
        self.disk_sha256 = project.file_sha256
        self._add_recent(self.path)
        self._tell_repairs(project)
        self.update_title()
        self.view.show_status(tr("Opened {path}").format(path=path), 5000)
        return True

    def _tell_repairs(self, project: Project) -> None:
        """Text repaired as the file was read (a broken character) is said, cell by cell,
        and the project is unsaved work: it differs from its file."""
        if not project.repairs:
            return
        for presenter in self.presenters:
            presenter.mark_modified()
        shown = [translated(r) for r in project.repairs[:20]]
        if len(project.repairs) > 20:
            shown.append(tr("… and {count} more").format(count=len(project.repairs) - 20))
        self.view.tell(tr("Opened with repairs"), "\n".join(shown))

    def open_project_state(self, project_json: str, workbench: str,
                           question: str = "") -> bool:
        """Load the project behind a certificate (asking about unsaved work first, with
        ``question`` when given) and show its workbench; the project is untitled (saving it
        asks for a name), its readings' source the one the certificate named."""
        if not self.confirm_discard(question):
            return False
        try:
            project = project_from_json(project_json, "the register's record", self._kinds())
            check_project(project, self._kinds(), "the register's record")
        except ProjectFileError as exc:
            self.view.tell(tr("Cannot open"), explained(exc))
            return False
        self.apply_project(project)
        for presenter in self.presenters:  # the certificate's source, not the record's rows'
            presenter.table_model.forget_origin()
        self.path = None
        self.disk_sha256 = None
        # the certificate's "Readings:" (the project file's name; rev62 F4: an amendment
        # said "readings typed in AngleBench" of captured readings)
        source = self.metadata.pop(READINGS_SOURCE, None)
        self.readings_source = source if isinstance(source, str) and source else None
        self._tell_repairs(project)
        self.view.show_workbench(workbench)
        self.update_title()
        return True

    def _disk_sha256(self) -> str | None:
        """SHA-256 of the project's file as it is on disk now (None: a file that is gone,
        or cannot be read, is not asked about: the save says what happens)."""
        try:
            return file_sha256(self.path)
        except OSError:
            return None

    def _kinds(self) -> dict:
        return {p.kind.key: p.kind for p in self.presenters}

    def save(self) -> bool:
        if self.path is None:
            return self.save_as()
        return self.save_to(self.path)

    def save_as(self) -> bool:
        path = self.view.ask_save_path(self.last_dir())
        if not path:
            return False
        if not path.lower().endswith(".json"):  # the window's dialog added it (and asked)
            path += ".anglebench.json"
        return self.save_to(path)

    def save_to(self, path: str | Path) -> bool:
        """Save the project in ``path``; False when it was not saved (told, or cancelled).
        The project's own file changed on disk since this window read or wrote it is not
        replaced unasked.

        "Changed on disk?" and the write are one step under the file's lock
        (models.project.save_lock), which every AngleBench process respects: a Save
        pressed elsewhere at the same moment waits for this one's file, finds it changed
        and asks (both were checked before either wrote: one's readings were lost,
        nobody asked). The lock is let go while the question is asked; after "replace
        it", the file is checked again under the lock."""
        same = self.path is not None and Path(path) == self.path
        agreed = self.disk_sha256  # the file's version this window may replace unasked
        while True:
            lock = SaveLock(path)
            try:
                lock.acquire()
            except ProjectFileBusy as exc:
                self.view.tell(tr("Cannot save"), (tr(
                    "{path} is being saved from another window (computer {host}, process "
                    "{pid}). Nothing was written; your readings are still here: save again in "
                    "a moment.") if exc.host else tr(
                    "{path} is being saved from another window. Nothing was written; your "
                    "readings are still here: save again in a moment.")).format(
                        path=path, host=exc.host, pid=exc.pid))
                return False
            except LockInTheWay as exc:
                self.view.tell(tr("Cannot save"), _in_the_way(exc))
                return False
            try:
                current = self._disk_sha256() if same else None
                if current is None or current == agreed:
                    # a file this window did not read or write as its project may be an
                    # issued one, or a link to one (rev64 F1: a Save through the link
                    # p.anglebench.json -> r1.xlsx replaced an issued results file)
                    if (current is None or current != self.disk_sha256) \
                            and not self._may_replace(path):
                        return False
                    digest = self._write(path, lock)
                    if digest is None:
                        return False
                    break
            finally:
                lock.release()
            answer = self.view.ask_overwrite_changed(self.path.name)
            if answer is None:
                return False
            if answer is False:
                return self.save_as()
            agreed = current  # replace that version (checked again: a later one asks again)
        self.path = Path(path)
        self.disk_sha256 = digest
        self.issued_details = {}
        for presenter in self.presenters:
            presenter.mark_saved()
        self.recovery.discard()
        if self.autosave_problem:  # the work is safe in the project file now
            self.autosave_problem = ""
            self.view.show_autosave_problem("")
        self._add_recent(self.path)
        self.update_title()
        self.view.show_status(tr("Saved {path}").format(path=path), 5000)
        return True

    def _may_replace(self, path: str | Path) -> bool:
        """Whether ``path`` is no file the register issued (else told, nothing written)."""
        from models.project.output_guard import OutputRefused

        try:
            self.refuse_issued(os.fspath(path))
        except OutputRefused as exc:
            self.view.tell(tr("Cannot save"), tr("{path}: {reason}. Your readings are still here.")
                           .format(path=path, reason=explained(exc)))
            return False
        return True

    def _write(self, path: str | Path, lock: SaveLock) -> str | None:
        """Write the project (the lock held: touched between blocks of rows, so that a
        long save is never taken for a dead one's); its SHA-256, None when it failed
        (told: the work stays)."""
        try:
            return save_project(path, self.project(), lock.touch)
        except Exception as exc:  # noqa: BLE001 - any failure (UnicodeEncodeError,
            # MemoryError, a TypeError of a setting) is a save that did not happen: said,
            # and the work stays (an exception here closed the window unsaved)
            log.exception("save of %s failed", path)
            reason = (exc.strerror if isinstance(exc, OSError) else None) or explained(exc) \
                or type(exc).__name__
            self.view.tell(tr("Cannot save"), tr("{path}: {reason}. Your readings are still here.")
                           .format(path=path, reason=reason))
            return None

    # -- files dropped on the window ----------------------------------------------------
    @staticmethod
    def droppable(paths: Sequence[str]) -> list[str]:
        return [p for p in paths if p.lower().endswith(DROPPABLE)]

    def drop(self, path: str) -> None:
        """A readings file goes into the current workbench (one undo step); a project file
        opens (asking about unsaved work)."""
        if path.lower().endswith(".json"):
            self.open_project(path)
        else:
            self.current().start_import(path)  # large files are read off the GUI thread

    # -- recent files -------------------------------------------------------------------
    def recent_files(self) -> list[str]:
        value = self.store.value(RECENT_FILES_KEY, [])
        if isinstance(value, str):
            value = [value]
        return [str(v) for v in (value or [])]

    def _add_recent(self, path: Path) -> None:
        files = [str(path)] + [f for f in self.recent_files() if f != str(path)]
        self.store.setValue(RECENT_FILES_KEY, files[:MAX_RECENT])
        self.view.show_recent(self.recent_files())

    def last_dir(self) -> str:
        """The folder file dialogs open in: the latest project's."""
        recent = self.recent_files()
        return str(Path(recent[0]).parent) if recent else str(Path.home())

    # -- autosave and recovery ------------------------------------------------------
    def _rows(self) -> int:
        return sum(p.sheet.row_count for p in self.presenters)

    def _schedule_autosave(self, *_args) -> None:
        """An edit: autosave a few seconds from now (not later while typing goes on)."""
        if not self.autosave_timer.isActive():
            self._unsaved_since = time.monotonic()
            self.autosave_timer.start(self._autosave_delay_ms())

    def autosave_now(self) -> None:
        """Autosave at once, not a few seconds from now: a reading taken from an instrument
        (app/capture/panel.py), which cannot be typed again (hostile77 M2)."""
        self.autosave_timer.stop()
        self.autosave()

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

    def _pending_edits(self) -> dict[str, tuple[int, int, str]]:
        """The text still in a cell's editor (typed, not yet entered), by workbench."""
        out = {}
        for presenter in self.presenters:
            table = getattr(getattr(presenter, "view", None), "table", None)
            pending = table.pending_edit() if hasattr(table, "pending_edit") else None
            if isinstance(pending, tuple) and len(pending) == 3:
                out[presenter.kind.key] = pending
        return out

    @staticmethod
    def _with_pending(project: Project, pending: dict[str, tuple[int, int, str]]) -> Project:
        """``project`` with each editor's text in its cell (the autosave's copy only: the
        sheet and its undo history are not touched). The metadata's ``pending_edits`` say
        where each text is, and what the cell held entered (``was``: a captured reading,
        say), for the recovery to put the text back as an edit that can be undone
        (:meth:`_typed_over_entered`)."""
        was: dict[str, str] = {}
        for key, (row, column, text) in pending.items():
            state = project.workbenches.get(key)
            if state is None or row < 0 or column < 0:
                continue
            entered = (state.rows.row(row) if isinstance(state.rows, NumericRows)
                       else list(state.rows[row])) if row < len(state.rows) else []
            was[key] = str(entered[column]) if column < len(entered) else ""
            # the readings with a value still being typed are the origin's no longer: a
            # certificate of the recovered work must say they were edited (day review,
            # stop 65: a file's name and SHA-256 stated for readings that were not its)
            origin = state.origin
            if isinstance(origin, dict):
                origin = {**origin, "edited": True}
            if isinstance(state.rows, NumericRows) and row < len(state.rows):
                # a large record's snapshot (its own copy): the row set as an edited one,
                # the million others not copied
                cells = state.rows.row(row)
                cells += [""] * (column + 1 - len(cells))
                cells[column] = text
                state.rows.edited[row] = cells
                project.workbenches[key] = replace(state, origin=origin)
                continue
            rows = list(state.rows)
            while len(rows) <= row:
                rows.append([])
            cells = list(rows[row])
            cells += [""] * (column + 1 - len(cells))
            cells[column] = text
            rows[row] = cells
            project.workbenches[key] = replace(state, rows=rows, origin=origin)
        if pending:
            project.metadata = {**project.metadata, "pending_edits": {
                key: {"row": row + 1, "column": column + 1, "text": text,
                      **({"was": was[key]} if key in was else {})}
                for key, (row, column, text) in pending.items()}}
        return project

    def autosave(self) -> None:
        pending = self._pending_edits()
        if not self.is_modified and not pending:
            return
        # the project as it is now: a save from here on makes this autosave stale
        generation = self.recovery.generation
        # the raw capture's sessions are snapshots whose frames are encoded blocks, cheap to
        # take here (a large sheet's autosave left them out once: a project recovered from it
        # had its readings and no frames, and its certificate no raw digest)
        raw = self.raw_capture()
        frames = sum(len(s.get("frames", ())) for sessions in raw.values() for s in sessions)
        if self._rows() > AUTOSAVE_THREAD_ROWS or frames > AUTOSAVE_THREAD_FRAMES:
            if self._autosave_thread is not None and self._autosave_thread.is_alive():
                self.autosave_timer.start()  # the last one is still writing: try again soon
                return
            project = self._with_pending(
                Project({p.kind.key: p.state(deep=False) for p in self.presenters},
                        self._autosaved_metadata(), raw), pending)
            self._autosave_thread = threading.Thread(
                target=self._write_recovery_in_background, args=(project, generation),
                daemon=True)
            self._autosave_thread.start()
        else:
            project = self.project(raw)
            project.metadata = self._autosaved_metadata()
            self._write_recovery(self._with_pending(project, pending), generation=generation)

    def _autosaved_metadata(self) -> dict:
        """The details, with the SHA-256 of the project file the work was read from or last
        saved in: the recovered work's save asks when that file was changed since."""
        metadata = dict(self.metadata)
        if self.disk_sha256:
            metadata["project_sha256"] = self.disk_sha256
        # the workbenches whose rows differ from that file's: recovered, their certificate
        # does not name the file as their source (day review 67 F4)
        metadata[UNSAVED_READINGS] = [p.kind.key for p in self.presenters
                                      if p.readings_unsaved()]
        return metadata

    def _write_recovery_in_background(self, project: Project, generation: int) -> None:
        # the window keeps the interpreter every 0.1 ms; a million new strings would start
        # full cyclic-GC passes that hold it for a few hundred ms (strings hold no cycles)
        workers = application_workers()
        with workers.gui_thread_first(), workers.cyclic_gc_paused():
            self._write_recovery(project, workers.wait_while_analysing, generation)

    def _write_recovery(self, project: Project, between_blocks=None,
                        generation: int | None = None) -> None:
        try:
            self.recovery.write(project, self.path, between_blocks, generation)
        except Exception as exc:  # noqa: BLE001 - any failure is said (not only OSError: one
            # escaping here killed the autosave thread without a word)
            log.exception("autosave failed")
            reason = (exc.strerror if isinstance(exc, OSError) else None) or explained(exc) \
                or type(exc).__name__
            self.autosave_finished.emit(f"{self.recovery.path}: {reason}")
            return
        self.autosave_finished.emit("")

    def _autosave_reported(self, reason: str) -> None:
        """Said in the window: a failure stays until a save succeeds (an autosave or the
        project saved); the autosave is tried again at the next edit."""
        if reason:
            self.autosave_problem = reason
            self.view.show_autosave_problem(tr(
                "Autosave failed: {reason}. Your unsaved readings are not protected: save the "
                "project (File › Save as) on a disk with room.").format(reason=reason))
            self.view.show_status(tr("Autosave failed: {reason}").format(reason=reason), 0)
        elif self.autosave_problem:
            self.autosave_problem = ""
            self.view.show_autosave_problem("")
            self.view.show_status(tr("Autosave works again"), 5000)

    def offer_recovery(self) -> bool:
        """If a window ended without saving, offer its autosaved work (newest first);
        another running window's autosave is never offered."""
        orphans = self.recovery.orphans()
        if not orphans:
            return False
        path = orphans[0]
        try:
            project = self.recovery.load(path, self._kinds())
        except ProjectFileError as exc:
            self.view.tell(tr("Cannot recover"),
                           tr("{reason} (the file was kept aside as damaged)").format(reason=exc))
            return False
        when = project.metadata.get("autosaved_at") or tr("an unknown time")
        source = project.metadata.get("project_path") or ""
        name = Path(source).name if source else tr("an untitled project")
        if not self.view.ask_recover(name, when):
            kept = self.recovery.set_aside(path, "declined")
            self.view.show_status(tr("The autosave was kept aside: {path}").format(path=kept), 15000)
            return False
        typed = project.metadata.get("pending_edits") or {}
        # which workbenches' rows differ from the file's (an autosave written before it
        # said: any may)
        unsaved = project.metadata.get(UNSAVED_READINGS)
        self.apply_project(project, Path(source).name if source else "")
        typed_over = self._typed_over_entered(typed) if isinstance(typed, dict) else set()
        self.path = Path(source) if source else None
        # the file the crashed window's work was based on: a save asks if it changed since
        # (none known: asks whenever the file is there)
        self.disk_sha256 = project.metadata.get("project_sha256") or None
        for presenter in self.presenters:  # recovered work is unsaved work
            presenter.mark_modified()
            presenter.recovered_unsaved = bool(source) and (
                not isinstance(unsaved, list) or presenter.kind.key in unsaved)
        self.recovery.adopt(path)  # the orphan renamed to this window's autosave, not deleted
        self.autosave()  # now this window's own autosave
        self._tell_repairs(project)
        self.update_title()
        if isinstance(typed, dict) and typed:
            cells = ", ".join(
                tr("row {row}, column {column}: {typed} typed over {was}").format(
                    row=e.get("row"), column=e.get("column"), typed=e.get("text"),
                    was=e.get("was")) if key in typed_over else
                tr("row {row}, column {column}").format(row=e.get("row"),
                                                        column=e.get("column"))
                for key, e in typed.items() if isinstance(e, dict))
            said = tr("Recovered, with the values that were still being typed ({cells}): "
                      "check them").format(cells=cells)
            if typed_over:
                said += tr("; Edit › Undo puts back the value entered before")
            self.view.show_status(said, 0)
        return True

    def _typed_over_entered(self, typed: dict) -> set[str]:
        """The workbenches whose value still being typed at the crash went over a value
        entered (a captured reading, say): the cell set back to that value and the text
        typed put in it again as an edit of its own, so Edit › Undo brings the entered value
        back. The keys of those put back.

        Why: the house's rule is that typed work is never lost, so the text comes back into
        its cell as before (it was the last thing the technician did, and an editor cannot be
        reopened in a window that has not been shown). But it was never entered: put in
        place of a captured reading without a trace, the only way back was to retype the
        reading from the cell's tooltip (day review 74 F2). As an edit of its own it is
        marked "edited after capture" like any typed edit, the status line names both
        values, and one Undo restores the captured reading. An autosave of an older version
        (no ``was``) and a large record's rows keep the text in place as before."""
        done = set()
        for presenter in self.presenters:
            entry = typed.get(presenter.kind.key)
            model = getattr(presenter, "table_model", None)
            if not isinstance(entry, dict) or "was" not in entry or model is None \
                    or isinstance(model.sheet.rows, NumericRows):
                continue
            try:
                row, column = int(entry["row"]) - 1, int(entry["column"]) - 1
            except (TypeError, ValueError):
                continue
            was, text = str(entry.get("was", "")), str(entry.get("text", ""))
            sheet = model.sheet
            if not (0 <= row < sheet.row_count and 0 <= column < sheet.column_count) \
                    or not was.strip() or was == text or sheet.text(row, column) != text:
                continue
            model.set_cells([(row, column, was)])
            presenter.undo_stack.clear()  # the project as it was entered: nothing to undo
            model.set_cells([(row, column, text)], tr("Recovered typing"))
            done.add(presenter.kind.key)
        return done
