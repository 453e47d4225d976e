"""``anglebench validate [--pdf OUT]``: the method validation record (ISO/IEC 17025 7.2.2).

Runs every reference case (:func:`models.validation.run.run_validation`) and prints one line
each; with ``--pdf`` writes a dated report a lab files as the validation of
this version of the software: each case with its source, expected value,
result and verdict, and the versions of Python, numpy and scipy it ran on.
Exit status 0 when every case passed, 1 otherwise. It speaks, and writes the report in,
the language of ``--language`` (default: the system's).
"""

from __future__ import annotations

import argparse
import datetime as dt
import math
import platform
import sys
from pathlib import Path

from app.command_line import EXIT_BAD_INPUT, Parser, add_language_option, language_asked, speaking
from app.command_line import say as _say
from models.certificate.document import Table
from models.messages import QT_TR_NOOP, in_language, joined, message, reason_of
from models.project.atomic_write import write_bytes_atomic
from models.validation.cases import ValidationCase
from models.validation.run import run_validation

__all__ = ["run_validate", "validation_pdf_bytes"]


#: libraries named besides the register's (models.register.store.LIBRARIES)
MORE_LIBRARIES = ("pypdfium2", "openpyxl", "fonttools", "GTC")


def _versions() -> list[tuple[str, str]]:
    """AngleBench with its commit, Python and every library a result or a record depends on."""
    import importlib.metadata

    from models.register.store import software_versions
    from models.software import software_identity

    versions = software_versions()
    rows = [("AngleBench", software_identity().printed),
            ("Python", versions.pop("python"))]
    for key in ("anglebench", "anglebench_commit", "anglebench_source_sha256"):
        versions.pop(key, None)
    for name in MORE_LIBRARIES:
        try:
            versions[name] = importlib.metadata.version(name)
        except importlib.metadata.PackageNotFoundError:
            continue
    rows += sorted(versions.items(), key=lambda kv: kv[0].lower())
    return rows + [(QT_TR_NOOP("Platform"), platform.platform())]


def document_id(run_at: dt.datetime) -> str:
    """The report's ID: the software's commit (or source digest) and the minute it ran."""
    from models.software import software_identity

    identity = software_identity()
    source = identity.commit[:12] if identity.commit else identity.source_sha256[:12]
    return f"AB-VAL-{identity.version}-{source}-{run_at:%Y%m%d%H%M}"


#: each kind of case's acceptance criterion, and why it is that
ACCEPTANCE = (
    QT_TR_NOOP("Check figures: the published figure to the digits it is printed with (the "
               "tolerance is half its last digit); a published table likewise."),
    QT_TR_NOOP("Exact simulations and examples worked by hand: agreement to 0.0001\" or "
               "better, far below any uncertainty a certificate states (its U is 0.01\" or "
               "more): what remains is rounding, not method."),
    QT_TR_NOOP("Budget against Monte Carlo: the spread of N simulated runs estimates a standard "
               "uncertainty to about 1/√(2N) (relative); the budget's u must agree within "
               "three times that, at least 10 %, over all points, and within four times that, "
               "at least 25 %, at the worst point of a curve (with N = 200: 15 % and 25 %; a "
               "worst point of 24 % passes by that margin, not by chance: over some 40 points "
               "the largest of their sampling errors reaches about 3 × 5 %, and a budget off by "
               "a quarter at one point would still be caught)."),
    QT_TR_NOOP("Coverage by simulation (the decided quantity's interval, half the "
               "peak-to-peak): the interval must cover the true value at least as often as the "
               "probability printed beside it, since a customer's risk rests on that figure; "
               "N runs of a true coverage p give fewer hits than the least number stated in "
               "under 1 % of studies (binomial), so fewer fail. The shapes are those that "
               "occur (smooth, rough, a single spike, the samples' real curves) with noise 0.1 "
               "to 2 times the half range at 12 to 72 points, and through the theodolite, "
               "polygon and positioning workbenches, each decided as its certificate decides "
               "(positioning: E/2 with E's own interval). Its width against what a correct "
               "interval needs (the oracle: the 2.275 %–97.725 % spread of value − truth over "
               "runs at the truth, read at Hazen's plotting positions, which few runs do not "
               "narrow) is reported beside it, and against the same spread of the measured "
               "half range, the least scattered estimate (the value, the measured half range "
               "less the noise's median excess, scatters more but runs less high); the aim is "
               "1.6 times at the most."),
    QT_TR_NOOP("Coverage study of the positioning figures (ISO 230-2 / GB/T 17421.2 A, E, M, R, "
               "B, B̄ and their one-direction forms; VDI/DGQ 3441 P, Ps, Pa, U): simulated axes "
               "(models/validation/axis_figures_rig.py) with a known systematic deviation curve "
               "(smooth pitch error, every harmonic the targets resolve, one spike, the bundled "
               "sample's curve), a known reversal and a known repeatability (constant, or ±50 % "
               "along the axis; the backward 10 % larger) of 0.1, 0.5 and 2 × the signal, 12 and "
               "72 targets, 5 runs each way by the standard test cycle, each test through the "
               "whole analysis. A figure's truth is the figure of the true distribution as the "
               "standard defines it. It passes when no more tests missed than a correct interval "
               "at the probability printed beside the figure would miss in 99 studies of 100 "
               "(binomial test); the probability printed is the one the full study reached "
               "where that is below the one asked for. Its mean width is stated as a multiple "
               "of the spread of measured − truth in each case (2z × its standard deviation "
               "over the case's tests): the width of an interval that knew σ along the axis, "
               "not of a correct one, which must also hold where σ differs from target to "
               "target in ways the readings cannot show. For R↑ and A↑ it is also stated "
               "against the narrowest interval that holds whatever σ does "
               "(tests/benchmarks/least_favourable_width_study.py); for B, E↑ and E (and the "
               "decided quantity, E/2) against the narrowest of simple bounds that hold every "
               "curve and σ pattern of tests/benchmarks/reversal_range_width_study.py: 1.6 × "
               "that narrowest is the aim."),
    QT_TR_NOOP("Software cases: exact (every name and figure found in the PDF's text; the "
               "register finds what it issued and reports what was changed; a file reads to "
               "the same numbers as numpy.loadtxt)."),
)


def software_cases() -> list[ValidationCase]:
    """What every workbench shares, checked end to end: a certificate's text as a reader
    extracts it, the register, and file import."""
    return [_pdf_text_case(), _register_case(), *_import_cases()]


SOFTWARE = QT_TR_NOOP("Software (all workbenches)")
END_TO_END = QT_TR_NOOP("exact, end to end")


def _pdf_text_case() -> ValidationCase:
    """The theodolite sample's certificate in Chinese with a Latin-only laboratory name,
    read back with PDFium: the name on every page and every figure of the results."""
    import json
    import re
    from dataclasses import replace

    import pypdfium2 as pdfium

    from app.writers.certificate_pdf import certificate_pdf_bytes
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    samples = Path(__file__).resolve().parent.parent / "resources" / "samples"
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), {})
    details = json.loads((samples / "certificate_theodolite.json").read_text("utf-8"))
    lab = "Shenzhen Angle Metrology Lab"
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details),
                                         kind.sample_file, {})
    document = replace(document, metadata=replace(document.metadata, lab_name=lab,
                                                  language="zh"))
    pdf = pdfium.PdfDocument(certificate_pdf_bytes(document))
    try:
        pages = [pdf[i].get_textpage().get_text_range() for i in range(len(pdf))]
    finally:
        pdf.close()
    flat = re.sub(r"\s+", "", "".join(pages))
    figures = {f.lstrip("+-−") if float(f.replace("−", "-")) == 0 else f  # no "−0.00"
               for row in document.results.rows for cell in row
               for f in re.findall(r"[+\-−]?\d+\.\d+", str(cell))}
    found = sum(f in flat for f in figures)
    named = sum(lab in page for page in pages)
    return ValidationCase(
        SOFTWARE, QT_TR_NOOP("certificate text as extracted from the PDF (zh, Latin-only lab "
                             "name)"), END_TO_END,
        message(QT_TR_NOOP("lab name on {pages} of {pages} pages, {n} of {n} figures"),
                pages=len(pages), n=len(figures)),
        message(QT_TR_NOOP("lab name on {named} of {pages} pages, {found} of {n} figures"),
                named=named, pages=len(pages), found=found, n=len(figures)),
        named == len(pages) and found == len(figures) and len(figures) > 20)


def _register_case() -> ValidationCase:
    """A register of its own: two certificates issued and verified; a PDF and its hash then
    rewritten together inside the database must be reported."""
    import hashlib
    import tempfile

    from models.certificate.metadata import CertificateMetadata
    from models.register.location import url_for_path
    from models.register.schema import CERTIFICATES
    from models.register.store import IssueRequest, Register

    meta = CertificateMetadata(approver="validation", calibration_date="")
    project = '{"format": "anglebench-project", "schema_version": 1, "workbenches": {}}'
    with tempfile.TemporaryDirectory(prefix="anglebench-validation-") as folder, \
            Register(url_for_path(Path(folder) / "register.sqlite")) as register:
        first, pdf = register.issue(IssueRequest("polygon", meta, project),
                                    lambda m: f"%PDF {m.certificate_number}".encode())
        register.issue(IssueRequest("polygon", meta, project), lambda m: b"%PDF second")
        verified = register.verify(pdf) is not None and register.audit(pdfs=True) == []
        forged = b"%PDF forged"
        with register.engine.begin() as conn:
            conn.execute(CERTIFICATES.update().where(CERTIFICATES.c.number == first.number)
                         .values(pdf=forged, pdf_sha256=hashlib.sha256(forged).hexdigest()))
        caught = len(register.audit(pdfs=True))
    return ValidationCase(
        SOFTWARE, QT_TR_NOOP("register: issue, verify, a PDF and its hash rewritten in the "
                             "database"), END_TO_END,
        QT_TR_NOOP("verified; the change reported"),
        message(QT_TR_NOOP("verified: {verified}; changes reported: {caught}"),
                verified=message(QT_TR_NOOP("yes") if verified else QT_TR_NOOP("no")),
                caught=caught),
        verified and caught >= 1)


def _import_cases() -> list[ValidationCase]:
    """Each sample read by the tolerant reader gives numpy.loadtxt's numbers; so does the
    same file written with semicolons and decimal commas."""
    import tempfile

    import numpy as np

    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    samples = Path(__file__).resolve().parent.parent / "resources" / "samples"
    cases = []
    for key, usecols in (("fringe", (0, 1, 2)), ("positioning", (0, 1, 3))):
        kind = KINDS[key]
        path = samples / kind.sample_file
        text = path.read_text("utf-8")
        header = text.splitlines()[0].split(",")
        reference = np.loadtxt(path, delimiter=",", skiprows=1, usecols=usecols, ndmin=2)
        worst = 0.0
        with tempfile.TemporaryDirectory(prefix="anglebench-validation-") as folder:
            comma = Path(folder) / "decimal-comma.csv"
            comma.write_text(text.replace(",", ";").replace(".", ","), "utf-8")
            for source in (path, comma):
                rows = map_columns(read_table(source), kind.columns)
                parsed = ReadingsSheet(kind.columns, rows).parse()
                read = np.column_stack([parsed.values[header[i]].astype(float)
                                        for i in usecols])
                worst = max(worst, float(np.max(np.abs(read - reference)))
                            if read.shape == reference.shape else math.inf)
        cases.append(ValidationCase(
            SOFTWARE, message(QT_TR_NOOP("file import of {file}, as written and with decimal "
                                         "commas, against numpy.loadtxt"),
                              file=kind.sample_file), END_TO_END, "0",
            f"{worst:g}", worst == 0.0))
    return cases


def _verdict(case: ValidationCase) -> str:
    return QT_TR_NOOP("pass") if case.passed else QT_TR_NOOP("FAIL")


def validation_pdf_bytes(cases: list[ValidationCase], run_at: dt.datetime, trials: int,
                         language: str = "en") -> bytes:
    """The report; ``language`` "zh" prints it in Chinese (the texts of the certificate's
    Chinese, from the same catalogue)."""
    from app.writers.certificate_pdf import ReportPdf, close_fonts  # fpdf2 only when a PDF is asked for

    passed = sum(c.passed for c in cases)
    from models.software import software_identity

    identity = software_identity()
    ident = document_id(run_at)
    pdf = ReportPdf((QT_TR_NOOP("AngleBench method validation"),
                     f"{ident} · {run_at:%Y-%m-%d %H:%M} UTC"),
                    (QT_TR_NOOP("Validation record of the software named below; file it with "
                                "the method's validation (ISO/IEC 17025 7.2.2)."),
                     f"{ident} · AngleBench {identity.short}"), language=language)
    say = pdf.say
    pdf.head = tuple(say(text) for text in pdf.head)
    pdf.foot = tuple(say(text) for text in pdf.foot)
    pdf.set_title(f"{ident}: AngleBench {identity.printed} validation report")
    pdf.set_creator(f"AngleBench {identity.printed}")
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
    pdf.key_values([(QT_TR_NOOP("Document ID"), ident), *_versions()])
    pdf.heading(QT_TR_NOOP("What was checked"))
    pdf.paragraph(message(QT_TR_NOOP(
        "Five workbenches. Three use non-standard methods, each from a published paper: the "
        "theodolite run (Tian et al., Acta Photonica Sinica 46(11) 1112005, 2017), the polygon "
        "encoder test (Tian et al., Acta Optica Sinica 35(5) 0512003, 2015) and the fringe "
        "signal analysis (Gao et al., Acta Optica Sinica 33(7) 0712001, 2013). The fourth, the "
        "positioning of an axis, follows standard methods (ISO 230-2, VDI/DGQ 3441, GB/T "
        "17421.2). The fifth, the cross-calibration of a polygon and an encoder against each "
        "other, solves the closure of the circle by least squares (Estler's rosette). For "
        "each: the publication's check figures or, for the standard methods, "
        "examples worked by hand; exact simulations with known truth made by first-principles "
        "simulators (3-D rotations of mirror and face normals, sampled signals with a true "
        "phase, an axis with a known error and lost motion) that share no code with the "
        "analysis, run through the whole analysis; and the GUM uncertainty budget against the "
        "spread of {trials} simulated repeated measurements (JCGM 101). Then what every "
        "workbench shares: the coverage factor k from ν, U rounded to two significant digits "
        "(GUM 7.2.6), the decision rules of ILAC-G8 with the guard band from the decided "
        "value's own interval, the probability of a false acceptance (JCGM 106) and the "
        "decisions refused (U incomplete, U ≥ T), the certificate's text as a reader extracts "
        "it from the PDF, the register, and file import."),
        trials=trials))
    pdf.heading(QT_TR_NOOP("Acceptance criteria"))
    for criterion in ACCEPTANCE:
        pdf.paragraph(joined(["• ", message(criterion)]), 8.5)
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



def _refused(pdf: str, say) -> bool:
    """Whether ``--pdf`` names a file no output may replace, said: the register (or one of
    its files) or a file it issued, a certificate's PDF, DCC or results file (rev64 F1:
    ``validate --pdf r.xlsx`` replaced an issued results file, the only copy, and then
    ``register verify`` called the real one "NOT in the register"); a recorded results file
    left under a temporary name beside it is kept first (app/issued_outputs.py)."""
    from app.issued_outputs import refuse_issued_outputs
    from models.project.output_guard import (
        OutputRefused,
        check_output,
        refuse_other_kind,
        register_files,
    )
    from models.register.location import register_url

    url = register_url()
    try:
        check_output(pdf, register_files(url), "--pdf")
        for said in refuse_issued_outputs(url, [("--pdf", pdf)]):
            _say(say(joined(("anglebench validate: ", said))))
        # nor a file that is no PDF, as analyze --certificate (contract75 F5: a readings CSV
        # named as --pdf became the report)
        refuse_other_kind(pdf, "--pdf")
    except OutputRefused as exc:
        _say(say(joined(("anglebench validate: ", reason_of(exc)))))
        return True
    return False

def _parser(words) -> argparse.ArgumentParser:
    parser = Parser(prog="anglebench validate",
                    description=words(QT_TR_NOOP("Run the method validation cases")))
    parser.add_argument("--pdf", metavar="OUT.pdf",
                        help=words(QT_TR_NOOP("also write the validation report")))
    parser.add_argument("--trials", type=int, default=200,
                        help=words(QT_TR_NOOP("simulated runs for each budget comparison, "
                                              "100 to 100000 (default 200)")))
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
    if args.pdf and _refused(args.pdf, say):
        return EXIT_BAD_INPUT
    run_at = dt.datetime.now(dt.timezone.utc).replace(second=0, microsecond=0)
    cases = run_validation(args.trials) + software_cases()
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

