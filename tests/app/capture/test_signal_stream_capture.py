"""A sin/cos signal stream over TCP: the read head simulator's signals follow its geometry
(checked with a fit at its true phase, worked out here from the geometry as documented),
the worker hands them on in blocks, every line accounted for, noise refused and counted."""

from __future__ import annotations

import math
import time

import numpy as np
import pytest

from app.capture.instruments import INSTRUMENTS, frame_values, reading_columns
from app.capture.signal_worker import SampleBlock, SignalStreamWorker
from app.capture.worker import Fault
from tests.instrument_simulators import SIMULATORS

ReadHead = SIMULATORS["signals"]


def fundamental(theta, u):
    """Offset, amplitude and phase (rad) of u's first harmonic, u ≈ o + A·sin(θ + c), by
    least squares at the true phase (harmonics 2 and 3 fitted beside it)."""
    design = np.column_stack([np.ones_like(theta)] + [f(k * theta) for k in (1, 2, 3)
                                                      for f in (np.sin, np.cos)])
    coef, *_ = np.linalg.lstsq(design, u, rcond=None)
    return coef[0], math.hypot(coef[1], coef[2]), math.atan2(coef[2], coef[1])


def head_figures(head, **mounting):
    theta = np.linspace(0, 2 * math.pi, 720, endpoint=False)
    u_sin, u_cos = (np.asarray(u) for u in head.channels(theta, **mounting))
    o_s, a_s, c_s = fundamental(theta, u_sin)
    o_c, a_c, c_c = fundamental(theta, u_cos)
    phase = math.degrees((c_c - c_s - math.pi / 2 + math.pi) % (2 * math.pi) - math.pi)
    return {"offset_sin": o_s, "offset_cos": o_c, "amplitude_sin": a_s, "amplitude_cos": a_c,
            "phase_deviation": phase}


def test_a_head_mounted_as_designed_gives_one_volt_peak_to_peak_in_quadrature():
    head = ReadHead("tcp")
    f = head_figures(head)
    assert f["amplitude_sin"] == pytest.approx(f["amplitude_cos"], rel=1e-12)
    assert f["offset_sin"] == pytest.approx(0, abs=1e-12) and f["offset_cos"] == pytest.approx(0, abs=1e-12)
    assert f["phase_deviation"] == pytest.approx(0, abs=1e-9)
    u_sin, _ = head.channels(np.linspace(0, 2 * math.pi, 4096))
    assert np.ptp(u_sin) == pytest.approx(1.0, rel=1e-5)


def test_the_gap_takes_the_contrast_and_the_yaw_the_quadrature():
    head = ReadHead("tcp")
    nominal = head_figures(head)["amplitude_sin"]
    # contrast exp(−((g − g0)/w)²), g0 = 0.8 mm, w = 0.25 mm: at 1.05 mm, e⁻¹
    assert head_figures(head, gap_mm=1.05)["amplitude_sin"] / nominal == pytest.approx(
        math.exp(-1), rel=1e-9)
    # yaw: the sin pair's fields sit at −1.5 s and +0.5 s, the cos pair's at −0.5 s and
    # +1.5 s along the lines (s = 0.15 mm): their centres 1 s apart, the lines shifted by
    # s·tan(yaw) between them, a phase of 360°·s·tan(yaw)/period (20 µm)
    for yaw_mrad in (1.0, 3.0, -5.0):
        expected = 360.0 * 0.15 * math.tan(yaw_mrad * 1e-3) / 0.020
        assert head_figures(head, yaw_mrad=yaw_mrad)["phase_deviation"] == pytest.approx(
            expected, abs=1e-6)


def test_the_roll_moves_the_light_and_parts_the_offsets():
    head = ReadHead("tcp")
    g, roll, w, s = 0.8, 20e-3, 0.4, 0.15
    spot = 2 * g * math.tan(roll)  # the reflected beam's shift on the fields
    light = [math.exp((y ** 2 - (y - spot) ** 2) / (2 * w ** 2))
             for y in ((k - 1.5) * s for k in range(4))]
    f = head_figures(head, roll_mrad=20.0)
    gain = head_figures(head)["amplitude_sin"] / (2 * 0.6)  # amplitude 2·E·m at m = 0.6, E = 1
    assert f["offset_sin"] == pytest.approx(gain * (light[0] - light[2]), rel=1e-9)
    assert f["offset_cos"] == pytest.approx(gain * (light[3] - light[1]), rel=1e-9)
    assert f["offset_sin"] < 0 < f["offset_cos"]


def _collect(worker: SignalStreamWorker, samples: int, timeout_s: float = 10.0):
    blocks: list[SampleBlock] = []
    faults: list[Fault] = []
    ends = time.monotonic() + timeout_s
    while (sum(b.u_sin.size for b in blocks) < samples and time.monotonic() < ends
           and not any(f.final for f in faults)):
        for event in worker.drain():
            (blocks if isinstance(event, SampleBlock) else faults).append(event)
        time.sleep(0.01)
    return blocks, faults


def test_the_worker_hands_the_stream_on_in_blocks_sample_for_sample():
    with ReadHead("tcp", sample_hz=10_000.0, noise_mv=0.5, seed=5) as head:
        worker = SignalStreamWorker(head.port).start()
        try:
            blocks, faults = _collect(worker, 5000)
        finally:
            worker.stop()
    assert not faults
    u_sin = np.concatenate([b.u_sin for b in blocks])
    u_cos = np.concatenate([b.u_cos for b in blocks])
    assert u_sin.size >= 5000
    assert len(blocks) < u_sin.size / 10  # blocks, not one event a sample
    # the connection's first line is kept, not a sample (it may be the rest of one begun
    # before the connection): the samples are those sent from the second on
    assert not blocks[0].used[0] and blocks[0].stale == 1 and blocks[0].refused == 0
    sent = np.array(list(head.history)[1:u_sin.size + 1])
    assert np.allclose(u_sin, sent[:, 1], atol=5e-7) and np.allclose(u_cos, sent[:, 2], atol=5e-7)
    # the lines are numbered without a gap, each block's first the previous block's end
    assert [b.first for b in blocks] == list(np.cumsum([0] + [len(b.lines) for b in blocks])[:-1])


def test_noise_on_the_line_is_refused_counted_and_kept_in_the_blocks():
    with ReadHead("tcp", faults=("noise",), sample_hz=5000.0, seed=8) as head:
        worker = SignalStreamWorker(head.port).start()
        try:
            blocks, faults = _collect(worker, 3000)
        finally:
            worker.stop()
    lines = sum(len(b.lines) for b in blocks)
    samples = sum(b.u_sin.size for b in blocks)
    refused = sum(b.refused for b in blocks)
    stale = sum(b.stale for b in blocks)  # the connection's first line, kept and not read
    assert refused > 0 and samples >= 3000 and samples + refused + stale == lines and stale <= 1
    assert all(int(b.used.sum()) == b.u_sin.size for b in blocks)
    assert worker.refused == refused or worker.refused >= refused


def test_a_pattern_without_its_groups_is_refused_before_anything_opens():
    with pytest.raises(ValueError, match="sin"):
        SignalStreamWorker("tcp://127.0.0.1:1", pattern=r"(?P<cos>\S+)")


def test_a_port_that_cannot_be_opened_ends_in_a_final_fault():
    worker = SignalStreamWorker("tcp://127.0.0.1:1", retries=1, retry_pause_s=0.01).start()
    _, faults = _collect(worker, 1, timeout_s=5.0)
    worker.stop()
    assert faults and faults[-1].final and "tcp://127.0.0.1:1" in str(faults[-1].message)


def test_a_signal_line_reads_back_to_the_fringe_columns():
    # the capture sessions' check of edits after capture reads a take's lines this way
    assert frame_values("signals", b"0.125,-0.5") == (0.125, -0.5)
    assert frame_values("signals", b"garbage") is None
    assert reading_columns("signals", ["u_sin", "u_cos", "theta_deg"]) == [("u_sin", 0), ("u_cos", 1)]
    assert INSTRUMENTS["signals"]().default_baud == 115200


@pytest.mark.slow
def test_anglebench_simulate_signals_streams_and_takes_settings_from_its_input():
    """The command's head read with a bare socket: 1 Vpp as mounted; ``gap 1.05`` on its
    standard input takes the amplitude to e⁻¹ of it (the contrast's fall-off)."""
    import socket
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parents[3]
    process = subprocess.Popen([sys.executable, "-m", "app.main", "simulate", "signals", "0",
                                "--noise", "0", "--commands", "--seconds", "30"], cwd=root,
                               stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        line = process.stdout.readline()
        port = int(line.split("tcp://127.0.0.1:")[1].split()[0])

        def amplitude(link, pending=b""):
            values = []
            while len(values) < 2000:
                pending += link.recv(65536)
                *lines, pending = pending.split(b"\n")
                values += [tuple(float(v) for v in x.split(b",")) for x in lines if x]
            u = np.array(values[-1000:])
            return float(np.mean(np.hypot(u[:, 0], u[:, 1]))), pending

        with socket.create_connection(("127.0.0.1", port), timeout=5) as link:
            nominal, _ = amplitude(link)
            process.stdin.write("gap 1.05\n")
            process.stdin.flush()
            time.sleep(0.5)
            link.recv(1 << 20)  # what was sent before the change
            later, _ = amplitude(link)
    finally:
        process.terminate()
        process.communicate(timeout=10)
    assert nominal == pytest.approx(0.5, rel=0.02)
    assert later / nominal == pytest.approx(math.exp(-1), rel=0.03)


def test_anglebench_capture_signals_writes_the_samples_as_sent(tmp_path):
    import csv

    from app.main import main

    out = tmp_path / "signals.csv"
    with ReadHead("tcp", sample_hz=2000.0, noise_mv=0.5, seed=4) as head:
        assert main(["capture", "signals", head.port, "--readings", "200", "--out", str(out),
                     "--silence", "0.5", "--retries", "1"]) == 0
        # the connection's first line is not read (it may be the rest of a sample begun
        # before the connection: Instrument.tail_parses): the samples from the second on
        sent = list(head.history)[1:201]
    with open(out, newline="", encoding="utf-8") as handle:
        rows = list(csv.reader(handle))
    assert rows[0] == ["time_s", "u_sin", "u_cos"]
    got = np.array([[float(v) for v in r[1:]] for r in rows[1:]])
    assert got.shape == (200, 2)
    assert np.allclose(got, np.array(sent)[:, 1:], atol=5e-7)
