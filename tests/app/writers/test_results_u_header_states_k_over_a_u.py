"""A header of the results workbook states a coverage factor only over a column that holds
a U (review finding: with the fringe's phase estimated from the signals the 'Parameters'
sheet was headed "U (k = 2.02, ν = 153)" over cells that all said "no U (phase estimated
from the signals)"). Checked where a U can be withheld: the fringe with its phase estimated
(and, beside it, with N equal steps, where the U and its k are stated), the theodolite of two
passes (the repeatability figures' intervals withheld), and the cross-calibration's polygon
certificate with the encoder's U withheld (no closure reading, no drift bound).

The readings come from first-principles rigs (tests/fringe_adc_rig.py,
tests/repeatability_rig.py, tests/crosscal_simulator.py), nothing from models/."""

from __future__ import annotations

import io
import re

import numpy as np
import pytest
from openpyxl import load_workbook

from app.writers.results_export import results_xlsx_bytes
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ParsedReadings, ReadingsSheet
from models.registry import KINDS
from tests.app.writers.test_certificate_export import map_columns, read_table
from tests.crosscal_simulator import Bench
from tests.fringe_adc_rig import Adc, Head, equal_steps, random_steps
from tests.repeatability_rig import theodolite_passes_csv

pytestmark = pytest.mark.slow  # (a certificate each, 0.2–0.5 s)

META = CertificateMetadata.from_dict({"certificate_number": "X", "lab_name": "L"})
K_STATED = re.compile(r"\bk\s*=")
ADC = Adc(offset_u_v=0.001, gain_u=0.002, noise_v=0.0003, lsb_v=0.00025)


def _fringe(estimated: bool):
    rng = np.random.default_rng(8)
    theta = random_steps(160, rng) if estimated else equal_steps(192, 64)
    u_sin, u_cos = ADC.digitise(*Head().clean(theta), rng)
    parsed = ParsedReadings({"u_sin": u_sin, "u_cos": u_cos,
                             "theta_deg": np.full(u_sin.size, np.nan)}, np.arange(u_sin.size))
    kind = KINDS["fringe"]
    result = kind.analyze(parsed, kind.settings_with_defaults(
        {"lines_per_rev": 16384, "samples_per_period": 0 if estimated else 64,
         "adc_offset_u_mv": 1.0, "adc_gain_u_pct": 0.2, "adc_lsb_mv": 0.25}))
    assert result.phase_source == ("estimated" if estimated else "samples_per_period")
    return kind.certificate(result, META)


def _theodolite_two_passes(tmp_path):
    text, _ = theodolite_passes_csv("varying", 13, 2, 0.3, np.random.default_rng(6804))
    csv = tmp_path / "passes2.csv"
    csv.write_text(text, encoding="utf-8")
    kind = KINDS["theodolite"]
    parsed = ReadingsSheet(kind.columns, map_columns(read_table(csv), kind.columns)).parse()
    return kind.certificate(kind.analyze(parsed, kind.settings_with_defaults({})), META)


def _crosscal_encoder_withheld():
    n = 12
    harmonics = {1: (0.8, 0.3), 2: (0.6, 1.1), 3: (0.4, 2.0)}
    bench = Bench(n, harmonics, np.random.default_rng(804).normal(0.0, 0.5, n),
                  rng=np.random.default_rng(4), noise_arcsec=0.05, drift_arcsec=0.3,
                  drift_common=True)
    rows = bench.rows((0, 1, 5), closure=False)
    kind = KINDS["crosscal"]
    text = [[str(j), str(i), f"{a:.9f}", f"{x:.6f}", ""] for j, i, a, x in rows]
    parsed = ReadingsSheet(kind.columns, text).parse()
    # (no vertical readings: the default tilt bound, 0 being refused where the tilt is not
    # identified; what is checked here is the encoder's U withheld, which no bound changes)
    result = kind.analyze(parsed, kind.settings_with_defaults({"ac_scale_pct": 0.0}))
    assert result.encoder_u_withheld is not None
    return kind.certificate(result, META)


def _sheets(document) -> dict[str, list[tuple]]:
    book = load_workbook(io.BytesIO(results_xlsx_bytes(document)))
    return {name: list(book[name].iter_rows(values_only=True)) for name in book.sheetnames}


def _k_over_no_u(sheets: dict[str, list[tuple]]) -> list[str]:
    """Each header cell that states a k over a column with no number in it."""
    wrong = []
    for name, rows in sheets.items():
        if name == "Certificate" or not rows:
            continue
        for j, head in enumerate(rows[0]):
            # (a column of units, "U (k = 2.01, ν ≥ 185): unit", is the U column's own)
            if isinstance(head, str) and K_STATED.search(head) and not head.endswith(": unit"):
                cells = [r[j] for r in rows[1:] if j < len(r)]
                if not any(isinstance(c, (int, float)) and np.isfinite(c) for c in cells):
                    wrong.append(f"{name}: {head!r} over {sorted(set(map(str, cells)))[:3]}")
    return wrong


def test_fringe_estimated_phase_heads_its_u_column_without_a_k():
    sheets = _sheets(_fringe(estimated=True))
    header, *rows = sheets["Parameters"]
    u_column = len(header) - 1
    held = [r[u_column] for r in rows if isinstance(r[u_column], str) and "no U" in r[u_column]]
    assert held, rows  # the parameters are there, each without a U
    assert _k_over_no_u(sheets) == []
    assert header[u_column] == "U"
    assert any("no U is stated" in str(r[0]) for r in rows)  # the reason, in the note


def test_fringe_equal_steps_keeps_its_k_over_its_u():
    sheets = _sheets(_fringe(estimated=False))
    header = sheets["Parameters"][0]
    assert any(isinstance(h, str) and K_STATED.search(h) for h in header), header
    assert _k_over_no_u(sheets) == []


@pytest.mark.parametrize("case", ["theodolite_two_passes", "crosscal_encoder_withheld"])
def test_no_header_states_a_k_over_cells_without_a_u(case, tmp_path):
    document = (_theodolite_two_passes(tmp_path) if case == "theodolite_two_passes"
                else _crosscal_encoder_withheld())
    assert _k_over_no_u(_sheets(document)) == []
