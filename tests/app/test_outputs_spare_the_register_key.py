"""An output named over the register's high-water mark or the laboratory's key is refused
(final review of stop 71: ``--results`` onto the mark wrote a results file there, and the
register then refused every issue as "restored or replayed"; onto the key, every signature
would have become another key's). The key is a file of random bytes with the mark folder
beside it, as a signed write leaves it; the mark is found by listing that folder, nothing
taken from the code that names it."""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from app.main import main
from tests.own_readings import own_readings

ROOT = Path(__file__).resolve().parents[2]
SAMPLE = ROOT / "resources" / "samples" / "theodolite_sample.csv"


@pytest.fixture
def keyed(lab_key) -> Path:
    """The laboratory's key file (tests/app/conftest.py ``lab_key``), as a path."""
    return Path(lab_key)


def _issue(tmp_path: Path, results: Path) -> int:
    details = json.loads((ROOT / "resources" / "samples" / "certificate_theodolite.json")
                         .read_text(encoding="utf-8"))
    for key in ("example", "certificate_number", "created", "issue_date"):
        details.pop(key, None)
    meta = tmp_path / "meta.json"
    meta.write_text(json.dumps(details), encoding="utf-8")
    # each its own run: readings of its own (the same readings and details are the first
    # calibration issued again, refused: register79)
    readings = own_readings(SAMPLE, f"run {len(os.listdir(tmp_path))}",
                            tmp_path.with_name(f"{tmp_path.name}-own"))
    return main(["analyze", "theodolite", str(readings), "--metadata", str(meta),
                 "--certificate", str(tmp_path / f"c{len(os.listdir(tmp_path))}.pdf"),
                 "--results", str(results), "--separate-calibration", "each its own run"])


def test_an_output_over_the_high_water_mark_or_the_key_is_refused(tmp_path, keyed, capsys):
    assert _issue(tmp_path, tmp_path / "r1.xlsx") == 0
    marks = list(Path(f"{keyed}.high-water").iterdir())
    assert len(marks) == 1
    mark, key = marks[0].read_bytes(), keyed.read_bytes()
    capsys.readouterr()
    assert _issue(tmp_path, marks[0]) == 2
    assert "high-water mark; nothing was written" in capsys.readouterr().err
    assert _issue(tmp_path, keyed) == 2
    assert "laboratory key; nothing was written" in capsys.readouterr().err
    assert marks[0].read_bytes() == mark and keyed.read_bytes() == key
    assert main(["register", "verify"]) == 0  # nothing stops the next issue
    assert _issue(tmp_path, tmp_path / "r2.xlsx") == 0
