"""Assessment 78 L1: with two runs, a figure whose coverage interval is withheld (A, R, P,
Ps) is printed to the place of that interval's half-width — R↑ 6.93″ as "10″", its interval
"2″ … 244″" not printed — and nothing beside it said so: a reader saw R↑ = R↓ = R = 10″.
The rounding is kept (the two runs know the figure no closer: day 68 F5, the window prints
the same), and said: the figure's interval cell "— (withheld; value rounded to 10″)", and the
note on its withheld interval names the place. The axis is the one of
test_withheld_figures_printed (simulated from first principles)."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from tests.models.positioning.test_withheld_figures_printed import _axis, _quoted


def _place(low: float, high: float) -> str:
    """The place two significant digits of the half-width of [low, high] end on, as text."""
    d = 1 - math.floor(math.log10(0.5 * (high - low)))
    return f"{10.0 ** -d:.{max(d, 0)}f}\""


@pytest.fixture(scope="module")
def document():
    from models.certificate.metadata import CertificateMetadata
    from models.positioning.analysis import POSITIONING
    from models.positioning.report import positioning_certificate
    from models.readings.sheet import ReadingsSheet

    rows, _ = _axis(np.random.default_rng(6805))
    settings = POSITIONING.settings_with_defaults({})
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), settings)
    return positioning_certificate(result, CertificateMetadata(
        tolerance=15.0, tolerance_unit="arcsec", decision_quantity="points"))


@pytest.mark.parametrize("figure", ["A", "R", "R_up", "R_down", "P", "Ps_max"])
def test_a_figure_rounded_to_its_withheld_intervals_place_says_so(document, figure):
    notes = " ".join(str(s) for s in document.statements)
    place = _place(*_quoted(notes, figure))
    row = next(r for r in document.statistics.rows if str(r[0]).startswith(f"{figure}:"))
    # the figure to that place, beside it the place said
    assert str(row[2]) == f"— (withheld; value rounded to {place})", row
    d = re.search(r"\.(\d+)\"$", str(row[1]))
    assert (len(d.group(1)) if d else 0) == max(0, -math.floor(math.log10(
        float(place.rstrip('"'))))), row
    # the note on the withheld interval names it too
    assert (f"measure at least 3 runs each way; {figure} is printed rounded to {place}, the "
            "last place of that interval's half-width to two significant digits") in notes


def test_a_figure_with_its_interval_has_no_such_words(document):
    row = next(r for r in document.statistics.rows if str(r[0]).startswith("E:"))
    assert "…" in str(row[2]) and "withheld" not in str(row[2])


def test_said_in_the_printed_certificate_in_english_and_chinese(document):
    import dataclasses

    from app.writers.certificate_pdf import certificate_pdf_bytes
    from tests.pdf_text import pdf_text

    text = pdf_text(certificate_pdf_bytes(document))
    assert "— (withheld; value rounded to 10\")" in text or "rounded to 1\")" in text, text
    assert "R_up is printed rounded to" in text
    zh = pdf_text(certificate_pdf_bytes(dataclasses.replace(
        document, metadata=dataclasses.replace(document.metadata, language="zh"))))
    assert "（未给出；数值修约到" in zh and "R_up 修约到" in zh, zh
