"""The capture journal: every reading and every raw frame appended, as it arrives, to a file
beside the capture's output, so that nothing taken is lost when the process is killed
(SIGTERM, SIGHUP, kill -9, a power cut) or the disk fills before the output is written.

Each reading is flushed and ``fsync``'ed before it counts as taken; frames are written as
they come but synced only with the next reading (a frame is the instrument's trace, a
reading is what the technician needs). The journal is a CSV one can open::

    # anglebench capture journal 1
    # started,2026-12-02T05:55:49+00:00
    # instrument,autocollimator
    # port,/dev/ttyUSB0
    # out,/home/lab/ac.csv
    # raw,/home/lab/ac.raw.csv
    # columns,time_s,ac_x_arcsec,ac_y_arcsec
    frame,0.004,1,"031,+012.50,-003.25"
    reading,0.004,12.5,-3.25

A ``reading`` row holds the output's columns (``time_s`` first), a ``frame`` row the time,
whether the line became a reading (1/0) and the line as the instrument sent it (bytes that
are not ASCII as ``\\xNN``). A line cut short by the kill is ignored when it is read back.

The journal is removed once the output (and the raw trace) have been written; one left over
means the capture that wrote it did not end: :func:`recover_journal` reads it back.
"""

from __future__ import annotations

import contextlib
import csv
import io
import os
from dataclasses import dataclass, field
from pathlib import Path

try:  # POSIX: a lock the kernel drops when the process dies
    import fcntl
except ImportError:  # pragma: no cover - Windows
    fcntl = None  # type: ignore[assignment]

__all__ = ["JOURNAL_SUFFIX", "CaptureJournal", "JournalContents", "journal_in_use",
           "journal_path", "read_journal"]

JOURNAL_SUFFIX = ".capture-journal.csv"
_MAGIC = "# anglebench capture journal 1"


def journal_path(out: str | os.PathLike[str]) -> Path:
    """The journal of a capture into ``out``: beside it, ``out`` + ``.capture-journal.csv``."""
    path = Path(out)
    return path.with_name(path.name + JOURNAL_SUFFIX)


def _line(cells) -> str:
    buffer = io.StringIO()
    csv.writer(buffer, lineterminator="\n").writerow(cells)
    return buffer.getvalue()


def frame_text(line: bytes) -> str:
    """A raw line as text: ASCII as is, any other byte as ``\\xNN``."""
    return line.decode("ascii", "backslashreplace")


class CaptureJournal:
    """Append-only journal at ``path`` (created; an existing file is never overwritten:
    FileExistsError). ``info``: the header's name/value pairs (instrument, port, out, raw)."""

    def __init__(self, path: str | os.PathLike[str], columns: tuple[str, ...],
                 info: dict[str, str]) -> None:
        self.path = Path(path)
        self.columns = tuple(columns)
        self.readings = 0
        self.frames = 0
        # O_EXCL: a journal left by a killed capture is recovered, never replaced
        fd = os.open(self.path, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0),
                     0o666)
        if fcntl is not None:  # held while the capture runs (the kernel drops it at a kill)
            fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
        self._file = os.fdopen(fd, "w", encoding="utf-8", newline="")
        try:
            header = [_MAGIC + "\n"] + [_line([f"# {k}", v]) for k, v in info.items()]
            header.append(_line(["# columns", *self.columns]))
            self._file.write("".join(header))
            self._sync()
        except BaseException:
            self.close()
            raise

    def _sync(self) -> None:
        self._file.flush()
        os.fsync(self._file.fileno())

    def frame(self, time_s: float, line: bytes, used: bool) -> None:
        """A line the instrument sent (written now, synced with the next reading)."""
        self._file.write(_line(["frame", repr(round(time_s, 6)), int(used), frame_text(line)]))
        self.frames += 1

    def reading(self, row: list[object]) -> None:
        """A reading (the output's row): on disk when this returns (OSError when it cannot
        be: the disk is full; the reading is then not taken)."""
        self._file.write(_line(["reading", *row]))
        self._sync()
        self.readings += 1

    def sync(self) -> None:
        """The frames written so far on disk too."""
        self._sync()

    def close(self) -> None:
        with contextlib.suppress(OSError, ValueError):
            self._sync()
        with contextlib.suppress(OSError, ValueError):
            self._file.close()

    def remove(self) -> None:
        """The output is written: the journal is no longer needed."""
        self.close()
        with contextlib.suppress(FileNotFoundError):
            os.unlink(self.path)


def journal_in_use(path: str | os.PathLike[str]) -> bool:
    """Whether a running capture holds the journal at ``path`` (its lock is taken)."""
    if fcntl is None:  # pragma: no cover - Windows: an open file cannot be removed anyway
        return False
    try:
        fd = os.open(path, os.O_RDONLY)
    except OSError:
        return False
    try:
        fcntl.flock(fd, fcntl.LOCK_EX | fcntl.LOCK_NB)
    except OSError:
        return True
    else:
        fcntl.flock(fd, fcntl.LOCK_UN)
        return False
    finally:
        os.close(fd)


@dataclass
class JournalContents:
    """What a journal holds: its header, the readings (output rows, without the ``reading``
    tag) and the raw frames ``(time_s, used, line)`` as text."""

    info: dict[str, str] = field(default_factory=dict)
    columns: tuple[str, ...] = ()
    readings: list[list[str]] = field(default_factory=list)
    frames: list[tuple[str, str, str]] = field(default_factory=list)


def read_journal(path: str | os.PathLike[str]) -> JournalContents:
    """Read a journal back (a row cut short by a kill, or one that does not read, is left
    out: it was never synced as taken). ValueError when ``path`` is not a capture journal."""
    with open(path, encoding="utf-8", errors="replace", newline="") as handle:
        text = handle.read()
    contents = JournalContents()
    if _MAGIC.startswith(text):  # killed before its header was on disk: nothing in it
        return contents
    if not text.startswith(_MAGIC):
        raise ValueError(f"{path}: not a capture journal")
    complete = text if text.endswith("\n") else text[: text.rfind("\n") + 1]
    for row in csv.reader(io.StringIO(complete)):
        if not row:
            continue
        tag = row[0]
        if tag == "# columns":
            contents.columns = tuple(row[1:])
        elif tag.startswith("# ") and len(row) == 2:
            contents.info[tag[2:]] = row[1]
        elif tag == "reading" and contents.columns and len(row) == len(contents.columns) + 1:
            contents.readings.append(row[1:])
        elif tag == "frame" and len(row) == 4:
            contents.frames.append((row[1], row[2], row[3]))
    return contents
