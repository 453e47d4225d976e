"""Property test over the command line: whatever the file holds, `analyze` either
succeeds with finite, bounded figures, or exits 2 with exactly one line on stderr —
never a traceback, never an absurd figure at exit 0.

Each example starts from a plausible record of the workbench and mutates it with
the kinds of damage seen in the field (hostile cells, lost or repeated rows,
odd line endings, quotes, huge numbers, other scripts' digits …).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.main import main

HOSTILE = st.sampled_from([
    "", " ", "nan", "inf", "-inf", "1e308", "-1e308", "1e300", "1e-320", "0", "-0", "1_0",
    "١٢", "１２", "12°61'", "12°34'56.7\"", "-0°00'12.5\"", "abc", "=cmd|' /C calc'!A0", "+",
    "\"", "\"unterminated", "a\rb", "1,5", "1.5.5", "0x10", "9" * 400, "x" * 2000, "−3", "+-1",
    "1e5", "360", "720", "-720", "90", "91", "-91", "114", "-297", "\t", "NaN", "None",
])


def _polygon(rng: np.random.Generator, n: int) -> list[list[str]]:
    nominal = np.arange(n) * 360.0 / n
    rows = [[str(i + 1), f"{(10 + nominal[i] + rng.normal(0, 0.005)) % 360:.6f}",
             f"{rng.normal(0, 0.2):.2f}", f"{rng.normal(0, 10):.2f}", f"{rng.normal(0, 50):.2f}",
             "1", "+"] for i in range(n)]
    return [["position", "encoder_deg", "polygon_dev_arcsec", "ac_x_arcsec", "ac_y_arcsec", "set",
             "direction"]] + rows + [rows[0][:]]


def _theodolite(rng: np.random.Generator, n: int) -> list[list[str]]:
    theta = np.linspace(-20, 20, n)
    return [["theta_deg", "azimuth_deg", "elevation_deg"]] + [
        [f"{t:g}", f"{t + rng.normal(0, 0.01):.6f}", f"{0.1 * math.cos(math.radians(t)):.6f}"]
        for t in theta]


def _fringe(rng: np.random.Generator, n: int) -> list[list[str]]:
    theta = np.cumsum(rng.uniform(0.05, 0.4, 8 * n))
    return [["u_sin", "u_cos"]] + [[f"{math.sin(t):.5f}", f"{math.cos(t):.5f}"] for t in theta]


def _positioning(rng: np.random.Generator, n: int) -> list[list[str]]:
    targets = np.arange(0, 30 * max(2, n // 8), 30.0)
    rows = []
    for run in (1, 2, 3):
        for sign, order in (("+", targets), ("-", targets[::-1])):
            rows += [[f"{t:g}", str(run), sign, f"{rng.normal(0, 3):.2f}"] for t in order]
    return [["target", "run", "direction", "deviation"]] + rows


BASES = {"polygon": _polygon, "theodolite": _theodolite, "fringe": _fringe,
         "positioning": _positioning}


@st.composite
def damaged_record(draw, kind: str) -> str:
    seed = draw(st.integers(0, 2**31 - 1))
    n = draw(st.integers(3, 40))
    rows = BASES[kind](np.random.default_rng(seed), n)
    for _ in range(draw(st.integers(0, 4))):
        action = draw(st.sampled_from(["cell", "cell", "cell", "drop", "repeat", "blank", "swap"]))
        r = draw(st.integers(0, len(rows) - 1))
        if action == "cell":
            c = draw(st.integers(0, len(rows[r]) - 1))
            rows[r][c] = draw(HOSTILE)
        elif action == "drop" and len(rows) > 2:
            rows.pop(r)
        elif action == "repeat":
            rows.insert(r, list(rows[r]))
        elif action == "blank":
            rows.insert(r, [""] * len(rows[0]))
        else:
            r2 = draw(st.integers(0, len(rows) - 1))
            rows[r], rows[r2] = rows[r2], rows[r]
    newline = draw(st.sampled_from(["\n", "\r\n", "\r"]))
    delimiter = draw(st.sampled_from([",", ",", ";", "\t"]))
    return newline.join(delimiter.join(cells) for cells in rows) + newline


def _finite_figures(value, key: str = "") -> None:
    if isinstance(value, dict):
        for k, v in value.items():
            _finite_figures(v, k)
    elif isinstance(value, list):
        for v in value:
            _finite_figures(v, key)
    elif isinstance(value, float):
        assert math.isfinite(value), key
        assert abs(value) < 1e9, (key, value)
        if "error" in key:
            assert abs(value) <= 648_000.0, (key, value)  # half a turn, in arcsec


def _run(kind: str, text: str, tmp_path, capsys) -> None:
    path = tmp_path / f"{kind}.csv"
    path.write_bytes(text.encode("utf-8"))
    extra = ["--samples-per-period", "16"] if kind == "fringe" and len(text) % 3 == 0 else []
    code = main(["analyze", kind, str(path), "--json", *extra])
    out, err = capsys.readouterr()
    assert "Traceback" not in err
    if code == 0:
        data = json.loads(out)
        _finite_figures(data)
        for key, values in data.items():
            if isinstance(values, list) and key.endswith(("error_arcsec", "error_nm")):
                assert all(isinstance(v, float | int) for v in values), key
    else:
        assert code == 2, (code, err)
        assert len(err.strip().splitlines()) == 1, err
        assert str(path) in err or "anglebench analyze" in err


FUZZ = settings(max_examples=120, deadline=None,
                suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])


@pytest.mark.slow
@FUZZ
@given(text=damaged_record("polygon"))
def test_polygon_cli_never_crashes(text, tmp_path, capsys):
    _run("polygon", text, tmp_path, capsys)


@pytest.mark.slow
@FUZZ
@given(text=damaged_record("theodolite"))
def test_theodolite_cli_never_crashes(text, tmp_path, capsys):
    _run("theodolite", text, tmp_path, capsys)


@pytest.mark.slow
@FUZZ
@given(text=damaged_record("fringe"))
def test_fringe_cli_never_crashes(text, tmp_path, capsys):
    _run("fringe", text, tmp_path, capsys)


@pytest.mark.slow
@FUZZ
@given(text=damaged_record("positioning"))
def test_positioning_cli_never_crashes(text, tmp_path, capsys):
    _run("positioning", text, tmp_path, capsys)


# -- the families of the last fuzz round (issue 30): off-centre signals, elevations of no
# set-up, full-width and European spellings, XLSX, binary headers; judged as the full round
# judges them (tests/hostile_records.py; `python tests/hostile_records.py --cases 2500` runs
# the full round of 10,000 cases, seeded, and counts every finding)

ROUND = settings(max_examples=15, deadline=None,
                 suppress_health_check=[HealthCheck.function_scoped_fixture,
                                        HealthCheck.too_slow])


@st.composite
def round_case(draw, kind: str, family: str):
    from tests.hostile_records import Picks, case

    return case(Picks(draw=draw), kind, family)


def _judged(kind: str, made, tmp_path) -> None:
    from tests.hostile_records import judge

    suffix, data, extra = made
    path = tmp_path / f"{kind}{suffix}"
    path.write_bytes(data)
    outcome, problems, text = judge(kind, str(path), extra)
    assert outcome != "traceback" and problems == [], (outcome, problems, text)


@ROUND
@given(made=round_case("fringe", "off-centre"))
@pytest.mark.slow
def test_fringe_off_centre_signals_are_compensated_or_refused(made, tmp_path):
    _judged("fringe", made, tmp_path)


@pytest.mark.slow
@ROUND
@given(made=round_case("theodolite", "no set-up"))
def test_theodolite_elevations_of_no_setup_are_refused(made, tmp_path):
    _judged("theodolite", made, tmp_path)


@ROUND
@given(kind=st.sampled_from(["theodolite", "polygon"]), data=st.data())
@pytest.mark.slow
def test_full_width_and_decimal_comma_spellings(kind, data, tmp_path):
    _judged(kind, data.draw(round_case(kind, "spelling")), tmp_path)


@pytest.mark.slow
@ROUND
@given(kind=st.sampled_from(["theodolite", "polygon", "fringe", "positioning"]), data=st.data())
def test_damaged_xlsx(kind, data, tmp_path):
    _judged(kind, data.draw(round_case(kind, "xlsx")), tmp_path)


@ROUND
@given(kind=st.sampled_from(["theodolite", "polygon", "fringe", "positioning"]), data=st.data())
def test_binary_headers_are_refused_in_one_clean_line(kind, data, tmp_path):
    _judged(kind, data.draw(round_case(kind, "binary header")), tmp_path)


@ROUND
@given(kind=st.sampled_from(["theodolite", "polygon", "fringe", "positioning"]), data=st.data())
@pytest.mark.slow
def test_damaged_records_judged_as_the_round_judges_them(kind, data, tmp_path):
    _judged(kind, data.draw(round_case(kind, "damaged")), tmp_path)


@st.composite
def twin_records(draw, kind: str):
    from tests.hostile_records import Picks, twins

    return twins(Picks(draw=draw), kind)


@pytest.mark.slow
@ROUND
@given(kind=st.sampled_from(["theodolite", "polygon"]), data=st.data())
def test_xlsx_reads_what_the_csv_reads(kind, data, tmp_path):
    """The same D°M'S" record — full-width, Chinese, European decimal commas, a hostile cell —
    as CSV and as XLSX: the same refusal or the same figures."""
    from tests.hostile_records import judge_twins

    csv_data, xlsx_data = data.draw(twin_records(kind))
    (tmp_path / "r.csv").write_bytes(csv_data)
    (tmp_path / "r.xlsx").write_bytes(xlsx_data)
    assert judge_twins(kind, str(tmp_path / "r.csv"), str(tmp_path / "r.xlsx")) == []
