"""What the result refuses is told before the file dialog, not after the technician has
chosen a file (#41): a grade the certificate details contradict; a SINUMERIK table of two
directions."""

from __future__ import annotations

from unittest import mock

import pytest
import shiboken6
from PySide6.QtWidgets import QWidget

from app.certificate_presenter import CertificatePresenter, CertificateView
from models.certificate.metadata import CertificateMetadata
from models.polygon.analysis import POLYGON
from models.readings.sheet import ReadingsSheet
from models.readings.tabular_import import map_columns, read_table


def _analysed(kind, samples_dir, settings=None):
    rows = map_columns(read_table(samples_dir / kind.sample_file), kind.columns)
    return kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings or {})


def test_a_grade_the_details_contradict_is_told_before_the_file_dialog(samples_dir):
    result = _analysed(POLYGON, samples_dir)  # grade 3
    view = mock.create_autospec(CertificateView, instance=True)
    view.edit_certificate_details.return_value = CertificateMetadata(item_grade="grade 5")
    view.confirm_draft.return_value = True
    presenter = CertificatePresenter(view, mock.MagicMock(), dict, lambda: None)
    assert not presenter.export_certificate(POLYGON, result, {}, "polygon.csv")
    view.choose_save_path.assert_not_called()
    title, text = view.tell.call_args.args
    assert "'grade 5' but the workbench is set to grade 3" in text


@pytest.mark.slow
def test_a_table_the_controller_refuses_is_told_before_the_file_dialog(qtbot, samples_dir):
    from widgets.positioning.presenter import PositioningPresenter
    from widgets.positioning.view import PositioningView

    view = mock.create_autospec(PositioningView, instance=True)
    view.settings_values.return_value = {}
    owner = QWidget()
    try:
        presenter = PositioningPresenter(view, parent=owner)
        rows = map_columns(read_table(samples_dir / presenter.kind.sample_file),
                           presenter.kind.columns)
        presenter.table_model.replace_all(rows)
        presenter.set_settings({"compensation_format": "sinumerik",
                                "compensation_tables": "separate",
                                "compensation_controller_options": "axis=AX4"})
        presenter.refresh()
        with mock.patch.object(presenter, "ask_controller_options", return_value=True):
            presenter.export_compensation_dialog()
        view.ask_compensation_path.assert_not_called()
        assert "one table per measuring system" in view.tell.call_args.args[1]
        # one table from the bidirectional mean: the file dialog is asked
        presenter.set_settings({**presenter.settings, "compensation_tables": "bidirectional"})
        presenter.refresh()
        view.ask_compensation_path.return_value = ""
        with mock.patch.object(presenter, "ask_controller_options", return_value=True):
            presenter.export_compensation_dialog()
        view.ask_compensation_path.assert_called_once()
    finally:
        shiboken6.delete(owner)
