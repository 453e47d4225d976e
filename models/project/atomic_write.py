"""Atomic file writes: write a temporary file beside the target, then rename."""

from __future__ import annotations

import contextlib
import glob
import os
import re
import stat
import tempfile
import time
from collections.abc import Iterable
from pathlib import Path

from models.project.durable_rename import fsync_directory, replace_durably
from models.project.output_guard import refuse_capture_journal, refuse_database

__all__ = ["fsync_directory", "is_temporary_name", "stale_temporaries", "write_bytes_atomic",
           "write_text_atomic"]


def _mode_for(target: Path) -> int:
    """The replaced file's mode, or what a plain ``open`` would give a new file (mkstemp
    makes 0600, which would hide a saved project or certificate from the rest of the lab)."""
    try:
        return stat.S_IMODE(target.stat().st_mode)
    except OSError:
        umask = os.umask(0o022)
        os.umask(umask)
        return 0o666 & ~umask


STALE_TEMP_SECONDS = 600


#: what mkstemp adds to the prefix (8 random characters) and the suffix
_TEMP_EXTRA = 8 + len(".tmp")


def _temp_prefix(target: Path) -> str:
    """``.NAME.``, NAME cut (at a character) so that the temp file's name is no longer than
    the folder allows (#61 review: a legal 241–255-byte name failed as "File name too long"
    at the write, after the certificate was issued)."""
    try:
        limit = os.pathconf(target.parent, "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):
        limit = 255
    room = max(8, limit - _TEMP_EXTRA - 2)
    name = target.name
    while len(name.encode("utf-8", "surrogateescape")) > room:
        name = name[:-1]
    return f".{name}."


def is_temporary_name(path: str | os.PathLike[str]) -> bool:
    """``path`` is named as the temporary file of a write here (``.NAME.XXXXXXXX.tmp``,
    :func:`_temp_prefix` and mkstemp's 8 characters): an unfinished write left by an
    interrupted issue or save."""
    return bool(re.fullmatch(r"\..+\.[A-Za-z0-9_]{8}\.tmp", os.path.basename(path)))


def stale_temporaries(target: str | os.PathLike[str]) -> list[Path]:
    """The temporary files (``.NAME.*.tmp``) beside ``target`` older than
    STALE_TEMP_SECONDS: left by a save of ``target`` that was killed half-way, which the
    next save clears (app/issued_outputs.py first keeps any that holds a recorded results
    file: an issue killed after recording it and before naming it)."""
    target = Path(target)
    now, found = time.time(), []
    with contextlib.suppress(OSError):
        for temp in target.parent.glob(f"{glob.escape(_temp_prefix(target))}*.tmp"):
            with contextlib.suppress(OSError):
                if now - temp.stat().st_mtime > STALE_TEMP_SECONDS:
                    found.append(temp)
    return found


def _remove_stale_temps(target: Path) -> None:
    """Temp files of an earlier save of ``target`` that was killed half-way."""
    for temp in stale_temporaries(target):
        with contextlib.suppress(OSError):
            temp.unlink()


def write_bytes_atomic(path: str | os.PathLike[str], data: bytes | Iterable[bytes], *,
                       through_link: bool = True) -> None:
    """Replace ``path`` with ``data`` (bytes, or pieces of it written one after another)
    so that readers see the old or the new file, never half.

    The temporary file is created in the target's folder (so the rename stays on
    one file system), flushed and fsync'ed before it is renamed into place for good
    (:func:`~models.project.durable_rename.replace_durably`: the folder fsync'ed after
    it, or on Windows a write-through rename, so the new name survives a power loss;
    where the folder cannot be fsync'ed the file is written all the same). On any error before the
    rename the temporary file is removed and the old file is left untouched. A target that is a
    SQLite database or one of its journals (a certificate register), or a capture's journal
    (the readings of a capture that did not end), is refused (OutputRefused, an OSError)
    before anything is written.

    The temporary file is always a new file (mkstemp: created exclusively, O_EXCL, so a
    link or file planted at its random name is never written through). ``through_link``: a
    symbolic link at ``path`` is written through (a user's link to where they keep the file
    stays a link); False: the link itself is replaced and its target left alone — for a
    name of the program's own (the autosave's pending file), where a link can only have
    been planted (reg72 #9: it replaced an issued PDF).
    """
    target = Path(path)
    refuse_database(target)  # a certificate register is never an output (output_guard.py)
    refuse_capture_journal(target)  # nor the readings of a capture that did not end
    if through_link and target.is_symlink():  # write through the link: it stays a link
        target = target.resolve()
    _remove_stale_temps(target)
    fd, tmp_name = tempfile.mkstemp(prefix=_temp_prefix(target), suffix=".tmp", dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            if hasattr(os, "fchmod"):  # POSIX
                os.fchmod(handle.fileno(), _mode_for(target))
            for piece in ([data] if isinstance(data, bytes | bytearray) else data):
                handle.write(piece)
            handle.flush()
            os.fsync(handle.fileno())
        replace_durably(tmp_name, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(tmp_name)
        raise


def write_text_atomic(path: str | os.PathLike[str], text: str | Iterable[str],
                      encoding: str = "utf-8") -> None:
    """Text version of :func:`write_bytes_atomic`; pieces of text are encoded and written
    one by one (a 45 MB project is never one string in memory, nor one long encode that
    holds the interpreter while a window waits)."""
    if isinstance(text, str):
        write_bytes_atomic(path, text.encode(encoding))
    else:
        write_bytes_atomic(path, (piece.encode(encoding) for piece in text))
