"""Issue 40 item 1: no output of the command line or the window lands on the certificate
register (its database, its journal/WAL/SHM files, through a symbolic or a hard link), an
input or the open project; the register is left byte for byte, and still verifies."""

from __future__ import annotations

import hashlib
import json
import os
from unittest import mock

import pytest

from app.certificate_presenter import CertificatePresenter, CertificateView
from app.main import main
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.register.store import Register
from models.registry import KINDS

#: the tests are of where an output may land, never of a PDF's pages: each certificate's PDF
#: a stand-in (tests/app/conftest.py; ~0.5 s of CPU a certificate not printed)
pytestmark = pytest.mark.usefixtures("pdf_stand_in")


def _digest(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture
def register(tmp_path, monkeypatch):
    """An empty register at clash/register.sqlite, the one the commands use."""
    path = tmp_path / "clash" / "register.sqlite"
    path.parent.mkdir()
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(path))
    Register(f"sqlite:///{path}").close()
    return path


def _names_of(register, tmp_path):
    """The register named directly, through a symbolic link, a hard link, its WAL and its
    issuers' turn file (`--results register.sqlite.issuing` replaced it)."""
    (tmp_path / "sym.pdf").symlink_to(register)
    os.link(register, tmp_path / "hard.pdf")
    return [register, tmp_path / "sym.pdf", tmp_path / "hard.pdf",
            register.with_name(register.name + "-wal"),
            register.with_name(register.name + ".issuing")]


def test_analyze_outputs_onto_the_register_are_refused(register, tmp_path, samples_dir, capsys):
    before = _digest(register)
    sample = str(samples_dir / "polygon_sample.csv")
    for target in _names_of(register, tmp_path):
        for flag in ("--certificate", "--results"):
            assert main(["analyze", "polygon", sample, flag, str(target)]) == 2
            err = capsys.readouterr().err
            assert f"{flag} {target} is the certificate register" in err, err
            assert "nothing was written" in err
    fringe = str(samples_dir / KINDS["fringe"].sample_file)
    assert main(["analyze", "fringe", fringe, "--table", str(register)]) == 2
    assert "--table" in capsys.readouterr().err
    assert _digest(register) == before
    assert main(["register", "verify"]) == 0


def test_an_output_onto_the_input_through_a_hard_link_is_refused(tmp_path, samples_dir, capsys):
    readings = tmp_path / "r.csv"
    readings.write_bytes((samples_dir / "polygon_sample.csv").read_bytes())
    os.link(readings, tmp_path / "hard.csv")
    before = readings.read_bytes()
    assert main(["analyze", "polygon", str(readings), "--results",
                 str(tmp_path / "hard.csv")]) == 2
    assert "is an input" in capsys.readouterr().err
    assert readings.read_bytes() == before


def test_a_certificate_named_over_a_lab_file_of_another_kind_is_refused(tmp_path, samples_dir,
                                                                       capsys):
    """A certificate's details JSON named as --certificate (meant as --metadata): it was
    replaced by a PDF without a word; now refused before anything is written or issued."""
    details = tmp_path / "certificate_positioning.json"
    details.write_bytes((samples_dir / "certificate_positioning.json").read_bytes())
    before = details.read_bytes()
    assert main(["analyze", "positioning", str(samples_dir / "positioning_sample.csv"),
                 "--certificate", str(details)]) == 2
    assert "exists and is not a PDF" in capsys.readouterr().err
    assert details.read_bytes() == before


def test_register_show_and_export_onto_the_register_are_refused(register, tmp_path, capsys):
    before = _digest(register)
    for target in _names_of(register, tmp_path):
        assert main(["register", "export", str(target)]) == 2
        assert f"OUT.zip {target} is the certificate register" in capsys.readouterr().err
        for flag in ("--pdf", "--project"):
            assert main(["register", "show", "AB-1", flag, str(target)]) == 2
            assert f"{flag} {target} is the certificate register" in capsys.readouterr().err
    assert main(["register", "show", "AB-1", "--pdf", str(tmp_path / "p.pdf"), "--project",
                 str(tmp_path / "p.pdf")]) == 2
    assert "--pdf and --project name the same file" in capsys.readouterr().err
    assert _digest(register) == before


@pytest.mark.slow
def test_an_issued_certificate_onto_the_register_uses_no_number(register, tmp_path,
                                                                 samples_dir, capsys):
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": ""})
    (tmp_path / "m.json").write_text(json.dumps(meta), encoding="utf-8")
    sample = str(samples_dir / "polygon_sample.csv")
    assert main(["analyze", "polygon", sample, "--metadata", str(tmp_path / "m.json"),
                 "--certificate", str(tmp_path / "ok.pdf")]) == 0
    capsys.readouterr()
    before = _digest(register)
    for target in _names_of(register, tmp_path):
        assert main(["analyze", "polygon", sample, "--metadata", str(tmp_path / "m.json"),
                     "--certificate", str(target)]) == 2
        assert "is the certificate register" in capsys.readouterr().err
    assert _digest(register) == before
    with Register(f"sqlite:///{register}") as opened:
        assert len(opened.list()) == 1 and opened.audit(pdfs=True) == []
        number = opened.list()[0].number
    assert main(["register", "show", number, "--pdf", str(register)]) == 2
    assert _digest(register) == before


class Store(dict):
    def value(self, key, default=None):
        return self.get(key, default)

    def setValue(self, key, value):  # noqa: N802 - QSettings' name
        self[key] = value


def test_the_window_refuses_an_export_onto_the_register_or_the_open_project(
        register, tmp_path, samples_dir):
    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, Store(), lambda: {}, mock.Mock())
    project = tmp_path / "open.anglebench.json"
    project.write_text("{}")
    presenter.open_project_path = lambda: project
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    before = _digest(register)
    for target, says in ((register, "is the certificate register"),
                         (project, "is the open project")):
        view.choose_save_path.return_value = str(target)
        assert not presenter.export_results(kind, result, {}, "run.csv")
        assert says in view.tell.call_args.args[1]
        view.edit_certificate_details.return_value = CertificateMetadata(lab_name="Lab")
        view.confirm_draft.return_value = True
        link = tmp_path / f"link-{target.stem}.pdf"  # a certificate always ends in .pdf
        link.symlink_to(target)
        view.choose_save_path.return_value = str(link)
        assert not presenter.export_certificate(kind, result, {}, "run.csv")
        assert says in view.tell.call_args.args[1]
    assert _digest(register) == before and project.read_text() == "{}"


def test_register_export_neutralises_formula_cells(register, tmp_path, capsys):
    import csv
    import io
    import zipfile

    from models.register.store import IssueRequest

    hostile = {"customer_name": "=HYPERLINK(\"http://evil\",\"click\")",
               "item_serial": "+cmd|' /C calc'!A0", "item_description": "@SUM(1+1)",
               "operator": "-2+3+cmd|' /C calc'!A0", "item_manufacturer": "-19°52'57.0\""}
    meta = CertificateMetadata.from_dict({"lab_name": "Lab", "approver": "Dr. Li",
                                          "certificate_number": "AB-1", **hostile})
    with Register(f"sqlite:///{register}") as opened:
        opened.issue(IssueRequest("polygon", meta, "{}", {"peak": -0.5}), lambda m: b"%PDF x")
    assert main(["register", "export", str(tmp_path / "all.zip")]) == 0
    with zipfile.ZipFile(tmp_path / "all.zip") as archive:
        rows = list(csv.DictReader(io.StringIO(archive.read("index.csv").decode())))
    (row,) = rows
    assert row["customer"] == "'" + hostile["customer_name"]
    assert row["item_serial"] == "'" + hostile["item_serial"]
    assert row["item_description"] == "'" + hostile["item_description"]
    assert row["operator"] == "'" + hostile["operator"]
    assert row["item_manufacturer"] == "-19°52'57.0\""  # an angle is data: as it is
    assert row["number"] == "AB-1"
    for value in row.values():
        assert not value.startswith(("=", "+", "@")) or value.startswith("'")


def test_the_window_saves_no_project_or_register_pdf_onto_the_register(register, tmp_path):
    from app.register_presenter import RegisterPresenter, RegisterView
    from models.project.file import Project, save_project
    from models.project.output_guard import OutputRefused

    before = _digest(register)
    with pytest.raises(OutputRefused, match="is a database"):  # File › Save as, any register
        save_project(register, Project())
    view = mock.create_autospec(CertificateView, instance=True)
    certificates = CertificatePresenter(view, Store(), lambda: {}, mock.Mock())
    register_view = mock.create_autospec(RegisterView, instance=True)
    presenter = RegisterPresenter(register_view, certificates, lambda *a: True)
    presenter.selected = lambda: mock.Mock(number="AB-1")
    (tmp_path / "link.pdf").symlink_to(register)
    register_view.ask_pdf_path.return_value = str(tmp_path / "link.pdf")
    assert not presenter.save_pdf()
    assert "is the certificate register" in register_view.tell.call_args.args[1]
    assert _digest(register) == before


def test_the_window_refuses_an_export_onto_an_imported_readings_file(register, tmp_path,
                                                                     samples_dir):
    view = mock.create_autospec(CertificateView, instance=True)
    presenter = CertificatePresenter(view, Store(), lambda: {}, mock.Mock())
    readings = tmp_path / "run.csv"
    readings.write_bytes((samples_dir / KINDS["theodolite"].sample_file).read_bytes())
    presenter.inputs = lambda: [str(readings)]
    kind = KINDS["theodolite"]
    rows = map_columns(read_table(readings), kind.columns)
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), kind.checked_settings({}))
    before = readings.read_bytes()
    view.choose_save_path.return_value = str(readings)
    assert not presenter.export_results(kind, result, {}, "run.csv")
    assert "is an input" in view.tell.call_args.args[1]
    assert readings.read_bytes() == before


@pytest.mark.slow
def test_table_exports_refuse_an_input_the_open_project_and_the_register(register, tmp_path,
                                                                         samples_dir, capsys):
    """--table of the fringe, positioning and cross-calibration workbenches onto an input
    (the readings, the details, the log compared) is refused before anything is written."""
    meta = tmp_path / "meta.json"
    meta.write_text((samples_dir / "certificate_fringe.json").read_text("utf-8"), "utf-8")
    for key in ("fringe", "positioning", "crosscal"):
        readings = tmp_path / f"{key}.csv"
        readings.write_bytes((samples_dir / KINDS[key].sample_file).read_bytes())
        kept = {p: _digest(p) for p in (readings, meta)}
        for target in (readings, meta, tmp_path / f"link-{key}.tsv"):
            if target.name.startswith("link"):
                target.symlink_to(readings)
            assert main(["analyze", key, str(readings), "--metadata", str(meta),
                         "--table", str(target)]) == 2, key
            err = capsys.readouterr().err
            assert f"--table {target} is an input" in err and "nothing was written" in err, err
        assert {p: _digest(p) for p in kept} == kept
    before = _digest(register)
    after = tmp_path / "after.csv"
    after.write_bytes((samples_dir / KINDS["positioning"].sample_file).read_bytes())
    assert main(["analyze", "positioning", str(samples_dir / KINDS["positioning"].sample_file),
                 "--compare-after", str(after), "--table", str(after)]) == 2
    assert "is an input" in capsys.readouterr().err
    assert _digest(register) == before


@pytest.mark.slow
def test_the_windows_table_exports_spare_inputs_the_project_and_the_register(
        register, window, tmp_path, qtbot):
    """The export buttons of the fringe, positioning and cross-calibration workbenches are
    guarded like the certificate's: an imported readings file, the open project and the
    register (named through a link) are refused, told, and left as they were."""
    window.load_all_samples()
    readings = tmp_path / "imported.csv"
    readings.write_text("1,2\n")
    window.imported_files.append(str(readings))
    project = tmp_path / "open.anglebench.json"
    project.write_text("{}")
    window.projects.path = project
    (tmp_path / "register-link.csv").symlink_to(register)
    kept = {p: _digest(p) for p in (readings, project, register)}
    exports = {"fringe": "export_table", "positioning": "export_compensation",
               "crosscal": "save_polygon_reference"}
    for key, name in exports.items():
        presenter = window.presenter_of(key) if hasattr(window, "presenter_of") else next(
            p for p in window.presenters if p.kind.key == key)
        qtbot.waitUntil(lambda p=presenter: p.result is not None, timeout=60000)
        told = []
        presenter.view.tell = lambda title, text, told=told: told.append(text)
        for target, says in ((readings, "is an input"), (project, "is the open project"),
                             (tmp_path / "register-link.csv", "is the certificate register")):
            assert getattr(presenter, name)(str(target)) == "", (key, target)
            assert says in told[-1] and "nothing was written" in told[-1], (key, told)
    assert {p: _digest(p) for p in kept} == kept
    fringe = next(p for p in window.presenters if p.kind.key == "fringe")
    assert fringe.export_table(str(tmp_path / "table.csv"))  # another name: written
    assert (tmp_path / "table.csv").stat().st_size > 0
