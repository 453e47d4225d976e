"""The worker thread that reads an instrument: it never blocks its caller, reconnects
after a fault, and keeps every reading.

Everything it learns goes into :attr:`CaptureWorker.events`, a queue the caller empties
when it likes (the command line in its loop, the window on a timer): a
:class:`Reading` per measurement, a :class:`Fault` per fault (and, asked for with
``stale_s``, a :class:`Stale` when no reading has come for that long). A fault that the
worker recovers from (the link dropped, the instrument went quiet) is followed by a
reconnection and more readings; a ``final`` fault ends the worker (the port cannot be
opened, or the link failed ``retries`` times in a row without one reading in between).
Readings already queued stay queued whatever happens.

Silence is judged on the worker's own clock and only from a read it began after the
silence had passed: a thread starved of CPU (a loaded machine) that wakes to find time gone
by reads what arrived meanwhile before it says anything (capture80: the window's own timer,
which a starved worker cannot feed, said "link lost" for a link that never fell silent).
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
from app.capture.link import READ_BLOCK, CaptureError, TcpLink, open_link
from models.capture.errors import FrameError, NoMeasurement
from models.capture.framing import LineFramer
from models.messages import QT_TR_NOOP, message

__all__ = ["CaptureWorker", "DroppedLines", "Fault", "NoTarget", "Reading", "Stale"]


@dataclass(frozen=True)
class Reading:
    #: seconds since the worker started, when the frame's last byte arrived
    time_s: float
    values: tuple[float, ...]
    unit: str
    #: the instrument's line as it sent it
    raw: bytes
    #: its index among the lines the worker kept since the start (read back with
    #: :meth:`CaptureWorker.lines`)
    frame: int = -1


@dataclass(frozen=True)
class Fault:
    #: a :class:`models.messages.Message`: English as a ``str``, translatable
    message: str
    final: bool


@dataclass(frozen=True)
class NoTarget:
    """Frames arrive whole but carry no measurement (:class:`~models.capture.errors.
    NoMeasurement`: an autocollimator's mirror out of its view while the table turns): put
    once, at the first such frame after a reading (or the connection). The link is alive: it
    is not a :class:`Fault`, and the worker never reconnects for it; the next
    :class:`Reading` ends it."""

    #: seconds since the worker started, when the frame arrived
    time_s: float
    #: why the frame holds no measurement (English, as the worker's refusals)
    reason: str
    #: the instrument's columns (keys) concerned, the value beyond the range and the range
    #: (None: the instrument marks the axes not valid)
    columns: tuple[str, ...] = ()
    value: float | None = None
    limits: tuple[float, float] | None = None
    #: the frame's index among the lines the worker kept
    frame: int = -1


@dataclass(frozen=True)
class Stale:
    """No reading for the worker's ``stale_s`` on its own clock, found by a read it began
    after that time (frames with no measurement, or nothing, or only what makes no
    reading): the last reading is stale. Put once, until the next :class:`Reading`; not a
    :class:`Fault` — the link is given up only after its silence (:attr:`CaptureWorker.
    silence_s`), and a reading ends it."""

    #: seconds since the worker started, when the read that found no reading began
    time_s: float
    #: seconds since the worker started, of the last reading (or of the connection)
    since_s: float


class DroppedLines(LookupError):
    """Lines asked of a worker that it has dropped from memory (:meth:`CaptureWorker.lines`)."""


class LinkLost(Exception):
    """The link ended during a session: (its message, the readings it gave)."""




def run_with_retries(worker, session, close) -> None:
    """Open ``worker``'s link and run ``session(link)`` on it until it returns, opening it
    again after a fault (a :class:`LinkLost` that gave readings starts the count afresh);
    each fault is put on ``worker.events`` as a :class:`Fault`, the last one final after
    ``worker.retries``. ``close(link)`` after every session. Shared by the readings' and the
    signal stream's workers."""
    failures = 0
    while not worker._stop.is_set():
        try:
            link = worker._open(worker.port, worker.baud)
        except CaptureError as exc:
            failures += 1
            final = failures > worker.retries
            worker.events.put(Fault(exc.args[0], final))
            if final:
                return
            worker._stop.wait(worker.retry_pause_s * failures)
            continue
        try:
            session(link)
            return
        except LinkLost as exc:
            failures = 1 if exc.args[1] else failures + 1
            final = failures > worker.retries
            worker.events.put(Fault(exc.args[0], final))
            if final:
                return
            worker._stop.wait(worker.retry_pause_s)
        finally:
            close(link)


class LinkThread:
    """A worker's thread on a link: started (its clock and UTC start kept), stopped, asked
    whether it runs. The readings' and the signal stream's workers share it."""

    def start(self):
        self._t0 = time.monotonic()
        self.started_utc = dt.datetime.now(dt.timezone.utc).isoformat()
        self._thread.start()
        return self

    def stop(self, wait_s: float = 2.0) -> None:
        self._stop.set()
        if self._thread.is_alive():
            self._thread.join(wait_s)

    @property
    def running(self) -> bool:
        return self._thread.is_alive()


class CaptureWorker(LinkThread):
    def __init__(self, port: str, instrument: Instrument, baud: int | None = None,
                 silence_s: float = 1.0, retries: int = 3, retry_pause_s: float = 0.2,
                 opener=open_link, reply_timeout_s: float | None = None,
                 poll_interval_s: float = 0.0, raw_cap: int | None = None,
                 request_interval_s: float = 0.0, stale_s: float | None = None) -> None:
        self.port, self.instrument = port, instrument
        self.baud = baud or instrument.default_baud
        self.silence_s, self.retries, self.retry_pause_s = silence_s, retries, retry_pause_s
        #: how long a request waits for its reply before it counts as a fault (default: the
        #: silence); the next request waits for the reply or this
        self.reply_timeout_s = silence_s if reply_timeout_s is None else reply_timeout_s
        #: the least time between two single-shot requests to a streaming instrument that is
        #: polled (an instrument that only answers requests: :attr:`request_interval_s`)
        self.poll_interval_s = poll_interval_s
        #: the least time between two requests to an instrument that only answers requests (a
        #: readout, a theodolite): with none, one that answers at once is asked again at once
        #: (#62 review: a readout polled at ~8.7 kHz, 2 M frames in a morning's record)
        self.request_interval_s = request_interval_s
        #: no reading for this long (its own clock) puts a :class:`Stale` (None: never)
        self.stale_s = stale_s
        #: requests sent, reply timeouts, lines found in a serial port's buffer at connection
        self.requests = 0
        self.timeouts = 0
        self.stale_at_connect = 0
        #: requests numbered over the worker's whole life, not per connection: a late reply to
        #: the last connection's request 1 would otherwise match this one's request 1
        self._transactions = 0
        #: whether a connection of this worker has read a streamed frame
        self._streamed = False
        #: the instrument did not stream when asked to and is read by single-shot requests
        self.polling = False
        self._open = opener
        self.events: queue.Queue[Reading | Fault | NoTarget | Stale] = queue.Queue()
        #: lines refused (noise, a wrong baud rate, an invalid axis, an error reply)
        self.refused = 0
        self.refusals: list[str] = []
        #: the lines the instrument sent that are still in memory, as sent: (seconds since the
        #: start, the line, whether it became a reading); appended by the worker thread only.
        #: Read them with :meth:`lines` (indices since the start, under the lock): lines
        #: before ``raw_first`` have been dropped
        self.raw: list[tuple[float, bytes, bool]] = []
        #: the index (since the start) of ``raw[0]``: lines a consumer has taken
        #: (:meth:`take_raw`) beyond ``raw_cap``, or said it no longer needs
        #: (:meth:`release`), are dropped from memory
        self.raw_first = 0
        self.raw_cap = raw_cap
        self._raw_taken = 0
        self._raw_lock = threading.RLock()  # take_raw reads and releases under it
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name=f"capture {port}", daemon=True)
        self._t0 = time.monotonic()
        #: when the worker started (UTC, ISO 8601): the raw frames' times count from it
        self.started_utc = ""


    def _keep(self, time_s: float, line: bytes, used: bool) -> int:
        """A line the instrument sent, kept; its index since the start."""
        with self._raw_lock:
            self.raw.append((time_s, line, used))
            return self.raw_first + len(self.raw) - 1

    @property
    def raw_end(self) -> int:
        """The index (since the start) after the newest line kept: the lines sent so far."""
        with self._raw_lock:
            return self.raw_first + len(self.raw)

    def lines(self, start: int, stop: int | None = None) -> list[tuple[float, bytes, bool]]:
        """The lines ``start`` … ``stop - 1`` (indices since the start; ``stop`` None or past
        the newest: up to the newest), a copy. :class:`DroppedLines` when one of them has
        been dropped from memory (never a slice of other lines)."""
        with self._raw_lock:
            end = self.raw_first + len(self.raw)
            stop = end if stop is None else min(stop, end)
            if start >= stop:
                return []
            if start < self.raw_first:
                raise DroppedLines(f"{self.port}: raw lines {start}…{stop - 1} asked for, lines "
                                   f"before {self.raw_first} were dropped from memory")
            return self.raw[start - self.raw_first:stop - self.raw_first]

    def release(self, before: int) -> int:
        """The lines before index ``before`` (since the start) are no longer needed: dropped
        from memory (``raw_first`` moves on; the indices of the others stay as they are).
        The number dropped."""
        with self._raw_lock:
            drop = min(before, self.raw_first + len(self.raw)) - self.raw_first
            if drop <= 0:
                return 0
            del self.raw[:drop]
            self.raw_first += drop
            return drop

    def take_raw(self) -> list[tuple[float, bytes, bool]]:
        """The lines sent since the last call (the caller keeps them, e.g. in a journal);
        with ``raw_cap``, only the newest ``raw_cap`` lines stay in memory after it."""
        with self._raw_lock:
            end = self.raw_first + len(self.raw)
            new = self.lines(self._raw_taken, end)
            self._raw_taken = end
            if self.raw_cap is not None and len(self.raw) > self.raw_cap:
                self.release(end - self.raw_cap)
            return new

    @property
    def t0(self) -> float:
        """``time.monotonic()`` at the start: the readings' and raw frames' times count from it."""
        return self._t0


    def _run(self) -> None:
        run_with_retries(self, self._session, self._close)

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

    def _read(self, link) -> bytes:
        """What has arrived, in one block (a serial port: what it says is waiting; a TCP link
        reads a block of whatever it holds)."""
        if isinstance(link, TcpLink):
            return link.read(READ_BLOCK)
        return link.read(link.in_waiting or 1)

    def _waiting_at_connect(self, link, framer: LineFramer) -> tuple[list[bytes], bool]:
        """A serial port's bytes received before this session asked for anything (old frames
        in the driver's buffer): read, not discarded, so the raw trace keeps them; and
        whether they end inside a line (its start stays in ``framer``: the rest arrives
        with the session's first bytes, and that line is an old one, not a reply — a
        readout's "+105.00012 deg" whose "+10" was waiting became a reading of 5.00012). A
        socket has none from before its connection: its first bytes are read as they come."""
        if isinstance(link, TcpLink):
            return [], False
        data = link.read(link.in_waiting) if link.in_waiting else b""
        return framer.feed(data), bool(data) and not data.endswith((b"\r", b"\n"))

    def _no_reading_message(self, heard_bytes: bool, last_refusal: str, timed_out: bool,
                            answered: bool = False):
        """Why no reading came: of the bytes since the last reading (``heard_bytes``,
        ``last_refusal``); ``answered``: the connection read a reading before."""
        seconds = f"{self.silence_s:g}"
        if not heard_bytes and not (timed_out and answered):
            return message(QT_TR_NOOP("{port}: no answer for {seconds} s"), port=self.port,
                           seconds=seconds)
        if timed_out:
            return message(QT_TR_NOOP("{port}: no reply to a request within {seconds} s (the "
                                      "reply timeout)"), port=self.port,
                           seconds=f"{self.reply_timeout_s:g}")
        if not last_refusal or last_refusal.startswith("not text"):
            return message(QT_TR_NOOP("{port}: only unreadable bytes for {seconds} s "
                                      "(a wrong baud rate? {baud} was used)"),
                           port=self.port, seconds=seconds, baud=self.baud)
        return message(QT_TR_NOOP("{port}: no valid reading for {seconds} s (last: {reason})"),
                       port=self.port, seconds=seconds, reason=last_refusal)

    def _session(self, link) -> int:
        """Read until stopped (returns the number of readings) or until the link is lost
        (raises :class:`LinkLost` with the reason and the number of readings).

        An instrument that is asked gets one request at a time: the next goes out when the
        reply to the last has come (a reading, a refused reply, device information) and
        :attr:`poll_interval_s` (polling a streaming instrument) or :attr:`request_interval_s`
        (an instrument that is asked) has passed since the last was sent, or — a fault with its
        own message, then a reconnection — when :attr:`reply_timeout_s` has passed with no
        reply. A reply that carries another transaction id than the request in flight is an
        old request's, kept in the raw trace and not read. While a request waits within its
        timeout, the instrument is not silent.
        """
        framer = LineFramer()
        instrument = self.instrument
        got = 0
        heard_bytes = False
        #: when the worker first read bytes since the last reading (None: none since): bytes
        #: are "unreadable" once they have come for the silence without making a reading, not
        #: when the first byte of a line is read late (a loaded machine starved this thread
        #: past the silence; its read returned the line's first byte, the rest waiting: "only
        #: unreadable bytes for 0.2 s (a wrong baud rate?)" and a reconnection, flake79)
        heard_from: float | None = None
        last_refusal = ""
        start = last_good = time.monotonic()
        #: the last whole frame that carried no measurement (a mirror out of view): the
        #: instrument is heard, not silent; and whether NoTarget was put since the last reading
        last_no_target = start
        out_of_view = False
        in_flight: float | None = None  # when the request in flight was sent
        stale_said = False  # Stale put since the last reading
        heard_since_request = False
        asked_at = -1e9
        lines = 0  # lines framed in this session
        expected: int | None = None  # the transaction id of the request in flight
        polling = instrument.request is None and instrument.poll is not None and (
            instrument.mode == "poll" or self.polling)
        try:
            waiting, begun = self._waiting_at_connect(link, framer)
            for line in waiting:
                self._keep(time.monotonic() - self._t0, line, False)
                self.stale_at_connect += 1
            # the first line of a connection may be the rest of a line the instrument began
            # before it: a line waiting half-read at the connection, or a stream joined while
            # a frame was on its way (a serial port or a network bridge alike). It is kept in
            # the raw trace, not read, where such a rest could pass for a reading
            # (Instrument.tail_parses). An instrument that is asked starts no line unasked,
            # unless one was waiting.
            partial_first = begun or (instrument.request is None and not polling
                                      and instrument.tail_parses)
            if instrument.start and not polling:
                link.write(instrument.start)
            while not self._stop.is_set():
                now = time.monotonic()
                if (not polling and instrument.mode == "auto" and instrument.poll is not None
                        and instrument.request is None and lines == 0 and not self._streamed
                        and now - start > min(instrument.stream_wait_s, self.silence_s / 2)):
                    # no frame since the stream was asked for: the instrument answers single
                    # shots (not one that has streamed on an earlier connection: it is silent
                    # for another reason, and polled for good it stalled an auto-take)
                    polling = self.polling = True
                    partial_first = begun  # its replies follow requests
                    if instrument.stop:
                        link.write(instrument.stop)
                ask = instrument.poll if polling else instrument.request_bytes(self._transactions + 1)
                interval = self.poll_interval_s if polling else self.request_interval_s
                if ask is not None and in_flight is None and now - asked_at >= interval:
                    self._transactions += 1
                    link.write(ask)
                    self.requests += 1
                    in_flight = asked_at = now
                    heard_since_request = False
                    expected = None if polling else instrument.transaction_of(self._transactions)
                # the silence is judged from this read: one begun after it has passed
                # found nothing (a thread starved past it reads first what came meanwhile)
                read_at = time.monotonic()
                data = self._read(link)
                now = time.monotonic()
                if data:
                    heard_bytes = heard_since_request = True
                    if heard_from is None:
                        heard_from = now
                for line in framer.feed(data):
                    lines += 1
                    if partial_first:
                        partial_first = False
                        self._keep(now - self._t0, line, False)
                        self.stale_at_connect += 1
                        continue
                    if ask is not None:
                        trid = instrument.reply_transaction(line)
                        stale = ""
                        if in_flight is None:
                            stale = "a reply with no request in flight"
                        elif expected is not None and trid is not None and trid != expected:
                            stale = (f"reply to an earlier request (transaction {trid}, waiting "
                                     f"for {expected})")
                        if stale:
                            self._keep(now - self._t0, line, False)
                            self.refused += 1
                            self._refusal(stale)
                            last_refusal = stale  # said if no reading follows (not "a wrong baud")
                            continue
                    in_flight = None
                    try:
                        parsed = instrument.values(line)
                        if parsed is not None:
                            instrument.check_range(parsed[0])
                    except FrameError as exc:
                        kept = self._keep(now - self._t0, line, False)
                        self.refused += 1
                        self._refusal(str(exc))
                        if isinstance(exc, NoMeasurement):
                            # the instrument is there, seeing no target: said once, never a
                            # fault of the link (live76 F3)
                            last_no_target = now
                            if not out_of_view:
                                out_of_view = True
                                self.events.put(NoTarget(now - self._t0, str(exc), exc.columns,
                                                         exc.value, exc.limits, kept))
                            continue
                        last_refusal = str(exc)
                        continue
                    index = self._keep(now - self._t0, line, parsed is not None)
                    if parsed is None:
                        continue
                    got += 1
                    last_good = now
                    out_of_view = stale_said = False
                    # what a silence after this says is of the bytes since it: a link that read
                    # well and went quiet is "no answer", not "only unreadable bytes"
                    heard_bytes, last_refusal, heard_from = False, "", None
                    if ask is None:
                        self._streamed = True
                    self.events.put(Reading(now - self._t0, parsed[0], parsed[1], line, index))
                waiting = in_flight is not None and read_at - in_flight <= self.reply_timeout_s
                timed_out = (in_flight is not None and not waiting)
                if timed_out and not heard_since_request:
                    self.timeouts += 1
                    raise LinkLost(self._no_reading_message(heard_bytes, last_refusal, True,
                                                            got > 0), got)
                # only silence (or nothing whole) is a fault: frames with no measurement
                # are an instrument that sees no target; bytes read since the last reading
                # are given the silence from the first of them to make one
                first_byte = last_good if heard_from is None else heard_from
                if self.stale_s is not None and not stale_said \
                        and read_at - last_good > self.stale_s:
                    stale_said = True
                    self.events.put(Stale(read_at - self._t0, last_good - self._t0))
                if read_at - max(last_good, last_no_target, first_byte) \
                        > self.silence_s and not waiting:
                    raise LinkLost(self._no_reading_message(heard_bytes, last_refusal, False), got)
        except (serial.SerialException, OSError) as exc:
            reason = (str(exc).strip() or type(exc).__name__).splitlines()[0][:200]
            raise LinkLost(message(QT_TR_NOOP("{port}: the link dropped ({reason})"),
                                    port=self.port, reason=reason), got) from None
        return got

    def _refusal(self, text: str) -> None:
        if len(self.refusals) < 20:
            self.refusals.append(text)
