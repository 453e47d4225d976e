"""``anglebench analyze … --certificate OUT.pdf --capture-record RAW.csv``: the instrument's
own output that ``anglebench capture --raw RAW.csv`` wrote (``time_s,reading,line``: every
line the instrument sent, and whether it became a reading), read back as a capture session
(models/capture/raw_record.py) behind the readings file's rows, so that a certificate
issued from the command line says which rows were captured from the instruments and names
the instrument output's SHA-256, as the window's does (stop 63: it named the readings file
alone).

Which row a reading went to: the readings file's ``time_s`` column when it has one (the
capture's ``--out`` keeps it; a row whose ``time_s`` is a reading's time in the record is
that reading's, any other row typed); without it, the record's readings are the file's
filled rows in order, as ``--out`` wrote them. A reading is one flagged line (``reading``
1), or with ``--stable`` the flagged lines of its dwell, which end at the line whose time
is the reading's.

The rows are then checked against the lines as the window checks a sheet
(app/certificate_issue.readings_edited_after_capture): a captured row whose value is not
what the instrument sent is refused, naming the file and the row, unless the edit is
declared (``--edited-after-capture``) — then the certificate lists every edit, as the
window's does.
"""

from __future__ import annotations

import csv
import io
from collections.abc import Sequence
from typing import Any

from app.capture.instruments import INSTRUMENTS, LineReadoutInstrument, SignalStreamInstrument
from models.messages import QT_TR_NOOP, message

__all__ = ["CaptureRecordError", "capture_session", "instrument_for"]

#: the instruments whose every value has a column of its own in a workbench's sheet (a
#: readout's value goes to a cell chosen when it is taken: not in a record's lines)
_SHEET_INSTRUMENTS = tuple(name for name, kind in INSTRUMENTS.items()
                           if not issubclass(kind, (LineReadoutInstrument, SignalStreamInstrument)))


class CaptureRecordError(ValueError):
    """The capture record cannot be read, or is not the readings': the message says which
    file and which line or row."""


def instrument_for(keys: Sequence[str]) -> str | None:
    """The instrument whose every value the sheet of ``keys`` has a column for (a
    theodolite's zenith angle goes to an elevation column); None when there is none."""
    for name in _SHEET_INSTRUMENTS:
        held = INSTRUMENTS[name]().columns
        if all(key in keys or (key == "zenith_deg" and "elevation_deg" in keys)
               for key in held):
            return name
    return None


def _frames(path: str, data: bytes) -> list[list[Any]]:
    """The record's lines as a session's frames ([seconds, line, 0/1])."""
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise CaptureRecordError(message(QT_TR_NOOP(
            "{path}: not a capture record written by 'anglebench capture --raw' (not UTF-8 "
            "text)"), path=path)) from None
    lines = list(csv.reader(io.StringIO(text, newline="")))
    if not lines or [cell.strip() for cell in lines[0]] != ["time_s", "reading", "line"]:
        raise CaptureRecordError(message(QT_TR_NOOP(
            "{path}: not a capture record written by 'anglebench capture --raw' (its first "
            "line is not time_s,reading,line)"), path=path))
    frames = []
    for number, cells in enumerate(lines[1:], 2):
        try:
            seconds, used, line = cells
            line.encode("latin-1")  # a line as sent: one code point a byte
            frames.append([float(seconds), line, {"1": 1, "0": 0}[used.strip()]])
        except (ValueError, KeyError, UnicodeEncodeError):
            raise CaptureRecordError(message(QT_TR_NOOP(
                "{path}: line {line} is not 'seconds,1 or 0,the line as sent'"),
                path=path, line=number)) from None
    return frames


def _filled(row: Sequence[str]) -> bool:
    return any(str(cell).strip() for cell in row)


def _number(text: str) -> float | None:
    try:
        return float(text)
    except (TypeError, ValueError):
        return None


def capture_session(path: str, data: bytes, readings_file: str, workbench: str,
                    keys: Sequence[str], rows: Sequence[Sequence[str]],
                    times: Sequence[str] | None) -> dict[str, Any]:
    """The capture session of the record ``data`` (read from ``path``) behind ``rows`` (the
    readings of ``readings_file`` in the columns ``keys``; ``times`` the file's ``time_s``
    cell of each row, None when it has no such column), recorded on ``workbench``."""
    instrument = instrument_for(keys)
    if instrument is None:
        raise CaptureRecordError(message(QT_TR_NOOP(
            "{path}: the {workbench} workbench has no column for an autocollimator's or a "
            "theodolite's reading: a capture record cannot be checked against its rows"),
            path=path, workbench=workbench))
    frames = _frames(path, data)
    flagged = [i for i, frame in enumerate(frames) if frame[2]]
    takes: list[list[int]] = []
    if times is not None:
        at = {}
        for row, text in enumerate(times):
            seconds = _number(text)
            if seconds is not None and _filled(rows[row]):
                at.setdefault(seconds, row)
        claimed = -1
        for j in flagged:
            if frames[j][0] not in at:
                continue
            first = j  # a dwell's earlier lines: flagged, no reading's own time, not taken
            while (first - 1 > claimed and frames[first - 1][2]
                   and frames[first - 1][0] not in at):
                first -= 1
            takes.append([at.pop(frames[j][0]), first, j])
            claimed = j
        if not takes:
            raise CaptureRecordError(message(QT_TR_NOOP(
                "{path}: no row of {file} is a reading of this capture record (no time_s of "
                "a row is the time of a reading in it): the record of another capture?"),
                path=path, file=readings_file))
    else:
        filled = [row for row, cells in enumerate(rows) if _filled(cells)]
        runs: list[list[int]] = []
        for j in flagged:
            if runs and runs[-1][1] == j - 1:
                runs[-1][1] = j
            else:
                runs.append([j, j])
        readings = ([[j, j] for j in flagged] if len(flagged) == len(filled) else runs)
        if len(readings) != len(filled):
            raise CaptureRecordError(message(QT_TR_NOOP(
                "{path}: {n} readings in the capture record, {m} rows in {file}: which row "
                "holds which reading is not known (keep the capture's time_s column in the "
                "readings file)"), path=path, n=len(readings), m=len(filled),
                file=readings_file))
        takes = [[row, first, last] for row, (first, last) in zip(filled, readings, strict=True)]
    return {"instrument": instrument, "port": "", "baud": 0, "started_utc": "",
            "frames": frames, "takes": takes, "workbench": workbench}
