"""The method validation cases, the independence of their simulators, and the report."""

from __future__ import annotations

import ast
import io
import re
from pathlib import Path

import pytest
from pypdf import PdfReader

from app.main import main

RIGS = ("rotation", "polygon_rig", "theodolite_rig", "fringe_rig", "positioning_rig",
        "crosscal_rig", "axis_figures_rig")


def test_rigs_import_nothing_from_the_code_they_check():
    """The simulators may use numpy, the standard library and each other, nothing else."""
    folder = Path(__file__).resolve().parents[2] / "models" / "validation"
    for name in RIGS:
        tree = ast.parse((folder / f"{name}.py").read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            if isinstance(node, ast.ImportFrom):
                module = node.module or ""
            elif isinstance(node, ast.Import):
                module = node.names[0].name
            else:
                continue
            allowed = module in ("__future__", "collections.abc", "dataclasses", "numpy") or (
                module.startswith("models.validation.") and module.rsplit(".", 1)[1] in RIGS)
            assert allowed, f"{name}.py imports {module}"


@pytest.mark.slow
def test_validate_command_writes_a_dated_report(tmp_path, capsys, validation_once):
    out = tmp_path / "validation.pdf"
    assert main(["validate", "--pdf", str(out), "--trials", "100"]) == 0
    printed = capsys.readouterr().out
    counted = re.search(r"^(\d+) passed, 0 failed$", printed, re.MULTILINE)
    assert counted, printed
    guide = Path(__file__).resolve().parents[2] / "docs" / "certificates-and-register.md"
    # the docs say how many (the README's "Validation" paragraph until #44 moved it there)
    assert f"runs {counted.group(1)} reference cases" in guide.read_text("utf-8")
    assert printed.count("pass  Theodolite run") >= 7 and printed.count("pass  Fringe") >= 5
    text = re.sub(r"\s+", " ", "\n".join(p.extract_text() for p in PdfReader(
        io.BytesIO(out.read_bytes())).pages))
    assert "Method validation report" in text and "reference cases passed" in text
    for name in ("numpy", "scipy", "Python", "AngleBench", "fpdf2", "SQLAlchemy", "PySide6",
                 "Document ID AB-VAL-", "Acceptance criteria", "hand-computed example",
                 "coverage factor k for ν = 8", "decision rule guard band", "register: issue",
                 "file import of", "certificate text as extracted"):
        assert name in text, name
    from models.software import software_identity

    assert software_identity().commit[:12] in text  # the checkout's commit
    assert "ζ spans ±187.9" in text and "largest |ε_x| at ψ = 10′" in text
    for source in ("check figure", "exact simulation", "budget vs Monte Carlo"):
        assert source in text
    assert re.search(r"Run on \d{4}-\d{2}-\d{2}", text)
