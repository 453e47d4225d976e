"""What an amendment says it changes of what decides the result (hostile78 F1):
models/register/basis_changes.py against the project recorded with the original."""

from __future__ import annotations

import json

from models.register.basis_changes import basis_changes, same_readings


def _project(rows=None, settings=None, **details) -> str:
    base = {"tolerance": 1.0, "tolerance_unit": "arcsec", "decision_rule": "guarded",
            "decision_quantity": "half_range", "coverage_probability_pct": 95.45,
            "document_type": "calibration", "item_grade": "grade 3",
            "standards": [{"description": "Theodolite", "serial": "T-1",
                           "certificate_no": "NIM-1", "uncertainty": 0.5,
                           "uncertainty_unit": "arcsec", "basis": "u"}]}
    return json.dumps({"format": "anglebench-project", "workbenches": {"theodolite": {
        "rows": rows if rows is not None else [["-20", "1", "2"], ["-19", "3", "4", ""]],
        "settings": settings if settings is not None else {"cmc_arcsec": 0.5}}},
        "metadata": {"certificates": {"theodolite": {**base, **details}}}})


def _said(old: str, new: str) -> list[str]:
    return [str(m) for m in basis_changes(old, new, "theodolite", "AB-1")]


def test_nothing_changed_says_nothing_and_a_sheets_padding_is_no_change():
    padded = [["-20", "1", "2", "", ""], [" -19", "3 ", "4"], ["", "", ""]]
    assert _said(_project(), _project(rows=padded)) == []
    assert same_readings(_project(), _project(rows=padded), "theodolite")
    assert not same_readings(_project(rows=[]), _project(rows=[]), "theodolite")  # none


def test_each_deciding_detail_is_said_with_its_unit():
    said = _said(_project(), _project(
        tolerance=3, tolerance_unit="urad", decision_rule="simple",
        document_type="test", lab_accreditation="CNAS L0001",
        standards=[{"description": "Theodolite", "serial": "T-1", "certificate_no": "NIM-1",
                    "uncertainty": 0.2, "uncertainty_unit": "arcsec", "basis": "u"}]))
    assert said == [
        'tolerance changed from ±1" (on AB-1) to ±3 µrad',
        "decision rule changed from guarded (on AB-1) to simple",
        "document asked for changed from calibration (on AB-1) to test",
        "accreditation changed from — (on AB-1) to CNAS L0001",
        'reference standards changed from Theodolite T-1 NIM-1 0.5" u (on AB-1) to '
        'Theodolite T-1 NIM-1 0.2" u']


def test_readings_and_settings_are_said_by_row_and_by_key():
    said = _said(_project(), _project(
        rows=[["-20", "1", "2"], ["-19", "3", "5"], ["-18", "1", "1"]],
        settings={"cmc_arcsec": 0, "ac_roll": 0}))
    assert said == ["readings changed from those of AB-1: row(s) 2–3 (2 rows there, 3 here)",
                    "analysis settings changed from those of AB-1: cmc_arcsec 0.5 → 0"]
    # a key one side's version did not write is a change only where it sets something
    assert _said(_project(settings={}), _project(settings={"ac_roll": 1.0})) == [
        "analysis settings changed from those of AB-1: ac_roll — → 1"]


def test_an_original_recorded_without_a_project_state_gives_nothing_to_compare():
    assert _said("", _project()) == [] and _said("not json", _project()) == []

