"""One request in flight: GeoCOM pacing against a slow theodolite, replies with and without
a transaction id, a late reply to an older request, and an ELCOMAT-kind autocollimator that
answers single shots only (``a``), through the command line as a technician runs it."""

from __future__ import annotations

import csv
import re

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.capture.instruments import Autocollimator, Theodolite
from app.capture.worker import CaptureWorker
from app.main import main
from models.capture.geocom import MAX_TRANSACTION_ID, parse_geocom_reply
from tests.app.capture.test_capture_link import FAST, collect
from tests.instrument_simulators import AutocollimatorSimulator, TheodoliteSimulator

CLI_FAST = ["--silence", "0.2", "--retries", "1"]


def rows_of(path):
    with open(path, newline="", encoding="utf-8") as handle:
        return list(csv.reader(handle))


def angle_requests(sim) -> list[bytes]:
    return [r for r in sim.received if r.startswith(b"%R1Q,2107")]


def test_a_slow_theodolite_gets_one_request_at_a_time_and_every_reading_is_fresh(tmp_path, capsys):
    """The instrument takes 0.3 s for each answer while it turns every 0.45 s: each reading is
    the answer to the one request in flight, the angle where the instrument stood when it
    answered, and no request waits in its buffer (the audit saw 9 requests for 5 replies)."""
    out = tmp_path / "theo.csv"
    positions = [(10.0 * i, 90.0 - 0.5 * i) for i in range(1, 9)]
    with TheodoliteSimulator("tcp", positions=positions, hold_s=0.45, reply_delay_s=0.3) as sim:
        assert main(["capture", "theodolite", sim.port, "--readings", "6", "--out", str(out),
                     "--silence", "1", "--retries", "0"]) == 0
        asked = angle_requests(sim)
    assert sim.max_pending == 1
    rows = rows_of(out)[1:]
    assert len(rows) == 6
    assert np.allclose([tuple(map(float, r[1:])) for r in rows], sim.sent[:6], atol=1e-7, rtol=0)
    # the readings follow the instrument: several positions seen, in order
    assert len({round(float(r[1])) for r in rows}) >= 3
    # six answered, at most one more asked (in flight when the set was complete)
    assert 6 <= len(asked) <= 7
    trids = [int(re.match(rb"%R1Q,2107,(\d+):", r).group(1)) for r in asked]
    assert trids[:7] == [1, 2, 3, 4, 5, 6, 7][:len(trids)]


def test_a_reply_without_a_transaction_id_is_read(tmp_path):
    out = tmp_path / "theo.csv"
    with TheodoliteSimulator("pty", positions=[(123.4567, 87.6543)], omit_trid=True) as sim:
        assert main(["capture", "theodolite", sim.port, "--readings", "5", "--out", str(out),
                     *CLI_FAST]) == 0
    rows = rows_of(out)[1:]
    assert [tuple(map(float, r[1:])) for r in rows] == [pytest.approx((123.4567, 87.6543), abs=1e-8)] * 5


class _AnswersTwice(TheodoliteSimulator):
    """Sends its first reply again just before its second: that copy arrives while the next
    request (a new transaction id) is in flight, as a late reply to an older request does;
    and a third copy on its own after the fourth reply, with no request in flight."""

    def answer(self, command: bytes) -> list[bytes]:
        replies = super().answer(command)
        if len(self.sent) == 1:
            self.first = replies
        if len(self.sent) == 2:
            return self.first + replies
        if len(self.sent) == 4:
            return replies + self.first
        return replies


def test_a_late_reply_to_an_older_request_is_not_taken_for_the_current_one():
    with _AnswersTwice("pty", positions=[(45.0, 90.0)]) as sim:
        worker = CaptureWorker(sim.port, Theodolite(), **FAST).start()
        readings, faults = collect(worker, 6)
        worker.stop()
    assert not faults and len(readings) == 6
    # the copy carried transaction 1 while 2 was in flight: kept in the raw trace, not read
    assert any("transaction 1, waiting for 2" in r for r in worker.refusals)
    assert any("no request in flight" in r or "transaction 1, waiting for 5" in r for r in worker.refusals)
    # the two copies kept in the raw trace and not read; a reply carrying 1 is read only for
    # a request that carried 1 (the eighth carries 1 again: on a loaded machine the test's
    # thread stopped the worker after it had asked an eighth, whose own reply was read)
    trid_1 = [used for _, line, used in worker.raw if line.startswith(b"%R1P,0,1:")]
    asked_1 = sum(1 for k in range(worker.requests) if k % MAX_TRANSACTION_ID == 0)
    assert trid_1.count(False) == 2 and 1 <= trid_1.count(True) <= asked_1


def test_a_slow_reply_waits_its_timeout_and_a_lost_one_is_a_fault_of_its_own():
    # 0.4 s per answer, silence 0.2 s, reply timeout 1 s: the wait is not silence
    with TheodoliteSimulator("pty", positions=[(1.0, 2.0)], reply_delay_s=0.4) as sim:
        worker = CaptureWorker(sim.port, Theodolite(), silence_s=0.2, retries=1,
                               retry_pause_s=0.05, reply_timeout_s=1.0).start()
        readings, faults = collect(worker, 3)
        worker.stop()
    assert not faults and len(readings) == 3 and sim.max_pending == 1
    with TheodoliteSimulator("pty", faults=("silence",)) as sim:
        worker = CaptureWorker(sim.port, Theodolite(), silence_s=0.2, retries=0,
                               reply_timeout_s=0.3).start()
        readings, faults = collect(worker, 1)
        worker.stop()
    assert readings == [] and faults[-1].final
    assert faults[-1].message == f"{sim.port}: no answer for 0.2 s"
    # an instrument that answered once and then lost a request: the timeout's own message
    with TheodoliteSimulator("pty", faults=("disconnect",), disconnect_after=2, gap_s=5.0) as sim:
        worker = CaptureWorker(sim.port, Theodolite(), silence_s=0.2, retries=0,
                               reply_timeout_s=0.3).start()
        readings, faults = collect(worker, 3)
        worker.stop()
    assert len(readings) == 2
    assert faults[-1].message == f"{sim.port}: no reply to a request within 0.3 s (the reply timeout)"
    assert worker.timeouts == 1


def test_the_theodolite_answers_what_a_client_asks_when_it_connects():
    """COM_NullProc and the identity calls, asked as a GeoCOM client asks them at start-up;
    the replies read with the project's own reply parser."""
    import socket

    with TheodoliteSimulator("tcp") as sim:
        host, port = sim.port[len("tcp://"):].split(":")
        with socket.create_connection((host, int(port)), timeout=2) as sock:
            replies = {}
            for trid, rpc in enumerate((0, 108, 5004, 5003, 110, 5034), start=1):
                sock.sendall(f"%R1Q,{rpc},{trid}:\r\n".encode())
                data = b""
                while not data.endswith(b"\r\n"):
                    data += sock.recv(256)
                replies[rpc] = parse_geocom_reply(data.strip())
                assert replies[rpc].trid == trid and replies[rpc].rc == 0
    assert replies[0].values == ()
    assert replies[108].values == ("15",)
    assert replies[5004].values[0].startswith('"')
    assert len(replies[110].values) == 3 and len(replies[5034].values) == 3


@settings(deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(com_rc=st.integers(0, 3077), trid=st.one_of(st.none(), st.integers(0, 32767)),
       rc=st.integers(-1, 13000),
       values=st.lists(st.floats(allow_nan=False, allow_infinity=False, width=32), max_size=9))
def test_geocom_replies_with_and_without_a_transaction_id(com_rc, trid, rc, values):
    head = f"%R1P,{com_rc}" + ("" if trid is None else f",{trid}")
    line = f"{head}:{rc}" + "".join(f",{v!r}" for v in values)
    reply = parse_geocom_reply(line.encode())
    assert (reply.com_rc, reply.trid, reply.rc) == (com_rc, trid, rc)
    assert [float(v) for v in reply.values] == values


def test_an_autocollimator_that_answers_only_single_shots_is_polled(tmp_path, capsys):
    """Some ELCOMAT firmware says nothing to A: the capture waits for the stream, then asks
    single shots (a), one at a time, and the readings are the instrument's."""
    out, raw = tmp_path / "ac.csv", tmp_path / "raw.csv"
    with AutocollimatorSimulator("tcp", positions=[(12.5, -3.25)], sigma=0.02,
                                 streams=False) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "10", "--out", str(out),
                     "--raw", str(raw), "--silence", "2", "--retries", "0"]) == 0
        received = list(sim.received)
    assert sim.max_pending == 1
    assert received[0] == b"A" and b"a" in received
    rows = rows_of(out)[1:]
    assert [tuple(map(float, r[1:])) for r in rows] == [(round(x, 3), round(y, 3)) for x, y in sim.sent[:10]]
    raw_rows = rows_of(raw)[1:]
    assert all(line.startswith("4 003 ") for _, _, line in raw_rows)
    err = capsys.readouterr().err
    assert "did not stream after A" in err and "10 readings written" in err


def test_polling_chosen_asks_single_shots_from_the_start_at_the_rate_given(tmp_path):
    out = tmp_path / "ac.csv"
    with AutocollimatorSimulator("pty", positions=[(1.5, 2.5)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "6", "--out", str(out),
                     "--mode", "poll", "--poll-rate", "10", *CLI_FAST]) == 0
        received = list(sim.received)
    assert b"A" not in received and received[0] == b"a"
    times = [float(r[0]) for r in rows_of(out)[1:]]
    assert times[-1] - times[0] >= 0.45  # 10 Hz at the most: 5 intervals of 0.1 s (less jitter)


def test_a_polled_autocollimator_through_the_stability_gate(tmp_path):
    out = tmp_path / "ac.csv"
    # the first position outlasts the wait for a stream (half the silence, 0.5 s) and a dwell
    with AutocollimatorSimulator("pty", positions=[(5.0, 6.0), (15.0, 16.0)], hold_s=1.2,
                                 streams=False) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "2", "--out", str(out),
                     "--stable", "0.5", "--dwell", "0.15", "--poll-rate", "50", "--silence", "1",
                     "--retries", "0", "--timeout", "20"]) == 0
    rows = rows_of(out)[1:]
    assert [tuple(map(float, r[1:])) for r in rows] == [pytest.approx((5.0, 6.0)),
                                                        pytest.approx((15.0, 16.0))]


def test_mode_is_refused_for_an_instrument_that_is_always_asked(tmp_path, capsys):
    assert main(["capture", "theodolite", "/dev/null", "--out", str(tmp_path / "x.csv"),
                 "--mode", "poll"]) == 2
    assert "--mode is the autocollimator's" in capsys.readouterr().err


def test_the_autocollimator_driver_keeps_its_poll_mode_across_a_reconnection():
    with AutocollimatorSimulator("tcp", positions=[(1.0, 2.0)], streams=False,
                                 faults=("disconnect",), disconnect_after=5) as sim:
        worker = CaptureWorker(sim.port, Autocollimator(), silence_s=0.6, retries=2,
                               retry_pause_s=0.05).start()
        readings, faults = collect(worker, 12)
        worker.stop()
    assert len(readings) == 12 and worker.polling
    assert len(faults) == 1 and not faults[0].final


class _StreamsFromConnect(AutocollimatorSimulator):
    """Streams from the moment a client connects, before it asks (a serial-to-network
    bridge in front of a streaming instrument), after a first line of 10 MB that has no
    end for a while (line noise of a bridge)."""

    def __init__(self, *args, junk: int = 0, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.junk = junk

    def _serve_link(self, link, read, write):
        if self.junk:
            write(link, b"x" * self.junk + b"\r")
        self._streaming, self._code = True, "3"
        frame = self.stream_frame()
        write(link, frame)
        return super()._serve_link(link, read, write)


def test_the_first_frame_after_a_tcp_connect_is_read_and_traced():
    with _StreamsFromConnect("tcp", positions=[(3.0, 4.0)], sigma=0.5) as sim:
        worker = CaptureWorker(sim.port, Autocollimator(), **FAST).start()
        readings, faults = collect(worker, 5)
        worker.stop()
    assert not faults
    first = sim.sent[0]
    assert readings[0].values == (round(first[0], 3), round(first[1], 3))
    assert worker.raw[0][1] == readings[0].raw and worker.raw[0][2]


def test_a_ten_megabyte_line_over_tcp_is_dropped_in_blocks_and_the_frames_after_it_read():
    import time

    with _StreamsFromConnect("tcp", positions=[(3.0, 4.0)], junk=10_000_000) as sim:
        started = time.monotonic()
        worker = CaptureWorker(sim.port, Autocollimator(), silence_s=3.0, retries=0).start()
        readings, faults = collect(worker, 5, timeout_s=10.0)
        took = time.monotonic() - started
        worker.stop()
    assert not faults and len(readings) == 5
    assert took < 5.0  # one byte per call took ~30 s
