"""Figures whose coverage interval is withheld (two runs: day 68, finding 5) are printed to
the decimal of two significant digits of the interval their reason quotes — the figure's own
scatter — on the certificate, in the command line's summary and in the window's verdict line
alike: not "A 19.866″ —" on the certificate beside the window's "A = 20″". The JSON keeps the
full number. The axis is simulated here from first principles (this file's generator
imports nothing from the code it checks).
"""

from __future__ import annotations

import json
import math
import re

import numpy as np
import pytest

from tests.repeatability_rig import iso230_rows


def _axis(rng, runs: int = 2, targets: int = 9, noise: float = 0.8):
    """An ISO 230-2 test of a rotary axis, x = f(P) ± b/2 + σ z at every approach, each run up
    through the targets and back down. Returns (rows, readings by (target, direction))."""
    angles = np.linspace(0.0, 360.0, targets, endpoint=False)
    f = 4.0 * np.sin(np.radians(angles)) + 1.5 * np.cos(np.radians(2 * angles))
    mu = {"+": f + 1.0, "-": f - 1.0}
    return iso230_rows(angles, mu, runs, noise, rng)


def _accuracy(readings) -> float:
    """ISO 230-2 A: max(x̄ + 2s) − min(x̄ − 2s) over every target and direction."""
    ends = [(np.mean(v) + 2 * np.std(v, ddof=1), np.mean(v) - 2 * np.std(v, ddof=1))
            for v in readings.values()]
    return max(e[0] for e in ends) - min(e[1] for e in ends)


def _decimals_of(low: float, high: float) -> int:
    """Two significant digits of the half-width of [low, high] (GUM 7.2.6)."""
    half = 0.5 * (high - low)
    return max(0, 1 - math.floor(math.log10(half)))


def _quoted(text: str, figure: str) -> tuple[float, float]:
    m = re.search(rf"No coverage interval is given for {figure}: .*? would be "
                  r"([\d.]+)\S* … ([\d.]+)", text)
    assert m, text
    return float(m.group(1)), float(m.group(2))


@pytest.fixture
def record(tmp_path):
    rows, readings = _axis(np.random.default_rng(6805))
    csv = tmp_path / "two_runs.csv"
    csv.write_text("target,run,direction,deviation\n" + "".join(
        f"{a},{r},{d},{x}\n" for a, r, d, x, _ in rows), encoding="utf-8")
    return rows, readings, csv


def test_a_withheld_figure_prints_to_its_quoted_intervals_decimal(record, capsys):
    from app.main import main
    from models.certificate.metadata import CertificateMetadata
    from models.positioning.analysis import POSITIONING
    from models.positioning.report import positioning_certificate
    from models.readings.sheet import ReadingsSheet

    rows, readings, csv = record
    a = _accuracy(readings)
    settings = POSITIONING.settings_with_defaults({})
    result = POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, rows).parse(), settings)
    assert result.iso.figures["A"] == pytest.approx(a, abs=1e-9)
    document = positioning_certificate(result, CertificateMetadata(
        tolerance=15.0, tolerance_unit="arcsec", decision_quantity="points"))
    # the certificate: A's row has no interval, its figure to the quoted interval's decimal
    row = next(r for r in document.statistics.rows if str(r[0]).startswith("A:"))
    # (the place said beside it: assessment 78 L1, test_withheld_figure_rounding_said)
    assert str(row[2]).startswith("— (withheld; value rounded to ")
    d = _decimals_of(*_quoted(" ".join(str(s) for s in document.statements), "A"))
    assert str(row[1]) == f"{a:.{d}f}\"", row
    assert getattr(row[1], "exact", None) == pytest.approx(a, abs=1e-9)  # the DCC's
    # the command line's summary and the window's verdict line: the readings' own interval
    assert main(["analyze", "positioning", str(csv)]) == 0
    out = capsys.readouterr().out
    d_window = _decimals_of(*_quoted(out, "A"))
    assert f"A = {a:.{d_window}f}\"" in out
    assert f"A = {a:.{d_window}f}\"" in str(POSITIONING.verdict(result))
    assert d_window < 3 and d < 3  # not the 0.001 of a figure known to the last digit
    # the JSON keeps the full number
    assert main(["analyze", "positioning", str(csv), "--json"]) == 0
    figures = json.loads(capsys.readouterr().out)
    found = [v for k, v in _walk(figures) if k == "A" and isinstance(v, dict)]
    assert found and found[0]["value"] == pytest.approx(a, abs=1e-9)


def _walk(node):
    if isinstance(node, dict):
        for k, v in node.items():
            yield k, v
            yield from _walk(v)
    elif isinstance(node, list):
        for v in node:
            yield from _walk(v)
