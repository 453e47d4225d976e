"""Audit 73 finding 2: a positioning axis's decided half range E/2 is half the difference of
two means of readings typed to 0.001″, an exact decimal; where it is a tie on the place
compared with T (5.075″ at 0.01″, 5.0795″ at 0.001″), ASTM E29 §6.4 rounds the 5 to the
even digit. Computed in binary the tie comes out a few ulps below (5.074999999999999″), and
until 0.8.21 it was rounded down: "pass" against ±5.07″ where E29 gives 5.08″, a fail.

The record is simulated here (numpy only, typed to 0.001″); the exact E/2 is done here with
decimal from the typed text, and E29's rounding of it too; the test runs every tie on the
two places that the record's group shifts give, so it does not depend on which of them the
program's arithmetic happens to land below."""

from __future__ import annotations

import contextlib
import io
import json
import math
from decimal import ROUND_HALF_EVEN, Decimal
from pathlib import Path

import numpy as np
import pytest

from app.main import main

ROOT = Path(__file__).resolve().parents[2]
SAMPLES = ROOT / "resources" / "samples"
TARGETS_DEG = np.linspace(15.0, 345.0, 12)
OPTIONS = ["--target-unit", "deg", "--deviation-unit", "arcsec", "--misalignment-u", "0.001",
           "--reference-resolution", "0.01", "--temperature-u", "0.001", "--language", "en",
           "--json"]


def _rows() -> list[list[str]]:
    """A rotary axis sent to 12 targets in 5 runs each way: a once-round error of 4″, a
    reversal of ±0.3″ and a repeatability of 0.2″, every reading typed to 0.001″."""
    rng = np.random.default_rng(7307)
    curve = 4.0 * np.sin(np.radians(TARGETS_DEG) + 0.7)
    rows = []
    for run in range(1, 6):
        for sign, d in (("+", 1.0), ("-", -1.0)):
            for i, target in enumerate(TARGETS_DEG):
                rows.append([f"{target:.4f}", str(run), sign,
                             f"{curve[i] + 0.3 * d + 0.2 * rng.standard_normal():.3f}"])
    return rows


def _exact_half_range(rows: list[list[str]]) -> Decimal:
    """E/2 of the typed readings: half the spread of the means at each target and way."""
    groups: dict[tuple[str, str], list[Decimal]] = {}
    for target, _, sign, reading in rows:
        groups.setdefault((target, sign), []).append(Decimal(reading))
    means = [sum(v, Decimal(0)) / len(v) for v in groups.values()]
    return ((max(means) - min(means)) / 2).normalize()


def _shifted(rows, shift: Decimal) -> list[list[str]]:
    """The first reading of the highest mean's group raised by ``shift`` (typed to 0.001″:
    E/2 moves by a tenth of it)."""
    groups: dict[tuple[str, str], list[Decimal]] = {}
    for target, _, sign, reading in rows:
        groups.setdefault((target, sign), []).append(Decimal(reading))
    top = max(groups, key=lambda k: sum(groups[k]))
    first = next(i for i, (t, _, s, _) in enumerate(rows) if (t, s) == top)
    return [[t, r, s, str(Decimal(x) + shift) if i == first else x]
            for i, (t, r, s, x) in enumerate(rows)]


def _ties(places: int, most: int = 5) -> list[tuple[Decimal, list[list[str]]]]:
    """The first ``most`` shifts of 0.001 … 0.5″ whose exact E/2 ends in a 5 just past
    ``places``."""
    base = _rows()
    found = []
    for k in range(1, 501):
        rows = _shifted(base, Decimal(k) / 1000)
        h = _exact_half_range(rows)
        sign, digits, exponent = h.as_tuple()
        if exponent == -(places + 1) and digits[-1] == 5:
            found.append((h, rows))
    return found[:most]


def _decide(tmp_path: Path, rows, tolerance: str) -> dict:
    readings = tmp_path / "axis.csv"
    readings.write_text("target,run,direction,deviation\n"
                        + "".join(",".join(r) + "\n" for r in rows), encoding="utf-8")
    details = json.loads((SAMPLES / "certificate_positioning.json").read_text("utf-8"))
    details.update(example=False, decision_rule="simple", decision_quantity="half_range",
                   tolerance_unit="arcsec",
                   standards=[{"description": "laser calibrator", "serial": "S-1",
                               "certificate_no": "C-1", "uncertainty": 1.0,
                               "uncertainty_unit": "arcsec", "basis": "U95",
                               "applies_to": "angle"}])
    meta = tmp_path / "details.json"
    # T typed as the lab types it: its digits as they stand
    meta.write_text(json.dumps({**details, "tolerance": tolerance}), "utf-8")
    said, told = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(said), contextlib.redirect_stderr(told):
        assert main(["analyze", "positioning", str(readings), "--metadata", str(meta),
                     *OPTIONS]) == 0, said.getvalue() + told.getvalue()
    text = said.getvalue()
    return json.loads(text[text.index("{"):])["decided_quantity"]


@pytest.mark.parametrize("places", [2, 3])
def test_an_exact_tie_is_compared_as_e29_rounds_it(tmp_path, monkeypatch, places):
    """T typed to ``places`` decimals, the tie's digits below it (5.07 for 5.075): E29 rounds
    the tie to the even digit, so an odd last digit fails and an even one passes, whichever
    side of the tie the float lies on."""
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    ties = _ties(places)
    assert len(ties) >= 4
    for exact, rows in ties:
        step = Decimal(1).scaleb(-places)
        t = exact.quantize(step, rounding="ROUND_DOWN")
        decided = _decide(tmp_path, rows, f"{t:.{places}f}")
        value = float(decided["value"])
        # the program's figure is the tie computed in binary, a few ulps off at most
        assert math.isclose(value, float(exact), rel_tol=1e-12), (value, exact)
        compared = decided["compared_with_tolerance"]
        decimals = compared["decimals"]
        assert decimals >= places
        e29 = exact.quantize(Decimal(1).scaleb(-decimals), rounding=ROUND_HALF_EVEN)
        assert Decimal(repr(compared["value"])) == e29, (exact, repr(value), compared)
        assert decided["verdict"] == ("pass" if e29 <= t else "fail"), (exact, repr(value))
