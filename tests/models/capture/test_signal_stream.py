"""A two-channel signal stream's lines: two numbers a line or a user's pattern; bad lines
refused with a reason and counted, never raised out of a block."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.capture.errors import FrameError
from models.capture.signal_stream import SignalLineParser

finite = st.floats(allow_nan=False, allow_infinity=False, width=64)
separators = st.sampled_from([",", ", ", " ,", " ", "  ", "\t", "\t,\t", " \t "])


def test_two_numbers_with_any_of_the_separators():
    parser = SignalLineParser()
    for line in (b"0.512,-0.118", b"0.512 -0.118", b"0.512\t-0.118", b"  0.512 , -0.118  ",
                 b"5.12e-1,-1.18E-1", b"+.512,-.118"):
        assert parser.parse(line) == pytest.approx((0.512, -0.118), rel=1e-15)


@pytest.mark.parametrize("line", [b"u_sin,u_cos", b"0.5", b"0.5,0.2,0.1", b"0.5,,0.2",
                                  b"nan,0.1", b"0.1,inf", b"1e999,0", b"\xff\xfe,1",
                                  b"0,5;0,2", b""])
def test_what_is_not_a_sample_is_refused_with_a_reason(line):
    with pytest.raises(FrameError) as info:
        SignalLineParser().parse(line)
    assert str(info.value)


def test_a_users_pattern_with_named_groups_in_any_order():
    parser = SignalLineParser(r"t=\S+ B=(?P<cos>\S+) A=(?P<sin>\S+)")
    assert parser.parse(b"t=0.001 B=-0.25 A=0.75") == (0.75, -0.25)
    # a decimal comma in a user's field
    assert SignalLineParser(r"(?P<sin>\S+);(?P<cos>\S+)").parse(b"0,5;-0,2") == (0.5, -0.2)
    with pytest.raises(FrameError, match="does not match"):
        parser.parse(b"0.1,0.2")


@pytest.mark.parametrize("pattern", [r"(?P<sin>\S+)", r"(?P<cos>x", r"(\S+),(\S+)"])
def test_a_pattern_without_both_groups_is_refused_at_once(pattern):
    with pytest.raises(ValueError, match="pattern"):
        SignalLineParser(pattern)


def test_a_block_keeps_the_lines_order_and_counts_the_refused():
    parsed = SignalLineParser().parse_lines([b"1,2", b"garbage", b"3 4", b"\x00\x01", b"5\t6"])
    assert parsed.u_sin.tolist() == [1.0, 3.0, 5.0]
    assert parsed.u_cos.tolist() == [2.0, 4.0, 6.0]
    assert parsed.used.tolist() == [True, False, True, False, True]
    assert parsed.refused == 2 and len(parsed.reasons) == 2


@settings(max_examples=200, deadline=None)
@given(finite, finite, separators)
def test_any_finite_pair_written_reads_back_exactly(u_sin, u_cos, sep):
    line = f"{u_sin!r}{sep}{u_cos!r}".encode()
    assert SignalLineParser().parse(line) == (u_sin, u_cos)


@settings(max_examples=200, deadline=None)
@given(st.lists(st.one_of(st.binary(max_size=30),
                          st.tuples(finite, finite).map(lambda p: f"{p[0]!r},{p[1]!r}".encode())),
                max_size=40))
def test_any_block_parses_without_raising_and_accounts_for_every_line(lines):
    parser = SignalLineParser()
    parsed = parser.parse_lines(lines)
    assert parsed.used.size == len(lines)
    assert int(parsed.used.sum()) + parsed.refused == len(lines)
    assert parsed.u_sin.size == parsed.u_cos.size == int(parsed.used.sum())
    expected = [parser.parse(line) for line, ok in zip(lines, parsed.used, strict=True) if ok]
    assert np.array_equal(np.column_stack([parsed.u_sin, parsed.u_cos]).reshape(-1, 2),
                          np.array(expected, dtype=float).reshape(-1, 2))
    assert np.all(np.isfinite(parsed.u_sin)) and np.all(np.isfinite(parsed.u_cos))
