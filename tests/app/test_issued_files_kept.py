"""rev63 F5–F7: no output replaces a file the register issued — ``register export`` (F5),
the window's table exports (F6) and the second of two issues naming the same results file
at once (F7: the name is taken without replacing, the second's bytes are kept under the
temporary name and recorded). The register of each test is its own (conftest.py)."""

from __future__ import annotations

import hashlib
import json
import shutil
import zipfile

import pytest

from app.main import main
from models.register.location import register_url
from models.register.store import Register
from tests.own_readings import own_readings

#: the tests are of which files an output may replace, never of a PDF's pages: each
#: certificate's PDF a stand-in (tests/app/conftest.py; ~0.5 s of CPU a certificate not printed)
pytestmark = pytest.mark.usefixtures("pdf_stand_in")


def _details(samples_dir, tmp_path, name="details.json", **changes):
    meta = json.loads((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8"))
    meta.update({"example": False, "certificate_number": "", **changes})
    path = tmp_path / name
    path.write_text(json.dumps(meta), encoding="utf-8")
    return path


def _issue(samples_dir, tmp_path, *outputs, separate=""):
    """The polygon sample issued; with ``separate``, a calibration of its own of the item:
    readings of its own (tests/own_readings.py; the same readings and details are the first
    calibration issued again, refused: register79)."""
    readings = samples_dir / "polygon_sample.csv"
    if separate:
        readings = own_readings(readings, separate, tmp_path.with_name(f"{tmp_path.name}-own"))
    return main(["analyze", "polygon", str(readings),
                 "--metadata", str(_details(samples_dir, tmp_path)), *outputs,
                 *(["--separate-calibration", separate] if separate else [])])


def _sha(path):
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _results():
    with Register(register_url()) as register:
        return {r["number"]: r["sha256"] for r in register.results_records()}


@pytest.mark.slow
def test_register_export_never_replaces_an_issued_file_nor_an_existing_one(
        samples_dir, tmp_path, capsys):
    """F5: 'register export r.xlsx' replaced the issued results file (its only copy) with
    the ZIP; onto the issued PDF too. An existing file is replaced only with --overwrite."""
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"
    assert _issue(samples_dir, tmp_path, "--certificate", str(pdf), "--results", str(xlsx)) == 0
    (number,) = _results()
    kept = {pdf: _sha(pdf), xlsx: _sha(xlsx)}
    capsys.readouterr()
    assert main(["register", "export", str(xlsx)]) == 2
    assert (f"anglebench register: {xlsx} is the results file of certificate {number}, as "
            "issued; an issued file is never replaced") in capsys.readouterr().err
    assert main(["register", "export", str(pdf), "--overwrite"]) == 2  # never, even asked
    assert f"{pdf} is the PDF of certificate {number}, as issued" in capsys.readouterr().err
    assert {path: _sha(path) for path in kept} == kept
    other = tmp_path / "notes.zip"
    other.write_bytes(b"someone's notes")
    assert main(["register", "export", str(other)]) == 2
    assert (f"anglebench register: {other} exists; nothing was written: choose another name, "
            "or add --overwrite to replace it") in capsys.readouterr().err
    assert other.read_bytes() == b"someone's notes"
    assert main(["register", "export", str(other), "--overwrite"]) == 0
    with zipfile.ZipFile(other) as archive:
        assert f"pdf/{number}.pdf" in archive.namelist()


@pytest.mark.slow
def test_two_issues_naming_one_results_file_both_keep_theirs(samples_dir, tmp_path, capsys,
                                                             monkeypatch):
    """F7: two issuers with the same --results both passed the check; the later rename
    replaced the first's results file and 'register verify' said all was intact. Here the
    other issue puts its results file at r.xlsx between this one's check and its rename."""
    first = tmp_path / "first.xlsx"
    assert _issue(samples_dir, tmp_path, "--results", str(first),
                  "--certificate", str(tmp_path / "first.pdf")) == 0
    (one,) = _results()
    target = tmp_path / "r.xlsx"
    recorded = Register.record_results

    def meanwhile(self, *args, **kwargs):  # the other issuer wins the name
        outcome = recorded(self, *args, **kwargs)
        shutil.copyfile(first, target)
        return outcome

    monkeypatch.setattr(Register, "record_results", meanwhile)
    capsys.readouterr()
    assert _issue(samples_dir, tmp_path, "--results", str(target), "--certificate",
                  str(tmp_path / "second.pdf"), separate="a second run") == 2
    said = capsys.readouterr().err
    results = _results()
    (two,) = set(results) - {one}
    assert _sha(target) == results[one] == _sha(first)  # the first's results file stays
    assert (f"certificate {two} is issued, recorded and written, and its results file "
            f"recorded, but not put in place: {target} became another certificate's issued "
            "file meanwhile, which is never replaced. The recorded results file is ") in said
    kept = tmp_path / said.split("The recorded results file is ")[1].split("; give it")[0]
    assert kept.parent == tmp_path and _sha(kept) == results[two]  # the second's, kept
    monkeypatch.undo()
    # the undo took the test's register away too (conftest's ANGLEBENCH_REGISTER): this
    # verified a new empty register in the default place, "intact" (contract75 F10)
    monkeypatch.setenv("ANGLEBENCH_REGISTER", str(tmp_path / "register.sqlite"))
    capsys.readouterr()
    assert main(["register", "verify"]) == 0
    assert "hash chain intact" in capsys.readouterr().out


@pytest.mark.slow
def test_the_windows_table_exports_never_replace_an_issued_results_file(
        samples_dir, tmp_path, window, qtbot, capsys):
    """F6: the compensation table, the fringe correction table and the cross-calibration
    face deviations replaced an issued results file ('register verify' then said NOT in
    the register); the CLI's --table refuses the same file."""
    issued = {}
    for key in ("positioning", "crosscal"):
        meta = json.loads((samples_dir / f"certificate_{key}.json").read_text("utf-8"))
        meta.update({"example": False, "certificate_number": ""})
        details = tmp_path / f"{key}.json"
        details.write_text(json.dumps(meta), "utf-8")
        issued[key] = tmp_path / f"{key}-results.csv"
        assert main(["analyze", key, str(samples_dir / f"{key}_sample.csv"), "--metadata",
                     str(details), "--certificate", str(tmp_path / f"{key}.pdf"),
                     "--results", str(issued[key])]) == 0
    numbers = _results()
    kept = {path: _sha(path) for path in issued.values()}
    window.load_all_samples()
    exports = (("positioning", "export_compensation", issued["positioning"]),
               ("fringe", "export_table", issued["positioning"]),
               ("crosscal", "save_polygon_reference", issued["crosscal"]))
    for key, name, target in exports:
        presenter = next(p for p in window.presenters if p.kind.key == key)
        qtbot.waitUntil(lambda p=presenter: p.result is not None, timeout=60000)
        told = []
        presenter.view.tell = lambda title, text, told=told: told.append(text)
        assert getattr(presenter, name)(str(target)) == "", key
        number = next(n for n, sha in numbers.items() if sha == kept[target])
        assert (f"{target} is the results file of certificate {number}, as issued; an "
                "issued file is never replaced") in told[-1], (key, told)
    assert {path: _sha(path) for path in kept} == kept
    fringe = next(p for p in window.presenters if p.kind.key == "fringe")
    assert fringe.export_table(str(tmp_path / "table.csv"))  # another name: written


# -- rev64: every writer spares the register's files; a recorded leftover is never lost -----

def _issued(samples_dir, tmp_path):
    """A certificate issued with its PDF c.pdf and its results file r.xlsx: (number, the
    paths with their SHA-256)."""
    pdf, xlsx = tmp_path / "c.pdf", tmp_path / "r.xlsx"
    assert _issue(samples_dir, tmp_path, "--certificate", str(pdf), "--results", str(xlsx)) == 0
    (number,) = _results()
    return number, {pdf: _sha(pdf), xlsx: _sha(xlsx)}


@pytest.mark.slow
def test_validate_and_capture_never_replace_an_issued_file(samples_dir, tmp_path, capsys):
    """rev64 F1: 'validate --pdf r.xlsx' and 'capture --out r.xlsx' (no instrument needed:
    refused before one is asked) replaced the issued results file, the only copy, exit 0;
    'register verify' then called the real one NOT in the register."""
    number, kept = _issued(samples_dir, tmp_path)
    xlsx, pdf = tmp_path / "r.xlsx", tmp_path / "c.pdf"
    capsys.readouterr()
    assert main(["validate", "--trials", "100", "--pdf", str(xlsx)]) == 2
    assert (f"anglebench validate: --pdf {xlsx} is the results file of certificate {number}, "
            "as issued; an issued file is never replaced") in capsys.readouterr().err
    link = tmp_path / "latest.pdf"
    link.symlink_to(pdf)
    assert main(["validate", "--trials", "100", "--pdf", str(link)]) == 2  # through a link
    assert f"is the PDF of certificate {number}, as issued" in capsys.readouterr().err
    for out in (xlsx, pdf):
        assert main(["capture", "autocollimator", "tcp://127.0.0.1:9", "--out", str(out),
                     "--readings", "3"]) == 2
        assert (f"anglebench capture: --out {out} is the "
                f"{'results file' if out == xlsx else 'PDF'} of certificate {number}, as "
                "issued") in capsys.readouterr().err
    assert {path: _sha(path) for path in kept} == kept
    assert main(["register", "verify", str(xlsx)]) == 0


@pytest.mark.slow
def test_the_windows_save_through_a_link_and_save_pdf_never_replace_an_issued_file(
        samples_dir, tmp_path, window, qtbot):
    """rev64 F1: File › Save as… onto p.anglebench.json, a link to an issued results file,
    wrote the project into the results file; the register window's Save PDF… checked the
    register's own files only."""
    from unittest import mock

    from app.register_presenter import RegisterPresenter, RegisterView

    number, kept = _issued(samples_dir, tmp_path)
    xlsx = tmp_path / "r.xlsx"
    link = tmp_path / "p.anglebench.json"
    link.symlink_to(xlsx)
    window.projects.view.ask_save_path = lambda _folder: str(link)
    window.menus.save_as_action.trigger()
    assert window.told[-1].startswith(f"{link}: ")
    assert (f"is the results file of certificate {number}, as issued; an issued file is never "
            "replaced") in window.told[-1]
    assert window.told[-1].endswith("Your readings are still here.")
    assert window.projects.path is None
    window.projects.view.ask_save_path = lambda _folder: str(tmp_path / "p2.anglebench.json")
    window.menus.save_as_action.trigger()  # another name: saved
    assert window.projects.path == tmp_path / "p2.anglebench.json"
    register_view = mock.create_autospec(RegisterView, instance=True)
    presenter = RegisterPresenter(register_view, window.certificates, lambda *a: True)
    presenter.selected = lambda: mock.Mock(number=number)
    register_view.ask_pdf_path.return_value = str(xlsx)
    assert not presenter.save_pdf()
    assert (f"{xlsx} is the results file of certificate {number}, as issued"
            in register_view.tell.call_args.args[1])
    assert {path: _sha(path) for path in kept} == kept


@pytest.mark.slow
def test_the_later_of_two_issues_naming_one_pdf_never_replaces_the_first(
        samples_dir, tmp_path, capsys):
    """rev64 F7: two issues naming the same --certificate c.pdf both passed the check made
    before issuing; the later one's rename replaced the earlier's PDF, whose issuer had been
    told it was there. Forced interleaving: the other issue records and places c.pdf between
    this one's commit and its placing; this one is refused at the moment of placing."""
    pdf = tmp_path / "c.pdf"
    issue = Register.issue
    other = []

    def meanwhile(self, *args, **kwargs):  # after this one's commit, the other issues
        outcome = issue(self, *args, **kwargs)
        if not other:
            other.append(outcome[0].number)
            assert _issue(samples_dir, tmp_path, "--certificate", str(pdf),
                          separate="the other bench's run") == 0
        return outcome

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(Register, "issue", meanwhile)
        assert _issue(samples_dir, tmp_path, "--certificate", str(pdf)) == 2
    said = capsys.readouterr().err
    with Register(register_url()) as register:
        records = {r.number: r for r in register.list()}
    (mine,) = other
    (theirs,) = set(records) - {mine}
    assert f"Certificate {theirs} issued: written to {pdf}" in said
    assert _sha(pdf) == records[theirs].pdf_sha256  # the first placed stays
    assert (f"certificate {mine} is issued and recorded, but not written: {pdf} became another "
            "certificate's issued file meanwhile, which is never replaced; save it with "
            f"'anglebench register show {mine} --pdf OUT.pdf'") in said
    assert not list(tmp_path.glob(".c.pdf.*"))  # no temporary file left
    capsys.readouterr()
    assert main(["register", "verify", str(pdf)]) == 0
    assert f"certificate {theirs}" in capsys.readouterr().out


@pytest.fixture(scope="module")
def _window_saving_plot_images(qapp, tmp_path_factory):
    """One window for the two links' cases below: each issues into its own register and
    saves the theodolite's empty error plot into its own folder (a window each took ~0.45 s
    of CPU)."""
    from tests.conftest import answered_window, delete_window

    shown = answered_window(tmp_path_factory.mktemp("window_saving_plot_images"))
    yield shown
    shown.projects.autosave_timer.stop()
    shown.close()
    delete_window(shown)


@pytest.mark.parametrize("link", ["symbolic", "hard"])
def test_a_plots_save_image_never_replaces_an_issued_file(_window_saving_plot_images, qtbot,
                                                          tmp_path, monkeypatch, link):
    """A plot's right-click "Save image…" wrote in place, unchecked: ``plot.png``, a link
    (or hard link) to an issued PDF, had the PDF replaced by a picture. It goes through the
    check of every other export now (the main window's hook), told, the PDF unchanged; and
    writes atomically (another name: a PNG)."""
    window = _window_saving_plot_images
    import os

    import pyqtgraph as pg

    from models.certificate.metadata import CertificateMetadata
    from models.register.store import IssueRequest
    from widgets import save_file

    meta = CertificateMetadata(approver="Dr. Li", calibration_date="2020-01-01",
                               item_serial="RX-1")
    issued = b"%PDF- the certificate as issued"
    with window.certificates.open_register() as register:
        number = register.issue(IssueRequest("polygon", meta, '{"workbenches": {}}'),
                                lambda m, head="": issued)[0].number
    pdf, png = tmp_path / "c.pdf", tmp_path / "plot.png"
    pdf.write_bytes(issued)
    png.symlink_to(pdf) if link == "symbolic" else os.link(pdf, png)
    presenter = window.presenter("theodolite")
    told: list[str] = []
    monkeypatch.setattr(presenter.view, "tell", lambda title, text: told.append(text),
                        raising=False)
    chosen = [str(png)]
    monkeypatch.setattr(save_file, "choose_save_file",
                        lambda *a, **k: (chosen[0], "PNG image (*.png)"))
    plot = presenter.view.error_plot
    save = next(action for view in [plot, *plot.findChildren(pg.GraphicsView)]
                if isinstance(view, pg.GraphicsView) for item in view.scene().items()
                if isinstance(item, pg.ViewBox) and item.getMenu(None) is not None
                for action in item.getMenu(None).actions() if action.text() == "Save image…")
    save.trigger()  # the plot's right-click menu, "Save image…", plot.png chosen
    assert told and (f"{png} is the PDF of certificate {number}, as issued; an issued file "
                     "is never replaced") in told[-1]
    assert pdf.read_bytes() == issued and png.read_bytes() == issued
    chosen[0] = str(tmp_path / "error.png")
    save.trigger()
    assert (tmp_path / "error.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(told) == 1 and not list(tmp_path.glob(".*.tmp"))
