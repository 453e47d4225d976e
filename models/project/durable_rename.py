"""A file renamed into place for good: the new name survives a power cut that comes just
after the save was reported done.

POSIX: ``os.replace``, then the folder fsync'ed (:func:`fsync_directory`; the file's own
fsync does not make its new name durable). Windows cannot open a folder, and
``os.replace`` there is ``MoveFileExW(MOVEFILE_REPLACE_EXISTING)``, which returns before
the rename is on the disk: a power cut after "saved" could give back the old file. There
the rename is ``MoveFileExW`` with ``MOVEFILE_WRITE_THROUGH`` as well, which returns only
once the move is on the disk (#63 winlock). Every rename-into-place in models/ and app/
goes through :func:`replace_durably` (or :func:`rename_new_durably`, the one that never
replaces a file).
"""

from __future__ import annotations

import contextlib
import errno
import logging
import os

__all__ = ["fsync_directory", "rename_new_durably", "replace_durably"]

log = logging.getLogger(__name__)

#: Windows: renames go through MoveFileExW (models/project/recovery.py has the same switch)
_WINDOWS = os.name == "nt"

MOVEFILE_REPLACE_EXISTING = 0x1
MOVEFILE_WRITE_THROUGH = 0x8
#: the Windows errors of a name that is taken
_NAME_TAKEN = (80, 183)  # ERROR_FILE_EXISTS, ERROR_ALREADY_EXISTS


def fsync_directory(folder: str | os.PathLike[str]) -> bool:
    """Make the renames done in ``folder`` survive a power loss (POSIX: fsync the folder;
    the file's own fsync does not make its new name durable, and on a file system that
    does not order the two, e.g. ext4 without data=ordered or XFS, the rename can be lost
    after the save was reported done).

    False where it cannot be done: Windows cannot open a folder (no ``O_DIRECTORY``; its
    renames are made durable by :func:`replace_durably` instead), and some file systems
    (network shares, FUSE) refuse to open or fsync one. That is logged, never raised: the
    rename has happened and every program already reads the new file; calling it a failed
    save would send the user to save again, or elsewhere, for a file that is there (and on
    such a share every save would fail)."""
    flag = getattr(os, "O_DIRECTORY", None)
    if flag is None:
        return False
    try:
        fd = os.open(folder, os.O_RDONLY | flag)
    except OSError as exc:
        log.warning("cannot open %s to make a rename in it durable: %s", folder, exc)
        return False
    try:
        os.fsync(fd)
    except OSError as exc:
        log.warning("cannot fsync %s (a rename in it may not survive a power loss): %s",
                    folder, exc)
        return False
    finally:
        os.close(fd)
    return True


def _kernel32():  # pragma: no cover - Windows only (the tests hand in a fake)
    """kernel32, its last error kept by ctypes (``ctypes.get_last_error``)."""
    import ctypes
    from ctypes import wintypes

    kernel32 = ctypes.WinDLL("kernel32", use_last_error=True)
    kernel32.MoveFileExW.argtypes = (wintypes.LPCWSTR, wintypes.LPCWSTR, wintypes.DWORD)
    kernel32.MoveFileExW.restype = wintypes.BOOL
    return kernel32


def _move_file_ex(src: str, dst: str, flags: int) -> bool:
    """Windows: ``MoveFileExW(src, dst, flags | MOVEFILE_WRITE_THROUGH)``; False when the call
    cannot be had here (logged: the caller renames as before). A failed move raises the
    Windows error as an OSError (``ctypes.WinError``: errno, winerror and text), naming
    both files; FileExistsError when the name is taken."""
    import ctypes

    try:
        move = _kernel32().MoveFileExW
    except (AttributeError, ImportError, OSError) as exc:
        log.warning("MoveFileExW is not available (%s): %s renamed to %s without "
                    "MOVEFILE_WRITE_THROUGH, it may not survive a power cut", exc, src, dst)
        return False
    if move(src, dst, flags | MOVEFILE_WRITE_THROUGH):
        return True
    code = ctypes.get_last_error()  # type: ignore[attr-defined]
    error = ctypes.WinError(code)  # type: ignore[attr-defined]
    if code in _NAME_TAKEN and not isinstance(error, FileExistsError):
        error = FileExistsError(errno.EEXIST, error.strerror)
    error.filename, error.filename2 = src, dst
    raise error


def replace_durably(src: str | os.PathLike[str], dst: str | os.PathLike[str]) -> None:
    """Rename ``src`` to ``dst``, replacing it (``os.replace``), for good: on POSIX the
    folder is fsync'ed after it (a folder that cannot be is logged, the rename stands);
    on Windows the rename is ``MoveFileExW(MOVEFILE_REPLACE_EXISTING |
    MOVEFILE_WRITE_THROUGH)``, which returns once it is on the disk. A failed rename
    raises OSError and leaves ``dst`` as it was."""
    src, dst = os.fspath(src), os.fspath(dst)
    if _WINDOWS:
        if not _move_file_ex(src, dst, MOVEFILE_REPLACE_EXISTING):
            os.replace(src, dst)
        return
    os.replace(src, dst)
    fsync_directory(os.path.dirname(os.path.abspath(dst)))


def rename_new_durably(src: str | os.PathLike[str], dst: str | os.PathLike[str]) -> None:
    """Give ``src``'s file the name ``dst`` only if that name is free (FileExistsError when
    it is taken: nothing replaced), for good, and let ``src``'s name go. POSIX: a hard link
    (which fails when ``dst`` exists), the folder fsync'ed, ``src`` removed (a name left
    behind is harmless); where there are no hard links (some network and FAT file systems)
    OSError, and the caller does what it did before. Windows: ``MoveFileExW`` with
    ``MOVEFILE_WRITE_THROUGH`` and without ``MOVEFILE_REPLACE_EXISTING`` (atomic, and
    refused when the name is taken)."""
    src, dst = os.fspath(src), os.fspath(dst)
    if not _WINDOWS or not _move_file_ex(src, dst, 0):
        os.link(src, dst)
        fsync_directory(os.path.dirname(os.path.abspath(dst)))
        with contextlib.suppress(OSError):
            os.unlink(src)
