"""The window while a run is in progress: set 1's result stays, set 2 shows as progress,
a certificate is refused before any dialog (#41)."""

from __future__ import annotations

from unittest import mock

import numpy as np
import pytest
import shiboken6
from PySide6.QtWidgets import QWidget

from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table
from widgets.polygon.presenter import PolygonPresenter
from widgets.polygon.view import PolygonView


@pytest.mark.slow  # the polygon's exact 3-D analysis, twice: ~3 s
def test_one_row_of_set_2_keeps_set_1s_result(qtbot, samples_dir):
    view = mock.create_autospec(PolygonView, instance=True)
    view.settings_values.return_value = {}
    owner = QWidget()
    try:
        presenter = PolygonPresenter(view, parent=owner)
        rows = map_columns(read_table(samples_dir / "polygon_sample.csv"), presenter.kind.columns)
        presenter.table_model.replace_all(rows[:25])  # set 1 with its closure
        presenter.refresh()
        alone = presenter.result.mean_corrected_arcsec.copy()
        presenter.table_model.replace_all(rows[:26])  # and the first row of set 2
        presenter.refresh()
        assert presenter.result is not None and presenter.problem == ""
        np.testing.assert_array_equal(presenter.result.mean_corrected_arcsec, alone)
        assert str(presenter.result.incomplete.text()) == "set 2: 1 of 24 faces"
        summary = view.set_summary.call_args.args[0]
        assert summary.startswith("In progress: set 2: 1 of 24 faces (rows 26–26)")
        errors = view.show_figures.call_args.args[0]
        assert errors.by_role("raw").y.size == 24  # set 1's curves, not emptied
        # the set in progress plotted as taken: its raw error against set 1's reference is
        # what the whole run, once complete, gives set 2 at those faces
        presenter.table_model.replace_all(rows[:29])  # set 2's first 4 faces: 1, 24, 23, 22
        presenter.refresh()
        sets = view.show_figures.call_args.kwargs["sets"]
        taken = next(x for x in sets.series if x.label == "set in progress (raw error)")
        whole = presenter.kind.analyze(ReadingsSheet(presenter.kind.columns, rows).parse(),
                                       presenter.settings)
        np.testing.assert_allclose(taken.x, whole.theta_deg[[0, 23, 22, 21]])
        np.testing.assert_allclose(taken.y, whole.sets[1].error_arcsec[[0, 23, 22, 21]],
                                   atol=1e-6)
        assert [x.label for x in sets.series[:2]] == ["1 (+)", "mean of the sets"]
        band = [x for x in sets.series if x.dashed]
        assert len(band) == 2 and band[0].y[0] - band[1].y[0] == 2.0  # grade 3: ±1″
        # a certificate is refused before the details dialog, naming what is in progress
        from app.certificate_presenter import CertificatePresenter, CertificateView

        dialogs = mock.create_autospec(CertificateView, instance=True)
        certificates = CertificatePresenter(dialogs, mock.MagicMock(), dict, lambda: None)
        assert not certificates.export_certificate(presenter.kind, presenter.result,
                                                   presenter.settings, "x.csv")
        assert "set 2: 4 of 24 faces" in dialogs.tell.call_args.args[1]
        dialogs.edit_certificate_details.assert_not_called()
    finally:
        shiboken6.delete(owner)
