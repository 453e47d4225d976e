"""Interpolator look-up tables (#45): the quantised table, applied by an independent chip
model to first-principles signals, leaves the residual it predicted; refusals name what would
reach the residual asked for; the writers hold the codes."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from models.fringe.analysis import FRINGE
from models.fringe.interpolator_export import (
    table_c_header,
    table_csv,
    table_intel_hex,
    write_interpolator_table,
)
from models.fringe.interpolator_table import IC_TW8, TableRefused, chip_profile, design_table
from models.readings.sheet import ParsedReadings
from tests.fringe_signal_simulator import Head, chip_phase, equal_phase, ideal_terms

PER = 64
HEAD = Head(peak_a=0.5, peak_b=0.53, quadrature_deg=4.0, offset_a=0.03, offset_b=-0.02,
            harmonics={3: (0.02, 0.4), 5: (0.006, 1.1), 2: (0.004, -0.7)})


def _result(head: Head, periods: int = 16, seed: int = 0):
    theta = equal_phase(periods, PER)
    u_a, u_b = head.signals(theta, np.random.default_rng(seed))
    parsed = ParsedReadings({"u_sin": u_a, "u_cos": u_b,
                             "theta_deg": np.full(theta.size, np.nan)}, np.arange(theta.size))
    return FRINGE.analyze(parsed, {"samples_per_period": PER, "max_order": 5,
                                   "harmonics": "all"})


def _actual(head: Head, table, points: int = 100_003) -> tuple[float, float]:
    """The chip's residual on the head's true signals (fractions of a period): largest
    magnitude and RMS, mean removed."""
    theta = np.arange(points) * (2 * math.pi / points)
    u_a, u_b = ideal_terms(head, *Head(head.peak_a, head.peak_b, head.quadrature_deg,
                                       head.offset_a, head.offset_b, head.harmonics
                                       ).signals(theta), table.terms.applied)
    p = table.profile
    e = np.angle(np.exp(1j * (chip_phase(u_a, u_b, table.codes, table.lsb_period,
                                         p.interpolation, p.sign) - theta)))
    e -= np.mean(e)
    return float(np.max(np.abs(e))) / (2 * math.pi), float(np.sqrt(np.mean(e * e))) / (2 * math.pi)


PROFILES = [
    chip_profile("generic", 64, 8),
    chip_profile("generic", 256, 10, separate_terms=("offset", "gain")),
    chip_profile("generic", 1024, 12, separate_terms=("offset", "gain", "phase")),
    IC_TW8,
]


@pytest.mark.parametrize("profile", PROFILES, ids=lambda p: f"{p.key}-{p.entries}-{p.bits}")
def test_quantised_table_leaves_the_residual_it_predicted(profile):
    result = _result(HEAD)
    table = design_table(result, profile)
    worst, rms = _actual(HEAD, table)
    # noise-free: the fit is the head; only the grids differ (1e-3 of the residual; a step
    # table's largest error sits at a jump, which a grid of 1/65537 of a period meets to
    # within its spacing times the error's slope: 1e-6 of a period)
    assert worst == pytest.approx(table.residual.max_abs, rel=1e-3, abs=1e-6)
    assert rms == pytest.approx(table.residual.rms, rel=1e-3, abs=1e-8)
    assert table.residual.max_abs < 0.2 * table.residual_without.max_abs
    assert int(np.max(np.abs(table.codes))) <= profile.max_code
    # the quantisation moves each corrected phase by at most half an LSB, and their mean
    # (removed) by as much: at most one LSB more than the unquantised table leaves
    assert table.residual.max_abs <= table.residual_unquantised.max_abs + table.lsb_period


def test_noisy_record_prediction_within_the_fits_noise():
    # 0.5 mV noise on 0.5 V signals, 256 periods of 64 samples: each fitted coefficient is
    # off by σ·√(2/n)/A = 1.1e-5 rad of phase; ten of them (orders 1…5, two channels), the
    # largest over a period about three of their RSS: 1e-4 rad = 1.7e-5 of a period. The
    # table made from the fit leaves on the true head what it predicted, to within that.
    result = _result(Head(**{**HEAD.__dict__, "noise": 5e-4}), periods=256, seed=7)
    for profile in (chip_profile("generic", 256, 10), IC_TW8):
        table = design_table(result, profile)
        worst, rms = _actual(HEAD, table)
        assert worst == pytest.approx(table.residual.max_abs, abs=2e-5)
        assert rms == pytest.approx(table.residual.rms, abs=1e-5)


def test_ic_tw8_profile_as_read():
    assert (IC_TW8.entries, IC_TW8.bits, IC_TW8.max_code) == (64, 8, 127)
    assert IC_TW8.lsb_period * 360 * 43 == pytest.approx(3.78, abs=0.01)  # the sheet's example
    with pytest.raises(TableRefused, match="64"):
        chip_profile("ic-tw8", entries=128)


def test_refused_when_bits_too_few_naming_what_would():
    result = _result(HEAD)
    table = design_table(result, chip_profile("generic", 1024, 6))
    asked = table.residual_unquantised.max_abs * 1.5  # the entries reach it, 6 bits do not
    assert table.residual.max_abs > asked
    with pytest.raises(TableRefused) as refused:
        design_table(result, chip_profile("generic", 1024, 6), max_residual_period=asked)
    text = str(refused.value)
    assert "quantisation" in text and "1024 entries of" in text
    bits = int(re.search(r"1024 entries of (\d+) bits would", text).group(1))
    assert bits > 6
    assert design_table(result, chip_profile("generic", 1024, bits),
                        max_residual_period=asked).residual.max_abs <= asked


def test_refused_when_the_lsb_cannot_hold_the_table():
    with pytest.raises(TableRefused, match="LSB of at least .* bits, would hold it"):
        design_table(_result(HEAD), chip_profile("generic", 64, 8, lsb_period=1e-6))


def test_writers_hold_the_codes(tmp_path):
    result = _result(HEAD)
    table = design_table(result, chip_profile("generic", 64, 12))
    codes = table.codes.tolist()
    csv = table_csv(table, "head.csv", 79.1, "arcsec")
    rows = [line.split(",") for line in csv.splitlines() if not line.startswith("#")][1:]
    assert [int(r[2]) for r in rows] == codes
    assert "# source record: head.csv" in csv and "LSB:" in csv
    header = table_c_header(table, "head.csv", name="lut")
    body = re.search(r"const int16_t lut\[64\] = \{(.*?)\};", header, re.S).group(1)
    assert [int(v) for v in body.replace("\n", " ").split(",") if v.strip()] == codes
    assert "#define LUT_BITS 12" in header
    # Intel HEX: checksums, and the codes back as 2-byte two's complement
    data = bytearray()
    for line in table_intel_hex(table).split():
        raw = bytes.fromhex(line[1:])
        assert sum(raw) & 0xFF == 0
        if raw[3] == 0:
            data += raw[4:-1]
    assert [int.from_bytes(data[i:i + 2], "little", signed=True)
            for i in range(0, len(data), 2)] == codes
    for suffix in (".csv", ".h", ".hex"):
        write_interpolator_table(tmp_path / f"t{suffix}", table, "head.csv")
        assert (tmp_path / f"t{suffix}").stat().st_size > 0
    with pytest.raises(ValueError, match=".csv, .h"):
        write_interpolator_table(tmp_path / "t.bin", table)


# -- properties -------------------------------------------------------------------------------

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from models.fringe.interpolator_table import InterpolatorTable, Residual, SeparateTerms  # noqa: E402


@given(bits=st.integers(2, 16), codes=st.data())
def test_intel_hex_holds_any_codes(bits, codes):
    most = (1 << (bits - 1)) - 1
    values = codes.draw(st.lists(st.integers(-most, most), min_size=1, max_size=300))
    zero = Residual(0.0, 0.0, 0.0)
    table = InterpolatorTable(chip_profile("generic", 64, bits), np.array(values), 1e-4,
                              np.zeros(len(values)), SeparateTerms(), zero, zero, zero)
    width, data = (bits + 7) // 8, bytearray()
    for line in table_intel_hex(table).split():
        assert line.startswith(":")
        raw = bytes.fromhex(line[1:])
        assert raw[0] == len(raw) - 5 and sum(raw) & 0xFF == 0
        if raw[3] == 0:
            assert int.from_bytes(raw[1:3], "big") == len(data) % 65536
            data += raw[4:-1]
    assert [int.from_bytes(data[i:i + width], "little", signed=True)
            for i in range(0, len(data), width)] == values


@settings(max_examples=15, deadline=None)
@given(quad=st.floats(-8, 8), ratio=st.floats(0.85, 1.15), h3=st.floats(0, 0.03),
       c3=st.floats(-3, 3), k=st.integers(4, 9), bits=st.integers(6, 12),
       linear=st.booleans())
def test_any_head_table_within_an_lsb_of_the_entries_limit(quad, ratio, h3, c3, k, bits,
                                                           linear):
    head = Head(peak_a=0.5, peak_b=0.5 * ratio, quadrature_deg=quad, offset_a=0.01,
                harmonics={3: (h3, c3)})
    theta = np.arange(4096) * (2 * math.pi / 4096)
    from models.fringe.model import fit_channels

    fits = fit_channels(theta, list(head.signals(theta)), (1, 2, 3))
    profile = chip_profile("generic", 1 << k, bits)
    if linear:
        from dataclasses import replace

        profile = replace(profile, interpolation="linear")
    table = design_table(fits, profile)
    assert int(np.max(np.abs(table.codes))) <= profile.max_code
    assert table.residual.max_abs <= table.residual_unquantised.max_abs + table.lsb_period
    # a step table's largest error sits at a jump: each grid (65 537 and 100 003 phases a
    # period) meets it to within its spacing times the error's slope (≤ 0.2 here): 4e-6
    worst, rms = _actual(head, table)
    assert worst == pytest.approx(table.residual.max_abs, rel=2e-3, abs=4e-6)
