"""A two-channel sin/cos signal stream read line by line: an ADC, an oscilloscope or an
encoder test box sending one sample of both channels a line.

By default a line holds two numbers, the sine channel's then the cosine channel's voltage,
separated by a comma, spaces or a tab (``0.512,-0.118``, ``0.512 -0.118``,
``0.512\\t-0.118``). A stream written otherwise is read with a regular expression the user
sets, with groups named ``sin`` and ``cos`` (e.g. ``t=\\S+ A=(?P<sin>\\S+) B=(?P<cos>\\S+)``);
the whole line must match. A line that is not a sample (a header, noise, a number that is
not finite) is refused with its reason: counted, kept in the raw trace, never read as a
sample.

A block of lines is read at once (:meth:`SignalLineParser.parse_lines`): a stream of
10 000 samples a second is handed on as arrays, never one object per sample.
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from models.capture.errors import FrameError

__all__ = ["DEFAULT_SIGNAL_PATTERN", "ParsedLines", "SignalLineParser"]

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
#: two numbers separated by a comma (spaces around it allowed), spaces or a tab
DEFAULT_SIGNAL_PATTERN = rf"\s*(?P<sin>{_NUMBER})(?:[ \t]*,[ \t]*|[ \t]+)(?P<cos>{_NUMBER})\s*"
#: the refusals kept word for word (the count goes on past it)
REFUSALS_KEPT = 20


@dataclass
class ParsedLines:
    """The samples a block of lines gives, in the order of the lines that read."""

    #: the channels' voltages (V), one per line that is a sample
    u_sin: np.ndarray
    u_cos: np.ndarray
    #: per line of the block: True when it became a sample
    used: np.ndarray
    #: the lines refused, and the first :data:`REFUSALS_KEPT` reasons
    refused: int = 0
    reasons: list[str] = field(default_factory=list)


class SignalLineParser:
    """The parser of one stream's lines (``pattern``: None for two numbers a line)."""

    def __init__(self, pattern: str | None = None) -> None:
        text = pattern or DEFAULT_SIGNAL_PATTERN
        try:
            self.pattern = re.compile(text)
        except re.error as exc:
            raise ValueError(f"pattern {text!r}: {exc}") from None
        missing = [g for g in ("sin", "cos") if g not in self.pattern.groupindex]
        if missing:
            raise ValueError(f"pattern {text!r} has no group named "
                             + " or ".join(repr(g) for g in missing))
        self.custom = bool(pattern)

    @staticmethod
    def _number(text: str, channel: str) -> float:
        number = "".join(text.split())
        if "," in number and "." not in number:
            number = number.replace(",", ".")  # a decimal comma (a user's pattern)
        try:
            value = float(number)
        except ValueError:
            raise FrameError(f"{channel}: not a number: {number[:40]!r}") from None
        if not math.isfinite(value):
            raise FrameError(f"{channel}: not a finite number: {number[:40]!r}")
        return value

    def parse(self, line: bytes) -> tuple[float, float]:
        """(u_sin, u_cos) of one line; :class:`FrameError` naming why it is not a sample."""
        try:
            text = line.decode("ascii")
        except UnicodeDecodeError:
            raise FrameError(f"not text: {line[:40]!r}") from None
        found = self.pattern.fullmatch(text)
        if not found:
            raise FrameError(f"not a sample (two numbers, sin then cos): {text[:40]!r}"
                             if not self.custom else
                             f"does not match the pattern: {text[:40]!r}")
        sin_text, cos_text = found.group("sin"), found.group("cos")
        if sin_text is None or cos_text is None:
            raise FrameError(f"no {'sin' if sin_text is None else 'cos'} value: {text[:40]!r}")
        return self._number(sin_text, "sin"), self._number(cos_text, "cos")

    def parse_lines(self, lines: Sequence[bytes]) -> ParsedLines:
        """Every line of a block read: the samples as arrays, which lines they came from,
        and the refusals counted (never raised)."""
        values = np.empty((len(lines), 2))
        used = np.zeros(len(lines), dtype=bool)
        reasons: list[str] = []
        refused = 0
        count = 0
        for i, line in enumerate(lines):
            try:
                values[count] = self.parse(line)
            except FrameError as exc:
                refused += 1
                if len(reasons) < REFUSALS_KEPT:
                    reasons.append(str(exc))
                continue
            used[i] = True
            count += 1
        return ParsedLines(values[:count, 0].copy(), values[:count, 1].copy(), used,
                           refused, reasons)
