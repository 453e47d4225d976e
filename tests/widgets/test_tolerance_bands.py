"""#41: the positioning and theodolite error plots draw the tolerance ±T and each point's U
band where the certificate details set a tolerance (T from the details the certificate
uses, U the JSON's ``expanded_uncertainty_*`` from the same budget); no band without a
tolerance. Read back from the drawn curves (getData)."""

from __future__ import annotations

import dataclasses

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from models.certificate.uncertainty_json import workbench_uncertainty_json

pytestmark = pytest.mark.slow  # a window

DETAILS = CertificateMetadata.from_dict({
    "lab_name": "Lab", "customer_name": "Customer", "item_description": "Rotary table",
    "item_serial": "R-1", "calibration_date": "2026-11-20", "operator": "Wang",
    "approver": "Dr. Li",
    "standards": [{"description": "Autocollimator + polygon", "certificate_no": "N-1",
                   "uncertainty": 0.3}]})


def _axis_log(seed: int = 4) -> list[list[str]]:
    """An ISO 230-2 log of a rotary axis: 4 targets × 5 runs, both directions; the axis'
    deviation a pitch error and a backlash, with 0.2″ of repeatability noise."""
    rng = np.random.default_rng(seed)
    rows = []
    targets = [0.0, 30.0, 60.0, 90.0]
    for run in range(1, 6):
        for direction, order in (("+", targets), ("-", targets[::-1])):
            for t in order:
                dev = 3.0 * np.sin(np.radians(2 * t)) + (0.8 if direction == "+" else -0.8) \
                    + rng.normal(0.0, 0.2)
                rows.append([f"{t:g}", str(run), direction, f"{dev:.3f}", ""])
    return rows


def _labelled(renderer_or_plot, label):
    curves = renderer_or_plot.curves
    names = renderer_or_plot._names if hasattr(renderer_or_plot, "_names") else \
        renderer_or_plot.renderer._names
    return [c for c, n in zip(curves, names, strict=True) if n == label]


def _drawn(curves):
    return [c for c in curves if c.getData()[0] is not None and len(c.getData()[0])]


def test_positioning_plot_draws_plus_minus_t_and_u_where_a_tolerance_is_set(window):
    presenter = window.presenter("positioning")
    presenter.table_model.replace_all(_axis_log(), "axis log")
    presenter.refresh()
    plot = presenter.view.deviation_plot
    bands_without = len(plot.bands)  # the ±2s bands
    assert bands_without == 2
    assert not _drawn(_labelled(plot, "tolerance ±T about the mid-range"))

    window.certificates.store_details("positioning", dataclasses.replace(DETAILS, tolerance=6.0))
    presenter.refresh()
    result = presenter.result
    assert len(plot.bands) == bands_without + 2  # each direction's U
    # ±T about the mid-range of the mean deviations (the half-range decision)
    means = np.concatenate([s.mean for _, _, s in result.directions_present()])
    mid = 0.5 * (means.max() + means.min())
    (upper,) = _drawn(_labelled(plot, "tolerance ±T about the mid-range"))
    index = plot.curves.index(upper)
    lower = plot.curves[index + 1]
    assert np.allclose(upper.getData()[1], mid + 6.0)
    assert np.allclose(lower.getData()[1], mid - 6.0)
    assert list(upper.getData()[0]) == [0.0, 90.0]
    # U per target: the JSON's expanded_uncertainty_mean_up / _down, drawn around each mean
    got = workbench_uncertainty_json(presenter.kind, result, dataclasses.replace(
        DETAILS, tolerance=6.0), presenter.settings)["per_target"]
    for name, _, stats in result.directions_present():
        u = np.asarray(got[f"expanded_uncertainty_mean_{name}"], dtype=float)
        assert np.all(u > 0)
        band = next(b for b in plot.bands[bands_without:]
                    if np.allclose(b.curves[0].getData()[1], stats.mean + u))
        assert np.allclose(band.curves[1].getData()[1], stats.mean - u)
        assert np.allclose(band.curves[0].getData()[0], result.positions)

    # every point judged against ±T: the limits about zero
    window.certificates.store_details("positioning", dataclasses.replace(
        DETAILS, tolerance=6.0, decision_quantity="points"))
    presenter.refresh()
    (upper,) = _drawn(_labelled(plot, "tolerance ±T"))
    assert np.allclose(upper.getData()[1], 6.0)
    assert np.allclose(plot.curves[plot.curves.index(upper) + 1].getData()[1], -6.0)

    # the tolerance taken away: no band
    window.certificates.store_details("positioning", DETAILS)
    presenter.refresh()
    assert len(plot.bands) == bands_without
    assert not _drawn(_labelled(plot, "tolerance ±T"))


def test_theodolite_error_plot_draws_t_and_u_on_the_corrected_panel(window):
    presenter = window.presenter("theodolite")
    presenter.load_sample()
    plot = presenter.view.error_plot
    renderer = plot.corrected_renderer
    assert renderer.bands == []
    window.certificates.store_details("theodolite", dataclasses.replace(DETAILS, tolerance=4.0))
    presenter.refresh()
    result = presenter.result
    order = np.argsort(result.theta_deg, kind="stable")
    corrected = result.corrected_error_arcsec[order]
    got = workbench_uncertainty_json(presenter.kind, result, dataclasses.replace(
        DETAILS, tolerance=4.0), presenter.settings)
    u = np.asarray(got["expanded_uncertainty_corrected_error_arcsec"], dtype=float)[order]
    (band,) = renderer.bands
    assert np.allclose(band.curves[0].getData()[1], corrected + u)
    assert np.allclose(band.curves[1].getData()[1], corrected - u)
    (upper,) = _drawn(_labelled(renderer, "tolerance ±T about the mid-range"))
    mid = 0.5 * (corrected.max() + corrected.min())
    assert np.allclose(upper.getData()[1], mid + 4.0)
    lower = renderer.curves[renderer.curves.index(upper) + 1]
    assert np.allclose(lower.getData()[1], mid - 4.0)
    # the corrected curve itself unchanged
    assert np.allclose(plot.corrected_curve.getData()[1], corrected)
    window.certificates.store_details("theodolite", DETAILS)
    presenter.refresh()
    assert renderer.bands == []
    assert not _drawn(_labelled(renderer, "tolerance ±T about the mid-range"))
