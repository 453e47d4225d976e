"""ISO 230-2 R and A of a theodolite run with passes are of the axis as read with this
theodolite: the standard deviations over the passes hold its pointing noise, and the
certificate, its JSON and the summary say how much (an audit, 0.8.15: a perfectly
repeatable axis read with 0.5″ pointing got R ≈ 3″, its interval [2.3, 4.3]″ called the
true figure's, where the axis' own R is 0).

The rig is tests/theodolite_passes_simulator.py (numpy only): a perfectly repeatable axis
(axis_noise = 0), the theodolite pointing with σ new in every reading (azimuth and
elevation). What its pointing alone gives: s_i ≈ σ at every θ, so R↑ = R↓ = 4σ and R = 4σ
with no reversal.
"""

from __future__ import annotations

import json
import re

import numpy as np
import pytest

from tests.theodolite_passes_simulator import passes_record
from tests.theodolite_run_json import run_json

SIGMA = 0.5  # the theodolite's pointing noise per reading, arcsec


def _figures_in(text: str) -> list[float]:
    """The arcsec figures of a text (a number followed by ″ or ")."""
    return [float(x) for x in re.findall(r"(\d+(?:\.\d+)?)(?:\"|″)", text)]


def _record(tmp_path):
    record = tmp_path / "repeatable.csv"
    truth = passes_record(record, np.random.default_rng(66), 5, SIGMA, 0.0, axis_noise=0.0)
    assert truth["R"] == pytest.approx(4 * SIGMA)  # the simulator's R holds σ (as ISO reads)
    return record


def _said_right(text: str) -> None:
    """The pointing noise stated within 20 % of σ, and the R it alone gives within 20 % of
    4σ (the R of a perfectly repeatable axis read with it)."""
    figures = _figures_in(text)
    assert any(abs(f - SIGMA) <= 0.2 * SIGMA for f in figures), text
    assert any(abs(f - 4 * SIGMA) <= 0.2 * 4 * SIGMA for f in figures), text


def test_the_json_states_the_pointing_noise_and_the_r_it_alone_gives(capsys, tmp_path):
    data = run_json(capsys, tmp_path, _record(tmp_path), SIGMA)
    pointing = data["iso230_2_pointing"]
    assert pointing["pointing_per_reading_arcsec"] == pytest.approx(SIGMA, rel=0.2)
    assert pointing["R_from_pointing_arcsec"] == pytest.approx(4 * SIGMA, rel=0.2)
    assert pointing["pointing_dof"] >= 20
    # the measured R is all the theodolite's pointing (the axis repeats perfectly), and more
    # than 4σ: the largest over 13 θ of noisy s (3.0″ here)
    assert data["iso230_2_figures"]["R"]["value"] >= pointing["R_from_pointing_arcsec"]
    note = data["iso230_2_pointing_note"]
    _said_right(note)
    assert "pointing noise" in note and "as read with this theodolite" in note
    # the interval of R and A is no longer called the true figure's unqualified
    assert "include the instrument's own repeatability" in data["iso230_2_figures_note"]


def test_the_json_in_chinese_states_the_same_figures(capsys, tmp_path):
    from app.main import main

    record = _record(tmp_path)
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps({"standards": [{
        "description": "Autocollimating theodolite", "uncertainty": SIGMA,
        "uncertainty_unit": "arcsec", "basis": "u", "applies_to": "reading"}]}))
    code = main(["analyze", "theodolite", str(record), "--json", "--metadata", str(meta),
                 "--language", "zh_CN"])
    out = capsys.readouterr()
    assert code == 0, out.err
    _said_right(json.loads(out.out)["iso230_2_pointing_note"])


@pytest.mark.parametrize("language", ["en", "zh_CN"])
def test_the_certificate_states_the_pointing_noise_in_r_and_a(tmp_path, language):
    from models.certificate.metadata import CertificateMetadata, ReferenceStandard
    from models.messages import in_language, translator
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.theodolite.analysis import THEODOLITE
    from models.theodolite.report import theodolite_certificate

    rows = map_columns(read_table(_record(tmp_path)), THEODOLITE.columns)
    result = THEODOLITE.analyze(ReadingsSheet(THEODOLITE.columns, rows).parse(),
                                THEODOLITE.settings_with_defaults({}))
    meta = CertificateMetadata(standards=(ReferenceStandard(
        "Autocollimating theodolite", uncertainty=SIGMA, basis="u"),))
    document = theodolite_certificate(result, meta)
    said = [in_language(s, translator(language)) for s in document.statements]
    english = [s for s in document.statements if "R ≈" in str(s)]
    assert len(english) == 1, document.statements
    _said_right(in_language(english[0], translator(language)))
    assert sum(1 for s in said if _figures_in(s) and "ν" in s) >= 1
    summary = THEODOLITE.summary(result)
    _said_right(summary.split("ISO 230-2 R and A")[1])
