"""A theodolite run of two passes: R, R↑, R↓ (and A, A↑, A↓) have no coverage interval, and
the certificate prints each to the decimal of the interval its reason quotes — the figure's
own scatter — not to 0.01″ ("R_up 4.24″" beside an interval 0″ … 443″ withheld: day 68,
finding 5); the DCC keeps the full number. The passes are simulated from first principles
(tests/repeatability_rig.py: a mirror on a tilted axis, read with pointing noise)."""

from __future__ import annotations

import json
import math
import re

import numpy as np

from app.main import main
from tests.repeatability_rig import theodolite_passes_csv


def _decimals_of(low: float, high: float) -> int:
    """Two significant digits of the half-width of [low, high] (GUM 7.2.6)."""
    return max(0, 1 - math.floor(math.log10(0.5 * (high - low))))


def test_two_passes_withheld_figures_print_to_their_quoted_intervals_decimal(tmp_path, capsys):
    from models.certificate.metadata import CertificateMetadata
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.theodolite.analysis import THEODOLITE
    from models.theodolite.report import theodolite_certificate

    text, _ = theodolite_passes_csv("varying", 13, 2, 0.3, np.random.default_rng(6804))
    csv = tmp_path / "passes2.csv"
    csv.write_text(text, encoding="utf-8")
    assert main(["analyze", "theodolite", str(csv), "--json"]) == 0
    figures = json.loads(capsys.readouterr().out)["iso230_2_figures"]
    rows = map_columns(read_table(csv), THEODOLITE.columns)
    result = THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, rows).parse(),
                                THEODOLITE.settings_with_defaults({}))
    document = theodolite_certificate(result, CertificateMetadata())
    checked = 0
    for row in document.statistics.rows:
        m = re.search(r"would be ([\d.]+)\S* … ([\d.]+)", str(row[-1]))
        if not str(row[0]).startswith("ISO 230-2 ") or m is None:
            continue
        key = str(row[0]).removeprefix("ISO 230-2 ")
        d = _decimals_of(float(m.group(1)), float(m.group(2)))
        value = figures[key]["value"]  # the JSON's full number
        assert str(row[1]) == f"{value:.{d}f}\"", (row, d)
        assert getattr(row[1], "exact", None) == value
        checked += 1
    assert checked >= 3
