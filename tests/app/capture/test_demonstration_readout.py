"""The window's demonstration readout (Instrument › Demonstration instrument…), read with
a bare socket as the ND 28x protocol says (STX asks, one line answers):

* its noise and drift are in arcseconds, as the dialog's fields say (″, ″/s), though the
  readout sends degrees (day review 74 F5: the default 0.05 ″ gave σ = 0.05° = 180″);
* it goes through its positions again for every run of a plan — rising, then (a plan in
  both directions) falling, then rising again — as an axis the operator moves does (day
  review 74 F14: it held its last position for ever, a second run could not be
  practised)."""

from __future__ import annotations

import socket
import time

import numpy as np
import pytest

from app.capture.panel import DemonstrationProcess

pytestmark = pytest.mark.slow  # a process of its own: seconds


def _readings(port: str, seconds: float) -> list[tuple[float, float]]:
    """(time, value in the readout's degrees) of every answer over ``seconds``."""
    host, number = port.removeprefix("tcp://").split(":")
    out: list[tuple[float, float]] = []
    with socket.create_connection((host, int(number)), timeout=5) as link:
        start = time.monotonic()
        pending = b""
        while time.monotonic() - start < seconds:
            link.sendall(b"\x02")
            while b"\n" not in pending:
                pending += link.recv(256)
            line, pending = pending.split(b"\n", 1)
            value, unit = line.decode().split()
            assert unit == "deg"
            out.append((time.monotonic() - start, float(value)))
    return out


def _read(seconds: float, *args, **kwargs) -> np.ndarray:
    demo = DemonstrationProcess("readout", *args, **kwargs)
    try:
        return np.array(_readings(demo.port, seconds))
    finally:
        demo.close()


def test_the_readouts_drift_and_noise_are_in_arcseconds():
    got = _read(1.5, noise=0.0, drift=36.0)
    slope = np.polyfit(got[:, 0], got[:, 1], 1)[0] * 3600.0  # ″ a second
    assert slope == pytest.approx(36.0, rel=0.15)
    got = _read(1.5, noise=36.0, drift=0.0)
    sigma = float(np.std(got[:, 1], ddof=1)) * 3600.0
    assert len(got) > 20 and sigma == pytest.approx(36.0, rel=0.35)


def _plateaus(values: list[float]) -> list[float]:
    """The positions in the order the axis stood at them (a new one where the value moves
    by more than 1″)."""
    out: list[float] = []
    for v in values:
        if not out or abs(v - out[-1]) > 1.0 / 3600.0:
            out.append(v)
    return out


@pytest.mark.parametrize("bidirectional", [True, False])
def test_the_readout_goes_through_its_targets_again_for_every_run(bidirectional):
    hold = 0.15  # s a target: 22 of them hold two runs with room (0.3 took 6.6 s a case)
    got = _read(22 * hold, noise=0.0, bidirectional=bidirectional, hold_s=hold)
    stood = _plateaus([float(v) for _, v in got])
    targets = [0.0, 15.0, 30.0, 45.0]
    nearest = [min(targets, key=lambda t: abs(t - v)) for v in stood]
    assert all(abs(v - t) < 10.0 / 3600.0 for v, t in zip(stood, nearest, strict=True))
    run = targets + (targets[::-1] if bidirectional else [])
    # the first 2 runs and more: the targets in the plan's order, again and again
    assert nearest[:len(run) * 2] == run * 2, nearest
    if bidirectional:  # at the top, coming down stops a few arcseconds off: a new reading
        up, down = stood[3], stood[4]
        assert 1.0 < abs(down - up) * 3600.0 < 10.0
