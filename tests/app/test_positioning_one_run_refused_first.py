"""A positioning record of one run each way can have no U whatever the certificate's details:
the window says so before it asks for them, naming every direction's targets (day review
69, finding 6: the refusal came after the whole details dialog, and named only "… 360
forward" though every target was approached once backward too). The record is simulated
by tests/repeatability_rig.py (first principles)."""

from __future__ import annotations

from unittest import mock

import numpy as np

from app.certificate_presenter import CertificatePresenter, CertificateView
from models.positioning.analysis import POSITIONING
from models.readings.sheet import ReadingsSheet
from tests.repeatability_rig import iso230_rows

ANGLES = np.linspace(0.0, 330.0, 12)


def _one_run():
    f = 4.0 * np.sin(np.radians(ANGLES))
    rows, _ = iso230_rows(ANGLES, {"+": f + 1.0, "-": f - 1.0}, 1, 0.8,
                          np.random.default_rng(6910))
    sheet = [[str(a), str(r), sign, str(x)] + [""] * (len(POSITIONING.columns) - 4)
             for a, r, sign, x, _ in rows]
    return POSITIONING.analyze(ReadingsSheet(POSITIONING.columns, sheet).parse(),
                               POSITIONING.settings_with_defaults({}))


def test_one_run_is_refused_before_the_details_naming_both_directions():
    result = _one_run()
    view = mock.create_autospec(CertificateView, instance=True)
    view.edit_certificate_details.return_value = None  # were it asked: cancelled
    presenter = CertificatePresenter(view, mock.MagicMock(), dict, lambda: None)
    assert not presenter.export_certificate(POSITIONING, result, {}, "axis.csv")
    view.edit_certificate_details.assert_not_called()
    view.choose_save_path.assert_not_called()
    _title, text = view.tell.call_args.args
    targets = ", ".join(f"{a:g}" for a in ANGLES)
    assert f"{targets} forward" in text and f"{targets} backward" in text, text
    assert "fewer than twice" in text
