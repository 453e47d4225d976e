"""The reversal's U in the JSON (issue 39: beside every reported error array its
``expanded_uncertainty_<name>`` and ``coverage_factor_<name>``; audit cov76: ``reversal_arcsec``
had none).

The reversal per face is ē↑ − ē↓, the forward sets' mean less the reverse sets'. What every
set shares (the polygon's and the zero face's calibration, the zero reading, the
autocollimator's roll) drops out of the difference; the sets' noise and their zero offsets
stay. With one set in a direction its offset is the reversal's own and nothing tells them
apart: U null, the reason beside it, as B and B̄ say. Checked against a first-principles rig
with a true reversal (tests/polygon_reversal_rig.py, numpy only).
"""

from __future__ import annotations

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.polygon.indicative_figures import REVERSAL_CONFOUNDED
from models.polygon.report import _kept_steady_drift, reversal_budget
from models.readings.sheet import ReadingsSheet
from tests.polygon_reversal_rig import ReversalRig

TWO_EACH_WAY = (1, -1, 1, -1)


def _analyse(rig: ReversalRig, directions, seed: int):
    rows = rig.rows(directions, np.random.default_rng(seed))
    return POLYGON.analyze(ReadingsSheet(POLYGON.columns, rows).parse(), {})


def test_two_sets_each_way_give_the_reversal_its_u_which_covers_the_truth():
    rig = ReversalRig(sigma_arcsec=0.1)
    meta = CertificateMetadata.from_dict({})
    deviations, expanded, factors = [], [], []
    for seed in range(200):
        result = _analyse(rig, TWO_EACH_WAY, 100 + seed)
        keys = POLYGON.certified_json(result, meta)
        if result.reversal_arcsec is None or keys["expanded_uncertainty_reversal_arcsec"] is None:
            continue  # the zero moved between the sets (a false alarm on noise): no reversal
        assert keys["reversal_uncertainty_reason"] is None
        deviations.append(result.reversal_arcsec - rig.reversal)
        expanded.append(keys["expanded_uncertainty_reversal_arcsec"])
        factors.extend(np.atleast_1d(keys["coverage_factor_reversal_arcsec"]))
    deviations, expanded = np.array(deviations), np.array(expanded, dtype=float)
    assert len(deviations) >= 190
    assert expanded.shape[1] == rig.faces and np.all(expanded > 0)
    # k of the sets' scatter (2 sets each way, 12 faces: ν = 22, k 2.13), up to 4.53 where
    # the sets' offsets (ν = 2) dominate
    assert min(factors) > 2.0 and max(factors) < 4.6 and np.median(factors) < 2.3
    covered = np.abs(deviations) <= expanded
    assert 0.93 <= covered.mean() <= 0.99, covered.mean()
    # no wider than the scatter needs (the noise of 2 sets each way: σ of the reversal 0.1″)
    ratio = np.median(expanded.mean(axis=0) / (2.0 * deviations.std(axis=0, ddof=1)))
    assert 0.95 <= ratio <= 1.4, ratio


def test_what_every_set_shares_is_not_in_the_reversals_u():
    """A polygon standard listed with its U (and a CMC) widens the mean's U, not the
    reversal's: the face's calibration error is the same in both directions' means."""
    result = _analyse(ReversalRig(), TWO_EACH_WAY, 7)
    plain = POLYGON.certified_json(result, CertificateMetadata.from_dict({}))
    listed = CertificateMetadata.from_dict({"standards": [
        {"description": "Polygon", "serial": "P-1", "certificate_no": "CAL-1",
         "uncertainty": 0.5}]})
    with_standard = POLYGON.certified_json(result, listed, {"cmc_arcsec": 5.0})
    assert with_standard["expanded_uncertainty_reversal_arcsec"] == \
        plain["expanded_uncertainty_reversal_arcsec"]
    assert with_standard["uncertainty_raised_to_cmc_reversal_arcsec"] == [False] * 12
    assert "uncertainty_raised_to_cmc_reversal_arcsec" not in plain
    mean_plain = POLYGON.uncertainty_budgets(result, CertificateMetadata.from_dict({}))
    mean_listed = POLYGON.uncertainty_budgets(result, listed)
    assert np.all(mean_listed["mean_corrected_error_arcsec"].expanded[1:]
                  > mean_plain["mean_corrected_error_arcsec"].expanded[1:] + 0.1)


def test_one_set_per_direction_gives_null_with_the_reason():
    result = _analyse(ReversalRig(), (1, -1), 8)
    keys = POLYGON.certified_json(result, CertificateMetadata.from_dict({}))
    assert result.reversal_arcsec is not None
    assert keys["expanded_uncertainty_reversal_arcsec"] is None
    assert keys["coverage_factor_reversal_arcsec"] is None
    assert keys["reversal_uncertainty_reason"] == str(REVERSAL_CONFOUNDED)


def test_one_direction_has_no_reversal_and_no_reason():
    result = _analyse(ReversalRig(), (1, 1), 9)
    keys = POLYGON.certified_json(result, CertificateMetadata.from_dict({}))
    assert result.reversal_arcsec is None
    assert keys == {"expanded_uncertainty_reversal_arcsec": None,
                    "coverage_factor_reversal_arcsec": None,
                    "reversal_uncertainty_reason": None}


@pytest.mark.parametrize("seed, before", [(3, 0.085), (18, 0.142), (34, 0.155), (38, 0.190)])
def test_a_drift_the_closures_show_by_chance_is_not_an_offset_of_the_reversal_too(seed, before):
    """No offsets and no drift in the rig (σ 0.1″, 12 faces, + − + −), runs whose closures'
    mean came out beyond its noise (kept 0.11–0.14″): the carried drift's input holds that
    estimate once; the zero offsets' input stays within the sets' means' noise share
    (σ/√n·√(1/2 + 1/2) = 0.029″). Before (rev77) the kept drift was taken out of the sets'
    means as a trend they do not have and τ floored at σ/√n: ``before`` ″ (the val77 double
    count, as in the mean's budget)."""
    rig = ReversalRig(sigma_arcsec=0.1)
    result = _analyse(rig, TWO_EACH_WAY, seed)
    assert abs(_kept_steady_drift(result, 0.1) or 0.0) > 0.1  # the situation
    budget = reversal_budget(result, CertificateMetadata.from_dict({}))
    sizes = {getattr(c.name, "template", c.name): float(np.max(np.abs(
        np.asarray(c.value) * np.asarray(c.sensitivity)))) for c in budget.components}
    assert sizes.get("Autocollimator zero offsets between the sets", 0.0) < 0.03 < before, sizes
    assert sizes["Zero drift carried from set to set"] > 0.2
