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
- dated more than :data:`FUTURE_TOLERANCE_SECONDS` ahead of this computer's clock (made
  by a computer whose clock is ahead, or this clock was set back since): its age cannot
  be told from its date (now − date is negative, and such a lock was never stale, every
  save refused until that date came). It is stale once this process has seen it
  unchanged (same file, size, date and content) for :data:`STALE_SECONDS` of its own
  monotonic clock: a live save touches it, which changes its date. A save that gives up
  waiting on one says so (:class:`LockInTheWay` "future", naming its date), so that the
  user can remove it or save again once it has been seen unchanged for that long.

Taking a lock that a live save holds waits up to :data:`WAIT_SECONDS` (a save of 150,000
rows takes about 0.3 s), then gives up with :class:`ProjectFileBusy`: the save is not
done and says who holds the file. Every wait has that deadline, whatever lies at the
lock's name.

The lock is opened without following a link and without waiting (``O_NOFOLLOW |
O_NONBLOCK``): a ``.NAME.lock`` that is not a regular file (a link, a named pipe, a
folder) is not a lock any AngleBench made, and the save is refused naming it
(:class:`LockInTheWay`), nothing written; the user removes it. It is not removed here:
it is not ours, and removing what we did not make is not atomic with our checks (a
saver that removed a link just as another replaced it by a real lock would remove that
lock, and two saves would write at once). Nor is the save done without the lock: every
saver would do the same, and two Saves would again both find the file unchanged.

A lock this user may not read (another user's, made with umask 077) is judged by its age
from ``lstat``; one that is stale but may not be removed (a folder with the sticky bit,
another user's file) refuses the save, naming its owner (:class:`LockInTheWay`). Locks
are made readable by every user (``fchmod`` 0644, whatever the umask), so that another
user's saver can read who holds it.
"""

from __future__ import annotations

import contextlib
import errno
import logging
import os
import socket
import stat
import threading
import time
from pathlib import Path

try:  # POSIX: a lock the kernel drops when the process dies
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None  # type: ignore[assignment]

__all__ = ["LockInTheWay", "ProjectFileBusy", "SaveLock", "lock_path_of"]

log = logging.getLogger(__name__)

STALE_SECONDS = 120.0
#: a lock dated further ahead than this is of unknown age (a clock ahead, or set back)
FUTURE_TOLERANCE_SECONDS = 30.0
TOUCH_SECONDS = 2.0
WAIT_SECONDS = 15.0
_POLL_SECONDS = 0.02
_SUFFIX = ".lock"
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)  # 0 on Windows (no links a user plants there)
_NONBLOCK = getattr(os, "O_NONBLOCK", 0)


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


class LockInTheWay(OSError):
    """A file at the lock's name that stops every save and that the user must remove:
    ``kind`` "link", "pipe", "folder" or "other" (not a regular file: not a lock any
    AngleBench made), "stale" (a lock untouched for ``age`` seconds that may not be
    removed from here, ``error`` saying why), or "future" (a lock ``dated`` ahead of this
    computer's clock, seconds since the epoch, not yet seen unchanged for
    :data:`STALE_SECONDS`: its age cannot be told); ``owner`` the user it belongs to (a
    name, or a user id when the name is not known here)."""

    def __init__(self, path: Path, kind: str, owner: str, age: float | None = None,
                 error: str = "", dated: float | None = None) -> None:
        super().__init__(errno.EEXIST, "in the way of the project's lock", str(path))
        self.path = Path(path)
        self.kind = kind
        self.owner = owner
        self.age = age
        self.error = error
        self.dated = dated


#: lock path -> (what it was when first seen so, time.monotonic() then): the age of a
#: lock dated in the future is how long this process has seen it unchanged
_seen: dict[str, tuple[tuple[object, ...], float]] = {}
_seen_lock = threading.Lock()


def _unchanged_for(path: Path, identity: tuple[object, ...]) -> float:
    """How long (this process's monotonic clock) the lock at ``path`` has been seen as
    ``identity``; 0 the first time, and each time it changed."""
    now = time.monotonic()
    with _seen_lock:
        seen = _seen.get(str(path))
        if seen is None or seen[0] != identity:
            _seen[str(path)] = (identity, now)
            return 0.0
        return now - seen[1]


def _forget(path: Path) -> None:
    with _seen_lock:
        _seen.pop(str(path), None)


def _age(path: Path, info: os.stat_result, content: tuple[str, ...] = ()) -> tuple[float, bool]:
    """The lock's age in seconds, and whether it is dated in the future (then the age is
    how long it has been seen unchanged here, :func:`_unchanged_for`)."""
    age = time.time() - info.st_mtime
    if age >= -FUTURE_TOLERANCE_SECONDS:
        _forget(path)
        return age, False
    identity = (info.st_dev, info.st_ino, info.st_size, info.st_mtime_ns, content)
    return _unchanged_for(path, identity), True


def _owner(uid: int) -> str:
    try:
        import pwd
        return pwd.getpwuid(uid).pw_name
    except (ImportError, KeyError, OSError):
        return str(uid)


def _kind(mode: int) -> str:
    if stat.S_ISLNK(mode):
        return "link"
    if stat.S_ISFIFO(mode):
        return "pipe"
    if stat.S_ISDIR(mode):
        return "folder"
    return "other"


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
        #: (date, owner) of the lock last found in the way when it is dated in the future
        self._future: tuple[float, str] | None = None

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
        gone = 0  # passes that found the lock stale or gone
        while True:
            try:
                if self._create():
                    return
                holder = self._inspect()
            except LockInTheWay:
                raise
            except OSError as exc:  # a folder where no lock can be made (read-only)
                log.warning("cannot lock %s (saved without a lock): %s", self.path, exc)
                return
            if holder is None:  # stale, removed (or gone): try again at once, once
                gone += 1
                if gone == 1:
                    continue
                if time.monotonic() < deadline or gone <= 3:
                    time.sleep(_POLL_SECONDS)  # made and gone again and again: no spin
                    continue
                holder = ("", "", None)  # the deadline holds whatever lies there
            if time.monotonic() >= deadline:
                if self._future is not None:  # its age cannot be told: said, with its date
                    dated, owner = self._future
                    raise LockInTheWay(self.path, "future", owner, dated=dated)
                raise ProjectFileBusy(self.path, *holder)
            time.sleep(_POLL_SECONDS)

    def _create(self) -> bool:
        """Create the lock file; False when it exists."""
        try:
            fd = os.open(self.path, os.O_RDWR | os.O_CREAT | os.O_EXCL | _NOFOLLOW, 0o666)
        except FileExistsError:
            return False
        if hasattr(os, "fchmod"):  # readable by another user's saver, whatever the umask
            with contextlib.suppress(OSError):
                os.fchmod(fd, 0o644)
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
        removed (or is gone already). :class:`LockInTheWay` when what lies there is not
        a lock file, or is a stale one that may not be removed."""
        self._future = None
        try:  # never through a link, never waiting for a writer (a named pipe)
            fd = os.open(self.path, os.O_RDONLY | _NOFOLLOW | _NONBLOCK)
        except FileNotFoundError:
            return None
        except OSError as exc:  # a link (ELOOP), a colleague's unreadable lock (EACCES)
            return self._unreadable(exc)
        try:
            info = os.fstat(fd)
            if not stat.S_ISREG(info.st_mode):
                raise LockInTheWay(self.path, _kind(info.st_mode), _owner(info.st_uid))
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
            now = os.fstat(fd)
            age, future = _age(self.path, now, tuple(self._read(fd)))
            stale = bool(locked and pid.isdigit() and host == _host()) or age > STALE_SECONDS
            if not stale:
                if future:
                    self._future = (now.st_mtime, _owner(now.st_uid))
                return holder
            log.warning("removing the stale lock %s (host %s, process %s, untouched for %.0f s%s)",
                        self.path, host or "?", pid or "?", age,
                        ", dated in the future" if future else "")
            _forget(self.path)
            if fcntl is not None:  # removed while our flock keeps other removers out
                try:
                    os.unlink(self.path)
                except FileNotFoundError:
                    pass
                except OSError as exc:  # not ours to remove: said, naming its owner
                    raise LockInTheWay(self.path, "stale", _owner(info.st_uid), age,
                                       exc.strerror or str(exc)) from exc
        finally:
            os.close(fd)  # our flock (if taken) goes with it
        if fcntl is None:  # Windows: an open file cannot be removed
            with contextlib.suppress(OSError):
                os.unlink(self.path)
        return None

    def _unreadable(self, exc: OSError) -> tuple[str, str, float | None] | None:
        """The lock could not be opened: judged by what ``lstat`` says (None: gone)."""
        try:
            info = os.lstat(self.path)
        except FileNotFoundError:
            return None
        except OSError:
            return "", "", None
        if not stat.S_ISREG(info.st_mode):
            raise LockInTheWay(self.path, _kind(info.st_mode), _owner(info.st_uid)) from exc
        age, future = _age(self.path, info)
        if age <= STALE_SECONDS:  # another user's live save (its holder unreadable)
            if future:
                self._future = (info.st_mtime, _owner(info.st_uid))
            return "", "", None
        _forget(self.path)
        log.warning("removing the stale lock %s (unreadable: %s; user %s, untouched for %.0f s)",
                    self.path, exc.strerror or exc, _owner(info.st_uid), age)
        try:  # no flock to keep other removers out: still that file?
            now = os.lstat(self.path)
            if (now.st_ino, now.st_mtime) != (info.st_ino, info.st_mtime):
                return None
            os.unlink(self.path)
        except FileNotFoundError:
            return None
        except OSError as error:
            raise LockInTheWay(self.path, "stale", _owner(info.st_uid), age,
                               error.strerror or str(error)) from error
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
