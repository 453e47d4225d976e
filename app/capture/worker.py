"""The worker thread that reads an instrument: it never blocks its caller, reconnects
after a fault, and keeps every reading.

Everything it learns goes into :attr:`CaptureWorker.events`, a queue the caller empties
when it likes (the command line in its loop, the window on a timer): a
:class:`Reading` per measurement, a :class:`Fault` per fault. A fault that the worker
recovers from (the link dropped, the instrument went quiet) is followed by a reconnection
and more readings; a ``final`` fault ends the worker (the port cannot be opened, or the
link failed ``retries`` times in a row without one reading in between). Readings already
queued stay queued whatever happens.
"""

from __future__ import annotations

import contextlib
import datetime as dt
import queue
import threading
import time
from dataclasses import dataclass

import serial

from app.capture.instruments import Instrument
from app.capture.link import CaptureError, open_link
from models.capture.errors import FrameError
from models.capture.framing import LineFramer
from models.messages import QT_TR_NOOP, message

__all__ = ["CaptureWorker", "Fault", "Reading"]


@dataclass(frozen=True)
class Reading:
    #: seconds since the worker started, when the frame's last byte arrived
    time_s: float
    values: tuple[float, ...]
    unit: str
    #: the instrument's line as it sent it
    raw: bytes
    #: its index among the lines the worker kept since the start (in
    #: :attr:`CaptureWorker.raw` at ``frame - raw_first``)
    frame: int = -1


@dataclass(frozen=True)
class Fault:
    #: a :class:`models.messages.Message`: English as a ``str``, translatable
    message: str
    final: bool


class _LinkLost(Exception):
    pass


class CaptureWorker:
    def __init__(self, port: str, instrument: Instrument, baud: int | None = None,
                 silence_s: float = 1.0, retries: int = 3, retry_pause_s: float = 0.2,
                 opener=open_link, raw_cap: int | None = None) -> None:
        self.port, self.instrument = port, instrument
        self.baud = baud or instrument.default_baud
        self.silence_s, self.retries, self.retry_pause_s = silence_s, retries, retry_pause_s
        self._open = opener
        self.events: queue.Queue[Reading | Fault] = queue.Queue()
        #: lines refused (noise, a wrong baud rate, an invalid axis, an error reply)
        self.refused = 0
        self.refusals: list[str] = []
        #: every line the instrument sent, as sent: (seconds since the start, the line,
        #: whether it became a reading); appended by the worker thread only
        self.raw: list[tuple[float, bytes, bool]] = []
        #: the index (since the start) of ``raw[0]``: frames a consumer has taken
        #: (:meth:`take_raw`) beyond ``raw_cap`` are dropped from memory
        self.raw_first = 0
        self.raw_cap = raw_cap
        self._raw_taken = 0
        self._raw_lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name=f"capture {port}", daemon=True)
        self._t0 = time.monotonic()
        #: when the worker started (UTC, ISO 8601): the raw frames' times count from it
        self.started_utc = ""

    def start(self) -> CaptureWorker:
        self._t0 = time.monotonic()
        self.started_utc = dt.datetime.now(dt.timezone.utc).isoformat()
        self._thread.start()
        return self

    def stop(self, wait_s: float = 2.0) -> None:
        self._stop.set()
        if self._thread.is_alive():
            self._thread.join(wait_s)

    def _keep(self, time_s: float, line: bytes, used: bool) -> int:
        """A line the instrument sent, kept; its index since the start."""
        with self._raw_lock:
            self.raw.append((time_s, line, used))
            return self.raw_first + len(self.raw) - 1

    def take_raw(self) -> list[tuple[float, bytes, bool]]:
        """The lines sent since the last call (the caller keeps them, e.g. in a journal);
        with ``raw_cap``, only the newest ``raw_cap`` lines stay in memory after it."""
        with self._raw_lock:
            new = self.raw[self._raw_taken - self.raw_first:]
            self._raw_taken = self.raw_first + len(self.raw)
            if self.raw_cap is not None and len(self.raw) > self.raw_cap:
                drop = len(self.raw) - self.raw_cap
                del self.raw[:drop]
                self.raw_first += drop
            return new

    @property
    def t0(self) -> float:
        """``time.monotonic()`` at the start: the readings' and raw frames' times count from it."""
        return self._t0

    @property
    def running(self) -> bool:
        return self._thread.is_alive()

    def _run(self) -> None:
        failures = 0
        while not self._stop.is_set():
            try:
                link = self._open(self.port, self.baud)
            except CaptureError as exc:
                failures += 1
                final = failures > self.retries
                self.events.put(Fault(exc.args[0], final))
                if final:
                    return
                self._stop.wait(self.retry_pause_s * failures)
                continue
            try:
                self._session(link)
                return
            except _LinkLost as exc:
                got = exc.args[1]
                failures = 1 if got else failures + 1
                final = failures > self.retries
                self.events.put(Fault(exc.args[0], final))
                if final:
                    return
                self._stop.wait(self.retry_pause_s)
            finally:
                self._close(link)

    def _close(self, link) -> None:
        with contextlib.suppress(serial.SerialException, OSError):
            if self.instrument.stop:
                link.write(self.instrument.stop)
        # pyserial's socket:// close() skips closing the socket when its shutdown fails (the
        # peer is gone): closed here too
        sock = getattr(link, "_socket", None)
        with contextlib.suppress(serial.SerialException, OSError):
            link.close()
        if sock is not None:
            with contextlib.suppress(OSError):
                sock.close()

    def _session(self, link) -> int:
        """Read until stopped (returns the number of readings) or until the link is lost
        (raises :class:`_LinkLost` with the reason and the number of readings)."""
        framer = LineFramer()
        instrument = self.instrument
        got = 0
        heard_bytes = False
        last_refusal = ""
        last_good = time.monotonic()
        asked_at: float | None = None
        try:
            link.reset_input_buffer()
            if instrument.start:
                link.write(instrument.start)
            while not self._stop.is_set():
                now = time.monotonic()
                if instrument.request is not None and (asked_at is None
                                                       or now - asked_at > self.silence_s / 4):
                    link.write(instrument.request)
                    asked_at = now
                data = link.read(link.in_waiting or 1)
                if data:
                    heard_bytes = True
                now = time.monotonic()
                for line in framer.feed(data):
                    try:
                        parsed = instrument.values(line)
                        if parsed is not None:
                            instrument.check_range(parsed[0])
                    except FrameError as exc:
                        self._keep(now - self._t0, line, False)
                        self.refused += 1
                        last_refusal = str(exc)
                        if len(self.refusals) < 20:
                            self.refusals.append(str(exc))
                        asked_at = None
                        continue
                    asked_at = None
                    index = self._keep(now - self._t0, line, parsed is not None)
                    if parsed is None:
                        continue
                    got += 1
                    last_good = now
                    self.events.put(Reading(now - self._t0, parsed[0], parsed[1], line, index))
                if now - last_good > self.silence_s:
                    seconds = f"{self.silence_s:g}"
                    if not heard_bytes:
                        what = message(QT_TR_NOOP("{port}: no answer for {seconds} s"),
                                       port=self.port, seconds=seconds)
                    elif not last_refusal or last_refusal.startswith("not text"):
                        what = message(QT_TR_NOOP("{port}: only unreadable bytes for {seconds} s "
                                                  "(a wrong baud rate? {baud} was used)"),
                                       port=self.port, seconds=seconds, baud=self.baud)
                    else:
                        what = message(QT_TR_NOOP("{port}: no valid reading for {seconds} s "
                                                  "(last: {reason})"), port=self.port,
                                       seconds=seconds, reason=last_refusal)
                    raise _LinkLost(what, got)
        except (serial.SerialException, OSError) as exc:
            reason = (str(exc).strip() or type(exc).__name__).splitlines()[0][:200]
            raise _LinkLost(message(QT_TR_NOOP("{port}: the link dropped ({reason})"),
                                    port=self.port, reason=reason), got) from None
        return got
