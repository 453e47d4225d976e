"""Crash recovery: each running window autosaves its unsaved work to a file of its own.

Every window holds a lock on a file beside its autosave for as long as it runs.
At start-up, an autosave whose lock nobody holds belongs to a window that did not
close normally (a crash, a power cut, kill -9): that one is offered back. Another
running window's autosave is never offered, overwritten or deleted.
"""

from __future__ import annotations

import contextlib
import os
import threading
import time
import uuid
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from models.project.durable_rename import replace_durably
from models.project.file import Project, ProjectFileError, load_project, save_project

try:  # POSIX: a lock the kernel drops when the process dies
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None  # type: ignore[assignment]

__all__ = ["RecoveryStore"]

STALE_TEMP_SECONDS = 600
#: Windows: a process is asked after through its handle (os.kill would end it)
_WINDOWS = os.name == "nt"


def _windows_process_alive(pid: int) -> bool:  # pragma: no cover - Windows only
    """Whether process ``pid`` runs (OpenProcess + GetExitCodeProcess): on Windows
    ``os.kill(pid, 0)`` is no test, it ends the process (TerminateProcess)."""
    import ctypes

    kernel32 = ctypes.windll.kernel32  # type: ignore[attr-defined]
    handle = kernel32.OpenProcess(0x1000, False, pid)  # PROCESS_QUERY_LIMITED_INFORMATION
    if not handle:
        return kernel32.GetLastError() == 5  # access denied: it exists, someone else's
    try:
        code = ctypes.c_ulong()
        if not kernel32.GetExitCodeProcess(handle, ctypes.byref(code)):
            return True  # cannot tell: take it as running (never offer a live window's work)
        return code.value == 259  # STILL_ACTIVE
    finally:
        kernel32.CloseHandle(handle)


def _process_alive(pid: int) -> bool:
    """Whether process ``pid`` runs, without touching it."""
    if _WINDOWS:
        return _windows_process_alive(pid)
    try:
        os.kill(pid, 0)  # POSIX: signal 0 only checks
    except ProcessLookupError:
        return False
    except PermissionError:
        return True  # it exists, another user's
    return True


def _lock_is_held(lock_path: Path) -> bool:
    """Whether a live window holds ``lock_path``."""
    if not lock_path.exists():
        return False
    if fcntl is None:  # Windows: the PID written in the file
        try:
            pid = int(lock_path.read_text().split()[0])
        except (OSError, ValueError, IndexError):
            return False
        return _process_alive(pid)
    try:
        fd = os.open(lock_path, os.O_RDWR)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        return True  # someone holds it
    else:
        fcntl.flock(fd, fcntl.LOCK_UN)
        return False
    finally:
        os.close(fd)


class RecoveryStore:
    """The autosaves in ``folder``: this window's own, and those of windows that died."""

    PREFIX = "recovery-"
    SUFFIX = ".anglebench.json"
    LEGACY_NAME = "recovery.anglebench.json"  # written by 0.1.0 before windows had their own

    def __init__(self, folder: str | Path) -> None:
        self.folder = Path(folder)
        token = f"{os.getpid()}-{uuid.uuid4().hex[:8]}"
        self.path = self.folder / f"{self.PREFIX}{token}{self.SUFFIX}"
        self.lock_path = self.folder / f"{self.PREFIX}{token}.lock"
        self._lock_fd: int | None = None
        self._write_lock = threading.Lock()
        #: one more at each :meth:`discard` (the project was saved, or the window closes):
        #: an autosave of a project taken before is not put on disk (:meth:`write`)
        self.generation = 0
        #: held for the moment an autosave is put in place, or the autosave is discarded
        self._publish_lock = threading.Lock()
        #: orphans adopted that could not be renamed: deleted once an autosave is written
        self._adopted: list[Path] = []

    # -- this window's own -------------------------------------------------------
    def claim(self) -> None:
        """Take this window's lock (held until :meth:`release`) and sweep temp files that
        a save killed half-way left behind."""
        self.folder.mkdir(parents=True, exist_ok=True)
        self._clean_stale_temps()
        if self._lock_fd is not None:
            return
        fd = os.open(self.lock_path, os.O_RDWR | os.O_CREAT, 0o644)
        if fcntl is not None:
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        os.write(fd, f"{os.getpid()}\n".encode())
        self._lock_fd = fd

    def release(self) -> None:
        """A clean exit: this window's autosave and lock go."""
        self.discard()
        if self._lock_fd is not None:
            with contextlib.suppress(OSError):
                os.close(self._lock_fd)
            self._lock_fd = None
        with contextlib.suppress(FileNotFoundError):
            self.lock_path.unlink()

    def write(self, project: Project, project_path: str | Path | None = None,
              between_blocks: Callable[[], None] | None = None,
              generation: int | None = None) -> bool:
        """Autosave ``project`` (safe from a worker thread: one write at a time);
        ``between_blocks`` is called between blocks of rows (see ``project_to_json``).

        ``generation``: :attr:`generation` when ``project`` was taken (by default, now).
        The autosave is written beside its place and put there only if nothing was
        discarded since: a project saved while a long autosave was being written leaves
        no autosave older than itself (the save discarded it, and the rename that ended
        the write put it back, to be offered after a crash over the newer file). False
        when it was dropped so."""
        if generation is None:
            generation = self.generation
        self.folder.mkdir(parents=True, exist_ok=True)
        project.metadata = dict(project.metadata)
        project.metadata["autosaved_at"] = time.strftime("%Y-%m-%d %H:%M:%S")
        project.metadata["project_path"] = str(project_path) if project_path else ""
        pending = self.path.with_name(f".{self.path.name}.pending.tmp")
        with self._write_lock:
            # the pending name is the program's own: a link planted there is replaced, never
            # written through (reg72 #9)
            save_project(pending, project, between_blocks, through_link=False)
            with self._publish_lock:
                if generation != self.generation:
                    with contextlib.suppress(OSError):
                        pending.unlink()
                    return False
                replace_durably(pending, self.path)  # for good before the orphans go
                for orphan in self._adopted:  # their work is in this window's autosave now
                    with contextlib.suppress(FileNotFoundError):
                        orphan.unlink()
                    self._drop_lock_of(orphan)
                self._adopted.clear()
        return True

    def exists(self) -> bool:
        return self.path.is_file()

    def discard(self) -> None:
        """This window's autosave goes (and one being written is not put in place)."""
        with self._publish_lock:
            self.generation += 1
            with contextlib.suppress(FileNotFoundError):
                self.path.unlink()
            for orphan in self._adopted:  # adopted work saved (or let go) with this window's
                with contextlib.suppress(FileNotFoundError):
                    orphan.unlink()
                self._drop_lock_of(orphan)
            self._adopted.clear()

    # -- windows that died ----------------------------------------------------------
    def orphans(self) -> list[Path]:
        """Autosaves of windows that did not close normally, newest first."""
        if not self.folder.is_dir():
            return []
        found = []
        for path in self.folder.glob(f"{self.PREFIX}*{self.SUFFIX}"):
            if path == self.path:
                continue
            lock = path.with_name(path.name[: -len(self.SUFFIX)] + ".lock")
            if not _lock_is_held(lock):
                found.append(path)
        legacy = self.folder / self.LEGACY_NAME
        if legacy.is_file():
            found.append(legacy)
        return sorted(found, key=lambda p: p.stat().st_mtime, reverse=True)

    def load(self, path: Path, kinds: Mapping[str, Any] | None = None) -> Project:
        """Read an orphaned autosave. A damaged one is kept aside under a name of its own
        (never over an earlier damaged one), not deleted."""
        try:
            return load_project(path, kinds)
        except ProjectFileError:
            self.set_aside(path, "damaged")
            raise

    def set_aside(self, path: Path, why: str) -> Path:
        """Rename an orphan so it is not offered again, keeping it on disk."""
        stamp = time.strftime("%Y%m%d-%H%M%S")
        target = path.with_name(f"{path.name}.{why}-{stamp}-{uuid.uuid4().hex[:6]}.json")
        with contextlib.suppress(OSError):
            replace_durably(path, target)
        self._drop_lock_of(path)
        return target

    def adopt(self, path: Path) -> None:
        """An orphan's work now lives in this window: its file becomes this window's
        autosave (renamed, under this window's lock: at no moment is the work in no file;
        it was deleted first, and a second crash before this window's own autosave was
        written, seconds later for a large sheet, lost it all), and its lock goes. When
        it cannot be renamed (or this window has an autosave of its own), the orphan stays
        until this window's next autosave is written."""
        if not self.exists():
            try:
                with self._publish_lock:
                    replace_durably(path, self.path)  # for good before its lock goes
            except OSError:
                pass
            else:
                self._drop_lock_of(path)
                return
        self._adopted.append(path)

    def _drop_lock_of(self, path: Path) -> None:
        if path.name.endswith(self.SUFFIX) and path.name.startswith(self.PREFIX):
            with contextlib.suppress(OSError):  # gone, or a read-only folder: left
                path.with_name(path.name[: -len(self.SUFFIX)] + ".lock").unlink()

    def _clean_stale_temps(self) -> None:
        now = time.time()
        for temp in self.folder.glob(".*.tmp"):
            with contextlib.suppress(OSError):
                if now - temp.stat().st_mtime > STALE_TEMP_SECONDS:
                    temp.unlink()
