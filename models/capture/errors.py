"""What a frame that cannot be read raises."""

from __future__ import annotations

__all__ = ["FrameError", "NoMeasurement"]


class FrameError(ValueError):
    """A line from the instrument that is not a frame of its protocol (noise, a wrong
    baud rate, a truncated reply) or that the instrument marks as not a measurement."""


class NoMeasurement(FrameError):
    """A whole frame of the instrument's protocol that carries no measurement: axes the
    instrument marks not valid, or a value beyond its range — what an autocollimator sends
    while its mirror is out of view (the table turning to the next face). The instrument is
    there and talking: not a fault of its link (live76 F3: out of view was reconnected every
    second and given up after ~15 s).

    ``columns``: the keys of the values concerned (the instrument's columns); ``value`` and
    ``limits``: the value beyond the range and the range (None: axes marked not valid)."""

    def __init__(self, text: str, columns: tuple[str, ...] = (), value: float | None = None,
                 limits: tuple[float, float] | None = None) -> None:
        super().__init__(text)
        self.columns, self.value, self.limits = tuple(columns), value, limits
