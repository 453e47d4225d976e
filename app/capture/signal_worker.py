"""The worker thread that reads a sin/cos signal stream and hands it on in blocks.

A stream of thousands of samples a second is not read as one event a sample (the capture
panel's :class:`app.capture.worker.CaptureWorker` does that for an instrument's few readings
a second): each read of the link becomes one :class:`SampleBlock` — the lines framed, the
samples they give as arrays (models/capture/signal_stream.py), which lines were refused —
put on :attr:`SignalStreamWorker.events`. The window empties the queue on its display
timer, whatever the stream's rate.

Every line the stream sends is in a block, refused ones included (the raw trace of a take).
A fault (the port cannot be opened, the link dropped, no sample for ``silence_s``) is a
:class:`app.capture.worker.Fault` on the same queue; the worker reconnects, and gives up
(a ``final`` fault) after ``retries`` failures in a row without a sample in between.
"""

from __future__ import annotations

import contextlib
import dataclasses
import queue
import threading
import time
from dataclasses import dataclass, field

import numpy as np
import serial

from app.capture.link import READ_BLOCK, TcpLink, open_link
from app.capture.worker import Fault, LinkLost, LinkThread, run_with_retries
from models.capture.framing import LineFramer
from models.capture.signal_stream import SignalLineParser
from models.messages import QT_TR_NOOP, message

__all__ = ["SampleBlock", "SignalStreamWorker"]

#: the default baud rate of a serial ADC stream
DEFAULT_BAUD = 115200


@dataclass
class SampleBlock:
    """The lines of one read of the link."""

    #: the index (since the worker started) of the block's first line
    first: int
    #: seconds since the worker started when the block arrived (each of its lines)
    time_s: float
    #: the lines as sent, and per line whether it became a sample
    lines: list[bytes]
    used: np.ndarray
    #: the samples (V), in the order of the lines that gave them
    u_sin: np.ndarray
    u_cos: np.ndarray
    refused: int = 0
    reasons: list[str] = field(default_factory=list)
    #: lines kept and not read that were not refused (a connection's first line: it may be
    #: the rest of a sample begun before the connection)
    stale: int = 0




class SignalStreamWorker(LinkThread):
    def __init__(self, port: str, pattern: str | None = None, baud: int | None = None,
                 silence_s: float = 2.0, retries: int = 3, retry_pause_s: float = 0.2,
                 opener=open_link) -> None:
        self.port = port
        self.parser = SignalLineParser(pattern)  # a bad pattern: ValueError here, at once
        self.pattern = pattern or ""
        self.baud = baud or DEFAULT_BAUD
        self.silence_s, self.retries, self.retry_pause_s = silence_s, retries, retry_pause_s
        self._open = opener
        self.events: queue.Queue[SampleBlock | Fault] = queue.Queue()
        #: lines framed, samples read and lines refused since the start
        self.lines = 0
        self.samples = 0
        self.refused = 0
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name=f"signals {port}", daemon=True)
        self._t0 = time.monotonic()
        self.started_utc = ""
        self._link = None
        self._link_lock = threading.Lock()


    def send(self, data: bytes) -> bool:
        """Write to the stream's link (a demonstration head's settings); False when no link
        is open or the write failed."""
        with self._link_lock:
            link = self._link
            if link is None:
                return False
            try:
                link.write(data)
            except (serial.SerialException, OSError):
                return False
        return True

    def drain(self, limit: int = 100_000) -> list[SampleBlock | Fault]:
        """What has arrived since the last call (at most ``limit`` events)."""
        out: list[SampleBlock | Fault] = []
        with contextlib.suppress(queue.Empty):
            while len(out) < limit:
                out.append(self.events.get_nowait())
        return out

    def _run(self) -> None:
        run_with_retries(self, self._held_session, self._release)

    def _held_session(self, link) -> None:
        with self._link_lock:
            self._link = link
        self._session(link)

    def _release(self, link) -> None:
        with self._link_lock:
            self._link = None
        with contextlib.suppress(serial.SerialException, OSError):
            link.close()

    def _read(self, link) -> bytes:
        if isinstance(link, TcpLink):
            return link.read(READ_BLOCK)
        return link.read(link.in_waiting or 1)

    def _session(self, link) -> None:
        framer = LineFramer()
        got = 0
        last_good = time.monotonic()
        heard = False
        joined = False  # whether the connection's first line has come
        stale = 0
        try:
            while not self._stop.is_set():
                # the silence is judged from this read: one begun after it has passed found
                # nothing (a thread starved past it reads first what came meanwhile: capture80)
                read_at = time.monotonic()
                data = self._read(link)
                now = time.monotonic()
                heard = heard or bool(data)
                lines = framer.feed(data)
                if lines:
                    parsed = self.parser.parse_lines(lines)
                    if not joined:
                        # the connection's first line may be the rest of a sample begun
                        # before it ("41 0.4964" of "0.0641 0.4964"): kept, not a sample
                        joined = True
                        if parsed.used[0]:
                            parsed = dataclasses.replace(
                                parsed, u_sin=parsed.u_sin[1:], u_cos=parsed.u_cos[1:],
                                used=np.concatenate([[False], parsed.used[1:]]))
                            stale = 1
                    block = SampleBlock(self.lines, now - self._t0, lines, parsed.used,
                                        parsed.u_sin, parsed.u_cos, parsed.refused,
                                        parsed.reasons, stale)
                    stale = 0
                    self.lines += len(lines)
                    self.samples += parsed.u_sin.size
                    self.refused += parsed.refused
                    self.events.put(block)
                    if parsed.u_sin.size:
                        got += parsed.u_sin.size
                        last_good = now
                if read_at - last_good > self.silence_s:
                    what = (QT_TR_NOOP("{port}: no answer for {seconds} s") if not heard else
                            QT_TR_NOOP("{port}: no valid sample for {seconds} s"))
                    raise LinkLost(message(what, port=self.port, seconds=f"{self.silence_s:g}"),
                                    got)
        except (serial.SerialException, OSError) as exc:
            reason = (str(exc).strip() or type(exc).__name__).splitlines()[0][:200]
            raise LinkLost(message(QT_TR_NOOP("{port}: the link dropped ({reason})"),
                                    port=self.port, reason=reason), got) from None
