"""Opening an instrument's port: a serial device (``/dev/ttyUSB0``, ``COM3``) or a TCP
address (``tcp://host:port``, or pyserial's own ``socket://host:port``).

A TCP address is opened as a plain socket (:class:`TcpLink`), not through pyserial's
``socket://`` handler: that handler empties its input when it opens, so the frames an
instrument (or a serial-to-network bridge) sends as soon as it is connected were lost,
and it says one byte is waiting whatever it holds, so lines were read a byte per call."""

from __future__ import annotations

import contextlib
import select
import socket

import serial

from models.messages import QT_TR_NOOP, message

__all__ = ["CaptureError", "TcpLink", "open_link", "serial_url"]

#: a read returns after this long without bytes, so the worker can look up and stop
READ_TIMEOUT_S = 0.02


class CaptureError(Exception):
    """A fault of the link, its message naming the port."""


def serial_url(port: str) -> str:
    """What pyserial opens for ``port``: ``tcp://`` spelt as its ``socket://``."""
    if port.lower().startswith("tcp://"):
        return "socket://" + port[len("tcp://"):]
    return port


#: how long connecting to a TCP address may take
CONNECT_TIMEOUT_S = 3.0
#: bytes read from a socket at once
READ_BLOCK = 65536


class TcpLink:
    """A TCP connection with the few calls the capture worker makes of a serial port."""

    def __init__(self, host: str, port: int, timeout: float = READ_TIMEOUT_S) -> None:
        self._socket = socket.create_connection((host, port), timeout=CONNECT_TIMEOUT_S)
        self._socket.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        self._socket.settimeout(1.0)  # a write that cannot go out in 1 s is a dropped link
        self.timeout = timeout

    @property
    def in_waiting(self) -> int:
        return 0

    def read(self, size: int = READ_BLOCK) -> bytes:
        """What has arrived (up to ``size``, at least a block when more is there), or b""
        after :attr:`timeout`; :class:`OSError` when the peer has closed the connection."""
        ready, _, _ = select.select([self._socket], [], [], self.timeout)
        if not ready:
            return b""
        data = self._socket.recv(max(size, READ_BLOCK))
        if not data:
            raise ConnectionResetError("the instrument closed the connection")
        return data

    def write(self, data: bytes) -> int:
        self._socket.sendall(data)
        return len(data)

    def reset_input_buffer(self) -> None:
        """Nothing: a new connection holds nothing from before it."""

    def close(self) -> None:
        with contextlib.suppress(OSError):
            self._socket.shutdown(socket.SHUT_RDWR)
        self._socket.close()


#: what a port that cannot be opened is said with (the command line ends on the first one
#: before the port was ever opened: docs/capture.md's one line)
CANNOT_OPEN = QT_TR_NOOP("{port}: cannot open ({reason})")


def tcp_port_refused(port: str) -> str | None:
    """Why ``tcp://host:N`` (or ``socket://``) names no TCP port: N outside 1 … 65535 (a
    Message); None for a good one and for a serial port."""
    address = _tcp_address(port)
    if address is None or 1 <= address[1] <= 65535:
        return None
    return message(QT_TR_NOOP("{port}: a TCP port is 1 to 65535"), port=port)


def _tcp_address(port: str) -> tuple[str, int] | None:
    lower = port.lower()
    for scheme in ("tcp://", "socket://"):
        if lower.startswith(scheme):
            rest = port[len(scheme):].split("?", 1)[0].rstrip("/")
            host, sep, number = rest.rpartition(":")
            if not sep or not number.isdigit():
                return None
            return host.strip("[]"), int(number)
    return None


def open_link(port: str, baud: int):
    """The open port; :class:`CaptureError` naming it when it cannot be opened."""
    address = _tcp_address(port)
    if address is not None:
        try:
            return TcpLink(*address)
        except (OSError, ValueError) as exc:
            raise CaptureError(message(CANNOT_OPEN, port=port,
                                       reason=_reason(exc))) from None
    try:
        return serial.serial_for_url(serial_url(port), baudrate=baud, timeout=READ_TIMEOUT_S,
                                     write_timeout=1.0)
    except (serial.SerialException, OSError, ValueError) as exc:
        raise CaptureError(message(CANNOT_OPEN, port=port,
                                   reason=_reason(exc))) from None


def _reason(exc: BaseException) -> str:
    # the system's words ("Connection refused"), not "[Errno 111] Connection refused"
    words = exc.strerror if isinstance(exc, OSError) and exc.strerror else None
    text = (words or str(exc)).strip() or type(exc).__name__
    return text.splitlines()[0][:200]
