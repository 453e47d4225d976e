import json
from pathlib import Path

import numpy as np
import pytest

from models.project.atomic_write import write_text_atomic
from models.project.file import (
    SCHEMA_VERSION,
    Project,
    ProjectFileError,
    WorkbenchState,
    load_project,
    project_from_json,
    save_project,
)
from models.project.recovery import RecoveryStore
from models.quantity import Quantity


def make_project():
    return Project(
        workbenches={
            "theodolite": WorkbenchState([["0", "0", "1°61'"], ["1", "1.0", "中文"]],
                                         {"method": "elevation", "psi_max_deg": 45.0}),
            "polygon": WorkbenchState([], {"grade": 3}),
        },
        metadata={"operator": "张三"},
    )


def test_round_trip_keeps_bad_cells_and_unicode(tmp_path):
    path = tmp_path / "p.anglebench.json"
    save_project(path, make_project())
    back = load_project(path)
    assert back == make_project()


def test_newer_schema_and_damaged_file_give_clear_messages(tmp_path):
    path = tmp_path / "new.json"
    path.write_text(json.dumps({"format": "anglebench-project", "schema_version": 99}))
    with pytest.raises(ProjectFileError, match="newer AngleBench.*schema 99.*Nothing was changed"):
        load_project(path)
    path.write_text('{"format": "anglebench-project", "schema_version": 1, "workbenches": {')
    with pytest.raises(ProjectFileError, match=r"damaged project file \(line 1"):
        load_project(path)
    with pytest.raises(ProjectFileError, match="not an AngleBench project"):
        project_from_json("[1, 2]")
    with pytest.raises(ProjectFileError, match="'rows' must be a list of lists"):
        project_from_json(json.dumps({"format": "anglebench-project", "schema_version": 1,
                                      "workbenches": {"x": {"rows": "oops"}}}))


def test_atomic_write_leaves_old_file_on_failure(tmp_path, monkeypatch):
    path = tmp_path / "p.json"
    path.write_text("old")

    def broken_replace(src, dst):
        raise OSError("disk full")

    monkeypatch.setattr("os.replace", broken_replace)
    with pytest.raises(OSError):
        write_text_atomic(path, "new")
    assert path.read_text() == "old"
    assert [p.name for p in tmp_path.iterdir()] == ["p.json"]


def test_recovery_store(tmp_path):
    store = RecoveryStore(tmp_path / "rec")
    store.claim()
    assert not store.exists()
    store.write(make_project(), "/labs/run.anglebench.json")
    assert store.exists()
    other = RecoveryStore(tmp_path / "rec")
    assert other.orphans() == []  # the writer is alive: nothing to recover
    store._lock_fd, fd = None, store._lock_fd
    import os

    os.close(fd)  # the writer dies
    assert other.orphans() == [store.path]
    back = other.load(store.path)
    assert back.workbenches == make_project().workbenches
    assert "autosaved_at" in back.metadata
    assert back.metadata["project_path"] == "/labs/run.anglebench.json"
    other.adopt(store.path)
    assert not store.exists() and other.orphans() == []
    broken = tmp_path / "rec" / "recovery-old.anglebench.json"
    broken.write_text("{broken")
    with pytest.raises(ProjectFileError):
        other.load(broken)
    assert not broken.exists()
    assert len(list((tmp_path / "rec").glob("recovery-old.anglebench.json.damaged-*.json"))) == 1


# -- #32: schema 2 gives the tolerance its unit; a schema-1 file is migrated as it is read --

FIXTURE = Path(__file__).parents[2] / "fixtures" / "project_schema1.anglebench.json"


def test_a_schema_1_file_opens_with_each_tolerance_in_its_workbench_unit(tmp_path):
    from models.registry import KINDS

    project = load_project(FIXTURE, KINDS)
    certificates = project.metadata["certificates"]
    # schema 1 wrote the tolerance in the unit of each workbench's errors, whatever the key said
    assert certificates["theodolite"]["tolerance"] == 3
    assert certificates["theodolite"]["tolerance_unit"] == "arcsec"
    assert "tolerance_arcsec" not in certificates["theodolite"]
    assert certificates["positioning"] == {  # in its deviation unit, every figure
        "tolerance": 15, "tolerance_unit": "urad", "operator": "Wang",
        "item_resolution": 0.1, "item_resolution_unit": "urad",
        "standards": [{"description": "Rotary calibrator", "uncertainty": 0.5,
                       "uncertainty_unit": "urad", "basis": "U95"}]}
    assert certificates["fringe"]["tolerance_unit"] == "nm"  # an interferometer period was set
    path = tmp_path / "again.anglebench.json"
    save_project(path, project)
    saved = json.loads(path.read_text("utf-8"))
    assert saved["schema_version"] == SCHEMA_VERSION == 2
    assert "_arcsec" not in path.read_text("utf-8")
    assert load_project(path) == project  # schema 2 is read as it is
    assert project_from_json(json.dumps({**saved, "schema_version": 1}), kinds=KINDS) == project  # idempotent


def test_a_schema_1_file_gives_the_same_analysis_and_the_same_verdict():
    from dataclasses import replace

    from models.certificate.metadata import CertificateMetadata, ReferenceStandard
    from models.readings.sheet import ReadingsSheet
    from models.readings.tabular_import import map_columns, read_table
    from models.registry import KINDS

    project = load_project(FIXTURE, KINDS)
    kind = KINDS["theodolite"]
    state = project.workbenches["theodolite"]
    opened = kind.analyze(ReadingsSheet(kind.columns, state.rows).parse(),
                          kind.settings_with_defaults(state.settings))
    sample = Path(__file__).parents[3] / "resources" / "samples" / "theodolite_sample.csv"
    typed = kind.analyze(ReadingsSheet(kind.columns, map_columns(read_table(sample), kind.columns)
                                       ).parse(), kind.settings_with_defaults({}))
    np.testing.assert_array_equal(opened.corrected_error_arcsec, typed.corrected_error_arcsec)
    migrated = CertificateMetadata.from_dict(project.metadata["certificates"]["theodolite"])
    assert migrated.tolerance_quantity == Quantity(3.0, "arcsec")
    # the fixture lists no standard: the theodolite listed with its certificate and U, so
    # that a statement is made (none is with no standard listed, audit 71 finding 2)
    theodolite = (ReferenceStandard("Autocollimating theodolite", "T-1", "CAL-1", 0.2),)
    new = kind.certificate_document(opened, replace(migrated, standards=theodolite)).conformity
    as_before = kind.certificate_document(opened, replace(CertificateMetadata.from_dict(
        json.loads(FIXTURE.read_text("utf-8"))["metadata"]["certificates"]["theodolite"]),
        standards=theodolite))
    assert (new.verdict, str(new.statement)) == (as_before.conformity.verdict,
                                                 str(as_before.conformity.statement))
    assert "±3\"" in new.statement


def test_a_tolerance_is_converted_to_the_errors_unit_and_never_across_kinds():
    from models.certificate.metadata import CertificateMetadata, MetadataError

    in_urad = CertificateMetadata.from_dict({"tolerance": 15, "tolerance_unit": "urad"})
    # 15 µrad = 15 / 4.8481368" = 3.0940"
    assert in_urad.tolerance_in("arcsec") == pytest.approx(3.09396, rel=1e-5)
    assert in_urad.tolerance_in("urad") == 15
    with pytest.raises(MetadataError, match="tolerance' is in µrad, but the errors are in nm"):
        in_urad.tolerance_in("nm")
    with pytest.raises(MetadataError, match="tolerance_unit' must be one of"):
        CertificateMetadata.from_dict({"tolerance": 15, "tolerance_unit": "furlong"})
    # details of the command line written before: the key's own unit
    assert CertificateMetadata.from_dict({"tolerance_arcsec": 2}).tolerance_quantity == \
        Quantity(2.0, "arcsec")


def test_the_project_file_is_given_the_workbenches_and_imports_none(tmp_path):
    """#44: the project file asked the registry for a workbench's error unit (an import the
    import contracts had to ignore); its caller gives it the workbenches now. A schema-1 file
    with certificate details read without them is refused rather than guessed in arcsec;
    a workbench not given keeps its details as written."""
    import ast

    from models.registry import KINDS

    source = (Path(__file__).parents[3] / "models" / "project" / "file.py").read_text("utf-8")
    imported = {node.module for node in ast.walk(ast.parse(source))
                if isinstance(node, ast.ImportFrom)}
    assert "models.registry" not in imported
    with pytest.raises(ValueError, match="read it with kinds"):
        load_project(FIXTURE)
    text = FIXTURE.read_text("utf-8")
    written = json.loads(text)["metadata"]["certificates"]
    only = project_from_json(text, kinds={"positioning": KINDS["positioning"]})
    certificates = only.metadata["certificates"]
    assert certificates["positioning"]["tolerance_unit"] == "urad"
    assert certificates["theodolite"] == written["theodolite"]  # not given: as written
