"""Issue 44: a setting edited after the analysis (its new analysis still to come) never
reaches the certificate of the old result: the presenter keeps the settings each result was
analysed with (``result_settings``), and the window's export passes those, not the form's.
The analysed ones win because every figure of the result was computed with them; the edited
ones reach a certificate with the result analysed from them."""

from __future__ import annotations

from unittest import mock

import numpy as np

from tests.widgets.test_presenters import _delete_presenters_at_teardown, load, make  # noqa: F401
from widgets.theodolite.presenter import TheodolitePresenter
from widgets.theodolite.view import TheodoliteView


def test_an_edited_setting_waits_for_its_analysis_before_a_certificate_states_it(
        qtbot, samples_dir):
    presenter, view = make(TheodolitePresenter, TheodoliteView, qtbot)
    load(presenter, samples_dir)
    analysed = presenter.result
    assert presenter.result_settings["cmc_arcsec"] == 0.0
    view.settings_values.return_value = {"cmc_arcsec": 0.7}
    presenter.settings_edited()  # the analysis is scheduled, not yet run
    assert presenter.settings["cmc_arcsec"] == 0.7
    assert presenter.result is analysed and presenter.result_settings["cmc_arcsec"] == 0.0

    from app.main_window import MainWindow

    window = mock.Mock()
    window._current_result.return_value = presenter.result
    window.current = presenter
    MainWindow.export_certificate(window)
    kind, result, settings = window.certificates.export_certificate.call_args.args[:3]
    assert result is analysed and settings["cmc_arcsec"] == 0.0

    presenter.refresh()  # the edit analysed: now its result states it
    assert presenter.result is not analysed and presenter.result_settings["cmc_arcsec"] == 0.7
    MainWindow.export_certificate(window)
    assert window.certificates.export_certificate.call_args.args[2]["cmc_arcsec"] == 0.7


def test_the_windows_u_band_is_held_to_the_cmc_it_was_analysed_with(qtbot, samples_dir):
    """The U band drawn beside the corrected error is the certificate's U: with the
    laboratory's CMC of the settings the result was analysed with as its floor."""
    from models.certificate.metadata import CertificateMetadata

    presenter, view = make(TheodolitePresenter, TheodoliteView, qtbot)
    presenter.certificate_details = lambda: CertificateMetadata(tolerance=5.0)
    load(presenter, samples_dir)
    _, bands, _ = presenter.tolerance_bands(presenter.result)
    computed = np.asarray(bands["corrected_error_arcsec"], dtype=float)
    cmc = round(float(np.median(computed[computed > 0])) * 1.5, 4)
    view.settings_values.return_value = {"cmc_arcsec": cmc}
    presenter.settings_edited()
    presenter.refresh()
    _, bands, _ = presenter.tolerance_bands(presenter.result)
    np.testing.assert_allclose(bands["corrected_error_arcsec"],
                               np.where(computed > 0, np.maximum(computed, cmc), computed))
