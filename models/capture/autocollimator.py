"""The Möller-Wedel ELCOMAT kind of electronic autocollimator: its serial protocol.

Commands are one letter ended by LF; replies are one line ended by CR:

========  =====================================  ==========================
command   what it asks                            reply
========  =====================================  ==========================
``a``     one absolute measurement                ``4 SSS x y``
``A``     absolute measurements, streamed         ``3 SSS x y`` each
``r``     one measurement relative to the zero    ``2 SSS x y``
``R``     relative measurements, streamed         ``1 SSS x y`` each
``s``     stop streaming                          (nothing)
``d``     device information                      ``8 serial day month year focal_mm``
========  =====================================  ==========================

``SSS`` is the status: its third digit says which axes hold a measurement (0 none,
1 x, 2 y, 3 both); x and y are in arcseconds. An axis the status marks invalid is
never read as a value, whatever number the line carries there (the instrument
repeats its last figure, or writes zero, when the reticle image leaves the sensor).

Sources: the issue's summary of the manual and Diamond Light Source's open EPICS
driver (``dls-controls/elcomat3000``: CR in, LF out, the status's third digit, the
``8`` device-information line), read for the protocol only. The relative codes
(``2``/``1``) follow the same pattern as the absolute ones; a frame of another code is
refused, not guessed at.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from models.capture.errors import FrameError

__all__ = ["ABSOLUTE_CODES", "AutocollimatorFrame", "DeviceInfo", "RELATIVE_CODES",
           "command", "parse_autocollimator_line"]

#: reply codes of absolute measurements (single ``a``, streamed ``A``) and relative ones
ABSOLUTE_CODES = {"4": "single", "3": "stream"}
RELATIVE_CODES = {"2": "single", "1": "stream"}
#: the commands, as sent (each ended by LF)
COMMANDS = {"single": b"a", "stream": b"A", "single_relative": b"r", "stream_relative": b"R",
            "stop": b"s", "device": b"d"}

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_MEASUREMENT = re.compile(rf"([1234])\s+(\d{{3}})\s+({_NUMBER})\s+({_NUMBER})")
_DEVICE = re.compile(r"8((?:\s+\d+){5})")


def command(name: str) -> bytes:
    """The bytes of a command (``single``, ``stream``, ``stop``, ``device`` …), LF-ended."""
    return COMMANDS[name] + b"\n"


@dataclass(frozen=True)
class AutocollimatorFrame:
    """One measurement line: x and y in arcseconds, None where the status marks the axis
    invalid."""

    code: str
    status: str
    x_arcsec: float | None
    y_arcsec: float | None

    @property
    def relative(self) -> bool:
        return self.code in RELATIVE_CODES

    @property
    def complete(self) -> bool:
        """Both axes hold a measurement."""
        return self.x_arcsec is not None and self.y_arcsec is not None


@dataclass(frozen=True)
class DeviceInfo:
    serial: int
    day: int
    month: int
    year: int
    focal_length_mm: int


def _text(line: bytes) -> str:
    try:
        return line.decode("ascii").strip()
    except UnicodeDecodeError:
        raise FrameError(f"not text: {line[:40]!r}") from None


def parse_autocollimator_line(line: bytes) -> AutocollimatorFrame | DeviceInfo:
    """One line (without its CR) as the instrument sent it; :class:`FrameError` for
    anything else."""
    text = _text(line)
    found = _MEASUREMENT.fullmatch(text)
    if found:
        code, status, x_text, y_text = found.groups()
        axes = status[2]
        if axes not in "0123":
            raise FrameError(f"status {status}: third digit {axes} is not 0-3")
        x, y = float(x_text), float(y_text)
        if not (math.isfinite(x) and math.isfinite(y)):
            raise FrameError(f"not a finite reading: {text!r}")
        return AutocollimatorFrame(code, status, x if axes in "13" else None,
                                   y if axes in "23" else None)
    found = _DEVICE.fullmatch(text)
    if found:
        return DeviceInfo(*(int(v) for v in found.group(1).split()))
    raise FrameError(f"not an autocollimator frame: {text[:40]!r}")
