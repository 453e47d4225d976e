"""regwin74: the key's fingerprint row is not covered by the signed state, and in 0.8.22 it
decided alone whether the key given is the register's. Someone who can write the database
(no key) who changes that row makes the lab's right key read as "not the key this register
was signed with": every signature check and the state's signature check are then switched
off, and a record they forged (rewritten, its chain recomputed: the reg73 #1 attack) is
never called changed — the lab is told to look for another key file instead.

Now the key is the register's when anything it signed says so (the state's signature, a
record's, the high-water mark beside the key); a fingerprint row that is not that key's is
reported as changed, and the forged record is found. A wrong key is still said to be one.

The attacks are made with SQL, as /work/reg73/repro does; the chain is recomputed from its
documented definition (tests/register_forgery.py): nothing is imported from the code they
check but its public entry points."""

from __future__ import annotations

import os
import shutil

import pytest

from app.main import main
from models.register.store import IssueRequest, RegisterError
from tests.models.register.test_register_reg73 import (
    META,
    PROJECT,
    _issue,
    _key,
    _open,
    _rewrite_newest,
    _rows,
    _sql,
)
from tests.register_forgery import stand_in_pdf


def _swap_fingerprint_row(url: str) -> str:
    """The attacker's value in the fingerprint row (any 64 hex digits: they hold no key)."""
    forged = os.urandom(32).hex()
    _sql(url, "UPDATE register_state SET value = :v WHERE name = 'key_fingerprint'", v=forged)
    return forged


def _said(register) -> str:
    return " ".join(str(p) for p in [*register.problems, register.key_problem or ""])


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_a_fingerprint_row_changed_is_reported_and_the_right_key_still_checks(
        register_url, tmp_path):
    key = _key(tmp_path)
    _issue(register_url, 2, key)
    rows = _rows(register_url, "SELECT name FROM register_state")
    assert "key_fingerprint" in {r["name"] for r in rows}
    forged = _swap_fingerprint_row(register_url)
    with _open(register_url, key) as register:
        said = _said(register)
        assert register.key_problem is None, said  # the right key is not called another
        assert f"key fingerprint ({forged[:16]}…)" in said and "changed outside" in said
        with pytest.raises(RegisterError, match="changed outside AngleBench"):
            register.issue(IssueRequest("polygon", META, PROJECT), stand_in_pdf)


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_a_record_forged_behind_a_fingerprint_row_changed_is_found(register_url, tmp_path):
    """The newest record's customer rewritten, its chain recomputed and the head set (no
    key needed), then the fingerprint row changed: the forgery is still found."""
    key = _key(tmp_path)
    _issue(register_url, 2, key)
    _rewrite_newest(register_url, customer="Forged Customer Ltd")
    _swap_fingerprint_row(register_url)
    with _open(register_url, key) as register:
        said = _said(register)
        assert "not the key this register was signed with" not in said
        assert "AB-2026-0002: its signature is not the laboratory key's" in said
        assert "state" in said and "does not carry the laboratory key's signature" in said


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_every_signature_garbled_and_the_row_changed_the_mark_still_knows_the_key(
        register_url, tmp_path):
    """Nothing in the database carries the key's signature any more (every one and the
    state's overwritten, the row changed): the high-water mark beside the key, which the
    database's writer cannot sign, still tells that the key is the register's — so every
    record is called changed, not the key wrong. Without the mark nothing can tell the
    right key from another: then it is said to be another, nothing called forged."""
    key = _key(tmp_path)
    _issue(register_url, 2, key)
    _sql(register_url, "UPDATE certificates SET signature = :s",
         "UPDATE register_state SET value = :s WHERE name = 'state_signature'", s="0" * 64)
    _swap_fingerprint_row(register_url)
    with _open(register_url, key) as register:
        said = _said(register)
        assert register.key_problem is None, said
        assert "AB-2026-0001: its signature is not the laboratory key's" in said
    shutil.rmtree(tmp_path / "lab.key.high-water")
    with _open(register_url, key) as register:
        said = _said(register)
        assert "not the key this register was signed with" in said and "forged" not in said


@pytest.mark.parametrize("register_url", ["sqlite", "postgresql"], indirect=True)
def test_a_wrong_key_is_still_said_to_be_one_whatever_the_row(register_url, tmp_path):
    """Another key proves nothing, with the row as written or changed."""
    _issue(register_url, 2, _key(tmp_path))
    other = _key(tmp_path, "other.key")
    for swap in (False, True):
        if swap:
            _swap_fingerprint_row(register_url)
        with _open(register_url, other) as register:
            said = _said(register)
            assert "not the key this register was signed with" in said, said
            assert "forged" not in said and "changed outside" not in said


@pytest.mark.parametrize("register_url", ["sqlite"], indirect=True)
def test_verify_on_the_command_line_says_changed_not_wrong_key(register_url, tmp_path,
                                                               monkeypatch, capsys):
    """``anglebench register verify`` with the lab's key: exit 3 (changed after issue),
    naming the forged record, not exit 2 "name the laboratory's key file"."""
    key = _key(tmp_path)
    _issue(register_url, 2, key)
    _rewrite_newest(register_url, customer="Forged Customer Ltd")
    _swap_fingerprint_row(register_url)
    monkeypatch.setenv("ANGLEBENCH_REGISTER_KEY", key)
    assert main(["register", "--register", register_url, "verify"]) == 3
    out = capsys.readouterr().out
    assert "CHANGED AFTER ISSUE" in out and "AB-2026-0002: its signature" in out
