"""The command line's "Readings:" names the file as the window does (day review 66 F7): a
file imported with its SHA-256, the bundled sample as the sample — not its basename alone,
which two different files share."""

from __future__ import annotations

import hashlib
import shutil

import app.cli
from app.main import main


def _source(monkeypatch, path, tmp_path) -> str:
    written = []
    monkeypatch.setattr(app.cli, "_write_pdf_and_dcc",
                        lambda args, kind, result, document, words, settings:
                        written.append(document))
    assert main(["analyze", "polygon", str(path), "--certificate",
                 str(tmp_path / "d.pdf")]) == 0  # a draft: no details, nothing recorded
    return written[0].source_name


def test_a_file_is_named_with_its_digest_and_the_sample_as_the_sample(
        samples_dir, tmp_path, monkeypatch, capsys):
    copy = tmp_path / "polygon_sample.csv"
    shutil.copyfile(samples_dir / "polygon_sample.csv", copy)
    digest = hashlib.sha256(copy.read_bytes()).hexdigest()
    assert _source(monkeypatch, copy, tmp_path) == (
        f"imported from polygon_sample.csv (SHA-256 {digest})")
    assert _source(monkeypatch, samples_dir / "polygon_sample.csv", tmp_path) == (
        "the bundled sample polygon_sample.csv")
