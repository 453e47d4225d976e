"""Outputs that may not land on a file we must keep: the certificate register (its SQLite
database and the journal, WAL and shared-memory files beside it), the inputs of the run and
the project open in the window; and, found by what they hold, a capture's journal (the
readings of a capture that did not end) and an AngleBench project (readings typed, details),
which no table, results file, certificate or archive replaces.

Two files are the same when they resolve to the same file: a symbolic link is followed, and
a hard link (another name of the same inode) is found by comparing ``st_dev``/``st_ino``.
A name that does not exist yet is compared by its resolved path (the register's WAL file
exists only while the database is open).

As a last line, :func:`refuse_database` looks at what the target holds: no AngleBench output
is ever a SQLite database or one of its journals, so a write that would replace one is
refused whoever asked for it (a register in another folder than the configured one, a
command this module was not told about).
"""

from __future__ import annotations

import contextlib
import os
import re
import stat
from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from pathlib import Path

from models.messages import QT_TR_NOOP, message
from models.project.file_kind import file_kind

__all__ = ["OutputRefused", "Protected", "check_output", "check_outputs", "input_files",
           "open_project", "refuse_capture_journal", "refuse_database", "refuse_kept_readings",
           "refuse_other_kind", "refuse_other_kinds", "refuse_other_project", "refuse_pem",
           "refuse_unwritable",
           "register_files", "same_file", "sqlite_path_of_url"]

#: the files SQLite keeps beside a database ``X``: ``X-journal`` (rollback journal),
#: ``X-wal`` (write-ahead log) and ``X-shm`` (its shared-memory index)
SQLITE_COMPANIONS = ("-journal", "-wal", "-shm")
#: the register's own file beside a SQLite register ``X``: ``X.issuing``, the issuers' turn
#: after a lost race (a file lock, models.register.store); an output written over it
#: (a rename: a new file) would split the issuers between two locks
TURN_FILE_SUFFIX = ".issuing"
#: the note beside a SQLite register naming the process that holds its write lock
#: (models/register/writer_note.py)
WRITER_NOTE_SUFFIX = ".writer"
#: the folder beside the laboratory's key where the register's high-water marks are kept
#: (``<key file>.high-water``: models/register/high_water.py)
HIGH_WATER_SUFFIX = ".high-water"

#: the first bytes of a SQLite database, of a rollback journal and of a WAL file (both byte
#: orders of its magic number); the -shm file has no magic and is found by its name
_SQLITE_MAGIC = (b"SQLite format 3\x00", bytes.fromhex("d9d505f920a163d7"),
                 bytes.fromhex("377f0682"), bytes.fromhex("377f0683"))

#: the first line of a capture journal (models/capture/journal.py's header, any version)
_CAPTURE_JOURNAL_MAGIC = b"# anglebench capture journal"
#: an AngleBench project (models/project/file.py's FORMAT_NAME), as every version writes its
#: first key; an autosave is one too
_PROJECT_FORMAT = re.compile(rb'\A\s*\{\s*"format"\s*:\s*"anglebench-project"')
#: the variable naming the laboratory's register key (models/register/signing.py's
#: KEY_ENV_VAR; not imported: the register's modules import this one)
REGISTER_KEY_ENV_VAR = "ANGLEBENCH_REGISTER_KEY"
#: how a PEM file starts (a private key, a certificate: the DCC's signing key and
#: certificates, a lab's TLS files): no output of AngleBench is one
_PEM_BEGIN = re.compile(rb"\A\s*-----BEGIN [A-Z0-9 ]+-----")
#: how the readings and the raw lines `anglebench capture` writes start (app/capture/cli.py:
#: their header's first column); no other output of AngleBench starts so
_CAPTURE_OUTPUT = re.compile(rb"\A(?:\xef\xbb\xbf)?time_s,")
#: the outputs that write a capture's readings or raw lines (``capture --out/--raw``, which
#: replace an earlier capture's only with --overwrite)
CAPTURE_FLAGS = frozenset(("--out", "--raw"))
#: the outputs that write a project (``register show --project``): a project they name is
#: replaced by a project, as the window's Save as does
PROJECT_FLAGS = frozenset(("--project",))


class OutputRefused(OSError):
    """An output names a file that must not be written (its reason is a Message). An
    OSError, so that every writer's "cannot write" path reports it and keeps going."""


@dataclass(frozen=True)
class Protected:
    """A file no output may replace, and what it is (a Message, e.g. "the register")."""

    path: Path
    what: str


def _identity(path: Path) -> tuple[int, int] | None:
    try:
        st = os.stat(path)  # follows symbolic links
    except (OSError, ValueError):
        return None
    return st.st_dev, st.st_ino


def _resolved(path: str | os.PathLike[str]) -> str:
    try:
        return os.path.normcase(os.path.realpath(os.path.expanduser(os.fspath(path))))
    except (OSError, ValueError, RuntimeError):
        return os.path.normcase(os.path.abspath(os.fspath(path)))


def same_file(a: str | os.PathLike[str], b: str | os.PathLike[str]) -> bool:
    """Whether ``a`` and ``b`` are one file: the same inode when both exist (a symbolic or
    hard link to it included), else the same resolved path."""
    first, second = _identity(Path(a)), _identity(Path(b))
    if first is not None and second is not None:
        return first == second
    return _resolved(a) == _resolved(b)


def sqlite_path_of_url(url: str) -> Path | None:
    """The database file of a ``sqlite:///`` register URL (None for a server register)."""
    text = (url or "").strip()
    if "://" not in text:
        return Path(text).expanduser() if text else None
    scheme, _, rest = text.partition("://")
    if not scheme.lower().startswith("sqlite"):
        return None
    # sqlite:///relative and sqlite:////absolute, as SQLAlchemy reads them
    rest = rest.split("?", 1)[0]
    rest = rest[1:] if rest.startswith("/") else rest
    if not rest or rest == ":memory:":
        return None
    return Path(rest)


def register_files(url: str) -> list[Protected]:
    """The register's database, its journal, WAL and shared-memory files, its issuers'
    turn file and its writer's note."""
    database = sqlite_path_of_url(url)
    if database is None:
        return []
    what = message(QT_TR_NOOP("the certificate register ({path})"), path=str(database))
    return [Protected(database, what)] + [
        Protected(Path(f"{database}{suffix}"),
                  message(QT_TR_NOOP("the certificate register's {kind} file ({path})"),
                          kind=suffix[1:], path=f"{database}{suffix}"))
        for suffix in (*SQLITE_COMPANIONS, TURN_FILE_SUFFIX, WRITER_NOTE_SUFFIX)]


def input_files(paths: Iterable[str | os.PathLike[str] | None]) -> list[Protected]:
    """The run's inputs (None and empty names left out)."""
    return [Protected(Path(p), message(QT_TR_NOOP("an input ({path})"), path=str(p)))
            for p in paths if p]


def open_project(path: str | os.PathLike[str] | None) -> list[Protected]:
    """The project open in the window (none when it was never saved)."""
    if not path:
        return []
    return [Protected(Path(path), message(QT_TR_NOOP("the open project ({path})"),
                                          path=str(path)))]


def _companion_of_database(path: str | os.PathLike[str]) -> bool:
    """Whether ``path`` names the journal, WAL or shared-memory file of a SQLite database
    that exists beside it."""
    resolved = _resolved(path)
    for suffix in SQLITE_COMPANIONS:
        if resolved.endswith(os.path.normcase(suffix)):
            base = resolved[: -len(suffix)]
            if _is_database(base):
                return True
    return False


def _regular_or_absent(path: str | os.PathLike[str]) -> bool:
    """Whether ``path`` (after links) is a regular file or names nothing yet: a FIFO, a
    device or a socket is neither (opening a FIFO waits for a writer for ever: rev62 M1)."""
    try:
        return stat.S_ISREG(os.stat(path).st_mode)
    except (OSError, ValueError):
        return True


def _is_database(path: str | os.PathLike[str]) -> bool:
    if not _regular_or_absent(path):  # never opened: a FIFO would block the open
        return False
    try:
        with open(path, "rb") as handle:
            head = handle.read(16)
    except (OSError, ValueError):
        return False
    return any(head.startswith(magic) for magic in _SQLITE_MAGIC)


def refuse_database(path: str | os.PathLike[str]) -> None:
    """Raise OutputRefused when ``path`` (after links) holds a SQLite database or one of its
    journals, or names the journal/WAL/shared-memory file of one: a certificate register,
    ours or not, is never an output."""
    if _is_database(path) or _companion_of_database(path):
        raise OutputRefused(message(QT_TR_NOOP(
            "{path} is a database (a certificate register?); nothing was written: choose "
            "another name"), path=os.fspath(path)))


#: what an output of each flag writes (models.project.file_kind's names): a file that exists
#: under that name and holds something else is not replaced (thbias2's run:
#: ``--certificate certificate_positioning.json`` wrote a PDF over a lab's metadata JSON,
#: no input of that run, without a word). Flags that write text (a CSV, a table) are not
#: judged: any text may be an earlier one of them.
_KIND_OF_FLAG: dict[str, tuple[str, str]] = {
    "--certificate": (QT_TR_NOOP("a PDF"), "pdf"),
    "--pdf": (QT_TR_NOOP("a PDF"), "pdf"),
    "--dcc": (QT_TR_NOOP("an XML document"), "xml"),
    "OUT.zip": (QT_TR_NOOP("a ZIP archive"), "zip"),
}


def _kind_expected(path: str | os.PathLike[str], flag: str) -> tuple[str, str] | None:
    if flag == "--results" and os.fspath(path).lower().endswith(".xlsx"):
        return QT_TR_NOOP("an XLSX workbook"), "zip"
    return _KIND_OF_FLAG.get(flag)


def refuse_other_kind(path: str | os.PathLike[str], flag: str) -> None:
    """Raise OutputRefused when ``path`` exists, is not empty and holds something other than
    what ``flag`` writes (a certificate named over a JSON, a spreadsheet or a readings file):
    that file is someone's work, and an output of another kind would replace it with no
    way back. An earlier output of the same kind is replaced as before."""
    expected = _kind_expected(path, flag)
    if expected is None or not _regular_or_absent(path):
        return
    try:
        with open(path, "rb") as handle:
            head = handle.read(4096)
    except OSError:  # absent (or unreadable: refuse_unwritable says why)
        return
    if not head.strip():
        return
    kind, wanted = expected
    if file_kind(head) == wanted:
        return
    raise OutputRefused(message(QT_TR_NOOP(
        "{flag} {out} exists and is not {kind}: it would be replaced with no way back; "
        "nothing was written: choose another name"), flag=flag, out=os.fspath(path),
        kind=message(kind)))


def refuse_other_kinds(outputs: Iterable[tuple[str, str | os.PathLike[str] | None]]) -> None:
    """:func:`refuse_other_kind` for each named output; run after the register's own checks,
    whose refusal says more ("is the PDF of certificate …")."""
    for flag, out in outputs:
        if out:
            refuse_other_kind(out, flag)


def check_output(path: str | os.PathLike[str] | None, protected: Sequence[Protected],
                 flag: str = "") -> None:
    """Raise OutputRefused when the output ``path`` is one of ``protected`` (after symbolic
    and hard links) or a database; nothing has been written then. ``flag``: how the user
    named the output (``--certificate``), said in the refusal."""
    if not path:
        return
    # what would fail only at the write, after a certificate's number was used (#61 review:
    # a folder named as the output; a folder that is not there)
    if os.path.isdir(path):
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out} is a folder; nothing was written: name a file in it"),
            flag=f"{flag} " if flag else "", out=os.fspath(path)))
    parent = os.path.dirname(os.path.abspath(path))
    if not os.path.isdir(parent):
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out}: the folder {folder} does not exist; nothing was written"),
            flag=f"{flag} " if flag else "", out=os.fspath(path), folder=parent))
    for item in protected:
        if same_file(path, item.path):
            raise OutputRefused(message(QT_TR_NOOP(
                "{flag}{out} is {what}; nothing was written: choose another name"),
                flag=f"{flag} " if flag else "", out=os.fspath(path), what=item.what))
    refuse_database(path)
    refuse_kept_readings(path, flag)
    refuse_register_key(path, flag)
    refuse_pem(path, flag)
    refuse_unwritable(path, flag)


def _head(path: str | os.PathLike[str], size: int = 4096) -> bytes:
    """The first ``size`` bytes of ``path`` (after links); b"" when it is not a regular file
    or cannot be read (a FIFO is never opened: it would wait for a writer)."""
    if not _regular_or_absent(path):
        return b""
    try:
        with open(path, "rb") as handle:
            return handle.read(size)
    except (OSError, ValueError):
        return b""


def refuse_capture_journal(path: str | os.PathLike[str], flag: str = "") -> None:
    """Raise OutputRefused when ``path`` (after links) is a capture's journal: the only copy
    of the readings of a capture that did not end (killed, a power cut), which the next
    capture into its output recovers. No write replaces one, whoever asks (hostile77 F2:
    ``analyze --table`` or ``--results`` named over it replaced 94 captured readings)."""
    if _head(path, len(_CAPTURE_JOURNAL_MAGIC)) == _CAPTURE_JOURNAL_MAGIC:
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out} is a capture's journal: the readings of a capture that did not end, "
            "which the next capture into its output recovers; nothing was written: choose "
            "another name"), flag=f"{flag} " if flag else "", out=os.fspath(path)))


def refuse_kept_readings(path: str | os.PathLike[str], flag: str = "") -> None:
    """Raise OutputRefused when ``path`` (after links) holds readings that an output would
    replace with no way back: a capture's journal (:func:`refuse_capture_journal`), the
    readings or raw lines a capture wrote unless ``flag`` writes them (:data:`CAPTURE_FLAGS`),
    or an AngleBench project — readings as typed, details — unless ``flag`` writes a project
    (:data:`PROJECT_FLAGS`). hostile77 F1: ``analyze --table p.anglebench.json`` replaced a
    project (not open anywhere) with a compensation table, exit 0, no word; the kind check
    (:func:`refuse_other_kind`) judges no output that writes text."""
    refuse_capture_journal(path, flag)
    head = _head(path)
    if flag not in CAPTURE_FLAGS and _CAPTURE_OUTPUT.match(head):
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out} holds readings captured from an instrument ('anglebench capture'): "
            "they would be replaced with no way back; nothing was written: choose another "
            "name"), flag=f"{flag} " if flag else "", out=os.fspath(path)))
    if flag in PROJECT_FLAGS:
        return
    if _PROJECT_FORMAT.match(head.lstrip(b"\xef\xbb\xbf")):
        raise _project_refused(path, flag)


def _project_refused(path: str | os.PathLike[str], flag: str) -> OutputRefused:
    return OutputRefused(message(QT_TR_NOOP(
        "{flag}{out} is an AngleBench project: its readings and details would be "
        "replaced with no way back; nothing was written: choose another name"),
        flag=f"{flag} " if flag else "", out=os.fspath(path)))


def refuse_other_project(path: str | os.PathLike[str], data: bytes,
                         flag: str = "--project") -> None:
    """Raise OutputRefused when ``path`` (after links) holds an AngleBench project other
    than ``data``, the project a command-line output would write there: the command line
    asks nothing, as the window's Save as does (hostile77: ``register show N --project
    tuesday.anglebench.json`` replaced a day's typed project, exit 0). The same project
    written again over itself changes nothing and is let be."""
    if not _PROJECT_FORMAT.match(_head(path).lstrip(b"\xef\xbb\xbf")):
        return
    try:
        with open(path, "rb") as handle:
            same = handle.read() == data
    except OSError:
        return
    if not same:
        raise _project_refused(path, flag)


def refuse_register_key(path: str | os.PathLike[str], flag: str = "") -> None:
    """Raise OutputRefused when ``path`` is the laboratory's register key (a file with its
    ``.high-water`` folder beside it) or a high-water mark in that folder (its key beside
    it): an output over the mark stopped all issuing as a register "restored or replayed",
    one over the key made every signature another key's (final review of stop 71)."""
    resolved = Path(_resolved(path))
    folder = resolved.parent
    # os.path's tests: False, not an error, for a name the system cannot take (too long)
    mark = folder.name.endswith(HIGH_WATER_SUFFIX) and \
        os.path.isfile(folder.parent / folder.name[: -len(HIGH_WATER_SUFFIX)])
    key = os.path.isdir(resolved.parent / f"{resolved.name}{HIGH_WATER_SUFFIX}")
    # the key named, before its first signed write made the folder beside it (hostile77 F4:
    # `--results lab.key` replaced a new key with a CSV, which then signed as the key)
    named = os.environ.get(REGISTER_KEY_ENV_VAR, "").strip()
    key = key or bool(named and same_file(path, named))
    if mark or key:
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out} is the certificate register's {what}; nothing was written: choose "
            "another name"), flag=f"{flag} " if flag else "", out=os.fspath(path),
            what=message(QT_TR_NOOP("high-water mark")) if mark else message(
                QT_TR_NOOP("laboratory key"))))


def refuse_pem(path: str | os.PathLike[str], flag: str = "") -> None:
    """Raise OutputRefused when ``path`` (after links) holds a PEM file — the DCC's signing
    key, its certificate, a trusted certificate, wherever they are named (the environment,
    the window's settings) —: no output of AngleBench is one, and a private key replaced is
    lost for good (hostile77 F4: ``--results`` and ``--table`` replaced the DCC signing key
    named by ANGLEBENCH_DCC_SIGNING_KEY)."""
    if _PEM_BEGIN.match(_head(path, 256)):
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out} is a key or a certificate (PEM); nothing was written: choose "
            "another name"), flag=f"{flag} " if flag else "", out=os.fspath(path)))


def refuse_unwritable(path: str | os.PathLike[str], flag: str = "") -> None:
    """Raise OutputRefused when ``path`` could not be written as a file: it exists and is
    not a regular file (a FIFO, a device, a socket), its name is longer than its folder
    allows, or a file cannot be created in its folder (read-only media, no permission: a
    probe file is made there and removed). Run before a certificate's number is used, so
    that what would fail at the write fails before anything is issued (rev62 F6, M1)."""
    out = os.fspath(path)
    said = f"{flag} " if flag else ""
    if not _regular_or_absent(path):
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out} is not a regular file (a pipe, a device or a socket); nothing was "
            "written: name a file"), flag=said, out=out))
    folder = os.path.dirname(os.path.abspath(out))
    try:
        limit = os.pathconf(folder, "PC_NAME_MAX")
    except (OSError, ValueError, AttributeError):
        limit = 255
    if len(os.path.basename(out).encode("utf-8", "surrogateescape")) > limit:
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out}: the name is longer than its folder allows ({limit} bytes); nothing "
            "was written: choose a shorter name"), flag=said, out=out, limit=limit))
    import tempfile  # only when an output is named (a plain analyze loads none of it)

    try:
        fd, probe = tempfile.mkstemp(prefix=".anglebench-probe.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise OutputRefused(message(QT_TR_NOOP(
            "{flag}{out}: no file can be written in {folder} ({reason}); nothing was "
            "written"), flag=said, out=out, folder=folder,
            reason=exc.strerror or str(exc))) from None
    os.close(fd)
    with contextlib.suppress(OSError):
        os.unlink(probe)


def check_outputs(outputs: Sequence[tuple[str, str | os.PathLike[str] | None]],
                  protected: Sequence[Protected]) -> None:
    """Each named output checked against ``protected``, and no two outputs the same file.
    ``outputs``: (flag, path) pairs; a pair without a path is skipped."""
    named = [(flag, out) for flag, out in outputs if out]
    for flag, out in named:
        check_output(out, protected, flag)
    for i, (flag, out) in enumerate(named):
        # names that differ only in case are one file on a case-insensitive file system
        # (macOS, Windows, a FAT stick): refused everywhere (rev62 M5)
        twin = next((f for f, o in named[i + 1:]
                     if same_file(out, o) or _resolved(out).casefold() == _resolved(o).casefold()),
                    None)
        if twin:
            raise OutputRefused(message(QT_TR_NOOP(
                "{flag} and {twin} name the same file ({out}); nothing was written"),
                flag=flag, twin=twin, out=os.fspath(out)))
