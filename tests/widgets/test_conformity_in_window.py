"""Day 65, F8: with a tolerance in the certificate details the window states the
conformity verdict the certificate would print (its rule, the statement, the decided value
and interval), and "no statement" with its reason where none can be made. Before, the
window drew the tolerance band and nothing else: pass or fail was seen only in an issued
PDF."""

from __future__ import annotations

import dataclasses

import pytest

from models.certificate.metadata import CertificateMetadata

pytestmark = pytest.mark.slow  # a window

DETAILS = CertificateMetadata.from_dict({
    "lab_name": "Lab", "customer_name": "Customer", "item_description": "Theodolite",
    "item_serial": "T-1", "calibration_date": "2026-11-20", "operator": "Wang",
    "approver": "Dr. Li",
    "standards": [{"description": "Autocollimator + polygon", "certificate_no": "N-1",
                   "uncertainty": 0.3}]})


def test_the_window_states_the_certificates_conformity_verdict(window):
    presenter = window.presenter("theodolite")
    presenter.load_sample()
    presenter.refresh()
    assert "Conformity" not in presenter.view.verdict.text()  # no tolerance: none
    for tolerance in (3.0, 0.2):
        details = dataclasses.replace(DETAILS, tolerance=tolerance, decision_rule="guarded")
        window.certificates.store_details("theodolite", details)
        presenter.refresh()
        printed = presenter.kind.certificate_document(presenter.result, details, "",
                                                      presenter.result_settings).conformity
        shown = presenter.view.verdict.text()
        assert presenter.view.verdict.isVisibleTo(presenter.view)
        # the certificate's whole statement under the pointer
        assert presenter.view.verdict.toolTip() == printed.statement
        rule = "Guard band w = U: pass / conditional / fail (ILAC-G8 4.2.3)"
        if tolerance == 3.0:
            assert printed.verdict == "pass"
            assert "The item conforms to the specification ±3\" (pass)." in printed.statement
            assert f"Conformity: pass ({rule}). Decided value 0.94\", interval " \
                "[0.00, 1.45]\"." in shown, shown
        else:  # U₊ ≥ T: no statement, and why (U₊ guards acceptance: assessment 76 M2)
            assert printed.verdict == "not assessed"
            assert f"Conformity: no statement ({rule}): " in shown, shown
            assert 'U₊ = 0.51" is not smaller than T = 0.2". Decided value 0.94", interval ' \
                '[0.00, 1.45]".' in shown, shown


def test_details_no_certificate_can_be_made_with_are_said_in_the_window(window):
    """The polygon's grade 3 (±1″) against a tolerance of ±3″ in the details: the
    certificate refuses them; the window says why no statement is made."""
    presenter = window.presenter("polygon")
    presenter.load_sample()
    window.certificates.store_details("polygon", dataclasses.replace(DETAILS, tolerance=3.0))
    presenter.refresh()
    shown = presenter.view.verdict.text()
    assert "No statement of conformity: the certificate details give a tolerance of ±3\"" \
        in shown, shown
