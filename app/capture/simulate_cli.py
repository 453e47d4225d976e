"""``anglebench simulate autocollimator|theodolite|readout|signals PORT``: a demonstration
instrument for training and for trying the program without hardware.

PORT is a TCP port of 127.0.0.1 (connect the window to ``tcp://127.0.0.1:PORT``) or
``pty`` (a pseudo-terminal, its device printed). The instrument answers its published
protocol (app/capture/simulators.py) with the settings given: where it points
(``--position``, or ``--positions`` held ``--hold`` seconds each), noise, drift and
faults. It runs until interrupted (Ctrl+C) or for ``--seconds``.

``signals`` is an encoder's read head streaming its sin/cos voltages (``u_sin,u_cos`` a
line) as it is mounted: ``--gap`` (mm), ``--yaw`` and ``--roll`` (mrad), ``--dirt`` on the
scale, ``--noise`` in mV, ``--signal-hz`` periods and ``--sample-rate`` samples a second.
With ``--commands`` it reads lines such as ``gap 0.9`` or ``yaw 3`` from its standard
input and changes the mounting while it streams (a client may send the same lines).
"""

from __future__ import annotations

import argparse
import contextlib
import re
import signal
import sys
import threading

from app.capture.simulators import SIMULATORS
from app.command_line import EXIT_BAD_INPUT, Parser, language_asked, speaking
from app.command_line import say as _say
from models.messages import QT_TR_NOOP, message, rendered

__all__ = ["FAULTS", "run_simulate", "simulator_from"]

#: the faults a demonstration instrument can be told to show
FAULTS = ("noise", "invalid_axes", "silence", "disconnect", "wrong_baud")


def _numbers(words):
    def read(text: str) -> tuple[float, ...]:
        try:
            values = tuple(float(v) for v in text.replace(";", ",").split(",") if v.strip())
        except ValueError:
            raise argparse.ArgumentTypeError(rendered(message(QT_TR_NOOP(
                "{text}: give numbers separated by commas"), text=repr(text)), words)) from None
        if not values:
            raise argparse.ArgumentTypeError(rendered(message(QT_TR_NOOP(
                "{text}: give numbers separated by commas"), text=repr(text)), words))
        return values
    return read


def _not_negative(words):
    """A number of 0 or more (contract75 F13: --noise -1 was accepted)."""
    def read(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            value = -1.0
        if not 0 <= value < float("inf"):
            raise argparse.ArgumentTypeError(rendered(message(QT_TR_NOOP(
                "{text}: give a number of 0 or more"), text=repr(text)), words))
        return value
    return read


#: the options whose value is a list of numbers, which may begin with a minus sign
_NUMBER_LISTS = ("--position", "--positions")


def _numbers_attached(argv: list[str]) -> list[str]:
    """``argv`` with a list of numbers that begins with a minus sign attached to its option
    (``--positions -1.1,0`` as ``--positions=-1.1,0``): argparse takes "-1.1,0" for an
    option and said "expected one argument" (day review live76 F10)."""
    out: list[str] = []
    i = 0
    while i < len(argv):
        word = argv[i]
        following = argv[i + 1] if i + 1 < len(argv) else ""
        if word in _NUMBER_LISTS and re.match(r"-\.?\d", following):
            out.append(f"{word}={following}")
            i += 2
            continue
        out.append(word)
        i += 1
    return out


def _port(words):
    def read(text: str) -> int | str:
        if text.strip().lower() == "pty":
            return "pty"
        try:
            port = int(text)
        except ValueError:
            port = -1
        if not 0 <= port <= 65535:
            raise argparse.ArgumentTypeError(rendered(message(QT_TR_NOOP(
                "{text}: a TCP port (0 to 65535; 0 takes a free one) or 'pty'"),
                text=repr(text)), words))
        return port
    return read


def _parser(words) -> argparse.ArgumentParser:
    p = Parser(prog="anglebench simulate", description=words(QT_TR_NOOP(
        "A demonstration instrument on a TCP port of 127.0.0.1 or a pseudo-terminal")))
    p.add_argument("instrument", choices=sorted(SIMULATORS), help=words(QT_TR_NOOP(
        "the instrument to simulate")))
    p.add_argument("port", type=_port(words), help=words(QT_TR_NOOP(
        "a TCP port of 127.0.0.1 (0: a free one), or 'pty' for a pseudo-terminal")))
    p.add_argument("--position", type=_numbers(words), metavar="X[,Y]", help=words(QT_TR_NOOP(
        "where the instrument points: AC x,y in arcseconds; the theodolite's Hz,V in degrees; "
        "the readout's value")))
    p.add_argument("--positions", type=_numbers(words), metavar="A,B,…", help=words(QT_TR_NOOP(
        "a script of readings (the first axis; the second stays), each held --hold seconds")))
    p.add_argument("--hold", type=float, default=5.0, metavar="SECONDS", help=words(QT_TR_NOOP(
        "how long each of --positions is held")))
    p.add_argument("--noise", type=_not_negative(words), default=0.05, metavar="SIGMA", help=words(QT_TR_NOOP(
        "Gaussian noise on every reading (arcseconds; the readout's unit)")))
    p.add_argument("--drift", type=float, default=0.0, metavar="PER_S", help=words(QT_TR_NOOP(
        "drift per second (arcseconds; the readout's unit)")))
    p.add_argument("--fault", action="append", choices=FAULTS, default=[], help=words(QT_TR_NOOP(
        "a fault to show (repeatable)")))
    p.add_argument("--rate", type=float, default=50.0, metavar="HZ", help=words(QT_TR_NOOP(
        "the autocollimator's stream rate; how often a theodolite or a readout answers at "
        "most (each answer takes 1/HZ s, as a measurement does)")))
    p.add_argument("--seconds", type=float, default=0.0, help=words(QT_TR_NOOP(
        "stop after this long (0: until interrupted)")))
    head = p.add_argument_group(words(QT_TR_NOOP("signals: the read head's mounting")))
    head.add_argument("--gap", type=float, default=0.8, metavar="MM", help=words(QT_TR_NOOP(
        "the gap between the read head and the scale (nominal 0.8 mm)")))
    head.add_argument("--yaw", type=float, default=0.0, metavar="MRAD", help=words(QT_TR_NOOP(
        "the head's rotation about the scale's normal (moiré)")))
    head.add_argument("--roll", type=float, default=0.0, metavar="MRAD", help=words(QT_TR_NOOP(
        "the head's tilt about the measuring direction")))
    head.add_argument("--dirt", type=float, default=0.0, metavar="0…1", help=words(QT_TR_NOOP(
        "a stain on the scale dimming the light once a revolution (0: clean)")))
    head.add_argument("--signal-hz", type=float, default=20.0, metavar="HZ", help=words(
        QT_TR_NOOP("signal periods a second (the scale's speed)")))
    head.add_argument("--sample-rate", type=float, default=5000.0, metavar="HZ", help=words(
        QT_TR_NOOP("samples a second of both channels")))
    head.add_argument("--commands", action="store_true", help=words(QT_TR_NOOP(
        "read settings such as 'gap 0.9' or 'yaw 3' from standard input while streaming")))
    return p


def simulator_from(instrument: str, port: int | str, position=None, positions=None,
                   hold_s: float = 5.0, noise: float = 0.05, drift: float = 0.0,
                   faults=(), rate_hz: float = 50.0, **head):
    """The demonstration instrument (not yet started: use it as a context manager)."""
    default = {"autocollimator": (12.5, -3.2), "theodolite": (30.0, 89.995),
               "readout": (105.00012,), "signals": (0.0,)}[instrument]
    base = tuple(position) if position else default
    width = len(default)
    base = (base + default[len(base):])[:width]
    script = [(v, *base[1:]) for v in positions] if positions else [base]
    return SIMULATORS[instrument](
        "pty" if port == "pty" else "tcp", faults=tuple(faults), positions=script,
        hold_s=hold_s if positions else 1e9, sigma=noise, drift_per_s=drift, rate_hz=rate_hz,
        tcp_port=0 if port == "pty" else int(port), seed=None,
        # an instrument that is asked measures before it answers (#41: answered at once, it
        # was asked ~8700 times a second and kept the window's thread 60 % busy)
        **({} if instrument in ("autocollimator", "signals") or rate_hz <= 0
           else {"reply_delay_s": 1.0 / rate_hz}), **head)


def _read_commands(sim) -> None:
    """Lines such as ``gap 0.9`` from standard input, each given to the simulator as if a
    client had sent it (a line it does not know is ignored)."""
    for line in sys.stdin:
        sim.answer(line.strip().encode("ascii", "replace"))


def run_simulate(argv: list[str], ready=None) -> int:
    """The command; ``ready`` (tests) is called with the simulator once it serves, and the
    command returns when it is set to stop (``simulator.stop_event``)."""
    with speaking(language_asked(argv)) as words:
        args = _parser(words).parse_args(_numbers_attached(argv))
        try:
            head = {}
            if args.instrument == "signals":  # the noise in mV; the stream at its own rate
                head = {"gap_mm": args.gap, "yaw_mrad": args.yaw, "roll_mrad": args.roll,
                        "dirt": args.dirt, "noise_mv": args.noise, "signal_hz": args.signal_hz,
                        "sample_hz": args.sample_rate}
            sim = simulator_from(args.instrument, args.port, args.position, args.positions,
                                 args.hold, 0.0 if head else args.noise, args.drift, args.fault,
                                 1000.0 if head else args.rate, **head)
            sim.__enter__()
        except OSError as exc:
            _say(rendered(message(QT_TR_NOOP("anglebench simulate: port {port}: {reason}"),
                                  port=args.port, reason=str(exc)), words))
            return EXIT_BAD_INPUT
        try:
            sys.stdout.write(rendered(message(QT_TR_NOOP(
                "A demonstration {instrument} answers on {port} (Ctrl+C stops it)"),
                instrument=args.instrument, port=sim.port), words) + "\n")
            sys.stdout.flush()
            done = threading.Event()
            if args.commands and hasattr(sim, "SETTINGS"):
                threading.Thread(target=_read_commands, args=(sim,), daemon=True).start()
            if ready is not None:
                ready(sim, done)
            elif threading.current_thread() is threading.main_thread():
                signal.signal(signal.SIGTERM, lambda *_: done.set())
            with contextlib.suppress(KeyboardInterrupt):
                done.wait(args.seconds if args.seconds > 0 else None)
        finally:
            sim.__exit__(None, None, None)
    return 0
