"""The drivers through the real serial code path (pyserial on a pseudo-terminal, or its
socket:// handler on 127.0.0.1) against the protocol simulators, in every fault mode."""

from __future__ import annotations

import contextlib
import queue
import time

import numpy as np
import pytest

from app.capture.instruments import Autocollimator, LineReadoutInstrument, Theodolite
from app.capture.link import serial_url
from app.capture.worker import CaptureWorker, Fault, NoTarget, Reading
from tests.instrument_simulators import AutocollimatorSimulator, ReadoutSimulator, TheodoliteSimulator

FAST = {"silence_s": 0.2, "retries": 1, "retry_pause_s": 0.05}


def collect(worker: CaptureWorker, n: int, timeout_s: float = 5.0):
    readings, faults = [], []
    end = time.monotonic() + timeout_s
    while len(readings) < n and time.monotonic() < end:
        try:
            event = worker.events.get(timeout=0.05)
        except queue.Empty:
            continue
        if isinstance(event, Reading):
            readings.append(event)
        elif not isinstance(event, NoTarget):  # frames with no measurement are no fault
            faults.append(event)
            if event.final:
                break
    return readings, faults


def test_tcp_is_spelt_as_pyserials_socket():
    assert serial_url("tcp://127.0.0.1:5000") == "socket://127.0.0.1:5000"
    assert serial_url("/dev/ttyUSB0") == "/dev/ttyUSB0"


@pytest.mark.parametrize("transport", ["pty", "tcp"])
def test_an_autocollimator_stream_is_read_frame_for_frame(transport):
    with AutocollimatorSimulator(transport, positions=[(12.5, -3.25)], sigma=0.05) as sim:
        worker = CaptureWorker(sim.port, Autocollimator(), **FAST).start()
        readings, faults = collect(worker, 100)
        worker.stop()
        # the simulator reads the stop command on its own thread: wait for it (up to 5 s)
        deadline = time.monotonic() + 5.0
        while (not sim.received or sim.received[-1] != b"s") and time.monotonic() < deadline:
            time.sleep(0.01)
    assert not faults and len(readings) == 100
    sent = [(round(x, 3), round(y, 3)) for x, y in sim.sent[:100]]
    assert [r.values for r in readings] == sent
    assert sim.received[0] == b"A" and sim.received[-1] == b"s"  # started, then stopped
    assert readings[0].raw.startswith(b"3 003 ")
    times = [r.time_s for r in readings]
    assert times == sorted(times)


def test_a_frame_with_an_invalid_axis_never_becomes_a_reading():
    with AutocollimatorSimulator("pty", faults=("invalid_axes",), positions=[(1.0, 2.0)]) as sim:
        worker = CaptureWorker(sim.port, Autocollimator(), **FAST).start()
        readings, faults = collect(worker, 30)
        worker.stop()
    assert not faults and len(readings) == 30
    assert all(r.values == (1.0, 2.0) for r in readings)
    sent_before = sim.sent[:sim.sent.index((1.0, 2.0), 0) + 45]
    assert [s for s in sent_before if None in s]  # invalid frames were sent …
    assert worker.refused >= 10                   # … and refused
    assert any("not valid" in r for r in worker.refusals)


def test_frames_out_of_range_are_no_target_in_view_never_a_fault_of_the_link():
    """live76 F3: an autocollimator whose mirror is out of view (the table turning) sends
    frames beyond its range: after the silence (0.2 s) the link was reconnected, and given
    up after the retries. For 1 s (five times the silence) it is one NoTarget, no fault, no
    reconnection, and the readings go on when the mirror is back; only silence is a fault."""
    with AutocollimatorSimulator("pty", positions=[(1.0, 2.0)], rate_hz=50.0) as sim:
        worker = CaptureWorker(sim.port, Autocollimator(), **FAST).start()
        events = []
        try:
            end = time.monotonic() + 3.0
            while time.monotonic() < end:
                with contextlib.suppress(queue.Empty):
                    events.append(worker.events.get(timeout=0.05))
                if time.monotonic() > end - 2.5 and sim.positions[0] == (1.0, 2.0) \
                        and not any(isinstance(e, NoTarget) for e in events):
                    sim.positions[0] = (9999.0, 2.0)  # out of view
                    back = time.monotonic() + 1.0
                if sim.positions[0] != (1.0, 2.0) and time.monotonic() > back:
                    sim.positions[0] = (1.5, 2.0)  # back in view
            sim.faults.add("silence")  # the instrument stops: that is a fault
            end = time.monotonic() + 2.0
            while time.monotonic() < end and not any(isinstance(e, Fault) for e in events):
                with contextlib.suppress(queue.Empty):
                    events.append(worker.events.get(timeout=0.05))
        finally:
            worker.stop()
    kinds = [type(e).__name__ for e in events]
    first_gone = kinds.index("NoTarget")
    # until the instrument fell silent: readings and one NoTarget, no fault of the link
    assert kinds.count("NoTarget") == 1
    assert set(kinds[:kinds.index("Fault")]) == {"Reading", "NoTarget"}
    (gone,) = [e for e in events if isinstance(e, NoTarget)]
    assert gone.columns == ("ac_x_arcsec",) and gone.value == pytest.approx(9999.0)
    assert gone.limits == (-3600.0, 3600.0)
    before, after = events[first_gone - 1], events[first_gone + 1]
    assert before.values == (1.0, 2.0) and after.values == (1.5, 2.0)
    assert after.time_s - gone.time_s >= 0.9  # out of view for 1 s, heard all along
    assert "no answer" in str(events[kinds.index("Fault")].message)


def test_line_noise_is_refused_and_every_frame_is_still_read():
    with AutocollimatorSimulator("pty", faults=("noise",), positions=[(7.0, -7.0)], sigma=1.0) as sim:
        worker = CaptureWorker(sim.port, Autocollimator(), **FAST).start()
        readings, faults = collect(worker, 60)
        worker.stop()
    assert not faults and len(readings) == 60
    assert [r.values for r in readings] == [(round(x, 3), round(y, 3)) for x, y in sim.sent[:60]]
    assert worker.refused > 0


def test_silence_is_a_final_fault_naming_the_port():
    with AutocollimatorSimulator("pty", faults=("silence",)) as sim:
        worker = CaptureWorker(sim.port, Autocollimator(), **FAST).start()
        readings, faults = collect(worker, 1)
        worker.stop()
    assert readings == []
    assert faults[-1].final and faults[-1].message == f"{sim.port}: no answer for 0.2 s"


def test_a_wrong_baud_rate_is_named():
    with TheodoliteSimulator("pty", faults=("wrong_baud",)) as sim:
        worker = CaptureWorker(sim.port, Theodolite(), baud=9600, **FAST).start()
        readings, faults = collect(worker, 1)
        worker.stop()
    assert readings == [] and faults[-1].final
    assert sim.port in faults[-1].message and "baud" in faults[-1].message
    assert "9600" in faults[-1].message


def test_a_port_that_does_not_exist():
    worker = CaptureWorker("/dev/nonexistent-anglebench", Autocollimator(), **FAST).start()
    readings, faults = collect(worker, 1)
    assert readings == [] and faults[-1].final
    assert faults[-1].message.startswith("/dev/nonexistent-anglebench: cannot open")


@pytest.mark.parametrize("transport", ["pty", "tcp"])
def test_a_disconnect_mid_set_loses_no_reading(transport):
    """The link drops after 8 answers; the worker reconnects and the set goes on: every
    answer the theodolite gave whole is a reading, in order, none twice. On the pty the
    request sent into the gap is lost, as on a pulled cable: it waits its reply timeout
    (longer than the gap), then the link is opened again."""
    positions = [(10.0 * i, 90.0 - i) for i in range(1, 5)]
    with TheodoliteSimulator(transport, faults=("disconnect",), disconnect_after=8,
                             positions=positions, hold_s=0.25) as sim:
        worker = CaptureWorker(sim.port, Theodolite(), **FAST, reply_timeout_s=0.5).start()
        readings, faults = collect(worker, 20)
        worker.stop()
    assert len(faults) == 1 and not faults[0].final and sim.port in faults[0].message
    assert len(readings) == 20
    assert np.allclose([r.values for r in readings], sim.sent[:20], rtol=0, atol=1e-7)


def test_theodolite_angles_in_degrees_and_error_replies_refused():
    with TheodoliteSimulator("pty", faults=("invalid_axes",), positions=[(123.4567, 87.6543)]) as sim:
        worker = CaptureWorker(sim.port, Theodolite(), **FAST).start()
        readings, faults = collect(worker, 10)
        worker.stop()
    assert not faults and len(readings) == 10
    assert all(r.values == pytest.approx((123.4567, 87.6543), abs=1e-8) for r in readings)
    assert any("1284" in r for r in worker.refusals)
    assert sim.received[0] == b"%R1Q,2107,1:1"  # TMC_GetAngle5, transaction 1, automatic incline


def test_a_readout_is_asked_and_read():
    with ReadoutSimulator("tcp", faults=("invalid_axes",), positions=[(105.00012,)], unit="deg") as sim:
        worker = CaptureWorker(sim.port, LineReadoutInstrument(), **FAST).start()
        readings, faults = collect(worker, 6)
        worker.stop()
    assert not faults
    assert [(r.values, r.unit) for r in readings] == [((105.00012,), "deg")] * 6
    assert worker.refused >= 2 and set(sim.received[:1]) == {b""}


def test_the_worker_never_blocks_its_caller():
    with AutocollimatorSimulator("pty", faults=("silence",)) as sim:
        started = time.monotonic()
        worker = CaptureWorker(sim.port, Autocollimator(), **FAST).start()
        assert time.monotonic() - started < 0.05
        assert isinstance(worker.events.get(timeout=3), Fault)
        stopping = time.monotonic()
        worker.stop()
        assert time.monotonic() - stopping < 0.5 and not worker.running
