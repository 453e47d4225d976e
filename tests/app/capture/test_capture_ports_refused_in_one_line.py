"""A port that is none, or cannot be opened, is one line (contract75 F13): capture
tcp://host:99999 was tried ("Connection refused" ×4, as simulate refuses 99999 at once); a
port that cannot be opened printed 4 lines with the default --retries where
docs/capture.md promises "exits 2 with one line naming the port"; simulate --noise -1 was
accepted."""

from __future__ import annotations

import socket

import pytest

from app.main import main


def _closed_port() -> int:
    with socket.socket() as probe:  # a port nothing listens on
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


@pytest.mark.parametrize("number", ["99999", "0", "65536"])
def test_a_tcp_port_outside_1_to_65535_is_refused_before_anything(tmp_path, capsys, number):
    out = tmp_path / "x.csv"
    port = f"tcp://127.0.0.1:{number}"
    assert main(["capture", "autocollimator", port, "--out", str(out), "--language", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err == [f"anglebench capture: {port}: a TCP port is 1 to 65535"]
    assert list(tmp_path.iterdir()) == []


def test_a_port_that_cannot_be_opened_is_one_line_with_the_default_retries(tmp_path, capsys):
    out = tmp_path / "x.csv"
    port = f"tcp://127.0.0.1:{_closed_port()}"
    assert main(["capture", "theodolite", port, "--out", str(out), "--language", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert err[0].startswith(f"anglebench capture: {port}: cannot open (Connection refused)")
    assert err[0].endswith("no reading was taken")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("noise", ["-1", "nan", "inf"])
def test_simulate_refuses_a_negative_noise(capsys, noise):
    with pytest.raises(SystemExit) as done:
        main(["simulate", "autocollimator", "0", "--noise", noise, "--seconds", "0.1",
              "--language", "en"])
    assert done.value.code == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1].endswith(f"argument --noise: '{noise}': give a number of 0 or more")
