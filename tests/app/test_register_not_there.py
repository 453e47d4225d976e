"""Read-only register commands never make the register they are pointed at (contract75
F10: 'register --register /nonexistent/dir/x.sqlite list' made the file and its folders,
exit 0; 'register --register ./typo.sqlite verify' said "hash chain intact over 0
record(s)", exit 0): exit 2, one line naming the path, nothing made. Issuing makes one, and
so do the lab's set-up commands that come before the first certificate."""

from __future__ import annotations

import pytest

from app.main import main

READING = [["list"], ["list", "--json"], ["show", "AB-2026-0001"], ["verify"],
           ["verify", "--head", "0123456789abcdef"], ["head"], ["signatories"],
           ["withdraw", "AB-2026-0001", "--reason", "typo"],
           ["acknowledge-loss", "--by", "Li", "--reason", "restored"],
           ["clock-correction", "--by", "Li", "--reason", "clock", "--confirm-date",
            "2026-12-07"]]


@pytest.mark.parametrize("command", READING, ids=lambda c: " ".join(c[:2]))
def test_a_register_that_is_not_there_is_refused_and_not_made(tmp_path, capsys, command):
    folder = tmp_path / "nonexistent" / "dir"
    typo = folder / "x.sqlite"
    assert main(["register", "--register", str(typo), *command, "--language", "en"]) == 2
    captured = capsys.readouterr()
    assert captured.err.strip().splitlines() == [
        f"anglebench register: there is no register at {typo}; nothing was created (a "
        "register is made by its first certificate): check --register or ANGLEBENCH_REGISTER"]
    assert captured.out == ""
    assert not (tmp_path / "nonexistent").exists()


def test_verify_of_a_file_and_export_against_a_mistyped_register(tmp_path, capsys,
                                                                 monkeypatch):
    pdf = tmp_path / "c.pdf"
    pdf.write_bytes(b"%PDF-1.4 not ours")
    typo = tmp_path / "typo.sqlite"
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(typo))  # the same through the environment
    assert main(["register", "verify", str(pdf), "--language", "en"]) == 2
    assert f"there is no register at {typo}" in capsys.readouterr().err
    assert main(["register", "export", str(tmp_path / "all.zip"), "--language", "en"]) == 2
    assert f"there is no register at {typo}" in capsys.readouterr().err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.pdf"]


def test_set_up_commands_make_the_register_and_then_it_reads(tmp_path, capsys):
    reg = tmp_path / "lab.sqlite"
    assert main(["register", "--register", str(reg), "continue", "AB-{year}-{seq:04d}", "43",
                 "--date", "2026-11-24", "--language", "en"]) == 0
    assert "will be AB-2026-0043" in capsys.readouterr().out
    assert reg.is_file()
    assert main(["register", "--register", str(reg), "list", "--language", "en"]) == 0
    assert main(["register", "--register", str(reg), "verify", "--language", "en"]) == 0
    assert "hash chain intact" in capsys.readouterr().out
