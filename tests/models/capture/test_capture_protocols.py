"""The instruments' protocols read from bytes: the ELCOMAT-kind autocollimator, Leica
GeoCOM and a line readout; the framing that survives line noise; the stability gate
and the Allan deviation with figures computed by hand."""

from __future__ import annotations

import contextlib
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from models.capture.allan import allan_deviation, last_even_run, octave_factors
from models.capture.autocollimator import (
    AutocollimatorFrame,
    DeviceInfo,
    command,
    parse_autocollimator_line,
)
from models.capture.errors import FrameError
from models.capture.framing import LineFramer
from models.capture.geocom import GET_ANGLE1, GET_ANGLE5, angles_of, parse_geocom_reply, request
from models.capture.line_readout import LineReadout
from models.capture.stability import StabilityGate, UnwrappedAngles

# ---------------------------------------------------------------- framing


def test_lines_end_at_cr_lf_or_both():
    framer = LineFramer()
    assert framer.feed(b"4 003 1.5 -2.25\r3 003 ") == [b"4 003 1.5 -2.25"]
    assert framer.feed(b"0.1 0.2\r%R1P,0,0:0\r\nx\n") == [b"3 003 0.1 0.2", b"%R1P,0,0:0", b"x"]


def test_an_endless_line_of_noise_is_dropped_and_the_next_line_read():
    framer = LineFramer(max_line=32)
    assert framer.feed(b"\xff" * 1000) == []
    assert framer.dropped == 1
    assert framer.feed(b"\xfe\xfe\r4 003 1 2\r") == [b"4 003 1 2"]


@pytest.mark.slow
@settings(max_examples=100, deadline=None)
@given(st.lists(st.binary(max_size=40), max_size=20), st.integers(1, 7))
def test_any_split_of_the_bytes_gives_the_same_lines(chunks, step):
    data = b"".join(chunks)
    whole = LineFramer().feed(data)
    framer = LineFramer()
    pieces = [line for i in range(0, len(data), step) for line in framer.feed(data[i:i + step])]
    assert pieces == whole


# ---------------------------------------------------------------- autocollimator


def test_the_commands_end_in_lf():
    assert command("single") == b"a\n" and command("stream") == b"A\n"
    assert command("stop") == b"s\n" and command("device") == b"d\n"
    assert command("single_relative") == b"r\n" and command("stream_relative") == b"R\n"


@pytest.mark.parametrize(("line", "x", "y"), [
    (b"4 003 12.34 -5.67", 12.34, -5.67),
    (b"3 003 -0.05 1000.25", -0.05, 1000.25),
    (b"4 001 12.34 -5.67", 12.34, None),   # y invalid
    (b"4 002 12.34 -5.67", None, -5.67),   # x invalid
    (b"3 000 12.34 -5.67", None, None),    # neither
    (b"  2 103 +1.0 -2e1  ", 1.0, -20.0),
])
def test_the_status_says_which_axes_are_values(line, x, y):
    frame = parse_autocollimator_line(line)
    assert isinstance(frame, AutocollimatorFrame)
    assert (frame.x_arcsec, frame.y_arcsec) == (x, y)
    assert frame.complete == (x is not None and y is not None)


def test_relative_and_absolute_codes():
    assert parse_autocollimator_line(b"2 003 1 1").relative
    assert parse_autocollimator_line(b"1 003 1 1").relative
    assert not parse_autocollimator_line(b"3 003 1 1").relative


def test_the_device_information_line():
    assert parse_autocollimator_line(b"8 12345 21 3 2019 300") == DeviceInfo(12345, 21, 3, 2019, 300)


@pytest.mark.parametrize("line", [b"", b"4 003 1.0", b"5 003 1 2", b"4 03 1 2", b"4 004 1 2",
                                  b"4 003 1 2 3", b"4 003 nan 2", b"4 003 1e999 2",
                                  b"\xff\xfe 003 1 2", b"4 003 1,5 2", b"%R1P,0,0:0,1,2"])
def test_anything_else_is_refused(line):
    with pytest.raises(FrameError):
        parse_autocollimator_line(line)


axis_value = st.floats(-2000, 2000, allow_nan=False).map(lambda v: round(v, 3))


@pytest.mark.slow
@settings(max_examples=150, deadline=None)
@given(st.sampled_from("1234"), st.sampled_from("0123"), axis_value, axis_value,
       st.lists(st.binary(max_size=30), max_size=4))
def test_a_frame_in_line_noise_is_read_exactly_and_an_invalid_axis_never(code, axes, x, y, noise):
    """Noise lines before and after a frame: the frame is read with its own figures, an
    axis its status marks invalid is never a value, and noise is refused, never read."""
    frame_bytes = f"{code} 00{axes} {x:.3f} {y:.3f}".encode()
    stream = b"\r".join(noise + [frame_bytes] + noise) + b"\r"
    frames = []
    for line in LineFramer().feed(stream):
        with contextlib.suppress(FrameError):
            frames.append(parse_autocollimator_line(line))
    mine = [f for f in frames if isinstance(f, AutocollimatorFrame) and f.status == f"00{axes}"
            and f.code == code]
    expected = AutocollimatorFrame(code, f"00{axes}", x if axes in "13" else None,
                                   y if axes in "23" else None)
    assert expected in mine, stream


@settings(max_examples=150, deadline=None)
@given(st.binary(max_size=80))
def test_garbage_is_refused_or_read_never_crashes(data):
    for line in LineFramer().feed(data + b"\r"):
        try:
            frame = parse_autocollimator_line(line)
        except FrameError:
            continue
        if isinstance(frame, AutocollimatorFrame):
            assert frame.status[2] in "0123"
            for value in (frame.x_arcsec, frame.y_arcsec):
                assert value is None or math.isfinite(value)


# ---------------------------------------------------------------- GeoCOM


def test_requests_are_the_published_ascii():
    assert request(GET_ANGLE5, 1) == b"%R1Q,2107:1\r\n"
    assert request(GET_ANGLE1, 1, trid=7) == b"%R1Q,2003,7:1\r\n"
    assert request(0) == b"%R1Q,0:\r\n"


def test_get_angle5_gives_hz_and_v_in_radians():
    # Hz 123.4567° and V 87.6543°, in radians as the instrument writes them
    hz, v = math.radians(123.4567), math.radians(87.6543)
    reply = parse_geocom_reply(f"%R1P,0,0:0,{hz:.10f},{v:.10f}".encode())
    assert (reply.com_rc, reply.trid, reply.rc) == (0, 0, 0)
    got = angles_of(reply, GET_ANGLE5)
    assert math.degrees(got[0]) == pytest.approx(123.4567, abs=1e-8)
    assert math.degrees(got[1]) == pytest.approx(87.6543, abs=1e-8)


def test_get_angle1_reads_the_first_two_of_nine_values():
    line = b"%R1P,0,3:0,1.5707963268,1.5707963268,0.000005,2123456,0.0001,-0.0002,0.00001,2123450,0"
    reply = parse_geocom_reply(line)
    assert reply.trid == 3 and len(reply.values) == 9
    assert angles_of(reply, GET_ANGLE1) == pytest.approx((math.pi / 2, math.pi / 2))


@pytest.mark.parametrize(("line", "why"), [
    (b"%R1P,0,0:1284,1.0,1.5", "1284"),       # accuracy not guaranteed: not certified
    (b"%R1P,3,0:0,1.0,1.5", "communication"),
    (b"%R1P,0,0:0,1.0", "2 values"),
    (b"%R1P,0,0:0,1.0,abc", "not angles"),
    (b"%R1P,0,0:0,7.0,1.5", "0 to 2"),
])
def test_a_reply_that_is_not_an_angle_is_refused_naming_why(line, why):
    with pytest.raises(FrameError, match=why):
        angles_of(parse_geocom_reply(line), GET_ANGLE5)


@settings(max_examples=150, deadline=None)
@given(st.binary(max_size=80))
def test_garbage_is_never_a_geocom_reply(data):
    for line in LineFramer().feed(data + b"\r\n"):
        try:
            reply = parse_geocom_reply(line)
        except FrameError:
            continue
        assert line.strip().startswith(b"%R1P,")
        assert isinstance(reply.rc, int)


# ---------------------------------------------------------------- line readout


@pytest.mark.parametrize(("line", "value", "unit"), [
    (b"  +105.00012 deg", 105.00012, "deg"),
    (b"X = -12,5 mm", -12.5, "mm"),
    (b"- 0.0034", -0.0034, ""),
    (b"1.5e-3 rad", 0.0015, "rad"),
])
def test_the_default_pattern(line, value, unit):
    got = LineReadout().parse(line)
    assert got.value == pytest.approx(value, rel=1e-12) and got.unit == unit


def test_a_pattern_of_the_users():
    readout = LineReadout(r"POS (?P<value>\S+) (?P<unit>\w+) OK")
    assert readout.parse(b"POS 12.25 deg OK").value == 12.25
    with pytest.raises(FrameError):
        readout.parse(b"POS 12.25 deg ERR")
    with pytest.raises(ValueError, match="value"):
        LineReadout(r"(?P<number>\d+)")
    with pytest.raises(ValueError, match="pattern"):
        LineReadout(r"(?P<value>\d+")


@pytest.mark.parametrize("line", [b"1.234,5 deg", b"abc", b"\xff12", b"inf deg"])
def test_the_readout_refuses(line):
    with pytest.raises(FrameError):
        LineReadout().parse(line)


# ---------------------------------------------------------------- stability gate


def test_a_reading_is_taken_after_the_dwell_inside_the_window():
    gate = StabilityGate(window=0.5, dwell_s=1.0)
    # moving 10" per frame, then settled at 100 ± 0.2" for 1.0 s (frames every 0.1 s)
    moving = [(0.1 * i, 10.0 * i) for i in range(10)]
    settled = [(1.0 + 0.1 * i, 100.0 + (0.2 if i % 2 else -0.2)) for i in range(11)]
    taken = [r for t, v in moving + settled if (r := gate.feed(t, [v])) is not None]
    assert len(taken) == 1
    reading = taken[0]
    assert reading.time_s == pytest.approx(2.0)   # the dwell starts at the first settled frame
    assert reading.frames == 11
    assert reading.mean[0] == pytest.approx(100.0 - 0.2 / 11)  # 6 at -0.2, 5 at +0.2
    assert reading.std[0] == pytest.approx(np.std([-0.2, 0.2] * 5 + [-0.2], ddof=1))


def test_no_take_while_the_spread_exceeds_the_window_or_the_frames_do_not_cover_the_dwell():
    gate = StabilityGate(window=0.5, dwell_s=1.0)
    assert all(gate.feed(0.1 * i, [0.6 * (i % 2)]) is None for i in range(50))
    gate = StabilityGate(window=0.5, dwell_s=1.0)
    assert gate.feed(0.0, [1.0]) is None and gate.feed(0.9, [1.0]) is None
    assert gate.feed(1.0, [1.0]) is not None


def test_after_a_take_the_next_needs_a_new_position_unless_retake():
    gate = StabilityGate(window=0.5, dwell_s=0.3)
    frames = [(0.1 * i, [5.0, 1.0]) for i in range(20)]
    assert sum(gate.feed(t, v) is not None for t, v in frames) == 1
    moved = [(2.0 + 0.1 * i, [9.0, 1.0]) for i in range(5)]
    assert sum(gate.feed(t, v) is not None for t, v in moved) == 1
    gate = StabilityGate(window=0.5, dwell_s=0.3, retake=True)
    assert sum(gate.feed(t, v) is not None for t, v in frames) == 5  # frames 0-3, 4-7, …


def test_after_a_restart_the_dwell_is_of_frames_after_it_and_a_taken_position_stays_taken():
    gate = StabilityGate(window=0.5, dwell_s=0.5)
    # 0.3 s of a quiet dwell, the link lost, frames again from 0.7 s
    assert all(gate.feed(0.1 * i, [2.0]) is None for i in range(4))
    gate.restart()
    assert gate.progress(0.7) == ("settling", 0.0)
    after = [gate.feed(0.7 + 0.1 * i, [2.0 + 0.01 * i]) for i in range(6)]
    assert after[:5] == [None] * 5  # without the restart, 0.7 s took from frames 0.0–0.3
    assert after[5].frames == 6 and after[5].mean == pytest.approx((2.025,))
    # taken: the same position after another restart is not taken again
    gate.restart()
    assert all(gate.feed(1.5 + 0.1 * i, [2.0]) is None for i in range(10))
    assert gate.progress(2.4) == ("taken", 0.0)


def test_no_take_until_the_other_instruments_have_read_during_the_dwell():
    """Settled from 1.0 s (frames every 0.1 s, dwell 0.5 s): with the encoder's newest
    reading from 0.8 s (during the turn) nothing is taken, the dwell going on; its reading
    at 1.75 s (during the dwell, whose first frame is then 1.2 s) lets the next frame take,
    the frames of the last 0.5 s (1.3–1.8 s) averaged."""
    gate = StabilityGate(window=0.5, dwell_s=0.5)
    turning = [gate.feed(0.1 * i, [30.0 * i], others_since=0.8) for i in range(10)]
    settled = [gate.feed(1.0 + 0.1 * i, [7.0], others_since=0.8) for i in range(8)]
    assert turning + settled == [None] * 18
    assert gate.dwell_since == pytest.approx(1.2)  # the frames kept slide with the dwell
    reading = gate.feed(1.8, [7.0], others_since=1.75)
    assert reading is not None and reading.time_s == pytest.approx(1.8)
    assert reading.frames == 6 and reading.mean == pytest.approx((7.0,))
    assert gate.dwell_since is None  # taken: no dwell in progress
    # an encoder read at the dwell's first frame is one read while steady
    gate = StabilityGate(window=0.5, dwell_s=0.5)
    assert [gate.feed(0.1 * i, [1.0], others_since=0.0) is not None
            for i in range(6)] == [False] * 5 + [True]


def test_a_reading_names_its_first_frame():
    """The reading carries its first frame's tag (the panel counted back through the 8,192
    frames it keeps, and named one frame for a dwell longer than those)."""
    gate = StabilityGate(window=0.5, dwell_s=1.0)
    # moving first (those frames leave the dwell), then settled from frame 1005
    frames = [gate.feed(0.01 * i, [0.0 if i < 5 else 1.0], tag=1000 + i) for i in range(106)]
    reading = frames[-1]
    assert frames[:-1] == [None] * 105 and reading.frames == 101
    assert reading.first_tag == 1005


@pytest.mark.parametrize("first", [10.0, 0.0, 359.9999])
def test_angles_unwrap_from_frame_to_frame_at_zero_and_at_the_opposite_side(first):
    """A theodolite's face II of its first target is 180° from the first frame: offsets from a
    fixed origin jumped between +180° and −180°; from frame to frame they are continuous."""
    unwrapped = UnwrappedAngles()
    assert unwrapped.offsets([first, 90.0]) == pytest.approx([0.0, 0.0])
    turned = (first + 180.0) % 360.0
    noise = [0.0001, -0.0001, 0.00005, -0.00015]  # ±0.5" about the opposite side
    offsets = [unwrapped.offsets([(turned + n) % 360.0, 270.0]) for n in noise]
    assert np.ptp([o[0] for o in offsets]) == pytest.approx(0.00025, abs=1e-9)
    mean = np.mean(offsets, axis=0)
    hz, v = unwrapped.angles(mean)
    assert (hz - turned + 180.0) % 360.0 - 180.0 == pytest.approx(np.mean(noise), abs=1e-9)
    assert v == pytest.approx(270.0)
    assert 0.0 <= hz < 360.0


def _naive_gate(frames, window, dwell, retake=False):
    """The gate's rule worked out from scratch at every frame (the test's own, quadratic):
    the readings as (time, mean, count, first tag)."""
    kept, taken, out = [], None, []
    for i, (t, v) in enumerate(frames):
        v = np.atleast_1d(np.asarray(v, dtype=float))
        if taken is not None:
            if np.all(np.abs(v - taken) <= window):
                continue
            taken, kept = None, []
        kept.append((t, v, i))
        while len(kept) > 1 and np.any(np.ptp([k[1] for k in kept], axis=0) > window):
            kept.pop(0)
        while len(kept) > 1 and kept[1][0] <= t - dwell + 1e-9:
            kept.pop(0)
        if t - kept[0][0] < dwell - 1e-9:
            continue
        mean = np.mean([k[1] for k in kept], axis=0)
        out.append((t, tuple(mean), len(kept), kept[0][2]))
        kept = []
        if not retake:
            taken = mean
    return out


@settings(max_examples=150, deadline=None)
@given(steps=st.lists(st.tuples(st.floats(0.001, 0.3), st.floats(-1.0, 1.0),
                                st.floats(-1.0, 1.0)), min_size=1, max_size=120),
       window=st.floats(0.05, 1.5), dwell=st.floats(0.01, 1.0), retake=st.booleans())
def test_the_gate_takes_what_the_rule_worked_out_from_scratch_takes(steps, window, dwell,
                                                                     retake):
    """Random two-axis streams (jumps, drifts, pauses): the gate's readings are those of the
    rule evaluated afresh over the frames at every step."""
    t, frames = 0.0, []
    for dt, x, y in steps:
        t += dt
        frames.append((t, [round(x, 3), round(y, 3)]))
    gate = StabilityGate(window=window, dwell_s=dwell, retake=retake)
    got = []
    for i, (time_s, v) in enumerate(frames):
        r = gate.feed(time_s, v, tag=i)
        if r is not None:
            got.append((r.time_s, r.mean, r.frames, r.first_tag))
    expected = _naive_gate(frames, window, dwell, retake)
    assert [(a, c, d) for a, _, c, d in got] == [(a, c, d) for a, _, c, d in expected]
    for (_, m, _, _), (_, e, _, _) in zip(got, expected, strict=True):
        assert m == pytest.approx(e, abs=1e-12)


def test_the_gate_refuses_a_window_or_dwell_of_zero():
    with pytest.raises(ValueError):
        StabilityGate(0, 1)
    with pytest.raises(ValueError):
        StabilityGate(1, 0)


# ---------------------------------------------------------------- Allan deviation


def test_allan_deviation_by_hand():
    y = [1.0, 3.0, 2.0, 6.0, 5.0]
    tau, adev = allan_deviation(y, 0.5, factors=[1, 2])
    # m = 1: differences 2, -1, 4, -1 → σ² = (4+1+16+1)/(2·4) = 2.75
    # m = 2: pair means 2, 2.5, 4, 5.5 → differences (4-2), (5.5-2.5) → σ² = (4+9)/(2·2) = 3.25
    assert tau.tolist() == [0.5, 1.0]
    assert adev == pytest.approx([math.sqrt(2.75), math.sqrt(3.25)])


def test_white_noise_averages_as_one_over_root_m():
    rng = np.random.default_rng(34)
    sigma = 0.05  # arcsec
    y = 100.0 + rng.normal(0, sigma, 200_000)
    tau, adev = allan_deviation(y, 0.004)
    assert tau[:4].tolist() == pytest.approx([0.004, 0.008, 0.016, 0.032])
    expected = sigma / np.sqrt(2 ** np.arange(len(adev)))
    usable = 2 ** np.arange(len(adev)) <= 1024  # enough averages to be within ~5 %
    assert adev[usable] == pytest.approx(expected[usable], rel=0.05)


def test_a_steady_drift_grows_as_tau_over_root_2():
    drift = 0.01  # arcsec per second
    t = np.arange(4000) * 0.1
    tau, adev = allan_deviation(drift * t, 0.1)
    assert adev == pytest.approx(drift * tau / math.sqrt(2), rel=1e-9)


def test_the_last_even_run_begins_after_the_last_gap():
    assert last_even_run([0, 1, 2, 3, 10, 11, 12]) == 4  # 7 s where 1 s was the rule
    assert last_even_run([0, 1, 2, 3, 4]) == 0
    assert last_even_run([0, 1, 1, 2, 3]) == 2  # a time repeated: the run starts after it
    assert last_even_run([0, 1, 2, 1.5, 2.5, 3.5]) == 3  # the clock went back
    assert last_even_run([]) == 0 and last_even_run([5.0]) == 0
    assert last_even_run([2.0, 2.0, 2.0]) == 3  # no spacing: no run
    # the rate raised from 10 Hz to 100 Hz: the frames at the old rate are not this run's (the
    # last of them, 0.01 s before the first at the new rate, is its first frame)
    times = np.concatenate((np.arange(100) * 0.1, 9.9 + np.arange(1, 501) * 0.01))
    assert last_even_run(times) == 99
    # a polled instrument's replies that jitter by their whole interval are one run
    rng = np.random.default_rng(7)
    assert last_even_run(np.cumsum(rng.uniform(0.05, 0.25, 400))) == 0


@settings(max_examples=200, deadline=None)
@given(before=st.integers(2, 300), after=st.integers(2, 300),
       interval=st.floats(1e-3, 2.0), gap=st.floats(4.5, 1e4), jitter=st.floats(0, 0.3),
       seed=st.integers(0, 2 ** 16))
def test_a_gap_anywhere_is_found_and_jitter_is_not_one(before, after, interval, gap, jitter,
                                                       seed):
    """Frames every ``interval`` ± ``jitter`` (a polled instrument's replies), one silence
    of ``gap`` intervals between two stretches: the run starts at the first frame after it."""
    rng = np.random.default_rng(seed)
    steps = interval * (1 + rng.uniform(-jitter, jitter, before + after - 1))
    steps[before - 1] = gap * interval
    times = 100.0 + np.concatenate(([0.0], np.cumsum(steps)))
    assert last_even_run(times) == before
    assert last_even_run(times[before:]) == 0


def test_allan_over_a_reconnection_is_of_the_run_after_it():
    """An autocollimator at 100 Hz, σ = 0.05", lost for 30 s during which the mirror settled
    3" further (a step no averaging of the frames after the gap can see): taken as one
    series the step shows as an Allan deviation far above the noise at the longest τ;
    the run after the gap averages down as white noise does."""
    rng = np.random.default_rng(61)
    sigma = 0.05
    t_before = np.arange(3000) * 0.01
    t_after = t_before[-1] + 30.0 + np.arange(3000) * 0.01
    times = np.concatenate((t_before, t_after))
    values = np.concatenate((np.full(3000, 100.0), np.full(3000, 103.0)))
    values = values + rng.normal(0.0, sigma, values.size)
    _, mixed = allan_deviation(values, 0.01)
    start = last_even_run(times)
    assert start == 3000
    _, run = allan_deviation(values[start:], 0.01)
    assert mixed[-1] > 20 * sigma  # the step read as instability
    m = 2 ** np.arange(len(run))
    usable = m <= 64  # 3000 frames: enough averages for 15 %
    assert run[usable] == pytest.approx(sigma / np.sqrt(m[usable]), rel=0.15)


def test_allan_refuses_what_it_cannot_compute():
    assert octave_factors(1).size == 0 and octave_factors(8).tolist() == [1, 2, 4]
    with pytest.raises(ValueError):
        allan_deviation([1.0, float("nan")], 1.0)
    with pytest.raises(ValueError):
        allan_deviation([1.0, 2.0], 0.0)
