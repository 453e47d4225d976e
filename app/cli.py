"""``anglebench analyze KIND FILE``: analyse a CSV without a window.

Prints a readable summary, or JSON with ``--json``. Bad input: exit status 2
and one line on stderr naming the file, the row and what is wrong.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
from pathlib import Path
from typing import Any

from models.analysis_kind import SettingsError
from models.certificate_metadata import CertificateMetadata, MetadataError
from models.kinds import KINDS
from models.readings import ReadingsSheet
from models.results_export import write_results_csv, write_results_xlsx
from models.tabular_import import TableImportError, map_columns, read_table

EXIT_BAD_INPUT = 2


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):  # one line, exit 2, no usage dump
        sys.stderr.write(f"anglebench analyze: {message}\n")
        raise SystemExit(EXIT_BAD_INPUT)


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="anglebench analyze", description="Analyse a readings file")
    p.add_argument("kind", choices=sorted(KINDS))
    p.add_argument("file")
    p.add_argument("--json", action="store_true", help="print JSON instead of a summary")
    p.add_argument("--certificate", metavar="OUT.pdf", help="also write a test certificate")
    p.add_argument("--metadata", metavar="META.json",
                   help="certificate metadata (lab, customer, item, standards…); without it "
                        "the certificate is marked DRAFT")
    p.add_argument("--results", metavar="OUT.csv|OUT.xlsx",
                   help="also write the results per point (with U) as CSV or XLSX")
    p.add_argument("--method", choices=["elevation", "azimuth"], help="theodolite: identify from")
    p.add_argument("--reference-row", type=int, help="theodolite: 1-based reference row")
    p.add_argument("--zenith", action="store_true", help="theodolite: vertical column is zenith V")
    p.add_argument("--grade", type=int, help="polygon: encoder grade 1–7")
    p.add_argument("--counting", choices=["auto", "with", "against"],
                   help="polygon: the encoder counts with or against the face numbering")
    p.add_argument("--zero-face", type=int,
                   help="polygon: the common zero (0: the first reading of set 1)")
    p.add_argument("--closure-drift", choices=["report", "spread"],
                   help="polygon: report the closure drift, or spread it linearly and remove it")
    p.add_argument("--ac-roll", type=float, metavar="ARCMIN",
                   help="polygon: the autocollimator reticle's roll limit (budget input)")
    p.add_argument("--lines-per-rev", type=int, help="fringe: grating lines per revolution")
    p.add_argument("--samples-per-period", type=int,
                   help="fringe: equal steps, N samples a period (leave it out to take the phase "
                        "from the theta_deg column, or to estimate it from the signals)")
    p.add_argument("--period-nm", type=float,
                   help="fringe: an interferometer, this many nm a fringe period (errors in nm)")
    return p


def _settings_from(args: argparse.Namespace) -> dict[str, Any]:
    settings: dict[str, Any] = {}
    if args.method:
        settings["method"] = args.method
    if args.reference_row is not None:
        settings["reference_row"] = args.reference_row
    if args.zenith:
        settings["vertical_reading"] = "zenith"
    if args.grade is not None:
        settings["grade"] = args.grade
    if args.counting:
        settings["counting"] = args.counting
    if args.zero_face is not None:
        settings["zero_face"] = args.zero_face
    if args.closure_drift:
        settings["closure_drift"] = args.closure_drift
    if args.ac_roll is not None:
        settings["ac_roll_arcmin"] = args.ac_roll
    if args.lines_per_rev is not None:
        settings["lines_per_rev"] = args.lines_per_rev
    if args.samples_per_period is not None:
        settings["samples_per_period"] = args.samples_per_period
    if args.period_nm is not None:
        settings["period_nm"] = args.period_nm
    return settings


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
    args = _parser().parse_args(argv)
    kind = KINDS[args.kind]
    try:
        table = read_table(args.file)
        rows = map_columns(table, kind.columns)
    except TableImportError as exc:
        sys.stderr.write(f"{exc}\n")
        return EXIT_BAD_INPUT
    parsed = ReadingsSheet(kind.columns, rows).parse()
    if parsed.errors:
        first = parsed.errors[0]
        line = table.line_numbers[first.row]
        more = f" (and {len(parsed.errors) - 1} more bad cell(s))" if len(parsed.errors) > 1 else ""
        sys.stderr.write(
            f"{args.file}: row {line}, column '{first.column_key}': {first.reason}{more}\n")
        return EXIT_BAD_INPUT
    try:
        result = kind.analyze(parsed, kind.settings_with_defaults(_settings_from(args)))
    except SettingsError as exc:
        sys.stderr.write(f"anglebench analyze: {exc}\n")
        return EXIT_BAD_INPUT
    except ValueError as exc:
        sys.stderr.write(f"{args.file}: {exc}\n")
        return EXIT_BAD_INPUT
    if args.json:
        sys.stdout.write(json.dumps(_finite(kind.to_json(result)), indent=1, ensure_ascii=False)
                         + "\n")
    else:
        sys.stdout.write(f"{kind.title}: {args.file}\n{kind.summary(result)}\n")
        for warning in getattr(result, "warnings", []):
            sys.stdout.write(f"Warning: {warning}\n")
    if args.certificate or args.results:
        return _export(args, kind, result)
    return 0


def _read_metadata(path: str | None) -> CertificateMetadata:
    if not path:
        return CertificateMetadata()
    try:
        with open(path, encoding="utf-8-sig") as handle:
            data = json.load(handle)
    except OSError as exc:
        raise MetadataError(f"{path}: cannot read ({exc.strerror})") from None
    except (json.JSONDecodeError, UnicodeDecodeError) as exc:
        raise MetadataError(f"{path}: not a JSON file ({exc})") from None
    try:
        return CertificateMetadata.from_dict(data)
    except MetadataError as exc:
        raise MetadataError(f"{path}: {exc}") from None


def _export(args: argparse.Namespace, kind, result) -> int:
    # The PDF writer (fpdf2) is imported only when a certificate is asked for.
    from app.certificate_pdf import write_certificate_pdf

    try:
        metadata = _read_metadata(args.metadata)
    except MetadataError as exc:
        sys.stderr.write(f"anglebench analyze: {exc}\n")
        return EXIT_BAD_INPUT
    try:
        document = kind.certificate_document(result, metadata, Path(args.file).name)
    except MetadataError as exc:
        sys.stderr.write(f"anglebench analyze: {exc}\n")
        return EXIT_BAD_INPUT
    try:
        if args.certificate:
            write_certificate_pdf(args.certificate, document)
            draft = " (DRAFT: " + ", ".join(metadata.missing_fields()) + " missing)" \
                if document.is_draft else ""
            sys.stderr.write(f"Certificate written to {args.certificate}{draft}\n")
        if args.results:
            if args.results.lower().endswith(".xlsx"):
                write_results_xlsx(args.results, document)
            else:
                write_results_csv(args.results, document)
            sys.stderr.write(f"Results written to {args.results}\n")
    except (OSError, ValueError) as exc:
        sys.stderr.write(f"anglebench analyze: cannot write: {exc}\n")
        return 1
    return 0
