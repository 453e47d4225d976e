"""A readout that answers with one line holding a number and perhaps its unit (an
encoder's position display such as HEIDENHAIN's ND 28x, a digital level, a
multimeter): read with a regular expression the user sets.

The pattern must have a group named ``value``; a group named ``unit`` is optional.
The default reads a signed decimal number (a decimal point or a decimal comma) and
the word after it. The readout is asked by sending ``request`` (default STX, which the
ND 28x family answers with one reading).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from models.capture.errors import FrameError

__all__ = ["DEFAULT_PATTERN", "DEFAULT_REQUEST", "LineReadout", "ReadoutValue"]

DEFAULT_PATTERN = (r"\s*[A-Za-z]?\s*[:=]?\s*(?P<value>[-+]?\s*\d+(?:[.,]\d+)?(?:[eE][-+]?\d+)?)"
                   r"\s*(?P<unit>\S*)\s*")
DEFAULT_REQUEST = b"\x02"


@dataclass(frozen=True)
class ReadoutValue:
    value: float
    unit: str


class LineReadout:
    """The parser of one readout's lines."""

    def __init__(self, pattern: str = DEFAULT_PATTERN) -> None:
        try:
            self.pattern = re.compile(pattern)
        except re.error as exc:
            raise ValueError(f"pattern {pattern!r}: {exc}") from None
        if "value" not in self.pattern.groupindex:
            raise ValueError(f"pattern {pattern!r} has no group named 'value'")

    def parse(self, line: bytes) -> ReadoutValue:
        try:
            text = line.decode("ascii")
        except UnicodeDecodeError:
            raise FrameError(f"not text: {line[:40]!r}") from None
        found = self.pattern.fullmatch(text)
        if not found:
            raise FrameError(f"does not match the pattern: {text[:40]!r}")
        number = "".join(found.group("value").split())
        if "," in number and "." in number:
            raise FrameError(f"both a decimal point and a decimal comma: {number!r}")
        try:
            value = float(number.replace(",", "."))
        except ValueError:
            raise FrameError(f"not a number: {number!r}") from None
        if not math.isfinite(value):
            raise FrameError(f"not a finite number: {number!r}")
        unit = found.group("unit") if "unit" in self.pattern.groupindex else None
        return ReadoutValue(value, unit or "")
