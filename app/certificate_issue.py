"""Issuing a certificate through the register: the number allocated, the PDF rendered with
it and recorded with the project state behind it, in one transaction; the file written
after the commit (a failed write leaves the record, and its PDF, in the register).

Shared by the window's certificate presenter and ``anglebench analyze --certificate``.
"""

from __future__ import annotations

import dataclasses
import datetime as dt
import logging
import os
from collections.abc import Callable, Mapping, Sequence
from typing import Any

from app.capture.instruments import INSTRUMENTS, frame_values, reading_columns
from app.issued_outputs import (
    clear_stale_beside,
    keep_in_sight,
    place_new,
    refuse_issued_files,
    written_beside,
)
from app.writers.certificate_pdf import certificate_pdf_bytes
from models.capture.edits import EditedReading, edited_after_capture
from models.capture.raw_record import raw_digest
from models.capture.take_cells import elevation_from_zenith_deg
from models.certificate.capture_dated import dated_before_capture_past_due
from models.certificate.metadata import NUMBER_FIELDS, CertificateMetadata
from models.certificate.readings_origin import captured_rows, filled_rows, readings_origin
from models.project.file import READINGS_SOURCE, Project, WorkbenchState, project_to_json
from models.project.output_guard import check_output, register_files
from models.readings.angles import parse_angle_deg
from models.readings.sheet import Column, ReadingsSheet
from models.register.store import CertificateRecord, IssueRequest, Register

log = logging.getLogger(__name__)

__all__ = ["IssuedNotWritten", "draft_reasons", "issue_certificate",
           "readings_edited_after_capture", "refuse_issued_files", "specimen_document"]


class IssuedNotWritten(OSError):
    """The certificate was issued and recorded, but one of its files could not be written.
    ``what``: which ("pdf", "dcc" or "results"; the register gives the PDF and the DCC back,
    not a results file); ``recorded``: for "results", whether the register records it (then
    its bytes are kept at ``kept``, the temporary file beside ``path``)."""

    def __init__(self, record: CertificateRecord, path: str, cause: OSError,
                 what: str = "pdf", recorded: bool = False, kept: str = "") -> None:
        super().__init__(f"{path}: {cause.strerror or cause}")
        self.record = record
        self.path = path
        self.what = what
        self.recorded = recorded
        self.kept = kept
        #: the certificate's other files that were not written either, each its own
        #: IssuedNotWritten (reg72 #5: only the first was named)
        self.others: tuple[IssuedNotWritten, ...] = ()


def _write_results(register: Register, record: CertificateRecord, path: str,
                   data: bytes) -> None:
    """The results file written beside ``path`` (a temporary file, fsync'ed), then recorded,
    then renamed to ``path``: the register records a results file only once its bytes are
    on disk (rev62 F6: it recorded one a full disk, read-only media or kill -9 never let be
    written). A write that fails records nothing; a rename that fails after the record
    keeps the recorded bytes in the temporary file, and says where."""
    import contextlib
    import tempfile
    from pathlib import Path

    from models.project.atomic_write import _mode_for, _temp_prefix
    from models.project.output_guard import refuse_capture_journal, refuse_database
    from models.register.store import RegisterError

    target = Path(path)
    try:
        refuse_database(target)
        refuse_capture_journal(target)  # nor a killed capture's readings (hostile77 F2)
        if target.is_symlink():
            target = target.resolve()
        clear_stale_beside(register, target)  # a killed save's leftovers (reg72 #11)
        fd, temp = tempfile.mkstemp(prefix=_temp_prefix(target), suffix=".tmp",
                                    dir=target.parent)
    except OSError as exc:
        raise IssuedNotWritten(record, path, exc, "results") from exc
    try:
        with os.fdopen(fd, "wb") as handle:
            if hasattr(os, "fchmod"):
                os.fchmod(handle.fileno(), _mode_for(target))
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
    except OSError as exc:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise IssuedNotWritten(record, path, exc, "results") from exc
    try:
        register.record_results(record.number, data, os.path.basename(path))
    except (RegisterError, OSError) as exc:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise IssuedNotWritten(record, path, exc if isinstance(exc, OSError)
                               else OSError(str(exc)), "results") from exc
    try:
        _place(register, temp, target)
    except OSError as exc:
        raise IssuedNotWritten(record, path, exc, "results", recorded=True,
                               kept=keep_in_sight(temp, target, record.number)) from exc


def _place(register: Register, temp: str, target) -> None:
    """``temp`` renamed to ``target`` without replacing a file the register issued since
    the check before the issue (rev63 F7: two issuers naming the same results file both
    passed the check, and the later rename replaced the first's results file, of which the
    register keeps only the SHA-256): :func:`app.issued_outputs.place_new`."""
    place_new(register, temp, target)


def _write_new(register: Register, path: str, data: bytes) -> None:
    """The PDF or the DCC of a certificate just recorded written to ``path``: a temporary
    file beside it, fsync'ed, then placed without replacing a file the register issued
    (:func:`app.issued_outputs.place_new`; rev64 F7: the second of two issues naming the
    same PDF replaced the first's). Nothing left on failure; the register holds the file."""
    import contextlib

    clear_stale_beside(register, path)  # killed saves' leftovers (reg72 #11)
    target, temp = written_beside(path, data)
    try:  # placed for good: the durable renames fsync the folder
        place_new(register, temp, target)
    except BaseException:
        with contextlib.suppress(OSError):
            os.unlink(temp)
        raise


def draft_reasons(metadata: CertificateMetadata) -> list[str]:
    """What keeps the certificate a draft; the number is not among them (the register
    allocates it)."""
    return [m for m in metadata.missing_fields() if m not in NUMBER_FIELDS.values()]


def specimen_document(document):
    """The document as a SPECIMEN (``"example": true`` on the command line, the training
    switch in the window): watermarked, numbered SPECIMEN-… from its details and its
    results as printed (a number the register refuses, so it cannot clash with an issued
    one); never recorded. The same readings, settings and details give the same number;
    other results another (until 0.8.18 the details alone: the polygon sample, its one set
    and its run with a CMC were all SPECIMEN-4ECF9DB2). The language it is printed in is
    not part of it: the same results in English, Chinese or both are one specimen (until
    0.8.21 the details' ``language`` was hashed with them, so the theodolite sample in en
    and zh were SPECIMEN-9D13E820 and SPECIMEN-9C7ACC74: assessment 72 L8)."""
    import hashlib

    printed = [str(document.conformity.statement), *map(str, document.settings)]
    for table in (document.parameters, document.results, document.statistics):
        printed += ["\x1f".join(map(str, row)) for row in table.rows]
    details = {k: v for k, v in document.metadata.to_dict().items() if k != "language"}
    stamp = hashlib.sha256(repr((details, printed)).encode()).hexdigest()[:8].upper()
    number = f"SPECIMEN-{stamp}"
    return dataclasses.replace(
        document, specimen=True,
        metadata=dataclasses.replace(document.metadata, certificate_number=number))


def readings_edited_after_capture(kind, settings: Mapping[str, Any], rows, sessions,
                                  cache: dict | None = None) -> list[EditedReading]:
    """The captured readings of ``sessions`` whose cells in ``rows`` differ now from what
    the instrument's frames give (models/capture/edits.py)."""
    keys = [c.key for c in kind.columns]
    zenith = settings.get("vertical_reading") == "zenith"
    # a take writes a theodolite's 90° − V where the column reads elevation: compared so
    # (#41: the elevation was not compared at all, an edit of it went unmarked)
    elevation = not zenith and "elevation_deg" in keys

    def zenith_at(instrument: str) -> int | None:
        """Where an instrument's reading holds a zenith angle (a theodolite's V)."""
        held = list(INSTRUMENTS[instrument]().columns) if instrument in INSTRUMENTS else []
        return held.index("zenith_deg") if "zenith_deg" in held else None

    def columns(instrument: str):
        out = reading_columns(instrument, keys, zenith)
        if elevation:
            out = [("elevation_deg", keys.index("elevation_deg")) if key == "zenith_deg"
                   else (key, column) for key, column in out]
        return out

    def values(instrument: str, line: bytes):
        got = frame_values(instrument, line)
        at = zenith_at(instrument) if elevation else None
        if got is not None and at is not None and len(got) > at:
            got = (*got[:at], elevation_from_zenith_deg(got[at]), *got[at + 1:])
        return got

    if cache is not None and elevation:  # the frames' readings as elevations kept apart
        cache = cache.setdefault("elevation", {})
    # a take writes a position in degrees in its target's turn (app/capture/panel.py)
    turns = [keys.index(near) for near, unit in kind.reading_positions(settings).values()
             if unit == "deg" and near in keys]

    def turn_of_row(cells) -> float | None:
        for column in turns:
            text = cells[column] if column < len(cells) else ""
            try:
                return float(parse_angle_deg(text))
            except (ValueError, TypeError, OverflowError):
                continue
        return None

    def number_in(column: int, text: str) -> float | None:
        """The number the analysis reads in a cell of the column: D°M′S″ in an angle
        column (a readout's reading there was "edited or cleared after capture")."""
        if column >= len(kind.columns):
            return None
        try:
            value = kind.columns[column].parse(text)
        except (ValueError, TypeError, OverflowError):
            return None
        return float(value) if isinstance(value, int | float) else None

    # a session recorded on another workbench is said, not checked (review 61 F7)
    return edited_after_capture(sessions or [], rows, columns, values, cache, kind.key,
                                turn_of_row if turns else None, number_in, keys)


def sign_if_configured(xml: bytes, key_file: str = "", cert_file: str = "") -> bytes:
    """The DCC signed with the lab's key and certificate when configured (the files given —
    the lab defaults' —, else the environment's: models/dcc/signature.py), unchanged
    otherwise."""
    from models.dcc.signature import sign_if_configured as sign

    return sign(xml, key_file, cert_file)


def readings_stated(workbench: str, source_name: str, rows: Sequence[Sequence[str]],
                    raw_capture: Sequence[dict[str, Any]] | None,
                    columns: Sequence[Column] = (), result: Any = None) -> tuple[str, str]:
    """The certificate's "Readings:" (``source_name``, and the rows captured from the
    instruments: day review 64 P8) and the instrument output's SHA-256 ("" when no reading
    was taken from it). With the workbench's ``columns``, the rows that cannot be read are
    named as left out of the analysis, and not counted (day review live76 F6), and so are
    the rows ``result`` left out (a positioning reading at another position: F7)."""
    # the instrument output is the readings' origin only when a reading was taken from it:
    # a session with no take (the tab was in front while instruments were connected) is
    # kept with the record, not named on the certificate (rev62day F15: "Instrument output:
    # SHA-256 …" on a report none of whose readings was captured)
    sessions = list(raw_capture or ())
    taken = any(session.get("takes") for session in sessions)
    filled = filled_rows(rows)
    left_out: list[int] = []
    # said with the rows captured (a sheet of takes, parsed again in a moment): a file's
    # million typed rows are not parsed a second time for it
    if columns and filled and taken:
        used = set(ReadingsSheet(columns, rows).parse().row_index.tolist())
        left_out = [r for r in filled if r not in used]
    left_out = sorted({*left_out, *(int(r) for r in getattr(result, "left_out", ()))})
    origin = readings_origin(source_name, captured_rows(sessions, rows, workbench),
                             len(filled), left_out)
    return origin, raw_digest(sessions) if taken else ""


def issue_certificate(register: Register, kind, result: Any, metadata: CertificateMetadata,
                      settings: Mapping[str, Any], rows: list[list[str]], source_name: str,
                      path: str, *, supersedes: str = "", change_note: str = "",
                      replacement: bool = False, separate_calibration: str = "",
                      correction_confirmed: bool = False, raw_capture: list | None = None,
                      another_makers_item: bool = False, another_lookalike_item: bool = False,
                      readings_of_another_item: tuple[str, str] | None = None,
                      same_readings_as: tuple[str, str] | None = None,
                      dcc: Callable[[Any, bytes], bytes] | None = None, dcc_path: str = "",
                      signing: tuple[str, str] = ("", ""),
                      results: Callable[[Any, CertificateRecord], bytes] | None = None,
                      results_path: str = "",
                      confirmed_date: dt.date | None = None) -> CertificateRecord:
    """Issue and record the certificate, then write it to ``path``. Raises RegisterError,
    ValueError (the content, e.g. details that contradict the settings), OSError before
    the commit (nothing recorded), or IssuedNotWritten (recorded; the file not written: its
    PDF can be saved from the register); OutputRefused (an OSError) when ``path`` is the
    register or one of its files, before anything is issued. ``raw_capture``: the instrument's sessions behind
    the readings (models/capture/raw_record.py), recorded with them in the project state
    (so in the register's hash chain); their SHA-256 is printed on the certificate, and so is
    every captured reading edited in the sheet since ("reading of row 3 edited after capture:
    21.56 → 26.56"). ``dcc(document, pdf)``: the digital certificate of the PDF rendered
    (app/dcc_issue.render_dcc), made with it — so with its number — before anything is
    recorded (a DCC refused as invalid issues nothing) and written to ``dcc_path`` after
    the PDF. ``signing``: the lab's key and certificate files (empty: the environment's).
    ``separate_calibration``: why an original for the item and date of calibration of a
    current certificate is a calibration of its own (else SameCalibrationIssued).
    ``another_makers_item``: the user confirmed that the item is another maker's than that
    of a current certificate of the same serial and date (else AnotherMakersItem; recorded
    in the register's chain when issued).
    ``another_lookalike_item``: the user confirmed that the item is another than that of
    the certificates whose serial its serial looks like, letters or digits that print alike,
    case aside, or, for an item of no serial, than that day's item of its description and
    maker with one, or the other way round (else LookalikeSerial, SerialLeftOut; recorded in
    the register's chain when issued; rev65 F7, stop 67).
    ``readings_of_another_item``: (N, why) — the readings, by their values, are those of
    certificate N of another item in the register, and why (else ReadingsOfAnotherItem;
    printed on it and recorded in the register's chain; hostile78 F7).
    ``same_readings_as``: (N, why) — a calibration of its own whose readings, by their
    values, and details are those of certificate N, current, of its item and date, and why
    (else SameReadingsIssued; stated in its change note and recorded in the chain).
    ``supersedes``: an amendment (or, with ``replacement``, a replacement) of that
    certificate, of its calibration: its workbench, item (serial as printed) and date of calibration,
    else NotTheSameCalibration, before anything is issued; ``correction_confirmed``: a
    corrected serial number or date of calibration, confirmed, stated on it (rev62 F1).
    ``confirmed_date``: today's date as the user confirmed it, for an issue far after the
    register's last record (else DateToConfirm: models/register/clock_rules).
    ``results(document, record)``: the results file (CSV or XLSX) of the certificate issued,
    made after the commit from the document the recorded PDF was rendered from and the
    register's record (so with the number and date of issue the register gave, and the
    PDF's and DCC's SHA-256), its SHA-256 recorded in the register (a chained entry:
    ``register verify`` checks it), then written to ``results_path``."""
    # a date of calibration typed before the readings were captured, past a standard's due
    # date, is refused (hostile78 F5: an expired standard read as in date)
    backdated = dated_before_capture_past_due(metadata, raw_capture)
    if backdated is not None:
        raise ValueError(backdated)
    # where the readings came from, as the certificate names them: an amendment opened from
    # this record names the same (rev62 F4)
    project = Project({kind.key: WorkbenchState([list(r) for r in rows], dict(settings))},
                      {"certificates": {kind.key: metadata.to_dict()},
                       READINGS_SOURCE: source_name},
                      {kind.key: raw_capture} if raw_capture else {})
    # "Readings:" as the rows came (typed, or which captured) and the instrument output
    origin, digest = readings_stated(kind.key, source_name, rows, raw_capture, kind.columns,
                                     result)
    edited = tuple(e.text() for e in readings_edited_after_capture(
        kind, settings, rows, raw_capture)) if raw_capture else ()
    request = IssueRequest(kind.key, metadata, project_to_json(project),
                           kind.headline_figures(result))

    made: dict[str, Any] = {}

    def render(final: CertificateMetadata, head: str = "", content: str = "",
               proof: str = "") -> bytes:
        document = dataclasses.replace(
            kind.certificate_document(result, final, origin, settings),
            raw_data_sha256=digest, edited_readings=edited, register_head=head,
            register_content=content, register_proof=proof)
        pdf = certificate_pdf_bytes(document)
        made["document"] = document  # the last one rendered is the one recorded
        if dcc is not None:  # the register may render again: the last one is recorded
            # signed when the lab's key and certificate are configured (models/dcc/signature)
            made["dcc"] = sign_if_configured(dcc(document, pdf), *signing)
        return pdf

    def prepare(final: CertificateMetadata) -> tuple[str, bytes | None]:
        """The document's kind and its DCC with an empty PDF, before the PDF is rendered:
        what the record digest the PDF carries covers (content form 2), so that it is
        rendered once (the register renders again if the rendering gives others)."""
        document = dataclasses.replace(
            kind.certificate_document(result, final, origin, settings),
            raw_data_sha256=digest, edited_readings=edited)
        return ("test" if document.is_test_report else "calibration",
                None if dcc is None else dcc(document, b""))

    # before a number is used: an output onto the register (or a database), one that
    # cannot be written (read-only media, a name too long, a FIFO or a device) and one that
    # is a file the register issued (any certificate's PDF, DCC or results file) are refused
    outputs = [("", path), ("--dcc", dcc_path if dcc is not None else ""),
               ("--results", results_path if results is not None else "")]
    for flag, out in outputs:
        if out:
            check_output(out, register_files(register.url), flag)
    for said in refuse_issued_files(register, outputs):
        # the command line and the window checked and said this before (cli.py,
        # certificate_presenter.py): a leftover that turned ten minutes old since, logged
        log.warning("%s", said)
    # the register stores the DCC made with the PDF of the same attempt (same number, the
    # PDF inside it) and chains its SHA-256
    record, pdf = register.issue(request, render, supersedes=supersedes,
                                 change_note=change_note, replacement=replacement,
                                 separate_calibration=separate_calibration,
                                 correction_confirmed=correction_confirmed,
                                 another_makers_item=another_makers_item,
                                 another_lookalike_item=another_lookalike_item,
                                 readings_of_another_item=readings_of_another_item,
                                 same_readings_as=same_readings_as,
                                 confirmed_date=confirmed_date,
                                 # what the document recorded is: a test report or a
                                 # calibration certificate (in the chain, chain format 4)
                                 document_kind=lambda: "test" if made["document"].is_test_report
                                 else "calibration",
                                 render_dcc=(lambda _final, _pdf: made["dcc"])
                                 if dcc is not None else None, prepare=prepare)
    # every output is tried, and every one not written is named (reg72 #5)
    failures: list[IssuedNotWritten] = []
    try:
        _write_new(register, path, pdf)
    except OSError as exc:
        failures.append(_not_written(IssuedNotWritten(record, path, exc, "pdf"), exc))
    if dcc is not None and dcc_path:
        try:
            _write_new(register, dcc_path, made["dcc"])
        except OSError as exc:
            failures.append(_not_written(IssuedNotWritten(record, dcc_path, exc, "dcc"), exc))
    if results is not None and results_path:
        # written, then recorded, then renamed into place: never recorded and not written
        try:
            _write_results(register, record, results_path, results(made["document"], record))
        except IssuedNotWritten as exc:
            failures.append(exc)
    if failures:
        failures[0].others = tuple(failures[1:])
        raise failures[0]
    return record


def _not_written(failure: IssuedNotWritten, cause: OSError) -> IssuedNotWritten:
    """``failure`` caused by ``cause`` (as ``raise … from cause`` sets it)."""
    failure.__cause__ = cause
    return failure
