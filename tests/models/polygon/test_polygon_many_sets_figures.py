"""Contract review 75 F11: a long polygon test is analysed in time growing with its rows,
with the figures it had. The later sets' JSON budgets are built once (their carried drift
each set's own), the sets' least squares of the reading noise set by set beyond a size:
both give what the per-set budgets and the whole least squares gave."""

from __future__ import annotations

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.polygon import model
from models.polygon.analysis import POLYGON
from models.polygon.report import OTHER_SET, _one_set, polygon_budget, polygon_json_budgets
from models.readings.sheet import ReadingsSheet
from models.validation.polygon_rig import PolygonRig

FACES = 24


def _result(sets: int, reverse_every: int = 2, drift: float = 0.1):
    rng = np.random.default_rng(sets)
    theta = np.arange(FACES) * 360.0 / FACES
    rig = PolygonRig(FACES, 0.6 * np.sin(np.radians(theta) + 0.4), 480.0, 30.0,
                     face_dev_arcsec=rng.normal(0, 0.1, FACES), noise_arcsec=0.05, rng=rng)
    rows: list[list[str]] = []
    for s in range(1, sets + 1):
        rows += rig.set_rows(s, reverse=s % reverse_every == 0, closure_drift_arcsec=drift)
    parsed = ReadingsSheet(POLYGON.columns, rows).parse()
    return POLYGON.analyze(parsed, POLYGON.settings_with_defaults({}))


@pytest.mark.parametrize("sets, reverse_every, drift", [(3, 2, 0.1), (6, 3, 0.3), (12, 2, 0.0)])
def test_later_sets_budgets_are_those_built_set_by_set(sets, reverse_every, drift):
    result = _result(sets, reverse_every, drift)
    metadata = CertificateMetadata()
    fast = polygon_json_budgets(result, metadata)
    # as before: each later set's budget built whole, its carried drift its own
    later = [_one_set(polygon_budget(result, metadata, None, share=OTHER_SET, drift_set=s),
                      result) for s in range(1, sets)]
    for name in ("error_arcsec", "pyramidal_error_arcsec", "corrected_error_arcsec"):
        got = np.asarray(fast[name].expanded)[FACES:]
        assert got.size == (sets - 1) * FACES
        if name == "pyramidal_error_arcsec":
            continue  # the set-up's inputs alone: no carried drift in it
        k_fast = np.asarray(fast[name].coverage_factors)[FACES:]
        if name == "corrected_error_arcsec":
            want = np.concatenate([b.expanded for b in later])
            np.testing.assert_array_equal(got, want)  # the same numbers, bit for bit
            np.testing.assert_array_equal(k_fast, np.concatenate([b.coverage_factors
                                                                  for b in later]))
    # where the drift is carried, each set carries its own share (not one budget for all)
    carried = [next((np.asarray(c.value) for c in b.components
                     if str(c.name) == "Zero drift carried from set to set"), None)
               for b in later]
    if drift >= 0.3:
        assert all(c is not None for c in carried)
        assert not np.allclose(carried[0], carried[-1])


def _dense(group, index):
    saved = model.DENSE_DIRECTION_FIT_ELEMENTS
    model.DENSE_DIRECTION_FIT_ELEMENTS = 10**12
    try:
        return model._direction_fit(group, index)
    finally:
        model.DENSE_DIRECTION_FIT_ELEMENTS = saved


@pytest.mark.parametrize("m, n, layout", [
    (2, 24, "same"), (5, 24, "same"), (7, 12, "shuffled"), (30, 24, "same"), (9, 5, None),
    (4, 24, "reversed"), (60, 24, "rolled")])
def test_the_least_squares_set_by_set_is_the_whole_one(m, n, layout):
    rng = np.random.default_rng(m * n)
    group = (rng.normal(size=(m, n)) + rng.normal(size=(m, 1))
             + np.sin(np.arange(n)) + 0.01 * np.arange(n) * rng.normal(size=(m, 1)))
    faces = np.arange(n, dtype=float)
    index = {"same": np.tile(faces, (m, 1)),
             "reversed": np.array([faces if k % 2 == 0 else faces[::-1] for k in range(m)]),
             "shuffled": np.array([rng.permutation(n) for _ in range(m)], dtype=float),
             "rolled": np.array([np.roll(faces, k) for k in range(m)]),
             None: None}[layout]
    ss, dof, residuals = model._direction_fit_by_sets(group, index)
    ss_whole, dof_whole, residuals_whole = _dense(group, index)
    assert dof == dof_whole
    assert ss == pytest.approx(ss_whole, rel=1e-12)
    np.testing.assert_allclose(residuals, residuals_whole, atol=1e-12)


def test_a_hundred_sets_use_the_fit_set_by_set_and_a_few_the_whole_one():
    assert 3 * FACES * (FACES + 6) <= model.DENSE_DIRECTION_FIT_ELEMENTS
    assert 100 * FACES * (FACES + 200) > model.DENSE_DIRECTION_FIT_ELEMENTS


@pytest.mark.parametrize("m", [4, 7, 30])
def test_the_carried_drifts_share_of_the_offsets_is_the_trace_it_was(m):
    """set_offsets_spread takes trace(P·C) block by block (P the centring within each
    direction): the same as the sets × sets product it replaced."""
    rng = np.random.default_rng(m)
    values = rng.normal(size=(m, FACES)) + rng.normal(size=(m, 1))
    directions = np.where(np.arange(m) % 3 == 1, -1, 1)
    before = -np.arange(m, dtype=float)
    carried, covariance = before * 0.05, np.outer(before, before) * 1e-4
    centring = np.zeros((m, m))
    for d in (1, -1):
        rows = np.nonzero(directions == d)[0]
        centring[np.ix_(rows, rows)] = np.eye(rows.size) - 1.0 / rows.size
    means = values.mean(axis=1) - carried
    squares = sum(float(np.sum((means[directions == d] - means[directions == d].mean()) ** 2))
                  for d in (1, -1)) - float(np.trace(centring @ covariance))
    dof = m - 2
    tau, got_dof = model.set_offsets_spread(values, directions, carried, covariance)
    assert got_dof == dof
    assert tau == pytest.approx(np.sqrt(squares / dof), rel=1e-12)
