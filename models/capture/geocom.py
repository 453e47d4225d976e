"""Leica GeoCOM, the ASCII remote-procedure calls of Leica theodolites and total
stations, as far as reading angles needs.

A request is ``%R1Q,<rpc>[,<trid>]:<param>,<param>…`` ended by CR LF; the reply is
``%R1P,<com_rc>[,<trid>]:<rc>[,<value>…]`` ended by CR LF. ``com_rc`` is the
communication's return code, ``rc`` the procedure's; 0 is GRC_OK for both. The
transaction id is optional on both sides (the reference manual's syntax puts it in
brackets): an instrument echoes the id of the request it answers, so a reply that
carries one is matched to its request, and a reply without one is taken as the answer
to the one request in flight. The client sends one request at a time and the next only
after the reply (or a reply timeout): the manual advises against queueing requests,
which the instrument's receive buffer may lose. The angle procedures read here:

* ``TMC_GetAngle1`` (RPC 2003, one parameter: the inclination mode) answers
  ``rc,Hz,V,AngleAccuracy,AngleTime,CrossIncline,LengthIncline,AccuracyIncline,
  InclineTime,FaceDef``;
* ``TMC_GetAngle5`` (RPC 2107, same parameter) answers ``rc,Hz,V``.

Hz and V are in radians. A reply whose ``rc`` is not 0 (for example 1284, the
accuracy not guaranteed, or 1283, no full compensation) is refused with its code:
the instrument itself says that angle is not a measurement to certify.

Why our own client and not ``geocompy``: the part of GeoCOM a calibration bench needs
is two requests and one reply format (this module, about eighty lines, pure and
tested on bytes), whereas geocompy brings its own connection handling and object
model which would sit beside our worker thread, reconnection and raw-frame record
instead of under them, and one more dependency to pin for a frozen lab install.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from models.capture.errors import FrameError

__all__ = ["GET_ANGLE1", "GET_ANGLE5", "GeocomReply", "MAX_TRANSACTION_ID", "angles_of",
           "parse_geocom_reply", "request"]

GET_ANGLE1 = 2003
GET_ANGLE5 = 2107
#: inclination mode of the angle requests: 1 = automatic (the instrument decides)
INCLINE_AUTOMATIC = 1

#: transaction ids are counted 1 … 7 and round again (an id in that range is echoed by every
#: GeoCOM generation; with one request in flight, seven tell any late reply from the current)
MAX_TRANSACTION_ID = 7

_REPLY = re.compile(r"%R1P,(\d+)(?:,(\d+))?:(-?\d+)((?:,[^,]*)*)")


def request(rpc: int, *params: object, trid: int | None = None) -> bytes:
    """The request's bytes, CR LF ended."""
    head = f"%R1Q,{rpc}" + (f",{trid}" if trid is not None else "")
    return (head + ":" + ",".join(str(p) for p in params) + "\r\n").encode("ascii")


@dataclass(frozen=True)
class GeocomReply:
    com_rc: int
    trid: int | None  # None: the reply carries no transaction id
    rc: int
    values: tuple[str, ...]


def parse_geocom_reply(line: bytes) -> GeocomReply:
    """One reply line (without its CR LF); :class:`FrameError` for anything else."""
    try:
        text = line.decode("ascii").strip()
    except UnicodeDecodeError:
        raise FrameError(f"not text: {line[:40]!r}") from None
    found = _REPLY.fullmatch(text)
    if not found:
        raise FrameError(f"not a GeoCOM reply: {text[:40]!r}")
    com_rc, trid, rc, rest = found.groups()
    values = tuple(rest[1:].split(",")) if rest else ()
    return GeocomReply(int(com_rc), None if trid is None else int(trid), int(rc), values)


def angles_of(reply: GeocomReply, rpc: int) -> tuple[float, float]:
    """Hz and V in radians from the reply to TMC_GetAngle1 or TMC_GetAngle5."""
    if reply.com_rc != 0:
        raise FrameError(f"communication return code {reply.com_rc}")
    if reply.rc != 0:
        raise FrameError(f"the instrument's return code {reply.rc}: no valid angle")
    wanted = {GET_ANGLE1: 9, GET_ANGLE5: 2}[rpc]
    if len(reply.values) != wanted:
        raise FrameError(f"RPC {rpc} answers {wanted} values, this reply has {len(reply.values)}")
    try:
        hz, v = float(reply.values[0]), float(reply.values[1])
    except ValueError:
        raise FrameError(f"not angles: {reply.values[:2]!r}") from None
    if not (math.isfinite(hz) and math.isfinite(v)) or not (0 <= hz < 2 * math.pi + 1e-9
                                                              and 0 <= v < 2 * math.pi + 1e-9):
        raise FrameError(f"Hz {hz}, V {v}: not angles in 0 to 2π rad")
    return hz, v
