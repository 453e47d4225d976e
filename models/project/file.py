"""The project file: one JSON document holding every workbench's readings and settings.

Schema (``schema_version`` 2)::

    {"format": "anglebench-project", "schema_version": 2, "app_version": "0.1.0",
     "metadata": {...},
     "workbenches": {"theodolite": {"rows": [["0", "0", "-0.03"], ...],
                                     "settings": {...},
                                     "readings_origin": {"source": "imported", ...}}, ...},
     "raw_capture": {"polygon": {"sha256": "…", "sessions": [...]}}}

``raw_capture`` (optional in schema 2: absent in a project with no instrument readings,
and in files written before it existed) keeps what the instruments sent, per workbench: see
models/capture/raw_record.py; ``sha256`` is the digest of ``sessions`` as stored, and a
file whose sessions no longer give it, or with a session recorded on another workbench
(its ``workbench``), is refused.

``cell_marks`` (optional in schema 2: absent where the table has no marks, and in files
written before they were kept) are the readings table's marks of cells — a take's reading
at another face or target than its row's — with what is said of each
(models/project/cell_marks.py).

``readings_origin`` (optional in schema 2: absent in files written before it existed) is
where the workbench's readings came from, as its certificate names them: typed, a file
imported (with its SHA-256), the bundled sample, pasted, sent from another workbench, with
the rows pasted since and whether they were edited (models/certificate/stored_origin.py).
A workbench without it has readings of an origin the file does not say: its certificate
says they are "from project NAME", never typed (day review 67).

Cells are stored as the text that was typed, so a file always reopens exactly
as it was saved, bad cells included.

Schema 2 gives the certificate's tolerance and resolution their unit:
``"tolerance": 0.5, "tolerance_unit": "nm"`` where schema 1 wrote
``"tolerance_arcsec": 0.5`` in the unit of the workbench's errors, whatever it was
(nm for an interferometer, the deviation unit of a positioning log); likewise
``item_resolution_arcsec`` and each reference standard's ``uncertainty_arcsec``. A
schema-1 file is migrated as it is read (:func:`migrate_certificate_details`); it is
written back as schema 2.
"""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from models import __version__ as APP_VERSION
from models.capture.raw_record import raw_digest, raw_sessions_from_json, sessions_json_pieces
from models.messages import QT_TR_NOOP, message, reason_of
from models.project.atomic_write import write_bytes_atomic

if TYPE_CHECKING:
    from models.workbench import Workbench

__all__ = [
    "FORMAT_NAME",
    "SCHEMA_VERSION",
    "Project",
    "READINGS_SOURCE",
    "ProjectFileError",
    "WorkbenchState",
    "check_project",
    "file_sha256",
    "load_project",
    "migrate_certificate_details",
    "project_from_json",
    "project_json_parts",
    "project_to_json",
    "save_project",
]

FORMAT_NAME = "anglebench-project"
SCHEMA_VERSION = 2
#: the metadata key of a certificate's project state (the register's record) that holds where
#: its readings came from, as the certificate names them ("Readings: …"): an amendment opened
#: from the register names the same source (rev62 F4)
READINGS_SOURCE = "readings_source"


class ProjectFileError(ValueError):
    """A project file cannot be opened; the message names the file and the reason."""


@dataclass
class WorkbenchState:
    rows: list[list[str]] = field(default_factory=list)
    settings: dict[str, Any] = field(default_factory=dict)
    #: where the rows came from, as the file keeps it (``readings_origin``: see the module's
    #: note; None: not recorded, a file written before it was)
    origin: dict[str, Any] | None = None
    #: the readings table's cell marks as the file keeps them (``cell_marks``:
    #: models/project/cell_marks.py; empty: none, or a file written before they were kept)
    marks: list[dict[str, Any]] = field(default_factory=list)
    #: a polygon certificate's deviations by face, as loaded (the cells' text), kept for the
    #: faces the table has no row of yet: a face taken or typed later gets its deviation
    #: (``certificate_by_face``, optional: empty for other workbenches, for none loaded, and
    #: in a file written before they were kept; gui78)
    certificate_by_face: dict[int, str] = field(default_factory=dict)


@dataclass
class Project:
    workbenches: dict[str, WorkbenchState] = field(default_factory=dict)
    metadata: dict[str, Any] = field(default_factory=dict)
    #: workbench key -> its capture sessions (models/capture/raw_record.py), optional
    raw_capture: dict[str, list[dict[str, Any]]] = field(default_factory=dict)
    #: what was repaired as the file was read (each a sentence naming the place), not saved
    repairs: list[str] = field(default_factory=list, compare=False, repr=False)
    #: SHA-256 (hex) of the file's bytes as read by :func:`load_project` ("" otherwise):
    #: the version a save must not replace unasked when it was changed since
    file_sha256: str = field(default="", compare=False, repr=False)


_ROWS_CHUNK = 20_000


def project_to_json(project: Project) -> str:
    """The project as JSON text."""
    return "".join(project_json_parts(project))


def project_json_parts(project: Project, between_blocks: Callable[[], None] | None = None
                       ) -> Iterator[str]:
    """The project as JSON text, in pieces. Rows are encoded a block at a time: one call
    of json's C encoder on a million rows would hold the interpreter for a second, and an
    autosave thread doing so would freeze the window; between blocks the GUI thread gets
    its turn, and ``between_blocks()`` is called (an autosave waits there while an analysis
    runs)."""
    def dumps(value) -> str:
        # compact separators keep json's C encoder (an indent would switch to the
        # pure-Python one, 30x slower on a million-row signal file)
        return json.dumps(value, ensure_ascii=False, separators=(",", ":"))

    yield (f'{{"format":{dumps(FORMAT_NAME)},"schema_version":{SCHEMA_VERSION},'
           f'"app_version":{dumps(APP_VERSION)},"metadata":{dumps(project.metadata)},'
           '"workbenches":{')
    for i, (key, state) in enumerate(project.workbenches.items()):
        yield ("," if i else "") + f'{dumps(str(key))}:{{"rows":['
        rows = state.rows
        if hasattr(rows, "json_blocks"):  # a column store: unedited blocks encoded once
            blocks = rows.json_blocks(_ROWS_CHUNK, dumps)
        else:
            blocks = (dumps(rows[start:start + _ROWS_CHUNK])[1:-1]
                      for start in range(0, len(rows), _ROWS_CHUNK))
        first = True
        for block in blocks:
            if block:
                yield block if first else "," + block
                first = False
            if between_blocks is not None:
                between_blocks()
        yield f'],"settings":{dumps(state.settings)}'
        if state.origin is not None:
            yield f',"readings_origin":{dumps(state.origin)}'
        if state.marks:
            yield f',"cell_marks":{dumps(state.marks)}'
        if state.certificate_by_face:
            yield (',"certificate_by_face":'
                   f'{dumps({str(k): v for k, v in sorted(state.certificate_by_face.items())})}')
        yield "}"
    yield "}"
    raw = {str(k): v for k, v in project.raw_capture.items() if v}
    if raw:
        yield ',"raw_capture":{'
        for i, (key, sessions) in enumerate(raw.items()):
            # the sessions' text a block of frames at a time (models.capture.raw_record:
            # a day's stream encoded in one call held the interpreter for seconds)
            yield (("," if i else "") + f'{dumps(key)}:{{"sha256":{dumps(raw_digest(sessions))},'
                   '"sessions":')
            for piece in sessions_json_pieces(sessions):
                yield piece
                if between_blocks is not None and len(piece) > 100_000:
                    between_blocks()
            yield "}"
            if between_blocks is not None:
                between_blocks()
        yield "}"
    yield "}"


def project_from_json(text: str, source: str = "project",
                      kinds: Mapping[str, Workbench[Any]] | None = None) -> Project:
    """Build a :class:`Project` from JSON text, checking the schema.

    ``kinds``: the workbenches by key (the caller's: models.registry.KINDS, or the one
    workbench it reads): a schema-1 file's certificate details are in the unit of each
    workbench's errors, which only the workbench knows (Workbench.error_unit); this module
    imports no workbench and no registry. The details of a workbench not in ``kinds`` are
    left as written. Only a schema-1 file with certificate details needs them: ValueError
    when such a file is read without.

    Raises :class:`ProjectFileError` for damaged JSON, a foreign file or a
    file written by a newer schema.
    """
    try:
        document = json.loads(text)
    except json.JSONDecodeError as exc:
        raise ProjectFileError(
            message(
            QT_TR_NOOP("{source}: damaged project file (line {lineno}, column {colno}: {msg}); nothing "
                       "was changed"),
            source=source, lineno=exc.lineno, colno=exc.colno, msg=exc.msg)
        ) from None
    except (RecursionError, ValueError):
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: damaged project file (nested too deep, or a number too long); nothing "
                       "was changed"),
            source=source)) from None
    try:
        repairs = _repair_lone_surrogates(text, document, source)
    except RecursionError:
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: damaged project file (nested too deep, or a number too long); nothing "
                       "was changed"),
            source=source)) from None
    if not isinstance(document, dict) or document.get("format") != FORMAT_NAME:
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: not an AngleBench project file"),
            source=source))
    version = document.get("schema_version")
    if not isinstance(version, int) or version < 1:
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: schema_version is missing or invalid"),
            source=source))
    if version > SCHEMA_VERSION:
        raise ProjectFileError(
            message(
            QT_TR_NOOP("{source}: written by a newer AngleBench (schema {version}; this version reads up "
                       "to {schema_version}). Nothing was changed; update AngleBench to open it."),
            source=source, version=version, schema_version=SCHEMA_VERSION)
        )
    benches = document.get("workbenches", {})
    if not isinstance(benches, dict):
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: 'workbenches' must be an object"),
            source=source))
    metadata = document.get("metadata") or {}
    if not isinstance(metadata, dict):
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: 'metadata' must be an object; nothing was changed"),
            source=source))
    certificates = metadata.get("certificates", {})
    if not isinstance(certificates, dict) or not all(isinstance(c, dict)
                                                     for c in certificates.values()):
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: 'metadata.certificates' must map workbenches to objects; nothing was "
                       "changed"),
            source=source))
    project = Project(metadata=dict(metadata))
    if version < 2 and certificates:
        if kinds is None:
            raise ValueError(f"{source}: a schema-1 project's certificate details are in each "
                             "workbench's error unit: read it with kinds (the workbenches)")
        settings_of = {key: state.get("settings") for key, state in benches.items()
                       if isinstance(state, dict) and isinstance(state.get("settings"), dict)}
        project.metadata["certificates"] = {
            key: migrate_certificate_details(details, kinds[key].error_unit(
                settings_of.get(key) or {})) if key in kinds else details
            for key, details in certificates.items()}
    for key, state in benches.items():
        if not isinstance(state, dict):
            raise ProjectFileError(message(
                QT_TR_NOOP("{source}: workbench '{key}' must be an object"),
                source=source, key=key))
        rows = state.get("rows", [])
        if not isinstance(rows, list) or not all(isinstance(r, list) for r in rows):
            raise ProjectFileError(message(
                QT_TR_NOOP("{source}: workbench '{key}': 'rows' must be a list of lists"),
                source=source, key=key))
        if not all(isinstance(c, str | int | float | type(None)) and not isinstance(c, bool)
                   for r in rows for c in r):
            raise ProjectFileError(message(
                QT_TR_NOOP("{source}: workbench '{key}': every cell must be text"),
                source=source, key=key))
        clean_rows = [["" if c is None else str(c) for c in r] for r in rows]
        settings = state.get("settings", {})
        if not isinstance(settings, dict):
            raise ProjectFileError(message(
                QT_TR_NOOP("{source}: workbench '{key}': 'settings' must be an object"),
                source=source, key=key))
        # where the rows came from: read as it is (models/certificate/stored_origin.py
        # judges it; one it cannot read is an origin not known, never a refused project)
        origin = state.get("readings_origin")
        # the table's cell marks (optional; one that cannot be read is left out, never a
        # refused project: models/project/cell_marks.py)
        marks = state.get("cell_marks", [])
        project.workbenches[str(key)] = WorkbenchState(
            clean_rows, dict(settings), dict(origin) if isinstance(origin, dict) else None,
            [dict(m) for m in marks if isinstance(m, dict)] if isinstance(marks, list) else [],
            _certificate_by_face(state.get("certificate_by_face")))
    project.raw_capture = _raw_capture(document.get("raw_capture", {}), source)
    project.repairs = repairs
    return project


def _certificate_by_face(kept: Any) -> dict[int, str]:
    """The polygon certificate's deviations by face as the file keeps them (optional): each
    face a whole number ≥ 1 with its deviation's text; an entry that is not is left out,
    never a refused project (the certificate can be loaded again)."""
    if not isinstance(kept, dict):
        return {}
    out: dict[int, str] = {}
    for face, value in kept.items():
        if isinstance(face, str) and face.isdigit() and int(face) >= 1 \
                and isinstance(value, str) and value.strip():
            out[int(face)] = value.strip()
    return out


#: a UTF-16 surrogate written as a JSON escape (a pair, or half of one), or one in the text
_MAYBE_SURROGATE = re.compile(r"\\u[dD][89abcdefABCDEF]|[\ud800-\udfff]")
_LONE_SURROGATE = re.compile(r"[\ud800-\udfff]")


def _repair_lone_surrogates(text: str, document: Any, source: str) -> list[str]:
    """Each lone UTF-16 surrogate in ``document``'s texts (a JSON escape such as
    ``"\\ud800"``: half of a character, written by a tool that cut an emoji in two, or by
    hand) replaced by U+FFFD, in place; a sentence naming each place and what was done.
    Such text cannot be written as UTF-8: a project holding one could never be saved.
    Raw frames are not repaired (that would change what the instrument sent): refused.
    ``text`` is only searched, so a file with no escape of a surrogate costs one scan."""
    if not _MAYBE_SURROGATE.search(text):
        return []
    repairs: list[str] = []

    def fixed(value: str, place: tuple, is_key: bool = False) -> str:
        if not _LONE_SURROGATE.search(value):
            return value
        codes = ", ".join(f"U+{ord(c):04X}" for c in _LONE_SURROGATE.findall(value))
        repaired = _LONE_SURROGATE.sub("\ufffd", value)
        if is_key:  # the place named by the key as it now reads
            place = (*place[:-1], repaired)
        if place[:1] == ("raw_capture",):
            raise ProjectFileError(message(
                QT_TR_NOOP("{source}: {where}: a broken character ({codes}: half of a UTF-16 "
                           "pair) in the raw frames; nothing was changed"),
                source=source, where=_place(place), codes=codes))
        repairs.append(message(
            QT_TR_NOOP("{source}: {where}: a broken character ({codes}: half of a UTF-16 pair) "
                       "was replaced by U+FFFD (\ufffd)"),
            source=source, where=_place(place), codes=codes))
        return repaired

    def walk(value: Any, place: tuple) -> Any:
        if isinstance(value, str):
            return fixed(value, place)
        if isinstance(value, list):
            for i, item in enumerate(value):
                if isinstance(item, str | list | dict):
                    value[i] = walk(item, (*place, i))
        elif isinstance(value, dict):
            for key in list(value):
                new_key = fixed(key, (*place, key), is_key=True) if isinstance(key, str) else key
                item = value.pop(key) if new_key != key else value[key]
                value[new_key] = walk(item, (*place, new_key)) \
                    if isinstance(item, str | list | dict) else item
        return value

    walk(document, ())
    return repairs


def _place(place: tuple) -> str:
    """Where a text is in the project document, as the window names it."""
    if len(place) >= 5 and place[0] == "workbenches" and place[2] == "rows":
        return message(QT_TR_NOOP("workbench '{key}', row {row}, column {column}"),
                       key=place[1], row=place[3] + 1, column=place[4] + 1)
    if len(place) >= 4 and place[0] == "workbenches" and place[2] == "settings":
        return message(QT_TR_NOOP("workbench '{key}', setting '{name}'"),
                       key=place[1], name=place[3])
    if len(place) >= 4 and place[:2] == ("metadata", "certificates"):
        return message(QT_TR_NOOP("certificate details of workbench '{key}', '{name}'"),
                       key=place[2], name=place[3])
    return message(QT_TR_NOOP("'{name}'"), name=" › ".join(str(p) for p in place))


def _raw_capture(raw: Any, source: str) -> dict[str, list[dict[str, Any]]]:
    """The optional raw frames, checked against their digest."""
    if not isinstance(raw, dict):
        raise ProjectFileError(message(
            QT_TR_NOOP("{source}: 'raw_capture' must be an object; nothing was changed"),
            source=source))
    out = {}
    for key, entry in raw.items():
        where = f"{source}: raw_capture '{key}'"
        if not isinstance(entry, dict) or not isinstance(entry.get("sha256"), str):
            raise ProjectFileError(message(
                QT_TR_NOOP("{where}: 'sha256' and 'sessions' expected; nothing was changed"),
                where=where))
        try:
            sessions = raw_sessions_from_json(entry.get("sessions"), where)
        except ValueError as exc:
            raise ProjectFileError(message(QT_TR_NOOP("{reason}; nothing was changed"),
                                           reason=reason_of(exc))) from None
        if raw_digest(sessions) != entry["sha256"]:
            raise ProjectFileError(message(
                QT_TR_NOOP("{where}: the raw frames do not give their SHA-256 (changed after "
                           "they were captured); nothing was changed"), where=where))
        for i, session in enumerate(sessions, 1):
            # bound to its workbench (review 61 F7: a raw record moved under another
            # workbench's readings stayed valid); a session of 0.8.10 names none
            if session.get("workbench", key) != key:
                raise ProjectFileError(message(
                    QT_TR_NOOP("{where}, session {i}: recorded on workbench '{recorded}', not "
                               "this one (moved in the file); nothing was changed"),
                    where=where, i=i, recorded=session["workbench"]))
        out[str(key)] = sessions
    return out


def migrate_certificate_details(details: dict[str, Any], error_unit: str) -> dict[str, Any]:
    """Certificate details written before the tolerance and the resolution had their unit
    (``tolerance_arcsec``, ``item_resolution_arcsec``: in the unit of the workbench's errors
    ``error_unit``) with ``tolerance`` and ``tolerance_unit`` (``item_resolution``,
    ``item_resolution_unit``); details that already state them come back as they are."""
    out = dict(details)
    for old, new in (("tolerance_arcsec", "tolerance"), ("item_resolution_arcsec", "item_resolution")):
        if old in out and new not in out:
            out[new] = out.pop(old)
            out[f"{new}_unit"] = error_unit
    standards = out.get("standards")
    if isinstance(standards, list):
        out["standards"] = [
            {**{k: v for k, v in s.items() if k != "uncertainty_arcsec"},
             "uncertainty": s["uncertainty_arcsec"], "uncertainty_unit": error_unit}
            if isinstance(s, dict) and "uncertainty_arcsec" in s and "uncertainty" not in s else s
            for s in standards]
    return out


def check_project(project: Project, kinds: Mapping[str, Any], source: str = "project") -> None:
    """Check every workbench of an opened project against its kind before anything is
    replaced: a known workbench, rows that fit its columns, settings of the right type
    and range. Raises :class:`ProjectFileError` naming the workbench and what is wrong."""
    for key, state in project.workbenches.items():
        kind = kinds.get(key)
        if kind is None:
            raise ProjectFileError(message(
                QT_TR_NOOP("{source}: workbench '{key}' is not one this version knows; nothing was "
                           "changed"),
                source=source, key=key))
        width = len(kind.columns)
        for i, row in enumerate(state.rows, 1):
            if len(row) > width and any(c.strip() for c in row[width:]):
                raise ProjectFileError(message(
                    QT_TR_NOOP("{source}: workbench '{key}', row {i}: {len} cells for {width} columns; "
                               "nothing was changed"),
                    source=source, key=key, i=i, len=len(row), width=width))
        try:
            kind.checked_settings(state.settings)
        except ValueError as exc:
            raise ProjectFileError(message(
                QT_TR_NOOP("{source}: workbench '{key}': {exc}; nothing was changed"),
                source=source, key=key, exc=reason_of(exc))) \
                from None


def save_project(path: str | Path, project: Project,
                 between_blocks: Callable[[], None] | None = None, *,
                 through_link: bool = True) -> str:
    """Write the project atomically (temp file + rename); the SHA-256 (hex) of the bytes
    written. ``through_link``: as :func:`write_bytes_atomic`'s (False: a symbolic link at
    ``path`` is replaced, never written through).

    A lone UTF-16 surrogate (half a character, which UTF-8 cannot hold: pasted, or from a
    tool) is written as its JSON escape (``\\ud800``, "backslashreplace": outside a JSON
    string there is no text but ASCII) instead of failing the save: the file is valid
    UTF-8 and reads back exactly, and opening it replaces the character, saying where."""
    digest = hashlib.sha256()

    def encoded(pieces):
        for piece in pieces:
            data = piece.encode("utf-8", "backslashreplace")
            digest.update(data)
            yield data

    write_bytes_atomic(path, encoded(project_json_parts(project, between_blocks)),
                       through_link=through_link)
    return digest.hexdigest()


def file_sha256(path: str | Path) -> str:
    """SHA-256 (hex) of the file at ``path`` (OSError when it cannot be read)."""
    digest = hashlib.sha256()
    with open(path, "rb") as handle:
        while block := handle.read(1 << 20):
            digest.update(block)
    return digest.hexdigest()


def load_project(path: str | Path, kinds: Mapping[str, Workbench[Any]] | None = None
                 ) -> Project:
    """The project at ``path`` (``kinds``: the workbenches, see :func:`project_from_json`)."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise ProjectFileError(message(
            QT_TR_NOOP("{path}: cannot read ({value})"),
            path=path, value=exc.strerror or exc)) from None
    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        raise ProjectFileError(message(
            QT_TR_NOOP("{path}: damaged project file (not UTF-8 text)"),
            path=path)) from None
    project = project_from_json(text, str(path), kinds)
    project.file_sha256 = hashlib.sha256(data).hexdigest()
    return project
