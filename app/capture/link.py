"""Opening an instrument's port: a serial device (``/dev/ttyUSB0``, ``COM3``) or a TCP
address (``tcp://host:port``, or pyserial's own ``socket://host:port``)."""

from __future__ import annotations

import serial

from models.messages import QT_TR_NOOP, message

__all__ = ["CaptureError", "open_link", "serial_url"]

#: a read returns after this long without bytes, so the worker can look up and stop
READ_TIMEOUT_S = 0.02


class CaptureError(Exception):
    """A fault of the link, its message naming the port."""


def serial_url(port: str) -> str:
    """What pyserial opens for ``port``: ``tcp://`` spelt as its ``socket://``."""
    if port.lower().startswith("tcp://"):
        return "socket://" + port[len("tcp://"):]
    return port


def open_link(port: str, baud: int) -> serial.SerialBase:
    """The open port; :class:`CaptureError` naming it when it cannot be opened."""
    try:
        return serial.serial_for_url(serial_url(port), baudrate=baud, timeout=READ_TIMEOUT_S,
                                     write_timeout=1.0)
    except (serial.SerialException, OSError, ValueError) as exc:
        raise CaptureError(message(QT_TR_NOOP("{port}: cannot open ({reason})"), port=port,
                                   reason=_reason(exc))) from None


def _reason(exc: BaseException) -> str:
    text = str(exc).strip() or type(exc).__name__
    return text.splitlines()[0][:200]
