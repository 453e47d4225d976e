"""What a plain ``anglebench analyze`` imports (#44, start-up within 1.5× numpy's import):
the named workbench's models and nothing heavy — no Qt, no plotting, no database, no PDF,
spreadsheet or XML library, no other workbench. A behaviour, checked in a fresh
interpreter; the time itself is measured in tests/benchmarks/test_cli_startup.py."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from app.main import main
from models.registry import KINDS, LOCATIONS

#: what no plain analysis needs (each costs from 0.05 to 0.5 s of start-up)
HEAVY = ("PySide6", "shiboken6", "pyqtgraph", "sqlalchemy", "psycopg", "fpdf", "openpyxl",
         "lxml", "signxml", "pypdfium2", "serial", "scipy")

#: what a plain analyze's summary of the theodolite, polygon or fringe needs none of, each a
#: millisecond or a few of the start-up (#44: ≤ 1.5× numpy's import, missed by less than
#: all of them together): the certificate's details, budgets and decision rules (JSON's U
#: and a certificate load them), the plot declarations, the entry plan and the capture
#: guide (the window's), json (--json and the details), and what argparse's help would
#: bring (shutil with the compression modules, locale through gettext), tempfile (an
#: atomic write); and, with no output named, the check that no output replaces an issued
#: file (app/issued_outputs.py, with hashlib, logging, tempfile and shutil: some 15 ms of
#: CPU, a tenth of the polygon's whole run), and heapq (Counter.most_common, for a delimiter)
NOT_FOR_A_SUMMARY = ("models.certificate.metadata", "models.certificate.document",
                     "models.certificate.builder", "models.uncertainty.budget",
                     "models.uncertainty.conformity", "models.plots",
                     "models.readings.entry_plan", "models.capture.guidance",
                     "models.register.store", "models.project.file", "app.writers", "json",
                     "shutil", "locale", "tempfile", "app.issued_outputs",
                     "models.project.atomic_write", "hashlib", "logging", "heapq")

#: what even --json (whose U comes with the certificate's figures and budgets, so
#: scipy.special) never needs: the PDF, the spreadsheet, the register, the window's texts
NOT_FOR_JSON = ("PySide6", "shiboken6", "pyqtgraph", "sqlalchemy", "fpdf", "openpyxl", "lxml",
                "signxml", "pypdfium2", "app.writers", "app.translations", "app.certificate_issue",
                "app.dcc_issue", "models.register.store", "models.project.file")

# the modules taken before the probe imports json to report them
PROBE = """
import contextlib, io, sys
from app.main import main
with contextlib.redirect_stdout(io.StringIO()):
    code = main(["analyze", *sys.argv[1:]])
modules = sorted(sys.modules)
import json
json.dump({"code": code, "modules": modules}, sys.stdout)
"""


def modules_after_analyze(kind: str, samples_dir, *options: str) -> set[str]:
    sample = samples_dir / KINDS[kind].sample_file
    proc = subprocess.run([sys.executable, "-c", PROBE, kind, str(sample), *options],
                          capture_output=True, text=True, timeout=60, check=False)
    assert proc.returncode == 0, proc.stderr
    out = json.loads(proc.stdout)
    assert out["code"] == 0
    return set(out["modules"])


def loaded(modules: set[str], names) -> list[str]:
    """The ``names`` (modules or packages) among ``modules``."""
    return sorted(n for n in names if any(m == n or m.startswith(n + ".") for m in modules))


# theodolite and polygon: the start-up figures of the issue; fringe shares their path (its
# lack-of-fit test's p value in closed form, models/fringe/unmodelled_harmonics.py, not
# scipy.stats' half a second)
@pytest.mark.parametrize("kind", ["theodolite", "polygon", "fringe"])
@pytest.mark.slow
def test_a_plain_analyze_imports_nothing_heavy_and_no_other_workbench(kind, samples_dir):
    modules = modules_after_analyze(kind, samples_dir)
    heavy = sorted({m.split(".")[0] for m in modules} & set(HEAVY))
    assert not heavy, f"a plain analyze of {kind} imported {heavy}"
    # numpy's masked arrays (a tenth of numpy's own import), which np.unique(x) loads
    assert "numpy.ma" not in modules
    others = sorted(m for m in modules for other in KINDS if other != kind
                    and (m == f"models.{other}" or m.startswith(f"models.{other}.")))
    assert not others, f"a plain analyze of {kind} imported other workbenches: {others}"
    assert LOCATIONS[kind].partition(":")[0] in modules  # the probe did analyse it


@pytest.mark.parametrize("kind", ["theodolite", "polygon", "fringe"])
@pytest.mark.slow
def test_a_plain_analyze_s_summary_loads_only_what_it_prints(kind, samples_dir):
    # a module named here, imported again at the top of a module a plain analyze loads,
    # fails this (the start-up's own figure is measured in tests/benchmarks/)
    modules = modules_after_analyze(kind, samples_dir)
    assert not loaded(modules, NOT_FOR_A_SUMMARY), \
        f"a plain analyze of {kind} imported {loaded(modules, NOT_FOR_A_SUMMARY)}"
    assert "models.uncertainty.rounding" in modules or kind != "theodolite"  # its U's digits


@pytest.mark.parametrize("kind", ["theodolite", "fringe"])
@pytest.mark.slow
def test_analyze_to_json_loads_no_pdf_spreadsheet_register_or_window(kind, samples_dir):
    modules = modules_after_analyze(kind, samples_dir, "--json")
    assert not loaded(modules, NOT_FOR_JSON), \
        f"analyze --json of {kind} imported {loaded(modules, NOT_FOR_JSON)}"
    assert "models.certificate.metadata" in modules  # the probe did state its U


@pytest.mark.slow
def test_the_registry_imports_a_workbench_when_it_is_first_asked_for():
    code = ("import sys; from models.registry import KINDS; "
            "keys = sorted(KINDS); before = 'models.polygon.analysis' in sys.modules; "
            "assert 'theodolite' in KINDS and len(KINDS) == len(keys); "
            "still = 'models.polygon.analysis' in sys.modules; KINDS['polygon']; "
            "print(before, still, 'models.polygon.analysis' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=60, check=True).stdout.split()
    assert out == ["False", "False", "True"]


def test_the_registry_refuses_an_entry_under_another_key():
    from models.registry import Workbenches

    wrong = Workbenches({"polygon": LOCATIONS["theodolite"]})
    with pytest.raises(LookupError, match="its key is 'theodolite'"):
        wrong["polygon"]
    assert "polygon" in wrong and "theodolite" not in wrong and list(wrong) == ["polygon"]
    with pytest.raises(KeyError):
        KINDS["no-such-workbench"]


# the command line read with the named workbench's options alone gives what the whole
# parser gives; anything else goes to the whole parser, which reads it as it always has
def run(capsys, *args):
    code = main(["analyze", *args])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_another_workbench_s_option_is_still_refused_by_name(capsys, samples_dir):
    code, out, err = run(capsys, "theodolite", str(samples_dir / "theodolite_sample.csv"),
                         "--faces", "12")
    assert code == 2 and not out
    assert "--faces applies to polygon and crosscal, not theodolite" in err


def test_an_abbreviated_option_reads_as_it_always_did(capsys, samples_dir):
    sample = str(samples_dir / "theodolite_sample.csv")
    whole = run(capsys, "theodolite", sample, "--psi-max-deg", "7", "--json")
    abbreviated = run(capsys, "theodolite", sample, "--psi-max", "7", "--json")
    assert whole[0] == 0 and abbreviated == whole
    # an ambiguous one is refused, naming the candidates (the whole parser's message)
    code, _, err = run(capsys, "theodolite", sample, "--ac-roll", "1")
    assert code == 2 and "--ac-roll" in err


def test_an_option_value_that_is_a_workbench_s_name_does_not_choose_the_workbench(
        capsys, tmp_path, monkeypatch, samples_dir):
    # the first word naming a workbench is here the metadata file's name: the whole parser
    # decides, and the theodolite's own option is read
    monkeypatch.chdir(tmp_path)
    (tmp_path / "polygon").write_text("{}", "utf-8")
    sample = str(samples_dir / "theodolite_sample.csv")
    code, out, err = run(capsys, "--metadata", "polygon", "theodolite", sample, "--json",
                         "--psi-max-deg", "7")
    assert code == 0, err
    assert json.loads(out)["psi_deg"] == pytest.approx(5.8249, abs=0.01)
