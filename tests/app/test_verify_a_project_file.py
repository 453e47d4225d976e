"""``register verify`` of a project file (hostile78 V1): the project the register exported
with a certificate, untouched, was "NOT in the register (no results file … altered …)",
exit 1. It is said to be the project recorded with that certificate (exit 0; 4 once the
certificate is withdrawn); a project changed since is said to be a project no certificate
was recorded with (exit 1), never an altered results file."""

from __future__ import annotations

import json

from app.main import main


def test_a_projects_file_is_told_as_a_project(samples_dir, tmp_path, capsys):
    meta = json.loads((samples_dir / "certificate_theodolite.json").read_text(encoding="utf-8"))
    meta.pop("issue_date")
    meta.update(example=False, certificate_number="")
    (tmp_path / "m.json").write_text(json.dumps(meta), encoding="utf-8")
    assert main(["analyze", "theodolite", str(samples_dir / "theodolite_sample.csv"),
                 "--certificate", str(tmp_path / "c.pdf"),
                 "--metadata", str(tmp_path / "m.json")]) == 0
    project = tmp_path / "p.anglebench.json"
    assert main(["register", "show", "AB-2026-0001", "--project", str(project)]) == 0
    capsys.readouterr()
    assert main(["register", "verify", str(project)]) == 0
    out = capsys.readouterr().out
    assert (f"{project}: the project (readings, settings and details) recorded with "
            "certificate AB-2026-0001, byte for byte as the register holds it") in out
    assert "NOT in the register" not in out
    edited = tmp_path / "edited.anglebench.json"
    edited.write_text(project.read_text(encoding="utf-8").replace('"-20"', '"-21"', 1),
                      encoding="utf-8")
    assert main(["register", "verify", str(edited)]) == 1
    out = capsys.readouterr().out
    assert (f"{edited}: an AngleBench project file, which is not the project recorded with "
            "any certificate") in out
    assert "no results file" not in out
    assert main(["register", "withdraw", "AB-2026-0001", "--reason", "wrong item"]) == 0
    capsys.readouterr()
    assert main(["register", "verify", str(project)]) == 4
    assert "AB-2026-0001 is no longer valid: withdrawn (wrong item)" in capsys.readouterr().out
