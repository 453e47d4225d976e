"""Why an output could not be written, in words and naming the file (contract75 F12: a
draft certificate on a full disk said "cannot write: [Errno 28] No space left on device",
no file named, exit 1; docs/command-line.md promises exit 2 and the file).

The file is the one the user named (``--certificate x.pdf``), never the temporary file
beside it the atomic write failed on; a full disk (or quota) is said as such, other
failures by the system's own words (``Permission denied``), never as ``[Errno N] …``."""

from __future__ import annotations

import errno
import os

from models.messages import QT_TR_NOOP, Message, message, reason_of
from models.project.output_guard import OutputRefused

__all__ = ["DISK_FULL", "output_not_written"]

#: the error numbers of a full disk or a full quota
DISK_FULL = frozenset(code for code in (errno.ENOSPC, getattr(errno, "EDQUOT", None))
                      if code is not None)


def output_not_written(path: str | os.PathLike[str], exc: BaseException,
                       flag: str = "") -> Message | str:
    """``{flag} {path}`` could not be written, and why, in words: "the disk is full" for
    ENOSPC/EDQUOT, a refusal's own reason (OutputRefused), else the system's words."""
    said = f"{flag} " if flag else ""
    out = os.fspath(path)
    if isinstance(exc, OutputRefused):  # its reason names the file
        return reason_of(exc)
    if isinstance(exc, OSError) and exc.errno in DISK_FULL:
        return message(QT_TR_NOOP("{flag}{path} cannot be written: the disk is full; nothing "
                                  "was written there (free some space and run again)"),
                       flag=said, path=out)
    reason = (exc.strerror if isinstance(exc, OSError) and exc.strerror else None) or \
        reason_of(exc) or type(exc).__name__
    return message(QT_TR_NOOP("{flag}{path} cannot be written ({reason}); nothing was "
                              "written there"), flag=said, path=out, reason=reason)
