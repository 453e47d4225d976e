"""capture80: a capture worker starved of CPU for more than 1 s (a loaded machine, CI) showed
a brief false "link lost": the window marked a value stale when its own timer had seen no
reading for 1 s, a timer a starved worker cannot feed. The link is lost only on evidence the
worker saw itself: no reading for the whole silence on its clock, from a read it began
after that silence (app/capture/worker.py).

The instrument is a process of its own (``anglebench simulate``, the window's demonstration
instrument): the test's process is starved, the instrument goes on sending, as a real one
does. The starvation is the test holding the GIL in a busy loop for 1.5 s (its switch
interval raised so that no other thread of the process runs meanwhile), between two ticks
of the window's timer (as a loaded machine may order them: the window's timer could not tell
a starved worker from a silent instrument)."""

from __future__ import annotations

import sys
import time

import pytest

from app.capture.panel import DemonstrationProcess, InstrumentLink
from tests.app.capture.window_steps import show_workbench as _show

pytestmark = pytest.mark.slow  # a window, an instrument process, 1.5 s held


def _hold_the_gil(seconds: float, tick) -> None:
    """No other thread of this process runs for ``seconds`` (this one busy), between two
    ``tick()`` — the window's timer, which on a loaded machine may well be given the CPU
    before and after it while the worker's thread waits (the first takes in what the worker
    had queued, as the window's timer does every 20 ms)."""
    switch = sys.getswitchinterval()
    sys.setswitchinterval(10.0 + seconds)
    try:
        tick()
        end = time.monotonic() + seconds
        while time.monotonic() < end:
            pass
        tick()
    finally:
        sys.setswitchinterval(switch)


def test_a_starved_worker_is_no_lost_link(window, qtbot, monkeypatch):
    _show(window, "polygon")
    panel = window.capture_panel
    said_lost: list[str] = []
    mark = InstrumentLink.mark_lost

    def watched(link, lost: bool) -> None:
        mark(link, lost)
        if lost:
            said_lost.append(link.value.text())

    monkeypatch.setattr(InstrumentLink, "mark_lost", watched)
    with DemonstrationProcess("autocollimator", noise=0.05) as instrument:
        # as the window connects it (its 1 s silence, its retries)
        panel.connect_to("autocollimator", instrument.port)
        qtbot.waitUntil(lambda: panel.take_button.isEnabled(), timeout=10000)
        qtbot.wait(300)
        worker = panel.worker
        for _ in range(2):
            _hold_the_gil(1.5, tick=panel.drain)
            qtbot.wait(1000)  # the window and the worker catch up
        status, lost, fault = panel.status.text(), panel.links[0].lost, panel.links[0].last_fault
        panel.disconnect_instrument()
    assert said_lost == [] and not lost, said_lost
    assert fault == "" and worker.timeouts == 0, fault  # no reconnection either
    assert status == f"Connected: {instrument.port}"


class _StarvedStream:
    """An autocollimator streaming a frame per read; read number ``starved_at`` comes back
    empty 1.5 s after it began — the thread descheduled right after its read found nothing
    waiting, while the instrument went on sending (the frames of those 1.5 s wait in the
    buffer, read at the next call)."""

    def __init__(self, starved_at: int = 20, starved_s: float = 1.5) -> None:
        self.reads, self.starved_at, self.starved_s = 0, starved_at, starved_s
        self.in_waiting = 0

    def read(self, _n: int = 1) -> bytes:
        self.reads += 1
        if self.reads == self.starved_at:
            time.sleep(self.starved_s)
            return b""
        time.sleep(0.01)
        if self.reads == self.starved_at + 1:  # what came while the thread was away
            return b"3 003 1.000 2.000\r" * 150
        return b"3 003 1.000 2.000\r"

    def write(self, data: bytes) -> int:
        return len(data)

    def close(self) -> None:
        pass


class _FallsSilent(_StarvedStream):
    """Frames for 20 reads, then nothing (the instrument fell silent)."""

    def read(self, _n: int = 1) -> bytes:
        self.reads += 1
        time.sleep(0.01)
        return b"3 003 1.000 2.000\r" if self.reads < 20 else b""


def test_a_worker_starved_after_an_empty_read_reads_again_before_it_says_silence():
    """The silence (1 s) is judged from a read begun after it: a read that began in time and
    came back late, empty, is no evidence (the worker said "no answer for 1 s" and
    reconnected). The window's stale time is judged so too (the test above; the next)."""
    from app.capture.instruments import Autocollimator
    from app.capture.worker import CaptureWorker, Fault, Reading

    port = _StarvedStream()
    worker = CaptureWorker("FAKE", Autocollimator(), silence_s=1.0, retries=1,
                           retry_pause_s=0.01, opener=lambda _port, _baud: port).start()
    deadline = time.monotonic() + 10.0
    events: list = []
    while time.monotonic() < deadline and port.reads < port.starved_at + 20:
        time.sleep(0.01)
    worker.stop()
    while not worker.events.empty():
        events.append(worker.events.get())
    assert [e for e in events if not isinstance(e, Reading)] == []
    assert not any(isinstance(e, Fault) for e in events)
    assert sum(isinstance(e, Reading) for e in events) >= port.starved_at + 150


def test_a_worker_that_reads_nothing_says_so_on_its_clock():
    """The other side: no reading from reads begun after the stale time and the silence —
    Stale, then the fault (the link lost is still said, and only then)."""
    from app.capture.instruments import Autocollimator
    from app.capture.worker import CaptureWorker, Fault, Reading, Stale

    port = _FallsSilent()
    worker = CaptureWorker("FAKE", Autocollimator(), silence_s=1.5, stale_s=0.5, retries=0,
                           opener=lambda _port, _baud: port).start()
    deadline = time.monotonic() + 10.0
    events: list = []
    while time.monotonic() < deadline and not any(isinstance(e, Fault) for e in events):
        time.sleep(0.01)
        while not worker.events.empty():
            events.append(worker.events.get())
    worker.stop()
    kinds = [type(e) for e in events if not isinstance(e, Reading)]
    assert kinds == [Stale, Fault], kinds
    stale = next(e for e in events if isinstance(e, Stale))
    last = [e for e in events if isinstance(e, Reading)][-1]
    assert stale.since_s == pytest.approx(last.time_s, abs=1e-6)
    assert 0.5 <= stale.time_s - stale.since_s < 0.6


class _StarvedSignals(_StarvedStream):
    """A sin/cos stream: a sample line per read, and read ``starved_at`` empty 1.5 s late."""

    def read(self, _n: int = 1) -> bytes:
        self.reads += 1
        if self.reads == self.starved_at:
            time.sleep(self.starved_s)
            return b""
        time.sleep(0.01)
        return b"0.1,0.2\n" * (150 if self.reads == self.starved_at + 1 else 1)


def test_a_signal_stream_worker_starved_after_an_empty_read_is_no_lost_link():
    """The fringe's signal stream worker judges its silence the same way."""
    from app.capture.signal_worker import SampleBlock, SignalStreamWorker
    from app.capture.worker import Fault

    port = _StarvedSignals()
    worker = SignalStreamWorker("FAKE", silence_s=1.0, retries=1, retry_pause_s=0.01,
                                opener=lambda _port, _baud: port).start()
    deadline = time.monotonic() + 10.0
    while time.monotonic() < deadline and port.reads < port.starved_at + 20:
        time.sleep(0.01)
    worker.stop()
    events = worker.drain()
    assert not any(isinstance(e, Fault) for e in events), [e for e in events
                                                           if isinstance(e, Fault)]
    assert sum(e.u_sin.size for e in events if isinstance(e, SampleBlock)) >= 150
