"""The software is identified (#29): ``anglebench --version`` and every certificate name the
version and the source's commit; installed without git, a digest of the source files."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pypdfium2 as pdfium
import pytest

from app.main import main
from app.writers.certificate_pdf import certificate_pdf_bytes
from models import __version__
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS
from models.software import SoftwareIdentity, software_identity, source_digest

ROOT = Path(__file__).resolve().parents[1]


def _head() -> str:
    if shutil.which("git") is None or not (ROOT / ".git").exists():
        pytest.skip("not a git checkout")
    return subprocess.run(["git", "-C", str(ROOT), "rev-parse", "HEAD"], capture_output=True,
                          text=True, check=True).stdout.strip()


def test_version_names_the_checkouts_commit(capsys):
    head = _head()
    assert main(["--version"]) == 0
    out = capsys.readouterr().out
    assert out.startswith(f"AngleBench {__version__}, commit {head}")
    run = subprocess.run([sys.executable, "-m", "app.main", "--version"], cwd=ROOT,
                         capture_output=True, text=True, check=True)
    assert head in run.stdout


@pytest.mark.slow
def test_a_certificate_names_the_commit(samples_dir):
    head = _head()
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), {})
    details = json.loads((samples_dir / "certificate_theodolite.json").read_text("utf-8"))
    document = kind.certificate_document(result, CertificateMetadata.from_dict(details),
                                         kind.sample_file, {})
    pdf = pdfium.PdfDocument(certificate_pdf_bytes(document))
    try:
        pages = [pdf[i].get_textpage().get_text_range() for i in range(len(pdf))]
    finally:
        pdf.close()
    assert all(head[:12] in page for page in pages)  # each page's foot
    assert head in re.sub(r"\s+", "", "".join(pages))  # the whole commit in the method


def test_without_git_the_source_digest_identifies_it(tmp_path):
    for package in ("app", "models", "widgets"):
        (tmp_path / package).mkdir()
        (tmp_path / package / "a.py").write_text("x = 1\n")
    before = source_digest(tmp_path)
    assert re.fullmatch(r"[0-9a-f]{64}", before)
    (tmp_path / "models" / "a.py").write_text("x = 2\n")
    assert source_digest(tmp_path) != before  # one changed line is another source
    identity = SoftwareIdentity("9.9", source_sha256=before)
    assert identity.line() == f"AngleBench 9.9, source sha256 {before}"
    assert identity.printed == f"9.9 (sha256 {before})"


def test_the_register_records_the_same():
    from models.register.store import software_versions

    identity = software_identity()
    versions = software_versions()
    assert versions["anglebench"] == __version__
    assert (versions.get("anglebench_commit", "").rstrip("+") == identity.commit
            or versions.get("anglebench_source_sha256") == identity.source_sha256)
    for library in ("numpy", "scipy", "fpdf2", "SQLAlchemy"):
        assert library in versions


def test_only_a_change_to_the_software_marks_it_modified(tmp_path):
    """The pictures ``make pictures`` writes are not a change to the software: a checkout
    where only they differ is not "-dirty" (its certificates' feet carry no "+"); any other
    tracked file changed is."""
    from models.software import describe_checkout

    if shutil.which("git") is None:
        pytest.skip("no git")

    def git(*args):
        subprocess.run(["git", "-C", str(tmp_path), "-c", "user.name=t", "-c",
                        "user.email=t@t", *args], check=True, capture_output=True)

    (tmp_path / "models").mkdir()
    (tmp_path / "resources" / "screenshots").mkdir(parents=True)
    (tmp_path / "models" / "a.py").write_text("x = 1\n")
    (tmp_path / "resources" / "screenshots" / "a.png").write_bytes(b"1")
    git("init", "-q")
    git("add", "-A")
    git("commit", "-qm", "one")
    assert not describe_checkout(tmp_path).endswith("-dirty")
    (tmp_path / "resources" / "screenshots" / "a.png").write_bytes(b"2")
    assert not describe_checkout(tmp_path).endswith("-dirty")
    (tmp_path / "models" / "a.py").write_text("x = 2\n")
    assert describe_checkout(tmp_path).endswith("-dirty")
