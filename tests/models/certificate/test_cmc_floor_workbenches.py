"""The laboratory's CMC reaches every U a workbench states (ILAC-P14 5.4), not only the
certificate's results column: the polygon's raw error in the DCC, the theodolite's raw error in
the JSON, and the fringe's decided half range (judged on its model curve, a budget of its
own)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from tests.models.certificate.test_traceability_and_scope import META, _sample

pytestmark = pytest.mark.slow  # each analyses a sample


def test_the_polygons_raw_error_u_in_the_dcc_is_held_to_the_cmc():
    kind, result = _sample("polygon")
    bare = kind.dcc_point_uncertainties(result, META)["raw_error_arcsec"].expanded
    cmc = float(np.max(bare)) + 0.1  # above every U the budget gives
    settings = {"cmc_arcsec": cmc}
    kind, result = _sample("polygon", settings)
    raw = kind.dcc_point_uncertainties(result, META, settings)["raw_error_arcsec"].expanded
    np.testing.assert_array_equal(raw[bare > 0], cmc)


def test_the_theodolites_raw_error_u_is_held_to_the_cmc_and_its_model_error_u_is_not():
    settings = {"cmc_arcsec": 2.0}
    kind, result = _sample("theodolite", settings)
    meta = dataclasses.replace(META, standards=(dataclasses.replace(
        META.standards[1], description="Autocollimating theodolite", uncertainty=0.5,
        basis="u"),))
    budgets = kind.uncertainty_budgets(result, meta, settings)
    raw = np.asarray(budgets["raw_error_arcsec"].expanded)
    computed = np.asarray(budgets["raw_error_arcsec"].computed_expanded)
    assert 0 < np.max(computed) < 2.0  # 1.41″ from the readings and the theodolite's u
    np.testing.assert_array_equal(raw[computed > 0], 2.0)
    # the set-up model's own U is a correction's, not an error of the axis: no floor
    model = budgets["model_error_arcsec"]
    np.testing.assert_array_equal(model.expanded, model.computed_expanded)


def test_the_fringes_decided_half_range_is_held_to_the_cmc():
    meta = dataclasses.replace(META, tolerance=0.5, standards=())
    kind, result = _sample("fringe")
    free = kind.certificate_document(result, meta).conformity
    assert free.expanded < 0.002 and free.lower_half_width < 0.002
    settings = {"cmc": 0.05}
    kind, result = _sample("fringe", settings)
    held = kind.certificate_document(result, meta, settings=settings).conformity
    assert held.value == free.value
    assert held.expanded == 0.05 and held.lower_half_width == 0.05
    assert held.interval_high == pytest.approx(free.value + 0.05)
