"""hostile77 F4: no output replaces a key. ``--results`` and ``--table`` were judged by no
content check (they write text), so they replaced the DCC signing key and its certificate
(PEM files, named by ANGLEBENCH_DCC_SIGNING_KEY/…_CERTIFICATE or the window's settings) and
a register key not yet used (its high-water folder not made yet): a private key lost, or a
CSV that then signed as the register's key."""

from __future__ import annotations

import hashlib
import os

import pytest

from app.main import main
from models.project.output_guard import REGISTER_KEY_ENV_VAR, OutputRefused, check_output
from models.register import signing

PEM_KEY = (b"-----BEGIN PRIVATE KEY-----\nMIIEvQIBADANBgkqhkiG9w0BAQEFAASCBKcwggSjAgEAAoIBAQC7\n"
           b"-----END PRIVATE KEY-----\n")
PEM_CERTIFICATE = (b"-----BEGIN CERTIFICATE-----\nMIIDazCCAlOgAwIBAgIUJ\n"
                   b"-----END CERTIFICATE-----\n")


def _digest(path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture
def keys(tmp_path, monkeypatch):
    """The DCC's signing key and certificate, and a register key with no high-water folder
    beside it yet, each named in the environment."""
    folder = tmp_path / "keys"
    folder.mkdir()
    (folder / "dcc-signing.key").write_bytes(PEM_KEY)
    (folder / "dcc-signing.pem").write_bytes(PEM_CERTIFICATE)
    (folder / "lab.key").write_bytes(os.urandom(32))
    monkeypatch.setenv("ANGLEBENCH_DCC_SIGNING_KEY", str(folder / "dcc-signing.key"))
    monkeypatch.setenv("ANGLEBENCH_DCC_SIGNING_CERTIFICATE", str(folder / "dcc-signing.pem"))
    monkeypatch.setenv(REGISTER_KEY_ENV_VAR, str(folder / "lab.key"))
    return [folder / "dcc-signing.key", folder / "dcc-signing.pem", folder / "lab.key"]


def test_the_variable_is_the_registers():
    assert REGISTER_KEY_ENV_VAR == signing.KEY_ENV_VAR


@pytest.mark.parametrize("flag", ["--table", "--results"])
def test_analyze_refuses_a_table_or_results_over_a_key(keys, samples_dir, flag, capsys):
    sample = str(samples_dir / "positioning_sample.csv")
    for key in keys:
        before = _digest(key)
        assert main(["analyze", "positioning", sample, flag, str(key)]) == 2
        err = capsys.readouterr().err
        assert f"{flag} {key} is " in err and "nothing was written" in err, err
        assert _digest(key) == before


def test_a_pem_file_is_refused_wherever_it_is_named(keys, tmp_path, monkeypatch):
    for name in ("ANGLEBENCH_DCC_SIGNING_KEY", "ANGLEBENCH_DCC_SIGNING_CERTIFICATE"):
        monkeypatch.delenv(name)  # named in the window's settings, say: found by content
    link = tmp_path / "table.csv"
    link.symlink_to(keys[0])
    for path in (keys[0], keys[1], link):
        with pytest.raises(OutputRefused, match=r"is a key or a certificate \(PEM\)"):
            check_output(path, [], "--table")


def test_the_register_key_named_is_refused_before_its_first_signed_write(keys):
    assert not (keys[2].parent / "lab.key.high-water").exists()
    with pytest.raises(OutputRefused, match="laboratory key"):
        check_output(keys[2], [], "--results")
    os.link(keys[2], keys[2].parent / "hard.csv")
    with pytest.raises(OutputRefused, match="laboratory key"):
        check_output(keys[2].parent / "hard.csv", [], "--results")
