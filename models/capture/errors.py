"""What a frame that cannot be read raises."""

from __future__ import annotations

__all__ = ["FrameError"]


class FrameError(ValueError):
    """A line from the instrument that is not a frame of its protocol (noise, a wrong
    baud rate, a truncated reply) or that the instrument marks as not a measurement."""
