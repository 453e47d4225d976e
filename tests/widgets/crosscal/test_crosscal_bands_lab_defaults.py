"""The cross-calibration's ±U bands are the U its certificate states with the details it
would be issued with: the workbench's details with the laboratory's defaults filled in
(app/certificate_presenter.py issue_details). Before, the bands were the readings' own U (no
details at all): with the lab defaults listing the comparator (an autocollimator, U95 =
0.1″ per reading) and nothing typed for the workbench, the window drew a band of ~0.03″
where the certificate states ~0.05″ (and its own plot drew the narrower band beside its
table's U)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata

pytestmark = pytest.mark.slow  # the window and a certificate

SAMPLES = Path(__file__).resolve().parents[3] / "resources" / "samples"


def _half_width(plot) -> tuple[np.ndarray, np.ndarray]:
    """(x, half-width) of the first ±band drawn on ``plot``, from its curves' data."""
    (band, *_rest) = plot.bands
    upper, lower = band.curves
    x, high = upper.getData()
    _, low = lower.getData()
    return np.asarray(x), (np.asarray(high) - np.asarray(low)) / 2.0


@pytest.mark.parametrize("item", ["encoder", "polygon"])
def test_bands_are_the_certificates_u_with_only_lab_defaults_set(window, qtbot, item):
    lab = CertificateMetadata.from_dict(json.loads(
        (SAMPLES / "certificate_crosscal_encoder.json").read_text(encoding="utf-8")))
    crosscal = window.presenter("crosscal")
    window.tabs.setCurrentIndex(window.presenters.index(crosscal))
    crosscal.set_settings({**crosscal.settings, "certificate_of": item})
    crosscal.load_sample()
    qtbot.waitUntil(lambda: crosscal.result is not None and not crosscal.analysis_pending)
    assert "crosscal" not in window.projects.metadata.get("certificates", {})  # none typed
    # Settings › lab defaults: the comparator's stated U among the lab's standards
    window.certificates.save_lab_defaults(lab.lab_defaults(), "crosscal")
    plot = crosscal.view.encoder_plot if item == "encoder" else crosscal.view.polygon_plot
    details = window.certificates.issue_details("crosscal")
    assert details.standards  # the lab defaults' comparator, nothing typed for the workbench
    document = crosscal.kind.certificate(crosscal.result, details,
                                         settings=crosscal.result_settings)
    certified = np.asarray(document.budget.expanded, dtype=float)
    own = crosscal.result.expanded_u_arcsec[0 if item == "encoder" else 1]
    assert np.all(certified > own * 1.2)  # the comparator's U makes a difference to see
    qtbot.waitUntil(lambda: plot.bands and np.allclose(_half_width(plot)[1], certified,
                                                       rtol=1e-9), timeout=3000)
    x, half = _half_width(plot)
    np.testing.assert_allclose(half, certified, rtol=1e-9)
    assert x.size == crosscal.result.faces
    # the certificate's own plot: its band is its table's U
    figure = document.plots[0]
    np.testing.assert_allclose(figure.series[0].band, certified, rtol=1e-12)
