"""What each instrument is sent and how its lines become readings.

An instrument either streams once started (the autocollimator after ``A``) or answers
one request at a time (GeoCOM's TMC_GetAngle5, a readout's STX). A request is sent only
when the previous one has been answered (or its reply timeout has passed): one request
in flight, never a queue of them in the instrument's buffer.

An autocollimator that does not stream after ``A`` (some ELCOMAT models and firmware
answer only single-shot requests) is read by single-shot ``a`` requests instead, paced
the same way (:attr:`Instrument.poll`): chosen with ``mode="poll"``, or found by
``mode="auto"`` when no frame arrives within :attr:`Instrument.stream_wait_s` of the
start.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass

from models.capture.autocollimator import AutocollimatorFrame, command, parse_autocollimator_line
from models.capture.errors import FrameError, NoMeasurement
from models.capture.geocom import (
    GET_ANGLE5,
    INCLINE_AUTOMATIC,
    MAX_TRANSACTION_ID,
    angles_of,
    parse_geocom_reply,
    request,
)
from models.capture.line_readout import DEFAULT_PATTERN, DEFAULT_REQUEST, LineReadout
from models.capture.signal_stream import SignalLineParser

#: an electronic autocollimator's range, default: ±1° (3600″) is more than any measures
#: (ELCOMAT kind: ±1000″ … ±2000″); a frame beyond it is a misread, not a reading
AUTOCOLLIMATOR_RANGE_ARCSEC = 3600.0

__all__ = ["AUTOCOLLIMATOR_RANGE_ARCSEC", "CAPTURE_MODES", "INSTRUMENTS", "Autocollimator",
           "Instrument", "LineReadoutInstrument", "SignalStreamInstrument", "Theodolite",
           "frame_values", "reading_columns"]

#: how a streaming instrument is read: ``auto`` (stream, single-shot requests when it does not
#: stream), ``stream`` or ``poll`` (single-shot requests only)
CAPTURE_MODES = ("auto", "stream", "poll")


@dataclass
class Instrument:
    #: the CSV's columns of one reading (``time_s`` comes first, ``unit`` last for a readout)
    columns: tuple[str, ...] = ()
    #: sent once after connecting (a stream's start), and when stopping
    start: bytes = b""
    stop: bytes = b""
    #: sent for every reading of an instrument that answers requests
    request: bytes | None = None
    #: the baud rate when none is given (the usual serial default; set the instrument's own)
    default_baud: int = 9600
    #: a streaming instrument's single-shot request, sent instead of the stream when it does
    #: not stream (None: it has none)
    poll: bytes | None = None
    #: ``mode="auto"``: how long to wait for the stream's first frame before polling
    stream_wait_s: float = 1.0
    #: ``auto``, ``stream`` or ``poll`` (:data:`CAPTURE_MODES`; ``poll`` needs :attr:`poll`)
    mode: str = "auto"
    #: the instrument's range, per value: (lowest, highest) or None (any finite value); a
    #: frame outside it is refused, not taken (a setting: ``--range`` on the command line)
    limits: tuple[tuple[float, float] | None, ...] = ()
    #: whether the end of a line, its start lost (a stream joined while a line was on its
    #: way), can pass for a reading: a readout's "+105.00012 deg" joined after "+10" reads
    #: 5.00012 deg, a signal sample "0.0641 0.4964" joined after "0.06" reads 41 V. The
    #: first line of a connection is then kept in the raw trace, not read. An instrument
    #: whose lines carry a fixed header (the autocollimator's fields, GeoCOM's "%R1P") refuses
    #: such an end by itself
    tail_parses: bool = True

    def check_range(self, values: tuple[float, ...]) -> None:
        """FrameError when a value is not finite or outside the instrument's range."""
        for i, value in enumerate(values):
            if not math.isfinite(value):
                raise FrameError(f"value {value} is not a number")
            limit = self.limits[i] if i < len(self.limits) else None
            if limit is not None and not limit[0] <= value <= limit[1]:
                name = self.columns[i] if i < len(self.columns) else f"value {i + 1}"
                # a whole frame beyond the range: no measurement (a mirror out of view),
                # the link is alive
                raise NoMeasurement(f"{name} {value:g} outside the instrument's range "
                                    f"{limit[0]:g} … {limit[1]:g}",
                                    (name,) if i < len(self.columns) else (), value, limit)

    def set_range(self, half_width: float | None) -> None:
        """Every value within ±``half_width`` (the instrument's own unit); None: the
        instrument's default."""
        if half_width is not None:
            self.limits = tuple((-half_width, half_width) for _ in self.columns
                                if _ != "unit")

    def values(self, line: bytes) -> tuple[tuple[float, ...], str] | None:
        """The reading's values and unit; None for a line that is not a measurement (device
        information); :class:`FrameError` for a line that cannot be one."""
        raise NotImplementedError

    def request_bytes(self, transaction: int) -> bytes | None:
        """The request to send, the ``transaction``-th of the session (from 1); None for an
        instrument that is not asked."""
        return self.request

    def transaction_of(self, transaction: int) -> int | None:
        """The transaction id the ``transaction``-th request carries (None: it carries none)."""
        return None

    def reply_transaction(self, line: bytes) -> int | None:
        """The transaction id a reply line carries (None: none, or not a reply that has one)."""
        return None


class Autocollimator(Instrument):
    def __init__(self, mode: str = "auto") -> None:
        if mode not in CAPTURE_MODES:
            raise ValueError(f"mode must be one of {', '.join(CAPTURE_MODES)}")
        super().__init__(("ac_x_arcsec", "ac_y_arcsec"), start=command("stream"),
                         stop=command("stop"), poll=command("single"), mode=mode,
                         limits=((-AUTOCOLLIMATOR_RANGE_ARCSEC, AUTOCOLLIMATOR_RANGE_ARCSEC),) * 2,
                         tail_parses=False)

    def values(self, line: bytes):
        frame = parse_autocollimator_line(line)
        if not isinstance(frame, AutocollimatorFrame):
            return None
        if not frame.complete:
            missing = " and ".join(a for a, v in (("x", frame.x_arcsec), ("y", frame.y_arcsec))
                                   if v is None)
            raise NoMeasurement(f"status {frame.status}: {missing} not valid",
                                tuple(key for key, v in zip(self.columns, (frame.x_arcsec,
                                                                           frame.y_arcsec),
                                                            strict=True) if v is None))
        return (frame.x_arcsec, frame.y_arcsec), "arcsec"


class Theodolite(Instrument):
    """GeoCOM TMC_GetAngle5, each request with a transaction id (1 … 7, round again)."""

    def __init__(self) -> None:
        super().__init__(("azimuth_deg", "zenith_deg"),
                         request=request(GET_ANGLE5, INCLINE_AUTOMATIC),
                         limits=((0.0, 360.0), (0.0, 360.0)))  # GeoCOM: 0 … 2π rad

    def transaction_of(self, transaction: int) -> int:
        return (transaction - 1) % MAX_TRANSACTION_ID + 1

    def request_bytes(self, transaction: int) -> bytes:
        return request(GET_ANGLE5, INCLINE_AUTOMATIC, trid=self.transaction_of(transaction))

    def reply_transaction(self, line: bytes) -> int | None:
        try:
            return parse_geocom_reply(line).trid
        except FrameError:
            return None

    def values(self, line: bytes):
        hz, v = angles_of(parse_geocom_reply(line), GET_ANGLE5)
        return (math.degrees(hz), math.degrees(v)), "deg"


class LineReadoutInstrument(Instrument):
    def __init__(self, pattern: str = DEFAULT_PATTERN, ask: bytes | None = DEFAULT_REQUEST) -> None:
        super().__init__(("value", "unit"), request=ask)
        self.readout = LineReadout(pattern)

    def values(self, line: bytes):
        got = self.readout.parse(line)
        return (got.value,), got.unit


class SignalStreamInstrument(Instrument):
    """A sin/cos signal stream (an ADC, an oscilloscope): it sends one sample of both
    channels a line, unasked (models/capture/signal_stream.py). The fringe workbench's live
    view reads it in blocks (app/capture/signal_worker.py); ``anglebench capture signals``
    reads it a line at a time."""

    def __init__(self, pattern: str | None = None) -> None:
        super().__init__(("u_sin", "u_cos"), default_baud=115200)
        self.parser = SignalLineParser(pattern)

    def values(self, line: bytes):
        return self.parser.parse(line), "V"


INSTRUMENTS = {"autocollimator": Autocollimator, "theodolite": Theodolite,
               "readout": LineReadoutInstrument, "signals": SignalStreamInstrument}


def reading_columns(instrument: str, keys: Sequence[str], vertical_zenith: bool = False
                    ) -> list[tuple[str, int | None]]:
    """Where each value of a reading of ``instrument`` goes in a sheet whose columns are
    ``keys``: the column's key and index; index None for a cell chosen when it is taken (a
    readout's), -1 for a value the sheet has no column for. A theodolite's zenith angle goes
    to the elevation column when the workbench reads zenith angles (``vertical_zenith``)."""
    if instrument == "readout":
        return [("value", None)]
    out: list[tuple[str, int | None]] = []
    for key in INSTRUMENTS[instrument]().columns:
        target = key
        if key == "zenith_deg" and vertical_zenith and "elevation_deg" in keys:
            target = "elevation_deg"
        out.append((target, list(keys).index(target) if target in keys else -1))
    return out


@functools.cache
def _instrument(name: str) -> Instrument:
    return INSTRUMENTS[name]()


def frame_values(instrument: str, line: bytes) -> tuple[float, ...] | None:
    """The values a raw line of ``instrument`` reads (None: not a reading)."""
    if instrument not in INSTRUMENTS:
        return None
    try:
        parsed = _instrument(instrument).values(line)
    except (FrameError, ValueError):
        return None
    return None if parsed is None else tuple(parsed[0])
