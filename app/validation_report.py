"""``anglebench validate [--pdf OUT]``: the method validation record (ISO/IEC 17025 7.2.2).

Runs every reference case of :mod:`models.validation.cases` and prints one line
each; with ``--pdf`` writes a dated report a lab files as the validation of
this version of the software: each case with its source, expected value,
result and verdict, and the versions of Python, numpy and scipy it ran on.
Exit status 0 when every case passed, 1 otherwise. It speaks, and writes the report in,
the language of ``--language`` (default: the system's).
"""

from __future__ import annotations

import argparse
import datetime as dt
import platform
import sys
from pathlib import Path

from app.command_line import EXIT_BAD_INPUT, Parser, add_language_option, language_asked, speaking
from app.command_line import say as _say
from models import __version__
from models.certificate.document import Table
from models.messages import QT_TR_NOOP, in_language, message
from models.project.atomic_write import write_bytes_atomic
from models.validation.cases import ValidationCase, run_validation

__all__ = ["run_validate", "validation_pdf_bytes"]


def _versions() -> list[tuple[str, str]]:
    import numpy
    import scipy

    return [("AngleBench", __version__), ("Python", platform.python_version()),
            ("numpy", numpy.__version__), ("scipy", scipy.__version__),
            (QT_TR_NOOP("Platform"), platform.platform())]


def _verdict(case: ValidationCase) -> str:
    return QT_TR_NOOP("pass") if case.passed else QT_TR_NOOP("FAIL")


def validation_pdf_bytes(cases: list[ValidationCase], run_at: dt.datetime, trials: int,
                         language: str = "en") -> bytes:
    """The report; ``language`` "zh" prints it in Chinese (the texts of the certificate's
    Chinese, from the same catalogue)."""
    from app.writers.certificate_pdf import ReportPdf, close_fonts  # fpdf2 only when a PDF is asked for

    passed = sum(c.passed for c in cases)
    pdf = ReportPdf((QT_TR_NOOP("AngleBench method validation"),
                     run_at.strftime("%Y-%m-%d %H:%M UTC")),
                    (QT_TR_NOOP("Validation record of the software named below; file it with "
                                "the method's validation (ISO/IEC 17025 7.2.2)."),
                     f"AngleBench {__version__}"), language=language)
    say = pdf.say
    pdf.head = tuple(say(text) for text in pdf.head)
    pdf.foot = tuple(say(text) for text in pdf.foot)
    pdf.set_title(f"AngleBench {__version__} validation report")
    pdf.set_creator(f"AngleBench {__version__}")
    pdf.set_creation_date(run_at)
    pdf.add_page()
    pdf.set_font("dejavu", "B", 17)
    pdf.cell(0, 9, say(QT_TR_NOOP("Method validation report")), new_x="LMARGIN", new_y="NEXT")
    outcome = message(
        QT_TR_NOOP("Run on {date} at {time} UTC: {passed} of {cases} reference cases passed.")
        if passed == len(cases) else
        QT_TR_NOOP("Run on {date} at {time} UTC: {passed} of {cases} reference cases passed — "
                   "NOT VALIDATED."),
        date=run_at.strftime("%Y-%m-%d"), time=run_at.strftime("%H:%M"), passed=passed,
        cases=len(cases))
    pdf.paragraph(outcome, 11)
    pdf.key_values(_versions())
    pdf.heading(QT_TR_NOOP("What was checked"))
    pdf.paragraph(message(QT_TR_NOOP(
        "Three non-standard methods, each from a published paper: the theodolite run (Tian et "
        "al., Acta Photonica Sinica 46(11) 1112005, 2017), the polygon encoder test (Tian et "
        "al., Acta Optica Sinica 35(5) 0512003, 2015) and the fringe signal analysis (Gao et "
        "al., Acta Optica Sinica 33(7) 0712001, 2013). For each: the publication's check "
        "figures; exact simulations with known truth made by first-principles simulators (3-D "
        "rotations of mirror and face normals, sampled signals with a true phase) that share no "
        "code with the analysis, run through the whole analysis; and the GUM uncertainty budget "
        "against the spread of {trials} simulated repeated measurements (JCGM 101)."),
        trials=trials))
    header = (QT_TR_NOOP("Case"), QT_TR_NOOP("Source"), QT_TR_NOOP("Expected"),
              QT_TR_NOOP("Obtained"), QT_TR_NOOP("Verdict"))
    for workbench in dict.fromkeys(c.workbench for c in cases):
        pdf.heading(workbench, keep_with=30)
        rows = [(c.name, c.source, c.expected, c.obtained, _verdict(c))
                for c in cases if c.workbench == workbench]
        pdf.data_table(Table(workbench, header, rows), (62, 24, 38, 36, 14),
                       ("LEFT", "LEFT", "RIGHT", "RIGHT", "CENTER"), size=7.5)
    pdf.heading(QT_TR_NOOP("Reviewed by"))
    pdf.paragraph(message(QT_TR_NOOP("Name, signature and date: {blank}"),
                          blank="______________________________________________"))
    try:
        return bytes(pdf.output())
    finally:
        close_fonts(pdf)


def _parser(words) -> argparse.ArgumentParser:
    parser = Parser(prog="anglebench validate",
                    description=words(QT_TR_NOOP("Run the method validation cases")))
    parser.add_argument("--pdf", metavar="OUT.pdf",
                        help=words(QT_TR_NOOP("also write the validation report")))
    parser.add_argument("--trials", type=int, default=200,
                        help=words(QT_TR_NOOP("simulated runs for each budget comparison "
                                              "(default 200)")))
    add_language_option(parser, words)
    return parser


def run_validate(argv: list[str]) -> int:
    language = language_asked(argv)
    with speaking(language) as words:
        args = _parser(words).parse_args(argv)

    def say(text: str) -> str:
        return in_language(text, words)

    if not 100 <= args.trials <= 100_000:
        _say(say(QT_TR_NOOP("anglebench validate: --trials must be 100 to 100000")))
        return EXIT_BAD_INPUT
    run_at = dt.datetime.now(dt.timezone.utc).replace(second=0, microsecond=0)
    cases = run_validation(args.trials)
    for c in cases:
        sys.stdout.write(say(message(QT_TR_NOOP("{verdict}  {workbench}: {name} — expected "
                                                "{expected}, obtained {obtained}"),
                                     verdict=say(_verdict(c)), workbench=say(c.workbench),
                                     name=say(c.name), expected=say(c.expected),
                                     obtained=say(c.obtained))) + "\n")
    passed = sum(c.passed for c in cases)
    sys.stdout.write(say(message(QT_TR_NOOP("{passed} passed, {failed} failed"), passed=passed,
                                 failed=len(cases) - passed)) + "\n")
    if args.pdf:
        path = Path(args.pdf)
        try:
            write_bytes_atomic(path, validation_pdf_bytes(
                cases, run_at, args.trials, "zh" if language == "zh_CN" else "en"))
        except OSError as exc:
            _say(say(message(QT_TR_NOOP("anglebench validate: cannot write {path}: {reason}"),
                             path=str(path), reason=exc.strerror)))
            return EXIT_BAD_INPUT
        _say(say(message(QT_TR_NOOP("Validation report written to {path}"), path=str(path))))
    return 0 if passed == len(cases) else 1

