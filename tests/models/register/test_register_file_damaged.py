"""hostile77 M1: a SQLite register file that is damaged (cut short, overwritten), is no
database, or is a folder was refused in SQLite's words alone ("database disk image is
malformed", "file is not a database", "unable to open database file"): now it says what the
file is and what to do; still nothing read or issued (exit 2)."""

from __future__ import annotations

import pytest

from app.main import main
from models.register.store import Register, RegisterError


@pytest.mark.parametrize("damage", ["cut", "garbage"])
def test_a_damaged_register_says_restore_it(register, damage, capsys):
    data = register.read_bytes()
    register.write_bytes(data[: len(data) // 2] if damage == "cut" else b"\x5a" * len(data))
    with pytest.raises(RegisterError, match="the file is damaged or is not a register"):
        Register(f"sqlite:///{register}")
    assert main(["register", "verify"]) == 2
    err = capsys.readouterr().err
    assert "restore the register from a backup" in err, err
    assert "acknowledge-loss" in err


def test_a_folder_named_as_the_register(tmp_path, monkeypatch, capsys):
    folder = tmp_path / "register.sqlite"
    folder.mkdir()
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(folder))
    assert main(["register", "list"]) == 2
    err = capsys.readouterr().err
    assert "is a folder, not a register file" in err, err
