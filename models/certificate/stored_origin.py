"""Where a sheet's readings came from, as a project file keeps it (``readings_origin`` of a
workbench: models/project/file.py), so that a project saved and opened again, or recovered
from its autosave, names the same source on its certificate (day review 67: its readings
then counted as typed, or as the project's).

The record is JSON::

    {"source": "imported", "name": "run.csv", "sha256": "…", "edited": false,
     "pasted_rows": [3, 4]}

``source`` is ``typed`` (no file), ``imported`` (``name``, ``sha256`` "" when unknown),
``sample`` (the bundled sample ``name``), ``pasted`` (over the whole sheet), ``sent``
(``workbench``, and ``origin`` its "Readings:" then) or ``project`` (``name``: a project
file that did not record it); ``edited``: the rows were changed since other than by a
paste; ``pasted_rows``: the rows (0-based, as saved) pasted into the sheet since. A
project file without it, or with one that cannot be read, has rows of an origin not
known: :class:`~models.certificate.readings_origin.FromProject` the file it was read from.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

from models.certificate.readings_origin import (
    FromProject,
    ImportedFrom,
    PastedIn,
    SentFrom,
    SheetOrigin,
)

__all__ = ["StoredOrigin", "origin_record", "stored_origin"]


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
        record = {"source": "sent", "workbench": origin.workbench, "origin": origin.origin}
    else:
        record = {"source": "project", "name": origin.name}
    record["edited"] = bool(edited)
    record["pasted_rows"] = sorted({int(r) for r in pasted})
    return record


def _text(record: dict, key: str) -> str | None:
    value = record.get(key, "")
    return value if isinstance(value, str) else None


def stored_origin(record: Any, project: str) -> StoredOrigin:
    """The origin ``record`` keeps (the module's note), read from the project file named
    ``project`` ("" an autosave of an untitled one): none, or one that cannot be read, is
    :class:`FromProject` that file, never typed."""
    unknown = StoredOrigin(FromProject(project))
    if not isinstance(record, dict):
        return unknown
    rows = record.get("pasted_rows", [])
    edited = record.get("edited", False)
    if not isinstance(rows, list) or not all(isinstance(r, int) and not isinstance(r, bool)
                                             and r >= 0 for r in rows) \
            or not isinstance(edited, bool):
        return unknown
    pasted = tuple(sorted(set(rows)))
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
        origin = SentFrom(workbench, sent)
    elif source == "project" and name is not None:
        origin = FromProject(name)
    else:
        return unknown
    return StoredOrigin(origin, edited, pasted)
