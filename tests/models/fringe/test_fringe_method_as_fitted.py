"""The fringe certificate's Method and its compensation, as the fit was made (day review 68).

F2: the Method said "fundamental and odd harmonics (3rd, 5th)" whatever was fitted; at N = 8
with the highest harmonic 3 (the refusal's advice followed) the parameters list A1 and A3
and the 5th is folded into A3. The Method now names the orders fitted and the order folded.

F8: with an order folded in, the error between the samples is not determined, yet "0.046″
after compensation" and the correction table were offered as good (window, CLI,
certificate, and an opinion that the table leaves the compensated error). Decided: the
compensated error at the sampled phases is the readings' own and is kept, said to hold at
the sampled phases only, and the correction table carries the same words; the opinion on
the table is replaced by them. JSON: ``compensation_determined_between_samples``.

The channels come from tests/fringe_channels.py (first principles), nothing from models/;
the certificates are read back with pdftotext, English and Chinese.
"""

from __future__ import annotations

import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.fringe_channels import Channels, equal_steps

LINES = 16384
SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
# the day review's record: true A3 5 mV, A5 4 mV
HEAD = Channels(offsets_v=(0.003, -0.004), amplitudes_v=(0.5, 0.49), quadrature_deg=0.5,
                sin_harmonics={3: (0.005, 0.4), 5: (0.004, 1.1)},
                cos_harmonics={3: (0.003, -0.3), 5: (0.0025, 0.2)}, noise_v=0.0003)
AT_SAMPLES = "at the sampled phases only"


def _record(tmp_path: Path, per_period: int) -> Path:
    theta = equal_steps(64 * per_period if per_period < 64 else 8 * per_period, per_period)
    u_sin, u_cos = HEAD.sample(theta, np.random.default_rng(68))
    path = tmp_path / f"n{per_period}.csv"
    path.write_text("u_sin,u_cos\n" + "".join(f"{s:.9f},{c:.9f}\n"
                                             for s, c in zip(u_sin, u_cos, strict=True)))
    return path


def _options(per_period: int, highest: int) -> list[str]:
    return ["--max-order", str(highest), "--lines-per-rev", str(LINES),
            "--samples-per-period", str(per_period)]


def _certificate_text(tmp_path: Path, per_period: int, highest: int, language: str,
                      capsys) -> str:
    if shutil.which("pdftotext") is None:
        pytest.fail("pdftotext is missing: apt-get install poppler-utils (.ci/run does)")
    details = json.loads((SAMPLES / "certificate_fringe.json").read_text("utf-8"))
    details.pop("certificate_number", None)  # the register allocates one
    details["language"] = language
    meta = tmp_path / f"meta_{language}.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    pdf = tmp_path / f"c_{language}.pdf"
    code = main(["analyze", "fringe", str(_record(tmp_path, per_period)), "--metadata",
                 str(meta), "--certificate", str(pdf), *_options(per_period, highest)])
    out = capsys.readouterr()
    assert code == 0, out.err
    text = subprocess.run(["pdftotext", "-enc", "UTF-8", str(pdf), "-"], capture_output=True,
                          text=True, encoding="utf-8", check=True).stdout
    text = re.sub(r"\s+", " ", text)
    # a page's foot and the next page's head, where a page breaks inside a sentence (the
    # statement moved onto a break when the document became a test report: assessment 72 M3)
    return re.sub(r" This (?:report|certificate) shall not be reproduced.*? Page \d+ of \d+ .*?"
                  r"(?:SPECIMEN-[0-9A-F]+|[A-Z]+-\d{4}-\d{4}) ", " ", text)


@pytest.fixture(scope="module")
def certificate_text(tmp_path_factory):
    """``certificate_text(per_period, highest, language, capsys)``: :func:`_certificate_text`
    once a module for each record and language (a certificate issued and printed, ~1.4 s of
    CPU; the English one at N = 8 is read by two tests). The text is a string: no test can
    change it."""
    texts: dict[tuple[int, int, str], str] = {}

    def text(per_period: int, highest: int, language: str, capsys) -> str:
        key = (per_period, highest, language)
        if key not in texts:
            folder = tmp_path_factory.mktemp(f"certificate-{per_period}-{highest}-{language}")
            texts[key] = _certificate_text(folder, per_period, highest, language, capsys)
        return texts[key]

    return text


@pytest.mark.parametrize("language", ["en", "zh"])
def test_the_method_names_the_orders_fitted_and_the_one_folded_in(certificate_text, capsys,
                                                                    language):
    text = certificate_text(8, 3, language, capsys)
    # the false claim is gone, in either language
    assert "odd harmonics (3rd, 5th)" not in text
    assert "3 次、5 次" not in text
    if language == "en":
        assert "an offset plus the harmonics of order 1, 3 (order 1 the fundamental)" in text
        assert ("Order 5 is not fitted: at the sampled phases it cannot be told from order 3, "
                "so A3 holds the two together.") in text


def test_the_method_names_the_5th_where_it_is_fitted_and_folds_nothing(certificate_text,
                                                                         capsys):
    text = certificate_text(64, 5, "en", capsys)
    assert "an offset plus the harmonics of order 1, 3, 5 (order 1 the fundamental)" in text
    assert "is not fitted" not in text
    assert AT_SAMPLES not in text
    # the opinion on the table stands where the curve between the samples is determined
    assert "the correction table is expected to leave" in text


SAID = ("at the sampled phases only: between them the correction table is built from fitted "
        "orders that hold orders not fitted (order 5 into order 3, order 7 into order 1), and "
        "the error it leaves "
        "there is not determined")


def test_the_certificate_says_the_compensation_holds_at_the_samples_only(certificate_text,
                                                                         capsys):
    """The statement replaces the opinion on the table (read back from the PDF); the
    statistics' "After compensation" and "Correction table" rows carry the same words (read
    from the document: a table's cells come back interleaved from pdftotext)."""
    text = certificate_text(8, 3, "en", capsys)
    # the table's own statement (its sha256) says it, in place of a statement of its own
    # (day review 68 F8, the rest)
    assert ("and the compensated error and the table hold " + SAID
            + "; sample more finely before loading the table into the encoder.") in text
    assert "the correction table is expected to leave" not in text
    from models.certificate.metadata import CertificateMetadata
    from models.fringe.analysis import FRINGE

    document = FRINGE.certificate(_result(8, 3), CertificateMetadata.from_dict({}))
    rows = {str(row[0]): " ".join(str(cell) for cell in row[1:])
            for row in document.statistics.rows}
    assert SAID in rows["After compensation (not applied to the item)"]
    assert SAID in rows["Correction table"]


def test_the_certificate_of_phases_that_resolve_the_5th_says_nothing_of_it():
    from models.certificate.metadata import CertificateMetadata
    from models.fringe.analysis import FRINGE

    document = FRINGE.certificate(_result(64, 5), CertificateMetadata.from_dict({}))
    assert not [row for row in document.statistics.rows if AT_SAMPLES in " ".join(map(str, row))]


def _result(per_period: int, highest: int):
    from models.fringe.analysis import FRINGE
    from models.readings.sheet import ParsedReadings

    count = 64 * per_period if per_period < 64 else 8 * per_period
    theta = equal_steps(count, per_period)
    u_sin, u_cos = HEAD.sample(theta, np.random.default_rng(68))
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(theta.size, math.nan)},
                            np.arange(theta.size))
    return FRINGE.analyze(parsed, {"max_order": highest, "lines_per_rev": LINES,
                                   "samples_per_period": per_period})


def _json(tmp_path: Path, per_period: int, highest: int, capsys) -> dict:
    code = main(["analyze", "fringe", str(_record(tmp_path, per_period)), "--json",
                 *_options(per_period, highest)])
    out = capsys.readouterr()
    assert code == 0, out.err
    return json.loads(out.out)


@pytest.mark.parametrize(("per_period", "highest", "determined"),
                         [(8, 3, False), (64, 5, True)])
def test_the_json_says_whether_the_compensation_holds_between_the_samples(
        tmp_path, capsys, per_period, highest, determined):
    data = _json(tmp_path, per_period, highest, capsys)
    assert bool(data["folded_orders"]) is not determined
    assert data["compensation_determined_between_samples"] is determined


def test_the_summary_and_the_windows_line_say_it(tmp_path, capsys):
    """The CLI's summary (the window's summary too), the table written and the bold line of
    the window (the workbench's verdict) say where the compensated error holds."""
    table = tmp_path / "table.csv"
    code = main(["analyze", "fringe", str(_record(tmp_path, 8)), *_options(8, 3),
                 "--table", str(table)])
    said = capsys.readouterr()
    out = said.out + said.err
    assert code == 0 and table.exists()
    assert "The compensated error holds at the sampled phases only" in out
    # the table written says it too, where it is written
    assert "Correction table, 1024 entries (CSV), " + AT_SAMPLES in out
    from models.fringe.analysis import FRINGE

    line = str(FRINGE.verdict(_result(8, 3)))
    assert "after compensation" in line and AT_SAMPLES in line
    assert AT_SAMPLES not in str(FRINGE.verdict(_result(64, 5)))
