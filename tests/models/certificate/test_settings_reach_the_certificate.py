"""Issue 44: the settings a result was analysed with reach the certificate and its budget as
an argument (``certificate(result, metadata, source_name, settings)``), never as a copy in
the result; so the CMC the certificate lists and the floor its U is held to are one figure.

Which settings win when the form was edited after the analysis: those the result was
analysed with (the window keeps them beside the result, ``WorkbenchPresenter.result_settings``;
tests/widgets/test_result_settings.py): every figure on the certificate was computed with
them, so the listing and the budget state them too."""

from __future__ import annotations

import dataclasses
import json
from pathlib import Path

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.certificate.uncertainty_json import workbench_uncertainty_json
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from models.registry import KINDS

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"
#: each workbench whose budget takes the laboratory's CMC from the settings, and its key
CMC_SETTING = {"theodolite": "cmc_arcsec", "polygon": "cmc_arcsec", "positioning": "cmc",
               "fringe": "cmc"}


def _sample(key: str, settings=None):
    kind = KINDS[key]
    rows = map_columns(read_table(SAMPLES / kind.sample_file), kind.columns)
    parsed = ReadingsSheet(kind.columns, rows).parse()
    checked = kind.checked_settings({**kind.sample_settings, **(settings or {})})
    return kind, kind.analyze(parsed, checked), checked


def _details(key: str) -> CertificateMetadata:
    return CertificateMetadata.from_dict(
        json.loads((SAMPLES / f"certificate_{key}.json").read_text("utf-8")))


@pytest.mark.parametrize("key", [pytest.param(k, marks=pytest.mark.slow) if k == "fringe" else k
                                 for k in CMC_SETTING])
def test_the_cmc_the_certificate_lists_is_the_floor_its_u_is_held_to(key):
    setting = CMC_SETTING[key]
    kind, result, analysed = _sample(key)  # analysed with no CMC stated
    details = _details(key)
    computed = kind.certificate_document(result, details, "", analysed).budget.expanded
    cmc = round(float(np.median(computed[computed > 0])) * 1.5, 4)  # above half the points
    stated = {**analysed, setting: cmc}
    # the result holds no copy of it: nothing in it could say another figure
    assert not any(f.name == "cmc" for f in dataclasses.fields(result))
    document = kind.certificate_document(result, details, "", stated)
    budget = document.budget
    assert budget.floor == cmc
    np.testing.assert_allclose(budget.expanded, np.where(computed > 0,
                                                         np.maximum(computed, cmc), computed))
    label = kind.parameter(setting).label
    listed = dict(document.settings)[label]
    assert listed == kind.parameter(setting).text(cmc) and f"{cmc:g}" in listed
    assert any("(CMC)" in s and f"{cmc:g}" in s for s in document.statements)
    # the JSON's U of the certificate's curve is held to the same floor
    keys = workbench_uncertainty_json(kind, result, details, stated)
    stated_u = [np.asarray(v, dtype=float) for name, v in _walk(keys)
                if name.startswith("expanded_uncertainty_")]
    assert stated_u and any(np.nanmin(u[u > 0]) >= cmc - 1e-12 for u in stated_u)
    without = workbench_uncertainty_json(kind, result, details, analysed)
    assert _walk(without) != _walk(keys)


def _walk(tree, prefix=""):
    out = []
    for name, value in tree.items():
        if isinstance(value, dict):
            out += _walk(value, f"{prefix}{name}/")
        elif isinstance(value, list):
            out.append((name, value))
    return out


@pytest.mark.slow
def test_a_cross_calibration_refuses_settings_other_than_its_analysis():
    """The cross-calibration's own U figures (its JSON's) are made from the settings, so they
    stay in its result: a certificate asked for with another CMC is refused, naming it."""
    kind, result, analysed = _sample("crosscal", {"cmc_arcsec": 0.05})
    details = _details("crosscal")
    assert kind.certificate_document(result, details, "", analysed).budget.floor == 0.05
    with pytest.raises(ValueError, match="cmc_arcsec is 0.2, but the result was analysed "
                                         "with 0.05"):
        kind.certificate_document(result, details, "", {**analysed, "cmc_arcsec": 0.2})


def test_the_polygons_stated_inputs_reach_its_budget_from_the_settings():
    """The tilt bound (when the tilt is not identified) and the σ of a reading (when the
    readings cannot evaluate it) were copied into the polygon's result for the budget; they
    reach it from the settings now: the certificate states the figures it computed with."""
    from models.certificate.withheld import UncertaintyWithheld
    from models.validation.polygon_rig import PolygonRig

    faces = 12
    th = np.radians(np.arange(faces) * 30.0)
    rig = PolygonRig(faces, 0.3 * np.cos(th), psi_arcsec=300.0, omega_deg=40.0,
                     noise_arcsec=0.03, rng=np.random.default_rng(3))
    flat = [[*r[:4], "12.5", *r[5:]] for r in rig.set_rows()]  # no tilt to identify
    kind = KINDS["polygon"]
    analysed = kind.checked_settings({"grade": 3})
    result = kind.analyze(ReadingsSheet(kind.columns, flat).parse(), analysed)
    assert result.sets[0].tilt is None
    assert not {"tilt_bound_arcsec", "reading_noise_arcsec"} & {
        f.name for f in dataclasses.fields(result)}
    details = CertificateMetadata()
    with pytest.raises(UncertaintyWithheld, match="state the σ of a reading"):
        kind.certificate_document(result, details, "", analysed)  # no σ stated: withheld
    documents = {bound: kind.certificate_document(
        result, details, "", {**analysed, "reading_noise_arcsec": 0.05,
                              "tilt_bound_arcsec": bound}) for bound in (100.0, 300.0)}
    for bound, document in documents.items():
        components = {str(c.name): c for c in document.budget.components}
        stated = [c for name, c in components.items() if name.startswith("Reading noise, stated")]
        assert len(stated) == 1 and "σ = 0.05\"" in str(stated[0].note)
        tilt = components["Pyramidal tilt, not identified (bound)"]
        assert f"{bound:g}" in str(tilt.note)
        listed = dict(document.settings)
        assert listed[kind.parameter("tilt_bound_arcsec").label] == \
            kind.parameter("tilt_bound_arcsec").text(bound)
    small, large = (documents[b].budget.components for b in (100.0, 300.0))
    u_small = next(c for c in small if str(c.name).startswith("Pyramidal")).standard_uncertainty(faces)
    u_large = next(c for c in large if str(c.name).startswith("Pyramidal")).standard_uncertainty(faces)
    assert np.all(u_large[1:] > 2.0 * u_small[1:])  # a third of the bound: well under half the u


@pytest.mark.parametrize("key", ["theodolite", "polygon", "positioning", "crosscal"])
def test_the_window_entry_plan_is_no_setting_on_the_certificate(key):
    """Day review 65 F13: "entry plan: passes — no plan" and "entry plan: θ steps −20:1:41"
    were printed among the certificate's analysis settings: window-only entry aids, and a
    plan printed of a run that used none may be read as the measurement plan."""
    kind, result, analysed = _sample(key)
    listed = dict(kind.certificate_document(result, _details(key), "", analysed).settings)
    aids = [p for p in kind.parameters if p.key.startswith("plan_")]
    assert aids and all(p.entry_aid for p in aids)
    assert not any(p.label in listed for p in aids), listed
    assert not any("plan" in label for label in listed), listed
    # the analysis' own settings are all there still
    assert set(listed) == {p.label for p in kind.parameters if not p.entry_aid}
