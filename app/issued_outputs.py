"""No output replaces a file the register issued: the PDF, the DCC or the results file of
any certificate, found by its SHA-256 (rev62 F8: a second certificate's ``--results`` replaced
the first's results file, of which the register keeps only the SHA-256, and ``--results`` onto
an issued PDF replaced it with a CSV). Light: a plain ``analyze`` imports it only when an
output names a file that exists."""

from __future__ import annotations

import hashlib
import os
from collections.abc import Iterable

from models.messages import QT_TR_NOOP, message, separated
from models.project.output_guard import OutputRefused, sqlite_path_of_url
from models.register.wording import issued_file_words

__all__ = ["refuse_issued_files", "refuse_issued_outputs"]


def _existing(outputs: Iterable[tuple[str, str | None]]) -> list[tuple[str, str]]:
    return [(flag, os.fspath(out)) for flag, out in outputs if out and os.path.isfile(out)]


def refuse_issued_files(register, outputs: Iterable[tuple[str, str | None]]) -> None:
    """Raise OutputRefused when an output (``(flag, path)`` pairs) is a file the register
    issued — the PDF, the DCC or the results file of any certificate, found by its SHA-256 —
    so that no later issue or export replaces it (rev62 F8: a results file, of which the
    register keeps only the SHA-256, was lost for good)."""
    for flag, out in _existing(outputs):
        digest = hashlib.sha256()
        try:
            with open(out, "rb") as handle:
                for piece in iter(lambda h=handle: h.read(1 << 20), b""):
                    digest.update(piece)
        except OSError:
            continue  # unreadable: the write will say so
        found = register.issued_file(digest.hexdigest())
        if found:
            raise OutputRefused(message(QT_TR_NOOP(
                "{flag}{out} is {what}, as issued; an issued file is never replaced: "
                "nothing was written, choose another name"),
                flag=f"{flag} " if flag else "", out=os.fspath(out),
                what=separated([issued_file_words(kind, number) for number, kind in found])))


def refuse_issued_outputs(url: str, outputs: Iterable[tuple[str, str | None]]) -> None:
    """:func:`refuse_issued_files` for a run that issues nothing (a draft, a specimen, the
    results or a table alone): the register at ``url`` is opened only when an output names a
    file that exists, and not when it cannot be (a SQLite register not made yet, a server
    that does not answer: then nothing can be found in it)."""
    existing = _existing(outputs)
    if not existing:
        return
    database = sqlite_path_of_url(url)
    if database is not None and not database.is_file():
        return
    from models.register.store import Register, RegisterError

    try:  # (a database error is a RegisterError: the register says why)
        with Register(url) as register:
            refuse_issued_files(register, existing)
    except RegisterError:
        return
