"""``anglebench register``: the certificate register for audits, without a window.

    anglebench register list [SEARCH]          newest first; SEARCH in number, serial, customer
    anglebench register show NUMBER            the record (--pdf OUT, --project OUT to extract)
    anglebench register verify FILE.pdf        is this PDF, byte for byte, one we issued?
    anglebench register export OUT.zip         every record: index.csv, PDFs, projects
    anglebench register interval SERIAL DAYS  set an instrument's calibration interval
    anglebench register continue SCHEME NEXT   continue numbering after hand-issued numbers

``--register URL`` (or ANGLEBENCH_REGISTER) chooses the register; the default is the
SQLite file in the user's data folder. Exit 2 with one line for a refusal; ``verify``
exits 1 for a PDF the register does not know.
"""

from __future__ import annotations

import argparse
import csv
import io
import sys
import zipfile

from models.project.atomic_write import write_bytes_atomic
from models.readings.sheet import one_line
from models.register.location import register_url

EXIT_BAD_INPUT = 2
COLUMNS = ("number", "status", "revision", "supersedes", "superseded_by", "issue_date",
           "calibration_date", "workbench", "item_description", "item_manufacturer",
           "item_serial", "customer", "operator", "workstation", "issued_at", "pdf_sha256")


class _Parser(argparse.ArgumentParser):
    def error(self, message: str):
        sys.stderr.write(one_line(f"anglebench register: {message}") + "\n")
        raise SystemExit(EXIT_BAD_INPUT)


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="anglebench register", description="The certificate register")
    p.add_argument("--register", metavar="URL", default="",
                   help="sqlite:///path, a file path or postgresql://user@host/db")
    sub = p.add_subparsers(dest="command", required=True)
    listing = sub.add_parser("list")
    listing.add_argument("search", nargs="?", default="")
    show = sub.add_parser("show")
    show.add_argument("number")
    show.add_argument("--pdf", metavar="OUT.pdf")
    show.add_argument("--project", metavar="OUT.anglebench.json")
    verify = sub.add_parser("verify")
    verify.add_argument("pdf")
    export = sub.add_parser("export")
    export.add_argument("out", metavar="OUT.zip")
    counter = sub.add_parser("continue", help="continue numbering from hand-issued numbers")
    counter.add_argument("scheme", help="e.g. AB-{year}-{seq:04d}")
    counter.add_argument("next", type=int, help="the next sequence number to issue")
    counter.add_argument("--date", default="", help="YYYY-MM-DD for the scheme's date fields "
                                                    "(default today)")
    interval = sub.add_parser("interval")
    interval.add_argument("serial")
    interval.add_argument("days", type=int, help="0 clears it")
    return p


def _print_record(record, register) -> None:
    revision = "" if record.revision == "original" else f", {record.revision}"
    lines = [f"{record.number}  ({record.status}{revision})"]
    for key in COLUMNS[3:]:
        value = getattr(record, key)
        if value:
            lines.append(f"  {key}: {value}")
    for name, value in record.headline.items():
        lines.append(f"  headline {name}: {value:.6g}")
    lines.append("  software: " + ", ".join(f"{k} {v}" for k, v in record.software.items()))
    due = register.due_date(record.item_serial) if record.item_serial else None
    if due:
        lines.append(f"  next calibration of {record.item_serial} due: {due.isoformat()}")
    sys.stdout.write("\n".join(lines) + "\n")


def _export(register, out: str) -> int:
    records = register.list()
    index = io.StringIO()
    writer = csv.writer(index)
    writer.writerow(COLUMNS + ("headline",))
    buffer = io.BytesIO()
    with zipfile.ZipFile(buffer, "w", zipfile.ZIP_DEFLATED) as archive:
        for record in records:
            writer.writerow([getattr(record, c) or "" for c in COLUMNS] + [record.headline_json])
            safe = record.number.replace("/", "_")
            archive.writestr(f"pdf/{safe}.pdf", register.pdf(record.number))
            archive.writestr(f"project/{safe}.anglebench.json", record.project_json)
        archive.writestr("index.csv", index.getvalue())
    write_bytes_atomic(out, buffer.getvalue())
    sys.stderr.write(f"{len(records)} certificate(s) exported to {out}\n")
    return 0


def run_register(argv: list[str]) -> int:
    args = _parser().parse_args(argv)
    from models.register.store import Register, RegisterError

    try:
        with Register(register_url(explicit=args.register)) as register:
            if args.command == "list":
                for r in register.list(args.search):
                    sys.stdout.write(f"{r.number}\t{r.status}\t{r.issue_date}\t{r.workbench}\t"
                                     f"{r.item_serial}\t{r.customer}\n")
                return 0
            if args.command == "show":
                record = register.get(args.number)
                _print_record(record, register)
                if args.pdf:
                    write_bytes_atomic(args.pdf, register.pdf(record.number))
                if args.project:
                    write_bytes_atomic(args.project, record.project_json.encode("utf-8"))
                return 0
            if args.command == "verify":
                try:
                    with open(args.pdf, "rb") as handle:
                        data = handle.read()
                except OSError as exc:
                    raise RegisterError(f"{args.pdf}: cannot read ({exc.strerror})") from None
                record = register.verify(data)
                if record is None:
                    sys.stdout.write(f"{args.pdf}: NOT in the register (no issued PDF has its "
                                     "SHA-256: altered, a draft, or from another register)\n")
                    return 1
                sys.stdout.write(f"{args.pdf}: certificate {record.number}, issued "
                                 f"{record.issued_at}, {record.status}; identical to the "
                                 "record (SHA-256)\n")
                return 0
            if args.command == "continue":
                import datetime as dt

                try:
                    date = dt.date.fromisoformat(args.date) if args.date else dt.date.today()
                except ValueError:
                    raise RegisterError(f"--date {args.date}: not YYYY-MM-DD") from None
                number = register.continue_numbering(args.scheme, date, args.next)
                sys.stdout.write(f"the next certificate of {args.scheme} will be {number}\n")
                return 0
            if args.command == "interval":
                register.set_interval(args.serial, args.days or None)
                return 0
            return _export(register, args.out)
    except RegisterError as exc:
        sys.stderr.write(one_line(f"anglebench register: {exc}") + "\n")
        return EXIT_BAD_INPUT
    except OSError as exc:
        sys.stderr.write(one_line(f"anglebench register: cannot write: {exc}") + "\n")
        return 1
