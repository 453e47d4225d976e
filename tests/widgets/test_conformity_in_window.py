"""Day 65, F8: with a tolerance in the certificate details the window states the
conformity verdict the certificate would print (its rule, the statement, the decided value
and interval), and "no statement" with its reason where none can be made. Before, the
window drew the tolerance band and nothing else: pass or fail was seen only in an issued
PDF."""

from __future__ import annotations

import dataclasses

import pytest

from models.certificate.metadata import CertificateMetadata
from tests.models.certificate.test_u_of_a_hundred_or_more import nm_axis

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


def test_the_window_prints_the_decided_interval_as_the_certificate_in_nm(tmp_path):
    """A linear axis in nm (assessment 76 M1): the window's line gives the decided value and
    its interval as the certificate prints them, 1000 nm and 770 … 1230 nm (U = 230 nm,
    rounded up to two significant digits), not the interval rounded on its own
    ([780, 1220] nm; until 0.8.24 [776, 1219] nm beside the certificate's 776 … 1220 nm)."""
    from widgets.workbench_presenter import conformity_text

    _, document = nm_axis(tmp_path)
    assert "770 nm … 1230 nm" in str(document.conformity.statement) or any(
        "770 nm … 1230 nm" in str(cell) for row in document.statistics.rows for cell in row)
    assert conformity_text(document.conformity).endswith(
        "Decided value 1000 nm, interval [770, 1230] nm.")


def test_the_windows_verdict_line_joins_its_chinese_sentences_without_a_space(tmp_path, qapp):
    """In Chinese the verdict and the decided value are two sentences joined as the
    language joins them: "…（…）。判定值 …", not "。 判定值" (cert77); in English with a
    space, as before."""
    from widgets.i18n import install_language
    from widgets.workbench_presenter import conformity_text

    _, document = nm_axis(tmp_path)
    english = conformity_text(document.conformity)
    assert ". Decided value 1000 nm, interval [770, 1230] nm." in english, english
    install_language("zh_CN")
    try:
        chinese = str(conformity_text(document.conformity))
    finally:
        install_language("en")
    assert chinese.startswith("符合性：") and "。判定值 1000 nm" in chinese, chinese
    assert "。 " not in chinese, chinese


@pytest.mark.parametrize("tolerance, rule, verdict, chinese", [
    (3.0, "guarded", "pass", "合格"),
    (1.2, "simple", "pass", "合格"),
    (1.2, "guarded", "conditional pass", "有条件合格"),
    (1.2, "guarded_binary", "fail", "不合格")])
def test_the_windows_verdict_is_the_certificates_word_in_both_languages(
        window, tolerance, rule, verdict, chinese):
    """Assessment 78 M1: the Chinese window said 符合性：通过 where the certificate, its XLSX
    and its DCC say 合格 for the same verdict (tr("pass") is the validation report's 通过, a
    check passed); its line named the zones 合格 / 有条件 / 不合格 beside it. The window now
    says the word the certificate's statement says, in English and in Chinese, and again
    after a change of language."""
    from app.writers.certificate_pdf.wording import VERDICT_CHINESE
    from models.messages import in_language, translator

    presenter = window.presenter("theodolite")
    presenter.load_sample()
    details = dataclasses.replace(DETAILS, tolerance=tolerance, decision_rule=rule)
    window.certificates.store_details("theodolite", details)
    presenter.refresh()
    printed = presenter.kind.certificate_document(presenter.result, details, "",
                                                  presenter.result_settings).conformity
    assert printed.verdict == verdict
    # the certificate's own sentence, in Chinese, holds the word (its XLSX's Verdict row too)
    assert chinese in in_language(printed.statement, translator("zh_CN")), printed.statement
    assert VERDICT_CHINESE[verdict] == chinese
    assert presenter.view.verdict.text().splitlines()[-1].startswith(f"Conformity: {verdict} (")
    window.set_language("zh_CN")
    try:
        shown = presenter.view.verdict.text().splitlines()[-1]
        assert shown.startswith(f"符合性：{chinese}（"), shown
        assert "通过" not in shown, shown
        presenter.refresh()
        assert presenter.view.verdict.text().splitlines()[-1].startswith(f"符合性：{chinese}（")
    finally:
        window.set_language("en")
    assert presenter.view.verdict.text().splitlines()[-1].startswith(f"Conformity: {verdict} (")
