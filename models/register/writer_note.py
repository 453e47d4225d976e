"""Who holds a SQLite register's write lock: a small note the writing process leaves beside
the database while it holds the lock (host, process, user, since when), removed when its
transaction ends.

SQLite does not say who holds its lock: a second issuer waited up to a minute in silence
and then said "database is locked" (reg72 #8). A write holds the lock for milliseconds, so
the note is there for as long as a writer that hangs or is stopped under a debugger holds
it. A note whose process is gone (this computer's process that no longer runs: killed while
it held the lock) is stale and ignored; a note from another computer cannot be checked
and is named as it says. A lock held by another program (the ``sqlite3`` shell, a backup
tool, an AngleBench older than this note) leaves none: it is then not named.
"""

from __future__ import annotations

import contextlib
import datetime as dt
import json
import os
import socket
import tempfile
from dataclasses import dataclass

from models.messages import QT_TR_NOOP, Message, message
from models.project.output_guard import WRITER_NOTE_SUFFIX

__all__ = ["Holder", "holder", "note_path", "remove_note", "write_note"]


@dataclass(frozen=True)
class Holder:
    """The process a note names."""

    host: str
    pid: int
    user: str
    since: str  # ISO 8601, UTC, to the second

    def text(self) -> Message:
        """``user@host, process 1234`` (the user left out when unknown)."""
        who = f"{self.user}@{self.host}" if self.user else self.host
        return message(QT_TR_NOOP("{who}, process {pid}"), who=who, pid=self.pid)


def note_path(database: str) -> str:
    """The note's name beside the database ``database``."""
    return f"{database}{WRITER_NOTE_SUFFIX}"


def _user() -> str:
    import getpass

    try:
        return getpass.getuser()
    except (KeyError, OSError):
        return ""


def write_note(database: str) -> None:
    """Note this process as the writer of ``database`` (called with the lock held; written
    beside it and renamed, so a reader finds a whole note or none). A note that cannot be
    written (a read-only folder, a full disk) is left out: the write goes on,
    and a waiter then does not name this writer."""
    body = json.dumps({"host": socket.gethostname(), "pid": os.getpid(), "user": _user(),
                       "since": dt.datetime.now(dt.timezone.utc).replace(
                           microsecond=0).isoformat()})
    target = note_path(database)
    temp = ""
    try:  # whole or not at all: renamed; the temporary a new file (O_EXCL), no link followed
        handle, temp = tempfile.mkstemp(prefix=f"{os.path.basename(target)}.", suffix=".tmp",
                                        dir=os.path.dirname(target) or ".")
        with os.fdopen(handle, "w", encoding="utf-8") as out:
            out.write(body)
        os.replace(temp, target)
    except OSError:
        if temp:
            with contextlib.suppress(OSError):
                os.unlink(temp)


def remove_note(database: str) -> None:
    """This process's note removed (the lock released); another process's note is left."""
    found = _read(note_path(database))
    if found is not None and found.pid == os.getpid() and found.host == socket.gethostname():
        with contextlib.suppress(OSError):
            os.unlink(note_path(database))


def _read(path: str) -> Holder | None:
    try:
        with open(path, encoding="utf-8") as handle:
            data = json.load(handle)
        return Holder(str(data["host"]), int(data["pid"]), str(data.get("user", "")),
                      str(data["since"]))
    except (OSError, ValueError, KeyError, TypeError):
        return None


def _running(pid: int) -> bool:
    """Whether process ``pid`` of this computer runs (a process of another user too)."""
    if pid <= 0:
        return False
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    except OSError:  # Windows: os.kill(pid, 0) is no test; the note is believed
        return True
    return True


def holder(database: str) -> Holder | None:
    """Who the note beside ``database`` says holds its write lock; None when there is no
    note, it cannot be read, or it is stale (a process of this computer that no longer
    runs)."""
    found = _read(note_path(database))
    if found is None:
        return None
    if found.host == socket.gethostname() and not _running(found.pid):
        return None
    return found
