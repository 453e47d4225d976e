"""Bytes from a serial line or a socket, cut into lines.

An instrument ends its replies with CR (the ELCOMAT kind), CR LF (GeoCOM) or LF; a
line ends at either CR or LF and empty lines are dropped, so CR LF is one end. Line
noise and a wrong baud rate give bytes that are not text, or no end at all: a line
longer than ``max_line`` bytes is thrown away (counted in :attr:`LineFramer.dropped`)
instead of growing without bound, and whatever follows its end is read afresh.
"""

from __future__ import annotations

__all__ = ["LineFramer"]


class LineFramer:
    """Feed it bytes as they arrive; it returns the complete lines (without their end)."""

    def __init__(self, max_line: int = 256) -> None:
        self.max_line = max_line
        self._buffer = bytearray()
        self._overlong = False
        #: lines thrown away for being longer than ``max_line``
        self.dropped = 0

    def feed(self, data: bytes) -> list[bytes]:
        lines: list[bytes] = []
        start, size = 0, len(data)
        while start < size:
            cr, lf = data.find(b"\r", start), data.find(b"\n", start)
            end = min(e for e in (cr, lf, size) if e >= 0)
            piece = data[start:end]
            if not self._overlong:
                if len(self._buffer) + len(piece) > self.max_line:
                    self._buffer.clear()
                    self._overlong = True
                    self.dropped += 1
                else:
                    self._buffer += piece
            if end == size:
                break
            # a line end
            if self._overlong:
                self._overlong = False
            elif self._buffer:
                lines.append(bytes(self._buffer))
            self._buffer.clear()
            start = end + 1
        return lines

    def reset(self) -> None:
        """Forget a partial line (after a reconnection: its start came from the old link)."""
        self._buffer.clear()
        self._overlong = False
