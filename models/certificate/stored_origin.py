"""Where a sheet's readings came from, as a project file keeps it (``readings_origin`` of a
workbench: models/project/file.py), so that a project saved and opened again, or recovered
from its autosave, names the same source on its certificate (day review 67: its readings
then counted as typed, or as the project's).

The record is JSON::

    {"source": "imported", "name": "run.csv", "sha256": "…", "edited": false,
     "pasted_rows": [3, 4]}

``source`` is ``typed`` (no file), ``imported`` (``name``, ``sha256`` "" when unknown),
``sample`` (the bundled sample ``name``), ``pasted`` (over the whole sheet), ``sent``
(``workbench``, ``origin`` its "Readings:" then, in English, and ``readings`` what that
line was made of) or ``project`` (``name``: a project file that did not record it);
``edited``: the rows were changed since other than by a paste; ``pasted_rows``: the rows
(0-based, as saved) pasted into the sheet since. A project file without it, or with one
that cannot be read, has rows of an origin not known:
:class:`~models.certificate.readings_origin.FromProject` the file it was read from.

A sent origin's ``readings`` (day review 67 F3: its English ``origin`` text alone was
printed in English on a Chinese certificate) is::

    {"origin": {"source": "imported", "name": "run.csv", "sha256": "…", "edited": true,
                "pasted_rows": [5, 6]},
     "rows": 50, "captured_rows": [8, 9], "project": "job.anglebench.json",
     "unsaved": false, "named": ""}

the sending sheet's origin (as above), its filled rows' count, the rows captured from the
instruments (0-based), the project file it was in ("" none), whether it was changed after
that file was saved, and the source a register's record named ("" none). A file written
before ``readings`` was kept (or with one that cannot be read) has its ``origin`` text
said as it is.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from models.certificate.readings_origin import (
    FromProject,
    ImportedFrom,
    PastedIn,
    ReadingsStatement,
    SentFrom,
    SheetOrigin,
    stated,
)

__all__ = ["StoredOrigin", "origin_record", "statement_record", "stored_origin"]


@dataclass(frozen=True)
class StoredOrigin:
    """A sheet's origin as read back: the step's ``origin`` (None: typed), ``edited``
    since, and the rows ``pasted`` since (0-based, ascending)."""

    origin: SheetOrigin | None = None
    edited: bool = False
    pasted: tuple[int, ...] = ()


def origin_record(origin: SheetOrigin | None, edited: bool, pasted: Iterable[int]) -> dict:
    """The project file's record of a sheet's origin (the module's note)."""
    record: dict[str, Any]
    if origin is None:
        record = {"source": "typed"}
    elif isinstance(origin, ImportedFrom):
        record = {"source": "sample" if origin.sample else "imported", "name": origin.name}
        if origin.sha256:
            record["sha256"] = origin.sha256
    elif isinstance(origin, PastedIn):
        record = {"source": "pasted"}
    elif isinstance(origin, SentFrom):
        # the English text too: what a reader written before ``readings`` says
        text = stated(origin.readings) if origin.readings is not None else origin.origin
        record = {"source": "sent", "workbench": origin.workbench, "origin": str(text)}
        if origin.readings is not None:
            record["readings"] = statement_record(origin.readings)
    else:
        record = {"source": "project", "name": origin.name}
    record["edited"] = bool(edited)
    record["pasted_rows"] = sorted({int(r) for r in pasted})
    return record


def statement_record(statement: ReadingsStatement) -> dict:
    """The project file's record of a sent origin's ``readings`` (the module's note)."""
    return {"origin": origin_record(statement.origin, statement.edited, statement.pasted),
            "rows": int(statement.row_count),
            "captured_rows": sorted({int(r) for r in statement.captured}),
            "project": statement.project, "unsaved": bool(statement.unsaved),
            "named": statement.named}


def _rows(value: Any) -> tuple[int, ...] | None:
    """Row numbers (0-based) as a record keeps them, ascending; None when they are not."""
    if not isinstance(value, list) or not all(isinstance(r, int) and not isinstance(r, bool)
                                              and r >= 0 for r in value):
        return None
    return tuple(sorted(set(value)))


#: how many sent origins deep a record is read (a sheet sent on from a sheet sent to it …):
#: a file nested deeper is not read to its end (its recursion would end the window)
_DEPTH = 8


def _statement(record: Any, depth: int) -> ReadingsStatement | None:
    """The ``readings`` of a sent origin's record (the module's note), ``depth`` sent
    origins in; None when it cannot be read whole."""
    if not isinstance(record, dict) or depth > _DEPTH:
        return None
    opened = _read(record.get("origin"), depth)
    count, captured = record.get("rows"), _rows(record.get("captured_rows", []))
    project, named = _text(record, "project"), _text(record, "named")
    unsaved = record.get("unsaved", False)
    if opened is None or captured is None or project is None or named is None \
            or not isinstance(unsaved, bool) or not isinstance(count, int) \
            or isinstance(count, bool) or count < 0:
        return None
    return ReadingsStatement(opened.origin, opened.edited, opened.pasted, count, captured,
                             project, unsaved, named)


def _text(record: dict, key: str) -> str | None:
    value = record.get(key, "")
    return value if isinstance(value, str) else None


def stored_origin(record: Any, project: str) -> StoredOrigin:
    """The origin ``record`` keeps (the module's note), read from the project file named
    ``project`` ("" an autosave of an untitled one): none, or one that cannot be read, is
    :class:`FromProject` that file, never typed."""
    read = _read(record)
    return StoredOrigin(FromProject(project)) if read is None else read


def _read(record: Any, depth: int = 0) -> StoredOrigin | None:
    """The origin ``record`` keeps (``depth`` sent origins in); None when there is none
    that can be read."""
    if not isinstance(record, dict):
        return None
    pasted = _rows(record.get("pasted_rows", []))
    edited = record.get("edited", False)
    if pasted is None or not isinstance(edited, bool):
        return None
    source = record.get("source")
    name, sha256 = _text(record, "name"), _text(record, "sha256")
    workbench, sent = _text(record, "workbench"), _text(record, "origin")
    origin: SheetOrigin | None
    if source == "typed":
        origin = None
    elif source in ("imported", "sample") and name and sha256 is not None:
        origin = ImportedFrom(name, sha256, source == "sample")
    elif source == "pasted":
        origin = PastedIn()
    elif source == "sent" and workbench and sent is not None:
        origin = SentFrom(workbench, sent, _statement(record.get("readings"), depth + 1))
    elif source == "project" and name is not None:
        origin = FromProject(name)
    else:
        return None
    return StoredOrigin(origin, edited, pasted)
