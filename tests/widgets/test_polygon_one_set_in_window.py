"""The polygon workbench with one set and no σ of a reading stated (issue 39): the window
says what the certificate, the command line and the JSON say — no U, so no decided value's
interval and no statement, and what to state — and, once the σ is stated, the decided
value with the interval the certificate prints. The version before showed the decided
value 0.00″ with an interval [0.00, 0.70]″ for a true half range of 1.08″ (one set, 24
faces; tests/models/polygon/test_polygon_one_set_withheld.py)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from models.certificate.metadata import CertificateMetadata
from tests.polygon_one_set_rig import OneSetBench, write_csv

pytestmark = pytest.mark.slow  # a window

DETAILS = CertificateMetadata.from_dict({
    "lab_name": "Lab", "customer_name": "Customer", "item_description": "Rotary encoder",
    "item_serial": "E-1", "calibration_date": "2026-11-20", "operator": "Wang",
    "approver": "Dr. Li", "tolerance": 5.0, "decision_rule": "guarded"})


def test_one_set_without_sigma_shows_no_interval_and_says_what_to_state(window, tmp_path):
    bench = OneSetBench(faces=24, seed=0)
    path = tmp_path / "one_set.csv"
    write_csv(path, bench.rows(np.random.default_rng(24)))
    presenter = window.presenter("polygon")
    presenter.set_settings({**presenter.settings, "grade": 5, "ac_roll_arcmin": 0.0})
    presenter.import_file(path)
    window.certificates.store_details("polygon", DETAILS)
    presenter.refresh()
    shown = " ".join(presenter.view.verdict.text().split())
    assert "No statement of conformity: no uncertainty can be given" in shown, shown
    # the set-up's field as the window labels it (gui78: "reading_noise_arcsec; on the
    # command line --reading-noise-arcsec" was shown to the technician)
    assert "in the set-up (“σ of a reading, when not evaluated”)" in shown, shown
    assert "reading_noise_arcsec" not in shown and "--reading" not in shown, shown
    assert "Decided value" not in shown, shown
    sigma = math.hypot(bench.sigma_enc_arcsec, bench.sigma_ac_arcsec)
    presenter.set_settings({**presenter.settings, "reading_noise_arcsec": round(sigma, 3)})
    presenter.refresh()
    shown = " ".join(presenter.view.verdict.text().split())
    printed = presenter.kind.certificate_document(
        presenter.result, dataclasses.replace(DETAILS), "", presenter.result_settings).conformity
    assert "Decided value" in shown and "no uncertainty can be given" not in shown, shown
    low, high = printed.interval_low, printed.interval_high
    assert low <= bench.truth_half_range() <= high
    # the ends as the certificate prints them: the printed value ∓ the printed U (round76)
    from models.certificate.document import printed_decided_figures

    ends = printed_decided_figures(printed)
    low_text, high_text = (str(ends[end]).rstrip('"') for end in ("low", "high"))
    assert f"interval [{low_text}, {high_text}]" in shown, (shown, ends)
