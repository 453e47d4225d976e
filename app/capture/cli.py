"""``anglebench capture {autocollimator,theodolite,readout,signals} PORT --out FILE.csv``:
readings from an instrument into a CSV, without a window.

One row per reading: ``time_s`` (seconds since the capture started) and
``ac_x_arcsec,ac_y_arcsec`` (autocollimator), ``azimuth_deg,zenith_deg`` (theodolite,
GeoCOM's Hz and V) or ``value,unit`` (readout). Without ``--stable`` every frame the
instrument sends whole is a reading; with ``--stable WINDOW --dwell SECONDS`` a reading is
the mean of the frames of a dwell whose spread stayed within WINDOW (arcseconds for the
autocollimator and the theodolite, the readout's own unit for a readout), and the next
one waits for the instrument to move to a new position.

The file is written atomically when the set is complete. Until then every reading (synced
to disk before it counts) and every line the instrument sent are appended to a journal
beside it, ``FILE.csv.capture-journal.csv`` (models/capture/journal.py), removed once the
file is written: a kill, a power cut or a full disk leaves every reading taken on disk, and
the next capture into FILE.csv says where they are (``FILE.recovered-STAMP.csv``); a file
that cannot be written (the disk full) exits 2 naming it, the journal and why in words. A fault
the link recovers from is said on stderr and the set goes on; one it does not,
``--timeout``, Ctrl-C, SIGTERM or SIGHUP ends with exit status 2 and one line naming the
port, and the readings already taken are written to ``FILE.partial.csv`` (``--raw``'s lines
too, even when no reading was taken). ``--out`` and ``--raw`` may not be one file, nor the
certificate register; one that exists is refused unless ``--overwrite`` is given, and without
it a file that appears under the name during the capture (or an earlier ``.partial.csv``)
is kept, the readings written beside it (``FILE.captured-STAMP.csv``).
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import datetime as dt
import io
import os
import queue
import signal
import threading
import time
from pathlib import Path

from app.capture.instruments import CAPTURE_MODES, INSTRUMENTS, Autocollimator, LineReadoutInstrument
from app.capture.link import CANNOT_OPEN, tcp_port_refused
from app.capture.worker import CaptureWorker, Fault, NoTarget
from app.command_line import EXIT_BAD_INPUT, Parser, add_language_option, language_asked, speaking
from app.command_line import say as _say
from models.capture.journal import (
    CaptureJournal,
    frame_text,
    journal_in_use,
    journal_path,
    read_journal,
)
from models.capture.line_readout import DEFAULT_PATTERN
from models.capture.stability import (
    OUT_OF_VIEW_GAP_S,
    StabilityGate,
    UnwrappedAngles,
    gate_scale,
)
from models.messages import QT_TR_NOOP, joined, message, reason_of, rendered
from models.project.atomic_write import write_text_atomic
from models.project.output_guard import OutputRefused, check_outputs, register_files
from models.register.location import register_url

__all__ = ["RAW_FRAMES_IN_MEMORY", "run_capture"]

#: raw lines kept in memory; older ones are in the journal (on disk) only
RAW_FRAMES_IN_MEMORY = 10_000


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
        "autocollimator (ELCOMAT kind), theodolite (Leica GeoCOM), readout (one line per "
        "reading) or signals (a sin/cos stream, u_sin,u_cos a line)")))
    p.add_argument("port", help=words(QT_TR_NOOP(
        "a serial port (/dev/ttyUSB0, COM3) or tcp://host:port")))
    p.add_argument("--out", required=True, metavar="FILE.csv",
                   help=words(QT_TR_NOOP("the CSV to write")))
    p.add_argument("--baud", type=_positive(words, int), help=words(QT_TR_NOOP(
        "baud rate, as set on the instrument (default 9600)")))
    p.add_argument("--readings", type=_positive(words, int), default=1, metavar="N",
                   help=words(QT_TR_NOOP("how many readings (default 1)")))
    p.add_argument("--stable", type=_positive(words), metavar="WINDOW", help=words(QT_TR_NOOP(
        "take a reading when the spread of the frames stays within WINDOW for --dwell "
        "seconds: arcseconds for every angle (a readout's degrees converted), a readout's "
        "own unit when it sends no angle")))
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
        "reading (with --stable: whether it is in a reading's dwell; the readings' trace to "
        "the instrument's own output)")))
    p.add_argument("--overwrite", action="store_true", help=words(QT_TR_NOOP(
        "replace --out and --raw when they exist (without it an existing file is refused; "
        "a file the register issued is never replaced)")))
    p.add_argument("--range", type=_positive(words), metavar="LIMIT", help=words(QT_TR_NOOP(
        "the instrument's range: a frame with a value beyond ±LIMIT (arcsec for the "
        "autocollimator, the readout's own unit) is refused, not taken (default: "
        "autocollimator ±3600, readout any)")))
    add_language_option(p, words)
    return p


def _raw_text_of(frames: list[tuple[str, str, str]]) -> str:
    """The raw trace's CSV from the journal's frames (time, 1/0, the line as text)."""
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(("time_s", "reading", "line"))
    writer.writerows(frames)
    return buffer.getvalue()


def _partial_path(out: str) -> Path:
    path = Path(out)
    return path.with_name(f"{path.stem}.partial{path.suffix or '.csv'}")


def _csv_text(columns: tuple[str, ...], rows: list[list[object]]) -> str:
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow(("time_s",) + columns)
    writer.writerows(rows)
    return buffer.getvalue()


class _Stopped(Exception):
    """The process was asked to end (SIGTERM, SIGHUP): the readings taken are written."""


def _stop_on(signum, _frame) -> None:
    raise _Stopped(signal.Signals(signum).name)


#: the signals that end a capture the way Ctrl-C does: the readings taken written first
_ENDING = tuple(getattr(signal, name) for name in ("SIGTERM", "SIGHUP") if hasattr(signal, name))


def _handle(handler) -> dict:
    """Set ``handler`` for the ending signals; the handlers they had (only the main thread
    may set them: elsewhere nothing is changed)."""
    if threading.current_thread() is not threading.main_thread():
        return {}
    return {sig: signal.signal(sig, handler) for sig in _ENDING}


def _recovered_path(path: Path, stamp: str) -> Path:
    return path.with_name(f"{path.stem}.recovered-{stamp}{path.suffix or '.csv'}")


def _recover(out: str, say) -> int | None:
    """A journal left beside ``out`` by a capture that did not end (killed, power cut): its
    readings (and raw lines, when that capture wrote them) written to ``*.recovered-STAMP``
    files, said, and the journal removed. None when all went well, else the exit status."""
    journal = journal_path(out)
    if not journal.exists():
        return None
    if journal_in_use(journal):
        say(message(QT_TR_NOOP("anglebench capture: another capture is writing into {out} "
                               "(its journal {path} is in use); choose another --out"),
                    out=out, path=str(journal)))
        return EXIT_BAD_INPUT
    try:
        contents = read_journal(journal)
        stamp = time.strftime("%Y%m%dT%H%M%S", time.localtime(journal.stat().st_mtime))
    except (OSError, ValueError) as exc:
        say(message(QT_TR_NOOP("anglebench capture: {path} is left from an earlier capture but "
                               "cannot be read ({reason}); move it away to capture into {out}"),
                    path=str(journal), reason=getattr(exc, "strerror", None) or str(exc),
                    out=out))
        return EXIT_BAD_INPUT
    if not contents.readings and not contents.frames:  # killed before it heard anything
        with contextlib.suppress(OSError):
            journal.unlink()
        return None
    target = _recovered_path(Path(out), stamp)
    writes = [(target, _csv_text(contents.columns[1:], contents.readings))]
    raw_target = None
    if contents.info.get("raw"):
        raw_target = _recovered_path(Path(contents.info["raw"]), stamp)
        writes.append((raw_target, _raw_text_of(contents.frames)))
    for path, text in writes:
        try:
            write_text_atomic(path, text)
        except OSError as exc:
            say(message(QT_TR_NOOP("anglebench capture: an earlier capture into {out} did not "
                                   "end; its readings are in {journal}, and {path} cannot be "
                                   "written ({reason})"), out=out, journal=str(journal),
                        path=str(path), reason=_why_not_written(exc)))
            return EXIT_BAD_INPUT
    with contextlib.suppress(OSError):
        journal.unlink()
    if raw_target is not None:
        say(message(QT_TR_NOOP("anglebench capture: an earlier capture into {out} did not end "
                               "(killed?): its {n} readings are in {path}, its {m} raw lines "
                               "in {raw}"), out=out, n=len(contents.readings), path=str(target),
                    m=len(contents.frames), raw=str(raw_target)))
    else:
        say(message(QT_TR_NOOP("anglebench capture: an earlier capture into {out} did not end "
                               "(killed?): its {n} readings are in {path}"), out=out,
                    n=len(contents.readings), path=str(target)))
    return None


def run_capture(argv: list[str]) -> int:
    language = language_asked(argv)
    with speaking(language) as words:
        args = _parser(words).parse_args(argv)

    def say(text) -> None:
        _say(rendered(text, words))

    if (args.stable is None) != (args.dwell is None):
        say(message(QT_TR_NOOP("anglebench capture: --stable and --dwell go together")))
        return EXIT_BAD_INPUT
    if args.range is not None and args.instrument == "theodolite":
        say(message(QT_TR_NOOP("anglebench capture: --range is for the autocollimator and the "
                               "readout (a theodolite reads 0° … 360°)")))
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
    instrument.set_range(args.range)
    bad_port = tcp_port_refused(args.port)
    if bad_port is not None:  # as 'simulate' refuses one (contract75 F13: 99999 was tried)
        say(joined(("anglebench capture: ", bad_port)))
        return EXIT_BAD_INPUT
    try:
        outputs = (("--out", args.out), ("--raw", args.raw))
        check_outputs(outputs, register_files(register_url()))
        # nor a file the register issued, a certificate's PDF, DCC or results file (rev64 F1:
        # --out r.csv replaced an issued results file, the only copy); a recorded results
        # file left under a temporary name beside one is kept first
        from app.issued_outputs import refuse_issued_outputs

        for said in refuse_issued_outputs(register_url(), outputs):
            say(joined(("anglebench capture: ", said)))
    except OutputRefused as exc:
        say(joined(("anglebench capture: ", reason_of(exc))))
        return EXIT_BAD_INPUT
    recovery = _recover(args.out, say)
    if recovery is not None:
        return recovery
    # an existing file is someone's readings (contract75 F4: a 50-row polygon test became 3
    # autocollimator readings, "3 readings written" and nothing more): refused unless
    # --overwrite, as 'register export' does; after the recovery above, which keeps a killed
    # capture's readings whatever is refused here
    if not args.overwrite:
        for flag, named in outputs:
            if named and os.path.lexists(named):
                say(message(QT_TR_NOOP("anglebench capture: {flag} {path} exists; nothing was "
                                       "captured: choose another name, or add --overwrite to "
                                       "replace it"), flag=flag, path=named))
                return EXIT_BAD_INPUT
    columns = instrument.columns
    try:
        journal = CaptureJournal(journal_path(args.out), ("time_s",) + columns, {
            "started": dt.datetime.now(dt.timezone.utc).isoformat(timespec="seconds"),
            "instrument": args.instrument, "port": args.port,
            "out": str(Path(args.out).resolve()),
            "raw": str(Path(args.raw).resolve()) if args.raw else ""})
    except OSError as exc:
        say(message(QT_TR_NOOP("anglebench capture: cannot write {path}: {reason}; nothing was "
                               "captured"), path=str(journal_path(args.out)),
                    reason=_why_not_written(exc)))
        return EXIT_BAD_INPUT
    gate = StabilityGate(args.stable, args.dwell) if args.stable else None
    # the gate's window is in arcseconds for every angle, as in the window's capture panel
    # (models.capture.stability.gate_scale): a theodolite's degrees and a readout's frames in
    # degrees are converted (a readout in another unit is gated in that unit); angles in
    # degrees go to the gate as continuous offsets from the first frame's (UnwrappedAngles),
    # so a position at 0°/360°, or 180° from the first frame, settles (and averages) where
    # it is
    unwrapped: UnwrappedAngles | None = None
    gate_unit_scale: float | None = None
    rows: list[list[object]] = []
    #: with --stable, each reading's first and last line (their indices since the start)
    dwells: list[tuple[int, int]] = []
    previous = _handle(_stop_on)
    worker = CaptureWorker(args.port, instrument, args.baud, silence_s=args.silence,
                           retries=max(args.retries, 0), reply_timeout_s=args.reply_timeout,
                           poll_interval_s=1.0 / args.poll_rate, raw_cap=RAW_FRAMES_IN_MEMORY)
    ends = time.monotonic() + args.timeout if args.timeout else None
    failure = None
    #: whether the port was ever opened: until then a port that cannot be opened ends the
    #: capture with its one line (contract75 F13: "cannot open …; reconnecting" ×3, then
    #: the last, 4 lines where docs/capture.md promises one)
    opened = False
    #: when the frames with no measurement began (None: readings come)
    no_target_since: float | None = None
    no_target_reason = ""

    def journal_frames() -> None:
        for t, line, used in worker.take_raw():
            journal.frame(t, line, used)

    def take(row: list[object]) -> None:
        journal_frames()
        journal.reading(row)  # on disk before it counts
        rows.append(row)

    try:
        worker.start()
        while len(rows) < args.readings:
            if ends is not None and time.monotonic() > ends:
                failure = message(QT_TR_NOOP("{port}: {n} of {total} readings in {seconds} s"),
                                  port=args.port, n=len(rows), total=args.readings,
                                  seconds=f"{args.timeout:g}")
                if no_target_since is not None:  # the instrument heard, seeing no target
                    failure = message(QT_TR_NOOP(
                        "{failure}; its frames carry no measurement since {since} s ({reason}): "
                        "no target in view?"), failure=failure,
                        since=f"{no_target_since:.1f}", reason=no_target_reason)
                break
            try:
                event = worker.events.get(timeout=0.05)
            except queue.Empty:
                journal_frames()
                continue
            if isinstance(event, Fault):
                if event.final or (not opened and getattr(event.message, "template", "")
                                   == CANNOT_OPEN):
                    failure = event.message
                    break
                opened = True  # a fault of a link that was open (silence, a drop)
                say(message(QT_TR_NOOP("anglebench capture: {reason}; reconnecting"),
                            reason=event.message))
                if gate is not None:
                    gate.restart()  # a reading never bridges the frames the link lost
                continue
            opened = True
            if isinstance(event, NoTarget):
                # frames with no measurement (a mirror out of view): the link is alive
                no_target_since, no_target_reason = event.time_s, event.reason
                continue
            if no_target_since is not None:
                # a reading never bridges a gap of frames without one
                if gate is not None and event.time_s - no_target_since >= OUT_OF_VIEW_GAP_S:
                    gate.restart()
                no_target_since = None
            unit = [event.unit] if args.instrument == "readout" else []
            if gate is None:
                take([repr(round(event.time_s, 6)), *map(repr, event.values), *unit])
                continue
            scale = gate_scale("deg" if args.instrument == "theodolite" else
                               getattr(event, "unit", ""))
            if scale != gate_unit_scale:
                # the first frame, or a readout that changed its unit mid-run: frames in two
                # units are not one quantity, the dwell starts again
                if gate_unit_scale is not None:
                    gate.restart()
                gate_unit_scale = scale
                unwrapped = UnwrappedAngles() if scale != 1.0 else None
            offsets = (unwrapped.offsets(event.values) * scale if unwrapped is not None
                       else event.values)
            taken = gate.feed(event.time_s, offsets, tag=event.frame)
            if taken is not None:
                dwells.append((int(taken.first_tag), int(event.frame)))
                means = (unwrapped.angles([m / scale for m in taken.mean])
                         if unwrapped is not None else tuple(float(m) for m in taken.mean))
                take([repr(round(taken.time_s, 6)), *map(repr, means), *unit])
    except KeyboardInterrupt:
        failure = message(QT_TR_NOOP("{port}: interrupted"), port=args.port)
    except _Stopped as exc:
        failure = message(QT_TR_NOOP("{port}: stopped by {signal}"), port=args.port,
                          signal=str(exc))
    except OSError as exc:  # the journal cannot be written: the disk is full
        failure = message(QT_TR_NOOP("cannot write {path} ({reason})"), path=str(journal.path),
                          reason=exc.strerror or str(exc))
    finally:
        # from here on the readings are written: a second SIGTERM waits for that
        _handle(signal.SIG_IGN)
        try:
            worker.stop()
            with contextlib.suppress(OSError, ValueError):
                journal_frames()
            journal.close()
            status = _finish(args, columns, rows, worker, journal, failure, say,
                             dwells if gate is not None else None)
        finally:
            for sig, handler in previous.items():
                signal.signal(sig, handler)
    return status


def _kept_path(path: Path) -> Path:
    return path.with_name(f"{path.stem}.captured-{time.strftime('%Y%m%dT%H%M%S')}"
                          f"{path.suffix or '.csv'}")


def _why_not_written(exc: OSError) -> str:
    """Why a capture's file could not be written, in words: "the disk is full" for ENOSPC or
    EDQUOT (models.project.write_failure.DISK_FULL), else the system's words, never
    "[Errno 28] …"."""
    from models.project.write_failure import DISK_FULL

    if exc.errno in DISK_FULL:
        return message(QT_TR_NOOP("the disk is full"))
    return exc.strerror or reason_of(exc) or type(exc).__name__


def _write_output(path: Path, text: str, say, replace: bool = True) -> Path:
    """``text`` written to ``path``, checked against the files the register issued when it
    is placed (app/issued_outputs.write_sparing_issued): the check at the start is as old
    as the capture, hours maybe, and a certificate, DCC or results file issued under that
    name meanwhile was replaced by this write. Refused, the readings go to a name of their
    own beside it (``out.captured-STAMP.csv``), said. The name written; OSError when
    neither can be written. Without ``replace`` (no --overwrite) a file there is not
    replaced either: one made during the capture, an earlier capture's ``.partial.csv``."""
    from app.issued_outputs import refuse_issued_outputs, write_sparing_issued

    data = text.encode("utf-8")
    if not replace and os.path.lexists(path):
        reason = message(QT_TR_NOOP("{path} exists and is not replaced without --overwrite"),
                         path=str(path))
        try:  # an issued file there is said as such
            refuse_issued_outputs(register_url(), [("", str(path))])
        except OutputRefused as exc:
            reason = reason_of(exc)
        other = _kept_path(path)
        write_sparing_issued(register_url(), other, data)
        say(message(QT_TR_NOOP("anglebench capture: {reason}; written to {path} instead"),
                    reason=reason, path=str(other)))
        return other
    try:
        write_sparing_issued(register_url(), path, data)
        return path
    except OutputRefused as exc:
        other = _kept_path(path)
        write_sparing_issued(register_url(), other, data)
        say(message(QT_TR_NOOP("anglebench capture: {reason}; written to {path} instead"),
                    reason=reason_of(exc), path=str(other)))
        return other


def _finish(args, columns, rows, worker, journal, failure, say, dwells=None) -> int:
    """The readings (and the raw lines) written; the journal removed once they are. With
    ``dwells`` (--stable: each reading's first and last line), a raw line is marked as
    having become a reading only within a reading's dwell: a stream's other frames did not."""
    target = Path(args.out) if failure is None else _partial_path(args.out)
    try:  # the journal is what was taken (a signal may have come between it and memory)
        kept = read_journal(journal.path)
        rows, frames = kept.readings, kept.frames
        start = 0  # the journal holds every line since the start
    except (OSError, ValueError):  # the journal unreadable: what memory holds
        start = worker.raw_first  # the worker has stopped: nothing is kept or dropped now
        frames = [(repr(round(t, 6)), str(int(u)), frame_text(line))
                  for t, line, u in worker.lines(start)]
    if dwells is not None:
        inside = set()
        for first, last in dwells:
            inside.update(range(first, last + 1))
        frames = [(t, used if i in inside else "0", text)
                  for i, (t, used, text) in enumerate(frames, start)]
    writes = [(target, _csv_text(columns, rows))] if rows else []
    raw_target = None
    if args.raw:  # written even when no reading was taken: then it is all there is
        raw_target = Path(args.raw) if failure is None else _partial_path(args.raw)
        writes.append((raw_target, _raw_text_of(frames)))
    written: dict[Path, Path] = {}
    for path, text in writes:
        try:
            written[path] = _write_output(path, text, say, args.overwrite)
        except OSError as exc:
            say(message(QT_TR_NOOP("anglebench capture: cannot write {path}: {reason}; the {n} "
                                   "readings taken are kept in {journal}"), path=str(path),
                        reason=_why_not_written(exc), n=len(rows),
                        journal=str(journal.path)))
            return EXIT_BAD_INPUT
    target = written.get(target, target)
    raw_target = written.get(raw_target, raw_target) if raw_target is not None else None
    journal.remove()
    if failure is not None and not rows:
        if raw_target is not None:
            say(message(QT_TR_NOOP("anglebench capture: {reason}; no reading was taken (the "
                                   "instrument's lines are in {raw})"), reason=failure,
                        raw=str(raw_target)))
        else:
            say(message(QT_TR_NOOP("anglebench capture: {reason}; no reading was taken"),
                        reason=failure))
        return EXIT_BAD_INPUT
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
