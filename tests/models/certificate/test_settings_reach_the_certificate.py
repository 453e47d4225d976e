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
