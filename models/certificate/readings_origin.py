"""Where a certificate's readings came from, as its "Readings:" line says it: the project's
file (or the file imported, the readings pasted, the workbench they were sent from, or
"readings typed in AngleBench"), the rows pasted into the sheet and, when rows were taken
from the instruments, which (day review 64 P8: "readings typed in AngleBench" was printed
of rows captured from the instruments, the PDF's "Instrument output SHA-256" line the only
hint; day review 66: and of readings pasted, or sent from another workbench)."""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass
from typing import Any

from models.messages import QT_TR_NOOP, message

__all__ = ["PASTED", "TYPED", "FromProject", "ImportedFrom", "PastedIn", "ReadingsStatement",
           "SentFrom", "SheetOrigin", "captured_rows", "filled_rows", "imported_source",
           "in_project", "readings_origin", "row_spans", "sheet_source", "source_stated",
           "stated"]

#: the readings' source when they are in no project file: typed into the sheet
TYPED = QT_TR_NOOP("readings typed in AngleBench")
#: the readings' source when they were pasted over the sheet from the clipboard (whose
#: source is not known to AngleBench)
PASTED = QT_TR_NOOP("readings pasted into AngleBench")


@dataclass(frozen=True)
class ImportedFrom:
    """The file a workbench's readings were imported from (File › Import, or the bundled
    sample: ``sample``), with the SHA-256 of its bytes as read ("" when it could not be
    read again). Day review 65 F4: an unsaved project's certificate said "readings typed in
    AngleBench" of readings imported from a CSV or loaded from the sample."""

    name: str
    sha256: str = ""
    sample: bool = False


@dataclass(frozen=True)
class PastedIn:
    """The sheet's rows were pasted over it from the clipboard (Edit › Paste replacing the
    sheet): where they were copied from is not known (day review 66: they were "readings
    typed in AngleBench")."""


@dataclass(frozen=True)
class SentFrom:
    """The sheet's rows were sent from another workbench (File › Send to positioning):
    ``workbench`` its title (a declared text), ``origin`` that workbench's own "Readings:"
    line when they were sent ("" when it has none), ``readings`` what that line was made of
    (None: not known, a project file written before it was kept: ``origin`` is then said as
    it is). Day review 67 F3: kept as its English text only, a Chinese certificate printed
    it in English after the project was saved and opened again."""

    workbench: str
    origin: str = ""
    readings: ReadingsStatement | None = None


@dataclass(frozen=True)
class FromProject:
    """The sheet's rows were read from a project file that does not record where they came
    from (written before it did: models/project/file.py ``readings_origin``), ``name`` its
    file's name ("" an autosave of an untitled project). Day review 67: such rows, and any
    whose origin was lost with a save or a crash, counted as "readings typed in
    AngleBench"."""

    name: str = ""


#: where a sheet's rows came from when one step replaced them all (None: typed, or a
#: project's)
SheetOrigin = ImportedFrom | PastedIn | SentFrom | FromProject


@dataclass(frozen=True)
class ReadingsStatement:
    """What a sheet's "Readings:" line is made of (:func:`stated` words it, in any
    language): ``origin``, ``edited`` and ``pasted`` as :func:`sheet_source` takes them, of
    ``row_count`` filled rows, the rows ``captured`` from the instruments (0-based), the
    name of the ``project`` file the window had them in ("" none), whether they were
    changed in the window after that file was saved or recovered (``unsaved``: day review
    67 F4), and the source a register's record ``named`` of an untitled project's."""

    origin: SheetOrigin | None = None
    edited: bool = False
    pasted: tuple[int, ...] = ()
    row_count: int = 0
    captured: tuple[int, ...] = ()
    project: str = ""
    unsaved: bool = False
    named: str = ""


def imported_source(origin: ImportedFrom, edited: bool) -> str:
    """The certificate's source of readings imported from a file: its name (and SHA-256),
    or the bundled sample; ``edited``: the rows were changed in the window after the
    import (typed, pasted or deleted), which the source then says."""
    if origin.sample:
        template = (QT_TR_NOOP("the bundled sample {name}, edited in AngleBench") if edited
                    else QT_TR_NOOP("the bundled sample {name}"))
        return message(template, name=origin.name)
    if origin.sha256:
        template = (QT_TR_NOOP("imported from {name} (SHA-256 {sha256}), edited in "
                               "AngleBench") if edited
                    else QT_TR_NOOP("imported from {name} (SHA-256 {sha256})"))
        return message(template, name=origin.name, sha256=origin.sha256)
    template = (QT_TR_NOOP("imported from {name}, edited in AngleBench") if edited
                else QT_TR_NOOP("imported from {name}"))
    return message(template, name=origin.name)


def _replaced_source(origin: SheetOrigin, edited: bool) -> str:
    """The source of rows that replaced the sheet in one step (``edited``: changed since)."""
    if isinstance(origin, ImportedFrom):
        return imported_source(origin, edited)
    if isinstance(origin, PastedIn):
        source = message(PASTED)
    elif isinstance(origin, FromProject):
        source = (message(QT_TR_NOOP("from project {name}"), name=origin.name) if origin.name
                  else message(QT_TR_NOOP("from an autosave that does not record their origin")))
    elif origin.readings is not None or origin.origin:
        # the sending workbench's line worded again from what it was made of (its text
        # alone, from a file that kept only that, is said as it is)
        said = stated(origin.readings) if origin.readings is not None else origin.origin
        source = message(QT_TR_NOOP("sent from the {workbench} workbench (its readings: "
                                    "{origin})"),
                         workbench=message(origin.workbench), origin=said)
    else:
        source = message(QT_TR_NOOP("sent from the {workbench} workbench"),
                         workbench=message(origin.workbench))
    return _edited(source) if edited else source


def _edited(source: str) -> str:
    """``source``, changed in the window since (other than by a paste)."""
    return message(QT_TR_NOOP("{source}, then edited in AngleBench"), source=source)


def sheet_source(origin: SheetOrigin | None, edited: bool, pasted: Sequence[int],
                 row_count: int, project: str = "") -> str | None:
    """The certificate's source of a sheet's readings: ``origin``, the step that replaced
    them all (None: typed, or a project's), ``edited`` whether they were changed since
    other than by a paste, ``pasted`` the filled rows (0-based, ascending) pasted into the
    sheet since, of ``row_count`` filled rows, said as the captured rows are
    (:func:`readings_origin`). None: typed (or the project's), nothing pasted.
    ``project``: the name of the project file the window has them in ("" none): rows
    :class:`FromProject` that file are its own (changed in it, as typed rows are: None
    when none was pasted)."""
    if isinstance(origin, FromProject) and project and origin.name == project:
        if not pasted:
            return None
        edited = False
    if origin is None:
        if not pasted:
            return None
        if len(pasted) >= row_count:
            return _replaced_source(PastedIn(), edited)
        said = message(QT_TR_NOOP("readings typed in AngleBench, except rows {rows} ({pasted} "
                                  "of {count}), pasted"),
                       rows=row_spans(pasted), pasted=len(pasted), count=row_count)
        return _edited(said) if edited else said
    source = _replaced_source(origin, edited)
    if not pasted or (isinstance(origin, PastedIn)):
        return source
    return message(QT_TR_NOOP("{source}; rows {rows} ({pasted} of {count}) pasted into "
                              "AngleBench"),
                   source=source, rows=row_spans(pasted), pasted=len(pasted), count=row_count)


def in_project(project: str, source: str | None, unsaved: bool = False) -> str:
    """The certificate's source of readings kept in the project file ``project``: its name,
    and where they came from when that is known (``source``, :func:`sheet_source`; None:
    typed, or the project's own). Day review 67: a project saved under a name said only
    its name of readings imported, pasted or sent from another workbench. ``unsaved``: the
    readings were changed in the window after that file was saved (or recovered from its
    autosave): the file is not named as their source (day review 67 F4: an auditor opening
    it would not find the certified readings)."""
    if unsaved:
        if source is None:
            return message(QT_TR_NOOP("readings typed or edited in AngleBench after {project} "
                                      "was saved (not the readings in that file)"),
                           project=project)
        return message(QT_TR_NOOP("{source}; changed in AngleBench after {project} was saved "
                                  "(not the readings in that file)"),
                       project=project, source=source)
    if source is None:
        return project
    return message(QT_TR_NOOP("{project}: {source}"), project=project, source=source)


def source_stated(statement: ReadingsStatement) -> str:
    """The source part of ``statement``'s "Readings:" line (:func:`readings_origin`'s
    ``source``): the project file and where its readings came from, or where they came
    from, or what a register's record named, or :data:`TYPED`."""
    source = sheet_source(statement.origin, statement.edited, list(statement.pasted),
                          statement.row_count, project=statement.project)
    if statement.project:
        return in_project(statement.project, source, statement.unsaved)
    return source or statement.named or TYPED


def stated(statement: ReadingsStatement) -> str:
    """``statement``'s "Readings:" line, a :class:`~models.messages.Message` that a
    certificate words in its own language(s)."""
    return readings_origin(source_stated(statement), statement.captured, statement.row_count)


def filled_rows(rows: Sequence[Sequence[str]]) -> list[int]:
    """The sheet's rows (0-based) that hold a reading: any cell not blank."""
    return [i for i, row in enumerate(rows) if any(str(cell).strip() for cell in row)]


def captured_rows(sessions: Iterable[dict[str, Any]], rows: Sequence[Sequence[str]],
                  workbench: str = "") -> list[int]:
    """The filled sheet rows (0-based, ascending) whose reading a take of ``sessions``
    (stored as in models/capture/raw_record.py) is in now: a take undone, superseded or
    whose row was deleted (a stored row below 0, models/capture/take_rows.py) is behind no
    row, and a session recorded on another workbench than ``workbench`` is not this
    sheet's."""
    filled = set(filled_rows(rows))
    taken: set[int] = set()
    for session in sessions:
        if workbench and session.get("workbench", workbench) != workbench:
            continue
        taken.update(int(take[0]) for take in session.get("takes", ()) if int(take[0]) in filled)
    return sorted(taken)


def row_spans(rows: Sequence[int]) -> str:
    """Rows (0-based, ascending) as a technician counts them, runs joined: "3–50, 52"."""
    spans: list[str] = []
    start = previous = None
    for row in [*rows, None]:
        if row is not None and previous is not None and row == previous + 1:
            previous = row
            continue
        if start is not None and previous is not None:
            spans.append(f"{start + 1}" if start == previous else f"{start + 1}–{previous + 1}")
        start = previous = row
    return ", ".join(spans)


def readings_origin(source: str, captured: Sequence[int], row_count: int,
                    left_out: Sequence[int] = ()) -> str:
    """The "Readings:" line: ``source`` (a project file's name, or :data:`TYPED`) and the
    rows taken from the instruments (``captured``, 0-based, of ``row_count`` rows) — all of
    them, or which. ``source`` alone when none was. ``left_out``: filled rows the analysis
    left out (0-based: a cell it cannot read, a reading it refused), named, and neither
    counted nor said captured (day review
    live76 F6: "all 17 rows captured" beside "Readings 16", row 17 having no target)."""
    if left_out:
        out = set(left_out)
        used = readings_origin(source, [r for r in captured if r not in out],
                               row_count - len(out))
        return message(QT_TR_NOOP("{readings}; row(s) {rows} left out of the analysis"),
                       readings=used, rows=row_spans(sorted(out)))
    if not captured:
        return message(source) if source == TYPED else source
    if len(captured) >= row_count:
        if source == TYPED:
            return message(QT_TR_NOOP("all {count} rows captured from the instruments"),
                           count=row_count)
        return message(QT_TR_NOOP("{source}; all {count} rows captured from the instruments"),
                       source=source, count=row_count)
    if source == TYPED:
        return message(QT_TR_NOOP("readings typed in AngleBench, except rows {rows} "
                                  "({captured} of {count}), captured from the instruments"),
                       rows=row_spans(captured), captured=len(captured), count=row_count)
    return message(QT_TR_NOOP("{source}; rows {rows} ({captured} of {count}) captured from "
                              "the instruments"),
                   source=source, rows=row_spans(captured), captured=len(captured),
                   count=row_count)

