"""An output that cannot be written says which file and why, in words, exit 2, as
docs/command-line.md promises (contract75 F12: on a full disk a draft certificate and a
--table gave "cannot write: [Errno 28] No space left on device", no file named, exit 1)."""

from __future__ import annotations

import errno
import os

import pytest

from app.main import main


def _full_disk(monkeypatch):
    """Every atomic write's fsync fails as on the review's 40 kB tmpfs."""
    import models.project.atomic_write as atomic_write

    def full(fd):
        raise OSError(errno.ENOSPC, "No space left on device")

    monkeypatch.setattr(atomic_write.os, "fsync", full)


@pytest.mark.parametrize(("kind", "sample", "flag", "name"), [
    ("polygon", "polygon_sample.csv", "--certificate", "draft.pdf"),
    ("polygon", "polygon_sample.csv", "--results", "r.xlsx"),
    ("positioning", "positioning_sample.csv", "--table", "t.csv"),
])
def test_a_full_disk_names_the_file_in_words_and_exits_2(samples_dir, tmp_path, capsys,
                                                         monkeypatch, kind, sample, flag, name):
    out = tmp_path / name
    _full_disk(monkeypatch)
    assert main(["analyze", kind, str(samples_dir / sample), flag, str(out),
                 "--language", "en"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert err[-1] == (f"anglebench analyze: {flag} {out} cannot be written: the disk is full; "
                       "nothing was written there (free some space and run again)")
    assert "Errno" not in "\n".join(err)
    assert os.listdir(tmp_path) == []  # no partial file, no temporary one


def test_another_failure_is_said_in_the_systems_words(samples_dir, tmp_path, capsys,
                                                      monkeypatch):
    import models.project.atomic_write as atomic_write

    def denied(fd):
        raise OSError(errno.EIO, "Input/output error")

    monkeypatch.setattr(atomic_write.os, "fsync", denied)
    out = tmp_path / "draft.pdf"
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"),
                 "--certificate", str(out), "--language", "en"]) == 2
    assert capsys.readouterr().err.strip().splitlines()[-1] == (
        f"anglebench analyze: --certificate {out} cannot be written (Input/output error); "
        "nothing was written there")
