"""Figures read in another angle unit are converted from their unrounded values and rounded
there (assessment 70 H3: the results workbook's *Statistics* sheet gave U = 6.79 µrad, 1.4″
converted, where U is 6.964 µrad; the summary's u of ψ 14.5 µrad, 3.0″ converted, where it
is 14.77 µrad). GUM 7.2.6: U to at most two significant digits, the value to its decimal.

The expected figures are made here from first principles: the units' definitions and
Python's decimal rounding, nothing imported from the code under test."""

from __future__ import annotations

import math
import re
from decimal import ROUND_CEILING, ROUND_HALF_EVEN, Decimal

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from app.main import main

#: one arcsecond in each unit, from the definitions (1° = 3600″, 1 rad = 180/π °)
PER_ARCSEC = {"arcsec": 1.0, "urad": math.pi / 648000.0 * 1e6, "mdeg": 1000.0 / 3600.0}
SYMBOL = {"arcsec": "\"", "urad": " µrad", "mdeg": " mdeg"}


def _two_significant(u: float) -> int:
    """Decimals that show u with two significant digits after rounding it UP, as every
    printed U is (9.93 shows as 10, not 10.0); negative from 100 on (137 shows as 140, to
    the tens: assessment 76 M1)."""
    d = 1 - math.floor(math.log10(u))
    if float(Decimal(repr(u)).quantize(Decimal(1).scaleb(-d), ROUND_CEILING)) >= 10.0 ** (2 - d):
        d -= 1
    return d


def _fixed(x: float, d: int, how=ROUND_HALF_EVEN) -> str:
    q = Decimal(repr(x)).quantize(Decimal(1).scaleb(-d), how)
    places = max(0, d)
    return f"{q:.{places}f}" if q != 0 else f"{0:.{places}f}"


def _off_the_edge(x: float, d: int) -> bool:
    """x is not within 1e-6 of a digit of a rounding edge at d decimals (where two exact
    ways of converting may round apart)."""
    frac = abs(x) * 10.0 ** d % 1.0
    return abs(frac - 0.5) > 1e-6 and min(frac, 1 - frac) > 1e-6


@settings(max_examples=300, deadline=None)
@given(value=st.floats(-2000.0, 2000.0), u=st.floats(0.002, 900.0),
       key=st.sampled_from(sorted(PER_ARCSEC)))
def test_value_and_u_converted_unrounded_then_rounded_in_the_unit(value, u, key):
    from models.certificate.document import format_uncertain
    from models.display_units import ANGLE_UNITS, in_unit
    from models.messages import message

    f = PER_ARCSEC[key]
    ux, vx = u * f, value * f
    d = _two_significant(ux)
    assume(_off_the_edge(ux, d) and _off_the_edge(vx, d))
    text = in_unit(message("result {x}", x=format_uncertain(value, u, "\"")), ANGLE_UNITS[key])
    s = SYMBOL[key]
    # U rounded up, as every printed U (issue 39)
    assert text == f"result {_fixed(vx, d)}{s} ± {_fixed(ux, d, ROUND_CEILING)}{s}"


@settings(max_examples=200, deadline=None)
@given(value=st.floats(0.0, 500.0), lower=st.floats(0.01, 400.0), upper=st.floats(0.01, 400.0),
       key=st.sampled_from(sorted(PER_ARCSEC)))
def test_a_decided_interval_reads_value_plus_minus_u_in_every_unit(value, lower, upper, key):
    """A half range with its interval (assessment 70 M1): in every unit, the printed value
    less the printed U₋ is the printed lower end, plus U₊ the upper; each U the computed one
    rounded up (assessment 72 H1: one U in every document), U₋ the value where the lower end
    is held at 0."""
    from models.display_units import ANGLE_UNITS, in_unit
    from models.messages import message
    from models.uncertainty.printed_figure import printed_interval_figures

    f = PER_ARCSEC[key]
    lower = min(lower, value) if value > 0 else lower
    shown = printed_interval_figures(value, lower, upper, "\"", clip=True)
    text = in_unit(message("{v} {lo} {up} {a} {b}", v=shown["value"], lo=shown["lower"],
                           up=shown["upper"], a=shown["low"], b=shown["high"]),
                   ANGLE_UNITS[key])
    v, lo, up, a, b = (Decimal(t) for t in re.findall(r"-?\d+(?:\.\d+)?", text))
    d = _two_significant(max(lower, upper) * f)
    # written with d decimals; none from the tens on (d ≤ 0), each figure then on U's grid
    assert -v.as_tuple().exponent == max(0, d)
    assert all(x % Decimal(1).scaleb(-d) == 0 for x in (v, lo, up, a, b))
    assert v - lo == a and v + up == b
    assume(all(_off_the_edge(x * f, d) for x in (value, lower, upper, value - lower,
                                                   value + upper)))
    assert v == Decimal(_fixed(value * f, d))
    assert lo == Decimal(_fixed(lower * f, d, ROUND_CEILING)) or (a == 0 and lo == v)
    assert up == Decimal(_fixed(upper * f, d, ROUND_CEILING))


def _sheets(path):
    from openpyxl import load_workbook

    book = load_workbook(path)
    stats = {row[0].value: [c.value for c in row[1:]] for row in book["Statistics"].iter_rows()}
    meta = {row[0].value: row[1].value for row in book["Certificate"].iter_rows()}
    return stats, meta


@pytest.mark.parametrize("key", ["urad", "mdeg"])
def test_statistics_sheet_states_u_of_the_certificate_sheet(capsys, samples_dir, tmp_path, key):
    """The theodolite sample read in µrad and mdeg: the *Statistics* sheet's U is the
    *Certificate* sheet's exact U rounded to two significant digits in that unit, and the
    decided value and its U₊ the exact ones rounded to the same decimal."""
    path = tmp_path / f"{key}.xlsx"
    code = main(["analyze", "theodolite", str(samples_dir / "theodolite_sample.csv"),
                 "--metadata", str(samples_dir / "certificate_theodolite.json"),
                 "--results", str(path), "--unit", key])
    capsys.readouterr()
    assert code == 0
    stats, meta = _sheets(path)
    symbol = SYMBOL[key].strip()
    big_u = meta[f"Expanded uncertainty U, largest ({symbol})"]
    row = next(v for k, v in stats.items() if str(k).startswith("Expanded uncertainty U (p"))
    d = _two_significant(big_u)
    assert row[0] == pytest.approx(float(_fixed(big_u, d)), abs=1e-12)
    decided = next(v for k, v in stats.items() if str(k).startswith("Decided quantity"))
    upper = meta[f"U of the decided value, above it (U+) ({symbol})"]
    lower = meta[f"U of the decided value, below it (U−) ({symbol})"]
    value = meta[f"Decided value ({symbol})"]
    d = _two_significant(max(upper, lower))
    assert decided[0] == pytest.approx(float(_fixed(value, d)), abs=1e-12)
    assert decided[2] >= float(_fixed(upper, d, ROUND_CEILING)) - 1e-12


def test_summary_u_of_the_set_up_converted_from_its_value(capsys, samples_dir):
    """The summary's u of ψ, α, β in µrad: the JSON's u (arcsec) converted, then rounded to
    two significant digits; each parameter in degrees to the digit of its u (L8: β was
    −0.0395° beside u = 0.12″ = 0.000033°)."""
    import json

    sample = str(samples_dir / "theodolite_sample.csv")
    assert main(["analyze", "theodolite", sample, "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert main(["analyze", "theodolite", sample, "--unit", "urad"]) == 0
    out = capsys.readouterr().out
    for name, key in (("ψ", "psi"), ("α", "alpha"), ("β", "beta")):
        u_deg = data[f"{key}_u_deg"]
        line = next(x for x in out.splitlines() if f" {name} = " in x)
        found = re.search(r"= (-?[\d.]+)° ± ([\d.]+) µrad", line)
        assert found, line
        u = u_deg * 3600.0 * PER_ARCSEC["urad"]
        assert found.group(2) == _fixed(u, _two_significant(u))
        # the value to u's second significant digit in degrees (four decimals at least)
        assert len(found.group(1).split(".")[1]) == max(4, _two_significant(u_deg))
        assert float(found.group(1)) == pytest.approx(data[f"{key}_deg"], abs=10.0 ** -max(
            4, _two_significant(u_deg)))


@pytest.mark.parametrize(("kind", "key"), [("theodolite", "corrected_error_arcsec"),
                                           ("polygon", "mean_corrected_error_arcsec")])
def test_summary_range_converted_from_its_unrounded_ends(capsys, samples_dir, kind, key):
    """Assessment 72 L5: the summary read in µrad or mdeg gave the corrected error's range
    from its ends rounded in arcseconds ("−7.66 µrad", −1.58″ converted, where the end is
    −7.644 µrad; the polygon's "−0.485 µrad" for −0.10″). Each end is the JSON's unrounded
    one converted, then rounded at the arcsecond figure's resolution carried over (two
    decimals of ″ are two of µrad, three of mdeg), the peak-to-peak the ends' difference as
    printed."""
    import json

    sample = str(samples_dir / f"{kind}_sample.csv")
    assert main(["analyze", kind, sample, "--json"]) == 0
    errors = [x for x in json.loads(capsys.readouterr().out)[key] if x is not None]
    for unit, decimals in (("urad", 2), ("mdeg", 3)):
        assert main(["analyze", kind, sample, "--unit", unit]) == 0
        out = capsys.readouterr().out
        line = next(x for x in out.splitlines() if x.startswith("Corrected error"))
        s = re.escape(SYMBOL[unit])
        found = re.search(rf"([+-][\d.]+){s} … ([+-][\d.]+){s} \(peak-to-peak ([\d.]+){s}",
                          line)
        assert found, line
        low, high, ptp = found.groups()
        f = PER_ARCSEC[unit]
        assert Decimal(low) == Decimal(_fixed(min(errors) * f, decimals)), line
        assert Decimal(high) == Decimal(_fixed(max(errors) * f, decimals)), line
        assert Decimal(ptp) == Decimal(high) - Decimal(low), line


@pytest.mark.parametrize("key", ["urad", "mdeg"])
def test_zones_read_in_another_unit_at_the_decimal_of_their_u(samples_dir, key):
    """Assessment 72 L4: the zones read in µrad carried the decimal of U in arcseconds
    ("pass ≤ 4.58 µrad (T − U₊, U₊ = 2.4 µrad)", 0.94″ converted; "12.12 µrad" beside
    2.4 µrad). In any unit each limit is T converted less (plus) the U printed beside it,
    rounded down to that U's decimal, as every other figure is printed to U's. The
    theodolite sample decided against ±1.445″ under the guarded rule."""
    import json

    from models.certificate.metadata import CertificateMetadata
    from models.display_units import ANGLE_UNITS, in_unit
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    kind = KINDS["theodolite"]
    sample = samples_dir / "theodolite_sample.csv"
    parsed = ReadingsSheet(kind.columns, map_columns(read_table(str(sample)), kind.columns)).parse()
    settings = kind.settings_with_defaults({})
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text("utf-8"))
    details |= {"tolerance": 1.445, "tolerance_unit": "arcsec", "decision_rule": "guarded"}
    document = kind.certificate_document(kind.analyze(parsed, settings),
                                         CertificateMetadata.from_dict(details), sample.name,
                                         settings)
    text = str(in_unit(document.conformity.zones, ANGLE_UNITS[key]))
    s = re.escape(SYMBOL[key])
    number = r"(\d+(?:\.\d+)?)"
    found = re.fullmatch(
        rf"pass ≤ {number}{s} \(T − U₊, U₊ = {number}{s}\) < conditional pass ≤ .+ \(T\) < "
        rf"conditional fail ≤ {number}{s} \(T \+ U₋, U₋ = {number}{s}\) < fail", text)
    assert found, text
    low, up, high, down = (Decimal(x) for x in found.groups())
    t = Decimal(repr(1.445 * PER_ARCSEC[key]))
    for limit, u, side in ((low, up, -1), (high, down, +1)):
        d = -u.as_tuple().exponent
        assert -limit.as_tuple().exponent == d, text
        assert limit == (t + side * u).quantize(Decimal(1).scaleb(-d), "ROUND_FLOOR"), text
