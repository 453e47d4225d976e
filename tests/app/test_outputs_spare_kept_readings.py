"""hostile77 F1, F2: no output replaces readings kept in a file that is neither an input nor
the open project — an AngleBench project (readings as typed, details) or a capture's journal
(the readings of a capture that did not end, which the next capture into its output
recovers). ``analyze --table``/``--results`` and ``register export --overwrite`` named over
one replaced it, exit 0, no word; the kind check judges no output that writes text."""

from __future__ import annotations

import hashlib

import pytest

from app.main import main
from models.capture.journal import CaptureJournal, journal_path, read_journal
from models.project.atomic_write import write_bytes_atomic
from models.project.output_guard import OutputRefused, check_output
from models.register.store import Register


def _digest(path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


@pytest.fixture
def project(tmp_path):
    """A project file of typed readings, open nowhere (as an older version wrote it too:
    its first key on a line of its own)."""
    path = tmp_path / "Tuesday.anglebench.json"
    path.write_text('{\n "format": "anglebench-project",\n "schema_version": 2,\n'
                    ' "workbenches": {"positioning": {"rows": [["0", "0.0012"]]}}\n}\n',
                    encoding="utf-8")
    return path


@pytest.fixture
def journal(tmp_path):
    """The journal a capture into ac.csv left when it was killed: 3 readings in it."""
    path = journal_path(tmp_path / "ac.csv")
    kept = CaptureJournal(path, ("time_s", "ac_x_arcsec", "ac_y_arcsec"),
                          {"instrument": "autocollimator", "out": str(tmp_path / "ac.csv")})
    for i in range(3):
        kept.frame(0.1 * i, b"3 003 12.5 -3.2", True)
        kept.reading([0.1 * i, 12.5, -3.2])
    kept.close()  # killed: never removed
    return path


@pytest.mark.parametrize("flag", ["--table", "--results"])
def test_analyze_refuses_a_table_or_results_over_a_project(register, project, samples_dir,
                                                           flag, capsys):
    before = _digest(project)
    sample = str(samples_dir / "positioning_sample.csv")
    assert main(["analyze", "positioning", sample, flag, str(project)]) == 2
    err = capsys.readouterr().err
    assert f"{flag} {project} is an AngleBench project" in err, err
    assert "nothing was written" in err
    assert _digest(project) == before


@pytest.mark.parametrize("flag", ["--table", "--results"])
def test_analyze_refuses_a_table_or_results_over_a_capture_journal(register, journal, samples_dir,
                                                                   flag, capsys):
    before = _digest(journal)
    sample = str(samples_dir / "positioning_sample.csv")
    assert main(["analyze", "positioning", sample, flag, str(journal)]) == 2
    err = capsys.readouterr().err
    assert f"{flag} {journal} is a capture's journal" in err, err
    assert _digest(journal) == before
    assert len(read_journal(journal).readings) == 3  # still there for the next capture


def test_export_overwrite_spares_a_project_and_a_journal(register, project, journal, capsys):
    for target in (project, journal):
        before = _digest(target)
        assert main(["register", "export", str(target), "--overwrite"]) == 2
        err = capsys.readouterr().err
        assert "nothing was written" in err, err
        assert _digest(target) == before


def test_a_project_is_replaced_by_a_project_only(project, tmp_path):
    # register show --project writes a project: over a project, as the window's Save as
    check_output(project, [], "--project")
    for flag in ("--table", "--results", "--certificate", "OUT.zip", ""):
        with pytest.raises(OutputRefused, match="is an AngleBench project"):
            check_output(project, [], flag)
    # a project through a symbolic link is found too
    link = tmp_path / "link.csv"
    link.symlink_to(project)
    with pytest.raises(OutputRefused, match="is an AngleBench project"):
        check_output(link, [], "--table")
    # the window's Save writes a project over its file: the last line lets it
    write_bytes_atomic(project, b'{"format": "anglebench-project", "schema_version": 2}')
    assert project.read_bytes().startswith(b'{"format"')


def test_no_write_replaces_a_capture_journal_whoever_asks(journal):
    before = _digest(journal)
    for flag in ("--project", "--table", ""):
        with pytest.raises(OutputRefused, match="is a capture's journal"):
            check_output(journal, [], flag)
    with pytest.raises(OutputRefused, match="is a capture's journal"):
        write_bytes_atomic(journal, b"x\n")  # the last line, for a writer not told of it
    assert _digest(journal) == before


def test_other_text_is_replaced_as_before(tmp_path):
    # a CSV of an earlier table, a JSON that is no project: replaced as before
    for name, text in (("t.csv", "target,compensation\n0,1\n"),
                       ("p.json", '{"format": "other", "anglebench-project": 1}\n')):
        path = tmp_path / name
        path.write_text(text, encoding="utf-8")
        check_output(path, [], "--table")
        write_bytes_atomic(path, b"new\n")
        assert path.read_bytes() == b"new\n"


def test_a_raw_named_as_the_captures_own_journal_is_kept_beside_it(tmp_path, capsys):
    # `capture --out a.csv --raw a.csv.capture-journal.csv --overwrite`: the raw lines were
    # written over the journal, which was then removed as done: the instrument's output
    # gone, exit 0, "3 readings written"
    from tests.instrument_simulators import AutocollimatorSimulator

    out = tmp_path / "a.csv"
    raw = journal_path(out)
    with AutocollimatorSimulator("pty", positions=[(12.5, -3.25)]) as sim:
        assert main(["capture", "autocollimator", sim.port, "--readings", "3", "--out",
                     str(out), "--raw", str(raw), "--overwrite", "--silence", "0.2",
                     "--retries", "1", "--language", "en"]) == 0
    err = capsys.readouterr().err
    assert f"{raw} is a capture's journal" in err, err
    kept = [p for p in tmp_path.iterdir() if ".captured-" in p.name]
    assert len(kept) == 1 and f"written to {kept[0]} instead" in err
    lines = kept[0].read_text(encoding="utf-8").splitlines()
    assert lines[0].startswith("time_s") and len(lines) >= 4  # the header and its frames
    assert not raw.exists()  # the journal removed once the outputs were written


def test_results_spare_a_captures_readings_which_a_capture_replaces_with_overwrite(
        register, tmp_path, samples_dir, capsys):
    # Monday's capture, no input of this run: `--results monday.csv` replaced it, exit 0
    monday, raw = tmp_path / "monday.csv", tmp_path / "monday.raw.csv"
    monday.write_text("time_s,ac_x_arcsec,ac_y_arcsec\n0.5,12.5,-3.25\n", encoding="utf-8")
    raw.write_text("\ufefftime_s,reading,line\n0.5,1,3 003 12.5 -3.25\n", encoding="utf-8")
    sample = str(samples_dir / "positioning_sample.csv")
    for target in (monday, raw):
        before = _digest(target)
        assert main(["analyze", "positioning", sample, "--results", str(target)]) == 2
        err = capsys.readouterr().err
        assert f"--results {target} holds readings captured from an instrument" in err, err
        assert _digest(target) == before
    # the capture's own outputs replace them (with --overwrite: its own rule)
    check_output(monday, [], "--out")
    check_output(raw, [], "--raw")
    # an earlier results file is replaced as before
    earlier = tmp_path / "r.csv"
    assert main(["analyze", "positioning", sample, "--results", str(earlier)]) == 0
    assert main(["analyze", "positioning", sample, "--results", str(earlier)]) == 0


@pytest.mark.usefixtures("pdf_stand_in")
def test_show_project_spares_another_project_and_writes_its_own_again(
        register, project, tmp_path, samples_dir, capsys):
    meta = tmp_path / "meta.json"
    meta.write_text((samples_dir / "certificate_polygon.json").read_text(encoding="utf-8")
                    .replace('"example": true', '"example": false'), encoding="utf-8")
    assert main(["analyze", "polygon", str(samples_dir / "polygon_sample.csv"), "--metadata",
                 str(meta), "--certificate", str(tmp_path / "c.pdf")]) == 0
    number = Register(f"sqlite:///{register}").list("")[0].number
    capsys.readouterr()
    before = _digest(project)  # Tuesday's typed readings, another project
    assert main(["register", "show", number, "--project", str(project)]) == 2
    err = capsys.readouterr().err
    assert f"--project {project} is an AngleBench project" in err, err
    assert _digest(project) == before
    own = tmp_path / "own.anglebench.json"
    assert main(["register", "show", number, "--project", str(own)]) == 0
    assert main(["register", "show", number, "--project", str(own)]) == 0  # the same again
    assert own.read_bytes().startswith(b'{"format"')
