"""``anglebench analyze KIND FILE``: analyse a CSV without a window.

Prints a readable summary, or JSON with ``--json``. Bad input: exit status 2
and one line on stderr naming the file, the row and what is wrong. Everything it says,
its help included, is in the language of ``--language`` (default: the system's).
"""

from __future__ import annotations

import argparse
import contextlib
import dataclasses
import math
import sys
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import TYPE_CHECKING, Any

from app.command_line import EXIT_BAD_INPUT, Parser, add_language_option, language_asked, speaking
from app.command_line import say as _say
from models.display_units import ANGLE_UNITS, in_unit
from models.messages import (
    QT_TR_NOOP,
    Message,
    declared_text,
    joined,
    listed,
    message,
    reason_of,
    rendered,
    translator,
)
from models.parameters import SettingsError
from models.project.output_guard import (
    OutputRefused,
    Protected,
    check_outputs,
    input_files,
    refuse_other_kinds,
    register_files,
)
from models.readings.incomplete import row_in_progress, typing_row, without_waiting_rows
from models.readings.numeric_csv import read_numeric
from models.readings.sheet import ParsedReadings, ReadingsSheet
from models.readings.tabular_import import (
    MissingColumnError,
    TableImportError,
    map_columns,
    read_table,
)
from models.registry import KINDS
from models.workbench import (
    AcceptsReference,
    ComparesAfterLog,
    IssuesCertificates,
    JudgesSignals,
    WritesCorrectionTable,
)

if TYPE_CHECKING:
    from models.certificate.metadata import CertificateMetadata

# What only some runs need is imported where it is needed (a plain ``analyze`` of a
# sample starts in about 1.5 times numpy's import: tests/app/test_cli_imports.py,
# tests/benchmarks/test_cli_startup.py): the certificate's details (JSON's U and the
# certificate), the project file's migrations and the results writers (the certificate's
# document); and only the named workbench is loaded
# (models/registry.py) unless the command line names another's option or asks for help.


def _why(exc: BaseException, words) -> str:
    """What went wrong, in the language of ``words`` (a translator)."""
    return rendered(reason_of(exc), words)


def _parser(words, kinds: tuple[str, ...] | None = None,
            parser_class: type[argparse.ArgumentParser] = Parser) -> argparse.ArgumentParser:
    """The command line, its help in the language of ``words`` (a translator), with the
    options of the workbenches ``kinds`` (default: all)."""
    kinds = tuple(KINDS) if kinds is None else kinds
    p = parser_class(prog="anglebench analyze",
                     description=words(QT_TR_NOOP("Analyse a readings file")))
    p.add_argument("kind", choices=sorted(KINDS), help=words(QT_TR_NOOP("the workbench")))
    p.add_argument("file", help=words(QT_TR_NOOP("the readings (CSV, TSV, XLSX)")))
    p.add_argument("--json", action="store_true",
                   help=words(QT_TR_NOOP("print JSON instead of a summary")))
    p.add_argument("--certificate", metavar="OUT.pdf",
                   help=words(QT_TR_NOOP("also write a test certificate")))
    p.add_argument("--dcc", metavar="OUT.xml",
                   help=words(QT_TR_NOOP("with --certificate: also write the certificate as a "
                                         "digital calibration certificate (PTB DCC 3.3.0 XML) "
                                         "with the PDF embedded")))
    p.add_argument("--reference-dcc", metavar="POLY.xml", default="",
                   help=words(QT_TR_NOOP("polygon: the polygon's digital calibration "
                                         "certificate (DCC): its face deviations replace the "
                                         "readings' deviation column and its U enters the "
                                         "budget")))
    p.add_argument("--dcc-schema", metavar="DIR", default="",
                   help=words(QT_TR_NOOP("the folder of PTB's DCC 3.3.0 schema set (dcc.xsd, "
                                         "si/, d-sig/): the DCC is validated against it and not "
                                         "written when invalid (else ANGLEBENCH_DCC_SCHEMA)")))
    p.add_argument("--metadata", metavar="META.json",
                   help=words(QT_TR_NOOP("certificate metadata (lab, customer, item, "
                                         "standards…); without it the certificate is marked "
                                         "DRAFT")))
    p.add_argument("--capture-record", metavar="RAW.csv", default="", help=words(QT_TR_NOOP(
        "the instrument's output that 'anglebench capture --raw' wrote for these readings: "
        "the certificate says which rows were captured and names its SHA-256; a captured "
        "row that differs from it is refused")))
    p.add_argument("--edited-after-capture", action="store_true", help=words(QT_TR_NOOP(
        "with --capture-record: captured readings were edited on purpose; the certificate "
        "lists every edit")))
    p.add_argument("--separate-calibration", metavar="REASON", default="",
                   help=words(QT_TR_NOOP("with --certificate: the item and date of calibration "
                                         "are those of a certificate still valid, and this is a "
                                         "calibration of its own (e.g. as left after an "
                                         "adjustment): why, printed on it with the other's "
                                         "number (else it is refused: a correction is an "
                                         "amendment or a replacement)")))
    p.add_argument("--another-makers-item", action="store_true", help=words(QT_TR_NOOP(
        "with --certificate: a certificate still valid reports the same serial number and "
        "date of calibration under another manufacturer's name, and this is indeed another "
        "maker's item (else it is refused: a maker's name spelt otherwise is the same "
        "maker); recorded in the register that you said so")))
    p.add_argument("--another-lookalike-item", action="store_true", help=words(QT_TR_NOOP(
        "with --certificate: the serial number is in no certificate of the register but "
        "looks like one that is (letters or digits that print alike, case aside: 1ra-0815 "
        "or LRA-o815 for LRA-0815), or the item has no serial number where a certificate "
        "still valid of that date of calibration reports an item of its description and "
        "maker with one (or the other way round), and this is indeed another item (else it "
        "is refused, naming that certificate); recorded in the register that you said so")))
    p.add_argument("--readings-of-another-item", metavar="N:REASON", default="",
                   help=words(QT_TR_NOOP(
                       "with --certificate: the readings (their values, however typed or "
                       "ordered) are those of certificate N of another item in the register, "
                       "and why (else it is refused, naming that certificate, its item and date "
                       "of calibration: no two calibrations repeat every reading to the last "
                       "digit); printed on the certificate and recorded in the register")))
    p.add_argument("--same-readings-as", metavar="N:REASON", default="",
                   help=words(QT_TR_NOOP(
                       "with --certificate and --separate-calibration: the readings (their "
                       "values, however typed or ordered) and the details are those of "
                       "certificate N, still valid, of this item and date of calibration, and "
                       "this is nevertheless a calibration of its own: why (else it is "
                       "refused: no two calibrations repeat every reading to the last digit, "
                       "so it is N's calibration issued again); stated on the certificate and "
                       "recorded in the register")))
    p.add_argument("--confirm-date", metavar="YYYY-MM-DD", default="", help=words(QT_TR_NOOP(
        "with --certificate: today's date, as you know it, for an issue more than 30 days "
        "after the register's last record (else it is refused, naming the date the computer's "
        "clock gives: a clock set ahead would date the certificate wrongly); recorded in the "
        "register that you confirmed it")))
    p.add_argument("--results", metavar="OUT.csv|OUT.xlsx",
                   help=words(QT_TR_NOOP("also write the results per point (with U) as CSV or "
                                         "XLSX")))
    p.add_argument("--columns", metavar="KEY=HEADER,…",
                   help=words(QT_TR_NOOP("which of the file's headers holds which column, when "
                                         "the headers are not recognised, e.g. "
                                         "theta_deg=转角,azimuth_deg=方位角")))
    p.add_argument("--confirm-implausible", action="store_true",
                   help=words(QT_TR_NOOP("issue the certificate although the result shows "
                                         "figures no instrument of the kind has (polygon: "
                                         "errors of degrees); you have checked the readings")))
    p.add_argument("--table", metavar="OUT",
                   help=words(QT_TR_NOOP("also write the workbench's correction table: fringe "
                                         "(CSV, or a C header for OUT.h), positioning "
                                         "(compensation table; --compensation-format, "
                                         "--compensation-step, --compensation-tables)")))
    p.add_argument("--unit", choices=sorted(ANGLE_UNITS), default="arcsec",
                   help=words(QT_TR_NOOP("angle unit of the printed summary and of --results "
                                         "(arcsec, urad or mdeg); JSON and certificates keep "
                                         "the unit of the evaluation")))
    p.add_argument("--compare-after", metavar="AFTER.csv",
                   help=words(QT_TR_NOOP("positioning: the log measured after compensation "
                                         "(analysed with the same settings); prints A, B, E, M, "
                                         "R before → after (JSON: before_after)")))
    for judge in _signal_judges(kinds)[:1]:  # one set of options, whichever holds them
        judge.add_signal_arguments(p, words)
    add_language_option(p, words)
    for _, shortcut in _shortcuts(kinds):
        p.add_argument(shortcut.flag, dest=_dest(shortcut.flag), action="store_true",
                       help=words(shortcut.help))
    for flag, owners in _flags(kinds).items():
        parts = []
        for kind, parameter in owners:
            # "| " so that a long list wraps (a word of 80 columns cannot)
            choices = (f" ({'| '.join(str(v) for v, _ in parameter.choices)})"
                       if parameter.choices else "")
            label = declared_text(parameter.label, words)
            explanation = declared_text(parameter.help, words)
            parts.append(rendered(message(QT_TR_NOOP("{kind}: {label}{choices}. {help}"),
                                          kind=kind, label=label, choices=choices,
                                          help=explanation), words))
        p.add_argument(flag, dest=_dest(flag), metavar=owners[0][1].kind.upper(),
                       help=" — ".join(parts).replace("%", "%%"))
    return p


def _signal_judges(kinds: tuple[str, ...] | None = None) -> list[JudgesSignals]:
    """The workbenches of ``kinds`` (all: None) that judge signals."""
    found = (KINDS[k] for k in kinds) if kinds is not None else KINDS.values()
    return [k for k in found if isinstance(k, JudgesSignals)]


def _signal_setup(kind, args: argparse.Namespace):
    """What the signal options ask of ``kind`` (None when it judges no signals); a
    ValueError when they are given to a workbench that does not."""
    if isinstance(kind, JudgesSignals):
        return kind.signal_setup(args)
    if not hasattr(args, "signal_scale"):  # read with the named workbench's options only
        return None
    for judge in _signal_judges()[:1]:
        used = [f for f in judge.signal_flags if getattr(args, f, None) is not None]
        if used or getattr(args, "signal_scale", 1.0) != 1.0:
            flag = "--" + (used[0] if used else "signal_scale").replace("_", "-")
            raise ValueError(message(QT_TR_NOOP("{flag} applies to {kinds}, not {kind}"),
                                     flag=flag, kinds=" and ".join(
                                         k for k, v in KINDS.items()
                                         if isinstance(v, JudgesSignals)), kind=args.kind))
    return None


def _dest(flag: str) -> str:
    return "setting_" + flag[2:].replace("-", "_")


def _flags(kinds: tuple[str, ...]) -> dict[str, list[tuple[str, Any]]]:
    """Each command-line flag of the workbenches ``kinds``, with the workbenches that
    declare it and their parameter."""
    flags: dict[str, list[tuple[str, Any]]] = {}
    for key in kinds:
        for parameter in KINDS[key].parameters:
            if parameter.cli:
                flags.setdefault(parameter.flag, []).append((key, parameter))
    return flags


def _shortcuts(kinds: tuple[str, ...]) -> list[tuple[str, Any]]:
    """The switches of the workbenches ``kinds`` that set one of its settings (``--zenith``),
    with its key."""
    return [(key, s) for key in kinds for s in KINDS[key].shortcuts]


class _Undecided(Exception):
    """The command line needs the whole parser (another workbench's option, an
    abbreviation, help, an error to report)."""


class _TrialParser(Parser):
    """Reads a command line with one workbench's options only; anything it does not know
    exactly is left to the whole parser, which reads it as it always has. It prints
    nothing: its formatter asks for no terminal width (argparse's asks shutil, for every
    option, and shutil's import brings the compression modules)."""

    def __init__(self, *args, **kwargs) -> None:
        kwargs.update(allow_abbrev=False, add_help=False, formatter_class=_silent_formatter)
        super().__init__(*args, **kwargs)

    def error(self, message: str):
        raise _Undecided(message)


def _silent_formatter(prog: str) -> argparse.HelpFormatter:
    """The trial parser's formatter: argparse makes one for every option it adds (to check
    its metavar); nothing it formats is shown."""
    return argparse.HelpFormatter(prog, width=80)


@contextlib.contextmanager
def _unsaid() -> Iterator[None]:
    """argparse's own words untranslated while the trial parser is built and parses: it
    shows none of them, and in English each is looked up through gettext (which imports
    locale and looks for catalogues on disk)."""
    saved = argparse._
    argparse._ = _as_written
    try:
        yield
    finally:
        argparse._ = saved


def _as_written(text: str) -> str:
    return text


def _parse(argv: list[str], words) -> tuple[argparse.Namespace, tuple[str, ...]]:
    """The arguments, and the workbenches whose options were read: the one named first in
    ``argv`` when the command line holds only its options (then no other workbench is
    imported), else all (their options are refused or explained by name)."""
    named = next((a for a in argv if a in KINDS), None)
    if named is not None and not {"-h", "--help"} & set(argv):
        try:
            with _unsaid():
                args, rest = _parser(words, (named,), _TrialParser).parse_known_args(argv)
        except _Undecided:
            pass
        else:
            if not rest and args.kind == named:
                return args, (named,)
    kinds = tuple(KINDS)
    return _parser(words, kinds).parse_args(argv), kinds


def _settings_from(args: argparse.Namespace, kinds: tuple[str, ...]) -> dict[str, Any]:
    """The settings the options give (those of the workbenches ``kinds`` were read), each
    checked against the chosen workbench's own declaration; an option of another workbench
    is refused."""
    settings: dict[str, Any] = {}
    for flag, owners in _flags(kinds).items():
        text = getattr(args, _dest(flag))
        if text is None:
            continue
        parameter = next((p for k, p in owners if k == args.kind), None)
        if parameter is None:
            raise SettingsError(message(QT_TR_NOOP("{flag} applies to {kinds}, not {kind}"),
                                        flag=flag, kinds=" and ".join(k for k, _ in owners),
                                        kind=args.kind))
        settings[parameter.key] = parameter.from_text(text)
    for key, shortcut in _shortcuts(kinds):
        if not getattr(args, _dest(shortcut.flag)):
            continue
        if key != args.kind:
            raise SettingsError(message(QT_TR_NOOP("{flag} applies to {kinds}, not {kind}"),
                                        flag=shortcut.flag, kinds=key, kind=args.kind))
        settings[shortcut.key] = shortcut.value
    return settings


def _column_mapping(text: str | None) -> dict[str, str] | None:
    if not text:
        return None
    mapping = {}
    for part in text.split(","):
        key, sep, header = part.partition("=")
        if not sep or not key.strip():
            raise TableImportError(message(QT_TR_NOOP(
                "anglebench analyze: --columns: '{part}' is not KEY=HEADER"), part=part))
        mapping[key.strip()] = header.strip()
    return mapping


def _protected(inputs: list[str]) -> list[Protected]:
    """What no output may replace: the inputs and the certificate register (the one this
    run would issue into), with its journal files."""
    from models.register.location import register_url

    return input_files(inputs) + register_files(register_url())


def _finite(value: Any) -> Any:
    """JSON has no NaN: write null instead."""
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_finite(v) for v in value]
    return value


def run_analyze(argv: list[str]) -> int:
    language = language_asked(argv)
    with speaking(language) as words:
        args, kinds = _parse(argv, words)
    args.language = language  # "system" resolved
    kind = KINDS[args.kind]

    try:
        settings = _settings_from(args, kinds)
    except SettingsError as exc:
        _say(f"anglebench analyze: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    inputs = [args.file] + ([args.metadata] if args.metadata else []) + (
        [args.capture_record] if args.capture_record else []) + (
        [args.compare_after] if args.compare_after else []) + (
        [args.reference_dcc] if args.reference_dcc else [])
    if args.reference_dcc:
        from models.dcc.reader import POLYGON_FACE_DEVIATIONS  # lxml's module: only for a DCC
    if args.reference_dcc and not (isinstance(kind, AcceptsReference)
                                   and kind.accepted_reference == POLYGON_FACE_DEVIATIONS):
        _say(words(QT_TR_NOOP("anglebench analyze: --reference-dcc is for the polygon "
                              "workbench")))
        return EXIT_BAD_INPUT
    if args.compare_after and not isinstance(kind, ComparesAfterLog):
        _say(words(QT_TR_NOOP("anglebench analyze: --compare-after is for the positioning "
                              "workbench")))
        return EXIT_BAD_INPUT
    if args.table and not isinstance(kind, WritesCorrectionTable):
        _say(rendered(message(QT_TR_NOOP("anglebench analyze: --table: {workbench} has no "
                                         "correction table"), workbench=message(kind.title)),
                      words))
        return EXIT_BAD_INPUT
    try:
        signal_setup = _signal_setup(kind, args)
    except ValueError as exc:
        _say(f"anglebench analyze: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    if getattr(args, "signal_presets", None):
        inputs.append(args.signal_presets)
    if (args.capture_record or args.edited_after_capture) and not args.certificate:
        _say(words(QT_TR_NOOP("anglebench analyze: --capture-record and "
                              "--edited-after-capture are for a certificate (--certificate)")))
        return EXIT_BAD_INPUT
    if args.edited_after_capture and not args.capture_record:
        _say(words(QT_TR_NOOP("anglebench analyze: --edited-after-capture needs "
                              "--capture-record (the capture the readings were edited after)")))
        return EXIT_BAD_INPUT
    if args.dcc and not args.certificate:
        _say(words(QT_TR_NOOP("anglebench analyze: --dcc needs --certificate (the DCC embeds the "
                              "PDF certificate)")))
        return EXIT_BAD_INPUT
    outputs = (("--certificate", args.certificate), ("--results", args.results),
               ("--table", args.table), ("--dcc", args.dcc),
               ("--interpolator-table", getattr(args, "interpolator_table", None)))
    try:
        check_outputs(outputs, _protected(inputs))
        # an issued file (any certificate's PDF, DCC or results file) is never replaced, by
        # an issue (checked again there) or a draft, a specimen, results or a table (rev62 F8);
        # its module (hashlib, logging, tempfile, shutil: a tenth of numpy's import) only for
        # a run that writes something: a plain analyze has nothing to check
        if any(out for _flag, out in outputs):
            from app.issued_outputs import refuse_issued_outputs
            from models.register.location import register_url

            for said in refuse_issued_outputs(register_url(), outputs):  # a results file kept
                _say(f"anglebench analyze: {rendered(said, words)}")
        # nor a file of another kind (a lab's details JSON named as --certificate)
        refuse_other_kinds(outputs)
    except OutputRefused as exc:
        _say(f"anglebench analyze: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    try:
        mapping = _column_mapping(args.columns)
    except TableImportError as exc:
        _say(_why(exc, words))
        return EXIT_BAD_INPUT
    # a file of plain numbers is read by numpy in one pass; anything else (or a file that
    # is not what it claims) by the tolerant reader, which names the row and the cell
    # (the rows as text when a reference DCC replaces a column of them)
    parsed = None if args.reference_dcc else read_numeric(args.file, kind.columns, mapping)
    table = None
    args.reference = None
    if parsed is None:
        try:
            table, rows = _read_rows(args.file, kind, mapping)
        except TableImportError as exc:
            _say(_why(exc, words))
            return EXIT_BAD_INPUT
        if args.reference_dcc:
            rows = _with_reference_dcc(args, kind, rows, settings, words)
            if rows is None:
                return EXIT_BAD_INPUT
        sheet = ReadingsSheet(kind.columns, rows)
        parsed = sheet.parse()
    keys = [c.key for c in kind.columns]
    reading = [keys.index(k) for k in kind.plan_reading_keys if k in keys]

    def blank_reading(row: int) -> bool:  # as the window tells it, by the cells' text
        return all(not sheet.text(row, c).strip() for c in reading)

    # rows at the end that wait for their reading (a plan's or the nominal step's cells
    # filled, no reading yet) are points not yet taken, not bad rows; a row with part of
    # its reading typed is none of them (row81: it was left out without a word)
    parsed, _ = without_waiting_rows(parsed, kind.plan_reading_keys,
                                     blank_reading if table is not None and reading else None)
    # The last row with a reading, some of its reading cells typed and the others blank
    # (a file saved while a reading was being typed: the autocollimator's x, not yet the
    # encoder) is the run in progress, as in the window (row81), not a bad row. Decided as
    # for a point short of its n readings (tests/app/test_cli_short_last_point.py): a file
    # may be any moment of a run, so the complete rows are analysed, the summary and the
    # JSON's "incomplete" say what is in progress, the exit is 0, and a certificate waits
    # for it (exit 2 with --certificate). Refusing the file would make the command line
    # judge a sheet the window shows as fine; taking the row as complete is impossible
    # (a reading has no value). A blank reading cell in any other row, or a cell typed
    # wrong anywhere, is still refused, naming the cell.
    typing = None
    if table is not None:
        parsed, typing = row_in_progress(
            parsed, typing_row(sheet.row_count, reading,
                               [kind.columns[c].required for c in reading], sheet.text),
            kind.plan_reading_keys, kind.columns, text=sheet.text)
    # every row the command line names (or takes: --reference-row) is the file's line, the
    # header line 1, as a bad cell's is (contract review 75 F7: the checks after parsing
    # named the window's sheet row, one less); the sheet row a reading is in is kept for
    # the JSON's incomplete.first_row/last_row, whose meaning is kept
    first_line = table.line_numbers[0] if table is not None and table.line_numbers \
        else parsed.first_line
    if parsed.errors:
        first = parsed.errors[0]
        line = table.line_numbers[first.row]
        more = (message(QT_TR_NOOP(" (and {n} more bad cell(s))"), n=len(parsed.errors) - 1)
                if len(parsed.errors) > 1 else "")
        _say(rendered(joined((message(QT_TR_NOOP("{file}: row {row}, column '{column}': {reason}"),
                                      file=args.file, row=line, column=first.column_key,
                                      reason=first.reason), more)), words))
        return EXIT_BAD_INPUT
    parsed = by_file_line(parsed, first_line)
    if typing is not None:  # its row counted as the file's line, as the readings' are
        typing = dataclasses.replace(typing, row=typing.row + first_line - 1)
    try:
        result = kind.analyze_as_far_as_it_goes(parsed, kind.settings_with_defaults(settings),
                                                typing)
    except SettingsError as exc:
        _say(f"anglebench analyze: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    except ValueError as exc:
        _say(f"{args.file}: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    comparison = None
    if args.compare_after:
        try:
            comparison = kind.compare_after(result, kind.after_log(args.compare_after, settings))
        except (ValueError, OSError) as exc:
            _say(f"anglebench analyze: --compare-after: {_why(exc, words)}")
            return EXIT_BAD_INPUT
    try:
        signal_keys, signal_texts, interpolator = (
            kind.signal_results(args, result, signal_setup) if isinstance(kind, JudgesSignals)
            else ({}, [], None))
    except ValueError as exc:
        _say(f"{args.file}: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    incomplete = getattr(result, "incomplete", None)
    if args.json:
        data = kind.to_json(result)
        data.update(signal_keys)
        if isinstance(kind, IssuesCertificates):
            # U beside every error array and the decided quantity, with the certificate
            # details given (their standards, tolerance and decision rule), else none
            from models.certificate.metadata import MetadataError
            from models.certificate.uncertainty_json import (
                certified_json,
                merge_json,
                workbench_uncertainty_json,
            )

            try:
                metadata = _read_metadata(args.metadata,
                                          kind.error_unit(kind.settings_with_defaults(settings)),
                                          getattr(args, "reference", None))
            except MetadataError as exc:
                _say(f"anglebench analyze: {_why(exc, words)}")
                return EXIT_BAD_INPUT
            merge_json(data, workbench_uncertainty_json(kind, result, metadata, settings))
            data.update(certified_json(kind, result, metadata, settings))  # the certificate's
        data["incomplete"] = None if incomplete is None else _incomplete_json(incomplete,
                                                                              first_line)
        if comparison is not None:
            data["before_after"] = {"after_file": args.compare_after, **comparison.as_dict()}
        import json  # only for --json and a certificate's details

        sys.stdout.write(json.dumps(_finite(data), indent=1, ensure_ascii=False) + "\n")
    else:
        say = words
        summary = rendered(in_unit(kind.summary(result), ANGLE_UNITS[args.unit]), say)
        sys.stdout.write(f"{say(kind.title)}: {args.file}\n{summary}\n")
        if incomplete is not None:
            sys.stdout.write(rendered(incomplete.progress(), say) + "\n")
        if comparison is not None:
            sys.stdout.write(rendered(in_unit(comparison.text(Path(args.compare_after).name),
                                              ANGLE_UNITS[args.unit]), say) + "\n")
        for text in signal_texts:
            sys.stdout.write(rendered(text, say) + "\n")
        for warning in getattr(result, "warnings", []):
            warning = rendered(in_unit(warning, ANGLE_UNITS[args.unit]), say)
            sys.stdout.write(say(QT_TR_NOOP("Warning: {warning}")).format(warning=warning)
                             + "\n")
    if args.table:
        from models.certificate.metadata import MetadataError

        try:
            # a table that states U states the certificate's, with the same details
            table_details = (_read_metadata(args.metadata,
                                            kind.error_unit(kind.settings_with_defaults(settings)),
                                            getattr(args, "reference", None))
                             if args.metadata else None)
            what = kind.correction_table(result, kind.settings_with_defaults(settings), args.table,
                                         table_details)
        except MetadataError as exc:
            _say(f"anglebench analyze: {_why(exc, words)}")
            return EXIT_BAD_INPUT
        except ValueError as exc:
            _say(f"anglebench analyze: --table: {_why(exc, words)}")
            return EXIT_BAD_INPUT
        except OSError as exc:  # a full disk: the file and the reason in words, exit 2
            _say(rendered(_output_not_written(args.table, exc, "--table"), words))
            return EXIT_BAD_INPUT
        # the first line says what was written; the next ones what to know of it
        said, _, notes = rendered(what, words).partition("\n")
        _say(rendered(message(QT_TR_NOOP("{what} written to {path}"), what=said,
                              path=args.table), words))
        for note in filter(None, notes.split("\n")):
            _say(note)
    if interpolator is not None:
        try:
            said = kind.write_signal_table(args, result, interpolator)
        except OSError as exc:
            _say(rendered(_output_not_written(args.interpolator_table, exc, "--interpolator-table"),
                          words))
            return EXIT_BAD_INPUT
        _say(rendered(said, words))
    # a test report asked for is called one when refused (ISO/IEC 17025 7.8.2.1 a))
    if incomplete is not None and args.certificate:
        _say(rendered(message(QT_TR_NOOP(
            "{file}: no test report was written: {progress} is not complete; a test report "
            "waits for it (the complete ones are analysed above)")
            if _test_report_asked(args) else QT_TR_NOOP(
            "{file}: no certificate was written: {progress} is not complete; a certificate "
            "waits for it (the complete ones are analysed above)"),
            file=args.file, progress=incomplete.text()), words))
        return EXIT_BAD_INPUT
    doubt = (kind.certificate_doubt(result)
             if isinstance(kind, IssuesCertificates) and args.certificate else "")
    if doubt and not args.confirm_implausible:
        _say(rendered(message(QT_TR_NOOP(
            "{file}: no test report was written: {reason} If the readings are right, run "
            "again with --confirm-implausible")
            if _test_report_asked(args) else QT_TR_NOOP(
            "{file}: no certificate was written: {reason} If the readings are right, run again "
            "with --confirm-implausible"), file=args.file, reason=doubt), words))
        return EXIT_BAD_INPUT
    if args.certificate or args.results:
        # the register keeps the readings as written: read as text when one is issued
        return _export(args, kind, result, settings,
                       (lambda: rows) if table is not None else
                       (lambda: _read_rows(args.file, kind, mapping)[1]))
    return 0


def by_file_line(parsed: ParsedReadings, first_line: int) -> ParsedReadings:
    """``parsed`` with each reading's row counted as the file's line (``first_line``: the
    line of the sheet's first row), so that every workbench's ``row_index + 1`` is the line
    its messages name: one mapping for every check after parsing."""
    if first_line == 1:
        return parsed
    return dataclasses.replace(parsed, row_index=parsed.row_index + (first_line - 1),
                               first_line=1)


def _incomplete_json(incomplete, first_line: int) -> dict[str, Any]:
    """The JSON's ``incomplete``: ``first_row``/``last_row`` the readings' rows as the
    window's sheet numbers them (the first under the header is row 1, their meaning kept),
    ``first_line``/``last_line`` the file's lines (as the summary names them)."""
    data = incomplete.as_dict()
    lines = {"first_line": data["first_row"], "last_line": data["last_row"]}
    data["first_row"] = int(data["first_row"]) - (first_line - 1)
    data["last_row"] = int(data["last_row"]) - (first_line - 1)
    data.update(lines)
    if "typing" in data:  # the row being typed: its sheet row and its file line
        typing = dict(data["typing"])
        typing["line"] = typing["row"]
        typing["row"] = int(typing["row"]) - (first_line - 1)
        data["typing"] = typing
    return data


def _with_reference_dcc(args: argparse.Namespace, kind, rows, settings, words):
    """The rows with the polygon's DCC deviations (app/reference_dcc.py), said what it
    replaced; None after saying why the DCC was refused."""
    from app.dcc_issue import dcc_schema_dir
    from app.reference_dcc import placed_reference, reference_rows
    from models.certificate.metadata import MetadataError
    from models.dcc.reader import DccError
    from models.dcc.signature import SigningError

    try:
        metadata = _read_metadata(args.metadata,
                                  kind.error_unit(kind.settings_with_defaults(settings)))
        rows, args.reference, said = reference_rows(
            args.reference_dcc, kind, rows, kind.settings_with_defaults(settings),
            metadata.calibration_date, dcc_schema_dir(args.dcc_schema))
        # the polygon the details list must be the DCC's, its U one they take: checked
        # before anything is analysed
        said = [*said, *placed_reference(metadata, args.reference)[1]]
    except (DccError, SigningError, MetadataError) as exc:
        _say(f"anglebench analyze: --reference-dcc: {_why(exc, words)}")
        return None
    for text in said:
        _say(rendered(message(QT_TR_NOOP("anglebench analyze: --reference-dcc: {text}"),
                              text=text), words))
    return rows


def _readings_source(path: str) -> str:
    """The certificate's "Readings:" of the file ``path`` as the window says it (day review
    66 F7: the command line named its basename only): "imported from NAME (SHA-256 …)", or
    "the bundled sample NAME" when it is one of resources/samples."""
    import resources
    from models.certificate.readings_origin import ImportedFrom, imported_source
    from models.project.file import file_sha256

    try:
        digest = file_sha256(path)
    except OSError:  # read once already; gone since: named without a digest
        digest = ""
    samples = Path(resources.__file__).resolve().parent / "samples"
    sample = Path(path).resolve().parent == samples
    return imported_source(ImportedFrom(Path(path).name, digest, sample), edited=False)


def _read_rows(path: str, kind, mapping) -> tuple[Any, list[list[str]]]:
    table = read_table(path)
    try:
        return table, map_columns(table, kind.columns, mapping)
    except MissingColumnError:
        own = None if mapping else kind.rows_from_table(table)  # the workbench's own layout
        if own is None:
            raise
        # its rows are the readings unrolled: a bad cell is named by the readings' row
        return dataclasses.replace(table, line_numbers=list(range(1, len(own) + 1))), own


def _test_report_asked(args: argparse.Namespace) -> bool:
    """Whether the details (--metadata) ask for a test report (``document_type`` "test");
    False when they do not read (they are refused, saying why, when they are used)."""
    from models.certificate.metadata import MetadataError

    try:
        return _read_metadata(args.metadata).document_type == "test"
    except MetadataError:
        return False


def _read_metadata(path: str | None, error_unit: str = "arcsec", reference=None
                   ) -> CertificateMetadata:
    """The details in ``path``; a ``tolerance_arcsec`` written before the tolerance had its
    unit is read in ``error_unit``, the unit of the errors it was judged against."""
    import json

    from models.certificate.metadata import CertificateMetadata, MetadataError
    from models.uncertainty.rounding import StatedNumber

    if reference is not None:
        from app.reference_dcc import with_reference

        return with_reference(_read_metadata(path, error_unit), reference)
    if not path:
        return CertificateMetadata()
    try:
        with open(path, encoding="utf-8-sig") as handle:
            # numbers with the decimals they were typed with: a tolerance of 1.50 is stated
            # to 0.01, the place ASTM E29 rounds a value compared with it to
            data = json.load(handle, parse_float=StatedNumber.from_text)
    except OSError as exc:
        raise MetadataError(message(QT_TR_NOOP("{path}: cannot read ({value})"), path=path,
                                    value=exc.strerror)) from None
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise MetadataError(message(QT_TR_NOOP("{path}: not a JSON file ({reason})"), path=path,
                                    reason=str(exc))) from None
    except (RecursionError, ValueError):  # nesting thousands deep; a number too long to read
        raise MetadataError(message(QT_TR_NOOP("{path}: not a certificate's details (nested too "
                                               "deep or a number too long)"), path=path)) from None
    from models.project.file import migrate_certificate_details

    try:
        if isinstance(data, dict):
            data = migrate_certificate_details(data, error_unit)
        return CertificateMetadata.from_dict(data)
    except MetadataError as exc:
        raise MetadataError(message("{path}: {reason}", path=path, reason=reason_of(exc))) from None


def _issue(args: argparse.Namespace, kind, result, metadata, settings, rows, report=False,
           raw_capture: list | None = None):
    """Issue through the register (the number allocated there unless the details give one);
    None after saying why it was refused. ``raw_capture``: the capture sessions behind the
    rows (--capture-record), recorded with them and named on the certificate."""
    from models.register.location import register_url

    words = translator(args.language)
    return _issue_into(register_url(), args, kind, result, metadata, settings, rows, words,
                       report, raw_capture)


def _capture_record(args: argparse.Namespace, kind, settings, rows: list[list[str]]
                    ) -> list[dict[str, Any]]:
    """The capture session of --capture-record behind ``rows`` (app/capture_record.py),
    checked against them as the window checks its sheet: a captured reading the file does
    not hold as the instrument sent it is refused (CaptureRecordError naming the file and
    the row), unless --edited-after-capture declares the edits (the certificate lists
    them)."""
    from app.capture_record import CaptureRecordError, capture_session
    from app.certificate_issue import readings_edited_after_capture

    path = args.capture_record
    try:
        with open(path, "rb") as handle:
            data = handle.read()
    except OSError as exc:
        raise CaptureRecordError(message(QT_TR_NOOP("{path}: cannot read ({value})"),
                                         path=path, value=exc.strerror)) from None
    table = read_table(args.file)
    header = [str(cell).strip().lower() for cell in (table.header or [])]
    same = len(table.rows) == len(rows)  # the file's rows are the sheet's (no own layout)
    times = ([row[header.index("time_s")] if header.index("time_s") < len(row) else ""
              for row in table.rows] if same and "time_s" in header else None)
    keys = [c.key for c in kind.columns]
    session = capture_session(path, data, Path(args.file).name, kind.key, keys, rows, times)
    if args.edited_after_capture:
        return [session]
    for edit in readings_edited_after_capture(kind, kind.settings_with_defaults(settings), rows,
                                              [session]):
        line = table.line_numbers[edit.row] if same and 0 <= edit.row < len(rows) \
            else edit.row + 1
        if edit.what in ("edited", "cleared"):
            raise CaptureRecordError(message(QT_TR_NOOP(
                "{file}: row {row}, column '{column}': {now} here, {captured} in the capture "
                "record {record}: nothing was issued (readings edited on purpose: run again "
                "with --edited-after-capture, and the certificate lists each edit)"),
                file=args.file, row=line, column=edit.column, now=edit.now or "—",
                captured=edit.captured, record=path))
        raise CaptureRecordError(message(QT_TR_NOOP(
            "{file}: row {row}: {edit} (the capture record {record}): nothing was issued"),
            file=args.file, row=line, edit=edit.text(), record=path))
    return [session]


def _write_pdf_and_dcc(args: argparse.Namespace, kind, result, document, words, settings) -> None:
    """The PDF of ``document`` and, with --dcc, its DCC (built and validated first: when it
    is refused, neither file is written), its budgets from the ``settings`` ``result`` was
    analysed with."""
    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.project.atomic_write import write_bytes_atomic

    pdf = certificate_pdf_bytes(document)
    xml = _dcc_of(args, kind, result, document, pdf, words, settings) if args.dcc else None
    _writing(args.certificate, "--certificate", lambda: write_bytes_atomic(args.certificate, pdf))
    if xml is not None:
        _writing(args.dcc, "--dcc", lambda: write_bytes_atomic(args.dcc, xml))
        _say(rendered(message(QT_TR_NOOP("DCC of {number} written to {path}"),
                              number=document.metadata.certificate_number, path=args.dcc), words))


def _dcc_of(args: argparse.Namespace, kind, result, document, pdf: bytes, words,
            settings) -> bytes:
    """The DCC of the certificate printed into ``pdf`` (app/dcc_issue.render_dcc); says on
    stderr when no schema folder is set, so it was not validated."""
    from app.dcc_issue import dcc_schema_dir, render_dcc

    folder = dcc_schema_dir(args.dcc_schema)
    xml = render_dcc(kind, result, document, pdf, Path(args.certificate).name, folder,
                     settings)
    if not folder and pdf:  # once: not of the DCC made before its PDF (its record digest)
        _say(rendered(message(QT_TR_NOOP(
            "{path}: the DCC was not validated (no schema folder: --dcc-schema DIR or "
            "ANGLEBENCH_DCC_SCHEMA)"), path=args.dcc), words))
    return xml


def _specimen(args: argparse.Namespace, kind, result, document, words, settings) -> None:
    """The bundled example details (``"example": true``): a SPECIMEN, watermarked and
    numbered SPECIMEN-… (a number the register refuses, so it cannot clash), never
    recorded in any register."""
    from app.certificate_issue import specimen_document

    document = specimen_document(document)
    number = document.metadata.certificate_number
    _write_pdf_and_dcc(args, kind, result, document, words, settings)
    _say(rendered(message(QT_TR_NOOP(
        "SPECIMEN {number} written to {path}: these are the bundled example details "
        "(\"example\": true); it is watermarked SPECIMEN, is not a certificate and was "
        "recorded in no register"), number=number, path=args.certificate), words))


def _readings_of_another_item(given: str) -> tuple[str, str] | None:
    """--readings-of-another-item (or --same-readings-as) N:REASON as (N, REASON), split
    at its first colon (the register splits it again after the number it names, where a
    typed number holds a colon); None when not given."""
    if not given.strip():
        return None
    number, _colon, reason = given.partition(":")
    return number.strip(), reason.strip()


def _issue_into(url, args, kind, result, metadata, settings, rows, words, report=False,
                raw_capture: list | None = None):
    """``report``: the document is a test report, and is called one (ISO/IEC 17025 7.8.2.1 a))."""
    from app.certificate_issue import IssuedNotWritten, issue_certificate
    from models.register.clock_rules import parse_confirmed_date
    from models.register.store import Register, RegisterError

    try:
        with Register(url) as register:
            # a write that waits for another's lock says so at once (reg72 #8)
            register.on_wait = lambda said: _say(f"anglebench analyze: {rendered(said, words)}")
            dcc = ((lambda document, pdf: _dcc_of(args, kind, result, document, pdf, words,
                                                  settings))
                   if args.dcc else None)
            record = issue_certificate(register, kind, result, metadata,
                                       kind.settings_with_defaults(settings), rows,
                                       _readings_source(args.file), args.certificate,
                                       dcc=dcc, dcc_path=args.dcc or "",
                                       separate_calibration=getattr(args, "separate_calibration", ""),
                                       another_makers_item=getattr(args, "another_makers_item",
                                                                   False),
                                       another_lookalike_item=getattr(
                                           args, "another_lookalike_item", False),
                                       readings_of_another_item=_readings_of_another_item(
                                           getattr(args, "readings_of_another_item", "")),
                                       same_readings_as=_readings_of_another_item(
                                           getattr(args, "same_readings_as", "")),
                                       confirmed_date=parse_confirmed_date(
                                           getattr(args, "confirm_date", "")),
                                       results=_issued_results(args) if args.results else None,
                                       results_path=args.results or "",
                                       raw_capture=raw_capture)
    except RegisterError as exc:
        _say(rendered(message(QT_TR_NOOP("anglebench analyze: {reason}; no certificate was "
                                         "written"), reason=reason_of(exc)), words))
        return None
    except IssuedNotWritten as exc:
        _say(rendered(_not_written(exc), words))
        for other in exc.others:  # every file not written is named (reg72 #5)
            _say(rendered(_not_written_either(other), words))
        return None
    except OutputRefused as exc:  # e.g. an issued file named as an output: nothing issued
        _say(f"anglebench analyze: {_why(exc, words)}")
        return None
    _say(rendered(message(QT_TR_NOOP("Test report {number} issued: written to {path} and "
                                     "recorded in the register (sha256 {sha}…)") if report else
                          QT_TR_NOOP("Certificate {number} issued: written to {path} and "
                                     "recorded in the register (sha256 {sha}…)"),
                          number=record.number, path=args.certificate,
                          sha=record.pdf_sha256[:16]), words))
    if args.dcc:
        _say(rendered(message(QT_TR_NOOP("DCC of {number} written to {path}"),
                              number=record.number, path=args.dcc), words))
    if args.results:
        _say(rendered(message(QT_TR_NOOP("Results of {number} written to {path} and recorded "
                                         "in the register"),
                              number=record.number, path=args.results), words))
    return record


def _not_written(exc) -> Message:
    """What to do about a certificate issued and recorded whose file ``exc`` names was not
    written: the PDF and the DCC are saved again from the register; a results file is not
    kept there (its SHA-256 only), so it is said whether the register records it (rev62 F6:
    the advice named the PDF whatever file was missing)."""
    number = exc.record.number
    if exc.what in ("pdf", "dcc") and isinstance(exc.__cause__, OutputRefused):
        # another issue put its certificate at that name meanwhile (rev64 F7): never replaced
        return message(QT_TR_NOOP(
            "anglebench analyze: certificate {number} is issued and recorded, but not written: "
            "{path} became another certificate's issued file meanwhile, which is never "
            "replaced; save it with 'anglebench register show {number} {flag} {out}'"),
            number=number, path=exc.path, flag=f"--{exc.what}",
            out="OUT.xml" if exc.what == "dcc" else "OUT.pdf")
    if exc.what == "dcc":
        return message(QT_TR_NOOP(
            "anglebench analyze: certificate {number} is issued and recorded, but {reason}: "
            "save its DCC with 'anglebench register show {number} --dcc OUT.xml'"),
            number=number, reason=str(exc))
    if exc.what == "results" and exc.recorded and isinstance(exc.__cause__, OutputRefused):
        # the name was taken by another issue meanwhile (rev63 F7): not to be renamed onto it
        return message(QT_TR_NOOP(
            "anglebench analyze: certificate {number} is issued, recorded and written, and "
            "its results file recorded, but not put in place: {path} became another "
            "certificate's issued file meanwhile, which is never replaced. The recorded "
            "results file is {kept}; give it another name"),
            number=number, path=exc.path, kept=exc.kept)
    if exc.what == "results" and exc.recorded:
        return message(QT_TR_NOOP(
            "anglebench analyze: certificate {number} is issued, recorded and written, and "
            "its results file recorded, but not renamed into place ({reason}): the recorded "
            "file is {kept}; rename it to {path}"),
            number=number, reason=str(exc), kept=exc.kept, path=exc.path)
    if exc.what == "results":
        return message(QT_TR_NOOP(
            "anglebench analyze: certificate {number} is issued, recorded and written (its "
            "PDF, and its DCC if asked for), but its results file was not ({reason}): the "
            "register records no results file for {number}"),
            number=number, reason=str(exc))
    return message(QT_TR_NOOP(
        "anglebench analyze: test report {number} is issued and recorded, but {reason}: "
        "save it with 'anglebench register show {number} --pdf OUT.pdf'")
        if exc.record.document_kind == "test" else QT_TR_NOOP(
        "anglebench analyze: certificate {number} is issued and recorded, but {reason}: save "
        "it with 'anglebench register show {number} --pdf OUT.pdf'"),
        number=number, reason=str(exc))


def _not_written_either(exc) -> Message:
    """Another file of the certificate ``exc`` names that was not written, after the first
    (:func:`_not_written`), and how to write it again — or that nothing can."""
    number = exc.record.number
    if exc.what == "dcc":
        return message(QT_TR_NOOP(
            "  nor its DCC ({reason}): save it with 'anglebench register show {number} --dcc "
            "OUT.xml'"), number=number, reason=str(exc))
    if exc.what == "results" and exc.recorded:
        return message(QT_TR_NOOP(
            "  its results file was recorded but not renamed into place ({reason}): the "
            "recorded file is {kept}; rename it to {path}"),
            reason=str(exc), kept=exc.kept, path=exc.path)
    return message(QT_TR_NOOP(
        "  nor its results file ({reason}): the register records no results file for "
        "{number}, and no command writes it afterwards (its readings and results are in the "
        "record: 'anglebench register show {number} --project OUT.json', analysed again "
        "without issuing)"), number=number, reason=str(exc))


def _issued_results(args: argparse.Namespace):
    """The results file of the certificate issued (app/certificate_issue.py): made from the
    document recorded and the register's record, so with its number and date of issue."""
    from app.writers.results_export import results_bytes

    return lambda document, record: results_bytes(args.results, document,
                                                  ANGLE_UNITS[args.unit], record)


def _export(args: argparse.Namespace, kind, result, settings: dict[str, Any],
            rows: Callable[[], list[list[str]]]) -> int:
    # The PDF writer (fpdf2) is imported only when a certificate is asked for.
    from app.certificate_issue import draft_reasons
    from app.dcc_issue import DccError
    from app.writers.results_export import write_results_csv, write_results_xlsx
    from models.certificate.metadata import MetadataError

    words = translator(args.language)
    try:
        metadata = _read_metadata(args.metadata,
                                  kind.error_unit(kind.settings_with_defaults(settings)),
                                  getattr(args, "reference", None))
    except MetadataError as exc:
        _say(f"anglebench analyze: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    raw_capture = None
    if args.capture_record:
        from app.capture_record import CaptureRecordError

        try:
            raw_capture = _capture_record(args, kind, settings, rows())
        except CaptureRecordError as exc:
            _say(f"anglebench analyze: {_why(exc, words)}")
            return EXIT_BAD_INPUT
    try:
        source = _readings_source(args.file)
        document = kind.certificate_document(result, metadata, source, settings)
        if raw_capture:  # a draft or a specimen names the capture as the issue does
            from app.certificate_issue import readings_edited_after_capture, readings_stated

            origin, digest = readings_stated(kind.key, source, rows(),
                                             raw_capture, kind.columns, result)
            document = dataclasses.replace(
                kind.certificate_document(result, metadata, origin, settings),
                raw_data_sha256=digest, edited_readings=tuple(
                    e.text() for e in readings_edited_after_capture(
                        kind, kind.settings_with_defaults(settings), rows(), raw_capture)))
    except MetadataError as exc:
        _say(f"anglebench analyze: {_why(exc, words)}")
        return EXIT_BAD_INPUT
    try:
        if args.certificate and metadata.example:
            _specimen(args, kind, result, document, words, settings)
        elif args.certificate and not draft_reasons(metadata):
            record = _issue(args, kind, result, metadata, settings, rows(),
                            document.is_test_report, raw_capture)
            if record is None:
                return EXIT_BAD_INPUT
            return 0  # the results file too, issued and recorded with it
        elif args.certificate:
            _write_pdf_and_dcc(args, kind, result, document, words, settings)
            _say(rendered(message(QT_TR_NOOP(
                "Test report written to {path} (DRAFT: {fields} missing; nothing was recorded "
                "in the register)") if document.is_test_report else QT_TR_NOOP(
                "Certificate written to {path} (DRAFT: {fields} missing; nothing was recorded "
                "in the register)"), path=args.certificate, fields=listed(
                    message(name) for name in metadata.missing_fields(
                        document.is_test_report))), words))
        if args.results:
            write = (write_results_xlsx if args.results.lower().endswith(".xlsx")
                     else write_results_csv)
            _writing(args.results, "--results",
                     lambda: write(args.results, document, ANGLE_UNITS[args.unit]))
            _say(rendered(message(QT_TR_NOOP("Results written to {path}"), path=args.results),
                          words))
    except DccError as exc:
        # said of the document it is (assessment 73 L2)
        _say(rendered(message(QT_TR_NOOP("anglebench analyze: {reason}; neither the test report "
                                         "nor its DCC was written")
                              if document.is_test_report else
                              QT_TR_NOOP("anglebench analyze: {reason}; neither the certificate "
                                         "nor its DCC was written"), reason=reason_of(exc)),
                      words))
        return EXIT_BAD_INPUT
    except _NotWritten as exc:  # the file named, the reason in words (contract75 F12)
        _say(rendered(_output_not_written(exc.path, exc.__cause__, exc.flag), words))
        return EXIT_BAD_INPUT
    except (OSError, ValueError) as exc:
        _say(rendered(message(QT_TR_NOOP("anglebench analyze: cannot write: {reason}"),
                              reason=reason_of(exc)), words))
        return 1
    return 0


class _NotWritten(Exception):
    """An output that could not be written: the file the user named (``path``, given as
    ``flag``); the cause is the OSError."""

    def __init__(self, path: str, flag: str) -> None:
        super().__init__(path)
        self.path, self.flag = path, flag


def _writing(path: str, flag: str, write: Callable[[], object]) -> None:
    """``write()``, its OSError raised as :class:`_NotWritten` naming ``path``: the
    atomic write fails on its temporary file, or on a full disk names no file at all."""
    try:
        write()
    except OSError as exc:
        raise _NotWritten(path, flag) from exc


def _output_not_written(path: str, exc: BaseException | None, flag: str) -> Message:
    """"anglebench analyze: " and why ``path`` could not be written, in words."""
    from models.project.write_failure import output_not_written

    return joined(("anglebench analyze: ",
                   output_not_written(path, exc or OSError(), flag)))
