"""The lock a save holds on a project file, so that "changed on disk?" and the write are
one step for every AngleBench process on every workstation that shares the folder.

Without it, two Saves pressed close together (two windows, two workstations) both found
the file as they had read it, and both wrote it: the later rename replaced the earlier
save's readings, and nobody was asked (rev62 F5). With it, the second save waits until
the first has renamed its file, then finds the file changed and asks.

The lock is a file beside the project, ``.NAME.lock``, created with ``O_EXCL`` (atomic
on a local disk and on network shares alike) and removed when the save ends. It holds
the process id, the host name and the time. On POSIX the creator also holds ``flock`` on
it, which the kernel drops when the process dies.

A lock left by a save that was killed (kill -9, a crash, a power cut) must not stop
saving for good. It is stale:

- on the same host: when nobody holds its ``flock``. A live saver on this host always
  does (it takes it the moment it creates the file), and a dead one cannot; unlike a
  process id, this cannot be fooled by a new process that got the dead one's id.
- from another host (its process cannot be seen from here) or where there is no
  ``flock`` (Windows, or a share that refuses it): when the file has not been touched
  for :data:`STALE_SECONDS`. A live save touches it every :data:`TOUCH_SECONDS` between
  blocks of rows, so a live one is never that old; the margin covers the final fsync of
  a large file on a slow share and the clocks of two workstations set a little apart.

Taking a lock that a live save holds waits up to :data:`WAIT_SECONDS` (a save of 150,000
rows takes about 0.3 s), then gives up with :class:`ProjectFileBusy`: the save is not
done and says who holds the file.
"""

from __future__ import annotations

import contextlib
import errno
import logging
import os
import socket
import time
from pathlib import Path

try:  # POSIX: a lock the kernel drops when the process dies
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None  # type: ignore[assignment]

__all__ = ["ProjectFileBusy", "SaveLock", "lock_path_of"]

log = logging.getLogger(__name__)

STALE_SECONDS = 120.0
TOUCH_SECONDS = 2.0
WAIT_SECONDS = 15.0
_POLL_SECONDS = 0.02
_SUFFIX = ".lock"


class ProjectFileBusy(OSError):
    """Another save holds the project file: on computer ``host`` (its name, "" when the
    lock says nothing yet), process ``pid``, since ``since`` (seconds since the epoch)."""

    def __init__(self, path: Path, host: str, pid: str, since: float | None) -> None:
        super().__init__(errno.EBUSY, "being saved by another window", str(path))
        self.host = host
        self.pid = pid
        self.since = since

    @property
    def holder(self) -> str:
        return f"{self.host}, process {self.pid}" if self.host else ""


def lock_path_of(path: str | os.PathLike[str]) -> Path:
    """``.NAME.lock`` beside ``path`` (NAME cut at a character where the folder's names
    are shorter: a legal 250-byte project name still gets its lock). Beside the file a
    link points to: a project opened through a link and by its own name has one lock."""
    target = Path(os.path.realpath(path))
    try:
        limit = os.pathconf(target.parent, "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):
        limit = 255
    room = max(8, limit - len(_SUFFIX) - 1)
    name = target.name
    while len(name.encode("utf-8", "surrogateescape")) > room:
        name = name[:-1]
    return target.with_name(f".{name}{_SUFFIX}")


def _host() -> str:
    try:
        return socket.gethostname() or "?"
    except OSError:  # pragma: no cover - no host name
        return "?"


def _flock(fd: int) -> bool | None:
    """Take ``flock`` on ``fd`` without waiting: True taken, False someone holds it, None
    not available here (Windows, or a file system that refuses locks)."""
    if fcntl is None:
        return None
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except BlockingIOError:
        return False
    except OSError as exc:
        if exc.errno in (errno.EAGAIN, errno.EACCES):
            return False
        return None  # ENOLCK, EOPNOTSUPP, …: the age rule alone
    return True


class SaveLock:
    """The lock of the project file ``path`` while one save checks and writes it (a
    context manager: :meth:`acquire` on entry, :meth:`release` on exit)."""

    def __init__(self, path: str | os.PathLike[str], wait: float | None = None) -> None:
        self.path = lock_path_of(path)
        self.wait = WAIT_SECONDS if wait is None else wait
        self._fd: int | None = None
        self._touched = 0.0

    @property
    def held(self) -> bool:
        return self._fd is not None

    def __enter__(self) -> SaveLock:
        self.acquire()
        return self

    def __exit__(self, *_exc) -> None:
        self.release()

    def acquire(self) -> None:
        """Take the lock, waiting for a live save to end (:class:`ProjectFileBusy` after
        ``wait`` seconds). A folder where no lock can be made (read-only, a share that
        refuses the name) is logged and the save goes on without one: it then fails, or
        succeeds, as it did before there were locks."""
        deadline = time.monotonic() + self.wait
        while True:
            try:
                if self._create():
                    return
                holder = self._inspect()
            except OSError as exc:  # not even a stale lock can be removed (a folder there)
                log.warning("cannot lock %s (saved without a lock): %s", self.path, exc)
                return
            if holder is None:  # stale, removed: try again at once
                continue
            if time.monotonic() >= deadline:
                raise ProjectFileBusy(self.path, *holder)
            time.sleep(_POLL_SECONDS)

    def _create(self) -> bool:
        """Create the lock file; False when it exists."""
        try:
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666)
        except FileExistsError:
            return False
        # at once: from here a live saver on this host is seen holding it (another saver
        # looking at the new file may hold it for a moment: taken once it has looked)
        until = time.monotonic() + 1.0
        while _flock(fd) is False and time.monotonic() < until:
            time.sleep(0.001)
        with contextlib.suppress(OSError):  # an empty lock is judged by its age
            os.write(fd, f"{os.getpid()} {_host()} {time.time():.3f}\n".encode())
        self._fd = fd
        self._touched = time.monotonic()
        return True

    def _inspect(self) -> tuple[str, str, float | None] | None:
        """Who holds the existing lock (host, pid, since); None when it was stale and is
        removed (or is gone already)."""
        try:
            fd = os.open(self.path, os.O_RDONLY)  # a colleague's lock: readable, not ours
        except FileNotFoundError:
            return None
        except OSError:
            return "", "", None
        try:
            locked = _flock(fd)
            holder = self._holder(fd)
            if locked is False:  # a live save on this host
                return holder
            try:  # still the lock file (not one removed and made again meanwhile)?
                if os.fstat(fd).st_ino != os.stat(self.path).st_ino:
                    return None
            except FileNotFoundError:
                return None
            host, pid, _since = holder
            age = time.time() - os.fstat(fd).st_mtime
            stale = bool(locked and pid.isdigit() and host == _host()) or age > STALE_SECONDS
            if not stale:
                return holder
            log.warning("removing the stale lock %s (host %s, process %s, untouched for %.0f s)",
                        self.path, host or "?", pid or "?", age)
            if fcntl is not None:  # removed while our flock keeps other removers out
                with contextlib.suppress(FileNotFoundError):
                    os.unlink(self.path)  # any other error: saved without a lock
        finally:
            os.close(fd)  # our flock (if taken) goes with it
        if fcntl is None:  # Windows: an open file cannot be removed
            with contextlib.suppress(OSError):
                os.unlink(self.path)
        return None

    @staticmethod
    def _read(fd: int) -> list[str]:
        try:
            os.lseek(fd, 0, os.SEEK_SET)
            return os.read(fd, 512).decode("utf-8", "replace").split()
        except OSError:
            return []

    def _holder(self, fd: int) -> tuple[str, str, float | None]:
        """(host, pid, since) as the lock file says ("", "", None: nothing written yet)."""
        fields = self._read(fd)
        if len(fields) < 3:
            return "", "", None
        try:
            since: float | None = float(fields[2])
        except ValueError:
            since = None
        return fields[1], fields[0], since

    def touch(self) -> None:
        """A save still going (called between blocks of rows): the lock is not stale."""
        if self._fd is None or time.monotonic() - self._touched < TOUCH_SECONDS:
            return
        self._touched = time.monotonic()
        with contextlib.suppress(OSError):
            os.utime(self.path)

    def release(self) -> None:
        """The save ended: the lock file goes (removed while still held: a waiting saver
        that opened it finds it gone and makes its own)."""
        if self._fd is None:
            return
        if fcntl is not None:
            with contextlib.suppress(OSError):
                os.unlink(self.path)
        with contextlib.suppress(OSError):
            os.close(self._fd)
        self._fd = None
        if fcntl is None:  # Windows: an open file cannot be removed
            with contextlib.suppress(OSError):
                os.unlink(self.path)
