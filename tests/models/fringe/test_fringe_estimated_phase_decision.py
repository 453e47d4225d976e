"""What an estimated phase and a stated ADC can and cannot support in the decision (#39).

The signals come from tests/fringe_signal_simulator.py (first principles: the true phase,
the two channels with their harmonics, noise and an ADC's rounding); the product is run as
a user runs it, through ``anglebench analyze fringe --json``.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from app.main import main
from tests.fringe_signal_simulator import Head, true_interpolation_error

pytestmark = pytest.mark.slow  # each case analyses a record and decides it by Monte Carlo

LINES = 16384  # a period of 79.1" of shaft angle
PERIOD_ARCSEC = 1_296_000 / LINES


def _record(path, head: Head, theta: np.ndarray, rng, lsb_v: float = 0.0,
            with_theta: bool = False) -> None:
    u_a, u_b = head.signals(theta, rng)
    if lsb_v:
        u_a, u_b = np.round(u_a / lsb_v) * lsb_v, np.round(u_b / lsb_v) * lsb_v
    header = "u_sin,u_cos" + (",theta_deg" if with_theta else "")
    rows = [f"{a:.9f},{b:.9f}" + (f",{math.degrees(t):.9f}" if with_theta else "")
            for a, b, t in zip(u_a, u_b, theta, strict=True)]
    path.write_text(header + "\n" + "\n".join(rows) + "\n")


def _decided(capsys, tmp_path, record, *options, whole: bool = False) -> dict:
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps({"tolerance": 2.0, "tolerance_unit": "arcsec",
                                "decision_rule": "guarded", "decision_quantity": "half_range",
                                "standards": [{"description": "angle reference",
                                               "uncertainty": 0.02, "uncertainty_unit": "arcsec",
                                               "basis": "U95"}]}))
    code = main(["analyze", "fringe", str(record), "--json", "--metadata", str(meta),
                 "--lines-per-rev", str(LINES), "--language", "en", *options])
    out = capsys.readouterr()
    assert code == 0, out.err
    data = json.loads(out.out)
    return data if whole else data["decided_quantity"]


def _true_half_range(head: Head) -> float:
    theta = np.arange(8192) * (2 * math.pi / 8192)
    clean = Head(head.peak_a, head.peak_b, head.quadrature_deg, head.offset_a, head.offset_b,
                 head.harmonics)
    u_a, u_b = clean.signals(theta)
    error = true_interpolation_error(np.arctan2(u_a, u_b), theta)
    return 0.5 * float(np.ptp(error)) / (2 * math.pi) * PERIOD_ARCSEC


def test_an_estimated_phase_states_no_interval_and_no_conformity_whatever_is_stated(
        capsys, tmp_path):
    """3rd and 5th harmonics of 0.4 % and 0.3 % (the same distortion of the grating in both
    channels): without a phase reference part of their distortion leaves the figure round.
    An audit found the interval printed missing the truth in 14 of 15 such records, with
    "pass" printed once every ADC figure and a phase U of 0.2° were stated."""
    head = Head(peak_a=0.5, peak_b=0.49, quadrature_deg=1.5, offset_a=0.004, offset_b=-0.006,
                harmonics={3: (0.004, 0.4), 5: (0.003, 1.3)}, noise=0.0003)
    rng = np.random.default_rng(11)
    steps = 2 * math.pi / 128 * (1.0 + 0.15 * np.sin(np.arange(16 * 128) / 40.0))
    theta = 0.7 + np.concatenate([[0.0], np.cumsum(steps[:-1])])  # the speed wanders ±15 %
    record = tmp_path / "estimated.csv"
    _record(record, head, theta, rng)
    data = _decided(capsys, tmp_path, record, "--phase-reference-u", "0.2",
                    "--adc-lsb-mv", "0.01", "--adc-offset-u-mv", "0.1",
                    "--adc-gain-u-pct", "0.05", "--adc-linearity-mv", "0.02", whole=True)
    # no U per sample either (it covered 15-19 % of the samples in the audit's records)
    assert data["expanded_uncertainty_raw_error_arcsec"] is None
    assert "estimated from the signals" in data["uncertainty_withheld"]
    decided = data["decided_quantity"]
    assert decided["interval_low"] is None and decided["interval_high"] is None
    assert decided["verdict"] is None and decided["probability_conforming"] is None
    assert decided["coverage_probability"] is None  # no interval, no probability of one
    assert "estimated from the signals" in decided["reason"]
    assert decided["value"] > 0.0  # the half range the signals show, stated as measured
    # with the true phase given, the same signals are decided, and the interval holds it
    given = tmp_path / "given.csv"
    _record(given, head, theta, np.random.default_rng(11), with_theta=True)
    decided = _decided(capsys, tmp_path, given)
    truth = _true_half_range(head)
    assert decided["interval_low"] <= truth <= decided["interval_high"]


def test_a_stated_adc_rounding_and_linearity_do_not_lower_the_decided_value(capsys, tmp_path):
    """Drawn at every phase of the model's curve on their own, the ADC's quantisation and
    linearity were taken for noise and the decided value lowered by the widening they would
    give a measured range (an audit: an LSB of 0.61 mV, 0.005"; a linearity of 0.5 mV,
    0.009"; the interval then missed the truth in 23 of 60 and 15 of 15 records). They are
    one pattern for the whole record: the value stays, the interval widens."""
    head = Head(peak_a=0.5, peak_b=0.485, quadrature_deg=2.0, offset_a=0.01, offset_b=-0.008,
                noise=0.003)
    theta = np.arange(16 * 128) * (2 * math.pi / 128) + 0.3
    record = tmp_path / "adc.csv"
    _record(record, head, theta, np.random.default_rng(5), lsb_v=0.00061, with_theta=True)
    bare = _decided(capsys, tmp_path, record)
    stated = _decided(capsys, tmp_path, record, "--adc-lsb-mv", "0.61",
                      "--adc-linearity-mv", "0.5")
    assert stated["measured"] == pytest.approx(bare["measured"], rel=1e-9)
    assert stated["value"] == pytest.approx(bare["value"], abs=1e-3)  # 0.010" lower before
    assert stated["interval_high"] > bare["interval_high"] + 0.005
    assert stated["interval_low"] <= bare["interval_low"]
    truth = _true_half_range(head)
    assert stated["interval_low"] <= truth <= stated["interval_high"]


def _third_harmonic_record(path, with_theta: bool = False) -> None:
    """8 periods of 64 samples from a head with a 3rd harmonic of 0.4 % (the same signals
    with or without the θ column)."""
    head = Head(peak_a=0.5, peak_b=0.49, quadrature_deg=1.5, offset_a=0.004, offset_b=-0.006,
                harmonics={3: (0.004, 0.4)}, noise=0.0003)
    theta = 0.3 + np.arange(8 * 64) * (2 * math.pi / 64)
    _record(path, head, theta, np.random.default_rng(5), with_theta=with_theta)


def test_an_estimated_phase_states_no_u_on_the_certificate_the_results_or_the_dcc(
        capsys, tmp_path):
    """The JSON withheld U per sample; the certificate, its results workbook and its DCC
    printed it (0.012" on the bundled sample's signals, a U the audit's records showed to
    cover 15-19 % of the samples). Now none states one: the PDF says why and gives the
    inputs evaluated as a lower bound only, the workbook's U column is gone, the DCC's errors
    carry no uncertainty; the decided half range's reason quotes the half range measured."""
    from openpyxl import load_workbook

    from tests.pdf_text import pdf_text

    record = tmp_path / "estimated.csv"
    _third_harmonic_record(record)
    meta = tmp_path / "meta.json"
    details = json.loads((Path(__file__).parents[3] / "resources" / "samples"
                          / "certificate_fringe.json").read_text(encoding="utf-8"))
    details.update(tolerance=2.0, decision_quantity="half_range")  # the bundled specimen's
    meta.write_text(json.dumps(details))
    pdf, dcc, xlsx = tmp_path / "c.pdf", tmp_path / "c.xml", tmp_path / "r.xlsx"
    code = main(["analyze", "fringe", str(record), "--metadata", str(meta), "--lines-per-rev",
                 str(LINES), "--language", "en", "--certificate", str(pdf), "--dcc", str(dcc),
                 "--results", str(xlsx), "--json"])
    out = capsys.readouterr()
    assert code == 0, out.err
    data = json.loads(out.out[out.out.index("{"):])
    measured = data["decided_quantity"]["value"]
    text = pdf_text(pdf.read_bytes())  # pdfium: ~0.5 s of CPU less than pypdf's
    assert "No expanded uncertainty is stated for the results" in text
    assert "a lower bound of U, not U" in text
    assert "No U is stated per sample" in text
    assert "Expanded uncertainty U not stated" in text
    assert f"as measured, half the peak-to-peak is {measured:.3g}\"" in text
    assert "Compensated error in the first period (no U stated)" in text
    xml = dcc.read_text(encoding="utf-8")
    assert "U of the inputs evaluated only (incomplete: a lower bound, not U)" in xml
    errors = xml[xml.index("anglebench_rawError\">"):]
    errors = errors[:errors.index("</dcc:quantity>")]
    assert "expandedMU" not in errors and "realListXMLList" in errors
    book = load_workbook(xlsx, read_only=True)
    headers = [str(c) for sheet in book.worksheets for row in sheet.iter_rows(max_row=3,
               values_only=True) for c in row if c is not None]
    assert not any(h.startswith("expanded_uncertainty") for h in headers), headers
    # with the phase given, the same record states U everywhere again
    given = tmp_path / "given.csv"
    _third_harmonic_record(given, with_theta=True)
    code = main(["analyze", "fringe", str(given), "--metadata", str(meta), "--lines-per-rev",
                 str(LINES), "--language", "en", "--certificate", str(pdf)])
    capsys.readouterr()
    assert code == 0
    text = pdf_text(pdf.read_bytes())
    assert "No expanded uncertainty is stated" not in text
    assert "The expanded uncertainty of the error is U =" in text


def test_an_estimated_phase_decided_point_by_point_states_no_interval(capsys, tmp_path):
    """The points quantity (every sample against ±T with its own U): with no U stated, the
    decided value (the largest |error|) has no interval either; a reviewer found ±U of the
    incomplete budget beside it on the certificate and in the JSON."""
    record = tmp_path / "estimated.csv"
    _third_harmonic_record(record)
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps({"tolerance": 2.0, "tolerance_unit": "arcsec",
                                "decision_rule": "guarded", "decision_quantity": "points"}))
    code = main(["analyze", "fringe", str(record), "--json", "--metadata", str(meta),
                 "--lines-per-rev", str(LINES), "--language", "en"])
    out = capsys.readouterr()
    assert code == 0, out.err
    decided = json.loads(out.out)["decided_quantity"]
    assert decided["value"] > 0.0 and decided["verdict"] is None
    assert decided["interval_low"] is None and decided["interval_high"] is None
