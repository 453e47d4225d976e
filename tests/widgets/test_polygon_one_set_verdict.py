"""One polygon set with no σ of a reading stated: the window's bold line says at once that no
statement of conformity can be made, why and what to state, as the command line's refusal
does (day review 68, finding 9: it said "Grade 3 (±1″) met: …" and nothing more, and the
technician learnt that no U can be given only at Export, after filling the details, from a
message beginning in lower case).

Readings simulated from first principles by tests/polygon_one_set_rig.py (numpy only)."""

from __future__ import annotations

import math
from unittest import mock

import numpy as np
import pytest

from app.certificate_presenter import CertificatePresenter, CertificateView
from models.certificate.metadata import CertificateMetadata
from models.readings.sheet import ReadingsSheet
from models.registry import KINDS
from tests.polygon_one_set_rig import OneSetBench, write_csv

#: what the window's refusal names: the set-up's field as the window labels it (gui78: not
#: the setting's key and command-line option, which the command line keeps)
ASKS = ("σ of a reading", "in the set-up (“σ of a reading, when not evaluated”)")
DETAILS = CertificateMetadata.from_dict({
    "lab_name": "Lab", "customer_name": "Customer", "item_description": "Rotary encoder",
    "item_serial": "E-1", "calibration_date": "2026-11-20", "operator": "Wang",
    "approver": "Dr. Li", "tolerance": 5.0, "decision_rule": "guarded"})


def _bold(presenter) -> str:
    return " ".join(presenter.view.verdict.text().split())


@pytest.mark.slow  # a window
def test_the_bold_line_says_no_statement_and_what_to_state_before_any_details(window, tmp_path):
    bench = OneSetBench(faces=24, seed=68)
    path = tmp_path / "one_set.csv"
    write_csv(path, bench.rows(np.random.default_rng(68)))
    presenter = window.presenter("polygon")
    presenter.set_settings({**presenter.settings, "grade": 5, "ac_roll_arcmin": 0.0})
    presenter.import_file(path)  # no certificate details stored: none with a tolerance
    shown = _bold(presenter)
    assert shown.startswith("No statement of conformity: no uncertainty can be given: with one "
                            "set"), shown
    assert all(words in shown for words in ASKS), shown
    assert " met" not in shown, shown  # no grade claimed met (or NOT met) without U
    # details with a tolerance stored: the certificate's reason is the same, said once
    window.certificates.store_details("polygon", DETAILS)
    presenter.refresh()
    shown = _bold(presenter)
    assert shown.count("no uncertainty can be given") == 1, shown
    # the σ stated: the grade's verdict, and no refusal
    sigma = math.hypot(bench.sigma_enc_arcsec, bench.sigma_ac_arcsec)
    presenter.set_settings({**presenter.settings, "reading_noise_arcsec": round(sigma, 3)})
    presenter.refresh()
    shown = _bold(presenter)
    assert "no uncertainty can be given" not in shown and "Grade 5 (±5\")" in shown, shown


def test_the_export_refusal_begins_with_a_capital():
    bench = OneSetBench(faces=12, seed=9)
    rows = bench.rows(np.random.default_rng(9))
    kind = KINDS["polygon"]
    settings = kind.checked_settings({"grade": 5, "ac_roll_arcmin": 0.0})
    result = kind.analyze(ReadingsSheet(kind.columns, rows).parse(), settings)
    view = mock.create_autospec(CertificateView, instance=True)
    view.edit_certificate_details.return_value = DETAILS
    presenter = CertificatePresenter(view, mock.MagicMock(), lambda: {}, mock.Mock())
    assert not presenter.export_certificate(kind, result, settings, "one_set.csv", [])
    title, text = view.tell.call_args.args
    assert title == "Cannot export"
    assert text.startswith("No uncertainty can be given: with one set"), text
    assert all(words in text for words in ASKS), text
    view.choose_save_path.assert_not_called()  # refused before a file name is asked
