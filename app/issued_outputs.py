"""No output replaces a file the register issued: the PDF, the DCC or the results file of
any certificate, found by its SHA-256 (rev62 F8: a second certificate's ``--results`` replaced
the first's results file, of which the register keeps only the SHA-256, and ``--results`` onto
an issued PDF replaced it with a CSV). ``analyze`` imports it only when an output is named
(its hashlib, logging and tempfile cost a plain analyze a tenth of numpy's import:
tests/app/test_cli_imports.py), and opens the register only when an output names a file
that exists, or a killed save's temporary file beside one.

A results file is written to a temporary file, recorded, then named (app/certificate_issue.py):
an issue killed between the last two leaves the only copy of a recorded file under the
temporary name, which the next save of that name clears after ten minutes as a killed save's
leftover (models/project/atomic_write.py). Every output checked here first keeps such a
file (:func:`keep_recorded_temporaries`) under a name that says whose it is."""

from __future__ import annotations

import contextlib
import hashlib
import logging
import os
from collections.abc import Iterable
from pathlib import Path

from models.messages import QT_TR_NOOP, Message, message, reason_of, separated
from models.project.atomic_write import stale_temporaries
from models.project.durable_rename import fsync_directory, rename_new_durably, replace_durably
from models.project.output_guard import OutputRefused, sqlite_path_of_url
from models.register.wording import issued_file_words

__all__ = ["clear_stale_beside", "kept_name", "keep_in_sight", "keep_recorded_temporaries", "place_new",
           "refuse_issued_files", "refuse_issued_outputs", "write_sparing_issued", "written_beside",
           "written_names"]

log = logging.getLogger(__name__)


def _existing(outputs: Iterable[tuple[str, str | None]]) -> list[tuple[str, str]]:
    return [(flag, os.fspath(out)) for flag, out in outputs if out and os.path.isfile(out)]


def _sha256(path: str | os.PathLike[str]) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        for piece in iter(lambda: handle.read(1 << 20), b""):
            digest.update(piece)
    return digest.hexdigest()


#: what a file name cannot hold on some file system a lab uses (Windows, a FAT stick, a
#: share): a certificate number printed "AB/2026/0001" or "AB:1" named no file (rev64 F13:
#: Path.with_name raised ValueError on every later write of that name)
_NOT_IN_A_NAME = frozenset('/\\:*?"<>|')


def kept_name(target: str | os.PathLike[str], number: str, n: int = 1) -> Path:
    """The name beside ``target`` a recorded results file of certificate ``number`` is kept
    under: ``r.AB-2026-0002.xlsx`` (``-2``, ``-3``… after it when ``n`` > 1), every
    character of the number a file name cannot hold (a path separator, ``:``, a control
    character) written ``-``."""
    target = Path(target)
    safe = "".join("-" if c in _NOT_IN_A_NAME or ord(c) < 32 else c for c in number)
    tail = "" if n == 1 else f"-{n}"
    return target.with_name(f"{target.stem}.{safe.strip('. ') or '-'}{tail}{target.suffix}")


def written_names(out: str | os.PathLike[str]) -> list[str]:
    """The names a write of ``out`` writes and clears killed saves' leftovers beside: ``out``,
    and where it is a symbolic link the file it points to (models/project/atomic_write.py
    writes through the link: rev64 F2, a write of ``latest.xlsx -> r.xlsx`` cleared the
    ``.r.xlsx.*.tmp`` the keeping never looked at)."""
    names = [os.fspath(out)]
    with contextlib.suppress(OSError, RuntimeError):
        if os.path.islink(out):
            names.append(os.fspath(Path(out).resolve()))
    return names


def keep_in_sight(temp: str | os.PathLike[str], target, number: str) -> str:
    """A recorded results file that is not in place, moved from its temporary name (which a
    later save of the same name clears as a killed save's leftover after ten minutes: the
    only copy, the register keeps its SHA-256 alone) to one beside ``target`` that names its
    certificate, ``r.AB-2026-0002.xlsx``: a hard link (Windows: a write-through move), else a
    copy, never replacing a file (``r.AB-2026-0002-2.xlsx`` when that is taken); then the
    temporary name removed. The temporary name when neither can be made."""
    target, temp = Path(target), os.fspath(temp)
    for n in range(1, 100):
        name = kept_name(target, number, n)
        try:
            rename_new_durably(temp, name)  # never over a file; for good
        except FileExistsError:
            continue
        except OSError:  # no hard links here (some network and FAT file systems): a copy
            try:
                _copy_new(temp, name)
            except FileExistsError:
                continue
            except OSError:
                return temp
            fsync_directory(name.parent)
            with contextlib.suppress(OSError):
                os.unlink(temp)
        return os.fspath(name)
    return temp


def _copy_new(source: str, name: Path) -> None:
    """``source`` copied to ``name``, which must not exist (FileExistsError), fsync'ed; a
    copy that fails half-way is removed."""
    with open(source, "rb") as src, open(name, "xb") as out:
        try:
            for piece in iter(lambda: src.read(1 << 20), b""):
                out.write(piece)
            out.flush()
            os.fsync(out.fileno())
        except BaseException:
            with contextlib.suppress(OSError):
                os.unlink(name)
            raise


def keep_recorded_temporaries(register, outputs: Iterable[tuple[str, str | None]]
                              ) -> list[Message]:
    """Keep, and say, every killed save's temporary file beside an output (older than ten
    minutes: models/project/atomic_write.stale_temporaries) whose SHA-256 is a results file
    the register recorded: placed beside it as ``r.<number>.xlsx`` (:func:`keep_in_sight`),
    so that the save about to be made, which clears such leftovers, never deletes the only
    copy of a recorded results file (an issue killed after recording it and before naming
    it). Returns what was said (also logged); OutputRefused when one cannot be kept (nothing
    is to be written then: the save would clear it)."""
    said: list[Message] = []
    recorded: dict[str, str] | None = None
    for _flag, given in outputs:
        if not given:
            continue
        for out, temp in ((name, temp) for name in written_names(given)
                          for temp in stale_temporaries(name)):
            if recorded is None:
                recorded = {}
                for entry in register.results_records():
                    recorded.setdefault(entry["sha256"], entry["number"])
            try:
                digest = _sha256(temp)
            except OSError:
                continue  # unreadable: the save clears it if it can
            number = recorded.get(digest)
            if number is None or _named(digest, out, number):
                continue  # no recorded file, or named already (killed after the link)
            kept = keep_in_sight(temp, out, number)
            if kept == os.fspath(temp):  # neither linked nor copied: the save would clear it
                raise OutputRefused(message(QT_TR_NOOP(
                    "{temp} is the results file recorded with certificate {number}, left under "
                    "a temporary name by an issue stopped before it was named, and it could "
                    "not be kept under another name: nothing was written; move it first"),
                    temp=os.fspath(temp), number=number))
            said.append(message(QT_TR_NOOP(
                "{temp} is the results file recorded with certificate {number}, left under "
                "a temporary name by an issue stopped before it was named: kept as {kept}"),
                temp=os.fspath(temp), number=number, kept=kept))
            # the caller says it (a warning here reached stderr too, through logging's
            # last resort: the notice was printed twice, reg72 #11)
            log.info("%s", said[-1])
    return said


def clear_stale_beside(register, target: str | os.PathLike[str]) -> None:
    """A killed save's leftovers beside ``target`` (``.NAME.*.tmp`` older than ten minutes:
    models/project/atomic_write.stale_temporaries) cleared before a file of an issue is
    written there, as every atomic write clears them (reg72 #11: the certificate's PDF, DCC
    and results file, written through :func:`written_beside` and :func:`place_new`, left
    them, though the docs promise the next save clears them). A recorded results file
    among them is kept first (:func:`keep_recorded_temporaries`; the check before the issue
    said what it kept: one that turned ten minutes old since is kept and logged); when one
    cannot be kept, or the register cannot be read, nothing is cleared."""
    try:
        for said in keep_recorded_temporaries(register, [("", os.fspath(target))]):
            log.warning("%s", said)
    except (OutputRefused, ValueError):  # (a RegisterError is a ValueError)
        return  # a recorded file that cannot be kept, or the register unread: none cleared
    for name in written_names(target):
        for temp in stale_temporaries(name):
            with contextlib.suppress(OSError):
                os.unlink(temp)


def _named(digest: str, out: str, number: str) -> bool:
    """Whether the recorded file of SHA-256 ``digest`` is at ``out`` or at the name
    :func:`keep_in_sight` gives it."""
    for name in (Path(out), kept_name(out, number)):
        with contextlib.suppress(OSError):
            if name.is_file() and _sha256(name) == digest:
                return True
    return False


def refuse_issued_files(register, outputs: Iterable[tuple[str, str | None]]) -> list[Message]:
    """Raise OutputRefused when an output (``(flag, path)`` pairs) is a file the register
    issued — the PDF, the DCC or the results file of any certificate, found by its SHA-256 —
    so that no later issue or export replaces it (rev62 F8: a results file, of which the
    register keeps only the SHA-256, was lost for good). First keeps a recorded results
    file left under a temporary name beside an output (:func:`keep_recorded_temporaries`),
    and returns what that said."""
    outputs = list(outputs)
    said = keep_recorded_temporaries(register, outputs)
    for flag, out in _existing(outputs):
        try:
            digest = _sha256(out)
        except OSError:
            continue  # unreadable: the write will say so
        found = register.issued_file(digest)
        if found:
            raise OutputRefused(message(QT_TR_NOOP(
                "{flag}{out} is {what}, as issued; an issued file is never replaced: "
                "nothing was written, choose another name"),
                flag=f"{flag} " if flag else "", out=os.fspath(out),
                what=separated([issued_file_words(kind, number) for number, kind in found])))
    return said


def place_new(register, temp: str | os.PathLike[str], target: str | os.PathLike[str]) -> None:
    """``temp`` renamed to ``target`` without replacing a file the register issued, checked
    at the moment of placing, not only before the issue (rev63 F7 for results files; rev64
    F7: two issues naming the same PDF both passed the check before, and the later one's
    rename replaced the earlier's PDF, whose issuer was told it was there). The name is taken
    with a hard link, which fails when ``target`` exists; a file there is replaced only when
    it is no issued file, checked and replaced under the file's save lock
    (models/project/save_lock.py), so that of two issuers finding the same file there the
    second finds the first's, issued, and is refused. Refused (OutputRefused, an OSError,
    or the lock's ProjectFileBusy), the bytes stay in ``temp``. Where hard links cannot be
    made (some network and FAT file systems) the same check and replacement under the lock."""
    try:  # for good: the folder fsync'ed, on Windows a write-through move (durable_rename)
        rename_new_durably(temp, target)
    except OSError:  # the name is taken (FileExistsError), or no hard links here
        from models.project.save_lock import SaveLock

        with SaveLock(target):
            refuse_issued_files(register, [("", os.fspath(target))])
            replace_durably(temp, target)


def refuse_issued_outputs(url: str, outputs: Iterable[tuple[str, str | None]]
                          ) -> list[Message]:
    """:func:`refuse_issued_files` for a run that issues nothing (a draft, a specimen, the
    results or a table alone): the register at ``url`` is opened only when an output names a
    file that exists or has a killed save's temporary file beside it, and not when it cannot
    be (a SQLite register not made yet, a server that does not answer: then nothing can be
    found in it). Returns what was said of recorded results files kept."""
    outputs = [(flag, os.fspath(out)) for flag, out in outputs if out]
    if not _existing(outputs) and not any(stale_temporaries(name) for _flag, out in outputs
                                          for name in written_names(out)):
        return []
    database = sqlite_path_of_url(url)
    if database is not None and not database.is_file():
        return []
    from models.register.store import Register, RegisterError

    try:  # (a database error is a RegisterError: the register says why)
        with Register(url) as register:
            return refuse_issued_files(register, outputs)
    except RegisterError:
        return []


def written_beside(path: str | os.PathLike[str], data: bytes) -> tuple[Path, str]:
    """``data`` in a temporary file beside the file ``path`` names (through a symbolic link,
    as every output; never the register's database), fsync'ed, for :func:`place_new`:
    (the target, the temporary file's name). Nothing is left when writing it fails."""
    import tempfile

    from models.project.atomic_write import _mode_for, _temp_prefix
    from models.project.output_guard import refuse_capture_journal, refuse_database

    target = Path(path)
    refuse_database(target)
    refuse_capture_journal(target)  # nor a killed capture's readings (hostile77 F2)
    if target.is_symlink():
        target = target.resolve()
    fd, temp = tempfile.mkstemp(prefix=_temp_prefix(target), suffix=".tmp", dir=target.parent)
    try:
        with os.fdopen(fd, "wb") as handle:
            if hasattr(os, "fchmod"):  # POSIX
                os.fchmod(handle.fileno(), _mode_for(target))
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise
    return target, temp


def write_sparing_issued(url: str, path: str | os.PathLike[str], data: bytes) -> None:
    """``data`` written to ``path``, an output of a run that issues nothing, checked against
    the files the register at ``url`` issued at the moment it is placed, not only when the
    run started (a capture may last hours: a certificate, DCC or results file issued under
    that name meanwhile was replaced by its final write): a temporary file beside it,
    fsync'ed, then :func:`place_new`. Written through a symbolic link, as every output.
    Where the register is not there or cannot be opened nothing can be found in it (as
    :func:`refuse_issued_outputs`): the file is replaced as an atomic write does; a register
    that fails while checking refuses it (OutputRefused, its reason). Refused or failed
    (OSError), nothing is left but what was there."""
    from models.register.store import Register, RegisterError

    target, temp = written_beside(path, data)
    try:
        database = sqlite_path_of_url(url)
        register = None
        if database is None or database.is_file():
            with contextlib.suppress(RegisterError):  # a database error is a RegisterError
                register = Register(url)
        if register is None:
            replace_durably(temp, target)
            return
        with register:
            try:
                clear_stale_beside(register, target)
                place_new(register, temp, target)
            except RegisterError as exc:  # not known to be no issued file: not replaced
                raise OutputRefused(reason_of(exc)) from exc
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise
