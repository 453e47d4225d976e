"""``anglebench validate [--pdf OUT]``: the method validation record (ISO/IEC 17025 7.2.2).

Runs every reference case of :mod:`models.validation.cases` and prints one line
each; with ``--pdf`` writes a dated report a lab files as the validation of
this version of the software: each case with its source, expected value,
result and verdict, and the versions of Python, numpy and scipy it ran on.
Exit status 0 when every case passed, 1 otherwise.
"""

from __future__ import annotations

import argparse
import datetime as dt
import platform
import sys
from pathlib import Path

from models import __version__
from models.certificate.document import Table
from models.project.atomic_write import write_bytes_atomic
from models.validation.cases import ValidationCase, run_validation

__all__ = ["run_validate", "validation_pdf_bytes"]


def _versions() -> list[tuple[str, str]]:
    import numpy
    import scipy

    return [("AngleBench", __version__), ("Python", platform.python_version()),
            ("numpy", numpy.__version__), ("scipy", scipy.__version__),
            ("Platform", platform.platform())]


def validation_pdf_bytes(cases: list[ValidationCase], run_at: dt.datetime, trials: int) -> bytes:
    from app.writers.certificate_pdf import ReportPdf, close_fonts  # fpdf2 only when a PDF is asked for

    passed = sum(c.passed for c in cases)
    pdf = ReportPdf(("AngleBench method validation", run_at.strftime("%Y-%m-%d %H:%M UTC")),
                    ("Validation record of the software named below; file it with the method's "
                     "validation (ISO/IEC 17025 7.2.2).", f"AngleBench {__version__}"))
    pdf.set_title(f"AngleBench {__version__} validation report")
    pdf.set_creator(f"AngleBench {__version__}")
    pdf.set_creation_date(run_at)
    pdf.add_page()
    pdf.set_font("dejavu", "B", 17)
    pdf.cell(0, 9, "Method validation report", new_x="LMARGIN", new_y="NEXT")
    pdf.paragraph(f"Run on {run_at.strftime('%Y-%m-%d at %H:%M UTC')}: {passed} of {len(cases)} "
                  f"reference cases passed{'' if passed == len(cases) else ' — NOT VALIDATED'}.",
                  11)
    pdf.key_values(_versions())
    pdf.heading("What was checked")
    pdf.paragraph(
        "Three non-standard methods, each from a published paper: the theodolite run (Tian et al., "
        "Acta Photonica Sinica 46(11) 1112005, 2017), the polygon encoder test (Tian et al., Acta "
        "Optica Sinica 35(5) 0512003, 2015) and the fringe signal analysis (Gao et al., Acta "
        "Optica Sinica 33(7) 0712001, 2013). For each: the publication's check figures; exact "
        "simulations with known truth made by first-principles simulators (3-D rotations of "
        "mirror and face normals, sampled signals with a true phase) that share no code with "
        "the analysis, run through the whole "
        f"analysis; and the GUM uncertainty budget against the spread of {trials} simulated "
        "repeated measurements (JCGM 101).")
    for workbench in dict.fromkeys(c.workbench for c in cases):
        pdf.heading(workbench, keep_with=30)
        rows = [(c.name, c.source, c.expected, c.obtained, "pass" if c.passed else "FAIL")
                for c in cases if c.workbench == workbench]
        pdf.data_table(Table(workbench, ("Case", "Source", "Expected", "Obtained", "Verdict"), rows),
                       (70, 26, 34, 30, 14), ("LEFT", "LEFT", "RIGHT", "RIGHT", "CENTER"), size=7.5)
    pdf.heading("Reviewed by")
    pdf.paragraph("Name, signature and date: ______________________________________________")
    try:
        return bytes(pdf.output())
    finally:
        close_fonts(pdf)


def run_validate(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="anglebench validate",
                                     description="Run the method validation cases")
    parser.add_argument("--pdf", metavar="OUT.pdf", help="also write the validation report")
    parser.add_argument("--trials", type=int, default=200,
                        help="simulated runs for each budget comparison (default 200)")
    args = parser.parse_args(argv)
    if not 100 <= args.trials <= 100_000:
        sys.stderr.write("anglebench validate: --trials must be 100 to 100000\n")
        return 2
    run_at = dt.datetime.now(dt.timezone.utc).replace(second=0, microsecond=0)
    cases = run_validation(args.trials)
    for c in cases:
        sys.stdout.write(f"{'pass' if c.passed else 'FAIL'}  {c.workbench}: {c.name} — expected "
                         f"{c.expected}, obtained {c.obtained}\n")
    passed = sum(c.passed for c in cases)
    sys.stdout.write(f"{passed} passed, {len(cases) - passed} failed\n")
    if args.pdf:
        path = Path(args.pdf)
        try:
            write_bytes_atomic(path, validation_pdf_bytes(cases, run_at, args.trials))
        except OSError as exc:
            sys.stderr.write(f"anglebench validate: cannot write {path}: {exc.strerror}\n")
            return 2
        sys.stderr.write(f"Validation report written to {path}\n")
    return 0 if passed == len(cases) else 1
