"""Demonstration instruments (Instrument › Demonstration instrument…, ``anglebench simulate``)
and the tests' simulators: instruments that are not there: an ELCOMAT-kind autocollimator, a GeoCOM theodolite
and a line readout, answering on a pseudo-terminal (``os.openpty``) or on a TCP port
of 127.0.0.1, as their published protocols say. Written from the protocols, not from
the drivers (nothing here imports ``models.capture`` or ``app.capture``), so a driver
that misreads the protocol fails against them.

Fault modes (``faults``): ``noise`` (garbage bytes and lines between frames),
``invalid_axes`` (every third frame marked invalid: an axis's status digit, or
GeoCOM's return code 1284, a readout's error line), ``silence`` (never answers),
``disconnect`` (the link drops after ``disconnect_after`` frames, and again every
``disconnect_every`` frames when that is set: a TCP client is cut off and a new one
accepted; on a pty, as with a pulled cable, nothing goes either way for ``gap_s``),
``wrong_baud`` (what a link at the wrong speed delivers: only garbage bytes).

A slow instrument (``reply_delay_s``) works through the requests it receives one after
the other, each taking that long, and answers each with the position at the moment it
answers; ``max_pending`` records the most requests it held unanswered at once (a client
that keeps one request in flight never makes it more than 1).

The instrument's position is a script: ``positions`` each held ``hold_s`` seconds, with
Gaussian noise of ``sigma`` (arcsec, or the readout's unit) on every frame and a drift of
``drift_per_s`` (the same unit per second since the start; 0: none).
``sent`` records every measurement frame written whole (value, or None for an
invalid one), so a test can check that none is lost.
"""

from __future__ import annotations

import contextlib
import math
import os
import random
import select
import socket
import threading
import time
import tty
from collections import deque

__all__ = ["SIMULATORS", "AutocollimatorSimulator", "ReadHeadSimulator", "ReadoutSimulator",
           "TheodoliteSimulator"]


class _Simulator:
    #: what ends one command the instrument receives
    command_end = b"\n"

    def __init__(self, transport: str = "pty", faults: tuple[str, ...] = (),
                 positions=((0.0, 0.0),), hold_s: float = 1e9, sigma: float = 0.0,
                 disconnect_after: int = 5, gap_s: float = 0.3, rate_hz: float = 250.0,
                 seed: int = 34, disconnect_every: int = 0, drift_per_s: float = 0.0,
                 tcp_port: int = 0, reply_delay_s: float = 0.0) -> None:
        self.transport, self.faults = transport, set(faults)
        self.positions, self.hold_s, self.sigma = list(positions), hold_s, sigma
        self.disconnect_after, self.gap_s, self.rate_hz = disconnect_after, gap_s, rate_hz
        #: with ``disconnect``: drop the link again every this many frames (0: once)
        self.disconnect_every = disconnect_every
        self.drift_per_s = drift_per_s
        #: with ``transport="tcp"``: the port of 127.0.0.1 to listen on (0: any free one)
        self.tcp_port = tcp_port
        self.cuts = 0
        #: seconds each request takes to answer; requests wait their turn
        self.reply_delay_s = reply_delay_s
        self.max_pending = 0
        self.rng = random.Random(seed)
        self.sent: list = []
        self.received: list[bytes] = []
        self._stop = threading.Event()
        self._frames = 0
        self._disconnected = False
        self._streaming = False

    # ------------------------------------------------------------ the link
    def __enter__(self):
        if self.transport == "pty":
            self._master, self._slave = os.openpty()
            tty.setraw(self._slave)
            tty.setraw(self._master)
            self.port = os.ttyname(self._slave)
        else:
            self._server = socket.socket()
            self._server.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
            self._server.bind(("127.0.0.1", self.tcp_port))
            self._server.listen(1)
            self.port = f"tcp://127.0.0.1:{self._server.getsockname()[1]}"
        self._start = time.monotonic()
        self._thread = threading.Thread(target=self._serve, daemon=True)
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop.set()
        self._thread.join(5)
        if self.transport == "pty":
            os.close(self._master)
            os.close(self._slave)
        else:
            self._server.close()

    def _serve(self) -> None:
        if self.transport == "pty":
            self._serve_link(self._master, os.read, os.write)
            return
        self._server.settimeout(0.05)
        while not self._stop.is_set():
            try:
                client, _ = self._server.accept()
            except OSError:
                continue
            with client:
                self._serve_link(client, lambda c, n: c.recv(n), lambda c, d: c.sendall(d))
                with contextlib.suppress(OSError):
                    client.shutdown(socket.SHUT_RDWR)

    def _serve_link(self, link, read, write) -> None:
        """Until stopped, or (TCP) until the link drops."""
        pending = b""
        next_frame = time.monotonic()
        queued: list[tuple[float, bytes]] = []  # (when it is answered, the request)
        while not self._stop.is_set():
            while queued and time.monotonic() >= queued[0][0]:
                _, one = queued.pop(0)
                for reply in self.answer(one):
                    if not self._write(link, write, reply):
                        return
            ready, _, _ = select.select([link], [], [], 0.002)
            if ready:
                try:
                    data = read(link, 4096)
                except OSError:
                    return
                if not data:
                    return
                pending += data
                while self.command_end in pending:
                    one, pending = pending.split(self.command_end, 1)
                    self.received.append(one)
                    if "silence" in self.faults or self._gap():
                        continue
                    if self.reply_delay_s > 0:
                        start = max([time.monotonic()] + [due for due, _ in queued[-1:]])
                        queued.append((start + self.reply_delay_s, one))
                        self.max_pending = max(self.max_pending, len(queued))
                        continue
                    self.max_pending = max(self.max_pending, 1)
                    for reply in self.answer(one):
                        if not self._write(link, write, reply):
                            return
            if self._streaming and time.monotonic() >= next_frame:
                next_frame += 1.0 / self.rate_hz
                if not ("silence" in self.faults or self._gap()):
                    frame = self.stream_frame()
                    if frame is not None and not self._write(link, write, frame):
                        return
            if self._cut_now():
                if self.transport == "tcp":
                    self._streaming = False
                    return
                self._gap_until = time.monotonic() + self.gap_s

    _gap_until = 0.0

    def _gap(self) -> bool:
        return time.monotonic() < self._gap_until

    def _cut_now(self) -> bool:
        if "disconnect" in self.faults and not self._disconnected \
                and self._frames >= self.disconnect_after:
            self._disconnected = not self.disconnect_every
            self.disconnect_after = self._frames + self.disconnect_every
            self.cuts += 1
            return True
        return False

    def _write(self, link, write, reply: bytes) -> bool:
        if "wrong_baud" in self.faults:
            reply = bytes(self.rng.randrange(128, 256) for _ in reply)
        if "noise" in self.faults and self.rng.random() < 0.3:
            reply = bytes(self.rng.randrange(256) for _ in range(self.rng.randrange(1, 30))) \
                + self.line_end + reply
        try:
            write(link, reply)
        except OSError:
            return False
        return True

    def position(self) -> tuple[float, ...]:
        index = min(int((time.monotonic() - self._start) / self.hold_s), len(self.positions) - 1)
        return tuple(self.positions[index])

    def noisy(self, value: float) -> float:
        return value + (self.rng.gauss(0.0, self.sigma) if self.sigma else 0.0) + self.drift()

    def drift(self) -> float:
        """The drift since the start (the noise's unit)."""
        return self.drift_per_s * (time.monotonic() - self._start) if self.drift_per_s else 0.0

    def invalid_now(self) -> bool:
        return "invalid_axes" in self.faults and self._frames % 3 == 2

    def answer(self, command: bytes) -> list[bytes]:
        raise NotImplementedError

    def stream_frame(self) -> bytes | None:
        return None


class AutocollimatorSimulator(_Simulator):
    """Commands end in LF, replies in CR (see the module's docstring of the protocol).
    ``streams=False``: a model that answers single shots (``a``, ``r``) only and says
    nothing to ``A``/``R``, as some ELCOMAT 3000 firmware does."""

    command_end = b"\n"
    line_end = b"\r"

    def __init__(self, *args, streams: bool = True, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.streams = streams

    def _measurement(self, code: str) -> bytes:
        x, y = (self.noisy(v) for v in self.position())
        axes = "3"
        if self.invalid_now():
            axes = "120"[(self._frames // 3) % 3]  # y lost, x lost, both lost in turn
        self._frames += 1
        self.sent.append((x if axes in "13" else None, y if axes in "23" else None))
        return f"{code} 00{axes} {x:.3f} {y:.3f}\r".encode()

    def answer(self, command: bytes) -> list[bytes]:
        command = command.strip()
        if command in (b"a", b"r"):
            return [self._measurement("4" if command == b"a" else "2")]
        if command in (b"A", b"R"):
            self._streaming, self._code = self.streams, ("3" if command == b"A" else "1")
            return []
        if command == b"s":
            self._streaming = False
            return []
        if command == b"d":
            return [b"8 40123 15 6 2021 300\r"]
        return []

    def stream_frame(self) -> bytes:
        return self._measurement(self._code)


class TheodoliteSimulator(_Simulator):
    """Leica GeoCOM: ``%R1Q,rpc[,trid]:params`` CR LF in, ``%R1P,0,trid:rc,…`` CR LF out
    (the transaction id echoed, 0 when the request has none; ``omit_trid`` answers
    ``%R1P,0:rc,…`` without one, which the reference's syntax allows). ``positions`` are
    (Hz, V) in degrees.

    Besides the angles (TMC_GetAngle1, 2003; TMC_GetAngle5, 2107) it answers what a client
    asks when it connects, as an instrument does: COM_NullProc (0), COM_GetDoublePrecision
    (108), COM_GetSWVersion (110), CSV_GetInstrumentNo (5003), CSV_GetInstrumentName (5004)
    and CSV_GetSWVersion (5034); any other procedure with GRC_UNDEFINED (1)."""

    command_end = b"\r\n"
    line_end = b"\r\n"
    #: the connection calls' replies after the return code
    IDENTITY = {0: "", 108: ",15", 110: ",1,50,0", 5003: ",1234567", 5004: ',"TM50 0.5"',
                5034: ",3,10,0"}

    def __init__(self, *args, omit_trid: bool = False, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.omit_trid = omit_trid

    def _reply(self, trid: int, rest: str) -> bytes:
        head = "%R1P,0" if self.omit_trid else f"%R1P,0,{trid}"
        return f"{head}:{rest}\r\n".encode()

    def answer(self, command: bytes) -> list[bytes]:
        text = command.decode("ascii", "replace").strip()
        if not text.startswith("%R1Q,") or ":" not in text:
            return []
        head = text[5:].split(":", 1)[0].split(",")
        rpc, trid = int(head[0]), (int(head[1]) if len(head) > 1 else 0)
        if rpc in self.IDENTITY:
            return [self._reply(trid, "0" + self.IDENTITY[rpc])]
        if rpc not in (2003, 2107):
            return [self._reply(trid, "1")]  # GRC_UNDEFINED for anything else
        # sigma in arcseconds on each angle
        hz, v = (math.radians(d + ((self.rng.gauss(0.0, self.sigma) if self.sigma else 0.0)
                                   + self.drift()) / 3600.0)
                 for d in self.position())
        hz %= 2 * math.pi  # the horizontal circle reads 0 to 2π
        bad = self.invalid_now()
        self._frames += 1
        rc = 1284 if bad else 0
        self.sent.append(None if bad else (math.degrees(hz), math.degrees(v)))
        values = f"{hz:.10f},{v:.10f}"
        if rpc == 2003:
            values += ",0.0000048,12345678,0.00001,-0.00002,0.0000048,12345670,0"
        return [self._reply(trid, f"{rc},{values}")]


class ReadoutSimulator(_Simulator):
    """Answers STX with one line ``  +105.00012 deg`` CR LF (ND 28x style)."""

    command_end = b"\x02"
    line_end = b"\r\n"

    def __init__(self, *args, unit: str = "deg", **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.unit = unit

    def answer(self, command: bytes) -> list[bytes]:
        bad = self.invalid_now()
        self._frames += 1
        if bad:
            self.sent.append(None)
            return [b"ERROR 02\r\n"]
        value = self.noisy(self.position()[0])
        self.sent.append(round(value, 5))
        return [f"{value:+.5f} {self.unit}\r\n".encode()]


class ReadHeadSimulator(_Simulator):
    """An incremental encoder's read head over its scale, as a technician mounts it: the
    two channel voltages it gives, streamed as an ADC does (``u_sin,u_cos`` LF, one line a
    sample, from the moment a client connects), computed from the head's geometry.

    **The head** (a reflective scale of period ``period_um``, a four-field scanning reticle
    as in the makers' open-loop heads): field k = 0…3 lies at ``y_k = (k − 1.5)·field_pitch``
    along the lines and is phase-shifted by k·90°; its photocurrent is
    ``E_k·[1 + m_k·(sin ψ_k + h3·sin 3ψ_k)]``, ``ψ_k = θ − k·π/2 + δ_k``, θ the true phase
    (2π × the scale's displacement / period). The channels are the differences
    ``u_sin = R·(I_0 − I_2)``, ``u_cos = R·(I_3 − I_1)``, R set so that the head at its
    nominal mounting gives 1 Vpp.

    * **gap** g: the fringe contrast falls as the gap leaves its nominal ``g0``,
      ``m = m0·exp(−((g − g0)/gap_width)²)``, and the third harmonic of the fringe grows
      with it (``h3 = 0.005 + 0.04·((g − g0)/gap_width)²``).
    * **yaw** (rotation about the scale's normal, the moiré angle): a field at ``y_k`` sees
      the lines displaced by ``y_k·tan yaw``, ``δ_k = 2π·y_k·tan(yaw)/period``, so the two
      channels' fields no longer sit 90° apart; over a field's own length the fringe is
      averaged, its contrast times ``sinc(field_length·tan(yaw)/period)``.
    * **roll** (tilt about the measuring direction): the light reflected by the scale lands
      displaced by ``2·g·tan(roll)`` on the fields, each field's illumination following the
      beam's Gaussian profile (``beam_width`` w; the fields' areas balance it for a square
      head): ``E_k = exp((y_k² − (y_k − 2g·tan roll)²)/(2·w²))``; unequal light in a
      channel's two fields is that channel's offset, and the channels' amplitudes part.
    * ``dirt``: a stain on the scale dims the light of every field by ``dirt`` (0…1) over
      ``dirt_periods`` periods once a revolution of ``periods_per_rev`` periods.

    The scale moves at ``signal_hz`` periods a second (``wobble``: relative speed
    variation at 0.7 Hz, a hand that turns the shaft); ``sample_hz`` samples a second with
    Gaussian noise of ``noise_mv`` on each channel. The settings change while it streams
    (:meth:`set`, or a line ``gap 0.9`` / ``yaw 2`` / ``roll -5`` sent to it; gap in mm, yaw
    and roll in mrad). ``history`` keeps the last samples sent with their true phase:
    ``(θ_rad, u_sin, u_cos)``.
    """

    command_end = b"\n"
    line_end = b"\n"
    #: the settings a line ``NAME VALUE`` changes, with their bounds
    SETTINGS = {"gap": (0.0, 5.0), "yaw": (-100.0, 100.0), "roll": (-200.0, 200.0),
                "dirt": (0.0, 1.0), "noise": (0.0, 1000.0), "speed": (-10000.0, 10000.0)}

    def __init__(self, *args, gap_mm: float = 0.8, yaw_mrad: float = 0.0,
                 roll_mrad: float = 0.0, dirt: float = 0.0, noise_mv: float = 1.0,
                 signal_hz: float = 20.0, sample_hz: float = 5000.0, wobble: float = 0.0,
                 period_um: float = 20.0, gap_nominal_mm: float = 0.8,
                 gap_width_mm: float = 0.25, field_pitch_mm: float = 0.15,
                 field_length_mm: float = 1.0, beam_width_mm: float = 0.4,
                 contrast: float = 0.6, periods_per_rev: int = 2048,
                 dirt_periods: float = 40.0, history: int = 200_000, **kwargs) -> None:
        super().__init__(*args, **kwargs)
        self.gap_mm, self.yaw_mrad, self.roll_mrad = gap_mm, yaw_mrad, roll_mrad
        self.dirt, self.noise_mv, self.signal_hz = dirt, noise_mv, signal_hz
        self.sample_hz, self.wobble = sample_hz, wobble
        self.period_um, self.gap_nominal_mm, self.gap_width_mm = (period_um, gap_nominal_mm,
                                                                  gap_width_mm)
        self.field_pitch_mm, self.field_length_mm = field_pitch_mm, field_length_mm
        self.beam_width_mm, self.contrast = beam_width_mm, contrast
        self.periods_per_rev, self.dirt_periods = periods_per_rev, dirt_periods
        self.history: deque = deque(maxlen=history)
        self._lock = threading.Lock()
        self._samples = 0
        self._phase_turns = 0.0  # the true phase, in periods, at the last sample
        self._clock: float | None = None
        # the transimpedance: 1 Vpp (0.5 V amplitude) at the nominal mounting
        self._gain = 1.0
        ideal, _ = self.channels([2 * math.pi * i / 4096 for i in range(4096)],
                                 gap_mm=gap_nominal_mm, yaw_mrad=0.0, roll_mrad=0.0, dirt=0.0)
        self._gain = 0.5 / (0.5 * (max(ideal) - min(ideal)))

    # the stream starts when a client connects: the base's flag is always on
    @property
    def _streaming(self) -> bool:
        return True

    @_streaming.setter
    def _streaming(self, _value: bool) -> None:
        pass

    def set(self, **settings: float) -> None:
        """Change the mounting while it streams (gap_mm, yaw_mrad, roll_mrad, dirt,
        noise_mv, signal_hz)."""
        with self._lock:
            for name, value in settings.items():
                if not hasattr(self, name):
                    raise AttributeError(name)
                setattr(self, name, float(value))

    def channels(self, theta_rad, gap_mm=None, yaw_mrad=None, roll_mrad=None, dirt=None,
                 position_turns=None):
        """The noiseless (u_sin, u_cos) in volts at the true phases ``theta_rad``, the head
        mounted as set (or as given)."""
        gap = self.gap_mm if gap_mm is None else gap_mm
        yaw = 1e-3 * (self.yaw_mrad if yaw_mrad is None else yaw_mrad)  # rad
        roll = 1e-3 * (self.roll_mrad if roll_mrad is None else roll_mrad)
        dirt = self.dirt if dirt is None else dirt
        period_mm = self.period_um * 1e-3
        excess = (gap - self.gap_nominal_mm) / self.gap_width_mm
        contrast = self.contrast * math.exp(-excess ** 2)
        if yaw:
            x = math.pi * self.field_length_mm * math.tan(yaw) / period_mm
            contrast *= abs(math.sin(x) / x)
        h3 = 0.005 + 0.04 * min(excess ** 2, 4.0)
        spot = 2.0 * max(gap, 0.0) * math.tan(roll)
        fields = []
        for k in range(4):
            y = (k - 1.5) * self.field_pitch_mm
            # the fields' areas are balanced for the beam of a head mounted square
            fields.append((math.exp((y ** 2 - (y - spot) ** 2) / (2.0 * self.beam_width_mm ** 2)),
                           2.0 * math.pi * y * math.tan(yaw) / period_mm - k * math.pi / 2.0))
        u_sin, u_cos = [], []
        turns = position_turns if position_turns is not None else [None] * len(theta_rad)
        middle = 0.5 * self.periods_per_rev / self.dirt_periods
        for theta, turn in zip(theta_rad, turns, strict=True):
            light = 1.0
            if dirt and turn is not None:
                where = (turn % self.periods_per_rev) / self.dirt_periods
                light = 1.0 - dirt * math.exp(-0.5 * ((where - middle) * 4.0) ** 2)
            currents = []
            for illumination, shift in fields:
                psi = theta + shift
                currents.append(light * illumination
                                * (1.0 + contrast * (math.sin(psi) + h3 * math.sin(3.0 * psi))))
            u_sin.append(self._gain * (currents[0] - currents[2]))
            u_cos.append(self._gain * (currents[3] - currents[1]))
        return u_sin, u_cos

    def _due(self) -> int:
        now = time.monotonic()
        if self._clock is None:
            self._clock = now
            self._samples = 0
        due = int((now - self._clock) * self.sample_hz) - self._samples
        return max(0, min(due, int(self.sample_hz)))  # at most a second's worth at once

    def stream_frame(self) -> bytes | None:
        count = self._due()
        if count == 0:
            return None
        with self._lock:
            turns, at = [], self._phase_turns
            for n in range(self._samples + 1, self._samples + count + 1):
                t = n / self.sample_hz
                at += self.signal_hz * (1.0 + self.wobble * math.sin(2 * math.pi * 0.7 * t)) \
                    / self.sample_hz
                turns.append(at)
            theta = [2.0 * math.pi * turn for turn in turns]
            u_sin, u_cos = self.channels(theta, position_turns=turns)
            if self.noise_mv:
                sigma = 1e-3 * self.noise_mv
                u_sin = [u + self.rng.gauss(0.0, sigma) for u in u_sin]
                u_cos = [u + self.rng.gauss(0.0, sigma) for u in u_cos]
            self._phase_turns = at
            self._samples += count
        self._frames += count
        self.history.extend(zip(theta, u_sin, u_cos, strict=True))
        return "".join(f"{s:.6f},{c:.6f}\n" for s, c in zip(u_sin, u_cos, strict=True)).encode()

    def answer(self, command: bytes) -> list[bytes]:
        """``NAME VALUE`` changes a setting (:attr:`SETTINGS`); anything else is ignored."""
        words = command.decode("ascii", "replace").split()
        if len(words) == 2 and words[0] in self.SETTINGS:
            try:
                value = float(words[1])
            except ValueError:
                return []
            low, high = self.SETTINGS[words[0]]
            if low <= value <= high:
                name = {"gap": "gap_mm", "yaw": "yaw_mrad", "roll": "roll_mrad",
                        "noise": "noise_mv", "speed": "signal_hz"}.get(words[0], words[0])
                self.set(**{name: value})
        return []


#: the demonstration instruments by the name ``anglebench simulate`` and the menu give them
SIMULATORS = {"autocollimator": AutocollimatorSimulator, "theodolite": TheodoliteSimulator,
              "readout": ReadoutSimulator, "signals": ReadHeadSimulator}
