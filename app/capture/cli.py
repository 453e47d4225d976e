"""``anglebench capture {autocollimator,theodolite,readout} PORT --out FILE.csv``:
readings from an instrument into a CSV, without a window.

One row per reading: ``time_s`` (seconds since the capture started) and
``ac_x_arcsec,ac_y_arcsec`` (autocollimator), ``azimuth_deg,zenith_deg`` (theodolite,
GeoCOM's Hz and V) or ``value,unit`` (readout). Without ``--stable`` every frame the
instrument sends whole is a reading; with ``--stable WINDOW --dwell SECONDS`` a reading is
the mean of the frames of a dwell whose spread stayed within WINDOW (arcseconds for the
autocollimator and the theodolite, the readout's own unit for a readout), and the next
one waits for the instrument to move to a new position.

The file is written atomically when the set is complete. A fault the link recovers
from is said on stderr and the set goes on; one it does not (or ``--timeout``) ends
with exit status 2 and one line naming the port, and the readings already taken are
written to ``FILE.partial.csv``.
"""

from __future__ import annotations

import argparse
import csv
import io
import queue
import time
from pathlib import Path

from app.capture.instruments import CAPTURE_MODES, INSTRUMENTS, Autocollimator, LineReadoutInstrument
from app.capture.worker import CaptureWorker, Fault
from app.command_line import EXIT_BAD_INPUT, Parser, add_language_option, language_asked, speaking
from app.command_line import say as _say
from models.capture.line_readout import DEFAULT_PATTERN
from models.capture.stability import StabilityGate
from models.messages import QT_TR_NOOP, message, rendered
from models.project.atomic_write import write_text_atomic

__all__ = ["run_capture"]


def _positive(words, kind=float):
    def read(text: str):
        try:
            value = kind(text)
        except ValueError:
            value = None
        if value is None or not value > 0:
            raise argparse.ArgumentTypeError(rendered(message(QT_TR_NOOP(
                "{text}: give a number greater than 0"), text=repr(text)), words))
        return value

    return read


def _parser(words) -> argparse.ArgumentParser:
    p = Parser(prog="anglebench capture",
               description=words(QT_TR_NOOP("Capture readings from an instrument into a CSV")))
    p.add_argument("instrument", choices=sorted(INSTRUMENTS), help=words(QT_TR_NOOP(
        "autocollimator (ELCOMAT kind), theodolite (Leica GeoCOM) or readout (one line per "
        "reading)")))
    p.add_argument("port", help=words(QT_TR_NOOP(
        "a serial port (/dev/ttyUSB0, COM3) or tcp://host:port")))
    p.add_argument("--out", required=True, metavar="FILE.csv",
                   help=words(QT_TR_NOOP("the CSV to write")))
    p.add_argument("--baud", type=_positive(words, int), help=words(QT_TR_NOOP(
        "baud rate, as set on the instrument (default 9600)")))
    p.add_argument("--readings", type=_positive(words, int), default=1, metavar="N",
                   help=words(QT_TR_NOOP("how many readings (default 1)")))
    p.add_argument("--stable", type=_positive(words), metavar="WINDOW", help=words(QT_TR_NOOP(
        "take a reading when the spread of the frames stays within WINDOW (arcsec; a "
        "readout's own unit) for --dwell seconds")))
    p.add_argument("--dwell", type=_positive(words), metavar="SECONDS",
                   help=words(QT_TR_NOOP("the dwell time of --stable")))
    p.add_argument("--pattern", default=DEFAULT_PATTERN, help=words(QT_TR_NOOP(
        "readout: regular expression of a line, with a group named value (and unit)")))
    p.add_argument("--silence", type=_positive(words), default=2.0, metavar="SECONDS",
                   help=words(QT_TR_NOOP("seconds without a valid frame before the link is "
                                         "reconnected (default 2)")))
    p.add_argument("--retries", type=int, default=3, metavar="N", help=words(QT_TR_NOOP(
        "reconnections in a row without a reading before giving up (default 3)")))
    p.add_argument("--reply-timeout", type=_positive(words), default=5.0, metavar="SECONDS",
                   help=words(QT_TR_NOOP(
                       "an instrument that is asked (theodolite, readout, a polled autocollimator): "
                       "how long one request waits for its reply before it counts as a fault; the "
                       "next request is sent only after the reply or this (default 5)")))
    p.add_argument("--mode", choices=CAPTURE_MODES, default="auto", help=words(QT_TR_NOOP(
        "autocollimator: auto (stream, or single-shot requests when it does not stream), "
        "stream, or poll (single-shot requests only)")))
    p.add_argument("--poll-rate", type=_positive(words), default=20.0, metavar="HZ",
                   help=words(QT_TR_NOOP("single-shot requests per second at the most when an "
                                         "autocollimator is polled (default 20)")))
    p.add_argument("--timeout", type=_positive(words), metavar="SECONDS",
                   help=words(QT_TR_NOOP("give up after this long (default: never)")))
    p.add_argument("--raw", metavar="RAW.csv", help=words(QT_TR_NOOP(
        "also write every line the instrument sent, time-stamped, and whether it became a "
        "reading (the readings' trace to the instrument's own output)")))
    add_language_option(p, words)
    return p


def _raw_text(lines: list[tuple[float, bytes, bool]]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(("time_s", "reading", "line"))
    writer.writerows((repr(round(t, 6)), int(used), line.decode("ascii", "backslashreplace"))
                     for t, line, used in lines)
    return buffer.getvalue()


def _wrapped(difference: float, scale: float) -> float:
    """An angle's difference (degrees) to ±180° when ``scale`` says the values are angles."""
    return (difference + 180.0) % 360.0 - 180.0 if scale != 1.0 else difference


def _partial_path(out: str) -> Path:
    path = Path(out)
    return path.with_name(f"{path.stem}.partial{path.suffix or '.csv'}")


def _csv_text(columns: tuple[str, ...], rows: list[list[object]]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(("time_s",) + columns)
    writer.writerows(rows)
    return buffer.getvalue()


def run_capture(argv: list[str]) -> int:
    language = language_asked(argv)
    with speaking(language) as words:
        args = _parser(words).parse_args(argv)

    def say(text) -> None:
        _say(rendered(text, words))

    if (args.stable is None) != (args.dwell is None):
        say(message(QT_TR_NOOP("anglebench capture: --stable and --dwell go together")))
        return EXIT_BAD_INPUT
    if args.instrument == "readout":
        try:
            instrument = LineReadoutInstrument(args.pattern)
        except ValueError as exc:
            say(message(QT_TR_NOOP("anglebench capture: --pattern: {reason}"), reason=str(exc)))
            return EXIT_BAD_INPUT
    elif args.instrument == "autocollimator":
        instrument = Autocollimator(args.mode)
    else:
        instrument = INSTRUMENTS[args.instrument]()
    if args.mode != "auto" and args.instrument != "autocollimator":
        say(message(QT_TR_NOOP("anglebench capture: --mode is the autocollimator's (an instrument "
                               "that answers requests is always asked)")))
        return EXIT_BAD_INPUT
    columns = instrument.columns
    gate = StabilityGate(args.stable, args.dwell) if args.stable else None
    # the gate's window is in arcseconds for angles in degrees; a theodolite's angles go to
    # the gate as their difference from the first frame's, wrapped to ±180°, so a position
    # at 0°/360° settles (and averages) where it is
    scale = 3600.0 if args.instrument == "theodolite" else 1.0
    origin: tuple[float, ...] | None = None
    rows: list[list[object]] = []
    worker = CaptureWorker(args.port, instrument, args.baud, silence_s=args.silence,
                           retries=max(args.retries, 0), reply_timeout_s=args.reply_timeout,
                           poll_interval_s=1.0 / args.poll_rate).start()
    ends = time.monotonic() + args.timeout if args.timeout else None
    failure = None
    try:
        while len(rows) < args.readings:
            if ends is not None and time.monotonic() > ends:
                failure = message(QT_TR_NOOP("{port}: {n} of {total} readings in {seconds} s"),
                                  port=args.port, n=len(rows), total=args.readings,
                                  seconds=f"{args.timeout:g}")
                break
            try:
                event = worker.events.get(timeout=0.05)
            except queue.Empty:
                continue
            if isinstance(event, Fault):
                if event.final:
                    failure = event.message
                    break
                say(message(QT_TR_NOOP("anglebench capture: {reason}; reconnecting"),
                            reason=event.message))
                continue
            unit = [event.unit] if args.instrument == "readout" else []
            if gate is None:
                rows.append([repr(round(event.time_s, 6)), *map(repr, event.values), *unit])
                continue
            origin = origin or (event.values if scale != 1.0 else (0.0,) * len(event.values))
            taken = gate.feed(event.time_s, [_wrapped(v - o, scale) * scale
                                             for v, o in zip(event.values, origin, strict=True)])
            if taken is not None:
                means = [o + float(v) / scale for v, o in zip(taken.mean, origin, strict=True)]
                if scale != 1.0:
                    means = [m % 360.0 for m in means]
                rows.append([repr(round(taken.time_s, 6)), *map(repr, means), *unit])
    except KeyboardInterrupt:
        failure = message(QT_TR_NOOP("{port}: interrupted"), port=args.port)
    finally:
        worker.stop()
    target = Path(args.out) if failure is None else _partial_path(args.out)
    if failure is not None and not rows:
        say(message(QT_TR_NOOP("anglebench capture: {reason}; no reading was taken"),
                    reason=failure))
        return EXIT_BAD_INPUT
    writes = [(target, _csv_text(columns, rows))]
    if args.raw:
        raw_target = Path(args.raw) if failure is None else _partial_path(args.raw)
        writes.append((raw_target, _raw_text(worker.raw)))
    for path, text in writes:
        try:
            write_text_atomic(path, text)
        except OSError as exc:
            say(message(QT_TR_NOOP("anglebench capture: cannot write {path}: {reason}"),
                        path=str(path), reason=exc.strerror or str(exc)))
            return 1
    if failure is not None:
        say(message(QT_TR_NOOP("anglebench capture: {reason}; the {n} readings taken are in "
                               "{path}"), reason=failure, n=len(rows), path=str(target)))
        return EXIT_BAD_INPUT
    if worker.polling and args.mode == "auto":
        say(message(QT_TR_NOOP("anglebench capture: {port} did not stream after A: read by "
                               "single-shot a requests (--mode poll asks so from the start)"),
                    port=args.port))
    if worker.refused:
        say(message(QT_TR_NOOP("{n} readings written to {path} ({refused} frames refused: "
                               "noise, an invalid axis or an error reply)"), n=len(rows),
                    path=str(target), refused=worker.refused))
    else:
        say(message(QT_TR_NOOP("{n} readings written to {path}"), n=len(rows), path=str(target)))
    return 0
