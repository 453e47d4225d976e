"""The figures a certificate prints, rounded as GUM 7.2.6 / JJF 1059.1 ask (review 61, F7):
U to two significant digits at most and a figure to the same decimal; a sum the text or a
table states adds up as printed. Every expected figure is recomputed here from the
analysis' full-precision arrays, with its own rounding rule (not the code's helpers)."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.uncertainty.budget import BudgetComponent, UncertaintyBudget
from models.uncertainty.conformity import HalfRangeEstimate, decide_conformity
from tests.models.certificate.test_certificate_statements import _sample
from tests.models.certificate.test_certificate_uncertainty import META, POSITIONING_INPUTS

pytestmark = pytest.mark.slow


def _bundled(name: str, **changes) -> CertificateMetadata:
    """The sample's own certificate details (its standards), with ``changes``."""
    data = json.loads(Path(f"resources/samples/certificate_{name}.json").read_text("utf-8"))
    return CertificateMetadata.from_dict({**data, "language": "en", **changes})


def two_digits(u: float) -> int:
    """The decimals that show ``u`` with two significant digits, from its scientific
    notation after rounding (1.436 → "1.4e+00": 1; 0.0996 → "1.0e-01": 2; 9.96 → 0)."""
    return max(0, 1 - int(f"{u:.1e}".split("e")[1]))


def decimals_of(text: str) -> int:
    number = re.search(r"[-+]?\d+(?:\.(\d+))?", text)
    assert number, text
    return len(number.group(1) or "")


def test_the_rule_of_two_digits_used_here():
    assert [two_digits(u) for u in (1.436, 0.0996, 9.96, 0.4918, 5.1, 123.0)] == [1, 2, 0, 2,
                                                                                   1, 0]


# F7.1: the positioning figures, their intervals and the results table ----------------------
@pytest.fixture(scope="module")
def positioning():
    kind, result = _sample("positioning", POSITIONING_INPUTS)
    return kind, result, kind.certificate_document(result, META, settings=POSITIONING_INPUTS)


def test_each_figure_of_the_axis_to_the_decimal_of_its_interval(positioning):
    """A = 22.447″ with its interval 16.24″ … 26.45″ (4–10″ wide) was printed to 0.001″:
    now the figure and the interval's ends to the decimal of the half-width, two digits."""
    kind, result, document = positioning
    from models.positioning.report import figure_uncertainties

    intervals = figure_uncertainties(result, document.budget)
    rows = {row[0].split(":")[0]: row for row in document.statistics.rows}
    figures = {**result.iso.figures, **result.vdi.as_dict()}
    checked = 0
    for key, row in rows.items():
        if key not in intervals or key not in figures:
            continue
        iv = intervals[key]
        d = two_digits((iv.high - iv.low) / 2.0)
        assert row[1] == f"{figures[key]:.{d}f}\"", key
        # each end rounded outwards from the computed one (the printed interval holds it)
        step = 10.0 ** -d
        low = math.floor(round(iv.low / step, 9)) * step + 0.0
        high = math.ceil(round(iv.high / step, 9)) * step + 0.0
        assert row[2] == f"{low:.{d}f}\" … {high:.{d}f}\"", key
        checked += 1
    assert checked >= 10
    # the sample's A: 22.447″ with an interval some 27″ wide (16.8 … 44.0″: each target's own
    # bounds of μ ± 2σ, #39) is "22″", not "22.447″" (it was "22.4″" beside 17.4 … 25.3″)
    assert decimals_of(rows["A"][1]) == 0 and rows["A"][1] == f"{figures['A']:.0f}\""


def test_the_summary_prints_the_figures_as_the_intervals_allow():
    kind, result = _sample("positioning")
    from models.positioning.report import figure_uncertainties

    intervals = figure_uncertainties(result)
    text = str(kind.summary(result))
    for key in ("A", "R", "E", "P"):
        iv = intervals[key]
        d = two_digits((iv.high - iv.low) / 2.0)
        figure = {**result.iso.figures, **result.vdi.as_dict()}[key]
        assert f"{key} = {figure:.{d}f}\"" in text, key
        # each end with its unit (0.8.19: both converted in another unit)
        assert f"{key} {iv.low:.{d}f}\" … {iv.high:.{d}f}\"" in text, key
        assert d <= 2


def test_positioning_results_table_rounds_s_and_b_i_to_what_u_gives(positioning):
    """s and B_i, M_i were printed to 0.001″ beside x̄ at 0.1″ (U 1.0–2.1″): s now to two
    significant digits, B_i = x̄↑ − x̄↓ of the means as printed, M_i to the coarser mean's
    decimal."""
    kind, result, document = positioning
    table = document.results
    col = {h: i for i, h in enumerate(table.header)}
    up, down = result.iso.forward, result.iso.backward
    for i, row in enumerate(table.rows):
        a, b = row[col["x̄↑"]], row[col["x̄↓"]]
        d = min(decimals_of(a), decimals_of(b))
        # B_i rounded on its own (a sum of rounded figures printed 30°'s −5.720 as −5.8)
        assert row[col["B_i"]] == format(round(up.mean[i] - down.mean[i], d) + 0.0, f"+.{d}f")
        assert row[col["M_i"]] == f"{(up.mean[i] + down.mean[i]) / 2:+.{d}f}"
        for name, s in (("s↑", up.std[i]), ("s↓", down.std[i])):
            assert row[col[name]] == f"{s:.{two_digits(s)}f}", name
        assert decimals_of(row[col["B_i"]]) <= 1  # U of the means 1.0–2.1″: 0.1″ at most


# F7.2: the theodolite's statistics ---------------------------------------------------------
def test_theodolite_statistics_to_the_decimal_of_u_and_adding_up():
    """"-1.58″ … +1.30″ peak-to-peak 2.88″, RMS 0.81″" beside U = 1.4″: now to 0.1″, the
    peak-to-peak the printed ends' difference."""
    kind, result = _sample("theodolite")
    document = kind.certificate_document(result, META)
    big_u = float(np.max(document.budget.expanded))
    d = two_digits(big_u)
    assert d == 1  # U = 1.4″
    rows = {row[0]: row for row in document.statistics.rows}
    for name, errors in (("Raw error", result.raw_error_arcsec),
                         ("Corrected error", result.corrected_error_arcsec)):
        low, high = f"{np.min(errors):+.{d}f}", f"{np.max(errors):+.{d}f}"
        assert rows[name][1] == f"{low}\" … {high}\"", name
        ptp = f"{float(high) - float(low):.{d}f}\""
        assert rows[name][2].startswith(f"peak-to-peak {ptp}"), name
    rms = math.sqrt(float(np.mean(result.corrected_error_arcsec ** 2)))
    assert rows["Corrected error"][2].endswith(f"RMS {rms:.{d}f}\"")


# F7.4 and F7.5: the conformity sentence --------------------------------------------------
_SENTENCE = re.compile(r": ([\d.]+)\", the measured ([\d.]+)\" less ([\d.]+)\"")


def test_the_polygon_sentence_adds_up_as_printed():
    """"0.45″, the measured 0.49″ less 0.05″": 0.49 − 0.05 is 0.44. The value and the
    measured figure keep their own rounding; the excess is their difference as printed."""
    kind, result = _sample("polygon")
    document = kind.certificate_document(result, _bundled("polygon", tolerance=1))
    c = document.conformity
    found = _SENTENCE.search(str(c.statement))
    assert found, c.statement
    value, measured, excess = found.groups()
    d = decimals_of(value)
    assert float(measured) - float(excess) == pytest.approx(float(value), abs=1e-9)
    assert value == f"{c.value:.{d}f}"
    assert measured == f"{c.measured:.{d}f}"
    # the sample's: 0.4383″, measured 0.4918″: "0.44″, the measured 0.49″ less 0.05″" (0.8.16:
    # the noise of the forward/reverse pair, the encoder's in it; 0.4457″ before)
    assert (value, measured, excess) == ("0.44", "0.49", "0.05")


def test_the_measured_value_is_said_above_the_interval_only_where_printed_so():
    """The theodolite's "0.02″ … 1.44″ …; the measured value lies above it" with the measured
    value printed 1.44″ too (1.44000 against 1.43966)."""
    kind, result = _sample("theodolite")
    document = kind.certificate_document(result, _bundled("theodolite"))
    statement = str(document.conformity.statement)
    found = re.search(r"the measured ([\d.]+)\".*?range ([\d.]+)\" … ([\d.]+)\"", statement)
    assert found, statement
    measured, _, high = found.groups()
    # the upper end is the printed value + the printed U₊, U₊ 0.4922″ rounded up to 0.50″
    # (assessment 70 M1): 0.95″ + 0.50″ = 1.45″, with the measured 1.44″ inside it
    assert (measured, high) == ("1.44", "1.45")
    assert "lies above it" not in statement


def _estimate(measured: float, value: float, lower: float, upper: float) -> HalfRangeEstimate:
    return HalfRangeEstimate(measured, measured - value, value, upper, lower, 0.9545, 100, 1)


@pytest.mark.parametrize("measured, above", [(1.5, True), (1.2003, False)])
def test_above_the_interval_as_printed(measured, above):
    """Value 0.95″ with −0.30″/+0.2499″: the interval printed ends at 1.20″; a measured
    1.5″ lies above it, a measured 1.2003″ (printed 1.20″) is not said to."""
    budget = UncertaintyBudget((BudgetComponent("noise", "B", "normal", 0.1, 1.0, 1.0,
                                                math.inf),), 2)
    c = decide_conformity(np.array([0.0, 1.9]), budget, 3.0,
                          estimate=_estimate(measured, 0.95, 0.30, 0.2499))
    text = str(c.statement)
    assert "… 1.20\"" in text and (f"the measured {measured:.2f}\"" in text)
    assert ("lies above it" in text) is above


def _signed(value: float, d: int) -> str:
    """A signed figure as a results table prints it: a figure that rounds to zero unsigned,
    "0.0", neither "-0.0" nor "+0.0" (assessment 76 L6)."""
    text = f"{value:+.{d}f}"
    return text[1:] if float(text) == 0.0 else text


# F7.6: "corrected = raw + correction" as printed --------------------------------------------
@pytest.mark.parametrize("key, raw, corrected, columns", [
    ("polygon", "mean_error_arcsec", "mean_corrected_arcsec",
     ("Raw error (\")", "Correction (\")", "Corrected error (\")")),
    ("theodolite", "raw_error_arcsec", "corrected_error_arcsec",
     ("Raw error (\")", "Correction (\")", "Corrected error (\")")),
])
def test_the_results_table_rounds_each_figure_on_its_own(key, raw, corrected, columns):
    """Polygon position 2 printed −0.27 + 0.10 and a corrected −0.16 (0.8.10); the first fix
    printed the difference of the rounded figures, a correction of 0.00001″ as +0.01″ (the
    assessor's re-check). Each figure is now its own value rounded to the point's U's
    decimal: a sum may be one off in its last digit, never a figure."""
    kind, result = _sample(key)
    document = kind.certificate_document(result, _bundled(key))
    table = document.results
    col = {h: i for i, h in enumerate(table.header)}
    raw_v, corrected_v = getattr(result, raw), getattr(result, corrected)
    big_u = document.budget.expanded
    for i, row in enumerate(table.rows):
        a, c, b = (row[col[name]] for name in columns)
        if big_u[i] > 0:
            d = two_digits(float(big_u[i]))
            assert a == _signed(raw_v[i], d) and b == _signed(corrected_v[i], d), (i, row)
            exact = corrected_v[i] - raw_v[i]
            assert c == _signed(exact, d), (i, row)
            assert abs(float(a) + float(c) - float(b)) <= 1.0001 * 10.0 ** -d, (i, row)


def test_a_cell_printed_rounded_keeps_its_full_figure_when_copied():
    import copy
    import pickle

    from models.certificate.document import Exact

    cell = Exact("16.2\" … 26.4\"", (16.2404765773, 26.4495967468))
    for again in (pickle.loads(pickle.dumps(cell)), copy.deepcopy(cell), copy.copy(cell)):
        assert again == "16.2\" … 26.4\"" and again.exact == cell.exact
